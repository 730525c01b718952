// @ts-check
// Kind 1: fill in a table for the mesh in the drawing. The grids below are the
// lecture's tables with inputs for cells; the student writes labels as the slides do (v3, e5,
// F2, "none" or λ for no face), may number the edges their own way and walk each edge either
// way: the core's checker (api.checkMeshTableAnswer) checks the structure the answer
// describes and names each mistake. Given columns come filled in from the lesson's own tables.
// The half-edge table (table: 'half-edge') is one more table of this kind, not a kind of its
// own: the same grids of typed labels (h5 for a half-edge), the same answer and progress
// shape, the same checking by the core with any numbering of its rows.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError, TABLES } from '../format.js';
import { refuseLargeMesh } from '../subjects.js';
import { elementLabel } from '../../ui/element-labels.js';
import { findingOf, incomplete, isPlainObject, unreadable } from './grading.js';

export const NONE = -1;
export const BLANK = -2;

// How each table names elements: the slides' v1, e1, F1 and "none"; lecture 001's edge list
// writes V1, E1, P1 and λ.
const NAMES = { vertex: 'v', edge: 'e', face: 'F', halfedge: 'h', none: 'none' };
const TABLE_NAMES = { 'edge-list': { vertex: 'V', edge: 'E', face: 'P', none: 'λ' } };
const namesOf = (table) => ({ ...NAMES, ...TABLE_NAMES[table] });
const REF_NAME = { vertex: 'a vertex', edge: 'an edge', face: 'a face', halfedge: 'a half-edge' };
const NONE_WORDS = new Set(['none', '-', '—', '–', 'λ', 'nil', 'null']);

// Each exercise table is one or more of the core's tables (api.tableDescriptors, the one
// description of every table: its title, the kind of its rows, its columns with the slide's
// headers and what they refer to): [representation, table, the columns to fill (null: every
// column that refers to an element)]. The checker names a cell by the kind of its row and
// the column's name, as the descriptors do.
const PARTS = {
  'winged-edge': [['winged-edge', 'edges', null], ['winged-edge', 'vertices', ['edge']], ['winged-edge', 'faces', null]],
  faces: [['vertex-face-tables', 'faces', null]],
  'edge-list': [['edge-list', 'edges', null], ['edge-list', 'polygons', null]],
  adjacency: [['adjacency-lists', 'vertices', ['vertices']]],
};

// The half-edge table (docs/api-mesh.md, "The half-edge view"), headed as the mesh lesson's
// Half-edge tab heads it; the target is not a column (it is the twin's origin), nor stored.
// A vertex on no face stores none; every other cell names something.
const he = (field, ref, none = false) => ({ field, head: field, ref, list: false, none });
const HALF_EDGE_GRIDS = [
  { table: 'halfedge', name: 'halfedges', title: 'Half-edges', columns: [he('origin', 'vertex'), he('face', 'face', true), he('next', 'halfedge'), he('prev', 'halfedge'), he('twin', 'halfedge')] },
  { table: 'vertex', name: 'vertices', title: 'Vertices: one outgoing half-edge each', columns: [{ ...he('halfedge', 'halfedge', true), head: 'half-edge' }] },
  { table: 'face', name: 'faces', title: 'Faces: one of their half-edges each', columns: [{ ...he('halfedge', 'halfedge'), head: 'half-edge' }] },
];

