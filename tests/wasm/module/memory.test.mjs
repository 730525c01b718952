// Memory over time: every API function is called many times succeeding and many
// times failing (the failures reach the core and come back as {ok:false}), meshes are
// built and disposed, and the wasm heap must not grow. Each failing call calls the
// function its case names and must be refused with that function's documented code
// (docs/api-curves.md, docs/api-mesh.md); a call refused for another reason fails the test.
// Mesh methods without input fail on a disposed mesh ('disposed'); the six API functions
// without input (NO_FAILING_INPUT) have no failing call at all.
//
// The measure: api.memoryUsage() -> { heapInUse: malloc's bytes in use, linearBytes: the
// wasm memory }. After a warm-up round (first-use allocations, registry capacity) the bytes
// in use must return to the same figure within HEAP_SLACK_BYTES, and linear memory must not
// grow by more than LINEAR_SLACK_BYTES. dlmalloc's smallest chunk is 16 bytes, so one
// leaked allocation per call costs at least 16 x calls bytes: 80 KB at 5,000 calls, 1.6 MB
// at 100,000, far above the slack. An escaping C++ exception (which leaks wasm stack in
// Emscripten 3.1.6) would also corrupt the module long before the end; the last check
// evaluates exactly.
//
// Counts: the issue asks for 100,000 failing and 100,000 succeeding calls of each function.
// The full 100,000 + 100,000 go to the three paths where a leak is most likely and most
// costly: buildMesh + dispose (the only handle-owning path: the core's mesh registry),
// parseMesh (untrusted text of any size crossing into the heap) and a query on a live mesh
// (the path a traversal animation calls thousands of times). Every other function goes
// through the very same boundary code (guarded(), error_object, to_typed_array) with
// its own inputs, so 5,000 + 5,000 each already shows a leak of one allocation per call
// (>= 80 KB) 20x above the slack, and the whole file stays at seconds, not minutes
// (a curve evaluation with its checks costs about 40 us per call here; 200,000 of each of
// the 50 cases would take well over ten minutes on these shared 2-core machines).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadBenchCore } from '../../bench/wasm/bench-core.mjs';

// The bench module: the shipped module's bindings, compiled with the same flags, plus the
// benchmark's hooks (two of the calls below); a leak in a binding shows in either.
const { api, hooks } = await loadBenchCore();
const FULL = 100000;
const REDUCED = 5000;
const WARM_UP = 200;
const HEAP_SLACK_BYTES = 4096;
const LINEAR_SLACK_BYTES = 1 << 20;

const tetra = api.generateMesh('tetrahedron');
const nonManifold = { // three triangles on edge v1-v2
  positions: [0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1],
  faces: [[0, 1, 2], [1, 0, 3], [1, 0, 4]],
};
const offText = api.formatMesh(tetra, { format: 'off' });
const objText = api.formatMesh(tetra, { format: 'obj' });
const badOff = offText.replace(/\n3 /, '\n3 x');
const bezier = { kind: 'bezier', dim: 2, points: [0, 0, 1, 2, 3, 2, 4, 0] };
const nurbs = { kind: 'nurbs', dim: 2, degree: 2, points: [1, 0, 1, 1, 0, 1], knots: [0, 0, 0, 1, 1, 1], weights: [1, Math.SQRT1_2, 1] };
const decreasing = { kind: 'bspline', dim: 2, degree: 3, points: [0, 0, 1, 2, 3, 2, 4, 0, 5, 1], knots: [0, 0, 0, 0, 2, 1, 3, 3, 3] };
const zeroWeight = { ...nurbs, weights: [1, 1, 0] };
const params = Float64Array.from({ length: 16 }, (_, j) => j / 15);
const outside = [0.5, 1.5];
const geometry = [0, 0, 1, 2, 3, 2, 4, 0];
// Two cubic segments of 4 entries each (Bezier P0..P3, or Hermite p0, p1, t0, t1).
const chain = [0, 0, 1, 2, 2, 2, 3, 0, 3, 0, 4, -2, 5, 1, 6, 0];
const bspline = { kind: 'bspline', dim: 2, degree: 3, points: [0, 0, 1, 2, 3, 2, 4, 0, 5, 1], knots: [0, 0, 0, 0, 1, 2, 2, 2, 2] };
const following = { kind: 'bezier', dim: 2, points: [4, 0, 5, -2, 7, -2, 8, 0] }; // starts where bezier ends
// A bicubic Bezier patch: p_ij = (i, j, (i - 1.5)(j - 1.5) / 2), points[3*(4*i + j) + k].
const patch = Array.from({ length: 16 }, (_, c) => [Math.floor(c / 4), c % 4, ((Math.floor(c / 4) - 1.5) * ((c % 4) - 1.5)) / 2]).flat();

// The long-lived mesh the query functions run on; disposed at the end.
const lecture = api.buildMesh(api.lectureExample());
const V_MISSING = 1000; // the lecture mesh has 5 vertices, 7 edges and 3 faces

