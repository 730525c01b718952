// The malformed-mesh corpus through wasm: every file of tests/corpus/mesh/ gives
// the outcome tests/corpus/mesh/expected.txt names, through the public API (parseMesh,
// validateMesh, buildMesh), with the code, the line or the elements in the message; the
// module keeps working afterwards and no mesh is left alive. The same files are checked
// natively in tests/native/files/test_mesh_corpus.cpp. Also: a 50 MB file generated here
// (never committed), and forgotten-disposal checks (liveMeshCount, 'disposed').
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { meshCases, readCorpusFile } from '../../helpers/corpus.mjs';

const api = await loadWingspline();
const cases = meshCases();

function expectParseError(c, text) {
  assert.throws(() => api.parseMesh(text, { format: c.format }), (err) => {
    assert.ok(err instanceof Error);
    assert.equal(err.code, c.code);
    assert.equal(err.line, c.line);
    assert.ok(err.message.startsWith(`line ${c.line}: `), err.message);
    return true;
  });
}

function expectBuilt(mesh, input) {
  try {
    const structure = mesh.validate();
    assert.ok(structure.ok, JSON.stringify(structure.problems));
    const counts = mesh.counts();
    assert.equal(counts.vertices, input.positions.length / 3);
    assert.equal(counts.faces, input.faces.length);
    for (const x of mesh.normals()) assert.ok(Number.isFinite(x), 'normals are finite');
    for (const p of mesh.planes()) {
      for (const x of [...p.cross, ...p.newell, p.residual]) assert.ok(Number.isFinite(x), 'planes are finite');
    }
  } finally {
    mesh.dispose();
  }
}

test('the corpus manifest lists every malformed mesh of the issue', () => {
  assert.ok(cases.length >= 19);
  for (const code of ['non-manifold-edge', 'non-manifold-vertex', 'inconsistent-orientation', 'repeated-vertex', 'duplicate-face',
    'index-out-of-range', 'truncated-file', 'parse-error', 'non-finite-coordinate', 'isolated-vertex']) {
    assert.ok(cases.some((c) => c.code === code), code);
  }
});

for (const c of cases) {
  test(`${c.file} as ${c.format}: ${c.outcome} ${c.code ?? ''}`, () => {
    const text = readCorpusFile(`mesh/${c.file}`);
    if (c.outcome === 'parse-error') {
      expectParseError(c, text);
      return;
    }
    const input = api.parseMesh(text, { format: c.format });
    const report = api.validateMesh(input);
    if (c.outcome === 'valid') {
      assert.deepEqual(report, { ok: true, problems: [] });
      expectBuilt(api.buildMesh(input), input);
      return;
    }
    const problem = report.problems.find((p) => p.code === c.code);
    assert.ok(problem, `validation reports ${c.code}: ${JSON.stringify(report.problems)}`);
    assert.equal(problem.severity, c.outcome === 'warning' ? 'warning' : 'error');
    for (const name of c.names) assert.ok(problem.message.includes(name), `"${problem.message}" names ${name}`);
    if (c.outcome === 'warning') {
      assert.equal(report.ok, true);
      expectBuilt(api.buildMesh(input), input);
      return;
    }
    assert.equal(report.ok, false);
    assert.throws(() => api.buildMesh(input), (err) => {
      assert.equal(err.code, report.problems.find((p) => p.severity === 'error').code, 'refused with the first error');
      assert.ok(err.details.some((p) => p.code === c.code), 'the refusal carries every problem');
      assert.equal(err.details.length, report.problems.length);
      return true;
    });
    assert.equal(api.liveMeshCount(), 0, 'a refused mesh leaves nothing alive');
  });
}

test('a zero-area face: the winged edge holds it and its normal is the zero vector, not NaN', () => {
  const mesh = api.buildMesh(api.parseMesh(readCorpusFile('mesh/zero-area-face.off'), { format: 'off' }));
  try {
    // F1 lies in z = 0, counter-clockwise seen from +z; F2 has no area.
    assert.deepEqual(Array.from(mesh.normals()), [0, 0, 1, 0, 0, 0]);
  } finally {
    mesh.dispose();
  }
});

test('an isolated vertex builds with edge -1 and counts in V', () => {
  const mesh = api.buildMesh(api.parseMesh(readCorpusFile('mesh/isolated-vertex.off'), { format: 'off' }));
  try {
    assert.equal(mesh.wingedEdge().vertices[3].edge, -1);
    assert.equal(mesh.counts().isolatedVertices, 1);
    assert.equal(mesh.counts().vertices, 4);
  } finally {
    mesh.dispose();
  }
});

