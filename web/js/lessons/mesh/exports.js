// Exports of the mesh lesson: the winged-edge tables as CSV, Markdown and LaTeX (with the
// slide's two-level header), and the mesh itself as OFF or OBJ, written by the core.
import { toCsv } from '../../app/file-io.js';
import { vLabel, eLabel, fLabel } from './labels.js';

const EDGE_HEAD = ['edge', 'S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R'];

function edgeRows(model) {
  const rows = [];
  for (let e = 0; e < model.E; e += 1) {
    const r = model.we.edges.subarray(8 * e, 8 * e + 8);
    rows.push([eLabel(e), vLabel(r[0]), vLabel(r[1]), fLabel(r[2]), fLabel(r[3]), eLabel(r[4]), eLabel(r[5]), eLabel(r[6]), eLabel(r[7])]);
  }
  return rows;
}

function vertexRows(model) {
  const rows = [];
  for (let v = 0; v < model.V; v += 1) rows.push([vLabel(v), model.positions[3 * v], model.positions[3 * v + 1], model.positions[3 * v + 2], eLabel(model.we.vertexEdge[v])]);
  return rows;
}

function faceRows(model) {
  return Array.from(model.we.faceEdge, (e, f) => [fLabel(f), eLabel(e)]);
}

export function wingedCsv(model) {
  return [
    '# VERTEX TABLE\n' + toCsv(['vertex', 'x', 'y', 'z', 'edge'], vertexRows(model)),
    '# EDGE TABLE (S, E: start and end vertex; L, R: left and right face; S:L, S:R, E:L, E:R: the wings)\n' + toCsv(EDGE_HEAD, edgeRows(model)),
    '# FACE TABLE\n' + toCsv(['face', 'edge'], faceRows(model)),
  ].join('\n');
}

const mdRow = (cells) => `| ${cells.map((c) => String(c)).join(' | ')} |`;

export function wingedMarkdown(model) {
  const table = (head, rows) => [mdRow(head), mdRow(head.map(() => '---')), ...rows.map(mdRow)].join('\n');
  return [
    '**VERTEX TABLE**', '', table(['', 'x', 'y', 'z', 'edge'], vertexRows(model)), '',
    '**EDGE TABLE** (wings: S:L, S:R at the Start; E:L, E:R at the End)', '', table(EDGE_HEAD.map((x, i) => (i === 0 ? '' : x)), edgeRows(model)), '',
    '**FACE TABLE**', '', table(['', 'edge'], faceRows(model)), '',
  ].join('\n');
}

// v3 -> $v_{3}$; an empty cell stays empty (a boundary side, as on the slide).
const tex = (label) => (label === '' ? '' : typeof label === 'number' ? String(label) : `$${label[0]}_{${label.slice(1)}}$`);

export function wingedLatex(model) {
  const lines = (rows) => rows.map((r) => `  ${r.map(tex).join(' & ')} \\\\`).join('\n');
  return [
    '% Winged-edge tables (lecture 000 layout), written by Wingspline',
    '\\begin{tabular}{c|ccc|c}', '  & $x$ & $y$ & $z$ & edge \\\\ \\hline', lines(vertexRows(model)), '\\end{tabular}', '',
    '\\begin{tabular}{c|cccc|cc|cc}', '  \\multicolumn{5}{c|}{} & \\multicolumn{2}{c|}{S} & \\multicolumn{2}{c}{E} \\\\',
    '  & S & E & L & R & L & R & L & R \\\\ \\hline', lines(edgeRows(model)), '\\end{tabular}', '',
    '\\begin{tabular}{c|c}', '  & edge \\\\ \\hline', lines(faceRows(model)), '\\end{tabular}', '',
  ].join('\n');
}

function meshText(model, ctx, format) {
  return ctx.api.formatMesh({ positions: model.positions, faces: model.faces }, { format });
}

export const meshExports = [
  { label: 'Winged-edge tables (CSV)', filename: 'mesh-winged-edge.csv', type: 'text/csv', make: (view, model) => wingedCsv(model) },
  { label: 'Winged-edge tables (Markdown)', filename: 'mesh-winged-edge.md', type: 'text/markdown', make: (view, model) => wingedMarkdown(model) },
  { label: 'Winged-edge tables (LaTeX)', filename: 'mesh-winged-edge.tex', type: 'application/x-tex', make: (view, model) => wingedLatex(model) },
  { label: 'Mesh (OFF)', filename: 'mesh.off', type: 'text/plain', make: (view, model, state, ctx) => meshText(model, ctx, 'off') },
  { label: 'Mesh (OBJ)', filename: 'mesh.obj', type: 'text/plain', make: (view, model, state, ctx) => meshText(model, ctx, 'obj') },
];