/** @returns {Array<{ table: string, representation: string, name: string, title: string, rows: number, rowRef: 'vertex'|'edge'|'face'|'halfedge', rowName: (r: number) => string, columns: Array<{ field: string, head: string, ref: 'vertex'|'edge'|'face'|'halfedge', list: boolean, none: boolean }> }>} */
function gridsOf(api, table, counts) {
  if (table === 'half-edge') {
    return HALF_EDGE_GRIDS.map((g) => ({ ...g, representation: 'half-edge', rows: counts[g.table], rowRef: /** @type {any} */ (g.table), rowName: (r) => `${NAMES[g.table]}${r + 1}` }));
  }
  return PARTS[table].map(([representation, name, only]) => {
    const d = api.tableDescriptors.find((x) => x.representation === representation && x.name === name);
    const columns = d.columns.filter((c) => c.refers && (!only || only.includes(c.name))).map((c) => ({
      field: c.name, head: c.group ? `${c.group}:${c.label}` : c.label, ref: c.refers, list: c.layout === 'csr',
      // "none" where the slides leave a cell empty: no face on a side, no edge at a vertex
      none: c.refers === 'face' || (d.rows === 'vertex' && c.refers === 'edge'),
    }));
    const names = namesOf(table);
    return {
      table: d.rows, representation, name, rows: counts[d.rows], rowRef: d.rows, columns,
      title: table === 'faces' ? `${d.title}, counter-clockwise` : d.title,
      rowName: (r) => `${names[d.rows]}${r + 1}`,
    };
  });
}

export const label = (ref, i) => (i === NONE ? 'none' : i === BLANK ? '' : elementLabel(ref, i));
// The same in a table's own names (lecture 001's edge list: V1, E1, P1, λ).
const labelIn = (names, ref, i) => (i === NONE ? names.none : i === BLANK ? '' : `${names[ref]}${i + 1}`);

/**
 * Reads one typed label: {value} (0-based, NONE, BLANK) or {problem}.
 * @param {string} raw @param {'vertex'|'edge'|'face'|'halfedge'} ref @param {number} count @param {boolean} allowNone
 */
export function readLabel(raw, ref, count, allowNone, names = NAMES) {
  const PREFIX = names;
  const s = raw.trim();
  if (s === '') return { value: BLANK };
  if (NONE_WORDS.has(s.toLowerCase())) {
    return allowNone ? { value: NONE } : { problem: `"${s}": this column always names ${REF_NAME[ref]}` };
  }
  const m = /^([a-zA-Z]?)\s*(\d{1,7})$/.exec(s);
  const letters = { vertex: 'vV', edge: 'eE', face: 'fFpP', halfedge: 'hH' }[ref];
  if (!m || (m[1] !== '' && !letters.includes(m[1]))) return { problem: `"${s.slice(0, 20)}" is not ${REF_NAME[ref]} (write ${PREFIX[ref]}1 to ${PREFIX[ref]}${count}${allowNone ? `, or ${names.none}` : ''})` };
  const n = Number(m[2]);
  if (n < 1 || n > count) return { problem: `"${s}" is not ${REF_NAME[ref]} of this mesh (${PREFIX[ref]}1 to ${PREFIX[ref]}${count})` };
  return { value: n - 1 };
}

// The exercise's tables for its mesh: the grids (the core's descriptors), the lesson's own rows
// (for the columns the exercise gives), the element counts. No DOM: the page and the grader share it.
function tableModel(api, check, subject) {
  const mesh = subject.mesh;
  if (!mesh) throw new ExerciseError('this lesson has no mesh to fill a table for', 'exercise.check.kind');
  refuseLargeMesh(mesh);
  const built = api.buildMesh(mesh);
  let grids;
  const own = {}; // the lesson's own rows, by the grid's row kind
  try {
    const we = built.wingedEdge();
    const counts = { vertex: we.vertices.length, edge: we.edges.length, face: we.faces.length, halfedge: 2 * we.edges.length };
    grids = gridsOf(api, check.table, counts);
    if (check.table === 'half-edge') Object.assign(own, halfEdgeRows(api, mesh, counts));
    else for (const grid of grids) own[grid.table] = built.tables(grid.representation)[grid.name].rows();
    for (const kind of ['vertex', 'edge', 'face', 'halfedge']) own[`${kind}Count`] = counts[kind];
  } finally {
    built.dispose();
  }
  const given = new Set(check.given ?? []);
  const names = namesOf(check.table);
  // A column the exercise gives, in format.js's names (the winged edge's vertex and face
  // tables' one column: vertexEdge, faceEdge; the half-edge table's: vertexHalfedge, faceHalfedge).
  const givenName = (grid, column) => (check.table === 'winged-edge' && grid.table !== 'edge' ? `${grid.table}Edge`
    : check.table === 'half-edge' && grid.table !== 'halfedge' ? `${grid.table}Halfedge` : column.field);
  /** The cells in order: key `${table}:${row}:${field}`, its grid and column, its given value (null: to fill in). */
  const cells = [];
  for (const grid of grids) {
    for (let r = 0; r < grid.rows; r += 1) {
      for (const c of grid.columns) {
        const value = given.has(givenName(grid, c)) ? own[grid.table][r][c.field] : null;
        cells.push({ key: `${grid.table}:${r}:${c.field}`, grid, row: r, column: c, given: value, name: `${grid.rowName(r)} ${c.head}` });
      }
    }
  }
  return { mesh, grids, names, cells, countOf: (ref) => own[`${ref}Count`] };
}

