// The code sandbox (web/js/code/runner.js) under Node, with the engine the site ships:
// a student's walk over the lecture's winged-edge tables, traced read by read; errors in the
// student's words with exact lines; the budget, memory and stack limits; nothing leaks out of
// the engine's realm or from one case to the next. Expected values are worked out by hand
// from the tables of lecture 000, written below.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createNodeSandbox, runInNode } from '../../web/js/code/quickjs-node.js';
import { newQuickJSWASMModuleFromVariant } from 'quickjs-emscripten-core';
import releaseSync from '@jitl/quickjs-wasmfile-release-sync';
import { runStudentCode, traceEntries, TRACE_LIMIT } from '../../web/js/code/runner.js';
import { EDGE_FIELDS, LECTURE_EDGES, FACES, lectureWinged, lectureHalfEdge, CCW_WALK } from '../helpers/lecture-code.mjs';

const wingedMesh = () => ({ winged: lectureWinged() });

test('the hand-written tables agree with the faces (each directed side of a face is an edge with that face on its side)', () => {
  const w = lectureWinged();
  for (const [f, corners] of FACES.entries()) {
    for (let k = 0; k < 3; k++) {
      const a = corners[k], b = corners[(k + 1) % 3];
      const e = LECTURE_EDGES.findIndex(([s, t]) => (s === a && t === b) || (s === b && t === a));
      assert.ok(e >= 0, `side v${a + 1}-v${b + 1} of F${f + 1} is an edge`);
      const [s, , left, right] = LECTURE_EDGES[e];
      assert.equal(s === a ? left : right, f, `e${e + 1} has F${f + 1} on the side it runs along`);
    }
  }
  // Spot checks against the slide: e3 = (v2 v3 | F1 F2 | e2 e5 e1 e4), v2 -> e6, F3 -> e5.
  assert.deepEqual(Array.from(w.edges.subarray(16, 24)), [1, 2, 0, 1, 1, 4, 0, 3]);
  assert.equal(w.vertexEdge[1], 5);
  assert.equal(w.faceEdge[2], 4);
  const h = lectureHalfEdge();
  for (let i = 0; i < 14; i++) {
    assert.equal(h.prev[h.next[i]], i, `prev(next(h${i}))`);
    assert.equal(h.origin[h.next[i]], h.origin[i ^ 1], `next(h${i}) starts where h${i} ends`);
    assert.equal(h.face[h.next[i]], h.face[i], `next(h${i}) is on the same face`);
    const [s, t, left, right] = LECTURE_EDGES[i >> 1];
    assert.equal(h.origin[i], i % 2 === 0 ? s : t);
    assert.equal(h.face[i], i % 2 === 0 ? left : right);
  }
});

const run = (source, cases, extra = {}) => runInNode({ source, entry: extra.entry ?? 'edgesAroundVertex', cases, ...extra });
const one = async (source, extra = {}) => {
  const out = await run(source, [{ args: extra.args ?? [1], mesh: extra.mesh ?? wingedMesh() }], extra);
  assert.ok(out.results, JSON.stringify(out.error));
  return out.results[0];
};

test('a correct CCW walk around v2 returns e6 e5 e3 e2 and its trace lists exactly the reads, in order', async () => {
  const r = await one(CCW_WALK);
  assert.equal(r.ok, true, JSON.stringify(r.error));
  assert.deepEqual(r.value, [5, 4, 2, 1]);
  const read = (table, row, field, value) => ({ op: 'read', table, row, field, value });
  assert.deepEqual(traceEntries(r.trace), [
    read('vertex', 1, 'edge', 5),
    read('edge', 5, 'start', 1), read('edge', 5, 'startLeft', 4),
    read('edge', 4, 'start', 1), read('edge', 4, 'startLeft', 2),
    read('edge', 2, 'start', 1), read('edge', 2, 'startLeft', 1),
    read('edge', 1, 'start', 0), read('edge', 1, 'endRight', 5),
  ]);
  assert.equal(r.reads, 9);
  assert.equal(r.writes, 0);
  assert.equal(r.trace.cut, false);
  assert.equal(r.transaction, undefined);
});

