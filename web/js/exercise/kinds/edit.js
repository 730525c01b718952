// @ts-check
// Kind edit: the mesh before an operation (flip e3, split e5, collapse e6, ...) and the
// student writes the rows of the winged-edge tables the operation rewrites, as they read
// after it (lecture 000's tables). The rows to write are the core's (api.editQuestion: the
// existing rows the operation rewrites or removes, and as many new rows as it adds
// elements); the student labels the new elements as they choose, and marks a removed
// element's row. The core checks the answer against the operation's change record
// (api.checkEditAnswer): any numbering of the new elements, each wrong cell named by its row
// and column with the rule to re-read, never its value (the value is in the worked answer).
//
// The answer, as kept in progress and submission files: per table (vertices, edges, faces)
// { cells: string[][] (one list per row, as typed: 8 per edge row, S E L R S:L S:R E:L E:R;
// 1 per vertex or face row), removed: boolean[], labels: string[] (the new rows') }.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { refuseLargeMesh, replayEdits } from '../subjects.js';
import { readLabel, label, BLANK } from './table.js';
import { gradeHalfEdgeEdit, workedHalfEdgeEdit, createHalfEdgeEditKind } from './edit-half-edge.js';
import { readCards, restoreCards, markCards, clearCards, columnArrows } from './edit-cards.js';

const TABLES = /** @type {const} */ (['vertices', 'edges', 'faces']);
const REF = /** @type {Record<string, 'vertex' | 'edge' | 'face'>} */ ({ vertices: 'vertex', edges: 'edge', faces: 'face' });
const EDGE_COLUMNS = ['S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'];
const EDGE_FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
const EDGE_REFS = /** @type {const} */ (['vertex', 'vertex', 'face', 'face', 'edge', 'edge', 'edge', 'edge']);
const width = (table) => (table === 'edges' ? 8 : 1);
const refOf = (table, k) => (table === 'edges' ? EDGE_REFS[k] : 'edge');
const columnOf = (table, k) => (table === 'edges' ? EDGE_COLUMNS[k] : 'edge');
// A typed label may name a new element: any number the student chose (the core says whether
// it names a row), so the reader takes numbers up to this.
const ANY_LABEL = 9999999;

// Value-free nudges, shown at the feedback level the author allows (docs/exercises.md).
const HINTS = {
  'wrong-wing': 'Sketch the mesh after the operation. Stand at the row\'s S (for S:L, S:R) or E (for E:L, E:R) and turn from this edge: counter-clockwise gives S:L and E:R, clockwise gives S:R and E:L.',
  'wrong-face': 'Walk along the edge from S to E in the mesh after the operation: the face on your left is L, the one on your right is R.',
  'wrong-vertex': 'Find where the operation puts this edge\'s two ends; S is the end your row starts from, and L and the wings follow that direction.',
  'removed-element': 'An element the operation removes is no longer anyone\'s neighbour: find what took its place.',
  'not-incident': 'List the edges that touch this vertex once the operation is done; any one of them may be stored.',
  'not-on-face': 'List the sides of this face once the operation is done; any one of them may be stored.',
  removed: 'Compare V, E and F before and after: the operation\'s counts say how many elements go, and which ones.',
  kept: 'Compare V, E and F before and after: the operation\'s counts say how many elements go, and which ones.',
  'new-removed': 'A new row is an element the operation adds: it stays.',
  blank: 'Every cell of a listed row is written; write none where there is no face.',
  'unknown-label': 'Use the labels the mesh has and the labels you gave the new rows.',
  'blank-label': 'Any label no element of that table has yet will do, for instance the next free number.',
  'used-label': 'Any label no element of that table has yet will do, for instance the next free number.',
  'duplicate-label': 'Give each new element its own label.',
};

const sentence = (s) => `${s[0].toUpperCase()}${s.slice(1)}${/[.!?]$/.test(s) ? '' : '.'}`;

/** The question's operation with its elements counted from 0, as the API takes it. */
function operationOf(api, check) {
  const entry = api.meshOperations.operations.find((o) => o.name === check.op?.op);
  if (!entry) {
    const names = api.meshOperations.operations.map((o) => o.name).join(', ');
    throw new ExerciseError(`its field exercise.check.op.op is "${String(check.op?.op).slice(0, 40)}", not an operation (${names})`, 'exercise.check.op.op');
  }
  const op = { op: entry.name };
  for (const [key, value] of Object.entries(check.op)) {
    if (key === 'op') continue;
    const arg = entry.arguments.find((a) => a.name === key);
    if (!arg) throw new ExerciseError(`its field exercise.check.op.${key} is not an argument of ${entry.name} (it takes ${entry.arguments.map((a) => a.name).join(', ')})`, `exercise.check.op.${key}`);
    op[key] = arg.kind ? value - 1 : value;
  }
  return op;
}

