// The declarations (types/wingspline.d.ts) flag misuse as an editor would. Every
// line marked @ts-expect-error MUST be a type error: if a declaration grew so loose that the
// misuse type-checks, tsc reports the unused directive and the `types` layer fails. The
// correct uses beside them must type-check. Checked, never run (tsc --noEmit -p
// tsconfig.examples.json).
import { loadWingspline, WingsplineError } from 'wingspline';
import type { Curve, Mesh, WingsplineErrorCode, MeshOperation } from 'wingspline';

export async function misuse(): Promise<void> {
  const api = await loadWingspline();
  const bezier: Curve = { kind: 'bezier', dim: 2, points: [0, 0, 1, 2, 3, 2, 4, 0] };
  const p: Float64Array = api.evaluateCurve(bezier, [0.5]);

  // @ts-expect-error a misspelt method name
  api.evaluateCurv(bezier, [0.5]);
  // @ts-expect-error an unknown curve kind
  api.evaluateCurve({ kind: 'bezeir', dim: 2, points: [0, 0, 1, 1] }, [0.5]);
  // @ts-expect-error dim is 2 or 3
  api.evaluateCurve({ kind: 'bezier', dim: 4, points: [0, 0, 0, 0] }, [0.5]);
  // @ts-expect-error params are numbers, not a string
  api.evaluateCurve(bezier, '0.5');
  // @ts-expect-error a NURBS curve needs its weights
  api.evaluateCurve({ kind: 'nurbs', dim: 2, points: [0, 0, 1, 1] }, [0.5]);
  // @ts-expect-error a Hermite curve needs its tangents
  api.curveDomain({ kind: 'hermite', dim: 2, points: [0, 0, 1, 1] });
  // @ts-expect-error the result is a Float64Array, not an array of points
  const wrong: number[][] = api.evaluateCurve(bezier, [0.5]);
  // @ts-expect-error an unknown basis
  api.basisMatrix('b-spline');
  // @ts-expect-error insertKnot takes the B-spline algorithms' curves only
  api.insertKnot({ kind: 'catmull-rom', dim: 2, points: [0, 0, 1, 1, 2, 0, 3, 1] }, 0.5);
  // @ts-expect-error the options object, not a bare number
  api.jointContinuity(bezier, bezier, 1e-9);
  // @ts-expect-error constraint modes are free, C0, G1, C1, C2
  api.enforceConstraint([0, 0], 2, 'bezier', 'G2');
  // Curve exercises (kinds 3-5): the shapes the player relies on.
  const joint = api.checkJointAnswer(bezier, bezier, { parametric: 1, why: ['meet'] });
  const jointField: string = joint.findings.length > 0 ? joint.findings[0].field : joint.worked.why.join();
  const value: number[] = api.checkValueAnswer({ curve: bezier }, { quantity: 'blend', i: 1, u: 0.5 }, [0.375], 0.001).expected;
  const holds: boolean = api.checkCurveProperty({ curve: bezier }, { kind: 'passes-through', point: [2, 1], tolerance: 0.01 }).holds;
  // @ts-expect-error a blending function needs its index i
  api.checkValueAnswer({ curve: bezier }, { quantity: 'blend', u: 0.5 }, [0.375], 0.001);
  // @ts-expect-error an unknown quantity
  api.workedValue({ curve: bezier }, { quantity: 'slope', u: 0.5 });
  // @ts-expect-error passes-through is asked of one curve, not of a joint
  api.checkCurveProperty({ a: bezier, b: bezier }, { kind: 'passes-through', point: [2, 1], tolerance: 0.01 });
  // @ts-expect-error the statements ticked are a list of ids
  api.checkJointAnswer(bezier, bezier, { why: 'meet' });

  // @ts-expect-error buildMesh needs the faces
  api.buildMesh({ positions: [0, 0, 0] });
  const mesh: Mesh = api.buildMesh(api.lectureExample());
  // @ts-expect-error the walk is traversalSteps
  mesh.ccwWalk(1);
  // @ts-expect-error a step's role is 'start' or 'end'
  if (mesh.traversalSteps(1)[0].role === 'Start') throw new Error('never');
  // @ts-expect-error an unknown representation
  mesh.tables('winged edge');
  // @ts-expect-error an unknown query
  mesh.query('edges-of-vertex', 1);
  // @ts-expect-error an operation's arguments by name: split-face takes f, a, b
  mesh.apply({ op: 'split-face', f: 0, e: 1 });
  const op: MeshOperation = { op: 'flip-edge', e: 2 };
  // @ts-expect-error check names an operation the core knows
  mesh.check('flip', 2);
  // @ts-expect-error the vertex table's rows have no 'edges' column
  const edges = mesh.wingedEdge().vertices[0].edges;
  // @ts-expect-error subdivide needs a scheme
  api.subdivide(mesh, { steps: 1 });
  // @ts-expect-error Mesh is a type, not something to construct: meshes come from buildMesh
  new Mesh();
  mesh.dispose();

  try {
    api.parseMesh('v 0 0', { format: 'obj' });
  } catch (err) {
    if (err instanceof WingsplineError) {
      const code: WingsplineErrorCode = err.code;
      // @ts-expect-error a misspelt error code cannot match
      if (err.code === 'parse_error') throw err;
      // @ts-expect-error line is a number
      const line: string = err.line;
      void code; void line;
    }
  }
  // @ts-expect-error parseMesh takes the text, not a file name option
  api.parseMesh({ file: 'mesh.obj' });
  // @ts-expect-error the csr layout has no faces list
  api.parseMesh('', { layout: 'csr' }).faces;
  // Checking a winged-edge table.
  const slide = api.lectureExample();
  const check = api.checkWingedEdgeAnswer({ faces: slide.faces, vertexCount: 5 }, { edges: [], vertexEdges: [], faceEdges: [] });
  const firstField: string = check.findings[0]?.field ?? '';
  // @ts-expect-error the exercise mesh needs its vertex count (or positions)
  api.checkWingedEdgeAnswer({ faces: slide.faces }, { edges: [], vertexEdges: [], faceEdges: [] });
  // @ts-expect-error the answer needs its face table
  api.checkWingedEdgeAnswer({ faces: slide.faces, vertexCount: 5 }, { edges: [], vertexEdges: [] });
  // @ts-expect-error findings have a row, not an edge
  void check.findings[0].edge;
  // The other tables and the walk.
  const faces = api.checkMeshTableAnswer({ faces: slide.faces, vertexCount: 5 }, 'faces', { faces: [[0, 1, 2], [1, 3, 2], [1, 4, 3]] });
  const workedFaces: number[][] = faces.worked.faces;
  const list = api.checkMeshTableAnswer({ faces: slide.faces, vertexCount: 5 }, 'edge-list', { edges: [0, 1, 0, -1], polygons: [[0], [], []] });
  const firstIndex: number = list.findings[0]?.index ?? -1;
  // @ts-expect-error an edge list's answer has polygons, not faces
  api.checkMeshTableAnswer({ faces: slide.faces, vertexCount: 5 }, 'edge-list', { faces: [] });
  // @ts-expect-error no such table
  api.checkMeshTableAnswer({ faces: slide.faces, vertexCount: 5 }, 'quad-edge', { faces: [] });
  const step = api.checkWalkStep(slide, { around: 'vertex', element: 1, step: 1, given: 4 });
  const closed: boolean = step.done;
  // @ts-expect-error a walk goes around a vertex or a face, not an edge
  api.checkWalkStep(slide, { around: 'edge', element: 1, step: 1, given: 4 });
  void workedFaces; void firstIndex; void closed;
  void p; void wrong; void op; void edges; void firstField; void jointField; void value; void holds;
}