test('the field order comes from edgeFields: the same walk over a permuted layout reads the same values', async () => {
  const w = lectureWinged();
  const order = ['endRight', 'start', 'left', 'startLeft', 'end', 'right', 'endLeft', 'startRight'];
  const edges = new Int32Array(56);
  for (let e = 0; e < 7; e++) order.forEach((name, k) => { edges[8 * e + k] = LECTURE_EDGES[e][EDGE_FIELDS.indexOf(name)]; });
  const r = await one(CCW_WALK, { mesh: { winged: { ...w, edges, edgeFields: order } } });
  assert.deepEqual(r.value, [5, 4, 2, 1]);
});

test('a wrong walk (S:R and E:L, clockwise) returns another ring', async () => {
  const wrong = CCW_WALK.replace('startLeft', 'startRight').replace('endRight', 'endLeft');
  const r = await one(wrong);
  assert.equal(r.ok, true);
  // e6 -S:R-> e2 -E:L-> e3 -S:R-> e5 -S:R-> e6
  assert.deepEqual(r.value, [5, 1, 2, 4]);
});

test('several cases run in order, each with its own trace', async () => {
  const out = await run(CCW_WALK, [{ args: [1], mesh: wingedMesh() }, { args: [0], mesh: wingedMesh() }]);
  assert.deepEqual(out.results.map((r) => r.value), [[5, 4, 2, 1], [0, 1]]);
  // v1: e1 (v1 is Start -> S:L e2), e2 (Start -> S:L e1): 1 + 2 + 2 reads.
  assert.equal(out.results[1].reads, 5);
});

test('syntax errors: the check runs before any case, with QuickJS\'s text and the exact line and column', async () => {
  const cases = [{ args: [1], mesh: wingedMesh() }];
  const a = await run('function edgesAroundVertex(mesh, v) {\n  let a = 1;\n  return a +;\n}', cases);
  assert.deepEqual(a.error, { kind: 'syntax', line: 3, column: 13, message: "Line 3, column 13: unexpected token in expression: ';'" });
  const b = await run('function edgesAroundVertex(mesh, v) {\n  return 1;\n}\n  }', cases);
  assert.equal(b.error.line, 4);
  assert.equal(b.error.column, 3);
  assert.match(b.error.message, /^Line 4, column 3: unexpected token.*'}'/);
  const c = await run('const x = ;', cases);
  assert.deepEqual([c.error.kind, c.error.line, c.error.column], ['syntax', 1, 11]);
  assert.equal(a.results, undefined, 'no case ran');
});

test('a runtime error carries the student\'s line', async () => {
  const r = await one('function edgesAroundVertex(mesh, v) {\n  const x = null;\n  return x.edge;\n}');
  assert.equal(r.ok, false);
  assert.equal(r.error.kind, 'runtime');
  assert.equal(r.error.line, 3);
  assert.match(r.error.message, /^Line 3, column \d+: TypeError: cannot read property 'edge' of null$/);
  const thrown = await one('function edgesAroundVertex(mesh, v) {\n\n  throw new Error("stuck at v" + v);\n}');
  assert.equal(thrown.error.line, 3);
  assert.match(thrown.error.message, /^Line 3, column \d+: stuck at v1$/);
});

test('a missing entry function is named', async () => {
  const r = await one('function edgesAround(mesh, v) { return []; }');
  assert.deepEqual(r.error, { kind: 'runtime', line: null, column: null, message: 'define a function named edgesAroundVertex' });
  const arrow = await one('const edgesAroundVertex = (mesh, v) => [v];');
  assert.deepEqual(arrow.value, [1], 'a top-level const arrow function counts');
});

