// The gallery's subdivide exercises asked of the subdivision lesson's subject, in Node over
// the real core, graded as the grader does (gradeSubdivide, no page). The right answers are
// worked here from the masks' formulas (Loop: 3/8 of each end of an interior edge and 1/8 of
// each corner opposite it; a boundary vertex 1/8, 6/8, 1/8 along the boundary; Catmull-Clark's
// vertex point ((n-2)/n) v + (1/n^2)(neighbours + face points), face points expanded into their
// corners) and the counts' rules (V' = V + E + F, E' = 2E + sum of corners, F' = sum of
// corners), from the lesson's own faces, never from the app's answers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { lessons } from '../../web/js/lessons/registry.js';
import { parseExercise, readExercise } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { gradeSubdivide, workedSubdivide, readFraction } from '../../web/js/exercise/kinds/subdivide.js';
import { subdivisionLesson } from '../../web/js/lessons/subdivision/lesson.js';

const api = await loadWingspline();
const lessonIds = lessons.map((l) => l.id);
const GALLERY = new URL('../../web/exercises/', import.meta.url);

function opened(id) {
  const exercise = parseExercise(fs.readFileSync(new URL(`${id}.json`, GALLERY), 'utf8'), { lessonIds });
  const state = readExerciseState(subdivisionLesson, exercise);
  const model = subdivisionLesson.compute({}, state, { api });
  return { exercise, check: exercise.check, subject: subdivisionLesson.exercise.subject({}, model, state, { api }) };
}

// Faces of the subject's mesh as lists of 0-based corners.
function facesOf(mesh) {
  const out = [];
  for (let f = 0; f + 1 < mesh.faceOffsets.length; f += 1) out.push(Array.from(mesh.faceVertices.subarray(mesh.faceOffsets[f], mesh.faceOffsets[f + 1])));
  return out;
}
const edgeKey = (a, b) => (a < b ? `${a}-${b}` : `${b}-${a}`);
function edgeFaces(faces) {
  const m = new Map();
  faces.forEach((f, i) => f.forEach((a, k) => { const key = edgeKey(a, f[(k + 1) % f.length]); m.set(key, [...(m.get(key) ?? []), i]); }));
  return m;
}

// Exact fractions as [num, den] with a gcd, only for the test's own arithmetic.
const gcd = (a, b) => (b === 0 ? Math.abs(a) : gcd(b, a % b));
const frac = (n, d) => { const g = gcd(n, d); return [n / g, d / g]; };
const add = ([a, b], [c, d]) => frac(a * d + c * b, b * d);
const text = ([n, d]) => (d === 1 ? `${n}` : `${n}/${d}`);
const rowsOf = (weights) => [...weights].map(([v, w]) => ({ point: `v${v + 1}`, weight: text(w) }));
function addTo(map, v, w) { map.set(v, map.has(v) ? add(map.get(v), w) : w); }

const ofLabel = (label) => Number(label.slice(1)) - 1;

test('the gallery holds the four subdivide exercises, each at feedback level check', () => {
  const ids = fs.readdirSync(GALLERY).filter((f) => f.endsWith('.json')).map((f) => f.slice(0, -5));
  const subdivide = ids.filter((id) => JSON.parse(fs.readFileSync(new URL(`${id}.json`, GALLERY), 'utf8')).check.kind === 'subdivide');
  assert.ok(subdivide.length >= 2, `${subdivide.length} subdivide exercises`);
  for (const id of subdivide) {
    const raw = JSON.parse(fs.readFileSync(new URL(`${id}.json`, GALLERY), 'utf8'));
    assert.deepEqual(raw.feedback, { level: 'check' }, id);
    assert.ok(Number.isInteger(raw.order) && raw.source, id);
    assert.ok(raw.hide.includes('step-panel'), `${id} hides the step panel (its masks and counts)`);
  }
});