/** The question the core reads off the operation's change record, or an ExerciseError naming the field. */
function questionOf(api, check, subject) {
  if (!subject.loaded) throw new ExerciseError('this lesson has no mesh to edit', 'exercise.check.kind');
  refuseLargeMesh(subject.loaded);
  const op = operationOf(api, check);
  try {
    return { op, ...api.editQuestion(subject.loaded, subject.edits ?? [], op) };
  } catch (err) {
    throw new ExerciseError(`its operation cannot be asked of its drawing: ${err.message}`, 'exercise.check.op');
  }
}

const rowCount = (q, table) => q.rows[table].length + q.added[table];

/** An empty answer to question q. */
function emptyAnswer(q) {
  return Object.fromEntries(TABLES.map((t) => [t, {
    cells: Array.from({ length: rowCount(q, t) }, () => Array(width(t)).fill('')),
    removed: Array(rowCount(q, t)).fill(false),
    labels: Array(q.added[t]).fill(''),
  }]));
}

/** Whether `answer` has the shape of an answer to q (it may come from an untrusted file). */
function fits(answer, q) {
  if (answer === null || typeof answer !== 'object') return false;
  return TABLES.every((t) => {
    const a = answer[t];
    const rows = rowCount(q, t);
    return a && typeof a === 'object' && Array.isArray(a.cells) && a.cells.length === rows
      && a.cells.every((row) => Array.isArray(row) && row.length === width(t) && row.every((c) => typeof c === 'string' && c.length <= 40))
      && Array.isArray(a.removed) && a.removed.length === rows && a.removed.every((x) => typeof x === 'boolean')
      && Array.isArray(a.labels) && a.labels.length === q.added[t] && a.labels.every((x) => typeof x === 'string' && x.length <= 40);
  });
}

/** How the question names an answer row. */
function rowName(q, table, row, typedLabel) {
  const listed = q.rows[table];
  const prefix = table === 'edges' ? 'row ' : `${REF[table]} table, row `;
  if (row < listed.length) return `${prefix}${label(REF[table], listed[row])}`;
  return `new ${REF[table]} row ${row - listed.length + 1}${typedLabel ? ` (${typedLabel})` : ''}`;
}

/** The typed answer as the API's numbers, or the cells that could not be read. */
function readAnswer(answer, q) {
  const problems = [];
  const out = {};
  for (const t of TABLES) {
    const a = answer[t];
    const labels = a.labels.map((raw, n) => {
      const r = readLabel(raw, REF[t], ANY_LABEL, false);
      if (r.problem) problems.push({ text: `New ${REF[t]} row ${n + 1}, its label: ${r.problem}.` });
      return r.value ?? BLANK;
    });
    const cells = [];
    a.cells.forEach((row, i) => row.forEach((raw, k) => {
      const r = a.removed[i] ? { value: BLANK } : readLabel(raw, refOf(t, k), ANY_LABEL, k !== 0 || t !== 'edges');
      if (r.problem) problems.push({ text: sentence(`${rowName(q, t, i, a.labels[i - q.rows[t].length])}, column ${columnOf(t, k)}: ${r.problem}`) });
      cells.push(r.value ?? BLANK);
    }));
    out[t] = { cells, removed: a.removed.slice(), labels };
  }
  return { problems, answer: out };
}

const UNREADABLE = { correct: false, incomplete: true, findings: [{ text: 'This answer could not be read: it is not an answer to this edit (its rows do not match the question).' }] };

