// @ts-check
// The subdivision lesson (lecture 000's "how to refine the mesh"): one Loop or
// Catmull-Clark step at a time, phase by phase (face points, edge points, vertex points,
// reconnection), each new point with its mask drawn on the old mesh; levels 0..5, limit
// positions, flat or smooth shading; beside it the same averaging on a control polygon
// (Chaikin, cubic Lane-Riesenfeld) converging to its B-spline. Every position, weight,
// valence and count is the core's (api.subdivide, subdivisionSteps, limitPositions,
// subdivideCurve, sampleCurve); this file keeps the state and arranges what the core returned.
import { number, integer, boolean, oneOf, text, list, object, nullable, viewSchema } from '../../app/schema.js';
import { MAX_MESH_VERTICES, MAX_MESH_FACES, MAX_FACE_CORNERS } from '../../app/limits.js';
import { importedMesh, importedCsr } from '../../app/imported-mesh.js';
import { importedArrays } from '../../app/mesh-import.js';
import { viewRotation, projectAll, unprojectDelta, fitProjected } from '../../ui/mesh/view.js';
import { sourceKey, createImportedKeys, hashNumbers } from '../../ui/mesh/mesh-choice.js';
import { SOURCES, SIZES, IMPORTED_FIELD, PHASES, MAX_LEVEL, meshInput, label, viewOf } from './source.js';
import { setupPanels } from './panels.js';
import { drawScene, pointAt } from './draw.js';
import { subdivisionExercise } from './exercise.js';

// The control polygon of the curve beside the mesh (x, y) as it starts: a zigzag, so the two
// schemes can be compared on the same points; the person drags its points (state.curve).
const CURVE_POLYGON = Object.freeze([0, 0, 1, 2, 2.5, 2.2, 3, 0.2, 4.2, 0.4, 5, 2.4, 6.2, 1.6]);
const CURVE_SAMPLES = 240;
// Coordinates of the curve's points stay within +-CURVE_EXTENT; 4..32 points (4: the fewest
// an open cubic polygon may have, docs/api-curves.md; 32: its cubic B-spline's K + p + 1
// knots fit the curve explorer's 40, for the link there).
const CURVE_EXTENT = 1000;
const CURVE_MAX_POINTS = 32;
// The core has no periodic B-spline evaluation: the closed limit is drawn as the core's
// closed subdivision after CLOSED_LIMIT_STEPS steps (n points -> 256 n), whose distance to the
// limit shrinks about 4x per step (docs/api-curves.md), far below a pixel.
const CLOSED_LIMIT_STEPS = 8;
// The reconnection is played pointer by pointer up to this many old faces (Loop: about 8 x
// (2E + 3F) assignments, some 24,000 at 500 faces); a bigger level shows its finished tables.
export const PLAYBACK_FACES = 500;

const size = (bounds) => integer({ min: bounds[0], max: bounds[1] });
const schema = {
  meshKind: oneOf(...SOURCES.map((s) => s.id)),
  sphere: object({ slices: size(SIZES.sphere[0]), stacks: size(SIZES.sphere[1]) }),
  grid: object({ nx: size(SIZES.grid[0]), ny: size(SIZES.grid[1]) }),
  // Either form of app/imported-mesh.js (flat in the current format; faces: older states and links).
  imported: nullable(importedMesh({ maxVertices: MAX_MESH_VERTICES, maxFaces: MAX_MESH_FACES, maxCorners: MAX_FACE_CORNERS })),
  // Control vertices (level 0) the person moved: where they are now.
  moved: list(object({ v: integer({ min: 0, max: 10000000 }), p: list(number(), { min: 3, max: 3 }) }), { max: 100000 }),
  scheme: oneOf('loop', 'catmull-clark'),
  level: integer({ min: 0, max: MAX_LEVEL }),
  phase: integer({ min: 0, max: PHASES.length }),
  // The new point whose mask is drawn (-1: the first point of the newest phase shown).
  focus: integer({ min: -1, max: 10000000 }),
  // The reconnection played pointer by pointer: how many assignments are shown (-1: all,
  // the next level's finished tables).
  reconnect: integer({ min: -1, max: 10000000 }),
  limit: boolean(),
  shading: oneOf('flat', 'smooth'),
  curveScheme: oneOf('chaikin', 'cubic-bspline'),
  curve: object({ points: list(number({ min: -CURVE_EXTENT, max: CURVE_EXTENT }), { min: 8, max: 2 * CURVE_MAX_POINTS }), closed: boolean() }),
  rotation: object({ yaw: number({ min: -100, max: 100 }), pitch: number({ min: -100, max: 100 }) }),
  view: viewSchema(),
};