// The lecture mesh's own tables as a student's answer (a wrong wing, so the check
// has a finding to report), and the same with a row cut short (malformed: 'invalid-answer').
const exerciseMesh = { faces: api.lectureExample().faces, vertexCount: 5 };
const exerciseAnswer = (() => {
  const w = lecture.wingedEdgeArrays();
  const edges = Array.from(w.edges);
  edges[4] = edges[5] === 0 ? 1 : 0;
  return { edges, vertexEdges: Array.from(w.vertexEdge), faceEdges: Array.from(w.faceEdge) };
})();
const shortAnswer = { ...exerciseAnswer, edges: exerciseAnswer.edges.slice(1) };

// A mesh already disposed: the methods that take no input (counts, storage, planes...) have
// one failing call, on a mesh that is gone ('disposed').
const gone = api.buildMesh(tetra);
gone.dispose();

// API functions that take no input at all, so no call of them can fail: they get only the
// succeeding calls (the table test below checks they really declare no parameter).
const NO_FAILING_INPUT = ['memoryUsage', 'liveMeshCount', 'lectureExample', 'foleyExample', 'hermiteFromConstraints', 'curveLimits',
  'jointReasons', 'jointClasses'];

// [name, calls of each kind, succeed(), failing calls]. Each failing call is [code, fn]: fn
// calls the function the case names with bad input and must be refused with exactly that
// code, thrown as a WingsplineError or, for the functions that answer with a report
// (validateMesh, check_ operations), returned as { ok: false } carrying the code.
const cases = [
  ['buildMesh + dispose', FULL, () => api.buildMesh(tetra).dispose(), [['non-manifold-edge', () => api.buildMesh(nonManifold)]]],
  // The same build in steps; a refused step ends the core's job (no job is left
  // behind), and so does a cancel.
  ['buildMeshInSteps + dispose', REDUCED, () => { const job = api.buildMeshInSteps(tetra); while (!job.step()); job.mesh.dispose(); api.buildMeshInSteps(tetra).cancel(); },
    [['non-manifold-edge', () => { const job = api.buildMeshInSteps(nonManifold); while (!job.step()); }]]],
  ['parseMesh (OFF)', FULL, () => api.parseMesh(offText, { format: 'off' }), [['parse-error', () => api.parseMesh(badOff, { format: 'off' })]]],
  ['validateMesh', REDUCED, () => api.validateMesh(tetra), [['index-out-of-range', () => api.validateMesh({ positions: [0, 0, 0], faces: [[0, 1, 2]] })]]],
  ['checkWingedEdgeAnswer + workedWingedEdgeAnswer', REDUCED,
    () => { api.checkWingedEdgeAnswer(exerciseMesh, exerciseAnswer); api.workedWingedEdgeAnswer(exerciseMesh, exerciseAnswer); },
    [['invalid-answer', () => api.checkWingedEdgeAnswer(exerciseMesh, shortAnswer)],
      ['invalid-answer', () => api.workedWingedEdgeAnswer(exerciseMesh, shortAnswer)]]],
  ['checkMeshTableAnswer', REDUCED,
    () => { api.checkMeshTableAnswer(exerciseMesh, 'edge-list', { edges: [0, 1, 0, -1], polygons: [[0], [], []] }); },
    [['invalid-answer', () => api.checkMeshTableAnswer(exerciseMesh, 'faces', { faces: [[0, 1, -3], [], []] })]]],
  ['subdivideStencil + checkSubdivideMask', REDUCED,
    () => { api.subdivideStencil(exerciseMesh, { scheme: 'loop', point: { type: 'edge', element: 1 } }); api.checkSubdivideMask(exerciseMesh, { scheme: 'loop', point: { type: 'edge', element: 1 }, mask: 'edge-interior', rows: [{ vertex: 0, num: 1, den: 2 }] }); },
    [['invalid-element', () => api.subdivideStencil(exerciseMesh, { scheme: 'loop', point: { type: 'vertex', element: 99 } })],
      ['invalid-answer', () => api.checkSubdivideMask(exerciseMesh, { scheme: 'loop', point: { type: 'edge', element: 1 }, mask: 'edge-interior', rows: [{ vertex: 0, num: 1, den: 0 }] })]]],
  ['checkSubdivideCounts + subdivisionCounts', REDUCED,
    () => { api.checkSubdivideCounts(exerciseMesh, { scheme: 'loop', vertices: 1, edges: 1, faces: 1 }); api.subdivisionCounts(exerciseMesh, { scheme: 'catmull-clark' }); },
    [['unknown-scheme', () => api.checkSubdivideCounts(exerciseMesh, { scheme: 'nope', vertices: 1, edges: 1, faces: 1 })],
      ['unknown-scheme', () => api.subdivisionCounts(exerciseMesh, { scheme: 'nope' })]]],
  ['checkWalkStep', REDUCED, () => api.checkWalkStep(api.lectureExample(), { around: 'vertex', element: 1, step: 1, given: 4 }),
    [['invalid-step', () => api.checkWalkStep(exerciseMesh, { around: 'vertex', element: 1, step: 9, given: 4 })]]],
  ['halfEdgeEditQuestion + checkHalfEdgeEditAnswer', REDUCED,
    () => {
      const q = api.halfEdgeEditQuestion(api.lectureExample(), [], { op: 'flip-edge', e: 2 });
      const blank = (rows, width) => ({ cells: Array(rows.length * width).fill(-2), removed: rows.map(() => false), labels: [] });
      api.checkHalfEdgeEditAnswer(api.lectureExample(), [], { op: 'flip-edge', e: 2 }, { vertices: blank(q.rows.vertices, 1), halfedges: blank(q.rows.halfedges, 4), faces: blank(q.rows.faces, 1) });
    },
    [['deleted-element', () => api.halfEdgeEditQuestion(api.lectureExample(), [{ op: 'collapse-edge', e: 3 }], { op: 'flip-edge', e: 3 })],
      ['invalid-answer', () => api.checkHalfEdgeEditAnswer(api.lectureExample(), [], { op: 'flip-edge', e: 2 }, { vertices: { cells: [], removed: [], labels: [] }, halfedges: { cells: [], removed: [], labels: [] }, faces: { cells: [], removed: [], labels: [] } })]]],
  ['editQuestion + checkEditAnswer', REDUCED,
    () => { api.editQuestion(api.lectureExample(), [], { op: 'flip-edge', e: 2 }); api.checkEditAnswer(api.lectureExample(), [], { op: 'set-face-edge', f: 0, e: 1 }, { vertices: { cells: [], removed: [], labels: [] }, edges: { cells: [], removed: [], labels: [] }, faces: { cells: [1], removed: [false], labels: [] } }); },
    [['deleted-element', () => api.editQuestion(api.lectureExample(), [{ op: 'collapse-edge', e: 3 }], { op: 'flip-edge', e: 3 })],
      ['invalid-answer', () => api.checkEditAnswer(api.lectureExample(), [], { op: 'flip-edge', e: 2 }, { vertices: { cells: [], removed: [], labels: [] }, edges: { cells: [], removed: [], labels: [] }, faces: { cells: [], removed: [], labels: [] } })]]],
  ['evaluateCurve', REDUCED, () => api.evaluateCurve(nurbs, params), [['decreasing-knots', () => api.evaluateCurve(decreasing, params)]]],
  ['evaluateDerivative', REDUCED, () => api.evaluateDerivative(bezier, params, 1), [['invalid-weight', () => api.evaluateDerivative(zeroWeight, params, 1)]]],
  ['mesh.edgesAroundVertex', FULL, () => lecture.edgesAroundVertex(1), [['invalid-element', () => lecture.edgesAroundVertex(V_MISSING)]]],
  ['mesh.adjacency', REDUCED, () => lecture.adjacency('vertices-of-face', 1),
    [['invalid-element', () => lecture.adjacency('vertices-around-vertex', V_MISSING)], ['unknown-query', () => lecture.adjacency('corners', 1)]]],
  ['parseMesh (OBJ)', REDUCED, () => api.parseMesh(objText, { format: 'obj' }), [['index-out-of-range', () => api.parseMesh('v 0 0 0\nf 1 2 3\n', { format: 'obj' })]]],
  ['formatMesh', REDUCED, () => api.formatMesh(tetra, { format: 'obj' }), [['unknown-format', () => api.formatMesh(tetra, { format: 'ply' })]]],
  ['generateMesh', REDUCED, () => api.generateMesh('sphere', { slices: 8, stacks: 4 }), [['unknown-mesh', () => api.generateMesh('torus')]]],
  ['lectureExample / foleyExample', REDUCED, () => { api.lectureExample(); api.foleyExample(); }, []],
  ['basisMatrix', REDUCED, () => api.basisMatrix('catmull-rom'), [['unknown-basis', () => api.basisMatrix('bezir')]]],
  ['basisMatrixRational', REDUCED, () => api.basisMatrixRational('bspline'), [['unknown-basis', () => api.basisMatrixRational('bsplin')], ['unknown-form', () => api.basisMatrixRational('bspline', 'sideways')]]],
  ['hermiteFromConstraints', REDUCED, () => api.hermiteFromConstraints(), []],
  ['evaluateWithDerivatives', REDUCED, () => api.evaluateWithDerivatives(nurbs, params, 2), [['parameter-out-of-range', () => api.evaluateWithDerivatives(bezier, outside, 2)]]],
  ['curveDomain', REDUCED, () => api.curveDomain(nurbs), [['decreasing-knots', () => api.curveDomain(decreasing)]]],
  ['sampleCurve', REDUCED, () => api.sampleCurve(nurbs, 50), [['invalid-weight', () => api.sampleCurve(zeroWeight, 50)]]],
  ['blendingFunctions', REDUCED, () => api.blendingFunctions(nurbs, params), [['decreasing-knots', () => api.blendingFunctions(decreasing, params)]]],
  ['segmentMatrices', REDUCED, () => api.segmentMatrices(bezier, 0), [['segment-out-of-range', () => api.segmentMatrices(bezier, 5)]]],
  ['deCasteljau', REDUCED, () => api.deCasteljau(geometry, 2, 0.3), [['invalid-weight', () => api.deCasteljau(geometry, 2, 0.3, [1, 1, 0, 1])]]],
  ['subdivideBezier', REDUCED, () => api.subdivideBezier(geometry, 2, 0.5), [['invalid-weight', () => api.subdivideBezier(geometry, 2, 0.5, [1, -1, 1, 1])]]],
  ['bezierSubdivisionMatrices', REDUCED, () => api.bezierSubdivisionMatrices(3, 0.5), [['parameter-out-of-range', () => api.bezierSubdivisionMatrices(3, 1.5)]]],
  ['elevateDegree', REDUCED, () => api.elevateDegree(geometry, 2), [['invalid-weight', () => api.elevateDegree(geometry, 2, [1, 0, 1, 1])]]],
  ['convertBasis', REDUCED, () => api.convertBasis(geometry, 2, 'bezier', 'hermite'), [['unknown-basis', () => api.convertBasis(geometry, 2, 'bezier', 'nurbs')]]],
  ['mesh.wingedEdge / wingedEdgeArrays / faceSet', REDUCED, () => { lecture.wingedEdge(); lecture.wingedEdgeArrays(); lecture.faceSet(); lecture.faceSet({ faces: [2, 0] }); },
    [['disposed', () => gone.wingedEdge()], ['disposed', () => gone.wingedEdgeArrays()], ['disposed', () => gone.faceSet()],
      ['invalid-element', () => lecture.faceSet({ faces: [0, 99] })], ['invalid-argument', () => lecture.faceSet({ faces: [0.5] })]]],
  ['mesh vertex queries', REDUCED, () => { lecture.facesAroundVertex(1); lecture.verticesAroundVertex(1); lecture.traversalSteps(1); },
    [['invalid-element', () => lecture.facesAroundVertex(V_MISSING)], ['invalid-element', () => lecture.verticesAroundVertex(V_MISSING)],
      ['invalid-element', () => lecture.traversalSteps(V_MISSING)]]],
  ['mesh face queries', REDUCED, () => { lecture.edgesOfFace(1); lecture.verticesOfFace(1); lecture.faceNeighbours(1); lecture.faceEdgeSteps(1); },
    [['invalid-element', () => lecture.edgesOfFace(V_MISSING)], ['invalid-element', () => lecture.verticesOfFace(V_MISSING)],
      ['invalid-element', () => lecture.faceNeighbours(V_MISSING)], ['invalid-element', () => lecture.faceEdgeSteps(V_MISSING)]]],
  ['mesh.facesOfEdge', REDUCED, () => lecture.facesOfEdge(2), [['invalid-element', () => lecture.facesOfEdge(V_MISSING)]]],
  ['mesh counts / bytes / validate / ringWalk', REDUCED, () => { lecture.counts(); lecture.bytes(); lecture.validate(); hooks.ringWalk(lecture); },
    [['disposed', () => gone.counts()], ['disposed', () => gone.bytes()], ['disposed', () => gone.validate()], ['disposed', () => hooks.ringWalk(gone)]]],
  ['mesh planes / normals', REDUCED, () => { lecture.planes(); lecture.planeArrays(); lecture.normals(); },
    [['disposed', () => gone.planes()], ['disposed', () => gone.planeArrays()], ['invalid-argument', () => lecture.normals({ into: new Float64Array(1) })]]],
  ['mesh.setVertexPosition', REDUCED, () => lecture.setVertexPosition(4, [2, -1, 0]),
    [['invalid-element', () => lecture.setVertexPosition(V_MISSING, [0, 0, 0])], ['invalid-argument', () => lecture.setVertexPosition(1, [NaN, 0, 0])]]],
  ['hooks.timeBuildInCore', REDUCED, () => hooks.timeBuildInCore(tetra, 1), [['non-manifold-edge', () => hooks.timeBuildInCore(nonManifold, 1)]]],
  // Each succeeding round chooses another stored edge and back (the version moves
  // on, so the representations are derived again: the old ones must be freed). e7 (index 6)
  // touches neither v1 nor F1.
  ['mesh operations', REDUCED, () => {
    lecture.coreVersion(); lecture.checkSetVertexEdge(0, 1); lecture.setVertexEdge(0, 1); lecture.setVertexEdge(0, 0);
    lecture.checkSetFaceEdge(0, 1); lecture.setFaceEdge(0, 1); lecture.apply({ op: 'set-face-edge', f: 0, e: 0 }); lecture.representations({ limit: 2 });
  }, [['disposed', () => gone.coreVersion()], ['edge-not-incident', () => lecture.checkSetVertexEdge(0, 6)],
    ['edge-not-incident', () => lecture.setVertexEdge(0, 6)], ['edge-not-on-face', () => lecture.checkSetFaceEdge(0, 6)],
    ['edge-not-on-face', () => lecture.setFaceEdge(0, 6)], ['edge-not-on-face', () => lecture.apply({ op: 'set-face-edge', f: 0, e: 6 })],
    ['unknown-operation', () => lecture.apply({ op: 'flip-everything' })], ['invalid-argument', () => lecture.representations({ limit: -1 })]]],
  ['deBoor', REDUCED, () => api.deBoor(bspline, 0.5), [['decreasing-knots', () => api.deBoor(decreasing, 0.5)]]],
  ['insertKnot', REDUCED, () => api.insertKnot(bspline, 1.5), [['decreasing-knots', () => api.insertKnot(decreasing, 0.5)]]],
  ['bsplineToBezier', REDUCED, () => api.bsplineToBezier(bspline), [['decreasing-knots', () => api.bsplineToBezier(decreasing)]]],
  ['knotMultiplicities', REDUCED, () => api.knotMultiplicities(bspline), [['decreasing-knots', () => api.knotMultiplicities(decreasing)]]],
  ['segmentAt', REDUCED, () => api.segmentAt(bspline, 1.5), [['decreasing-knots', () => api.segmentAt(decreasing, 0.5)]]],
  ['clampedKnots', REDUCED, () => api.clampedKnots(7, 3), [['too-few-points', () => api.clampedKnots(3, 3)]]],
  ['uniformKnots', REDUCED, () => api.uniformKnots(7, 3), [['invalid-argument', () => api.uniformKnots(3, 3)]]],
  ['unclampedKnots', REDUCED, () => api.unclampedKnots(bspline.knots, 3), [['decreasing-knots', () => api.unclampedKnots(decreasing.knots, 3)]]],
  ['isClampedKnots', REDUCED, () => api.isClampedKnots(bspline.knots, 3), [['wrong-knot-count', () => api.isClampedKnots([0, 1], 3)]]],
  ['isBezierInDisguise', REDUCED, () => api.isBezierInDisguise(bspline.knots, 3), [['wrong-knot-count', () => api.isBezierInDisguise([0, 1], 3)]]],
  ['dragWithConstraint', REDUCED, () => api.dragWithConstraint(chain, 2, 'bezier', 'C2', 2, [2.5, 1.5]),
    [['invalid-argument', () => api.dragWithConstraint(chain, 2, 'bezier', 'C2', 99, [0, 0])]]],
  ['enforceConstraint', REDUCED, () => api.enforceConstraint(chain, 2, 'hermite', 'C2'), [['wrong-point-count', () => api.enforceConstraint(chain.slice(2), 2, 'hermite', 'C2')]]],
  ['appendSegment', REDUCED, () => api.appendSegment(chain, 2, 'bezier', 'G1'), [['invalid-argument', () => api.appendSegment(chain, 2, 'bezier', 'G2')]]],
  ['nurbsCircle / nurbsEllipse', REDUCED, () => { api.nurbsCircle({ center: [0, 0], radius: 1 }); api.nurbsEllipse({ center: [0, 0], rx: 2, ry: 1 }); },
    [['invalid-argument', () => api.nurbsCircle({ center: [0, 0], radius: -1 })], ['invalid-argument', () => api.nurbsEllipse({ center: [0, 0], rx: 0, ry: 1 })]]],
  ['nurbsArc', REDUCED, () => api.nurbsArc({ center: [0, 0], radius: 1, startAngle: 0, endAngle: 2 }),
    [['invalid-argument', () => api.nurbsArc({ center: [0, 0], radius: 1, startAngle: 0, endAngle: 10 })]]],
  ['nurbsConic', REDUCED, () => api.nurbsConic({ p0: [0, 0], p1: [1, 1], p2: [2, 0], weight: 0.5 }),
    [['invalid-weight', () => api.nurbsConic({ p0: [0, 0], p1: [1, 1], p2: [2, 0], weight: -1 })]]],
  ['curvature', REDUCED, () => api.curvature(nurbs, params), [['invalid-weight', () => api.curvature(zeroWeight, params)]]],
  ['arcLength', REDUCED, () => api.arcLength(nurbs), [['decreasing-knots', () => api.arcLength(decreasing)]]],
  ['arcLengthParams', REDUCED, () => api.arcLengthParams(nurbs, 10), [['decreasing-knots', () => api.arcLengthParams(decreasing, 10)]]],
  ['jointContinuity', REDUCED, () => api.jointContinuity(bezier, following, { tolerance: 1e-9 }), [['decreasing-knots', () => api.jointContinuity(bezier, decreasing)]]],
  // Curve exercises (kinds 3-5).
  ['checkJointAnswer + jointReasons + jointClasses', REDUCED,
    () => { api.jointReasons(); api.jointClasses(); api.checkJointAnswer(bezier, following, { parametric: 1, geometric: 1, why: ['meet'] }); },
    [['invalid-argument', () => api.checkJointAnswer(bezier, following, { why: ['tangent'] })],
      ['decreasing-knots', () => api.checkJointAnswer(bezier, decreasing, {})]]],
  ['workedValue + checkValueAnswer', REDUCED,
    () => { api.workedValue({ curve: bspline }, { quantity: 'boehm', u: 0.5, index: 2 }); api.checkValueAnswer({ curve: bezier }, { quantity: 'blend', i: 1, u: 0.5 }, [0.4], 0.001); },
    [['invalid-argument', () => api.checkValueAnswer({ curve: bezier }, { quantity: 'blend', i: 9, u: 0.5 }, [0.4], 0.001)],
      ['parameter-out-of-range', () => api.workedValue({ curve: bezier }, { quantity: 'point', u: 1.5 })]]],
  ['checkCurveProperty', REDUCED,
    () => { api.checkCurveProperty({ a: bezier, b: following }, { kind: 'joint-class', parametric: 1 }); api.checkCurveProperty({ curve: bezier }, { kind: 'passes-through', point: [2, 1], tolerance: 0.01 }); },
    [['degenerate-curve', () => api.checkCurveProperty({ curve: { kind: 'bezier', dim: 2, points: [1, 1, 1, 1] } }, { kind: 'passes-through', point: [0, 0], tolerance: 0.1 })],
      ['invalid-argument', () => api.checkCurveProperty({ a: bezier, b: following }, { kind: 'joint-class', geometric: 5 })]]],
  ['cubicDerivation', REDUCED, () => api.cubicDerivation('bspline'), [['unsupported-curve-kind', () => api.cubicDerivation('catmull-rom')]]],
  ['interpolatePolynomial', REDUCED, () => api.interpolatePolynomial(geometry, 2),
    [['nodes-not-increasing', () => api.interpolatePolynomial(geometry, 2, [0, 1, 1, 2])], ['nodes-too-close', () => api.interpolatePolynomial(geometry, 2, [0, 1e-12, 1, 2])]]],
  ['curveLimits', REDUCED, () => api.curveLimits(), []],
  ['chainGuarantees / bsplineGuarantees', REDUCED, () => { api.chainGuarantees({ basis: 'bezier', slots: 4, isPoint: [true, true, true, true], maps: [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]] }); api.bsplineGuarantees({ knots: [0, 1, 2, 3, 4, 5, 6, 7], degree: 3, count: 4 }); },
    [['invalid-argument', () => api.chainGuarantees({ basis: 'bezier', slots: 4, isPoint: [true, true, true, true], maps: [] })],
      ['decreasing-knots', () => api.bsplineGuarantees({ knots: [0, 1, 0.5, 2, 3, 4, 5, 6], degree: 3, count: 4 })]]],
  ['samplePatch', REDUCED, () => api.samplePatch({ kind: 'bezier', points: patch, nu: 4, nv: 4 }),
    [['wrong-point-count', () => api.samplePatch({ kind: 'bezier', points: patch.slice(3), nu: 4, nv: 4 })]]],
  ['transformPoints', REDUCED, () => api.transformPoints(geometry, 2, [0, -1, 1, 1, 0, 2, 0, 0, 1]), [['invalid-argument', () => api.transformPoints(geometry, 2, [1, 0, 0, 1])]]],
  ['mesh.storage / representations', REDUCED, () => { lecture.storage(); lecture.representations({ limit: 3 }); },
    [['disposed', () => gone.storage()], ['invalid-argument', () => lecture.representations({ limit: -1 })]]],
  ['mesh.tables', REDUCED, () => { lecture.tables('edge-list', { offset: 1, limit: 2 }); lecture.tables('winged-edge'); },
    [['invalid-argument', () => lecture.tables('edge-list', { offset: -1 })], ['unknown-representation', () => lecture.tables('wingededge')]]],
  ['mesh.boundingBox / vertexNormal', REDUCED, () => { lecture.boundingBox(); lecture.vertexNormal(1); },
    [['disposed', () => gone.boundingBox()], ['invalid-element', () => lecture.vertexNormal(V_MISSING)]]],
  // Picking and the display proxy of a big mesh.
  ['mesh.pick / displayProxy', REDUCED, () => { lecture.pick([1, 0.5, 0], [0, 0, 1], { radius: 0.1 }); lecture.displayProxy(2); },
    [['invalid-argument', () => lecture.pick([1, 0.5, 0], [0, 0, 0])], ['invalid-argument', () => lecture.displayProxy(0)]]],
  ['mesh.query', REDUCED, () => lecture.query('faces-around-vertex', 1),
    [['invalid-element', () => lecture.query('faces-around-vertex', V_MISSING)], ['unknown-query', () => lecture.query('faces-of-vertex', 1)]]],
  // The half-edge view, made once per topology version and kept in the mesh's entry.
  ['mesh half-edge view', REDUCED, () => {
    lecture.halfEdge(); lecture.halfEdgeArrays({ offset: 2, limit: 4 }); lecture.halfEdgeTraversalSteps(1); lecture.halfEdgeFaceSteps(1);
    lecture.halfEdgeQuery('edges-of-face', 1); lecture.halfEdgeStorage(); lecture.lastHalfEdgeChange();
  }, [['disposed', () => gone.halfEdge()], ['disposed', () => gone.lastHalfEdgeChange()], ['invalid-argument', () => lecture.halfEdgeArrays({ offset: -1 })],
    ['invalid-element', () => lecture.halfEdgeTraversalSteps(V_MISSING)], ['invalid-element', () => lecture.halfEdgeFaceSteps(V_MISSING)],
    ['invalid-element', () => lecture.halfEdgeQuery('edges-of-face', V_MISSING)], ['disposed', () => gone.halfEdgeStorage()]]],
  ['hooks.timeNormalsInCore', REDUCED, () => hooks.timeNormalsInCore(lecture, 1), [['invalid-argument', () => hooks.timeNormalsInCore(lecture, 0)]]],
  // The measurements the lessons ask the core for.
  ['convexHull / mapPoints / maxDistance', REDUCED, () => { api.convexHull(geometry, 2); api.mapPoints(geometry, 2, { kind: 'perspective', px: 0.01 }); api.maxDistance(geometry, geometry, 2); },
    [['non-finite-input', () => api.convexHull([0, 0, NaN, 1], 2)], ['perspective-behind-eye', () => api.mapPoints(geometry, 2, { kind: 'perspective', px: -10 })],
      ['invalid-argument', () => api.maxDistance(geometry, geometry.slice(2), 2)]]],
  ['comparison checks', REDUCED, () => { api.blendingWeightCheck([bezier], 5); api.pointCurveDistances(geometry, 2, [bezier], 5); api.splitCheck([bezier]); api.knotRefinementCheck(bspline, 5); },
    [['invalid-weight', () => api.blendingWeightCheck([zeroWeight], 5)], ['invalid-weight', () => api.pointCurveDistances(geometry, 2, [zeroWeight], 5)],
      ['invalid-argument', () => api.splitCheck([nurbs])], ['invalid-weight', () => api.knotRefinementCheck(zeroWeight, 5)]]],
  ['catmullRomTangents', REDUCED, () => api.catmullRomTangents(geometry, 2), [['too-few-points', () => api.catmullRomTangents([0, 0], 2)]]],
  ['convertPatchBasis', REDUCED, () => api.convertPatchBasis(patch, 'bezier', 'hermite'), [['wrong-point-count', () => api.convertPatchBasis(patch.slice(3), 'bezier', 'hermite')]]],
  ['curvatureComb / homogeneousLift', REDUCED, () => { api.curvatureComb(nurbs, params); api.homogeneousLift(geometry, 2, [1, 2, 1, 1]); },
    [['invalid-weight', () => api.curvatureComb(zeroWeight, params)], ['wrong-weight-count', () => api.homogeneousLift(geometry, 2, [1, 2])]]],
  ['patchCornerCheck / patchJoinCheck', REDUCED, () => { api.patchCornerCheck({ kind: 'bezier', points: patch }); api.patchJoinCheck({ kind: 'bezier', a: patch, b: patch, samples: 4 }); },
    [['wrong-point-count', () => api.patchCornerCheck({ kind: 'bezier', points: patch.slice(3) })], ['wrong-point-count', () => api.patchJoinCheck({ kind: 'bezier', a: patch, b: patch.slice(3) })]]],
  // The Euler operations (a fresh lecture mesh per call: the edits grow it).
  ['mesh editing', REDUCED, () => {
    const lecture = api.buildMesh(api.lectureExample());
    try {
      lecture.check('flip-edge', 4); lecture.flipEdge(4); lecture.splitEdge(2); lecture.splitFace(0, 5, 0); lecture.joinFaces(7);
      lecture.pokeFace(2); lecture.undo(); lecture.pokeFace(2); lecture.collapseEdge(8, 0);
      lecture.gaps(); lecture.format(); lecture.compact();
    } finally {
      lecture.dispose();
    }
  }, [['unknown-operation', () => lecture.check('flip-edgy', 0)], ['boundary-edge', () => lecture.flipEdge(0)], ['invalid-parameter', () => lecture.splitEdge(2, 1.5)],
    ['adjacent-corners', () => lecture.splitFace(0, 0, 1)], ['boundary-edge', () => lecture.joinFaces(0)], ['invalid-element', () => lecture.pokeFace(V_MISSING)],
    ['invalid-element', () => lecture.collapseEdge(V_MISSING)], ['disposed', () => gone.compact()], ['disposed', () => gone.gaps()],
    ['unknown-format', () => lecture.format({ format: 'stl' })], ['cannot-undo', () => { const fresh = api.buildMesh(tetra); try { fresh.undo(); } finally { fresh.dispose(); } }], ['disposed', () => gone.undo()]]],
  // Subdivision of meshes and curves.
  ['subdivide + dispose / subdivisionSteps / reconnectionPlayback / limitPositions', REDUCED, () => {
    api.subdivide(lecture, { scheme: 'catmull-clark', steps: 2 }).dispose();
    api.subdivisionSteps(lecture, { scheme: 'catmull-clark' });
    api.reconnectionPlayback(lecture, { scheme: 'catmull-clark' });
    api.limitPositions(lecture, { scheme: 'catmull-clark' });
  }, [['too-large', () => api.subdivide(lecture, { scheme: 'catmull-clark', steps: 16 })], ['unknown-scheme', () => api.subdivisionSteps(lecture, { scheme: 'nope' })],
    ['unknown-scheme', () => api.reconnectionPlayback(lecture, { scheme: 'nope' })], ['unknown-scheme', () => api.limitPositions(lecture, { scheme: 'nope' })]]],
  // An edit's cost against mesh size, measured by the core on small grids.
  ['queryCostGrowth', REDUCED, () => api.queryCostGrowth('faces-around-vertex', [4, 8]),
    [['invalid-argument', () => api.queryCostGrowth('edges-of-face', [5])], ['unknown-query', () => api.queryCostGrowth('faces-of-face', [4])]]],
  ['editCostGrowth', REDUCED, () => api.editCostGrowth('flip-edge', [4, 8]),
    [['invalid-argument', () => api.editCostGrowth('flip-edge', [3])], ['unknown-operation', () => api.editCostGrowth('flip-edgy', [4])]]],
  ['subdivideCurve', REDUCED, () => api.subdivideCurve(geometry, 2, { scheme: 'cubic-bspline', closed: true, steps: 3 }),
    [['too-few-points', () => api.subdivideCurve(geometry.slice(0, 2), 2, { scheme: 'chaikin' })]]],
  ['memoryUsage / liveMeshCount', REDUCED, () => { api.memoryUsage(); api.liveMeshCount(); }, []],
];