// The blank cells of one edge row make one finding ("row e1: S, E and L are blank: ..."), so a
// row not yet written reads as one line, not eight.
function groupBlanks(findings) {
  const out = [];
  const rows = new Map();
  for (const f of findings) {
    if (f.code !== 'blank' || f.table !== 'edge') { out.push(f); continue; }
    const key = f.index;
    if (!rows.has(key)) { rows.set(key, { ...f, columns: [] }); out.push(rows.get(key)); }
    rows.get(key).columns.push(EDGE_COLUMNS[EDGE_FIELDS.indexOf(f.field)]);
  }
  return out.map((f) => {
    if (!f.columns || f.columns.length === 1) return f;
    const where = f.reason.slice(0, f.reason.indexOf(', column'));
    const list = `${f.columns.slice(0, -1).join(', ')} and ${f.columns[f.columns.length - 1]}`;
    return { ...f, reason: `${where}: ${f.columns.length === 8 ? 'every column' : `columns ${list}`} ${f.columns.length === 8 ? 'is' : 'are'} blank: every cell of a row the operation rewrites is written (none where there is no face)` };
  });
}

/**
 * Grades an answer (DOM-free; the grader runs it over loadWingspline()).
 * @param {{ api: any, check: any, subject: any, answer: any }} parts
 * @returns {{ correct: boolean, partial?: boolean, incomplete?: boolean, findings: Array<{ text: string, hint?: string }>, note?: string }}
 */
export function gradeEdit({ api, check, subject, answer }) {
  if (check.structure === 'half-edge') return gradeHalfEdgeEdit({ api, check, subject, answer, operationOf });
  const q = questionOf(api, check, subject);
  if (!fits(answer, q)) return UNREADABLE;
  const typed = TABLES.some((t) => answer[t].removed.some(Boolean) || answer[t].labels.some((x) => x.trim())
    || answer[t].cells.some((row) => row.some((c) => c.trim())));
  if (!typed) return { correct: false, incomplete: true, findings: [{ text: 'Nothing is written yet: write the rows after the operation, then Check.' }] };
  const read = readAnswer(answer, q);
  if (read.problems.length) return { correct: false, findings: read.problems };
  const r = api.checkEditAnswer(subject.loaded, subject.edits ?? [], q.op, read.answer);
  return {
    correct: r.correct,
    findings: groupBlanks(r.findings).map((f) => ({ text: sentence(f.reason), hint: HINTS[f.code] })),
    note: r.correct ? `Every row after ${q.operation} is right.` : undefined,
  };
}

/**
 * The worked answer: every row after the operation, new elements numbered from the next free labels.
 * @param {{ api: any, check: any, subject: any }} parts
 */
export function workedEdit({ api, check, subject }) {
  if (check.structure === 'half-edge') return workedHalfEdgeEdit({ api, check, subject, operationOf });
  const q = questionOf(api, check, subject);
  const numbers = Object.fromEntries(TABLES.map((t) => [t, {
    cells: Array(rowCount(q, t) * width(t)).fill(BLANK), removed: Array(rowCount(q, t)).fill(false), labels: Array(q.added[t]).fill(BLANK),
  }]));
  const w = api.checkEditAnswer(subject.loaded, subject.edits ?? [], q.op, numbers).worked;
  return { lines: workedLines(q, w) };
}

function workedLines(q, w) {
  const lines = [`After ${q.operation}:`];
  for (const t of TABLES) {
    for (let row = 0; row < rowCount(q, t); row += 1) {
      const n = row - q.rows[t].length;
      const name = n < 0 ? label(REF[t], q.rows[t][row]) : `${label(REF[t], w[t].labels[n])} (new)`;
      if (w[t].removed[row]) { lines.push(`${name}: removed`); continue; }
      const cells = w[t].cells.slice(row * width(t), (row + 1) * width(t));
      lines.push(t === 'edges'
        ? `${name}: ${cells.map((c, k) => `${EDGE_COLUMNS[k]} ${label(EDGE_REFS[k], c)}`).join(', ')}`
        : `${name} (${REF[t]} table): edge ${label('edge', cells[0])}`);
    }
  }
  return lines;
}