function defaultState() {
  return {
    meshKind: 'tetrahedron',
    sphere: { slices: 12, stacks: 6 },
    grid: { nx: 4, ny: 3 },
    imported: null,
    moved: [],
    scheme: 'loop',
    level: 0,
    phase: 0,
    focus: -1,
    reconnect: -1,
    limit: false,
    shading: 'flat',
    curveScheme: 'cubic-bspline',
    curve: { points: [...CURVE_POLYGON], closed: false },
    rotation: viewOf('tetrahedron'),
    view: { cx: 0, cy: 0, zoom: 150 },
  };
}

function checkState(state) {
  if (state.meshKind === 'file' && !state.imported) return 'the state names an imported mesh but does not hold it';
  if (state.curve.points.length % 2) return 'the curve\'s points need an x and a y each';
  return null;
}

// ------------------------------------------------------------------ the chain of levels
// One chain per (mesh, scheme): levels[k] is the core's mesh after k steps, steps[k] its
// next step as phases and masks (or the core's refusal), derived[k] what the drawing and
// the tables read of it. A chain that another mesh or scheme replaces is disposed only
// after the new one was accepted, so a refused choice keeps the page's meshes alive.
function emptyChain(key) {
  return { key, levels: [], steps: [], derived: [], playbacks: [] };
}

function disposeChain(chain) {
  for (const mesh of chain.levels) mesh?.dispose();
  chain.levels = [];
}

function levelOf(chain, k, scheme, api) {
  for (let i = chain.levels.length; i <= k; i += 1) {
    try {
      chain.levels.push(api.subdivide(chain.levels[i - 1], { scheme, steps: 1 }));
    } catch (err) {
      err.message = `Level ${i} is refused: ${err.message}`;
      throw err;
    }
  }
  return chain.levels[k];
}

// The next step of level k as the core teaches it, or its refusal ({error}).
function stepsOf(chain, k, scheme, api) {
  if (!chain.steps[k]) {
    try {
      chain.steps[k] = { value: api.subdivisionSteps(chain.levels[k], { scheme }) };
    } catch (err) {
      if (!err.code) throw err;
      chain.steps[k] = { error: err };
    }
  }
  return chain.steps[k];
}

// Level k's reconnection as the core's pointer assignments (api.reconnectionPlayback), once,
// for a level small enough to step through (PLAYBACK_FACES); null above it.
function playbackOf(chain, k, scheme, api) {
  if (chain.levels[k].counts().faces > PLAYBACK_FACES) return null;
  if (!chain.playbacks[k]) {
    const playback = api.reconnectionPlayback(chain.levels[k], { scheme });
    // Which step writes each entry ("edge:12:startLeft" -> step), for the tables' cells.
    const firstWrite = new Map();
    playback.steps.forEach((s, i) => firstWrite.set(`${s.table}:${s.row}:${s.field}`, i));
    chain.playbacks[k] = { ...playback, firstWrite };
  }
  return chain.playbacks[k];
}

// What the page reads of one level's mesh, once: positions, faces, counts, winged-edge
// arrays, face normals; smooth normals and limit positions when first asked.
function derivedOf(chain, k) {
  if (!chain.derived[k]) {
    const mesh = chain.levels[k];
    const faces = mesh.tables('vertex-face-tables').faces.arrays;
    chain.derived[k] = {
      mesh,
      we: mesh.wingedEdgeArrays(),
      faceOffsets: faces.faceOffsets,
      faceVertices: faces.faceVertices,
      counts: mesh.counts(),
      normals: mesh.normals(),
      vertexNormals: null,
      limit: null,
    };
  }
  return chain.derived[k];
}

function vertexNormalsOf(d) {
  if (!d.vertexNormals) {
    const V = d.we.positions.length / 3;
    const out = new Float64Array(3 * V);
    for (let v = 0; v < V; v += 1) out.set(d.mesh.vertexNormal(v), 3 * v);
    d.vertexNormals = out;
  }
  return d.vertexNormals;
}

// Per face of the drawing: its normal (flat) or its corners' normals (smooth), as the core
// gave them; the drawing turns them into a shade.
function shadingOf(d, shading) {
  return shading === 'smooth' ? { kind: 'smooth', normals: vertexNormalsOf(d) } : { kind: 'flat', normals: d.normals };
}

