// @ts-check
// A mesh's tables drawn from the core's table descriptors (web/js/core/tables.js): the
// caption, the headers (the slide's S E L R and the wings under S and E), one row per
// element of its kind, each cell by what its column holds. The same code shows the winged
// edge of every mesh lesson, so what a table says is what the core stores.
// Offers: describedTable(d, letters, rowOf) (a createVirtualTable spec: caption, head,
//   rowLabel, row), headOf(d), rowCells(d, row, letters), sub(letter, i), NOTATION, num(x),
//   createWingedTables(api) -> (arrays, counts) -> {vertices, edges, faces} (readTable's Tables).
// Needs: the JS API's table descriptors (api.tableDescriptors) and the winged-edge arrays of
//   a mesh (mesh.wingedEdgeArrays(): positions, vertexEdge, faceEdge, edges[8*e + k]).
import { h } from '../../app/dom.js';
import { readTable, findDescriptor } from '../../core/tables.js';

// Numbers in tables: short, and -0 as 0.
export function num(x, digits = 4) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return '0';
  if (Number.isInteger(x)) return String(x);
  return String(Number(x.toPrecision(digits)));
}

// A label as the slides write it (F with a subscript 1): a text and one <sub> element, no
// wrapper, so a 250-item adjacency list lays out as few boxes as it can.
export const sub = (letter, i, before = '') => (i >= 0 ? [before + letter, h('sub', {}, String(i + 1))] : '');
const triple = (p) => `(${num(p[0])}, ${num(p[1])}, ${num(p[2])})`;
const listOf = (indices, label) => {
  const items = Array.from(indices).filter((i) => i >= 0);
  const out = [];
  items.forEach((i, k) => out.push(label(i, k ? ' ' : '')));
  return out.length ? out : '—';
};

// The letters each representation names its elements with (Foley: V, E, P; λ = no polygon).
export const NOTATION = {
  default: { vertex: 'v', edge: 'e', face: 'F', none: '' },
  'edge-list': { vertex: 'V', edge: 'E', face: 'P', none: 'λ' },
};

// Header rows from a descriptor: the labels, and above them the groups (the winged edge's
// wings: L R under S, L R under E) when any column has one.
export function headOf(d) {
  const labels = ['', ...d.columns.map((c) => c.label)];
  if (!d.columns.some((c) => c.group)) return [labels];
  const groups = [{ text: '', colspan: 1 }];
  for (const c of d.columns) {
    const last = groups[groups.length - 1];
    if (last.text === c.group) last.colspan += 1;
    else groups.push({ text: c.group, colspan: 1 });
  }
  return [groups, labels];
}

// The cells of one row from what each column holds: coordinates as numbers or (x, y, z),
// references as the slide's labels, lists of references in one cell. A table whose only
// column is a list shows one cell per item, as the slides' face tables do (F₁ V₁ V₂ V₃).
export function rowCells(d, row, letters) {
  const coordinate = (x) => (Array.isArray(x) ? triple(x) : num(x));
  const spread = d.columns.length === 1 && d.columns[0].layout === 'csr';
  const cells = [];
  for (const c of d.columns) {
    const value = row[c.name];
    if (c.refers === null) {
      if (spread) cells.push(...value.map(coordinate));
      else cells.push(coordinate(value));
      continue;
    }
    const label = (i, before) => sub(letters[c.refers], i, before);
    if (spread) cells.push(...value.map((i) => label(i)));
    else if (Array.isArray(value)) cells.push(listOf(value, label));
    else cells.push(value >= 0 ? label(value) : letters.none);
  }
  return cells;
}

// What createVirtualTable (ui/virtual-table.js) needs to show descriptor d: rowOf(i) is the
// Table (readTable) that holds row i.
// rowKey is the row's values: its cells are drawn from them alone (the letters are the table's).
export function describedTable(d, letters, rowOf) {
  return { caption: d.title, head: headOf(d), rowLabel: (i) => sub(letters[d.rows], i), row: (i) => rowCells(d, rowOf(i).row(i), letters), rowKey: (i) => rowOf(i).row(i) };
}

// The winged-edge tables of a mesh's arrays, read once per arrays object (a mesh version,
// or one step of an edit being played): counts gives the rows of each table.
export function createWingedTables(api) {
  const read = new WeakMap(); // arrays -> {vertices, edges, faces}
  return (arrays, counts) => {
    if (!read.has(arrays)) {
      const table = (name) => readTable(findDescriptor(api.tableDescriptors, 'winged-edge', name), { rows: counts[name], arrays });
      read.set(arrays, { vertices: table('vertices'), edges: table('edges'), faces: table('faces') });
    }
    return read.get(arrays);
  };
}