test('a bad index says which indices exist, at the student\'s line', async () => {
  const r = await one('function edgesAroundVertex(mesh, v) {\n  const ok = mesh.edge(6).end;\n  return mesh.edge(99).start;\n}');
  assert.equal(r.error.kind, 'runtime');
  assert.equal(r.error.line, 3);
  assert.match(r.error.message, /^Line 3, column \d+: there is no edge 99: the edges are 0 to 6$/);
  assert.equal(r.reads, 1, 'the read of e7 before it is traced');
  const half = await one('function edgesAroundVertex(mesh, v) { return mesh.vertex(1.5).edge; }');
  assert.match(half.error.message, /there is no vertex 1\.5: the vertices are 0 to 4$/);
  const none = await one('function edgesAroundVertex(mesh, v) { return mesh.face(-1).edge; }');
  assert.match(none.error.message, /there is no face -1: the faces are 0 to 2 \(-1 means "none"\)$/);
  const text = await one('function edgesAroundVertex(mesh, v) { return mesh.edge("e1").start; }');
  assert.match(text.error.message, /there is no edge "e1": the edges are 0 to 6$/);
  const w = lectureWinged();
  w.edges.fill(-1, 8 * 3, 8 * 4); // e4 removed
  // A removed element's row stays, every entry -1, as the lesson's tables show it.
  const removed = await one('function edgesAroundVertex(mesh, v) { return [mesh.edge(3).start, mesh.edge(3).endRight, mesh.edge(2).start]; }', { mesh: { winged: w } });
  assert.equal(removed.ok, true);
  assert.deepEqual(removed.value, [-1, -1, 1]); // e3 starts at v2 (lecture 000)
  const other = await one('function edgesAroundVertex(mesh, v) {\n  return mesh.halfEdge(0).next;\n}');
  assert.match(other.error.message, /^Line 2, column \d+: this task gives the winged edge only$/);
});

test('read-only tasks refuse every assignment to the mesh', async () => {
  for (const statement of ['mesh.edge(1).startLeft = 5', 'mesh.vertex(0).edge = 2', 'mesh.vertex(0).position = [1, 2, 3]',
    'mesh.face(0).edge = 1', 'mesh.addEdge()', 'mesh.edgeCount = 3']) {
    const r = await one(`function edgesAroundVertex(mesh, v) {\n  ${statement};\n  return 0;\n}`);
    assert.equal(r.ok, false, statement);
    assert.match(r.error.message, /^Line 2, column \d+: this task only reads the structure; the mesh cannot be changed here$/, statement);
    assert.equal(r.writes, 0);
  }
});

test('writable tasks: writes go to an overlay that later reads see; adds return the next index; all of it is the transaction', async () => {
  const source = `function edgesAroundVertex(mesh, v) {
  const before = mesh.edge(1).startLeft;
  mesh.edge(1).startLeft = 5;
  const after = mesh.edge(1).startLeft;
  const nv = mesh.addVertex([3, 0, 0]);
  const ne = mesh.addEdge();
  const nf = mesh.addFace();
  mesh.edge(ne).start = nv;
  mesh.vertex(nv).edge = ne;
  mesh.face(nf).edge = ne;
  mesh.vertex(0).position = [0.5, 0, 0];
  return [before, after, nv, ne, nf, mesh.vertexCount, mesh.edgeCount, mesh.faceCount,
    mesh.edge(ne).end, mesh.vertex(nv).position, mesh.vertex(0).position];
}`;
  const r = await one(source, { writable: true });
  assert.equal(r.ok, true, JSON.stringify(r.error));
  assert.deepEqual(r.value, [0, 5, 5, 7, 3, 6, 8, 4, -1, [3, 0, 0], [0.5, 0, 0]]);
  assert.deepEqual(r.transaction, {
    writes: [
      { table: 'edge', row: 1, field: 'startLeft', value: 5 },
      { table: 'edge', row: 7, field: 'start', value: 5 },
      { table: 'vertex', row: 5, field: 'edge', value: 7 },
      { table: 'face', row: 3, field: 'edge', value: 7 },
      { table: 'vertex', row: 0, field: 'position', value: [0.5, 0, 0] },
    ],
    added: { vertex: [[3, 0, 0]], edge: 1, face: 1, halfEdge: 0 },
  });
  assert.equal(r.writes, 5);
  assert.equal(r.adds, 3);
  const entries = traceEntries(r.trace);
  assert.deepEqual(entries.slice(0, 4), [
    { op: 'read', table: 'edge', row: 1, field: 'startLeft', value: 0 },
    { op: 'write', table: 'edge', row: 1, field: 'startLeft', value: 5 },
    { op: 'read', table: 'edge', row: 1, field: 'startLeft', value: 5 },
    { op: 'add', table: 'vertex', row: 5 },
  ]);
});