function compute(view, state, ctx) {
  const api = ctx.api;
  const base = sourceKey(state, view.importedKey);
  const key = `${base}|${hashNumbers(state.moved.flatMap((m) => [m.v, ...m.p]))}|${state.scheme}`;
  const fresh = view.chain?.key !== key;
  const chain = fresh ? emptyChain(key) : view.chain;
  try {
    if (fresh) chain.levels.push(api.buildMesh(meshInput(state, api)));
    // The view turns about the centre of the mesh as first built (moving a vertex does not
    // move the view).
    if (view.centre?.key !== base) view.centre = { key: base, value: chain.levels[0].boundingBox().centre };
    const model = modelOf(view, chain, state, api);
    if (fresh) {
      if (view.chain) disposeChain(view.chain);
      view.chain = chain;
    }
    return model;
  } catch (err) {
    if (fresh) disposeChain(chain);
    view.lastRefusal = { code: err.code ?? null, message: err.message, state };
    throw err;
  }
}

function modelOf(view, chain, state, api) {
  const { level, scheme } = state;
  levelOf(chain, level, scheme, api);
  const steps = stepsOf(chain, level, scheme, api);
  // Loop's refusal of a face that is not a triangle holds for every level and phase.
  if (steps.error?.code === 'not-a-triangle-mesh') throw steps.error;
  if (state.phase > 0 && steps.error) throw Object.assign(new Error(`Level ${level + 1} is refused: ${steps.error.message}`), { code: steps.error.code });
  const old = derivedOf(chain, level);
  const reconnected = state.phase >= PHASES.length;
  if (reconnected) levelOf(chain, level + 1, scheme, api);
  const shown = reconnected ? derivedOf(chain, level + 1) : old;
  if (state.limit && !shown.limit) shown.limit = api.limitPositions(shown.mesh, { scheme });
  const positions = state.limit ? shown.limit : shown.we.positions;
  const R = viewRotation({ mode3d: true, rotation: state.rotation });
  const centre = view.centre.value;
  const control = derivedOf(chain, 0);
  const s = steps.value ?? null;
  const phases = s ? s.phases : [];
  const shownPhases = phases.slice(0, state.phase);
  const pointPhases = shownPhases.filter((p) => p.name !== 'reconnection' && p.count > 0);
  const focus = focusOf(state.focus, pointPhases);
  return {
    scheme,
    level,
    phase: state.phase,
    mesh: shown.mesh,          // the mesh shown (the next level once reconnected)
    levelMesh: old.mesh,       // the level's own mesh (exports)
    we: shown.we,
    counts: shown.counts,
    levelCounts: old.counts,
    nextCounts: s ? s.counts : null,
    faceOffsets: shown.faceOffsets,
    faceVertices: shown.faceVertices,
    projected: projectAll(positions, R, centre),
    // What the GPU picture uploads once per mesh shown (ui/gl-mesh.js): its positions, the
    // centre the view turns about, and the key that changes with them.
    positions,
    centre,
    glKey: `${shown.mesh.id}.${shown.mesh.version}|${state.limit}|${state.shading}|${centre.join(',')}`,
    oldProjected: reconnected ? null : (state.limit ? projectAll(old.we.positions, R, centre) : null),
    newProjected: s && !reconnected && pointPhases.length ? projectAll(s.positions, R, centre) : null,
    rotation: R,
    // The control mesh (level 0): its vertices are the handles.
    control: { positions: control.we.positions, edges: control.we.edges, projected: level === 0 && !reconnected && !state.limit ? null : projectAll(control.we.positions, R, centre) },
    shading: shadingOf(shown, state.shading),
    limit: state.limit,
    steps: s,
    stepsRefusal: steps.error?.message ?? null,
    phases,
    shownPhases,
    pointPhases,
    focus,
    extraordinary: s && !reconnected ? extraordinaryOf(s, scheme) : [],
    interiorVertices: s ? interiorCount(s) : 0,
    reconnection: reconnected ? reconnectionOf(playbackOf(chain, level, scheme, api), state.reconnect, old.counts.faces) : null,
    sourceKey: view.centre.key, // the mesh chosen (not its moved vertices nor the scheme)
    curve: curveOf(api, state, reconnected ? level + 1 : level),
  };
}