test('Loop, the edge point of e2 (v2-v3) on the lecture\'s mesh: 3/8, 3/8 of its ends, 1/8 of each opposite corner', () => {
  const { check, subject } = opened('subdivision-loop-edge-point-e2');
  const faces = facesOf(subject.subdivision.mesh);
  // Lecture 000's faces: F1 = (v1 v2 v3), F2 = (v2 v4 v3), F3 = (v2 v5 v4).
  assert.deepEqual(faces, [[0, 1, 2], [1, 3, 2], [1, 4, 3]]);
  const [a, b] = [ofLabel('v2'), ofLabel('v3')];
  const around = edgeFaces(faces).get(edgeKey(a, b));
  assert.equal(around.length, 2, 'v2-v3 is an interior edge');
  const weights = new Map([[a, frac(3, 8)], [b, frac(3, 8)]]);
  for (const f of around) addTo(weights, faces[f].find((v) => v !== a && v !== b), frac(1, 8));
  const answer = { mask: 'edge-interior', rows: rowsOf(weights) };
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer }), { correct: true, findings: [], note: 'Interior edge mask, 4 old points.' });
  // The same weights as decimals read exactly, in another order.
  const decimal = { mask: 'edge-interior', rows: [{ point: 'v1', weight: '0.125' }, { point: 'v4', weight: '.125' }, { point: '3', weight: '0.375' }, { point: 'V2', weight: '0.375' }] };
  assert.equal(gradeSubdivide({ api, check, subject, answer: decimal }).correct, true);
  // Wrong: the boundary mask (the midpoint), then a weight of a corner.
  const midpoint = gradeSubdivide({ api, check, subject, answer: { mask: 'edge-boundary', rows: [{ point: 'v2', weight: '1/2' }, { point: 'v3', weight: '1/2' }] } });
  assert.equal(midpoint.correct, false);
  const texts = midpoint.findings.map((f) => f.text);
  assert.equal(texts.length, 5);
  assert.equal(texts[0], 'The mask chosen is not the one that makes the edge point of e2: re-read when a point is made by a boundary mask rather than an interior one.');
  assert.match(texts[1], /^The weight of v2 \(row 1\) in the edge point of e2 is not right\. Re-read the mask that makes this point\.$/);
  assert.match(texts[2], /^The weight of v3 \(row 2\)/);
  assert.match(texts[3], /^v1 is missing: the edge point of e2 also averages v1\./);
  assert.match(texts[4], /^v4 is missing/);
  for (const f of midpoint.findings) for (const value of ['3/8', '1/8', '0.375', '0.125']) assert.ok(!f.text.includes(value) && !(f.hint ?? '').includes(value), f.text);
});

test('Loop, the vertex point of v2 on the lecture\'s mesh: v2 is on the boundary, 1/8, 6/8, 1/8 along it', () => {
  const { check, subject } = opened('subdivision-loop-vertex-point-v2');
  const faces = facesOf(subject.subdivision.mesh);
  const v = ofLabel('v2');
  // The boundary edges at v2 are the edges on one face only.
  const along = [...edgeFaces(faces)].filter(([key, fs]) => fs.length === 1 && key.split('-').map(Number).includes(v)).map(([key]) => key.split('-').map(Number).find((u) => u !== v));
  assert.deepEqual(along.sort(), [ofLabel('v1'), ofLabel('v5')]);
  const weights = new Map([[v, frac(6, 8)]]);
  for (const u of along) addTo(weights, u, frac(1, 8));
  assert.equal(gradeSubdivide({ api, check, subject, answer: { mask: 'vertex-boundary', rows: rowsOf(weights) } }).correct, true);
  // The interior Loop rule with beta(5) is not it: a wrong mask and three stray points.
  const r = gradeSubdivide({ api, check, subject, answer: { mask: 'vertex-interior', rows: [{ point: 'v2', weight: '3/4' }, { point: 'v3', weight: '1/8' }, { point: 'v4', weight: '1/8' }] } });
  assert.deepEqual(r.findings.map((f) => f.text.slice(0, 12)), ['The mask cho', 'v3 (row 2) i', 'v4 (row 3) i', 'v1 is missin', 'v5 is missin']);
});