test('writable tasks: a value out of range or not an index is refused at the line, the overlay unchanged', async () => {
  const r = await one('function edgesAroundVertex(mesh, v) {\n  mesh.edge(0).endLeft = 7;\n}', { writable: true });
  assert.match(r.error.message, /^Line 2, column \d+: endLeft must be an edge index/);
  assert.match(r.error.message, /from 0 to 6 or -1 for none\), not 7$/);
  assert.deepEqual(r.transaction.writes, []);
  const s = await one('function edgesAroundVertex(mesh, v) {\n  mesh.edge(0).left = "F1";\n}', { writable: true });
  assert.match(s.error.message, /left must be a face index \(a whole number from 0 to 2 or -1 for none\), not "F1"$/);
  const ok = await one('function edgesAroundVertex(mesh, v) {\n  mesh.edge(0).left = -1;\n  return mesh.edge(0).left;\n}', { writable: true });
  assert.equal(ok.value, -1);
});

test('each forbidden global gives the sandbox message, and typeof still works', async () => {
  for (const name of ['fetch', 'document', 'window', 'localStorage', 'importScripts', 'postMessage', 'XMLHttpRequest', 'require', 'process']) {
    const r = await one(`function edgesAroundVertex(mesh, v) {\n  return ${name}.length;\n}`);
    assert.equal(r.ok, false, name);
    assert.equal(r.error.message, `Line 2, column ${r.error.column}: ${name} is not available: your code runs in a sandbox that sees only the mesh`);
  }
  const t = await one('function edgesAroundVertex(mesh, v) { return [typeof fetch, typeof window, typeof require]; }');
  assert.deepEqual(t.value, ['undefined', 'undefined', 'undefined']);
});

test('prototype pollution stays in the engine\'s realm and does not survive to the next case', async () => {
  const source = `function edgesAroundVertex(mesh, v) {
  const seen = [Object.prototype.polluted === 1, typeof Array.prototype.push];
  Object.prototype.polluted = 1;
  Array.prototype.push = null;
  Array.prototype.toJSON = () => 'hacked';
  Object.defineProperty(Array.prototype, '0', { set() { throw new Error('setter'); }, configurable: true });
  JSON.stringify = () => '"hacked"';
  try { mesh.vertexCount = 0; } catch (e) {}
  mesh.extra = 1;
  return { seen, ring: [mesh.vertex(v).edge], count: mesh.vertexCount, extra: mesh.extra === undefined };
}`;
  const out = await run(source, [{ args: [1], mesh: wingedMesh() }, { args: [1], mesh: wingedMesh() }]);
  for (const r of out.results) {
    assert.equal(r.ok, true, JSON.stringify(r.error));
    assert.deepEqual(r.value, { seen: [false, 'function'], ring: [5], count: 5, extra: true });
  }
  assert.equal(Object.prototype.polluted, undefined);
  assert.equal(typeof Array.prototype.push, 'function');
  assert.equal(Array.prototype.toJSON, undefined);
  assert.equal(JSON.stringify([1]), '[1]');
});

test('an infinite loop stops within 2 s with kind timeout and the loop\'s line', async () => {
  const started = Date.now();
  const top = await one('function edgesAroundVertex(mesh, v) { return 1; }\nlet n = 0;\n\nfor (;;) {}\n', { budgetMs: 500 });
  assert.equal(top.error.kind, 'timeout');
  assert.equal(top.error.line, 4);
  assert.match(top.error.message, /^Line 4, column 1: your code ran longer than 0\.5 s and was stopped/);
  const nested = await one('function f() {\n  let i = 0;\n  while (true) {}\n}\nfunction g() { f() }\nfunction edgesAroundVertex(mesh, v) {\n  g();\n}', { budgetMs: 500 });
  assert.equal(nested.error.kind, 'timeout');
  assert.equal(nested.error.line, 3);
  const walking = await one('function edgesAroundVertex(mesh, v) {\n  let e = 0;\n  while (e !== -2) {\n    e = mesh.edge(e).startLeft;\n  }\n}', { budgetMs: 500 });
  assert.equal(walking.error.kind, 'timeout');
  assert.ok(walking.error.line === 3 || walking.error.line === 4, `line ${walking.error.line}`);
  assert.ok(walking.reads > 100, 'the reads before the stop are counted');
  assert.ok(Date.now() - started < 2000 * 3, 'three runs of 0.5 s each');
  const t0 = Date.now();
  const defaultBudget = await one('function edgesAroundVertex(mesh, v) {\n  for (;;) {}\n}');
  assert.equal(defaultBudget.error.kind, 'timeout');
  assert.equal(defaultBudget.error.line, 2);
  assert.ok(Date.now() - t0 < 2000, `stopped after ${Date.now() - t0} ms`);
});

