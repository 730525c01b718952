// Where the subdivision lesson's mesh comes from: a mesh of the core (tetrahedron, cube,
// lecture 000's example, a generated sphere or grid) or an imported OFF/OBJ file. The core
// builds and checks every one of them; this file only names them and keys them.

import { importedArrays } from '../../app/mesh-import.js';
import { importedCsr } from '../../app/imported-mesh.js';
import { contentHashOf } from '../../app/share-link.js';

export const MAX_LEVEL = 5;
// Phases of one step as the core lists them (api.subdivisionSteps): state.phase = how many
// of them are shown (0: the level's mesh alone, 4: reconnected).
export const PHASES = ['face-points', 'edge-points', 'vertex-points', 'reconnection'];

// The slides' labels, 1-based: v1, e1, F1 (-1, no element, is an empty cell).
export { elementLabel as label } from '../../ui/element-labels.js';

export const SOURCES = [
  { id: 'tetrahedron', label: 'Tetrahedron (triangles)' },
  { id: 'cube', label: 'Cube (quads)' },
  { id: 'lecture', label: 'Lecture example (lecture 000)' },
  { id: 'sphere', label: 'UV sphere' },
  { id: 'grid', label: 'Grid (open)' },
  { id: 'file', label: 'Your file (OFF/OBJ)' },
];

// The imported mesh is the lesson's one large field (docs/state-format.md, "Large fields").
export const IMPORTED_FIELD = {
  imported: { what: 'an imported mesh', file: 'the OFF file', export: 'subdivision-level0.off', label: (imported) => imported.name },
};

// One key per mesh choice: equal keys share the chain of levels built from it. An imported
// mesh is keyed by a hash of its numbers, once per object (the spread copies of a state
// share it); `memo` is the lesson view's WeakMap.
export function sourceKey(state, memo) {
  switch (state.meshKind) {
    case 'sphere': return `sphere:${state.sphere.slices}x${state.sphere.stacks}`;
    case 'grid': return `grid:${state.grid.nx}x${state.grid.ny}`;
    case 'file': {
      if (!state.imported) return 'file:none';
      // A mesh the import worker hashed (SHA-256 of its text, issue 17) is keyed by that hash.
      if (!memo.has(state.imported)) memo.set(state.imported, `file:${state.imported.name}:${contentHashOf(state.imported) ?? fingerprint(state.imported)}`);
      return memo.get(state.imported);
    }
    default: return state.meshKind;
  }
}

// The positions, then each face's size and corners (either form of imported-mesh.js).
function fingerprint(imported) {
  const { faceOffsets, faceVertices } = importedCsr(imported);
  const numbers = [...imported.positions];
  for (let f = 0; f + 1 < faceOffsets.length; f += 1) numbers.push(faceOffsets[f + 1] - faceOffsets[f], ...faceVertices.subarray(faceOffsets[f], faceOffsets[f + 1]));
  return hashNumbers(numbers);
}

// A short key of a list of numbers (FNV-1a over the numbers at 1e-6): the moved control
// vertices' part of a chain's key.
export function hashNumbers(numbers) {
  let h = 2166136261;
  for (const x of numbers) h = Math.imul(h ^ (Math.round(x * 1e6) | 0), 16777619);
  return (h >>> 0).toString(36);
}

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

function baseInput(state, api) {
  switch (state.meshKind) {
    case 'lecture': {
      const { positions, faces } = api.lectureExample();
      return { positions, faces };
    }
    case 'sphere': return api.generateMesh('sphere', { slices: state.sphere.slices, stacks: state.sphere.stacks });
    case 'grid': return api.generateMesh('grid', { nx: state.grid.nx, ny: state.grid.ny });
    case 'file':
      if (!state.imported) throw Object.assign(new Error('No file has been imported yet: use Open OFF/OBJ (or drop an .off or .obj file on the page).'), { code: 'no-file' });
      return importedArrays(state.imported) ?? importedCsr(state.imported);
    default: return api.generateMesh(state.meshKind);
  }
}
