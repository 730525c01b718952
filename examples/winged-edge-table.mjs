// @ts-check
// Homework helper: read an OBJ (or OFF) file, print its winged-edge tables as lecture 000
// writes them (v1.., e1.., F1.., '-' where an edge has no face on that side) and the CCW
// walk around one vertex.
//   node examples/winged-edge-table.mjs [file.obj] [vertex number, 1-based]
//   node examples/winged-edge-table.mjs --slide [vertex number]
// Defaults: examples/lecture-mesh.obj and v2. A file has faces but no edge numbers, so the
// core numbers the edges face by face and they may differ from a slide's; the walk meets the
// same neighbours in the same order. --slide builds the same mesh with lecture 000's own
// numbering (api.lectureExample()): the slide's tables, and the walk e6 e5 e3 e2 around v2.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { loadWingspline } from 'wingspline';

const slide = process.argv[2] === '--slide';
const file = slide ? "lecture 000's slide" : process.argv[2] ?? fileURLToPath(new URL('lecture-mesh.obj', import.meta.url));
const vertex = Number(process.argv[3] ?? 2);
const format = file.toLowerCase().endsWith('.off') ? 'off' : 'obj';

const api = await loadWingspline();
const mesh = api.buildMesh(slide ? api.lectureExample() : api.parseMesh(await readFile(file, 'utf8'), { format }));
try {
  const { vertices, edges, faces } = mesh.wingedEdge();
  /** @type {(i: number) => string} */
  const v = (i) => `v${i + 1}`;
  /** @type {(i: number) => string} */
  const e = (i) => (i < 0 ? '-' : `e${i + 1}`);
  /** @type {(i: number) => string} */
  const f = (i) => (i < 0 ? '-' : `F${i + 1}`);
  /** @type {(cells: Array<string | number>) => string} */
  const row = (cells) => cells.map((c) => String(c).padEnd(5)).join(' ').trimEnd();
  const counts = mesh.counts();
  console.log(`${file}: ${counts.vertices} vertices, ${counts.edges} edges, ${counts.faces} faces`);
  console.log('\nVERTEX TABLE');
  vertices.forEach((r, i) => console.log(row([v(i), r.x, r.y, r.z, e(r.edge)])));
  console.log('\nEDGE TABLE');
  console.log(row(['', 'S', 'E', 'L', 'R', 'S:L', 'S:R', 'E:L', 'E:R']));
  edges.forEach((r, i) => console.log(row([e(i), v(r.start), v(r.end), f(r.left), f(r.right),
    e(r.startLeft), e(r.startRight), e(r.endLeft), e(r.endRight)])));
  console.log('\nFACE TABLE');
  faces.forEach((r, i) => console.log(row([f(i), e(r.edge)])));

  // The walk: at an edge whose Start is v read its S:L wing, otherwise its E:R wing.
  const steps = mesh.traversalSteps(vertex - 1);
  console.log(`\nCCW walk around ${v(vertex - 1)}: ${steps.map((s) => e(s.edge)).join(' ')}`);
  for (const s of steps) {
    const r = edges[s.edge];
    const other = s.role === 'start' ? r.end : r.start;
    console.log(`  ${e(s.edge)} (to ${v(other)}): ${v(vertex - 1)} is its ${s.role === 'start' ? 'Start' : 'End'}, so read ${s.role === 'start' ? 'S:L' : 'E:R'} = ${e(s.next)}`);
  }
} finally {
  mesh.dispose();
}
