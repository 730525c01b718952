// Mesh part of the API (issue 3). Filled in by the mesh core.
export function createMeshApi(/* raw */) {
  return {};
}
