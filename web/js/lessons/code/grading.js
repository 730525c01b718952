// @ts-check
// Grading one run: the sandbox's result for each case against the core's answer for it.
// Pure (no page, no core calls): the page and the tests grade the same way. A case passes
// when the function returned exactly the core's answer (the same elements in the same order;
// the same number); the first case that does not is the one the lesson shows, with where the
// two answers part.
import { elementLabel } from '../../core/element-labels.js';
import { traceEntries } from '../../code/runner.js';

const KIND_OF_ANSWER = { edges: 'edge', faces: 'face', 'half-edges': 'halfedge' };

// A value as the lesson writes it: a list of elements by their labels (e6 e5), a number.
export function describeAnswer(task, value) {
  if (value === undefined) return 'nothing (undefined)';
  if (task.answer === 'number') return typeof value === 'number' ? String(value) : JSON.stringify(value);
  if (task.answer === 'position') {
    return isPoint(value) ? `(${value.map((x) => String(Number(x.toPrecision(12)))).join(', ')})` : `${JSON.stringify(value)?.slice(0, 80) ?? String(value)} (not a point [x, y, z])`;
  }
  if (!Array.isArray(value)) return `${JSON.stringify(value)?.slice(0, 80) ?? String(value)} (not a list)`;
  const kind = KIND_OF_ANSWER[task.answer];
  const shown = value.slice(0, 60).map((x) => (Number.isInteger(x) && x >= 0 ? elementLabel(kind, x) : JSON.stringify(x)));
  return `[${shown.join(' ')}${value.length > 60 ? ` … (${value.length} in all)` : ''}]`;
}

const isPoint = (v) => Array.isArray(v) && v.length === 3 && v.every((x) => typeof x === 'number' && Number.isFinite(x));

// The size of a case's mesh: its largest coordinate, in absolute value.
export function meshScale(snapshot) {
  let scale = 0;
  for (const x of snapshot.winged.positions) scale = Math.max(scale, Math.abs(x));
  return scale;
}

// A point returned is the core's when each coordinate is within 1e-9 of the mesh's size
// (`scale`, meshScale): the student's sums and the core's differ by rounding only, and the
// test means the same on a mesh a million times smaller or larger (a point near the origin is
// measured against the mesh, not against itself).
export function samePoint(expected, value, scale) {
  if (!isPoint(value)) return false;
  const tolerance = 1e-9 * Math.max(scale, ...expected.map(Math.abs));
  return value.every((x, i) => Math.abs(x - expected[i]) <= tolerance);
}

// Where a returned list first differs from the expected one (0-based), or -1 when equal.
export function partsAt(expected, value) {
  if (!Array.isArray(expected)) return Object.is(expected, value) ? -1 : 0;
  if (!Array.isArray(value)) return 0;
  const n = Math.max(expected.length, value.length);
  for (let i = 0; i < n; i += 1) if (expected[i] !== value[i]) return i;
  return -1;
}

// The reads a trace counts: every read of a stored entry. A half-edge's twin is h ^ 1,
// arithmetic, not an entry the structure stores, as the core counts the lecture's rule.
export const countsAsRead = (step) => step.op === 'read' && step.field !== 'twin';

// The tables a writing function leaves: the case's winged edge with the transaction's writes
// applied in order, the rows it added at the end (all -1 until written). Plain arrays, as the
// core's table check takes them.
export function tablesAfter(snapshot, transaction) {
  const w = snapshot.winged;
  const fields = w.edgeFields;
  const added = transaction?.added ?? {};
  const edges = [...Array.from(w.edges), ...new Array(8 * (added.edge ?? 0)).fill(-1)];
  const vertexEdges = [...Array.from(w.vertexEdge), ...new Array(added.vertex?.length ?? 0).fill(-1)];
  const faceEdges = [...Array.from(w.faceEdge), ...new Array(added.face ?? 0).fill(-1)];
  for (const { table, row, field, value } of transaction?.writes ?? []) {
    if (table === 'edge') edges[8 * row + fields.indexOf(field)] = /** @type {number} */ (value);
    else if (table === 'vertex' && field === 'edge') vertexEdges[row] = /** @type {number} */ (value);
    else if (table === 'face' && field === 'edge') faceEdges[row] = /** @type {number} */ (value);
  }
  return { edges, vertexEdges, faceEdges };
}

// Where the vertices a writing function added end up, in row order: the position each was
// added with, or the last one written to it.
export function addedPositions(snapshot, transaction) {
  const first = snapshot.winged.vertexEdge.length;
  const out = (transaction?.added?.vertex ?? []).map((p) => Array.from(p));
  for (const { table, row, field, value } of transaction?.writes ?? []) {
    if (table === 'vertex' && field === 'position' && row >= first) out[row - first] = Array.from(/** @type {number[]} */ (value));
  }
  return out;
}

