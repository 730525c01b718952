// The gallery's exercises asked of their lessons' subjects, in Node over the real
// core: each lesson's `exercise.subject` hands the check what the drawing shows, and the
// answers a student would work out from the lectures are the right ones. Expected values are
// computed here from the lectures' formulas (Bernstein polynomials, the Hermite matrix,
// de Casteljau), and the slide's printed tables, never read from the app.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { loadWingspline } from 'wingspline';
import { lessons } from '../../web/js/lessons/registry.js';
import { parseExercise } from '../../web/js/exercise/format.js';
import { readExerciseState } from '../../web/js/exercise/player.js';
import { askOf } from '../../web/js/exercise/kinds/value.js';
import { propertySubject } from '../../web/js/exercise/kinds/property.js';
import { meshLesson } from '../../web/js/lessons/mesh/lesson.js';
import { lesson as curvesLesson } from '../../web/js/lessons/curves/lesson.js';
import { lesson as continuityLesson } from '../../web/js/lessons/continuity/lesson.js';
import { lesson as comparisonLesson } from '../../web/js/lessons/comparison/lesson.js';
import { lesson as surfacesLesson } from '../../web/js/lessons/surfaces/lesson.js';
import { subdivisionLesson } from '../../web/js/lessons/subdivision/lesson.js';
import { slideRows, SLIDE_VERTEX_EDGES, SLIDE_FACE_EDGES, slideWalk, FOLEY_EDGE_LIST, FOLEY_POLYGONS } from '../helpers/lecture-slide.mjs';

const api = await loadWingspline();
const LESSONS = Object.fromEntries([meshLesson, curvesLesson, continuityLesson, comparisonLesson, surfacesLesson, subdivisionLesson].map((l) => [l.id, l]));
const lessonIds = lessons.map((l) => l.id);

// An exercise of the gallery, its lesson state and the subject its check is asked of.
function opened(id) {
  const exercise = parseExercise(fs.readFileSync(new URL(`../../web/exercises/${id}.json`, import.meta.url), 'utf8'), { lessonIds });
  const lesson = LESSONS[exercise.lesson];
  const state = readExerciseState(lesson, exercise);
  // The model where the subject needs one (the continuity lab's segments, the subdivision's mesh).
  const model = exercise.lesson === 'continuity' || exercise.lesson === 'subdivision' ? lesson.compute({}, state, { api }) : null;
  return { exercise, subject: lesson.exercise.subject({}, model, state, { api }) };
}

const num = (label) => Number(label.slice(1)) - 1;
const cell = (x) => (x === '-' ? -1 : num(x));

test('the slide\'s winged-edge tables, as printed, answer the winged-edge exercise; one wrong wing is named', () => {
  const { exercise, subject } = opened('mesh-winged-edge-slide');
  const rows = slideRows();
  const answer = {
    edges: rows.flatMap((r) => [r.S, r.E, r.L, r.R, r.SL, r.SR, r.EL, r.ER].map(cell)),
    vertexEdges: SLIDE_VERTEX_EDGES.map(num),
    faceEdges: SLIDE_FACE_EDGES.map(num),
  };
  assert.deepEqual(api.checkMeshTableAnswer(subject.mesh, exercise.check.table, answer).findings, []);
  answer.edges[8 * 4 + 4] = num('e2'); // e5's S:L is e3 on the slide
  const r = api.checkMeshTableAnswer(subject.mesh, exercise.check.table, answer);
  assert.equal(r.findings.length, 1);
  assert.match(r.findings[0].reason, /row e5: .*\(S:L\) is e3, not e2/);
});

test('the walk exercises follow the slide\'s walks (the core numbering the edges as the slide does)', () => {
  for (const [id, around, element] of [['mesh-walk-around-v2', 'vertex', 'v2'], ['mesh-walk-along-f1', 'face', 'F1']]) {
    const { exercise, subject } = opened(id);
    const walk = slideWalk(around, element).map(num);
    for (let k = 1; k <= walk.length; k += 1) {
      const expected = walk[k % walk.length];
      const r = api.checkWalkStep(subject.mesh, { around, element: exercise.check.element - 1, step: k, given: expected });
      assert.equal(r.correct, true, `${id} step ${k}`);
      assert.equal(r.done, k === walk.length);
    }
  }
});

