// The homework scripts in examples/ run as a student runs them (`node
// examples/<name>.mjs`, importing 'wingspline' by name) and print what the lectures say.
// Every expected value is recomputed here from the lectures' rules, never copied from a run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { repoRoot } from '../helpers/browser.mjs';
import { SLIDE_EDGE_TABLE } from '../helpers/lecture-slide.mjs';

const run = (script, args = []) => execFileSync(process.execPath, [path.join('examples', script), ...args], { cwd: repoRoot, encoding: 'utf8' });
const line = (out, label) => {
  const found = out.split('\n').find((l) => l.startsWith(label));
  assert.ok(found, `a line starting '${label}' in:\n${out}`);
  return found.slice(label.length).trim();
};

// ---------------------------------------------------------------- (a) OBJ -> winged edge
test('winged-edge-table.mjs: the lecture mesh\'s OBJ gives a winged-edge table consistent with its faces, and the CCW walk around v2 meets v5, v4, v3, v1 as on lecture 000\'s slide', () => {
  const out = run('winged-edge-table.mjs');
  // The OBJ read here, independently: vertices and faces (1-based).
  const obj = fs.readFileSync(path.join(repoRoot, 'examples', 'lecture-mesh.obj'), 'utf8').split('\n');
  const faces = obj.filter((l) => l.startsWith('f ')).map((l) => l.split(/\s+/).slice(1).map((t) => Number(t.split('/')[0])));
  const vertexCount = obj.filter((l) => l.startsWith('v ')).length;
  assert.deepEqual([vertexCount, faces.length], [5, 3]);
  const edges = new Map();
  for (const m of out.matchAll(/^e(\d+)\s+v(\d+)\s+v(\d+)\s+(F\d+|-)\s+(F\d+|-)\s+e(\d+)\s+e(\d+)\s+e(\d+)\s+e(\d+)\s*$/gm)) {
    const face = (t) => (t === '-' ? null : Number(t.slice(1)));
    edges.set(Number(m[1]), { s: Number(m[2]), e: Number(m[3]), l: face(m[4]), r: face(m[5]), sl: Number(m[6]), sr: Number(m[7]), el: Number(m[8]), er: Number(m[9]) });
  }
  assert.equal(edges.size, 7, `7 edge rows (V - E + F = 1 for a disc):\n${out}`);
  // Left face: the one whose corner cycle runs S -> E; right face: the one running E -> S.
  const runs = (f, a, b) => faces[f - 1].some((v, i, c) => v === a && c[(i + 1) % c.length] === b);
  const faceRunning = (a, b) => { const i = faces.findIndex((_, f) => runs(f + 1, a, b)); return i < 0 ? null : i + 1; };
  for (const [n, e] of edges) {
    assert.equal(e.l, faceRunning(e.s, e.e), `e${n}: its left face runs v${e.s} -> v${e.e}`);
    assert.equal(e.r, faceRunning(e.e, e.s), `e${n}: its right face runs v${e.e} -> v${e.s}`);
  }
  const walk = line(out, 'CCW walk around v2:').split(/\s+/).map((t) => Number(t.replace(/^e/, '')));
  // Lecture 000's walk rule: at an edge whose Start is v, the next edge is its S:L wing,
  // otherwise its E:R wing; the walk stops when it returns to the first edge.
  walk.forEach((n, i) => {
    const e = edges.get(n);
    const next = e.s === 2 ? e.sl : e.er;
    assert.equal(next, walk[(i + 1) % walk.length], `after e${n} the rule reads e${next}`);
  });
  const neighbours = walk.map((n) => { const e = edges.get(n); return e.s === 2 ? e.e : e.s; });
  // The slide: e6 (v2-v5), e5 (v2-v4), e3 (v2-v3), e2 (v1-v2), as a cycle.
  const k = neighbours.indexOf(5);
  assert.deepEqual([...neighbours.slice(k), ...neighbours.slice(0, k)], [5, 4, 3, 1], `the walk ${walk} meets ${neighbours}`);
});

test('winged-edge-table.mjs --slide: lecture 000\'s numbering gives the slide\'s edge table row for row and the walk e6 e5 e3 e2', () => {
  const out = run('winged-edge-table.mjs', ['--slide']);
  // Lecture 000, "Winged Edge", EDGE TABLE (tests/helpers/lecture-slide.mjs).
  const slide = SLIDE_EDGE_TABLE;
  const rows = out.split('\n').filter((l) => /^e\d+\s+v\d/.test(l)).map((l) => l.trim().split(/\s+/).join(' '));
  assert.deepEqual(rows, slide);
  assert.equal(line(out, 'CCW walk around v2:'), 'e6 e5 e3 e2');
});

// ---------------------------------------------------------------- (b) knot insertion
function parseArray(out, label) { return JSON.parse(line(out, label)); }

