// The tasks of "Program the structure" (web/js/lessons/code/), graded as the page grades them:
// the cases the core builds (cases.js), the student's code in the QuickJS sandbox under Node
// (web/js/code/quickjs-node.js), the grade (grading.js). For every task: the lecture's rule
// written as a student would passes every case for many seeds, and the trace of that rule
// reads exactly as many entries as the core's counting reader says the lecture's rule reads
// (two independent counts); typical wrong solutions fail, at the case the test expects, with
// the message naming the mesh, the element and where the answers part.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from '../../dist/js/core/wingspline.js';
import { TASKS, taskOf } from '../../web/js/lessons/code/tasks.js';
import { makeCases, lectureCase, sandboxMesh, HIDDEN_KINDS, seeded } from '../../web/js/lessons/code/cases.js';
import { gradeRun, failureText, partsAt, samePoint, meshScale } from '../../web/js/lessons/code/grading.js';
import { createNodeSandbox } from '../../web/js/code/quickjs-node.js';
import { CORRECT } from '../helpers/code-solutions.mjs';
import { runTask } from '../../web/js/lessons/code/check.js';

const api = await loadWingspline({ parts: ['mesh', 'subdivision', 'exercises'] });
const sandbox = createNodeSandbox();

// The lecture's rules, as a student would write them: tests/helpers/code-solutions.mjs.

// Typical mistakes, and the first case each must fail on (0: the slide's mesh).
const WRONG = {
  'edges-around-vertex': [
    // The wrong wing at the start: clockwise on the slide's v2 already.
    { source: CORRECT['edges-around-vertex'].replace('r.startLeft', 'r.startRight'), firstFail: 0 },
    // Never turning at the end vertex: fine while v is every edge's start, wrong on the slide's v2 (e2 ends there).
    { source: CORRECT['edges-around-vertex'].replace("r.start === v ? r.startLeft : r.endRight", 'r.startLeft'), firstFail: 0 },
  ],
  'edges-of-face': [{ source: CORRECT['edges-of-face'].replace('r.endLeft', 'r.startLeft'), firstFail: 0 }],
  'faces-around-vertex': [
    // Keeping the boundary's none: the slide's v2 is on the boundary (e2 has no right face).
    { source: CORRECT['faces-around-vertex'].replace('if (f !== -1) faces.push(f);', 'faces.push(f);'), firstFail: 0 },
  ],
  'euler-characteristic': [
    // Testing an index for truth: edge 0 is falsy, so the slide's v1 (it stores e1, edge 0) is not counted.
    { source: CORRECT['euler-characteristic'].replace('if (mesh.vertex(v).edge !== -1) V++', 'if (mesh.vertex(v).edge > 0) V++'), firstFail: 0 },
  ],
  'half-edges-around-vertex': [{ source: CORRECT['half-edges-around-vertex'].replace('.prev).twin', '.next).twin'), firstFail: 0 }],
  'half-edges-of-face': [{ source: CORRECT['half-edges-of-face'].replace('.next;', '.twin;'), firstFail: 0 }],
  'split-edge': [
    // The edges at E keep pointing at e: the slide's e3 has neighbours at its end.
    { source: CORRECT['split-edge'].replace('setWing(a, E, L, n);', ''), firstFail: 0 },
    // The new vertex a third of the way: the tables are right, its position is not.
    { source: CORRECT['split-edge'].replace('(sx + ex) / 2', '(sx + ex) / 3'), firstFail: 0, message: /its position is not the midpoint/ },
  ],
  'loop-edge-point': [
    // The midpoint everywhere: right on the boundary, and on the slide's e3 too (v1 v2 v4 v3 is
    // a parallelogram, so c + d = S + E there); wrong on the tetrahedron, the third case.
    { source: CORRECT['loop-edge-point'].replace('if (r.left === -1 || r.right === -1) return', 'return'), firstFail: 2 },
    // The weights swapped, 1/8 (S + E) + 3/8 (c + d): the same point where c + d = S + E (the
    // slide's e3 again), wrong on the tetrahedron.
    { source: CORRECT['loop-edge-point'].replace('3 / 8 * (S[k] + E[k]) + 1 / 8 * (c[k] + d[k])', '1 / 8 * (S[k] + E[k]) + 3 / 8 * (c[k] + d[k])'), firstFail: 2 },
  ],
  'loop-vertex-point': [
    // The interior rule on the boundary too: the slide's v2 is on the boundary.
    { source: CORRECT['loop-vertex-point'].replace('if (boundary.length === 2) return', 'if (false) return'), firstFail: 0 },
    // 3/(8n) instead of Loop's weight: the two agree at valence 6 only (both 1/16); on the
    // boundary (the slide's v2, the fan's centre) neither is used; the tetrahedron's valence 3
    // gives 1/8 against Loop's 3/16: the third case.
    { source: CORRECT['loop-vertex-point'].replace('const beta = (5 / 8 - Math.pow(3 / 8 + Math.cos(2 * Math.PI / n) / 4, 2)) / n;', 'const beta = 3 / (8 * n);'), firstFail: 2 },
  ],
  'catmull-clark-face-point': [
    // The edge's start whatever the side: the slide's F1 lies right of e1 (v1 -> v3), so v1 is
    // counted twice and v3 not at all.
    { source: CORRECT['catmull-clark-face-point'].replace('r.left === f ? r.start : r.end', 'r.start'), firstFail: 0 },
  ],
  'flip-edge': [
    // Forgetting what the end vertex stores: the slide's v3 stores e3 itself.
    { source: CORRECT['flip-edge'].replace('if (mesh.vertex(E).edge === e) mesh.vertex(E).edge = c;', ''), firstFail: 0 },
    // Turning e the wrong way round (c -> d) with the same wings.
    { source: CORRECT['flip-edge'].replace('r.start = dv; r.end = cv;', 'r.start = cv; r.end = dv;'), firstFail: 0 },
  ],
};