test('a timeout names the loop that was running: one-line functions, a top-level loop below a function with a loop', async () => {
  const oneLine = await one('function f(){ while(true){} } function g(){ f() }\nfunction edgesAroundVertex(mesh, v) { g(); }', { budgetMs: 300 });
  assert.deepEqual([oneLine.error.kind, oneLine.error.line, oneLine.error.column], ['timeout', 1, 15]);
  const below = await one('function edgesAroundVertex(mesh, v) {\n  for (let i = 0; i < 3; i++) {}\n  return 0;\n}\n/* while */\nwhile (true) {}\n', { budgetMs: 300 });
  assert.deepEqual([below.error.kind, below.error.line, below.error.column], ['timeout', 6, 1]);
});

test('deep recursion stops cleanly, and the engine runs the next case', async () => {
  const out = await run('function edgesAroundVertex(mesh, v) {\n  return edgesAroundVertex(mesh, v + 1) + 1;\n}', [{ args: [1], mesh: wingedMesh() }]);
  const r = out.results[0];
  assert.equal(r.ok, false);
  assert.equal(r.error.kind, 'runtime');
  assert.equal(r.error.line, 2);
  assert.match(r.error.message, /too much recursion/);
  assert.equal(r.engineFailed, undefined);
  const sandbox = createNodeSandbox();
  const again = await sandbox.run({ source: CCW_WALK, entry: 'edgesAroundVertex', cases: [{ args: [1], mesh: wingedMesh() }] });
  assert.deepEqual(again.results[0].value, [5, 4, 2, 1]);
});

test('a huge allocation hits the memory limit cleanly', async () => {
  const r = await one('function edgesAroundVertex(mesh, v) {\n  const all = [];\n  all.push(new Array(50000000).fill(v));\n}');
  assert.equal(r.ok, false);
  assert.equal(r.error.kind, 'memory');
  assert.equal(r.error.line, 3);
  assert.match(r.error.message, /used more than 32 MB of memory/);
  const single = await one('function edgesAroundVertex(mesh, v) {\n  return new Array(1e8).fill(0).length;\n}');
  assert.deepEqual([single.error.kind, single.error.line], ['memory', 2]);
  // Typed arrays keep their bytes outside the engine's accounting, so the sandbox has none.
  const typed = await one('function edgesAroundVertex(mesh, v) {\n  return new Float64Array(1e8).length;\n}');
  assert.equal(typed.error.message, `Line 2, column ${typed.error.column}: Float64Array is not available in the sandbox: use an ordinary array`);
  const next = await one(CCW_WALK);
  assert.deepEqual(next.value, [5, 4, 2, 1]);
});

test('returning a function, NaN, a cycle or a Map is a result error; undefined is said', async () => {
  const fn = await one('function edgesAroundVertex(mesh, v) { return [1, () => 2]; }');
  assert.deepEqual(fn.error, { kind: 'result', line: null, column: null, message: 'your function returned a function at [1] (did you forget to call it?)' });
  const nan = await one('function edgesAroundVertex(mesh, v) { return { ring: [0, 0 / 0] }; }');
  assert.equal(nan.error.message, 'your function returned NaN at .ring[1]; return finite numbers');
  const inf = await one('function edgesAroundVertex(mesh, v) { return 1 / 0; }');
  assert.equal(inf.error.message, 'your function returned Infinity; return finite numbers');
  const cycle = await one('function edgesAroundVertex(mesh, v) { const a = [1]; a.push(a); return a; }');
  assert.equal(cycle.error.kind, 'result');
  assert.match(cycle.error.message, /cycle/);
  const map = await one('function edgesAroundVertex(mesh, v) { return new Map(); }');
  assert.match(map.error.message, /not plain data/);
  const nothing = await one('function edgesAroundVertex(mesh, v) { }');
  assert.deepEqual([nothing.ok, nothing.value, nothing.returnedUndefined], [true, null, true]);
});

