// @ts-check
// Where the subdivision lesson's mesh comes from: a mesh of the core (tetrahedron, cube,
// lecture 000's example, a generated sphere or grid) or an imported OFF/OBJ file. The core
// builds and checks every one of them; this file only names them (ui/mesh/mesh-choice.js
// keys them and reads their faces).
import { sourceOf, meshKinds } from '../../ui/mesh/mesh-choice.js';
import { elementLabel as label } from '../../ui/element-labels.js';

export const MAX_LEVEL = 5;
// Phases of one step as the core lists them (api.subdivisionSteps): state.phase = how many
// of them are shown (0: the level's mesh alone, 4: reconnected).
export const PHASES = ['face-points', 'edge-points', 'vertex-points', 'reconnection'];

// The slides' labels, 1-based: v1, e1, F1 (-1, no element, is an empty cell).
export { label };

export const SOURCES = meshKinds(['tetrahedron', 'cube', 'lecture', 'sphere', 'grid', 'file'],
  { tetrahedron: 'Tetrahedron (triangles)', lecture: 'Lecture example (lecture 000)', grid: 'Grid (open)' });

// The view each mesh opens in (yaw, pitch in radians; ui/mesh/view.js). Lecture 000's example
// lies in the plane z = 0: seen from the top, as the slide draws it. The tetrahedron turned so
// that three of its faces face the viewer at clearly different angles to the light (shades
// 0.64, 0.40 and 0.18 of the ramp; seen face on, the default turn showed one uniform
// triangle). Every other mesh: a turn that shows it as a solid.
const VIEWS = { lecture: { yaw: 0, pitch: 0 }, tetrahedron: { yaw: -2.35, pitch: -0.7 } };
const DEFAULT_VIEW = { yaw: 0.6, pitch: 0.45 };
export const viewOf = (meshKind) => ({ ...(VIEWS[meshKind] ?? DEFAULT_VIEW) });

// [min, max] of each size field (ui/mesh/chooser.js; the schema in lesson.js holds them too):
// the sphere's slices, stacks; the grid's nx, ny.
export const SIZES = {
  sphere: [[3, 100], [3, 50]],
  grid: [[1, 64], [1, 64]],
};

// The imported mesh is the lesson's one large field (docs/state-format.md, "Large fields").
export const IMPORTED_FIELD = {
  imported: { what: 'an imported mesh', file: 'the OFF file', export: 'subdivision-level0.off', label: (imported) => imported.name },
};

// The indexed face set of a state (the core's mesh or the imported file) with the control
// vertices the person moved put where the state says (state.moved: [{v, p: [x, y, z]}]).
export function meshInput(state, api) {
  const input = baseInput(state, api);
  if (!state.moved.length) return input;
  const positions = Float64Array.from(input.positions);
  const count = positions.length / 3;
  for (const { v, p } of state.moved) {
    if (v >= count) throw Object.assign(new Error(`moved vertex ${label('vertex', v)} does not exist in this mesh (it has ${count} vertices)`), { code: 'invalid-element' });
    positions.set(p, 3 * v);
  }
  return { ...input, positions };
}

// The mesh choice's faces without the slides' numbering of the lecture example: the core
// numbers the control mesh itself, as it numbers every level.
function baseInput(state, api) {
  const { positions, faces, faceOffsets, faceVertices } = sourceOf(state, api);
  return faces ? { positions, faces } : { positions, faceOffsets, faceVertices };
}