// The new point whose mask is drawn: the chosen one if its phase is shown, else the first
// point of the newest phase shown.
function focusOf(focus, pointPhases) {
  if (!pointPhases.length) return -1;
  if (focus >= 0 && pointPhases.some((p) => focus >= p.first && focus < p.first + p.count)) return focus;
  return pointPhases[pointPhases.length - 1].first;
}

// Interior old vertices whose valence (the core's count of edges at the vertex) is not the
// scheme's regular one: 6 for Loop, 4 for Catmull-Clark.
function extraordinaryOf(s, scheme) {
  const regular = scheme === 'loop' ? 6 : 4;
  const interior = s.ruleNames.indexOf('vertex-interior');
  const out = [];
  for (let v = 0; v < s.valences.length; v += 1) {
    if (s.rules[v] === interior && s.valences[v] !== regular) out.push({ v, n: s.valences[v] });
  }
  return out;
}

// The reconnection's playback as shown: {lines, steps, sources, firstWrite, shown} (shown: how many
// assignments are made, all when the state says -1), or {tooBig: faces} above PLAYBACK_FACES.
function reconnectionOf(playback, reconnect, faces) {
  if (!playback) return { tooBig: faces };
  const n = playback.steps.length;
  return { ...playback, shown: reconnect < 0 || reconnect > n ? n : reconnect };
}

// How many old vertices take the interior vertex rule (the core's rule per vertex): a mesh
// whose vertices are all on the boundary has none, and so no extraordinary vertex either.
function interiorCount(s) {
  const interior = s.ruleNames.indexOf('vertex-interior');
  let n = 0;
  for (let v = 0; v < s.valences.length; v += 1) if (s.rules[v] === interior) n += 1;
  return n;
}

// The curve beside the mesh: the polygon after as many steps as the mesh's level, and the
// B-spline they converge to (uniform knots, degree 2 for Chaikin, 3 for the cubic rule).
// A closed polygon's limit is the periodic B-spline, drawn as many closed steps (above).
function curveOf(api, state, steps) {
  const { closed } = state.curve;
  const points = Float64Array.from(state.curve.points);
  const degree = state.curveScheme === 'chaikin' ? 2 : 3;
  const scheme = state.curveScheme;
  const refined = api.subdivideCurve(points, 2, { scheme, closed, steps });
  const limit = closed
    ? api.subdivideCurve(points, 2, { scheme, closed, steps: CLOSED_LIMIT_STEPS })
    : api.sampleCurve({ kind: 'bspline', dim: 2, degree, points, knots: api.uniformKnots(points.length / 2, degree) }, CURVE_SAMPLES).points;
  return { control: points, refined, limit, steps, degree, closed };
}

// The control vertices are the handles (up to HANDLE_LIMIT of them): drag one, or select it
// with ] and move it with the arrows, and every level follows.
const HANDLE_LIMIT = 400;
const controlProjected = (model) => model.control.projected ?? model.projected;

function handles(view, model) {
  if (!model || model.control.positions.length / 3 > HANDLE_LIMIT) return [];
  const P = controlProjected(model);
  const out = [];
  for (let v = 0; 3 * v < P.length; v += 1) out.push({ id: `v${v}`, x: P[3 * v], y: P[3 * v + 1], label: `control vertex ${label('vertex', v)}` });
  return out;
}

// A control vertex dragged in the view plane moves by R^T (dx, dy, 0) in the world.
function moveHandle(view, state, id, x, y, model) {
  const v = Number(id.slice(1));
  const P = controlProjected(model);
  if (!Number.isInteger(v) || 3 * v >= P.length) return null;
  const [dx, dy, dz] = unprojectDelta(model.rotation, x - P[3 * v], y - P[3 * v + 1]);
  const c = model.control.positions;
  const p = [c[3 * v] + dx, c[3 * v + 1] + dy, c[3 * v + 2] + dz];
  return { ...state, moved: state.moved.filter((m) => m.v !== v).concat([{ v, p }]) };
}

const fitView = (view, model, stage) => (model ? fitProjected(model.projected, stage, 0.2) : defaultState().view);

const SCHEME_NAMES = { loop: 'Loop', 'catmull-clark': 'Catmull-Clark' };

function describe(view, model, state) {
  if (!model) return 'No mesh.';
  const kind = SOURCES.find((k) => k.id === state.meshKind)?.label ?? state.meshKind;
  const c = model.counts;
  const phase = model.shownPhases.length ? ` Step to level ${model.level + 1}: ${model.shownPhases.map((p) => p.name.replace('-', ' ')).join(', ')} shown.` : '';
  return `${kind}, ${SCHEME_NAMES[state.scheme]} subdivision, level ${state.level}: ${c.vertices} vertices, ${c.edges} edges, ${c.faces} faces.${phase}`;
}