// The code a failing call was refused with, or null when it was not refused.
function refusal(fn, label) {
  let r;
  try {
    r = fn();
  } catch (err) {
    if (!(err instanceof Error) || typeof err.code !== 'string') throw new Error(`${label}: threw ${String(err)}`);
    return err.code;
  }
  if (r && r.ok === false) return r.code ?? r.problems?.[0]?.code ?? null;
  return null;
}

function run(fn, count) {
  for (let i = 0; i < count; i += 1) fn();
}

function runFailing(failing, count, label) {
  for (const [code, fn] of failing) {
    for (let i = 0; i < count; i += 1) {
      const got = refusal(fn, label);
      if (got !== code) throw new Error(`${label}: ${fn} was refused with ${got}, expected ${code}`);
    }
  }
}

test('the table covers every function of the API and of a mesh, each with a failing call that calls it', () => {
  const succeedText = cases.map(([, , ok]) => String(ok)).join('\n');
  const failText = cases.flatMap(([, , , bad]) => bad.map(([, fn]) => String(fn))).join('\n');
  const functions = Object.keys(api).filter((k) => typeof api[k] === 'function');
  assert.deepEqual(functions.filter((k) => !succeedText.includes(`api.${k}(`)), [], 'API functions without a succeeding call');
  assert.deepEqual(functions.filter((k) => !NO_FAILING_INPUT.includes(k) && !failText.includes(`api.${k}(`)), [],
    'API functions without a failing call of their own');
  assert.deepEqual(NO_FAILING_INPUT.filter((k) => api[k].length !== 0), [], 'functions said to take no input declare parameters');
  const methods = Object.getOwnPropertyNames(Object.getPrototypeOf(lecture))
    .filter((k) => k !== 'constructor' && k !== 'dispose')
    // Getters (disposed, id, version) are read, not called.
    .filter((k) => !Object.getOwnPropertyDescriptor(Object.getPrototypeOf(lecture), k).get);
  assert.deepEqual(methods.filter((k) => !succeedText.includes(`lecture.${k}(`)), [], 'Mesh methods without a succeeding call');
  assert.deepEqual(methods.filter((k) => !failText.includes(`lecture.${k}(`) && !failText.includes(`gone.${k}(`)), [],
    'Mesh methods without a failing call of their own');
});