// A valid OFF of at least `bytes` bytes, built here as text: an n x n grid of the unit
// square, two triangles per quad (CCW seen from +z), coordinates written with 17 digits so
// every vertex line is long. Returns { text, n }.
function largeOff(bytes) {
  const vertexLine = (i, j, n) => `${(i / n).toPrecision(17)} ${(j / n).toPrecision(17)} ${(Math.sin(i + j) * 0.1).toPrecision(17)}`;
  let n = Math.ceil(Math.sqrt(bytes / 100)); // about 60 bytes per vertex + 2 x 20 per face
  for (;;) {
    const lines = ['OFF', `${(n + 1) * (n + 1)} ${2 * n * n} 0`];
    for (let j = 0; j <= n; j += 1) for (let i = 0; i <= n; i += 1) lines.push(vertexLine(i, j, n));
    const v = (i, j) => j * (n + 1) + i;
    for (let j = 0; j < n; j += 1) {
      for (let i = 0; i < n; i += 1) {
        lines.push(`3 ${v(i, j)} ${v(i + 1, j)} ${v(i + 1, j + 1)}`, `3 ${v(i, j)} ${v(i + 1, j + 1)} ${v(i, j + 1)}`);
      }
    }
    const text = lines.join('\n') + '\n';
    if (text.length >= bytes) return { text, n, lines: lines.length };
    n = Math.ceil(n * Math.sqrt(bytes / text.length)) + 1;
  }
}

test('a 50 MB OFF file generated at test time is read and built, and an error on its last line is named', () => {
  const FIFTY_MB = 50 * 1024 * 1024;
  const { text, n, lines } = largeOff(FIFTY_MB);
  assert.ok(text.length >= FIFTY_MB);
  // Far more elements than a page imports (api.meshLimits): read with the counts lifted.
  const input = api.parseMesh(text, { format: 'off', layout: 'csr', checkCounts: false });
  assert.equal(input.positions.length, 3 * (n + 1) * (n + 1));
  assert.equal(input.faceOffsets.length - 1, 2 * n * n);
  const mesh = api.buildMesh(input);
  try {
    const counts = mesh.counts();
    assert.equal(counts.euler, 1, 'an open disc');
    assert.equal(counts.boundaryLoops, 1);
  } finally {
    mesh.dispose();
  }
  const damaged = text.slice(0, text.lastIndexOf(' ') + 1) + 'oops\n';
  assert.throws(() => api.parseMesh(damaged, { format: 'off', checkCounts: false }),
    (err) => err.code === 'parse-error' && err.line === lines && err.message.includes("'oops'"));
});

test('forgotten disposal is visible: liveMeshCount counts, dispose() returns it to 0, a disposed mesh throws disposed', () => {
  assert.equal(api.liveMeshCount(), 0);
  const meshes = ['tetrahedron', 'cube'].map((kind) => api.buildMesh(api.generateMesh(kind)));
  meshes.push(api.buildMesh(api.lectureExample()));
  assert.equal(api.liveMeshCount(), 3);
  meshes[1].dispose();
  assert.equal(api.liveMeshCount(), 2);
  meshes[1].dispose(); // idempotent
  assert.equal(api.liveMeshCount(), 2);
  const disposed = meshes[1];
  for (const call of [() => disposed.wingedEdge(), () => disposed.edgesAroundVertex(0), () => disposed.counts(),
    () => disposed.validate(), () => disposed.normals(), () => disposed.planes(), () => disposed.traversalSteps(0),
    () => disposed.faceNeighbours(0), () => disposed.setVertexPosition(0, [0, 0, 0])]) {
    assert.throws(call, (err) => err.code === 'disposed' && /disposed/.test(err.message));
  }
  meshes[0].dispose();
  meshes[2].dispose();
  assert.equal(api.liveMeshCount(), 0);
});

test('every corpus file, 200 times over, leaves the module working and nothing alive', () => {
  for (let round = 0; round < 200; round += 1) {
    for (const c of cases) {
      try {
        api.buildMesh(api.parseMesh(readCorpusFile(`mesh/${c.file}`), { format: c.format })).dispose();
      } catch (err) {
        assert.equal(typeof err.code, 'string');
      }
    }
  }
  assert.equal(api.liveMeshCount(), 0);
  const mesh = api.buildMesh(api.lectureExample());
  // Lecture 000: CCW around v2 (index 1) is e6, e5, e3, e2 (indices 5, 4, 2, 1).
  assert.deepEqual(Array.from(mesh.edgesAroundVertex(1)), [5, 4, 2, 1]);
  mesh.dispose();
});
