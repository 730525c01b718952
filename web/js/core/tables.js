// @ts-check
// The one generic reader of the mesh tables. The core describes every table
// once (core/src/mesh/tables.cpp: name, element kind of its rows, columns with labels and
// the element kind each refers to, each array's layout: `stride` numbers per row, or a
// list cut into rows by CSR offsets); the binding sends those descriptors once
// (meshTableDescriptors) and any table's data as flat typed arrays (meshTables). This file
// turns {descriptor, data} into rows by index and cells by column name, for every table
// alike. See docs/api-mesh.md, "Tables".
import { WingsplineError } from './errors.js';
import { elementLabel } from './element-labels.js';

// A table's cell: a number (width 1), an array of `width` numbers, or for a CSR column an
// array of items (numbers, or arrays of `width` numbers).
function cellReader(column, arrays, first) {
  const data = arrays[column.array];
  const { width } = column;
  const pick = (start) => (width === 1 ? data[start] : Array.from(data.subarray(start, start + width)));
  if (column.layout === 'fixed') {
    const { stride } = column;
    return (i) => pick(stride * (i - first) + column.first);
  }
  const offsets = arrays[column.offsets];
  const base = offsets[0] ?? 0;
  return (i) => {
    const from = offsets[i - first] - base;
    const to = offsets[i - first + 1] - base;
    const items = new Array(to - from);
    for (let k = from; k < to; k += 1) items[k - from] = pick(width * k);
    return items;
  };
}

// descriptor: one entry of meshTableDescriptors(); data: {rows (the table's full row
// count), first (the window's first row), arrays: {name: TypedArray}} as meshTables sends
// it (or the whole table: first = 0). Rows are addressed by their index in the whole table.
export function readTable(descriptor, { rows, first = 0, arrays }) {
  const readers = new Map(descriptor.columns.map((c) => [c.name, cellReader(c, arrays, first)]));
  const lead = descriptor.arrays[0];
  const size = arrays[lead.name].length;
  const count = lead.role === 'offsets' ? Math.max(0, size - 1) : size / lead.stride;
  // A row is named as the lesson's table labels it (F3 for row 2 of a face table).
  const label = (i) => elementLabel(descriptor.rows, i);
  const inWindow = (i) => {
    if (!Number.isInteger(i) || i < first || i >= first + count) {
      const row = Number.isInteger(i) && i >= 0 ? label(i) : `row ${String(i).slice(0, 40)}`;
      const read = count === 0 ? 'none' : count === 1 ? label(first) : `${label(first)} to ${label(first + count - 1)}`;
      throw new WingsplineError('invalid-element', `${row} is not among the rows read (${read}) of the ${descriptor.representation} ${descriptor.name} table`);
    }
    return i;
  };
  const table = {
    descriptor,
    representation: descriptor.representation,
    name: descriptor.name,
    title: descriptor.title,
    kind: descriptor.rows, // 'vertex' | 'edge' | 'face': one row per element of this kind
    columns: descriptor.columns,
    arrays,
    total: rows,
    first,
    count,
    column(name) {
      const c = descriptor.columns.find((x) => x.name === name);
      if (!c) throw new WingsplineError('unknown-column', `the ${descriptor.representation} ${descriptor.name} table has no column '${String(name).slice(0, 40)}'`);
      return c;
    },
    cell(i, name) {
      table.column(name);
      return readers.get(name)(inWindow(i));
    },
    // {columnName: cell} for row i.
    row(i) {
      inWindow(i);
      const out = {};
      for (const [name, read] of readers) out[name] = read(i);
      return out;
    },
    rows() {
      const out = new Array(count);
      for (let k = 0; k < count; k += 1) out[k] = table.row(first + k);
      return out;
    },
  };
  return table;
}

// The descriptor of one table from the list, by representation key and table name.
export function findDescriptor(descriptors, representation, name) {
  const d = descriptors.find((x) => x.representation === representation && x.name === name);
  if (!d) throw new WingsplineError('unknown-table', `no table '${String(name).slice(0, 40)}' in representation '${String(representation).slice(0, 40)}'`);
  return d;
}

// A column's header as text: the group above it and its label ("S:L"), or its label.
export const columnHeading = (column, joiner = ':') => (column.group ? `${column.group}${joiner}${column.label}` : column.label);
