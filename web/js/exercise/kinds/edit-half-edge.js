// @ts-check
// Kind edit with structure "half-edge": the mesh before an operation (flip e3, split e5, ...)
// and the student writes the rows of the half-edge view the operation changes, as they read
// after it: per half-edge its origin, face, next and prev (target and twin follow from the
// numbering), per vertex and per face its half-edge. The rows to write are the core's
// (api.halfEdgeEditQuestion: the view before and after compared); new elements take the
// numbers the core gives them, which the panel states (the winged-edge edit kind, edit.js,
// asks the numbering too; here the pointers are the question). The core checks the answer
// (api.checkHalfEdgeEditAnswer): each wrong cell named by its row and column with the rule to
// re-read, never its value.
//
// The answer, as kept in progress and submission files: per table (vertices, halfedges, faces)
// { cells: string[][] (4 per half-edge row: origin face next prev; 1 per vertex or face row),
// removed: boolean[], labels: [] }.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { refuseLargeMesh, replayEdits } from '../subjects.js';
import { readLabel, label, BLANK } from './table.js';
import { readCards, restoreCards, markCards, clearCards, columnArrows } from './edit-cards.js';

const TABLES = /** @type {const} */ (['halfedges', 'vertices', 'faces']);
const REF = /** @type {Record<string, 'halfedge' | 'vertex' | 'face'>} */ ({ halfedges: 'halfedge', vertices: 'vertex', faces: 'face' });
const HALF_COLUMNS = ['origin', 'face', 'next', 'prev'];
const HALF_REFS = /** @type {const} */ (['vertex', 'face', 'halfedge', 'halfedge']);
const width = (table) => (table === 'halfedges' ? 4 : 1);
const refOf = (table, k) => (table === 'halfedges' ? HALF_REFS[k] : 'halfedge');
const columnOf = (table, k) => (table === 'halfedges' ? HALF_COLUMNS[k] : 'half-edge');
const TITLES = { halfedges: 'Half-edge table', vertices: 'Vertex table', faces: 'Face table' };

// Value-free nudges, shown at the feedback level the author allows (docs/exercises.md).
const HINTS = {
  'wrong-origin': 'Find the edge this half-edge belongs to after the operation: the odd half runs S → E, the even one E → S.',
  'wrong-face': 'Walk along the half-edge from its origin in the mesh after the operation: the face on your left is its face (none on the boundary).',
  'wrong-next': 'Stand at the half-edge\'s end and turn to the next side of the same face, counter-clockwise; on the boundary, follow the boundary loop.',
  'wrong-prev': 'prev is next read backwards: which half-edge of the same face ends where this one starts?',
  'not-leaving': 'List the half-edges that start at this vertex after the operation; on the boundary take the one with no face.',
  'not-on-face': 'List the half-edges around this face after the operation: any one of them may be stored.',
  removed: 'Compare V, E and F before and after: the operation\'s counts say how many elements go, and which ones.',
  kept: 'Compare V, E and F before and after: the operation\'s counts say how many elements go, and which ones.',
  blank: 'Every cell of a listed row is written; write none where there is no face.',
};

const sentence = (s) => `${s[0].toUpperCase()}${s.slice(1)}${/[.!?]$/.test(s) ? '' : '.'}`;
const tableOf = (finding) => (finding.table === 'vertex' ? 'vertices' : finding.table === 'edge' ? 'halfedges' : 'faces');

/** The question and the operation (0-based) for the API, or an ExerciseError naming the field. */
function questionOf(api, check, subject, operationOf) {
  if (!subject.loaded) throw new ExerciseError('this lesson has no mesh to edit', 'exercise.check.kind');
  refuseLargeMesh(subject.loaded);
  const op = operationOf(api, check);
  try {
    return { op, ...api.halfEdgeEditQuestion(subject.loaded, subject.edits ?? [], op) };
  } catch (err) {
    throw new ExerciseError(`its operation cannot be asked of its drawing: ${err.message}`, 'exercise.check.op');
  }
}

// The largest label a typed cell may name per element kind: the counts after the operation.
function limits(q) {
  const most = (t) => Math.max(q.beforeCount[t], ...q.rows[t].map((r) => r + 1));
  return { halfedge: most('halfedges'), vertex: most('vertices'), face: most('faces') };
}