// Graded as the page and the grader grade: check.js runTask, one mesh at a time; an edit by
// the core's table check against the faces of the core's own edit of the same mesh (and the
// new vertices' positions against the core's).
async function grade(task, source, seed) {
  const ran = await runTask({ api, checker: () => api, task, source, seed, run: (request) => sandbox.run(request) });
  assert.ok(!ran.error, ran.error?.message);
  return ran.grade;
}

test('the cases: the slide\'s mesh first, then one of each hidden kind, all valid, the same for the same seed', () => {
  for (const task of TASKS) {
    const a = makeCases(api, task, 7);
    const b = makeCases(api, task, 7);
    assert.equal(a.length, 1 + HIDDEN_KINDS.length);
    assert.equal(a[0].label, 'the slide\'s mesh (lecture 000)');
    assert.deepEqual(a[0].args, task.lectureArgs);
    assert.deepEqual(a.map((c) => [c.args, c.expected]), b.map((c) => [c.args, c.expected]));
    // A case not asked is one whose mesh has no element the task's edit accepts.
    // (or, for Loop's points, a mesh with faces that are not triangles: the cube, the joined grid,
    // a sphere after splits).
    for (const c of a.filter((x) => !x.args)) {
      assert.ok((task.answer === 'edit' && /no edge of it/.test(c.skipped)) || (task.scheme === 'loop' && /not triangles/.test(c.skipped)), `${task.id}: ${c.label}`);
    }
  }
  // The slide's answers, as the statements and lecture 000 give them.
  assert.deepEqual(lectureCase(api, taskOf('edges-around-vertex')).expected, [5, 4, 2, 1]); // e6 e5 e3 e2
  assert.deepEqual(lectureCase(api, taskOf('edges-of-face')).expected, [0, 1, 2]); // e1 e2 e3
  assert.deepEqual(lectureCase(api, taskOf('faces-around-vertex')).expected, [2, 1, 0]); // F3 F2 F1
  assert.equal(lectureCase(api, taskOf('euler-characteristic')).expected, 1); // 5 - 7 + 3
  // Flipping e3 of the slide (v2 -> v3 between F1 and F2) joins v4 and v1: F1 = (v1 v2 v4), F2 = (v4 v3 v1).
  const flip = lectureCase(api, taskOf('flip-edge')).expected;
  const facesAfter = [0, 1, 2].map((f) => Array.from(flip.faceVertices.subarray(flip.faceOffsets[f], flip.faceOffsets[f + 1])));
  const rotated = (face, first) => { const k = face.indexOf(first); return [...face.slice(k), ...face.slice(0, k)]; };
  assert.deepEqual(rotated(facesAfter[0], 0), [0, 1, 3]);
  assert.deepEqual(rotated(facesAfter[1], 3), [3, 2, 0]);
  // Splitting e3 (v2 -> v3, F1 on its left, F2 on its right) puts v6 between v2 and v3 in both:
  // F1 = (v1 v2 v6 v3), F2 = (v2 v4 v3 v6); v6 is the midpoint of the slide's v2 and v3.
  const split = lectureCase(api, taskOf('split-edge')).expected;
  const splitFaces = [0, 1].map((f) => Array.from(split.faceVertices.subarray(split.faceOffsets[f], split.faceOffsets[f + 1])));
  assert.deepEqual(rotated(splitFaces[0], 0), [0, 1, 5, 2]);
  assert.deepEqual(rotated(splitFaces[1], 1), [1, 3, 2, 5]);
  assert.equal(split.vertexCount, 6);
  const P = api.lectureExample().positions;
  assert.deepEqual(split.newPositions[0], [0, 1, 2].map((k) => (P[3 + k] + P[6 + k]) / 2));
  assert.equal(api.liveMeshCount(), 0, 'every case mesh is disposed');
});