/**
 * @param {import('./tasks.js').Task} task
 * @param {Array<{ label: string, args: number[] | null, expected?: any, referenceReads?: number | null, skipped?: string, snapshot?: any }>} cases
 *   a case with args null was not asked (skipped says why: no element of it suits the task)
 * @param {Array<any>} results the sandbox's, one per asked case in order (value or error, trace)
 * @param {{ checkEdit?: (c: any, result: any) => { correct: boolean, findings: any[] } }} [options]
 *   an edit task's check of what the function left (the core's, through the caller)
 */
export function gradeRun(task, cases, results, { checkEdit } = {}) {
  let next = 0;
  const graded = cases.map((c, i) => {
    if (!c.args) return { index: i, label: c.label, args: null, asked: false, ok: false, skipped: c.skipped, trace: [], reads: 0, referenceReads: 0 };
    const r = results[next++];
    // The sandbox's compact trace as plain steps {op, table, row, field, value}.
    const trace = r?.trace ? traceEntries(r.trace) : [];
    const reads = trace.filter(countsAsRead).length;
    if (!r || !r.ok) {
      // No result: the run stopped at an earlier mesh's endless loop (each would take the whole budget).
      const error = r?.error ?? { kind: 'skipped', message: 'not run: the run stopped at the endless loop of an earlier mesh', line: null, column: null };
      return { index: i, label: c.label, args: c.args, asked: true, ok: false, error, expected: c.expected, reads, writes: r?.writes ?? 0, referenceReads: c.referenceReads, trace, partsAt: 0, logs: r?.logs ?? [] };
    }
    const base = { index: i, label: c.label, args: c.args, asked: true, value: r.value, expected: c.expected, reads, writes: r.writes ?? 0, referenceReads: c.referenceReads, trace, traceCut: Boolean(r.trace?.cut), logs: r.logs ?? [] };
    if (task.answer === 'edit') {
      const check = checkEdit?.(c, r) ?? { correct: false, findings: [{ message: 'the edit could not be checked' }] };
      return { ...base, ok: check.correct, check, partsAt: check.correct ? -1 : 0 };
    }
    if (task.answer === 'position') {
      const ok = samePoint(c.expected, r.value, meshScale(c.snapshot));
      return { ...base, ok, partsAt: ok ? -1 : 0 };
    }
    const at = partsAt(c.expected, r.value);
    return { ...base, ok: at === -1, partsAt: at };
  });
  const asked = graded.filter((g) => g.asked);
  const firstFail = graded.findIndex((g) => g.asked && !g.ok);
  return { task: task.id, cases: graded, asked: asked.length, passed: asked.filter((g) => g.ok).length, firstFail: firstFail === -1 ? null : firstFail };
}

// One sentence on a failed case, in the lesson's words.
// The mesh and the element a case asks about: "the slide's mesh (lecture 000), v2".
export function caseWhere(task, g) {
  const asked = task.params.map((kind, k) => elementLabel(kind, g.args[k])).join(', ');
  return `${g.label}${asked ? `, ${asked}` : ''}`;
}

export function failureText(task, g) {
  const where = caseWhere(task, g);
  if (g.error) {
    // The sandbox's messages begin with "Line 3, column 9: " when they have a place.
    const at = g.error.line && !/^Line \d/.test(g.error.message) ? ` (line ${g.error.line}${g.error.column ? `, column ${g.error.column}` : ''})` : '';
    const said = g.error.message || 'your code threw a value that is not an Error (throw new Error("...") says what went wrong)';
    return `On ${where}: ${said}${at}`.replace(/([^.?!])$/, '$1.');
  }
  if (g.check) {
    const first = g.check.findings[0];
    const more = g.check.findings.length > 1 ? ` (${g.check.findings.length} problems in all; the first is shown)` : '';
    // The core's message and hint name the row and column and say what to re-read; its
    // reason (the right value) is not shown: the student finds it.
    return `On ${where}: the tables your function left are not the winged edge of the mesh after the ${task.editName ?? 'edit'}, so nothing was applied. ${first?.message ?? ''}${first?.hint ? ` ${first.hint}` : ''}${more}`;
  }
  const part = task.answer !== 'position' && Array.isArray(g.expected) && g.partsAt >= 0
    ? ` The answers part at entry ${g.partsAt + 1}: expected ${g.partsAt < g.expected.length ? describeAnswer(task, [g.expected[g.partsAt]]).slice(1, -1) : 'the end of the list'}, yours ${Array.isArray(g.value) && g.partsAt < g.value.length ? describeAnswer(task, [g.value[g.partsAt]]).slice(1, -1) : 'ends there'}.`
    : '';
  return `On ${where}: expected ${describeAnswer(task, g.expected)}, your function returned ${describeAnswer(task, g.value)}.${part}`;
}
