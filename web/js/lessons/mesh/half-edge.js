// @ts-check
// The half-edge tab: the structure OpenMesh, pmp-library, CGAL and geometry-central store,
// read from the core's half-edge view of the same mesh (docs/api-mesh.md, "The half-edge
// view"), and beside it the correspondence with the winged edge the lecture teaches: for one
// edge, its winged-edge row and its two half-edge rows, each winged-edge field named as the
// half-edge expression that gives it. Every number is the core's; this file only names them.
//
// Numbering, as the API states it from 0 and the page shows it from 1: edge eₖ gives the
// half-edges h₂ₖ₋₁ = S → E (on its left face L) and h₂ₖ = E → S (on R); twin(h) is the
// other of the pair (API: edge e gives 2e and 2e + 1, twin(h) = h ^ 1).
import { h } from '../../app/dom.js';
import { sub } from '../../ui/mesh/tables.js';
import { EDGE_FIELDS, halfEdgeUnmade } from './edit-playback.js';

// Rows of the half-edge view asked of the core per block, once per mesh version (lesson.js
// resets derived.halfEdge with the topology), a few blocks kept: a million faces never
// crosses the boundary whole.
const BLOCK = 3000;
const BLOCKS_KEPT = 8;

// The winged-edge fields as half-edge expressions of h = the edge's S → E half-edge and its
// twin t = E → S (the lecture's wing X:Y is the other edge at vertex X of the face on side Y).
//   field: [expression shown, which half-edge, which array, 'vertex' | 'face' | 'edge' of it]
export const CORRESPONDENCE = Object.freeze({
  start: ['origin(h)', 'h', 'origin', 'vertex'],
  end: ['origin(twin(h)) = target(h)', 't', 'origin', 'vertex'],
  left: ['face(h)', 'h', 'face', 'face'],
  right: ['face(twin(h))', 't', 'face', 'face'],
  startLeft: ['edge of prev(h)', 'h', 'prev', 'edge'],
  startRight: ['edge of next(twin(h))', 't', 'next', 'edge'],
  endLeft: ['edge of next(h)', 'h', 'next', 'edge'],
  endRight: ['edge of prev(twin(h))', 't', 'prev', 'edge'],
});
// The half-edge table's columns after its row header (target and twin are read, never stored).
export const HALF_EDGE_COLUMNS = Object.freeze(['origin', 'target', 'face', 'next', 'prev', 'twin']);
const HEADINGS = { start: 'S', end: 'E', left: 'L', right: 'R', startLeft: 'S:L', startRight: 'S:R', endLeft: 'E:L', endRight: 'E:R' };

const H = (i) => (i >= 0 ? sub('h', i) : '—');
const V = (i) => (i >= 0 ? sub('v', i) : '—');
const F = (i) => (i >= 0 ? sub('F', i) : '—');
const E = (i) => (i >= 0 ? sub('e', i) : '—');
const LABEL = { vertex: V, face: F, edge: E };
// A table wider than a phone's side column scrolls sideways in its own box (focusable, so
// the keyboard scrolls it too).
const scrolling = (table, label) => h('div', { class: 'he-scroll', tabindex: 0, role: 'region', 'aria-label': label }, table);

/**
 * @param {any} ctx
 * @param {{ table: (spec: any) => any, model: () => any, selection: any }} parts
 *   table: the tab's table maker (hover and pick wired), model: the lesson's model now.
 */