test('the trace stops recording at its cap and says so, while the counts go on', async () => {
  const r = await one(`function edgesAroundVertex(mesh, v) {
  let s = 0;
  for (let i = 0; i < ${TRACE_LIMIT + 10}; i++) s += mesh.vertex(0).edge;
  return s;
}`, { budgetMs: 20000 });
  assert.equal(r.ok, true, JSON.stringify(r.error));
  assert.equal(r.value, 0);
  assert.equal(r.trace.count, TRACE_LIMIT);
  assert.equal(r.trace.total, TRACE_LIMIT + 10);
  assert.equal(r.trace.cut, true);
  assert.equal(r.reads, TRACE_LIMIT + 10);
});

test('console.log lines come back with the result', async () => {
  const r = await one('function edgesAroundVertex(mesh, v) {\n  console.log("at", v, [mesh.vertex(v).edge]);\n  return 0;\n}');
  assert.deepEqual(r.logs, ['at 1 [5]']);
});

test('the half-edge API walks the lecture mesh: twin is h ^ 1, target the twin\'s origin', async () => {
  // CCW around v2 from its boundary half-edge h3 (v2 -> v1): h <- twin(prev(h)).
  // h3 -> prev h11 (v5->v2) -> twin h10 -> prev h9 -> twin h8 -> prev h5 -> twin h4 -> prev h2 -> twin h3.
  const source = `function ringAround(mesh, v) {
  const first = mesh.vertex(v).halfEdge;
  const ring = [];
  let h = first;
  do {
    ring.push(mesh.halfEdge(h).target);
    h = mesh.halfEdge(mesh.halfEdge(h).prev).twin;
  } while (h !== first);
  return ring;
}`;
  const out = await run(source, [{ args: [1], mesh: { halfEdge: lectureHalfEdge() } }], { entry: 'ringAround' });
  const r = out.results[0];
  assert.equal(r.ok, true, JSON.stringify(r.error));
  assert.deepEqual(r.value, [0, 4, 3, 2], 'v1, v5, v4, v3');
  const entries = traceEntries(r.trace);
  assert.deepEqual(entries.slice(0, 4), [
    { op: 'read', table: 'vertex', row: 1, field: 'halfEdge', value: 3 },
    { op: 'read', table: 'halfEdge', row: 3, field: 'target', value: 0 },
    { op: 'read', table: 'halfEdge', row: 3, field: 'prev', value: 11 },
    { op: 'read', table: 'halfEdge', row: 11, field: 'twin', value: 10 },
  ]);
  assert.equal(r.reads, 1 + 4 * 3);
  const fields = await run('function f(mesh) {\n  const h = mesh.halfEdge(5);\n  return [mesh.halfEdgeCount, h.origin, h.face, h.next, h.prev, h.twin, h.target, mesh.face(1).halfEdge, mesh.vertexCount, mesh.edgeCount];\n}',
    [{ mesh: { halfEdge: lectureHalfEdge() } }], { entry: 'f' });
  // h5: e3 reversed, v3 -> v2 on F2; next h8 (v2 -> v4), prev h7 (v4 -> v3).
  assert.deepEqual(fields.results[0].value, [14, 2, 1, 8, 7, 4, 1, 8, 5, 7]);
  const noWinged = await run('function f(mesh) {\n  return mesh.edge(0).start;\n}', [{ mesh: { halfEdge: lectureHalfEdge() } }], { entry: 'f' });
  assert.match(noWinged.results[0].error.message, /^Line 2, column \d+: this task gives the half-edge only$/);
});

