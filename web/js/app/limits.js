// @ts-check
// The limits of what a lesson state may hold: one set, used where a value enters (the
// inspector, a lesson's entries, imported files: ctx.commit checks every change against the
// lesson's schema) and where it is read back (share links, local storage, state files:
// share-link.js validates with the same schema). A value the page accepts is therefore one
// its own state format reads back on the next visit.
//
// The mesh limits are the core's (core/include/wingspline/mesh/limits.h, exposed as
// api.meshLimits). Schemas are built when a lesson module loads, before the core does, so
// the numbers are repeated here once; tests/wasm/mesh/sets-planes-limits.test.mjs fails if they ever
// differ from the core's.

// |x| of any coordinate or free number of a state, in world units.
export const COORDINATE_BOUND = 1e9;
// Corners of one face of an imported mesh.
export const MAX_FACE_CORNERS = 1000;
// Vertices and faces of an imported mesh (the import limit: the largest mesh a
// school laptop holds, docs/api-mesh.md "Import limits and memory").
export const MAX_MESH_VERTICES = 2000000;
export const MAX_MESH_FACES = 2000000;
// Levels of objects and lists inside each other in a value read from outside (a share link,
// a saved state, an imported JSON state, an exercise, an exercise's progress), counting the
// outermost object as level 1. A lesson state needs about 6 (envelope, state, imported mesh,
// faces, a face); deeper values are refused before anything walks them, since copying or
// writing a value (structuredClone, JSON.stringify) recurses once per level and 100,000
// levels overflow the stack (docs/state-format.md, "Limits").
export const MAX_NESTING = 64;