// The half-edge table in the lesson's own numbering (edge e gives h(2e+1), h(2e+2); what the
// Half-edge tab shows), for the columns an exercise gives (and the walk's choices): the core's
// worked answer of a blank table, whose rows nothing identifies, is that numbering. From the exercises module, so the
// table works in any lesson with a mesh.
export function halfEdgeRows(api, mesh, counts) {
  const blank = (n) => new Array(n).fill(BLANK);
  const w = api.checkMeshTableAnswer(mesh, 'half-edge', { halfedges: blank(5 * counts.halfedge), vertexHalfedges: blank(counts.vertex), faceHalfedges: blank(counts.face) }).worked;
  const fields = ['origin', 'face', 'next', 'prev', 'twin'];
  return {
    halfedge: Array.from({ length: counts.halfedge }, (_, r) => Object.fromEntries(fields.map((f, k) => [f, w.halfedges[5 * r + k]]))),
    vertex: w.vertexHalfedges.map((x) => ({ halfedge: x })),
    face: w.faceHalfedges.map((x) => ({ halfedge: x })),
  };
}

// The answer (typed text per cell key) as the checker takes it; problems of reading as
// {key, text}. Given cells read as the page shows them.
function readTable(model, check, textOf) {
  const { cells, names, countOf } = model;
  const problems = [];
  const byKey = new Map(cells.map((x) => [x.key, x]));
  const cell = (x) => {
    const raw = x.given !== null ? labelIn(names, x.column.ref, x.given) : textOf(x.key);
    if (x.column.list) {
      const out = [];
      for (const p of raw.split(/[\s,;]+/).filter((q) => q !== '')) {
        const r = readLabel(p, x.column.ref, countOf(x.column.ref), false, names);
        if (r.problem) problems.push({ key: x.key, text: `${x.name}: ${r.problem}.` });
        else out.push(r.value);
      }
      return out;
    }
    // (none is read where a column names an edge or half-edge, so the core says why it is wrong)
    const r = readLabel(raw, x.column.ref, countOf(x.column.ref), Boolean(x.column.none) || x.column.ref === 'edge' || x.column.ref === 'halfedge', names);
    if (r.problem) { problems.push({ key: x.key, text: `${x.name}: ${r.problem}.` }); return BLANK; }
    return r.value;
  };
  const rowsOf = (table) => {
    const grid = model.grids.find((g) => g.table === table);
    return Array.from({ length: grid.rows }, (_, r) => grid.columns.map((c) => cell(byKey.get(`${table}:${r}:${c.field}`))));
  };
  let value;
  if (check.table === 'winged-edge') value = { edges: rowsOf('edge').flat(), vertexEdges: rowsOf('vertex').flat(), faceEdges: rowsOf('face').flat() };
  else if (check.table === 'half-edge') value = { halfedges: rowsOf('halfedge').flat(), vertexHalfedges: rowsOf('vertex').flat(), faceHalfedges: rowsOf('face').flat() };
  else if (check.table === 'faces') value = { faces: rowsOf('face').map((r) => r[0]) };
  else if (check.table === 'edge-list') value = { edges: rowsOf('edge').flat(), polygons: rowsOf('face').map((r) => r[0]) };
  else value = { vertexVertices: rowsOf('vertex').map((r) => r[0]) };
  return { value, problems };
}

