// @ts-check
// Kind 1: fill in a table for the mesh in the drawing. The grids below are the
// lecture's tables with inputs for cells; the student writes labels as the slides do (v3, e5,
// F2, "none" or λ for no face), may number the edges their own way and walk each edge either
// way: the core's checker (api.checkMeshTableAnswer) checks the structure the answer
// describes and names each mistake. Given columns come filled in from the lesson's own tables.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError, TABLES } from '../format.js';
import { refuseLargeMesh } from '../subjects.js';
import { elementLabel } from '../../ui/element-labels.js';

export const NONE = -1;
export const BLANK = -2;

// How each table names elements: the slides' v1, e1, F1 and "none"; lecture 001's edge list
// writes V1, E1, P1 and λ.
const NAMES = { vertex: 'v', edge: 'e', face: 'F', none: 'none' };
const TABLE_NAMES = { 'edge-list': { vertex: 'V', edge: 'E', face: 'P', none: 'λ' } };
const namesOf = (table) => ({ ...NAMES, ...TABLE_NAMES[table] });
const REF_NAME = { vertex: 'a vertex', edge: 'an edge', face: 'a face' };
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

/** @returns {Array<{ table: string, representation: string, name: string, title: string, rows: number, rowRef: 'vertex'|'edge'|'face', rowName: (r: number) => string, columns: Array<{ field: string, head: string, ref: 'vertex'|'edge'|'face', list: boolean, none: boolean }> }>} */
function gridsOf(api, table, counts) {
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
 * @param {string} raw @param {'vertex'|'edge'|'face'} ref @param {number} count @param {boolean} allowNone
 */
export function readLabel(raw, ref, count, allowNone, names = NAMES) {
  const PREFIX = names;
  const s = raw.trim();
  if (s === '') return { value: BLANK };
  if (NONE_WORDS.has(s.toLowerCase())) {
    return allowNone ? { value: NONE } : { problem: `"${s}": this column always names ${REF_NAME[ref]}` };
  }
  const m = /^([a-zA-Z]?)\s*(\d{1,7})$/.exec(s);
  const letters = { vertex: 'vV', edge: 'eE', face: 'fFpP' }[ref];
  if (!m || (m[1] !== '' && !letters.includes(m[1]))) return { problem: `"${s.slice(0, 20)}" is not ${REF_NAME[ref]} (write ${PREFIX[ref]}1 to ${PREFIX[ref]}${count}${allowNone ? `, or ${names.none}` : ''})` };
  const n = Number(m[2]);
  if (n < 1 || n > count) return { problem: `"${s}" is not ${REF_NAME[ref]} of this mesh (${PREFIX[ref]}1 to ${PREFIX[ref]}${count})` };
  return { value: n - 1 };
}

/** @param {any} parts */
export function createTableKind({ api, check, subject }) {
  const mesh = subject().mesh;
  if (!mesh) throw new ExerciseError('this lesson has no mesh to fill a table for', 'exercise.check.kind');
  refuseLargeMesh(mesh);
  // The lesson's own tables, for the columns the exercise gives (the lesson's numbering).
  const built = api.buildMesh(mesh);
  let grids;
  const own = {}; // the lesson's own rows, by the grid's row kind
  try {
    const we = built.wingedEdge();
    const counts = { vertex: we.vertices.length, edge: we.edges.length, face: we.faces.length };
    grids = gridsOf(api, check.table, counts);
    for (const grid of grids) own[grid.table] = built.tables(grid.representation)[grid.name].rows();
    for (const kind of ['vertex', 'edge', 'face']) own[`${kind}Count`] = counts[kind];
  } finally {
    built.dispose();
  }
  const countOf = (ref) => own[`${ref}Count`];
  const given = new Set(check.given ?? []);
  const names = namesOf(check.table);
  const inputs = new Map(); // `${table}:${row}:${field}` -> input

  // A column the exercise gives, in format.js's names (the winged edge's vertex and face
  // tables' one column: vertexEdge, faceEdge).
  const givenName = (grid, column) => (check.table === 'winged-edge' && grid.table !== 'edge' ? `${grid.table}Edge` : column.field);
  function givenValue(grid, row, column) {
    return given.has(givenName(grid, column)) ? own[grid.table][row][column.field] : null;
  }

  const root = h('div', { class: 'exercise-tables' });
  for (const grid of grids) {
    const head = h('tr', {}, h('th', { scope: 'col' }, grid.rowRef), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)));
    const body = [];
    for (let r = 0; r < grid.rows; r += 1) {
      const rowName = grid.rowName(r);
      body.push(h('tr', {}, h('th', { scope: 'row' }, rowName), grid.columns.map((c) => {
        const value = givenValue(grid, r, c);
        const input = /** @type {HTMLInputElement} */ (h('input', {
          type: 'text', class: c.list ? 'cell list' : 'cell', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
          'aria-label': `${rowName} ${c.head}`, 'data-table': grid.table, 'data-row': r, 'data-field': c.field,
          readonly: value !== null, value: value === null ? '' : labelIn(names, c.ref, value),
        }));
        if (value !== null) input.classList.add('given');
        inputs.set(`${grid.table}:${r}:${c.field}`, { input, column: c, grid });
        return h('td', {}, input);
      })));
    }
    root.append(h('table', { class: 'data-table exercise-grid' }, h('caption', {}, grid.title), h('thead', {}, head), h('tbody', {}, body)));
  }
  const workedBox = h('div', { class: 'exercise-worked', hidden: true });
  root.append(workedBox);

  // The typed answer as text, cell by cell (progress keeps it exactly as typed).
  const answer = () => Object.fromEntries([...inputs].filter(([, x]) => !x.input.readOnly).map(([key, x]) => [key, x.input.value]));
  function restore(saved) {
    if (!saved || typeof saved !== 'object') return;
    for (const [key, value] of Object.entries(saved)) {
      const x = inputs.get(key);
      if (x && !x.input.readOnly && typeof value === 'string') x.input.value = value.slice(0, 200);
    }
  }

  // The answer as the checker takes it; problems of reading come first, as findings.
  function read() {
    const problems = [];
    const cell = (x) => {
      const raw = x.input.value;
      if (x.column.list) {
        const parts = raw.split(/[\s,;]+/).filter((p) => p !== '');
        const out = [];
        for (const p of parts) {
          const r = readLabel(p, x.column.ref, countOf(x.column.ref), false, names);
          if (r.problem) problems.push({ x, text: r.problem });
          else out.push(r.value);
        }
        return out;
      }
      const r = readLabel(raw, x.column.ref, countOf(x.column.ref), Boolean(x.column.none) || x.column.ref === 'edge', names);
      if (r.problem) { problems.push({ x, text: r.problem }); return BLANK; }
      return r.value;
    };
    const rowsOf = (table) => {
      const grid = grids.find((g) => g.table === table);
      return Array.from({ length: grid.rows }, (_, r) => grid.columns.map((c) => cell(inputs.get(`${table}:${r}:${c.field}`))));
    };
    let value;
    if (check.table === 'winged-edge') value = { edges: rowsOf('edge').flat(), vertexEdges: rowsOf('vertex').flat(), faceEdges: rowsOf('face').flat() };
    else if (check.table === 'faces') value = { faces: rowsOf('face').map((r) => r[0]) };
    else if (check.table === 'edge-list') value = { edges: rowsOf('edge').flat(), polygons: rowsOf('face').map((r) => r[0]) };
    else value = { vertexVertices: rowsOf('vertex').map((r) => r[0]) };
    return { value, problems };
  }

  function mark(x, text) {
    x.input.setAttribute('aria-invalid', 'true');
    x.input.title = text;
  }
  function clearMarks() {
    for (const { input } of inputs.values()) { input.removeAttribute('aria-invalid'); input.removeAttribute('title'); }
  }

  // A finding's cell: its table, the student's row, its field.
  function cellOf(f) {
    const table = f.table; // (the kind of the row: the edge list's polygons are 'face' rows)
    const grid = grids.find((g) => g.table === table);
    if (!grid) return null;
    const field = grid.columns.some((c) => c.field === f.field) ? f.field : grid.columns.length === 1 ? grid.columns[0].field : null;
    return field === null ? null : inputs.get(`${table}:${f.row}:${field}`) ?? null;
  }

  return {
    root,
    answer,
    restore,
    check() {
      clearMarks();
      const { value, problems } = read();
      if ([...inputs.values()].every((x) => x.input.readOnly || x.input.value.trim() === '')) {
        return { correct: false, incomplete: true, findings: ['Fill in the table first: every cell is blank.'] };
      }
      if (problems.length) {
        for (const p of problems) mark(p.x, p.text);
        return { correct: false, incomplete: true, findings: problems.map((p) => `${p.x.input.getAttribute('aria-label')}: ${p.text}.`) };
      }
      const r = api.checkMeshTableAnswer(mesh, check.table, value);
      for (const f of r.findings) {
        const x = cellOf(f);
        if (x) mark(x, f.reason);
      }
      return { correct: r.correct, findings: r.findings.map((f) => f.reason) };
    },
    worked() {
      const { value } = read();
      const r = api.checkMeshTableAnswer(mesh, check.table, value);
      setChildren(workedBox, h('h3', {}, 'Worked answer'), workedTables(r.worked));
      workedBox.hidden = false;
      return { lines: [] };
    },
  };

  // The worked answer in the grids' shape, read-only.
  function workedTables(worked) {
    const rows = (table) => {
      const grid = grids.find((g) => g.table === table);
      const flat = { edge: worked.edges, vertex: check.table === 'winged-edge' ? worked.vertexEdges : worked.vertexVertices, face: check.table === 'winged-edge' ? worked.faceEdges : check.table === 'edge-list' ? worked.polygons : worked.faces }[table];
      const width = grid.columns.length;
      return Array.from({ length: grid.rows }, (_, r) => grid.columns.map((c, k) => {
        const v = c.list ? flat[r] : flat[width * r + k];
        return c.list ? v.map((x) => labelIn(names, c.ref, x)).join(' ') : labelIn(names, c.ref, v);
      }));
    };
    return grids.map((grid) => h('table', { class: 'data-table exercise-grid worked' }, h('caption', {}, grid.title),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, ''), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)))),
      h('tbody', {}, rows(grid.table).map((cells, r) => h('tr', {}, h('th', { scope: 'row' }, grid.rowName(r)), cells.map((c) => h('td', {}, c)))))));
  }
}