test('a removed element\'s row reads -1 in every entry of the snapshot', () => {
  const cases = makeCases(api, taskOf('euler-characteristic'), 3);
  const joined = cases[5];
  const w = joined.snapshot.winged;
  const removedFaces = [...w.faceEdge].filter((x) => x === -1).length;
  assert.ok(removedFaces >= 1, 'the joined grid has removed faces');
  // V - E + F counted from the live rows is the core's Euler characteristic (a disc: 1).
  const V = [...w.vertexEdge].filter((x) => x !== -1).length;
  let E = 0;
  for (let e = 0; e < w.edges.length / 8; e += 1) {
    const row = w.edges.subarray(8 * e, 8 * e + 8);
    if (row[0] === -1) assert.ok(row.every((x) => x === -1), `removed edge ${e}: every entry -1`);
    else E += 1;
  }
  const F = w.faceEdge.length - removedFaces;
  assert.equal(V - E + F, 1);
  assert.equal(joined.expected, 1);
});

for (const task of TASKS) {
  test(`${task.id}: the lecture's rule passes every case for 12 seeds, reading what the core says the rule reads`, async () => {
    for (let seed = 1; seed <= 12; seed += 1) {
      const g = await grade(task, CORRECT[task.id], seed * 7919);
      assert.equal(g.firstFail, null, `seed ${seed}: ${g.firstFail !== null ? failureText(task, g.cases[g.firstFail]) : ''}`);
      // A walk reads what the core's counting reader says the lecture's rule reads; an edit's
      // reference is the core's own writes, compared with nothing (another order is as right).
      // A subdivision point has no counting reader in the core: its cases are asked, that is all.
      if (task.answer === 'edit' || task.answer === 'position') assert.ok(g.asked >= 5, `${g.asked} meshes asked`);
      else for (const c of g.cases) assert.equal(c.reads, c.referenceReads, `${c.label}: traced reads against the core's count`);
    }
  });
  test(`${task.id}: typical mistakes fail where they must, with the mesh, the element and the difference named`, async () => {
    for (const { source, firstFail, message } of WRONG[task.id]) {
      const g = await grade(task, source, 12345);
      assert.equal(g.firstFail, firstFail, source);
      const failed = g.cases[firstFail];
      const text = failureText(task, failed);
      assert.match(text, new RegExp(`^On ${failed.label.replace(/[()]/g, '\\$&')}`));
      if (failed.check) {
        assert.match(text, new RegExp(`the tables your function left are not the winged edge of the mesh after the ${task.editName}, so nothing was applied\\. (The vertex|The edge|The face|Row)`));
        if (message) assert.match(text, message);
      } else if (!failed.error) {
        assert.match(text, /expected .* your function returned/);
        if (task.answer === 'position') assert.match(text, /expected \(-?[\d.e-]+, -?[\d.e-]+, -?[\d.e-]+\), your function returned \(/);
        else assert.equal(partsAt(failed.expected, failed.value), failed.partsAt);
      }
    }
  });
}

test('an endless walk (the stop condition never met) stops on every case with the loop\'s line, and the run goes on', async () => {
  const task = taskOf('edges-around-vertex');
  const source = CORRECT['edges-around-vertex'].replace('} while (e !== first);', '} while (e !== -2);');
  const cases = makeCases(api, task, 1).slice(0, 2);
  const t0 = performance.now();
  const answer = await sandbox.run({ source, entry: task.entry, budgetMs: 300, cases: cases.map((c) => ({ args: c.args, mesh: sandboxMesh(task, c) })) });
  const g = gradeRun(task, cases, answer.results);
  assert.ok(performance.now() - t0 < 4000);
  assert.equal(g.firstFail, 0);
  for (const c of g.cases) {
    assert.equal(c.error?.kind, 'timeout');
    // The do ... while loop spans lines 5 to 9 of the source.
    assert.ok(c.error.line >= 5 && c.error.line <= 9, `line ${c.error.line}`);
  }
});

test('a half-edge task is given the half-edge only: reading a winged-edge pointer is an error at its line', async () => {
  const task = taskOf('half-edges-around-vertex');
  const c = lectureCase(api, task);
  const answer = await sandbox.run({ source: 'function halfEdgesAroundVertex(mesh, v) {\n  return [mesh.vertex(v).edge];\n}', entry: task.entry, budgetMs: 1500, cases: [{ args: c.args, mesh: sandboxMesh(task, c) }] });
  assert.equal(answer.results[0].ok, false);
  assert.match(answer.results[0].error.message, /^Line 2, column \d+: this task gives the half-edge only/);
});

test('the seeded generator: the same seed, the same numbers; spread over [0, 1)', () => {
  const a = seeded(42); const b = seeded(42);
  const xs = Array.from({ length: 1000 }, () => a.next());
  assert.deepEqual(xs, Array.from({ length: 1000 }, () => b.next()));
  assert.ok(xs.every((x) => x >= 0 && x < 1));
  const mean = xs.reduce((s, x) => s + x, 0) / xs.length;
  assert.ok(Math.abs(mean - 0.5) < 0.05, `mean ${mean}`);
});

test('a point is compared against the mesh\'s size: the same verdicts on a mesh a million times smaller or larger', () => {
  for (const s of [1e-6, 1, 1e6]) {
    // A triangle (0,0,0) (2s,0,0) (0,3s,0): its size is 3s; the point asked lies on an axis, so
    // one of its coordinates is 0 and cannot set the tolerance itself.
    const snapshot = { winged: { positions: Float64Array.from([0, 0, 0, 2 * s, 0, 0, 0, 3 * s, 0]) } };
    assert.equal(meshScale(snapshot), 3 * s);
    const want = [0, 1.5 * s, 0];
    assert.ok(samePoint(want, [1e-12 * s, 1.5 * s * (1 + 1e-15), 0], meshScale(snapshot)), `${s}: rounding-sized differences pass`);
    assert.ok(!samePoint(want, [1e-6 * s, 1.5 * s, 0], meshScale(snapshot)), `${s}: a millionth of the mesh does not`);
    for (const bad of [[0, 1.5 * s], [NaN, 1.5 * s, 0], [0, Infinity, 0], '0,1,0', null]) assert.equal(samePoint(want, bad, meshScale(snapshot)), false, `${s}: ${bad}`);
  }
});