/** Whether `answer` has the shape of an answer to q (it may come from an untrusted file). */
function fits(answer, q) {
  if (answer === null || typeof answer !== 'object') return false;
  return TABLES.every((t) => {
    const a = answer[t];
    const rows = q.rows[t].length;
    return a && typeof a === 'object' && Array.isArray(a.cells) && a.cells.length === rows
      && a.cells.every((row) => Array.isArray(row) && row.length === width(t) && row.every((c) => typeof c === 'string' && c.length <= 40))
      && Array.isArray(a.removed) && a.removed.length === rows && a.removed.every((x) => typeof x === 'boolean');
  });
}

const rowName = (q, t, i) => `${t === 'halfedges' ? 'row' : `${REF[t]} table, row`} ${label(REF[t], q.rows[t][i])}`;

/** The typed answer as the API's numbers, or the cells that could not be read. */
function readAnswer(answer, q) {
  const problems = [];
  const most = limits(q);
  const out = {};
  for (const t of TABLES) {
    const a = answer[t];
    const cells = [];
    a.cells.forEach((row, i) => row.forEach((raw, k) => {
      const ref = refOf(t, k);
      const r = a.removed[i] ? { value: BLANK } : readLabel(raw, ref, most[ref], t === 'halfedges' && k === 1);
      if (r.problem) problems.push({ text: sentence(`${rowName(q, t, i)}, column ${columnOf(t, k)}: ${r.problem}`) });
      cells.push(r.value ?? BLANK);
    }));
    out[t] = { cells, removed: a.removed.slice(), labels: [] };
  }
  return { problems, answer: out };
}

const UNREADABLE = { correct: false, incomplete: true, findings: [{ text: 'This answer could not be read: it is not an answer to this edit (its rows do not match the question).' }] };

/**
 * Grades an answer (DOM-free; the grader runs it over loadWingspline()).
 * @param {{ api: any, check: any, subject: any, answer: any, operationOf: (api: any, check: any) => any }} parts
 */
export function gradeHalfEdgeEdit({ api, check, subject, answer, operationOf }) {
  const q = questionOf(api, check, subject, operationOf);
  if (!fits(answer, q)) return UNREADABLE;
  const typed = TABLES.some((t) => answer[t].removed.some(Boolean) || answer[t].cells.some((row) => row.some((c) => c.trim())));
  if (!typed) return { correct: false, incomplete: true, findings: [{ text: 'Nothing is written yet: write the half-edge rows after the operation, then Check.' }] };
  const read = readAnswer(answer, q);
  if (read.problems.length) return { correct: false, findings: read.problems };
  const r = api.checkHalfEdgeEditAnswer(subject.loaded, subject.edits ?? [], q.op, read.answer);
  return {
    correct: r.correct,
    findings: r.findings.map((f) => ({ text: sentence(f.reason), hint: HINTS[f.code] })),
    note: r.correct ? `Every half-edge row after ${q.operation} is right.` : undefined,
  };
}

/** The worked answer: every asked row after the operation, as the view reads it. */
export function workedHalfEdgeEdit({ api, check, subject, operationOf }) {
  const q = questionOf(api, check, subject, operationOf);
  const w = api.checkHalfEdgeEditAnswer(subject.loaded, subject.edits ?? [], q.op, emptyNumbers(q)).worked;
  const lines = [`After ${q.operation}:`];
  for (const t of TABLES) {
    q.rows[t].forEach((row, i) => {
      const name = `${label(REF[t], row)}${row >= q.beforeCount[t] ? ' (new)' : ''}`;
      if (w[t].removed[i]) { lines.push(`${name}: removed`); return; }
      const cells = w[t].cells.slice(i * width(t), (i + 1) * width(t));
      lines.push(t === 'halfedges'
        ? `${name}: ${cells.map((c, k) => `${HALF_COLUMNS[k]} ${label(HALF_REFS[k], c) || 'none'}`).join(', ')}`
        : `${name} (${REF[t]} table): half-edge ${label('halfedge', cells[0])}`);
    });
  }
  return { lines };
}

const emptyNumbers = (q) => Object.fromEntries(TABLES.map((t) => [t, {
  cells: Array(q.rows[t].length * width(t)).fill(BLANK), removed: q.rows[t].map(() => false), labels: [],
}]));

