// @ts-check
// Exports of the mesh lesson: the winged-edge tables as CSV, Markdown and LaTeX (with the
// slide's two-level header), and the mesh itself as OFF or OBJ, written by the core.
import { toCsv } from '../../app/file-io.js';
import { columnHeading } from '../../core/tables.js';
import { vLabel, eLabel, fLabel } from './labels.js';

// Every cell from the table's descriptor: coordinates as numbers, references as the slide's
// labels (v3, e5, F2; a boundary side stays empty, as on the slide).
const LABEL = { vertex: vLabel, edge: eLabel, face: fLabel };
const NOTES = {
  csv: { edges: ' (S, E: start and end vertex; L, R: left and right face; S:L, S:R, E:L, E:R: the wings)' },
  md: { edges: ' (wings: S:L, S:R at the Start; E:L, E:R at the End)' },
};

function rowsOf(table) {
  const rows = [];
  for (let i = 0; i < table.total; i += 1) {
    const row = table.row(i);
    rows.push([LABEL[table.kind](i), ...table.columns.map((c) => (c.refers ? LABEL[c.refers](row[c.name]) : row[c.name]))]);
  }
  return rows;
}

// The winged edge's three tables (vertices, edges, faces), read through the generic reader.
const wingedTables = (model) => Object.values(model.mesh.tables('winged-edge'));

export function wingedCsv(model) {
  return wingedTables(model).map((t) => `# ${t.title}${NOTES.csv[t.name] ?? ''}\n`
    + toCsv([t.kind, ...t.columns.map((c) => columnHeading(c))], rowsOf(t))).join('\n');
}

const mdRow = (cells) => `| ${cells.map((c) => String(c)).join(' | ')} |`;

export function wingedMarkdown(model) {
  const table = (head, rows) => [mdRow(head), mdRow(head.map(() => '---')), ...rows.map(mdRow)].join('\n');
  return [...wingedTables(model).flatMap((t) => [`**${t.title}**${NOTES.md[t.name] ?? ''}`, '',
    table(['', ...t.columns.map((c) => columnHeading(c))], rowsOf(t)), ''])].join('\n');
}

// v3 -> $v_{3}$; an empty cell stays empty (a boundary side, as on the slide).
const tex = (label) => (label === '' ? '' : typeof label === 'number' ? String(label) : `$${label[0]}_{${label.slice(1)}}$`);

// Runs of columns that the tabular separates with a rule: coordinates, references, and each
// group of the slide's second header line (the wings under S, under E).
function runsOf(columns) {
  const runs = [];
  for (const c of columns) {
    const key = c.group || (c.refers ? 'references' : 'coordinates');
    if (runs.length && runs[runs.length - 1].key === key) runs[runs.length - 1].columns.push(c);
    else runs.push({ key, group: c.group, columns: [c] });
  }
  return runs;
}

function latexTable(t) {
  const lines = (rows) => rows.map((r) => `  ${r.map(tex).join(' & ')} \\\\`).join('\n');
  const runs = runsOf(t.columns);
  const out = [`\\begin{tabular}{c|${runs.map((r) => 'c'.repeat(r.columns.length)).join('|')}}`];
  if (runs.some((r) => r.group)) {
    const spans = runs.map((r, k) => {
      const n = r.columns.length + (k === 0 ? 1 : 0);
      return `\\multicolumn{${n}}{c${k < runs.length - 1 ? '|' : ''}}{${r.group}}`;
    });
    out.push(`  ${spans.join(' & ')} \\\\`);
  }
  const head = t.columns.map((c) => (c.refers ? c.label : `$${c.label}$`));
  out.push(`  & ${head.join(' & ')} \\\\ \\hline`, lines(rowsOf(t)), '\\end{tabular}', '');
  return out;
}

export function wingedLatex(model) {
  return ['% Winged-edge tables (lecture 000 layout), written by Wingspline', ...wingedTables(model).flatMap(latexTable)].join('\n');
}

// The mesh as it is now: the core writes it (an edited mesh's gaps are left out and the
// live elements numbered in order, as compact() would number them).
function meshText(model, ctx, format) {
  return model.mesh.format({ format });
}

export const meshExports = [
  { label: 'Winged-edge tables (CSV)', filename: 'mesh-winged-edge.csv', type: 'text/csv', make: (view, model) => wingedCsv(model) },
  { label: 'Winged-edge tables (Markdown)', filename: 'mesh-winged-edge.md', type: 'text/markdown', make: (view, model) => wingedMarkdown(model) },
  { label: 'Winged-edge tables (LaTeX)', filename: 'mesh-winged-edge.tex', type: 'application/x-tex', make: (view, model) => wingedLatex(model) },
  { label: 'Mesh (OFF)', filename: 'mesh.off', type: 'text/plain', make: (view, model, state, ctx) => meshText(model, ctx, 'off') },
  { label: 'Mesh (OBJ)', filename: 'mesh.obj', type: 'text/plain', make: (view, model, state, ctx) => meshText(model, ctx, 'obj') },
];