test('Catmull-Clark, the vertex point of the cube\'s corner v1: the formula with n = 3, face points expanded', () => {
  const { check, subject } = opened('subdivision-catmull-clark-cube-corner');
  const faces = facesOf(subject.subdivision.mesh);
  const v = ofLabel('v1');
  const around = faces.filter((f) => f.includes(v));
  const neighbours = new Set(around.flatMap((f) => { const k = f.indexOf(v); return [f[(k + 1) % f.length], f[(k + f.length - 1) % f.length]]; }));
  const n = neighbours.size;
  assert.equal(n, 3);
  const weights = new Map([[v, frac(n - 2, n)]]);
  for (const u of neighbours) addTo(weights, u, frac(1, n * n));
  for (const f of around) for (const c of f) addTo(weights, c, frac(1, n * n * f.length));
  assert.deepEqual(text(weights.get(v)), '5/12');
  const answer = { mask: 'vertex-interior', rows: rowsOf(weights) };
  assert.equal(gradeSubdivide({ api, check, subject, answer }).correct, true);
  const worked = workedSubdivide({ api, check, subject }).lines.join('\n');
  for (const [u, w] of weights) assert.ok(worked.includes(`v${u + 1}: ${text(w)}`), `the worked answer gives v${u + 1}: ${text(w)}`);
  // Face points left unexpanded (1/9 for each face point's corner... a usual slip): named.
  const slip = { mask: 'vertex-interior', rows: [...weights].map(([u, w]) => ({ point: `v${u + 1}`, weight: u === v ? '1/3' : text(w) })) };
  const r = gradeSubdivide({ api, check, subject, answer: slip });
  assert.equal(r.findings.length, 1);
  assert.match(r.findings[0].text, /^The weight of v1 \(row 1\) in the vertex point of v1 is not right: v1 is the old vertex itself/);
  assert.ok(!r.findings[0].text.includes('5/12'));
});

test('Catmull-Clark counts on the cube: V + E + F, 2E + corners, corners', () => {
  const { check, subject } = opened('subdivision-catmull-clark-cube-counts');
  const faces = facesOf(subject.subdivision.mesh);
  const V = subject.subdivision.mesh.positions.length / 3;
  const E = edgeFaces(faces).size;
  const F = faces.length;
  const corners = faces.reduce((s, f) => s + f.length, 0);
  const right = { vertices: String(V + E + F), edges: String(2 * E + corners), faces: String(corners) };
  assert.deepEqual(right, { vertices: '26', edges: '48', faces: '24' });
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer: right }), { correct: true, findings: [] });
  const wrong = gradeSubdivide({ api, check, subject, answer: { ...right, edges: '36' } });
  assert.equal(wrong.findings.length, 1);
  assert.match(wrong.findings[0].text, /^The number of edges after one Catmull-Clark step is not right/);
  assert.ok(!wrong.findings[0].text.includes('48'));
  const blank = gradeSubdivide({ api, check, subject, answer: { ...right, faces: ' ' } });
  assert.equal(blank.incomplete, true);
  assert.deepEqual(blank.findings, [{ text: 'F: type the number of faces.' }]);
});

test('answers that cannot be read are said, never thrown: other shapes, unreadable rows, fractions read exactly', () => {
  const { check, subject } = opened('subdivision-loop-edge-point-e2');
  for (const bad of [null, 3, 'v1', [], { mask: 'nonsense', rows: [] }, { mask: null, rows: 'v1' }, { mask: null, rows: [{ point: 1, weight: '1' }] }, { mask: null, rows: Array(65).fill({ point: '', weight: '' }) }]) {
    const r = gradeSubdivide({ api, check, subject, answer: bad });
    assert.equal(r.correct, false);
    assert.equal(r.incomplete, true);
    assert.match(r.findings[0].text, /^This answer could not be read: /);
  }
  const rows = (list) => ({ mask: 'edge-interior', rows: list.map(([point, weight]) => ({ point, weight })) });
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer: rows([['v2', '3/8'], ['', ''], ['v3', '3/8'], ['', '']]) }).findings, [{ text: 'Row 2 is empty: fill it in or remove it.' }]);
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer: rows([['w2', '3/8']]) }).findings, [{ text: 'Row 1: "w2" is not an old point\'s label (write it as the drawing does, e.g. v3).' }]);
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer: rows([['v2', '3/0']]) }).findings, [{ text: 'Row 1: "3/0" divides by 0.' }]);
  assert.deepEqual(gradeSubdivide({ api, check, subject, answer: rows([['v9', '1']]) }).findings.map((f) => f.text)[0], 'Row 1 names v9, but the old mesh has vertices v1 to v5.');
  assert.deepEqual(readFraction('0.375'), { num: 375, den: 1000 });
  assert.deepEqual(readFraction('-1/8'), { num: -1, den: 8 });
  assert.ok('problem' in readFraction('1e-3'));
  assert.ok('problem' in readFraction('0.33333333333333333'));
});

