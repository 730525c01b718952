// @ts-check
// Kind 1: fill in a table for the mesh in the drawing (issue 19). The grids below are the
// lecture's tables with inputs for cells; the student writes labels as the slides do (v3, e5,
// F2, "none" or λ for no face), may number the edges their own way and walk each edge either
// way: the core's checker (api.checkMeshTableAnswer) checks the structure the answer
// describes and names each mistake. Given columns come filled in from the lesson's own tables.
import { h, setChildren } from '../../app/dom.js';
import { ExerciseError, TABLES } from '../format.js';
import { refuseLargeMesh } from '../subjects.js';

export const NONE = -1;
export const BLANK = -2;

const PREFIX = { vertex: 'v', edge: 'e', face: 'F' };
const REF_NAME = { vertex: 'a vertex', edge: 'an edge', face: 'a face' };
const NONE_WORDS = new Set(['none', '-', '—', '–', 'λ', 'nil', 'null']);

// The grids of each table: the checker's table and field names, the slide's headers.
function gridsOf(table, counts) {
  const { V, E, F } = counts;
  /** @returns {{ field: string, head: string, ref: 'vertex'|'edge'|'face', list?: boolean, none?: boolean, given?: string }} */
  const cell = (field, head, ref, extra = {}) => ({ field, head, ref, ...extra });
  if (table === 'winged-edge') {
    return [
      { table: 'edge', title: 'EDGE TABLE', rows: E, rowRef: 'edge', columns: [
        cell('start', 'S', 'vertex'), cell('end', 'E', 'vertex'), cell('left', 'L', 'face', { none: true }), cell('right', 'R', 'face', { none: true }),
        cell('startLeft', 'S:L', 'edge'), cell('startRight', 'S:R', 'edge'), cell('endLeft', 'E:L', 'edge'), cell('endRight', 'E:R', 'edge')] },
      { table: 'vertex', title: 'VERTEX TABLE', rows: V, rowRef: 'vertex', columns: [cell('edge', 'edge', 'edge', { given: 'vertexEdge', none: true })] },
      { table: 'face', title: 'FACE TABLE', rows: F, rowRef: 'face', columns: [cell('edge', 'edge', 'edge', { given: 'faceEdge' })] },
    ];
  }
  if (table === 'faces') {
    return [{ table: 'face', title: 'FACE TABLE (each face lists vertex references, counter-clockwise)', rows: F, rowRef: 'face', columns: [cell('vertices', 'vertices', 'vertex', { list: true })] }];
  }
  if (table === 'edge-list') {
    return [
      { table: 'edge', title: 'Eᵢ = (V₁, V₂, P₁, P₂)', rows: E, rowRef: 'edge', columns: [
        cell('v1', 'V₁', 'vertex'), cell('v2', 'V₂', 'vertex'), cell('p1', 'P₁', 'face', { none: true }), cell('p2', 'P₂', 'face', { none: true })] },
      { table: 'polygon', title: 'Pᵢ = (E…)', rows: F, rowRef: 'face', columns: [cell('edges', 'edges', 'edge', { list: true })] },
    ];
  }
  return [{ table: 'vertex', title: 'Adjacency lists: the vertices next to each vertex', rows: V, rowRef: 'vertex', columns: [cell('vertices', 'vertices', 'vertex', { list: true })] }];
}

export const label = (ref, i) => (i === NONE ? 'none' : i === BLANK ? '' : `${PREFIX[ref]}${i + 1}`);

/**
 * Reads one typed label: {value} (0-based, NONE, BLANK) or {problem}.
 * @param {string} raw @param {'vertex'|'edge'|'face'} ref @param {number} count @param {boolean} allowNone
 */
