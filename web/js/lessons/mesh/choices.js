// @ts-check
// The meshes the mesh lesson offers (ui/mesh/chooser.js shows them; ui/mesh/mesh-choice.js
// builds them) and the bounds of the generated meshes' sizes, which the state's schema
// (lesson.js) holds too.
import { meshKinds } from '../../ui/mesh/mesh-choice.js';

export const MESH_KINDS = meshKinds(['lecture', 'foley', 'tetrahedron', 'cube', 'fan', 'grid', 'sphere', 'file']);

// [min, max] of each size field: the fan's triangles; the grid's nx, ny; the sphere's
// slices, stacks (up to the sphere of a million faces, which the GPU draws).
export const MESH_SIZES = {
  fan: [[1, 64]],
  grid: [[1, 400], [1, 400]],
  sphere: [[3, 1000], [3, 600]],
};

// The imported mesh (state.imported = { name, positions, faces }) is the one large field of
// the lesson's state: links and local storage hold it by content hash, the mesh itself in
// IndexedDB, unless it is small enough to travel inline (share-link.js, `contentFields`;
// docs/state-format.md, "Large fields"). A link that only refers to it tells the person to
// send the OFF file with it, and offers the export.
export const IMPORTED_CONTENT = {
  imported: { what: 'an imported mesh', file: 'the OFF file', export: 'mesh.off', label: (imported) => imported.name },
};
