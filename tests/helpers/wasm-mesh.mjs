// Meshes for the wasm tests that are always disposed: withValidMesh(api, input, body) builds
// `input`, checks that it validates, runs body(mesh) and disposes the mesh even when body
// throws, so a failing assertion leaves no mesh alive for the next test.
import assert from 'node:assert/strict';

export function withValidMesh(api, input, body) {
  const mesh = api.buildMesh(input);
  try {
    const report = mesh.validate();
    assert.equal(report.ok, true, JSON.stringify(report.problems));
    return body(mesh);
  } finally {
    mesh.dispose();
  }
}
