// @ts-check
// Which mesh a lesson state chose, as the mesh lessons keep it: `state.meshKind` (a mesh of
// the core: the lectures' examples, a tetrahedron, a cube, a fan, a generated grid or
// sphere; or 'file', an imported OFF/OBJ in `state.imported`) and the sizes `fanSize`,
// `grid: {nx, ny}`, `sphere: {slices, stacks}`. The core builds and checks every mesh; this
// file only names the choice's indexed face set and keys it.
// Offers: MESH_CHOICES, meshKinds(ids, names), sourceOf(state, api), sourceKey(state, importedKey), createImportedKeys(),
//   hashNumbers(numbers), faceCsr(data).
// Needs: the JS API (api.lectureExample, foleyExample, generateMesh) and an imported mesh in
//   either form of app/imported-mesh.js.
import { importedArrays } from '../../app/mesh-import.js';
import { importedCsr, importedFaceCount } from '../../app/imported-mesh.js';
import { contentHashOf } from '../../app/share-link.js';

// The meshes sourceOf builds, with the name a chooser shows (ui/mesh/chooser.js).
export const MESH_CHOICES = {
  lecture: 'Lecture example (v1..v5, lecture 000)',
  foley: 'Foley example (V1..V4, lecture 001)',
  tetrahedron: 'Tetrahedron',
  cube: 'Cube (quads)',
  fan: 'Open fan',
  grid: 'Grid',
  sphere: 'UV sphere',
  file: 'Your file (OFF/OBJ)',
};

// A lesson's meshes ({id, label}, the chooser's list): ids in the order shown, and the
// names a lesson words its own way.
export const meshKinds = (ids, names = {}) => ids.map((id) => ({ id, label: names[id] ?? MESH_CHOICES[id] }));

// The key that identifies one mesh choice (its topology and base geometry): equal keys
// share one core mesh. importedKey: the key of an imported mesh (createImportedKeys).
export function sourceKey(state, importedKey) {
  switch (state.meshKind) {
    case 'fan': return `fan:${state.fanSize}`;
    case 'grid': return `grid:${state.grid.nx}x${state.grid.ny}`;
    case 'sphere': return `sphere:${state.sphere.slices}x${state.sphere.stacks}`;
    case 'file': return state.imported ? importedKey(state.imported) : 'file:none';
    default: return state.meshKind;
  }
}

// The imported mesh rides along unchanged from state to state (spread copies share it), so
// its key is hashed once per object, not on every walk step; one memo per lesson view.
// A mesh the import worker hashed (SHA-256 of its text) is keyed by that hash.
export function createImportedKeys() {
  const keys = new WeakMap();
  return (imported) => {
    if (!keys.has(imported)) keys.set(imported, `file:${imported.name}:${importedFaceCount(imported)}:${contentHashOf(imported) ?? fingerprint(imported)}`);
    return keys.get(imported);
  };
}

// FNV-1a over numbers at 1e-6: one step.
const FNV_OFFSET = 2166136261;
const mix = (h, x) => Math.imul(h ^ (Math.round(x * 1e6) | 0), 16777619);

// The positions, then each face's size and corners (either form of imported-mesh.js),
// hashed as they are read (no copy of a million faces' numbers).
function fingerprint(imported) {
  let h = FNV_OFFSET;
  for (const x of imported.positions) h = mix(h, x);
  const { faceOffsets, faceVertices } = importedCsr(imported);
  for (let f = 0; f + 1 < faceOffsets.length; f += 1) {
    h = mix(h, faceOffsets[f + 1] - faceOffsets[f]);
    for (let i = faceOffsets[f]; i < faceOffsets[f + 1]; i += 1) h = mix(h, faceVertices[i]);
  }
  return (h >>> 0).toString(36);
}

// A short key of a list of numbers (e.g. the moved vertices of a state).
export function hashNumbers(numbers) {
  let h = FNV_OFFSET;
  for (const x of numbers) h = mix(h, x);
  return (h >>> 0).toString(36);
}

// Faces as offsets and corners (CSR: face f is vertices[offsets[f] .. offsets[f + 1])),
// whatever container the core or the state used: the one form the lessons keep (a million
// faces as a million small arrays cost a tenth of a second and much memory).
export function faceCsr(data) {
  if (data.faceOffsets) return { offsets: data.faceOffsets, vertices: data.faceVertices };
  const faces = data.faces;
  const offsets = new Int32Array(faces.length + 1);
  for (let f = 0; f < faces.length; f += 1) offsets[f + 1] = offsets[f] + faces[f].length;
  const vertices = new Int32Array(offsets[faces.length]);
  for (let f = 0; f < faces.length; f += 1) vertices.set(faces[f], offsets[f]);
  return { offsets, vertices };
}

// The indexed face set of a state's mesh choice and, for the slides' meshes, the slide's
// numbering (edges, vertexEdges, faceEdges: a lesson that numbers its own drops them).
export function sourceOf(state, api) {
  switch (state.meshKind) {
    case 'lecture': return api.lectureExample();
    case 'foley': return api.foleyExample();
    case 'tetrahedron': return api.generateMesh('tetrahedron');
    case 'cube': return api.generateMesh('cube');
    case 'fan': return api.generateMesh('fan', { n: state.fanSize, layout: 'csr' });
    case 'grid': return api.generateMesh('grid', { nx: state.grid.nx, ny: state.grid.ny, layout: 'csr' });
    case 'sphere': return api.generateMesh('sphere', { slices: state.sphere.slices, stacks: state.sphere.stacks, layout: 'csr' });
    case 'file': {
      if (!state.imported) throw Object.assign(new Error('No file has been imported yet: use Open OFF/OBJ (or drop an .off or .obj file on the page).'), { code: 'no-file' });
      // Freshly imported: the worker's flat arrays, built in bulk.
      const flat = importedArrays(state.imported);
      if (flat) return { positions: flat.positions, faceOffsets: flat.faceOffsets, faceVertices: flat.faceVertices };
      return importedCsr(state.imported);
    }
    default: throw Object.assign(new Error(`unknown mesh ${state.meshKind}`), { code: 'unknown-mesh' });
  }
}
