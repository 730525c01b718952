// The core ships as four modules (docs/architecture.md, "Module size"): a page asks for the
// parts it uses, the package gets every part by default. Each module is built from the one
// source: the same version, the same error list, the same answers where two modules hold the
// same code (curve sampling), and C++ errors (native wasm exceptions) become the same
// {code, message} errors in every module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline, WingsplineError } from 'wingspline';

const pkg = JSON.parse(fs.readFileSync(new URL('../../../package.json', import.meta.url), 'utf8'));
const PARTS = ['mesh', 'subdivision', 'curves', 'exercises'];
// Two triangles sharing the edge v2-v3 (5 edges).
const TWO_TRIANGLES = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], faces: [[0, 1, 2], [2, 1, 3]] };
// An edge shared by three faces: refused by every module that builds meshes.
const THREE_AT_AN_EDGE = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1], faces: [[0, 1, 2], [1, 0, 3], [0, 1, 4]] };

test('each part alone reports the package version and the one error list', async () => {
  const full = await loadWingspline();
  for (const part of PARTS) {
    const api = await loadWingspline({ parts: [part] });
    assert.equal(api.version, pkg.version, part);
    assert.deepEqual(api.errorCodes, full.errorCodes, `${part}: the same error list`);
    assert.equal(await loadWingspline({ parts: [part] }), api, `${part}: one API object per set of parts`);
  }
});

test('a part carries its own functions only', async () => {
  const mesh = await loadWingspline({ parts: ['mesh'] });
  assert.equal(typeof mesh.buildMesh, 'function');
  assert.equal(mesh.subdivide, undefined, 'the mesh lesson\'s module has no subdivision');
  assert.equal(mesh.evaluateCurve, undefined);
  assert.equal(mesh.checkMeshTableAnswer, undefined);
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  for (const name of ['buildMesh', 'subdivide', 'limitPositions', 'sampleCurve', 'uniformKnots', 'subdivideCurve']) assert.equal(typeof subdivision[name], 'function', name);
  assert.equal(subdivision.segmentMatrices, undefined);
  const curves = await loadWingspline({ parts: ['curves'] });
  assert.equal(curves.buildMesh, undefined);
  assert.equal(typeof curves.segmentMatrices, 'function');
  const exercises = await loadWingspline({ parts: ['exercises'] });
  assert.equal(typeof exercises.checkMeshTableAnswer, 'function');
  assert.equal(typeof exercises.checkCurveProperty, 'function');
  assert.equal(exercises.buildMesh, undefined);
  // 'subdivision' holds the mesh API: asked with 'mesh', one module holds the meshes.
  const both = await loadWingspline({ parts: ['mesh', 'subdivision'] });
  assert.equal(both, subdivision);
  const full = await loadWingspline();
  for (const name of Object.keys(mesh).concat(Object.keys(subdivision), Object.keys(curves), Object.keys(exercises))) {
    assert.ok(name in full, `the package API has ${name}`);
  }
});

test('parts that do not exist are refused with invalid-argument', async () => {
  for (const parts of [[], ['meshes'], 'mesh', [1]]) {
    await assert.rejects(loadWingspline({ parts }), (err) => err instanceof WingsplineError && err.code === 'invalid-argument' && /mesh/.test(err.message), JSON.stringify(parts));
  }
});

test('a refusal thrown in C++ is the same {code, message} error in every module that builds meshes', async () => {
  for (const part of ['mesh', 'subdivision']) {
    const api = await loadWingspline({ parts: [part] });
    assert.throws(() => api.buildMesh(THREE_AT_AN_EDGE), (err) => err instanceof WingsplineError && err.code === 'non-manifold-edge' && /3 faces/.test(err.message), part);
    const m = api.buildMesh(TWO_TRIANGLES);
    assert.equal(m.counts().edges, 5, `${part}: the module keeps working after a refusal`);
    m.dispose();
  }
  const exercises = await loadWingspline({ parts: ['exercises'] });
  assert.throws(() => exercises.checkMeshTableAnswer({ faces: [[0, 1, 2]], vertexCount: 3 }, 'no-such-table', {}), (err) => err instanceof WingsplineError && typeof err.code === 'string');
});

test('curve sampling answers bit for bit the same in the curves and the subdivision modules', async () => {
  const curves = await loadWingspline({ parts: ['curves'] });
  const subdivision = await loadWingspline({ parts: ['subdivision'] });
  const points = [0, 0, 1, 2, 3, 2, 4, 0, 5, 1];
  for (const degree of [2, 3]) {
    const knots = curves.uniformKnots(5, degree);
    assert.deepEqual(subdivision.uniformKnots(5, degree), knots);
    const spec = { kind: 'bspline', dim: 2, degree, points, knots };
    assert.deepEqual(subdivision.sampleCurve(spec, 33), curves.sampleCurve(spec, 33));
  }
  for (const scheme of ['chaikin', 'cubic-bspline']) {
    assert.deepEqual(subdivision.subdivideCurve(points, 2, { scheme, steps: 3 }), curves.subdivideCurve(points, 2, { scheme, steps: 3 }));
  }
  assert.throws(() => subdivision.sampleCurve({ kind: 'bspline', dim: 2, degree: 3, points, knots: [0, 1] }), (err) => err instanceof WingsplineError && typeof err.code === 'string');
});