/** @param {any} parts */
export function createHalfEdgeEditKind({ api, check, subject, operationOf }) {
  const asked = subject();
  const q = questionOf(api, check, asked, operationOf);
  // The rows as they read before the operation, for reading beside the answer.
  const before = replayEdits(api, asked.loaded, asked.edits ?? [], (mesh) => mesh.halfEdgeArrays());
  const beforeCells = (t, i) => (t === 'halfedges'
    ? [before.origin[i], before.face[i], before.next[i], before.prev[i]]
    : [t === 'vertices' ? before.vertexHalfedge[i] : before.faceHalfedge[i]]);
  const newOnes = TABLES.flatMap((t) => q.rows[t].filter((r) => r >= q.beforeCount[t]).map((r) => label(REF[t], r)));

  /** @type {Record<string, { cells: HTMLInputElement[][], removed: HTMLInputElement[] }>} */
  const inputs = {};
  const root = h('div', { class: 'exercise-edit exercise-edit-half-edge' },
    h('p', { class: 'exercise-edit-op' }, 'The operation: ', h('strong', {}, q.operation), '. Write the rows of the half-edge tables it changes, as they read after it.'),
    h('p', { class: 'hint' }, 'Edge eₖ gives the half-edges h₂ₖ₋₁ = S → E and h₂ₖ = E → S; target and twin follow. ',
      newOnes.length ? `New elements take the next free numbers: ${newOnes.join(', ')}.` : 'This operation adds no element.'));
  const cellInput = (t, row, k, name) => /** @type {HTMLInputElement} */ (h('input', {
    type: 'text', class: 'cell', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
    'data-table': t, 'data-row': String(row), 'data-col': String(k), 'aria-label': `${name}, ${columnOf(t, k)} after the operation`,
  }));
  for (const t of TABLES) {
    if (!q.rows[t].length) continue;
    inputs[t] = { cells: [], removed: [] };
    const section = h('div', { class: 'exercise-edit-table', 'data-table': t }, h('h3', {}, TITLES[t]));
    q.rows[t].forEach((element, row) => {
      const isNew = element >= q.beforeCount[t];
      const name = label(REF[t], element);
      const cells = Array.from({ length: width(t) }, (_, k) => cellInput(t, row, k, name));
      const removed = /** @type {HTMLInputElement} */ (h('input', { type: 'checkbox', id: `exercise-hedit-${t}-${row}-removed`, 'data-table': t, 'data-row': String(row), 'data-col': 'removed' }));
      inputs[t].cells.push(cells);
      inputs[t].removed.push(removed);
      const head = h('legend', {}, h('span', { class: 'exercise-edit-name' }, name, isNew ? ' (new)' : ''), ' ',
        h('label', { class: 'choice', for: removed.id }, removed, 'removed'));
      const beforeLine = isNew ? h('p', { class: 'exercise-edit-before' }, 'new: not in the tables before')
        : h('p', { class: 'exercise-edit-before' }, 'before: ', beforeCells(t, element).map((c, k) => `${t === 'halfedges' ? `${HALF_COLUMNS[k]} ` : ''}${label(refOf(t, k), c) || 'none'}`).join(' · '));
      section.append(h('fieldset', { class: 'exercise-edit-row', 'data-table': t, 'data-row': String(row) }, head, beforeLine,
        h('div', { class: 'exercise-edit-cells' }, cells.map((input, k) => h('label', { class: 'exercise-edit-cell' }, h('span', {}, columnOf(t, k)), input)))));
    });
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
      const result = gradeHalfEdgeEdit({ api, check, subject: asked, answer: answer(), operationOf });
      const named = [];
      if (!result.correct && !result.incomplete) {
        const read = readAnswer(answer(), q);
        if (!read.problems.length) {
          for (const f of api.checkHalfEdgeEditAnswer(asked.loaded, asked.edits ?? [], q.op, read.answer).findings) {
            const t = tableOf(f);
            named.push([t, f.index, f.field === 'removed' ? 'removed' : String(t === 'halfedges' ? HALF_COLUMNS.indexOf(f.field) : 0)]);
          }
        }
      }
      markCards(root, named);
      return result;
    },
    worked() { return workedHalfEdgeEdit({ api, check, subject: asked, operationOf }); },
    reset() { clearCards(root); },
  };
}