test('Foley\'s two polygons: the edge list and polygon table as lecture 001 prints them answer the edge-list exercise', () => {
  const { exercise, subject } = opened('mesh-edge-list-foley');
  // Lecture 001: P1 = (1, 2, 4), P2 = (4, 2, 3): the faces the exercise's mesh holds.
  assert.deepEqual(subject.mesh.faces.map((f) => f.map((v) => v + 1)), [[1, 2, 4], [4, 2, 3]]);
  const ref = (x) => (x === 'λ' ? -1 : Number(x.slice(1)) - 1);
  const edges = FOLEY_EDGE_LIST.flatMap((row) => row.map(ref));
  const polygons = FOLEY_POLYGONS.map((p) => p.map(ref));
  assert.deepEqual(api.checkMeshTableAnswer(subject.mesh, exercise.check.table, { edges, polygons }).findings, []);
  polygons[1][2] = 0; // P2 = (E2, E3, E1): E1 is not a side of P2
  assert.equal(api.checkMeshTableAnswer(subject.mesh, exercise.check.table, { edges, polygons }).findings.length, 1);
});

test('curve values: B₁,₃(1/2) = 3/8 and P(1/2) = (P0 + 3P1 + 3P2 + P3)/8 of the lecture\'s polygon', () => {
  const blend = opened('curves-bernstein-half');
  const { of, ask } = askOf(blend.exercise.check, blend.subject);
  assert.equal(api.checkValueAnswer(of, ask, [3 / 8], blend.exercise.check.tolerance).correct, true);
  assert.equal(api.checkValueAnswer(of, ask, [0.4], blend.exercise.check.tolerance).correct, false);
  const point = opened('curves-de-casteljau-point');
  const P = point.subject.curve.points;
  const mid = [0, 1].map((c) => (P[c] + 3 * P[2 + c] + 3 * P[4 + c] + P[6 + c]) / 8);
  assert.deepEqual(mid, [2, 1.5]);
  const q = askOf(point.exercise.check, point.subject);
  assert.equal(api.checkValueAnswer(q.of, q.ask, mid, point.exercise.check.tolerance).correct, true);
});

test('Boehm\'s rule: inserting u = 1/4 into knots (0,0,0,0,1/2,1,1,1,1) gives Q₂ = 3/4 P₁ + 1/4 P₂ (a₂ = 1/4 / (1 − 0))', () => {
  const { exercise, subject } = opened('curves-boehm-insert');
  assert.deepEqual(Array.from(subject.curve.knots), [0, 0, 0, 0, 0.5, 1, 1, 1, 1]);
  const P = subject.curve.points;
  const q2 = [0.75 * P[2] + 0.25 * P[4], 0.75 * P[3] + 0.25 * P[5]];
  const { of, ask } = askOf(exercise.check, subject);
  assert.equal(api.checkValueAnswer(of, ask, q2, 1e-12).correct, true);
  // Q₂ is not P₂ nor the average of P₁ and P₂.
  assert.equal(api.checkValueAnswer(of, ask, [P[4], P[5]], exercise.check.tolerance).correct, false);
  assert.equal(api.checkValueAnswer(of, ask, [(P[2] + P[4]) / 2, (P[3] + P[5]) / 2], exercise.check.tolerance).correct, false);
});

test('the comparison lab\'s values: the first Bezier segment at 1/2, and M_H G of the first Hermite segment', () => {
  const bez = opened('comparison-bezier-midpoint');
  const pts = bez.subject.curves.bezier.points;
  const mid = [0, 1].map((c) => (pts[c] + 3 * pts[2 + c] + 3 * pts[4 + c] + pts[6 + c]) / 8);
  const b = askOf(bez.exercise.check, bez.subject);
  assert.equal(api.checkValueAnswer(b.of, b.ask, mid, 0.01).correct, true);
  const her = opened('comparison-hermite-mg');
  const h = her.subject.curves.hermite;
  // Lecture 003: M_H = [[2 -2 1 1] [-3 3 -2 -1] [0 0 1 0] [1 0 0 0]], G = [P0 P1 T0 T1]: row 1, x.
  const x = 2 * h.points[0] - 2 * h.points[2] + h.tangents[0] + h.tangents[2];
  const m = askOf(her.exercise.check, her.subject);
  assert.equal(api.checkValueAnswer(m.of, m.ask, [x], 1e-9).correct, true);
});

