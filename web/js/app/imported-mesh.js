// @ts-check
// The imported mesh of a lesson state, described once (the mesh and subdivision lessons,
// the import worker, the mesh sources). Two forms are read:
//   flat  {name, positions: number[], faceSizes: number[], faceVertices: number[]}: face f's
//         corners are faceVertices[s_f .. s_f + faceSizes[f]) with s_f the sum of the sizes
//         before it. What an import writes now: a million faces are three plain
//         arrays of numbers, not a million small arrays (which cost the page 50-70 ms pauses
//         of the garbage collector and 50 ms to build).
//   faces {name, positions: number[], faces: number[][]}: what states, links and files saved
//         before the flat form hold; still read, never written by an import.
// docs/state-format.md, "The imported mesh".
import { SchemaError, text, list, number } from './schema.js';

const describe = (v) => (Array.isArray(v) ? 'a list' : v === null ? 'null' : typeof v);

// A schema check (schema.js's shape: (value, path) -> the value, or throws SchemaError naming
// the field) for either form, within the limits given. A clean value is returned itself.
export function importedMesh({ maxVertices, maxFaces, maxCorners }) {
  const name = text({ maxLength: 120 });
  const positions = list(number(), { min: 9, max: 3 * maxVertices });
  const cornerList = list((v, p) => corner(v, p, maxVertices), { min: 3, max: maxCorners });
  const faces = list(cornerList, { min: 1, max: maxFaces });
  return (v, path) => {
    if (v === null || typeof v !== 'object' || Array.isArray(v)) throw new SchemaError(path, `must be an object, not ${describe(v)}`);
    name(v.name, `${path}.name`);
    positions(v.positions, `${path}.positions`);
    if ('faces' in v) {
      faces(v.faces, `${path}.faces`);
      const extra = Object.keys(v).filter((k) => !['name', 'positions', 'faces'].includes(k));
      return extra.length ? { name: v.name, positions: v.positions, faces: v.faces } : v;
    }
    flatFaces(v, path, { maxVertices, maxFaces, maxCorners });
    const extra = Object.keys(v).filter((k) => !['name', 'positions', 'faceSizes', 'faceVertices'].includes(k));
    return extra.length ? { name: v.name, positions: v.positions, faceSizes: v.faceSizes, faceVertices: v.faceVertices } : v;
  };
}

function corner(v, path, maxVertices) {
  if (!Number.isInteger(v)) throw new SchemaError(path, `must be a whole number, not ${typeof v === 'number' ? v : describe(v)}`);
  if (v < 0 || v > maxVertices - 1) throw new SchemaError(path, `must be between 0 and ${maxVertices - 1}, not ${v}`);
  return v;
}

// The flat form's faces: sizes 3..maxCorners, at most maxFaces of them, and exactly as many
// corners as the sizes add up to, each a vertex number. Plain loops: a million faces in a
// few milliseconds, allocating nothing.
function flatFaces(v, path, { maxVertices, maxFaces, maxCorners }) {
  const { faceSizes: sizes, faceVertices: corners } = v;
  if (!Array.isArray(sizes)) throw new SchemaError(`${path}.faceSizes`, sizes === undefined ? 'is missing (an imported mesh holds faces, or faceSizes and faceVertices)' : `must be a list, not ${describe(sizes)}`);
  if (!Array.isArray(corners)) throw new SchemaError(`${path}.faceVertices`, corners === undefined ? 'is missing' : `must be a list, not ${describe(corners)}`);
  if (sizes.length < 1 || sizes.length > maxFaces) throw new SchemaError(`${path}.faceSizes`, `must have 1 to ${maxFaces} entries, not ${sizes.length}`);
  let total = 0;
  for (let f = 0; f < sizes.length; f += 1) {
    const n = sizes[f];
    if (!Number.isInteger(n) || n < 3 || n > maxCorners) {
      throw new SchemaError(`${path}.faceSizes[${f}]`, `must be a whole number of corners from 3 to ${maxCorners}, not ${typeof n === 'number' ? n : describe(n)}`);
    }
    total += n;
  }
  if (corners.length !== total) {
    throw new SchemaError(`${path}.faceVertices`, `must have ${total} entries (the corners faceSizes adds up to), not ${corners.length}`);
  }
  // Whole numbers 0..maxVertices-1 pass the fast test; anything else is checked again by
  // corner(), which names the entry.
  for (let i = 0; i < corners.length; i += 1) {
    const c = corners[i];
    if (!(typeof c === 'number' && (c | 0) === c && c >= 0 && c < maxVertices)) corner(c, `${path}.faceVertices[${i}]`, maxVertices);
  }
}

// How many faces an imported mesh has (either form).
export function importedFaceCount(imported) {
  return imported.faces ? imported.faces.length : imported.faceSizes.length;
}

// An imported mesh (either form) as the core's bulk input: {positions: Float64Array,
// faceOffsets: Int32Array, faceVertices: Int32Array}.
export function importedCsr(imported) {
  const positions = Float64Array.from(imported.positions);
  if (imported.faces) {
    const faces = imported.faces;
    const faceOffsets = new Int32Array(faces.length + 1);
    for (let f = 0; f < faces.length; f += 1) faceOffsets[f + 1] = faceOffsets[f] + faces[f].length;
    const faceVertices = new Int32Array(faceOffsets[faces.length]);
    for (let f = 0; f < faces.length; f += 1) faceVertices.set(faces[f], faceOffsets[f]);
    return { positions, faceOffsets, faceVertices };
  }
  const sizes = imported.faceSizes;
  const faceOffsets = new Int32Array(sizes.length + 1);
  for (let f = 0; f < sizes.length; f += 1) faceOffsets[f + 1] = faceOffsets[f] + sizes[f];
  return { positions, faceOffsets, faceVertices: Int32Array.from(imported.faceVertices) };
}

// Copies `from[first..end)` into the plain array `to` (a typed array's numbers as a JSON list).
export function copyInto(to, from, first, end) {
  for (let i = first; i < end; i += 1) to.push(from[i]);
}

// The flat imported value of a parsed mesh (CSR typed arrays), at once: the import worker's.
export function flatImportedValue(name, positions, faceOffsets, faceVertices) {
  const faceSizes = [];
  for (let f = 0; f + 1 < faceOffsets.length; f += 1) faceSizes.push(faceOffsets[f + 1] - faceOffsets[f]);
  const p = [];
  copyInto(p, positions, 0, positions.length);
  const c = [];
  copyInto(c, faceVertices, 0, faceVertices.length);
  return { name: name.slice(0, 120), positions: p, faceSizes, faceVertices: c };
}