test('the check is read with a sentence naming the field: a mask question needs its point, Loop has no face points', () => {
  const raw = JSON.parse(fs.readFileSync(new URL('subdivision-loop-edge-point-e2.json', GALLERY), 'utf8'));
  const refused = (change) => {
    const x = structuredClone(raw);
    change(x.check);
    try { readExercise(x, { lessonIds }); } catch (err) { return err.message; }
    return 'read';
  };
  assert.equal(refused(() => {}), 'read');
  assert.match(refused((c) => { delete c.point; }), /exercise\.check\.point is missing \(a mask question names the new point/);
  assert.match(refused((c) => { c.point.type = 'face'; }), /exercise\.check\.point\.type is "face", but Loop's scheme makes no face points/);
  assert.match(refused((c) => { c.point.element = 0; }), /exercise\.check\.point\.element/);
  assert.match(refused((c) => { c.steps = 2; }), /exercise\.check\.steps is only for ask "counts"/);
  assert.match(refused((c) => { c.ask = 'counts'; }), /exercise\.check\.point is only for ask "mask"/);
  assert.match(refused((c) => { c.ask = 'counts'; delete c.point; c.steps = 9; }), /exercise\.check\.steps/);
  assert.match(refused((c) => { c.scheme = 'butterfly'; }), /exercise\.check\.scheme/);
  assert.equal(refused((c) => { c.ask = 'counts'; delete c.point; c.steps = 2; }), 'read');
});

test('3,000 random answers, typed or damaged, are graded without an exception, each finding a sentence', () => {
  // A seeded generator (mulberry32), so a failure can be replayed.
  let seed = 20261127;
  const random = () => { seed = (seed + 0x6D2B79F5) | 0; let t = seed; t = Math.imul(t ^ (t >>> 15), t | 1); t ^= t + Math.imul(t ^ (t >>> 7), t | 61); return ((t ^ (t >>> 14)) >>> 0) / 4294967296; };
  const pick = (list) => list[Math.floor(random() * list.length)];
  const pieces = ['v', 'V', '1', '2', '3', '5', '9', '0', '/', '.', '-', ' ', 'x', '8', '16', '99999999999'];
  const typed = () => Array.from({ length: Math.floor(random() * 6) }, () => pick(pieces)).join('');
  const exercises = ['subdivision-loop-edge-point-e2', 'subdivision-loop-vertex-point-v2', 'subdivision-catmull-clark-cube-corner', 'subdivision-catmull-clark-cube-counts'].map(opened);
  let correct = 0;
  for (let i = 0; i < 3000; i += 1) {
    const { check, subject } = pick(exercises);
    const answer = check.ask === 'counts'
      ? { vertices: typed(), edges: typed(), faces: random() < 0.1 ? 7 : typed() }
      : { mask: pick([null, 'edge-interior', 'edge-boundary', 'vertex-interior', 'vertex-boundary', 'face-point', 'other']), rows: Array.from({ length: Math.floor(random() * 6) }, () => (random() < 0.05 ? null : { point: typed(), weight: typed() })) };
    const r = gradeSubdivide({ api, check, subject, answer });
    assert.equal(typeof r.correct, 'boolean');
    assert.ok(Array.isArray(r.findings));
    if (!r.correct) assert.ok(r.findings.length > 0 && r.findings.every((f) => typeof f.text === 'string' && f.text.length > 10), JSON.stringify(r));
    correct += r.correct;
  }
  assert.equal(correct, 0); // (random strings do not make a right answer)
});