// OFF and OBJ files: the import worker (app/mesh-import.js) has the core parse them (its
// message names the line) and report every problem; the first error refuses the file and the
// page keeps its mesh.
function importMesh(view, { value, problems }, state, name, ctx) {
  const errors = problems.filter((p) => p.severity === 'error');
  if (errors.length) throw Object.assign(new Error(`${name}: ${errors[0].message}`), { code: errors[0].code });
  const next = { ...state, meshKind: 'file', imported: value, moved: [], level: 0, phase: 0, focus: -1 };
  if (state.scheme === 'loop') refuseUnderLoop(value, next, ctx);
  return next;
}

// Loop refuses a mesh with a face that is not a triangle: the import is refused as the
// built-in cube is, with the core's message (it names the face) and the offer of
// Catmull-Clark. The core is asked only when some face has another number of corners.
function refuseUnderLoop(imported, next, ctx) {
  const mesh = importedArrays(imported) ?? importedCsr(imported);
  const { faceOffsets } = mesh;
  let triangles = true;
  for (let f = 0; f + 1 < faceOffsets.length && triangles; f += 1) triangles = faceOffsets[f + 1] - faceOffsets[f] === 3;
  if (triangles) return;
  const built = ctx.api.buildMesh(mesh);
  try {
    ctx.api.subdivisionSteps(built, { scheme: 'loop' });
  } catch (err) {
    if (err.code !== 'not-a-triangle-mesh') throw err;
    const run = () => { if (ctx.commit({ ...next, scheme: 'catmull-clark' })) queueMicrotask(() => ctx.fitView()); };
    throw Object.assign(new Error(err.message), { code: err.code, offer: { id: 'use-catmull-clark', label: 'Use Catmull-Clark', run } });
  } finally {
    built.dispose();
  }
}

const meshFile = (format) => ({
  label: `Mesh of this level (${format.toUpperCase()})`,
  filename: (state) => `subdivision-level${state.level}.${format}`,
  type: 'text/plain',
  make: (view, model) => model.levelMesh.format({ format }),
});

/** @type {import('../../app/contract.js').Lesson} */
export const subdivisionLesson = {
  id: 'subdivision',
  title: 'Subdivision',
  // The core modules the page loads (docs/architecture.md, "Module size").
  core: ['subdivision'],
  stateVersion: 3,
  exercise: subdivisionExercise,
  // Version 2 holds the curve's polygon (it was fixed before): a version-1 link gets it.
  // Version 3 holds the reconnection's playback step: an older state shows the finished tables.
  migrations: { 1: (old) => ({ ...old, curve: { points: [...CURVE_POLYGON], closed: false } }), 2: (old) => ({ ...old, reconnect: -1 }) },
  schema,
  defaultState,
  checkState,
  contentFields: IMPORTED_FIELD,
  inspector: false,
  setup(ctx) {
    const view = { chain: null, centre: null, importedKey: createImportedKeys(), lastRefusal: null, rotating: null, panels: null };
    view.panels = setupPanels(ctx, view);
    return view;
  },
  compute,
  update: (view, model, state) => view.panels.update(model, state),
  draw: (view, painter, model, state, ctx) => drawScene(painter, model, state, ctx),
  afterFrame: (view, model, state, ctx) => view.panels.curvePlot.draw(model, ctx.colors),
  describe,
  // One line for the History.
  summarize: (state) => `${state.scheme === 'loop' ? 'Loop' : 'Catmull-Clark'} on ${state.meshKind === 'file' ? `"${state.imported?.name ?? 'an imported mesh'}"` : state.meshKind}, level ${state.level}`,
  fitView,
  handles,
  moveHandle,
  click(view, x, y, ctx, event) {
    const model = ctx.model;
    const i = model ? pointAt(model, x, y, ctx.state.view.zoom) : -1;
    if (i >= 0) {
      ctx.commit({ ...ctx.state, focus: i }, { history: false });
      return true;
    }
    view.rotating = { x: event.clientX, y: event.clientY, ...ctx.state.rotation };
    return true;
  },
  exports: [meshFile('off'), meshFile('obj')],
  meshImporters: { off: importMesh, obj: importMesh },
};