test('bspline-knot.mjs: Boehm\'s rule gives the new control points, and the curve sampled before and after in the CSV is the same', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'wingspline-example-'));
  try {
    const csvFile = path.join(dir, 'samples.csv');
    const out = run('bspline-knot.mjs', [csvFile]);
    const p = Number(line(out, 'degree:'));
    const u = Number(line(out, 'insert u ='));
    const t = parseArray(out, 'knots before:');
    const P = parseArray(out, 'points before:'); // [[x, y], ...]
    const t2 = parseArray(out, 'knots after:');
    const Q = parseArray(out, 'points after:');
    assert.deepEqual(t2, [...t.filter((x) => x <= u), u, ...t.filter((x) => x > u)], 'u joins the knot vector in order');
    // Boehm (lecture 003): span k with t_k <= u < t_k+1; Q_i = a_i P_i + (1 - a_i) P_i-1,
    // a_i = (u - t_i) / (t_i+p - t_i) for k-p+1 <= i <= k; the others are kept.
    let k = t.length - p - 2;
    while (!(t[k] <= u && u < t[k + 1])) k -= 1;
    const expected = [];
    for (let i = 0; i <= P.length; i += 1) {
      if (i <= k - p) expected.push(P[i]);
      else if (i >= k + 1) expected.push(P[i - 1]);
      else {
        const a = (u - t[i]) / (t[i + p] - t[i]);
        expected.push([0, 1].map((c) => a * P[i][c] + (1 - a) * P[i - 1][c]));
      }
    }
    // Tolerance: 1e-12 times the control polygon's size (largest coordinate magnitude).
    const size = Math.max(...P.flat().map(Math.abs));
    assert.equal(Q.length, expected.length);
    Q.forEach((q, i) => assert.ok(Math.hypot(q[0] - expected[i][0], q[1] - expected[i][1]) <= 1e-12 * size, `Q${i} = ${q}, Boehm gives ${expected[i]}`));
    const [head, ...rows] = fs.readFileSync(csvFile, 'utf8').trim().split('\n');
    assert.equal(head, 'u,x_before,y_before,x_after,y_after');
    const values = rows.map((r) => r.split(',').map(Number));
    assert.ok(values.length >= 50, `${values.length} samples`);
    assert.equal(values[0][0], t[p]);
    assert.equal(values.at(-1)[0], t[t.length - p - 1]);
    for (const [s, xb, yb, xa, ya] of values) assert.ok(Math.hypot(xa - xb, ya - yb) <= 1e-12 * size, `u = ${s}: (${xb}, ${yb}) before, (${xa}, ${ya}) after`);
    // A clamped curve starts at its first control point and ends at its last.
    assert.ok(Math.hypot(values[0][1] - P[0][0], values[0][2] - P[0][1]) <= 1e-12 * size);
    assert.ok(Math.hypot(values.at(-1)[1] - P.at(-1)[0], values.at(-1)[2] - P.at(-1)[1]) <= 1e-12 * size);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

// ---------------------------------------------------------------- (c) joints
// C^k / G^k of cubic Bezier segments a, b at a's end and b's start, from the lectures'
// definitions: P'(1) = 3 (P3 - P2), P'(0) = 3 (P1 - P0), P''(1) = 6 (P3 - 2 P2 + P1),
// P''(0) = 6 (P2 - 2 P1 + P0); G1: same unit tangent; G2: also the same curvature vector
// (P'' - (P''.T) T) / |P'|^2. Tolerance 1e-9 relative to the segments' size.
function expectedJoint(a, b) {
  const sub = (x, y) => [x[0] - y[0], x[1] - y[1]];
  const lin = (...terms) => [0, 1].map((c) => terms.reduce((s, [w, p]) => s + w * p[c], 0));
  const size = Math.max(...[...a, ...b].flat().map(Math.abs));
  const same = (x, y, scale = size) => Math.hypot(...sub(x, y)) <= 1e-9 * scale;
  const d1a = lin([3, a[3]], [-3, a[2]]);
  const d1b = lin([3, b[1]], [-3, b[0]]);
  const d2a = lin([6, a[3]], [-12, a[2]], [6, a[1]]);
  const d2b = lin([6, b[2]], [-12, b[1]], [6, b[0]]);
  const c0 = same(a[3], b[0]);
  const c1 = c0 && same(d1a, d1b, Math.hypot(...d1a) + Math.hypot(...d1b));
  const c2 = c1 && same(d2a, d2b, Math.hypot(...d2a) + Math.hypot(...d2b));
  const unit = (v) => v.map((x) => x / Math.hypot(...v));
  const g1 = c0 && same(unit(d1a), unit(d1b), 1);
  const kappa = (d1, d2) => { const T = unit(d1); const n = d2[0] * T[0] + d2[1] * T[1]; const s = Math.hypot(...d1) ** 2; return [(d2[0] - n * T[0]) / s, (d2[1] - n * T[1]) / s]; };
  const ka = kappa(d1a, d2a);
  const kb = kappa(d1b, d2b);
  const g2 = g1 && same(ka, kb, Math.hypot(...ka) + Math.hypot(...kb) + 1e-300);
  return { parametric: c2 ? 2 : c1 ? 1 : c0 ? 0 : -1, geometric: g2 ? 2 : g1 ? 1 : c0 ? 0 : -1 };
}

test('bezier-joints.mjs: every joint\'s C^k / G^k verdict is the one the definitions give, and the three joints show C2, G1 without C1, and a corner', () => {
  const out = run('bezier-joints.mjs');
  const segments = [...out.matchAll(/^segment (\d+): (\[.*\])$/gm)].map((m) => JSON.parse(m[2]));
  assert.ok(segments.length >= 2, out);
  const verdicts = [...out.matchAll(/^joint (\d+): C\^(-?\d+)\S* G\^(-?\d+)/gm)].map((m) => ({ parametric: Number(m[2]), geometric: Number(m[3]) }));
  // "C^-1" would be a gap; the script prints "not even C^0" then; none here.
  assert.equal(verdicts.length, segments.length - 1, out);
  verdicts.forEach((v, j) => assert.deepEqual(v, expectedJoint(segments[j], segments[j + 1]), `joint ${j + 1}:\n${out}`));
  assert.deepEqual(verdicts.map((v) => [v.parametric, v.geometric]), [[2, 2], [0, 1], [0, 0]], 'the cases the script is written to show');
});