for (const [name, count, succeed, failing] of cases) {
  const what = failing.length > 0 ? `${count} succeeding and ${count} failing calls (each refused with its own code)`
    : `${count} succeeding calls (no input, so no failing call)`;
  test(`${name}: ${what} do not grow the heap`, () => {
    run(succeed, WARM_UP);
    runFailing(failing, WARM_UP, name);
    const before = api.memoryUsage();
    run(succeed, count);
    runFailing(failing, count, name);
    const after = api.memoryUsage();
    assert.ok(Math.abs(after.heapInUse - before.heapInUse) <= HEAP_SLACK_BYTES,
      `bytes in use went from ${before.heapInUse} to ${after.heapInUse}`);
    assert.ok(after.linearBytes - before.linearBytes <= LINEAR_SLACK_BYTES,
      `linear memory went from ${before.linearBytes} to ${after.linearBytes}`);
    assert.equal(api.liveMeshCount(), 1, 'only the shared lecture mesh is alive');
  });
}

test('after all of it the module is exact and, once the last mesh is disposed, nothing is alive', () => {
  // Lecture 000: CCW around v2 is e6, e5, e3, e2 (0-based 5, 4, 2, 1).
  assert.deepEqual(Array.from(lecture.edgesAroundVertex(1)), [5, 4, 2, 1]);
  // The NURBS quarter circle: every point at distance 1 from the origin.
  const p = api.evaluateCurve(nurbs, params);
  for (let j = 0; j < params.length; j += 1) assert.ok(Math.abs(Math.hypot(p[2 * j], p[2 * j + 1]) - 1) < 1e-12);
  lecture.dispose();
  assert.equal(api.liveMeshCount(), 0);
});