test('half-edge writes and a new pair go to the transaction', async () => {
  const source = `function f(mesh) {
  const h = mesh.addHalfEdgePair();
  mesh.halfEdge(h).origin = 1;
  mesh.halfEdge(h + 1).origin = 4;
  mesh.halfEdge(h).next = h + 1;
  mesh.vertex(4).halfEdge = h + 1;
  return [h, mesh.halfEdgeCount, mesh.halfEdge(h).target, mesh.halfEdge(h + 1).face];
}`;
  const out = await run(source, [{ mesh: { winged: lectureWinged(), halfEdge: lectureHalfEdge() } }], { entry: 'f', writable: true });
  const r = out.results[0];
  assert.equal(r.ok, true, JSON.stringify(r.error));
  assert.deepEqual(r.value, [14, 16, 4, -1]);
  assert.deepEqual(r.transaction.added, { vertex: [], edge: 0, face: 0, halfEdge: 2 });
  assert.deepEqual(r.transaction.writes.map((w) => [w.table, w.row, w.field, w.value]),
    [['halfEdge', 14, 'origin', 1], ['halfEdge', 15, 'origin', 4], ['halfEdge', 14, 'next', 15], ['vertex', 4, 'halfEdge', 15]]);
  const twin = await run('function f(mesh) {\n  mesh.halfEdge(0).twin = 3;\n}', [{ mesh: { halfEdge: lectureHalfEdge() } }], { entry: 'f', writable: true });
  assert.match(twin.results[0].error.message, /^Line 2, column \d+: twin is h \^ 1/);
});

test('a malformed request is refused before anything runs', async () => {
  const out = await runInNode({ source: 'x', entry: 'not a name', cases: [] });
  assert.equal(out.error.kind, 'request');
  const bad = await runInNode({ source: 'x', entry: 'f', cases: [{ mesh: { winged: { ...lectureWinged(), edges: [1, 2] } } }] });
  assert.equal(bad.error.kind, 'request');
});

test('every runtime and context is disposed, whatever the case ended with, and the engine\'s memory does not grow', async () => {
  // The module, with every runtime it makes recorded (quickjs-emscripten's own test wrapper
  // does not see runtimes freed in this version) and every context those runtimes make.
  const base = await newQuickJSWASMModuleFromVariant(releaseSync);
  const runtimes = [];
  const contexts = [];
  const engine = {
    newRuntime(options) {
      const runtime = base.newRuntime(options);
      runtimes.push(runtime);
      const newContext = runtime.newContext.bind(runtime);
      runtime.newContext = (o) => { const c = newContext(o); contexts.push(c); return c; };
      return runtime;
    },
  };
  const assertAllDisposed = () => {
    assert.ok(runtimes.length > 0 && contexts.length > 0);
    assert.deepEqual(runtimes.filter((r) => r.alive).length, 0, 'no runtime left alive');
    assert.deepEqual(contexts.filter((c) => c.alive).length, 0, 'no context left alive');
  };
  const programs = [
    [CCW_WALK, {}],
    ['function edgesAroundVertex(mesh, v) {\n  return mesh.edge(99).start;\n}', {}],
    ['function edgesAroundVertex(mesh, v) {\n  for (;;) {}\n}', { budgetMs: 100 }],
    ['function edgesAroundVertex(mesh, v) {\n  mesh.edge(0).start = 1;\n  return [mesh.addEdge(), () => 1];\n}', { writable: true }],
    ['function edgesAroundVertex(mesh, v) {\n  throw "plain text";\n}', {}],
    ['function edgesAroundVertex(mesh, v) {\n  return edgesAroundVertex(mesh, v);\n}', {}],
    ['function edgesAroundVertex(mesh, v) {\n  return 1 +;\n}', {}],
  ];
  const runAll = () => {
    for (const [source, extra] of programs) {
      const out = runStudentCode(engine, { source, entry: 'edgesAroundVertex', cases: [{ args: [1], mesh: wingedMesh() }], ...extra });
      assert.ok(out.results || out.error.kind === 'syntax');
      for (const r of out.results ?? []) assert.equal(r.engineFailed, undefined, JSON.stringify(r.error));
    }
  };
  runAll();
  assertAllDisposed();
  const bytes = base.getWasmMemory().buffer.byteLength;
  for (let i = 0; i < 10; i++) runAll();
  assertAllDisposed();
  assert.equal(base.getWasmMemory().buffer.byteLength, bytes, 'the wasm memory did not grow over 70 more runs');
});