/** @param {any} parts */
export function createEditKind({ api, check, subject }) {
  // The same operation asked in half-edge terms (structure "half-edge"): edit-half-edge.js.
  if (check.structure === 'half-edge') return createHalfEdgeEditKind({ api, check, subject, operationOf });
  const asked = subject();
  const q = questionOf(api, check, asked);
  // The rows as they read before the operation, for reading beside the answer.
  const before = replayEdits(api, asked.loaded, asked.edits ?? [], (mesh) => mesh.wingedEdgeArrays());
  const stride = before.edgeFields.length;
  const beforeCells = (t, i) => (t === 'edges'
    ? EDGE_FIELDS.map((f) => before.edges[stride * i + before.edgeFields.indexOf(f)])
    : [t === 'vertices' ? before.vertexEdge[i] : before.faceEdge[i]]);

  /** @type {Record<string, { cells: HTMLInputElement[][], removed: HTMLInputElement[], labels: HTMLInputElement[] }>} */
  const inputs = {};
  const root = h('div', { class: 'exercise-edit' },
    h('p', { class: 'exercise-edit-op' }, 'The operation: ', h('strong', {}, q.operation), '.'));
  const cellInput = (t, row, k, name) => /** @type {HTMLInputElement} */ (h('input', {
    type: 'text', class: 'cell', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
    'data-table': t, 'data-row': String(row), 'data-col': String(k), 'aria-label': `${name}, ${columnOf(t, k)} after the operation`,
  }));
  for (const t of TABLES) {
    const rows = rowCount(q, t);
    if (!rows) continue;
    inputs[t] = { cells: [], removed: [], labels: [] };
    const section = h('div', { class: 'exercise-edit-table', 'data-table': t },
      h('h3', {}, t === 'edges' ? 'Edge table' : t === 'vertices' ? 'Vertex table' : 'Face table'));
    for (let row = 0; row < rows; row += 1) {
      const n = row - q.rows[t].length;
      const isNew = n >= 0;
      const name = isNew ? `new ${REF[t]} row ${n + 1}` : label(REF[t], q.rows[t][row]);
      const cells = Array.from({ length: width(t) }, (_, k) => cellInput(t, row, k, name));
      const removed = /** @type {HTMLInputElement} */ (h('input', { type: 'checkbox', id: `exercise-edit-${t}-${row}-removed`, 'data-table': t, 'data-row': String(row), 'data-col': 'removed' }));
      inputs[t].cells.push(cells);
      inputs[t].removed.push(removed);
      let head;
      if (isNew) {
        const labelInput = /** @type {HTMLInputElement} */ (h('input', {
          type: 'text', class: 'cell', id: `exercise-edit-${t}-label-${n}`, spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
          'data-table': t, 'data-row': String(row), 'data-col': 'label', 'aria-label': `${name}: its label (your choice)`,
        }));
        inputs[t].labels.push(labelInput);
        head = h('legend', {}, h('label', { for: labelInput.id }, `New ${REF[t]}, label `), labelInput);
      } else {
        head = h('legend', {}, h('span', { class: 'exercise-edit-name' }, name), ' ',
          h('label', { class: 'choice', for: removed.id }, removed, 'removed'));
      }
      const beforeLine = isNew ? h('p', { class: 'exercise-edit-before' }, 'new: not in the tables before')
        : h('p', { class: 'exercise-edit-before' }, 'before: ', beforeCells(t, q.rows[t][row]).map((c, k) => `${t === 'edges' ? `${EDGE_COLUMNS[k]} ` : ''}${label(refOf(t, k), c) || 'none'}`).join(' · '));
      section.append(h('fieldset', { class: 'exercise-edit-row', 'data-table': t, 'data-row': String(row) }, head, beforeLine,
        h('div', { class: `exercise-edit-cells${t === 'edges' ? ' edge' : ''}` },
          cells.map((input, k) => h('label', { class: 'exercise-edit-cell' }, h('span', {}, columnOf(t, k)), input)))));
    }
    root.append(section);
  }
  columnArrows(root);
  const answer = () => readCards(TABLES, inputs);

  return {
    root,
    answer,
    restore(saved) {
      if (fits(saved, q)) restoreCards(TABLES, inputs, saved);
    },
    check() {
      const result = gradeEdit({ api, check, subject: asked, answer: answer() });
      // Mark the cells named (by their row and column), so they can be found at a glance.
      const named = [];
      if (!result.correct && !result.incomplete) {
        const read = readAnswer(answer(), q);
        if (!read.problems.length) {
          for (const f of api.checkEditAnswer(asked.loaded, asked.edits ?? [], q.op, read.answer).findings) {
            const t = f.table === 'vertex' ? 'vertices' : f.table === 'edge' ? 'edges' : 'faces';
            named.push([t, f.index, f.field === 'label' ? 'label' : f.field === 'removed' ? 'removed' : String(t === 'edges' ? EDGE_FIELDS.indexOf(f.field) : 0)]);
          }
        }
      }
      markCards(root, named);
      return result;
    },
    worked() { return workedEdit({ api, check, subject: asked }); },
    reset() { clearCards(root); },
  };
}

export { emptyAnswer as emptyEditAnswer };