// A finding's cell key: its table, the student's row, its field.
function cellKeyOf(model, f) {
  const grid = model.grids.find((g) => g.table === f.table); // (the kind of the row: the edge list's polygons are 'face' rows)
  if (!grid || f.row < 0) return null;
  const field = grid.columns.some((c) => c.field === f.field) ? f.field : grid.columns.length === 1 ? grid.columns[0].field : null;
  return field === null ? null : `${f.table}:${f.row}:${field}`;
}

const TABLE_SHAPE = 'the table as typed: {"edge:0:start": "v1", …} (text per cell)';

/** @param {unknown} answer @returns {((key: string) => string) | null} */
function typedCells(answer) {
  if (!isPlainObject(answer)) return null;
  const entries = Object.entries(/** @type {any} */ (answer));
  if (entries.length > 20000 || !entries.every(([, v]) => typeof v === 'string' && v.length <= 200)) return null;
  const map = new Map(entries);
  return (key) => map.get(key) ?? '';
}

// The grade and, per finding, the cell it names (the page marks them).
function markTable(api, check, model, answer) {
  const textOf = typedCells(answer);
  if (!textOf) return { result: unreadable(TABLE_SHAPE), marks: [] };
  if (model.cells.every((x) => x.given !== null || textOf(x.key).trim() === '')) {
    return { result: incomplete('Fill in the table first: every cell is blank.'), marks: [] };
  }
  const { value, problems } = readTable(model, check, textOf);
  if (problems.length) {
    return { result: { correct: false, incomplete: true, findings: problems.map((p) => ({ text: p.text })) }, marks: problems.map((p) => ({ key: p.key, text: p.text })) };
  }
  const r = api.checkMeshTableAnswer(model.mesh, check.table, value);
  return {
    result: { correct: r.correct, findings: r.findings.map((f) => findingOf(f.message, f.hint)) },
    marks: r.findings.map((f) => ({ key: cellKeyOf(model, f), text: f.message })).filter((m) => m.key !== null),
    worked: r.worked,
  };
}

/**
 * Grades a filled-in table (the page's answer: the text typed per cell). Pure: no DOM.
 * @param {{ api: any, check: any, subject: any, answer: unknown }} parts
 * @returns {import('./grading.js').GradeResult}
 */
export function gradeTable({ api, check, subject, answer }) {
  return markTable(api, check, tableModel(api, check, subject), answer).result;
}

// The worked table as rows of labels, in the student's numbering where their rows match.
function workedRows(api, check, model, answer) {
  const textOf = typedCells(answer) ?? (() => '');
  const { value } = readTable(model, check, textOf);
  const worked = api.checkMeshTableAnswer(model.mesh, check.table, value).worked;
  return model.grids.map((grid) => {
    const flat = check.table === 'half-edge'
      ? { halfedge: worked.halfedges, vertex: worked.vertexHalfedges, face: worked.faceHalfedges }[grid.table]
      : { edge: worked.edges, vertex: check.table === 'winged-edge' ? worked.vertexEdges : worked.vertexVertices, face: check.table === 'winged-edge' ? worked.faceEdges : check.table === 'edge-list' ? worked.polygons : worked.faces }[grid.table];
    const width = grid.columns.length;
    const rows = Array.from({ length: grid.rows }, (_, r) => grid.columns.map((c, k) => {
      const v = c.list ? flat[r] : flat[width * r + k];
      return c.list ? v.map((x) => labelIn(model.names, c.ref, x)).join(' ') : labelIn(model.names, c.ref, v);
    }));
    return { grid, rows };
  });
}

/**
 * The worked table, one line per row ("e1: S v1, E v2, …"), in the student's numbering where
 * the answer given matches (any answer, or none).
 * @param {{ api: any, check: any, subject: any, answer?: unknown }} parts
 */