export function createHalfEdgeTab(ctx, { table, model, selection }) {
  // Rows i .. of the three tables (half-edges, vertices, faces) share one block per offset.
  const blockAt = (i) => {
    const m = model();
    const start = Math.floor(i / BLOCK) * BLOCK;
    m.derived.halfEdge ??= new Map();
    let block = m.derived.halfEdge.get(start);
    if (!block) {
      if (m.derived.halfEdge.size >= BLOCKS_KEPT) m.derived.halfEdge.delete(m.derived.halfEdge.keys().next().value);
      block = m.mesh.halfEdgeArrays({ offset: start, limit: BLOCK });
      m.derived.halfEdge.set(start, block);
    }
    return { block, k: i - start };
  };
  // While the edit player plays the edit's half-edge entries, the cells it has not reached
  // show what they held before the edit (the core's rows are the view after it): made once per
  // player step, O(the edit).
  let unmade = { record: null, at: -1, values: new Map() };
  const shown = (table, row, field, value) => {
    const m = model();
    if (!m.halfEdgePlayback || m.editStep >= m.editSteps) return value;
    if (unmade.record !== m.lastOperation || unmade.at !== m.editStep) unmade = { record: m.lastOperation, at: m.editStep, values: halfEdgeUnmade(m.lastOperation, m.editStep) };
    return unmade.values.get(`${table}:${row}:${field}`) ?? value;
  };
  // One half-edge's fields from the core (its twin is in the same block: blocks start even).
  const halfEdge = (i) => {
    const { block, k } = blockAt(i);
    const at = (x, field) => shown('halfedge', x, field, block[field][k + x - i]);
    const origin = at(i, 'origin');
    const gap = origin < 0;
    return { origin, target: at(i ^ 1, 'origin'), face: at(i, 'face'), next: at(i, 'next'), prev: at(i, 'prev'), twin: gap ? -1 : i ^ 1, gap };
  };

  const tables = {
    halfedges: table({ id: 'he-halfedge-table', kind: 'halfedge', onPick: (i) => { pickedHalf = i; }, caption: 'Half-edges: eₖ gives h₂ₖ₋₁ = S → E and h₂ₖ = E → S',
      head: [['', ...HALF_EDGE_COLUMNS]],
      rowLabel: (i) => sub('h', i),
      row: (i) => {
        // A gap is -1 (—) in every field; while an edit plays, each field as it is assigned.
        const r = halfEdge(i);
        return [V(r.origin), V(r.target), F(r.face), H(r.next), H(r.prev), H(r.twin)];
      } }),
    vertices: table({ id: 'he-vertex-table', kind: 'vertex', caption: 'Vertices: one outgoing half-edge each',
      head: [['', 'half-edge']], rowLabel: (i) => sub('v', i), row: (i) => { const { block, k } = blockAt(i); return [H(shown('vertex', i, 'halfedge', block.vertexHalfedge[k]))]; } }),
    faces: table({ id: 'he-face-table', kind: 'face', caption: 'Faces: one of their half-edges each',
      head: [['', 'half-edge']], rowLabel: (i) => sub('F', i), row: (i) => { const { block, k } = blockAt(i); return [H(shown('face', i, 'halfedge', block.faceHalfedge[k]))]; } }),
  };

  // The half-edge row picked last (its edge is the lesson's pick): the correspondence names
  // the winged-edge fields that half-edge replaces. -1: an edge was picked, not a half.
  let pickedHalf = -1;

  // The correspondence: which edge it shows, and its rows.
  const heading = h('h3', { id: 'he-correspondence-title' });
  const note = h('p', { class: 'hint', id: 'he-correspondence-note' });
  const body = h('tbody', {});
  const correspondence = h('table', { class: 'data-table', id: 'he-correspondence', 'aria-labelledby': 'he-correspondence-title' },
    h('thead', {}, h('tr', {}, ['winged edge', 'stored', 'as a half-edge expression', 'its value'].map((t) => h('th', { scope: 'col' }, t)))), body);
  const edgeShown = (m) => {
    if (selection.pick?.kind === 'edge') return selection.pick.index;
    if (selection.pick?.kind === 'halfedge') return selection.pick.index >> 1;
    if (m.frame?.table === 'edge') return m.frame.row;
    return 0;
  };
  function updateCorrespondence(m) {
    if (!m.E) { heading.textContent = 'No edge to compare'; body.replaceChildren(); note.textContent = ''; return; }
    const e = Math.min(edgeShown(m), m.E - 1);
    const he = { h: halfEdge(2 * e), t: halfEdge(2 * e + 1) };
    heading.replaceChildren('Edge ', ...E(e), ' in both structures: h = ', ...H(2 * e), ', t = twin(h) = ', ...H(2 * e + 1));
    if (he.h.gap) {
      note.textContent = 'This edge was removed by an edit: its number stays a gap in both structures until the mesh is compacted.';
      body.replaceChildren();
      return;
    }
    // A half-edge row picked (of this edge): the four fields it stands for, its own or its twin's.
    const half = pickedHalf >> 1 === e && selection.pick?.kind === 'edge' && selection.pick.index === e ? (pickedHalf & 1 ? 't' : 'h') : null;
    const replaced = half ? EDGE_FIELDS.filter((field) => CORRESPONDENCE[field][1] === half) : [];
    if (half) {
      const he = 2 * e + (half === 't' ? 1 : 0);
      note.replaceChildren(...H(he), half === 'h' ? ' (S → E, on the left face)' : ' (E → S, on the right face)', ' replaces the winged-edge fields ',
        replaced.map((f) => HEADINGS[f]).join(', '), ': its origin, its face, and the edges of prev and next; the other four are its twin\'s.');
    } else {
      note.textContent = 'Pick an edge (or a half-edge row) to compare another. The wing X:Y is the other edge at vertex X of the face on side Y; in half-edge terms it is the edge of the half-edge before or after h (or its twin) around that face.';
    }
    const we = m.weShown ?? m.we;
    body.replaceChildren(...EDGE_FIELDS.map((field, k) => {
      const [expression, which, array, kind] = CORRESPONDENCE[field];
      const read = he[which][array];
      const value = kind === 'edge' ? (read >= 0 ? read >> 1 : -1) : read;
      const stored = we.edges[8 * e + k];
      const label = LABEL[kind];
      const via = kind === 'edge' ? [' (', ...H(read), ')'] : [];
      const classes = [stored === value ? '' : 'is-mismatch', replaced.includes(field) ? 'is-highlighted' : ''].filter(Boolean).join(' ');
      return h('tr', { 'data-field': field, class: classes || undefined },
        h('th', { scope: 'row' }, HEADINGS[field]), h('td', {}, label(stored)),
        h('td', {}, expression), h('td', {}, label(value), ...via));
    }));
  }

  // The walk of the walk panel, in half-edge terms, from the same first edge: around v,
  // h -> twin(prev(h)) (counter-clockwise, as the winged-edge walk); along F, h -> next(h).
  // Beside each step, the edge the winged-edge walk met at that step: the same ring both ways.
  // It plays with the walk panel's player: frame 0 is the start, frame k (1..n) the k-th
  // edge met, frame n + 1 the end; the row, the line of the pseudocode and the cell read
  // (halfEdgeWalkMark, marked by tabs.js in the half-edge table) follow the frame.
  const walkTitle = h('h3', { id: 'he-walk-title' });
  const walkNote = h('p', { class: 'hint', id: 'he-walk-note' });
  const walkCode = h('ol', { class: 'pseudocode', id: 'he-walk-code', 'aria-label': 'The half-edge walk\'s pseudocode' });
  const walkNow = h('p', { class: 'walk-text', id: 'he-walk-now', 'aria-live': 'polite' });
  const walkBody = h('tbody', {});
  const walkTable = h('table', { class: 'data-table', id: 'he-walk', 'aria-labelledby': 'he-walk-title' },
    h('thead', {}, h('tr', {}, ['step', 'half-edge h', 'reads', 'next half-edge', 'its edge', 'winged-edge walk'].map((t) => h('th', { scope: 'col' }, t)))), walkBody);
  let walkKey = '';
  /** @type {{ steps: any[], vertexWalk: boolean } | null} */
  let walk = null;
  function updateWalk(m) {
    const order = m.frames?.[0]?.order ?? [];
    const key = `${m.topology}:${m.walkKind}:${m.walkElement}:${order[0] ?? -1}`;
    if (key !== walkKey) {
      walkKey = key;
      walk = buildWalk(m, order);
    }
    showWalkFrame(m);
  }
  function buildWalk(m, order) {
    const vertexWalk = m.walkKind === 'vertex';
    const element = m.walkElement;
    if (element < 0 || !order.length) {
      walkTitle.textContent = 'The walk in half-edge terms';
      walkNote.textContent = 'Choose a vertex or a face in the walk panel: its walk is shown here in half-edge terms.';
      walkBody.replaceChildren();
      walkCode.replaceChildren();
      return null;
    }
    const we = m.we;
    // The half-edge of the winged walk's first edge that leaves v (around a vertex) or lies on F.
    const first = order[0];
    const steps = vertexWalk
      ? m.mesh.halfEdgeTraversalSteps(element, { start: we.edges[8 * first] === element ? 2 * first : 2 * first + 1 })
      : m.mesh.halfEdgeFaceSteps(element);
    walkTitle.replaceChildren(vertexWalk ? 'Around ' : 'Along ', ...(vertexWalk ? V(element) : F(element)),
      vertexWalk ? ' in half-edge terms: h → twin(prev(h)), counter-clockwise' : ' in half-edge terms: h → next(h)');
    const same = steps.length === order.length && steps.every((st, k) => st.halfedge >> 1 === order[k]);
    walkNote.textContent = `${steps.length} steps, one read each (${vertexWalk ? 'prev' : 'next'}; the twin is the other half of the same edge, found without a read)${same ? ': the same edges in the same order as the winged-edge walk.' : '. The face walk starts from the face\'s own half-edge, so it may meet the same edges from another first one.'}${vertexWalk ? ' next(twin(h)) turns the other way: clockwise.' : ''}`;
    // A label's nodes are placed once: a fresh one for every place it is shown.
    const name = () => (vertexWalk ? V(element) : F(element));
    walkCode.replaceChildren(...(vertexWalk
      ? [['Initialize: h₀ ← the half-edge of e₀ that leaves ', ...name(), ' (origin(h) = ', ...name(), ')'], ['Repeat: report edge(h)'],
        ['  h ← twin(prev(h))  (one read: prev; twin(h) is h\'s pair)'], ['While: h ≠ h₀'], ['Done: all edges around ', ...name(), ', CCW']]
      : [['Initialize: h₀ ← halfedge(', ...name(), ')  (one read: the face table)'], ['Repeat: report edge(h)'],
        ['  h ← next(h)  (one read: next)'], ['While: h ≠ h₀'], ['Done: all edges of ', ...name(), ', CCW']]
    ).map((parts, k) => h('li', { 'data-line': String(k) }, ...parts)));
    walkBody.replaceChildren(...steps.map((st, k) => h('tr', { 'data-step': String(k + 1), class: (st.halfedge >> 1) === order[k] ? undefined : 'is-mismatch' },
      h('th', { scope: 'row' }, String(k + 1)), h('td', {}, ...H(st.halfedge)),
      h('td', {}, `${st.column}(`, ...H(st.halfedge), ') = ', ...H(st.read)),
      h('td', {}, ...[H(st.next)].flat(), vertexWalk ? [' = twin(', ...H(st.read), ')'] : []),
      h('td', {}, ...E(st.halfedge >> 1)), h('td', {}, ...[E(order[k] ?? -1)].flat()))));
    return { steps, vertexWalk };
  }
  // Which step frame m.frame is (0 the start, 1..n the edges, n + 1 the end).
  const stepOf = (m) => (m.frame ? (m.frame.done ? m.frame.order.length + 1 : m.frame.foundCount) : -1);
  function showWalkFrame(m) {
    if (!walk) { walkNow.textContent = ''; return; }
    const k = stepOf(m);
    const n = walk.steps.length;
    const line = k <= 0 ? 0 : k > n ? 4 : 2;
    for (const li of walkCode.children) li.classList.toggle('is-current', li.getAttribute('data-line') === String(line) || (line === 2 && li.getAttribute('data-line') === '1'));
    for (const tr of walkBody.rows) {
      const here = tr.getAttribute('data-step') === String(k);
      tr.classList.toggle('is-highlighted', here);
      if (here) tr.setAttribute('aria-current', 'step'); else tr.removeAttribute('aria-current');
    }
    // Reads so far: the start's one, then one per step (the winged edge reads two per step:
    // the S (or L) test and the wing).
    const reads = 1 + Math.min(Math.max(k, 0), n);
    const wingedReads = 1 + 2 * Math.min(Math.max(k, 0), n);
    const st = walk.steps[k - 1];
    const what = k <= 0 ? ['Start at ', ...H(walk.steps[0]?.halfedge ?? -1), '.']
      : k > n ? [`Back at `, ...H(walk.steps[0].halfedge), ` = h₀: ${n} edges met.`]
        : ['Step ', String(k), ': report ', ...E(st.halfedge >> 1), '; read ', `${st.column}(`, ...H(st.halfedge), ') = ', ...H(st.read),
          ...(walk.vertexWalk ? ['; its twin is ', ...H(st.next)] : []), '.'];
    walkNow.replaceChildren(...what, ` Reads so far: ${reads} here, ${wingedReads} in the winged-edge walk.`);
  }

  // The cell the walk reads at this frame, for tabs.js to mark in the half-edge table
  // (columns: 1 origin, 2 target, 3 face, 4 next, 5 prev, 6 twin), or null.
  function walkMark(m) {
    const k = stepOf(m);
    const st = walk?.steps[k - 1];
    if (!st) return null;
    return { row: st.halfedge, read: st.column === 'prev' ? 5 : 4 };
  }

  const root = h('div', { class: 'half-edge-tab' },
    h('p', { class: 'hint' }, 'The half-edge structure (OpenMesh, pmp-library, CGAL, geometry-central; beyond the lectures), from the same mesh: each edge is two directed half-edges, one per side. A half-edge stores its origin vertex, its face (none on the boundary), the next and the previous half-edge around that face; its twin is the other half of its edge. A boundary half-edge\'s next and prev follow the boundary loop; a vertex stores one outgoing half-edge (on the boundary, the boundary one), a face one of its half-edges.'),
    heading, note, scrolling(correspondence, 'The correspondence table'), walkTitle, walkNote, walkCode, walkNow, scrolling(walkTable, 'The walk in half-edge terms'), tables.halfedges.root, tables.vertices.root, tables.faces.root);

  return {
    root,
    tables,
    counts: { halfedge: () => 2 * model().E },
    walkMark,
    update(m) { updateCorrespondence(m); updateWalk(m); },
  };
}