test('the surface patch: p(1/2, 1/2) by the Bernstein weights 1/8, 3/8, 3/8, 1/8, and the corner p(1, 0)', () => {
  const centre = opened('surfaces-bezier-centre');
  const P = centre.subject.patch.points;
  const w = [1, 3, 3, 1].map((x) => x / 8);
  const expected = [0, 1, 2].map((c) => { let s = 0; for (let i = 0; i < 4; i += 1) for (let j = 0; j < 4; j += 1) s += w[i] * w[j] * P[3 * (4 * i + j) + c]; return s; });
  const a = askOf(centre.exercise.check, centre.subject);
  assert.equal(api.checkValueAnswer(a.of, a.ask, expected, 1e-9).correct, true);
  const corner = opened('surfaces-bezier-corner');
  const c = askOf(corner.exercise.check, corner.subject);
  // p(u, v) = Σ B_i(u) B_j(v) P_ij with the net row-major in i (u) then j (v), as the lesson's
  // formula panel writes it: at u = 1, v = 0 only B_3(1) B_0(0) = 1 remains, so p = P_30.
  assert.equal(api.checkValueAnswer(c.of, c.ask, P.slice(3 * 12, 3 * 12 + 3), 1e-12).correct, true);
  // and not the other corners (a u/v swap would give P_03).
  for (const k of [0, 3, 15]) assert.equal(api.checkValueAnswer(c.of, c.ask, P.slice(3 * k, 3 * k + 3), 0.01).correct, false, `corner ${k}`);
});

test('the continuity exercises: the G1 preset is G1 but not C1, the corner C0; the C2 joint is not yet "C1 but not C2"', () => {
  const g1 = opened('continuity-classify-g1');
  const { a, b } = g1.subject.joints[0];
  assert.equal(api.checkJointAnswer(a, b, { parametric: 0, geometric: 1, why: ['meet', 'same-direction'] }).correct, true);
  assert.equal(api.checkJointAnswer(a, b, { parametric: 1, geometric: 1, why: ['meet', 'same-direction'] }).correct, false);
  const corner = opened('continuity-classify-corner');
  assert.equal(api.checkJointAnswer(corner.subject.joints[0].a, corner.subject.joints[0].b, { parametric: 0, geometric: 0, why: ['meet'] }).correct, true);
  const c2 = opened('continuity-make-c1-not-c2');
  const { joint, ...property } = c2.exercise.check.property;
  assert.equal(api.checkCurveProperty(propertySubject(c2.exercise.check.property, c2.subject), property).holds, false);
  const through = opened('curves-through-a-point');
  assert.equal(api.checkCurveProperty(propertySubject(through.exercise.check.property, through.subject), through.exercise.check.property).holds, false);
});

test('the subdivision exercises: one Catmull-Clark step on two triangles gives 6 quads on 11 vertices; the tetrahedron\'s adjacency', () => {
  const cc = opened('subdivision-catmull-clark-triangles');
  const offsets = cc.subject.mesh.faceOffsets;
  // Each triangle becomes 3 quads; vertices: 4 corners + 5 edge points + 2 face points.
  assert.equal(offsets.length - 1, 6);
  assert.equal(cc.subject.mesh.positions.length / 3, 11);
  for (let f = 0; f < 6; f += 1) assert.equal(offsets[f + 1] - offsets[f], 4);
  // The answer a student reads off the drawing: every vertex's neighbours, from the quads' sides.
  const next = Array.from({ length: 11 }, () => new Set());
  for (let f = 0; f < 6; f += 1) {
    const q = Array.from(cc.subject.mesh.faceVertices.slice(offsets[f], offsets[f + 1]));
    q.forEach((v, i) => { next[v].add(q[(i + 1) % 4]); next[q[(i + 1) % 4]].add(v); });
  }
  // Corners of the two triangles have 2 or 3 neighbours, face points 3, edge points 3 or 4.
  assert.deepEqual(next.map((s) => s.size).sort(), [2, 2, 3, 3, 3, 3, 3, 3, 3, 3, 4].sort());
  assert.equal(api.checkMeshTableAnswer(cc.subject.mesh, 'adjacency', { vertexVertices: next.map((s) => [...s].reverse()) }).correct, true);
  const tet = opened('subdivision-loop-tetrahedron-adjacency');
  // Every vertex of a tetrahedron is next to the three others.
  const all = [0, 1, 2, 3].map((v) => [0, 1, 2, 3].filter((w) => w !== v));
  assert.equal(api.checkMeshTableAnswer(tet.subject.mesh, 'adjacency', { vertexVertices: all }).correct, true);
});