export function readLabel(raw, ref, count, allowNone) {
  const s = raw.trim();
  if (s === '') return { value: BLANK };
  if (NONE_WORDS.has(s.toLowerCase())) {
    return allowNone ? { value: NONE } : { problem: `"${s}": this column always names ${REF_NAME[ref]}` };
  }
  const m = /^([a-zA-Z]?)\s*(\d{1,7})$/.exec(s);
  const letters = { vertex: 'vV', edge: 'eE', face: 'fFpP' }[ref];
  if (!m || (m[1] !== '' && !letters.includes(m[1]))) return { problem: `"${s.slice(0, 20)}" is not ${REF_NAME[ref]} (write ${PREFIX[ref]}1 to ${PREFIX[ref]}${count}${allowNone ? ', or none' : ''})` };
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
  let own;
  let counts;
  try {
    const we = built.wingedEdge();
    const el = built.tables('edge-list');
    counts = { V: we.vertices.length, E: we.edges.length, F: we.faces.length };
    own = { edge: we.edges, vertex: we.vertices.map((x) => ({ vertexEdge: x.edge })), face: we.faces.map((x) => ({ faceEdge: x.edge })), edgeList: el.edges.rows() };
  } finally {
    built.dispose();
  }
  const given = new Set(check.given ?? []);
  const grids = gridsOf(check.table, counts);
  const countOf = (ref) => ({ vertex: counts.V, edge: counts.E, face: counts.F })[ref];
  const inputs = new Map(); // `${table}:${row}:${field}` -> input

  function givenValue(grid, row, column) {
    const name = column.given ?? column.field;
    if (!given.has(name)) return null;
    if (check.table === 'edge-list') return own.edgeList[row][name];
    return own[grid.table][row][name];
  }

  const root = h('div', { class: 'exercise-tables' });
  for (const grid of grids) {
    const head = h('tr', {}, h('th', { scope: 'col' }, grid.rowRef === 'edge' && check.table === 'edge-list' ? 'E' : grid.rowRef), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)));
    const body = [];
    for (let r = 0; r < grid.rows; r += 1) {
      const rowName = grid.table === 'polygon' ? `P${r + 1}` : grid.rowRef === 'edge' && check.table === 'edge-list' ? `E${r + 1}` : label(grid.rowRef, r);
      body.push(h('tr', {}, h('th', { scope: 'row' }, rowName), grid.columns.map((c) => {
        const value = givenValue(grid, r, c);
        const input = /** @type {HTMLInputElement} */ (h('input', {
          type: 'text', class: c.list ? 'cell list' : 'cell', spellcheck: 'false', autocomplete: 'off', autocapitalize: 'off',
          'aria-label': `${rowName} ${c.head}`, 'data-table': grid.table, 'data-row': r, 'data-field': c.field,
          readonly: value !== null, value: value === null ? '' : value === NONE ? 'none' : label(c.ref, value),
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
          const r = readLabel(p, x.column.ref, countOf(x.column.ref), false);
          if (r.problem) problems.push({ x, text: r.problem });
          else out.push(r.value);
        }
        return out;
      }
      const r = readLabel(raw, x.column.ref, countOf(x.column.ref), Boolean(x.column.none) || x.column.ref === 'edge');
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
    else if (check.table === 'edge-list') value = { edges: rowsOf('edge').flat(), polygons: rowsOf('polygon').map((r) => r[0]) };
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
    // (the core names a row by its kind: the edge list's polygon rows are 'face' rows)
    const table = check.table === 'edge-list' && f.table === 'face' ? 'polygon' : f.table;
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
      const flat = { edge: check.table === 'edge-list' ? worked.edges : worked.edges, vertex: check.table === 'winged-edge' ? worked.vertexEdges : worked.vertexVertices, face: check.table === 'winged-edge' ? worked.faceEdges : worked.faces, polygon: worked.polygons }[table];
      const width = grid.columns.length;
      return Array.from({ length: grid.rows }, (_, r) => grid.columns.map((c, k) => {
        const v = c.list ? flat[r] : flat[width * r + k];
        return c.list ? v.map((x) => label(c.ref, x)).join(' ') : label(c.ref, v);
      }));
    };
    return grids.map((grid) => h('table', { class: 'data-table exercise-grid worked' }, h('caption', {}, grid.title),
      h('thead', {}, h('tr', {}, h('th', { scope: 'col' }, ''), grid.columns.map((c) => h('th', { scope: 'col' }, c.head)))),
      h('tbody', {}, rows(grid.table).map((cells, r) => h('tr', {}, h('th', { scope: 'row' }, grid.table === 'polygon' ? `P${r + 1}` : label(grid.rowRef, r)), cells.map((c) => h('td', {}, c)))))));
  }
}

export const TABLE_LABELS = Object.fromEntries(Object.entries(TABLES).map(([k, v]) => [k, v.label]));