export function workedTable({ api, check, subject, answer }) {
  const model = tableModel(api, check, subject);
  return {
    lines: workedRows(api, check, model, answer).flatMap(({ grid, rows }) => rows.map((cells, r) => `${grid.title}, ${grid.rowName(r)}: ${grid.columns.map((c, k) => `${c.head} ${cells[k] || '–'}`).join(', ')}`)),
  };
}

/** @param {any} parts */
export function createTableKind({ api, check, subject }) {
  const model = tableModel(api, check, subject());
  const { grids, names } = model;
  const inputs = new Map(); // key -> input
  const cellByKey = new Map(model.cells.map((x) => [x.key, x]));
  const root = h('div', { class: 'exercise-tables' });
  for (const grid of grids) {
    const head = h('tr', {}, h('th', { scope: 'col' }, grid.rowRef === 'halfedge' ? 'half-edge' : grid.rowRef), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)));
    const body = [];
    for (let r = 0; r < grid.rows; r += 1) {
      const rowName = grid.rowName(r);
      body.push(h('tr', {}, h('th', { scope: 'row' }, rowName), grid.columns.map((c) => {
        const x = cellByKey.get(`${grid.table}:${r}:${c.field}`);
        const value = x.given;
        const input = /** @type {HTMLInputElement} */ (h('input', {
          type: 'text', class: c.list ? 'cell list' : 'cell', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
          'aria-label': `${rowName} ${c.head}`, 'data-table': grid.table, 'data-row': r, 'data-field': c.field,
          readonly: value !== null, value: value === null ? '' : labelIn(names, c.ref, value),
        }));
        if (value !== null) input.classList.add('given');
        inputs.set(x.key, input);
        return h('td', {}, input);
      })));
    }
    // A grid wider than its column (a phone, a narrow window) scrolls in its own box, and a
    // cue above it says so while it does.
    const cue = h('p', { class: 'exercise-scroll-cue hint', id: `exercise-cue-${grid.table}`, hidden: true }, `${grid.title} is wider than this column: scroll it sideways for every column →`);
    const box = h('div', { class: 'exercise-grid-box' },
      h('table', { class: 'data-table exercise-grid' }, h('caption', {}, grid.title), h('thead', {}, head), h('tbody', {}, body)));
    root.append(cue, box);
    if (typeof ResizeObserver === 'function') new ResizeObserver(() => { cue.hidden = box.scrollWidth <= box.clientWidth + 1; }).observe(box);
  }
  const workedBox = h('div', { class: 'exercise-worked', hidden: true });
  root.append(workedBox);

  // The typed answer as text, cell by cell (progress keeps it exactly as typed).
  const answer = () => Object.fromEntries([...inputs].filter(([, input]) => !input.readOnly).map(([key, input]) => [key, input.value]));
  function restore(saved) {
    if (!saved || typeof saved !== 'object') return;
    for (const [key, value] of Object.entries(saved)) {
      const input = inputs.get(key);
      if (input && !input.readOnly && typeof value === 'string') input.value = value.slice(0, 200);
    }
  }
  function clearMarks() {
    for (const input of inputs.values()) { input.removeAttribute('aria-invalid'); input.removeAttribute('title'); }
  }

  return {
    root,
    answer,
    restore,
    check() {
      clearMarks();
      const { result, marks } = markTable(api, check, model, answer());
      for (const m of marks) {
        const input = inputs.get(m.key);
        if (input) { input.setAttribute('aria-invalid', 'true'); input.title = m.text; }
      }
      return result;
    },
    worked() {
      const tables = workedRows(api, check, model, answer());
      setChildren(workedBox, h('h3', {}, 'Worked answer'), tables.map(({ grid, rows }) => h('table', { class: 'data-table exercise-grid worked' }, h('caption', {}, grid.title),
        h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, ''), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)))),
        h('tbody', {}, rows.map((cells, r) => h('tr', {}, h('th', { scope: 'row' }, grid.rowName(r)), cells.map((c) => h('td', {}, c))))))));
      workedBox.hidden = false;
      return { lines: [] };
    },
  };
}
