// @ts-check
// The representations of one mesh as live tables (lecture 000: independent faces, vertex
// and face tables, adjacency lists, winged edge; lecture 001: pointers to an edge list), the
// queries compared, storage with the lectures' pros and cons, and plane equations. Tables
// are virtual (virtual-table.js): a 100,000-face mesh only builds the rows in view, and the
// adjacency rows ask the core only for those rows.
import { h, revealInBoxes } from '../../app/dom.js';
import { createGrowthPlot, querySeries, storageSeries, COST_FACES } from './growth.js';
import { createVirtualTable, headRows } from '../../ui/virtual-table.js';
import { createStoredEdgeControl } from './stored-edge.js';
import { findDescriptor } from '../../core/tables.js';
import { VERTEX_EDGE_COLUMN, FACE_EDGE_COLUMN } from '../../ui/mesh/walk.js';
import { num, sub, NOTATION, headOf, rowCells, describedTable, createWingedTables } from '../../ui/mesh/tables.js';
import { visibleSteps, rowsNotYetWritten, halfEdgeSteps, EDGE_FIELDS, COORDINATES } from './edit-playback.js';
import { queryTarget, whyNot } from './live-elements.js';
import { createHalfEdgeTab, HALF_EDGE_COLUMNS } from './half-edge.js';

const F = (i) => sub('F', i);
// Representation tables longer than this show their first rows and say so (the winged-edge
// tables, read as typed arrays, are never cut).
export const REPRESENTATION_ROWS = 3000;
const REPRESENTATION_BLOCKS_KEPT = 8;
// Rows of the planes table asked of the core at a time; faces measured per task for the
// largest residual (about 10 ms each here).
const PLANE_BLOCK = 256;
const PLANE_SCAN = 20_000;
const count = (n) => n.toLocaleString('en');

// Lectures 000 (✓/✗ bullets) and 003 (polygon list / vertex list / edge list), quoted.
export const PROS_CONS = {
  'independent-faces': { title: 'Independent faces (polygon list)', pros: ['simplest representation (003)'],
    cons: ['redundant vertices: changing a vertex changes each instance (000)', 'no efficient/precise vertex-adjacency info (000)', 'shared edges are drawn twice (003)'] },
  'vertex-face-tables': { title: 'Vertex and face tables (vertex list)', pros: ['shared vertices: changing a vertex changes a single point (000)', 'compact and moving vertices is easy (003)'],
    cons: ['no efficient adjacency info (000)', 'difficult to find polygons that share an edge (003)'] },
  'adjacency-lists': { title: 'Adjacency lists', pros: ['efficient adjacency info (000)'], cons: ['extra storage (000)', 'variable size arrays (000)'] },
  'partial-adjacency-lists': { title: 'Partial adjacency lists', pros: ['efficient adjacency info (000)'], cons: ['extra storage (000)', 'variable size arrays (000)'] },
  'edge-list': { title: 'Pointers to an edge list (Foley, 001)', pros: ['shared edges are not drawn twice (003)', 'adjacent polygons are readily apparent from the edge records (003)'],
    cons: ['which edges are incident to a vertex is not easy: all edges must be inspected (001)', 'takes up a lot of storage (003)'] },
  'winged-edge': { title: 'Winged edge', pros: ['all adjacencies in O(1) time', 'little extra storage', 'fixed-size records', 'supports polygonal faces'],
    cons: ['mesh needs to be oriented'] },
  // Beyond the lectures: what the libraries a student meets next store (the half-edge tab).
  'half-edge': { title: 'Half-edge (beyond the lectures)', pros: ['all adjacencies in O(1) time, as the winged edge', 'a step never asks which side of an edge it is on: next and prev belong to the face', 'fixed-size records; supports polygonal faces'],
    cons: ['two records per edge', 'mesh needs to be oriented'] },
};

const SHORT_NAMES = {
  'vertex-face-tables': 'vertex and face tables', 'adjacency-lists': 'adjacency lists', 'partial-adjacency-lists': 'partial adjacency lists',
  'edge-list': 'edge list', 'winged-edge': 'winged edge',
};

// pickElement(element): a table row was clicked (the panels highlight it everywhere);
// selection: the lesson view's {hover, pick} (panels.js), read when the marks are drawn.
export function createRepresentationTabs(ctx, labels, { pickElement, selection }) {
  const tabIds = Object.keys(labels);
  const tablist = h('div', { class: 'mesh-tabs', role: 'tablist', 'aria-label': 'Representations' });
  const panels = {};
  const buttons = {};
  for (const id of tabIds) {
    buttons[id] = h('button', { type: 'button', role: 'tab', id: `tab-${id}`, 'aria-controls': `tabpanel-${id}`, 'data-tab': id,
      onclick: () => ctx.commit({ ...ctx.state, tab: id }, { history: false }) }, labels[id]);
    panels[id] = h('div', { role: 'tabpanel', id: `tabpanel-${id}`, 'aria-labelledby': `tab-${id}`, class: 'mesh-tabpanel', hidden: true });
    tablist.append(buttons[id]);
  }
  tablist.addEventListener('keydown', (event) => {
    if (event.key !== 'ArrowRight' && event.key !== 'ArrowLeft') return;
    event.stopPropagation();
    event.preventDefault();
    const i = tabIds.indexOf(ctx.state.tab);
    const next = tabIds[(i + (event.key === 'ArrowRight' ? 1 : -1) + tabIds.length) % tabIds.length];
    ctx.commit({ ...ctx.state, tab: next }, { history: false });
    buttons[next].focus();
  });
  const root = h('section', { class: 'mesh-representations', id: 'tables-panel', 'aria-label': 'Representations' }, tablist, ...Object.values(panels));

  let model = null;
  // Every representation table is drawn from its descriptor (ui/mesh/tables.js). The winged
  // edge's tables are read from the lesson's own copy of its arrays (model.we, never cut); the others are
  // fetched from the core in blocks of REPRESENTATION_ROWS rows (every table of one
  // representation at once) and kept until the mesh changes, so scrolling a 100k-row table
  // fetches only the block in view.
  const wingedTables = createWingedTables(ctx.api);
  const tableAt = (representation, name, i) => {
    // weShown: the tables as the edit player shows them (model.we once the edit is done).
    if (representation === 'winged-edge') return wingedTables(model.weShown, { vertices: model.V, edges: model.E, faces: model.F })[name];
    const block = Math.floor(i / REPRESENTATION_ROWS) * REPRESENTATION_ROWS;
    const key = `${representation}:${block}`;
    model.derived.reps ??= new Map();
    let tablesOfBlock = model.derived.reps.get(key);
    if (!tablesOfBlock) {
      if (model.derived.reps.size >= REPRESENTATION_BLOCKS_KEPT) model.derived.reps.delete(model.derived.reps.keys().next().value);
      tablesOfBlock = model.mesh.tables(representation, { offset: block, limit: REPRESENTATION_ROWS });
      model.derived.reps.set(key, tablesOfBlock);
    }
    return tablesOfBlock[name];
  };
  const hoverRow = (kind) => (index) => { selection.hover = { kind, index }; markElements(); ctx.render(); };
  const leave = () => { selection.hover = null; markElements(); ctx.render(); };
  const pickRow = (kind) => (index) => pickElement({ kind, index });
  const table = (spec) => ({ kind: spec.kind, ...createVirtualTable({ onRowEnter: hoverRow(spec.kind), onRowLeave: leave, onRowClick: pickRow(spec.kind), ...spec }) });
  // A table of the core, shown from its descriptor alone.
  const described = (representation, name, id) => {
    const d = findDescriptor(ctx.api.tableDescriptors, representation, name);
    const letters = NOTATION[representation] ?? NOTATION.default;
    return table({ id, kind: d.rows, ...describedTable(d, letters, (i) => tableAt(representation, name, i)) });
  };

  const tables = {
    // ---------------------------------------------------------- winged edge (lecture 000)
    wingedVertex: described('winged-edge', 'vertices', 'we-vertex-table'),
    wingedEdge: described('winged-edge', 'edges', 'we-edge-table'),
    wingedFace: described('winged-edge', 'faces', 'we-face-table'),
    // ---------------------------------------------------------- independent faces (000)
    // These tables show the core's own arrays of each representation, so a moved vertex
    // shows up in every copy the core had to rewrite.
    independent: described('independent-faces', 'faces', 'independent-face-table'),
    // ---------------------------------------------------------- vertex and face tables (000)
    vfVertex: described('vertex-face-tables', 'vertices', 'vf-vertex-table'),
    vfFace: described('vertex-face-tables', 'faces', 'vf-face-table'),
    // ---------------------------------------------------------- adjacency lists (000)
    adjVertex: described('adjacency-lists', 'vertices', 'adj-vertex-table'),
    adjEdge: described('adjacency-lists', 'edges', 'adj-edge-table'),
    adjFace: described('adjacency-lists', 'faces', 'adj-face-table'),
    partialVertex: described('partial-adjacency-lists', 'vertices', 'partial-vertex-table'),
    partialEdge: described('partial-adjacency-lists', 'edges', 'partial-edge-table'),
    partialFace: described('partial-adjacency-lists', 'faces', 'partial-face-table'),
    // ---------------------------------------------------------- pointers to an edge list (001)
    foleyVertex: described('edge-list', 'vertices', 'foley-vertex-table'),
    foleyEdge: described('edge-list', 'edges', 'foley-edge-table'),
    foleyPolygon: described('edge-list', 'polygons', 'foley-polygon-table'),
    // ---------------------------------------------------------- planes (001, 003)
    planes: table({ id: 'plane-table', kind: 'face', caption: 'Ax + By + Cz + D = 0 per face',
      head: [[{ text: '', colspan: 1 }, { text: 'cross product P₁P₂ × P₁P₃ (001)', colspan: 4 }, { text: 'Newell (003)', colspan: 4 }, { text: '', colspan: 2 }],
        ['', 'A', 'B', 'C', 'D', 'A', 'B', 'C', 'D', 'unit normal (Newell)', 'planarity residual']],
      rowLabel: F, row: (face) => {
        // Read from the core's flat arrays, a block of rows at a time as they come into view
        // (planeArrays({offset, limit}), once per mesh version).
        const { cross, newell, residual, normals: n, at: f } = planeRow(face);
        const four = (a) => [num(a[4 * f]), num(a[4 * f + 1]), num(a[4 * f + 2]), num(a[4 * f + 3])];
        return [...four(cross), ...four(newell), `(${num(n[3 * f], 3)}, ${num(n[3 * f + 1], 3)}, ${num(n[3 * f + 2], 3)})`, num(residual[f], 3)];
      } }),
  };

  // ------------------------------------------------------------ fill the panels
  // The half-edge tab's tables: a half-edge row hovers and picks its edge (both its rows marked).
  const halfEdgeTab = createHalfEdgeTab(ctx, {
    model: () => model, selection,
    table: (spec) => (spec.kind === 'halfedge'
      ? { kind: 'halfedge', ...createVirtualTable({ onRowEnter: (i) => hoverRow('edge')(i >> 1), onRowLeave: leave, onRowClick: (i) => { spec.onPick?.(i); pickRow('edge')(i >> 1); }, ...spec }) }
      : table(spec)),
  });
  Object.assign(tables, { heHalfedge: halfEdgeTab.tables.halfedges, heVertex: halfEdgeTab.tables.vertices, heFace: halfEdgeTab.tables.faces });
  panels['half-edge'].append(halfEdgeTab.root);

  const changeNote = (id) => h('p', { class: 'change-note', id, 'aria-live': 'polite' });
  const notes = { faces: changeNote('change-independent'), vf: changeNote('change-vertex-face'), winged: changeNote('change-winged') };
  const storedEdge = createStoredEdgeControl(ctx);
  panels.winged.append(h('p', { class: 'hint' }, 'Baumgart\'s winged edge as on the slide: S, E (start and end vertex), L, R (left and right face) and the four wings: the left and right edge at the Start, and at the End. Boundary edges have one face; their wings treat the boundary as a face.'),
    notes.winged, storedEdge.root, tables.wingedVertex.root, tables.wingedEdge.root, tables.wingedFace.root);
  panels.faces.append(h('p', { class: 'hint' }, 'Each face lists vertex coordinates (lecture 000): changing a vertex requires changing the coordinates of each instance. Drag a vertex and count.'),
    notes.faces, tables.independent.root);
  panels['vertex-face'].append(h('p', { class: 'hint' }, 'Each face lists vertex references: changing a vertex changes a single point.'), notes.vf, tables.vfVertex.root, tables.vfFace.root);
  panels.adjacency.append(h('p', { class: 'hint' }, 'Lecture 000: store all vertex, edge and face adjacencies (the core\'s own arrays); the partial lists keep only the incidences of neighbouring dimensions.'),
    tables.adjVertex.root, tables.adjEdge.root, tables.adjFace.root,
    h('h3', {}, 'Partial adjacency lists'), tables.partialVertex.root, tables.partialEdge.root, tables.partialFace.root);
  panels['edge-list'].append(h('p', { class: 'hint' }, 'Foley & van Dam: each edge stores its two vertices and the polygons on either side; a polygon is a list of pointers to edges.'),
    tables.foleyVertex.root, tables.foleyEdge.root, tables.foleyPolygon.root);

  const queryPanel = createQueryPanel(ctx, (kind) => growthOf(kind));
  panels.queries.append(queryPanel.root);
  // Storage: one row per representation, through the same table as the others.
  let storageRows = [];
  const perFace = (bytes) => num(bytes / Math.max(1, model.counts.faces), 4);
  const storageTable = createVirtualTable({ id: 'storage-table', className: 'data-table', caption: 'Storage of this mesh in each representation',
    head: [['representation', 'entries', 'bytes', 'bytes per face', 'arrays']], cellClasses: ['', '', '', 'arrays'],
    rowLabel: (i) => PROS_CONS[storageRows[i][0]]?.title ?? storageRows[i][0], rowAttributes: (i) => ({ 'data-representation': storageRows[i][0] }),
    row: (i) => {
      const st = storageRows[i][1];
      return [st.entries.toLocaleString('en'), st.bytes.toLocaleString('en'), perFace(st.bytes), st.arrays.map((a) => `${a.name}: ${a.entries.toLocaleString('en')} × ${a.bytesPerEntry} B`).join('; ')];
    } });
  const storageCounts = h('p', {});
  const repName = (rep) => PROS_CONS[rep]?.title ?? rep;
  const storageGrowth = createGrowthPlot(ctx, { id: 'storage-growth', yLabel: 'bytes',
    caption: 'Storage against mesh size: grids of 4 × 4 to 128 × 128 quads, each split into two triangles (the core\'s figures; log-log axes).', names: repName });
  const storageBody = h('div', { id: 'storage-body' }, storageCounts, storageTable.root, storageGrowth.root,
    ...Object.entries(PROS_CONS).map(([name, r]) => h('div', { class: 'pros-cons', 'data-representation': name }, h('h3', {}, r.title),
      h('ul', {}, r.pros.map((p) => h('li', { class: 'pro' }, h('span', { 'aria-label': 'advantage' }, '✓ '), p)),
        r.cons.map((p) => h('li', { class: 'con' }, h('span', { 'aria-label': 'disadvantage' }, '✗ '), p))))));
  panels.storage.append(storageBody);
  const planeNote = h('p', { class: 'hint', id: 'plane-note' });
  panels.planes.append(h('p', { class: 'hint' }, 'From three vertices: (A, B, C) = P₁P₂ × P₁P₃ and D by substitution (001). Newell (003): A = ½ Σ (zᵢ + zᵢ₊₁)(yᵢ − yᵢ₊₁), B = ½ Σ (xᵢ + xᵢ₊₁)(zᵢ − zᵢ₊₁), C = ½ Σ (yᵢ + yᵢ₊₁)(xᵢ − xᵢ₊₁).'),
    planeNote, tables.planes.root);

  const tabTables = {
    winged: ['wingedVertex', 'wingedEdge', 'wingedFace'], faces: ['independent'], 'vertex-face': ['vfVertex', 'vfFace'],
    adjacency: ['adjVertex', 'adjEdge', 'adjFace', 'partialVertex', 'partialEdge', 'partialFace'], 'edge-list': ['foleyVertex', 'foleyEdge', 'foleyPolygon'], planes: ['planes'],
    'half-edge': ['heHalfedge', 'heVertex', 'heFace'],
  };
  const tableKind = Object.fromEntries(Object.entries(tables).map(([name, t]) => [name, t.kind]));
  const counts = { vertex: () => model.V, edge: () => model.E, face: () => model.F, ...halfEdgeTab.counts };
  const drawnVersion = {};
  const revealed = {}; // table name -> the walk position whose row it last scrolled into view
  const revealedEdit = {}; // table name -> the edit player's position when it last revealed
  const revealedWhat = {}; // table name -> 'edit' or 'walk': which of the two it last revealed
  let pendingReveals = []; // rows to scroll into view at the next frame (markElements)
  let revealFrame = 0;

  // The row the walk reads at this step, with its table's head, right under the walk's
  // narration (panels.js): on a phone the tables are far below the walk's buttons, so the
  // row is shown where the student is looking (web/css/mesh.css shows it on
  // narrow screens only). Built from the same descriptor as the table (headOf, rowCells).
  const walkRow = h('div', { class: 'walk-row', id: 'walk-row', 'aria-live': 'off' });
  let walkRowKey = '';
  function showWalkRow(frame, inEdit) {
    const key = frame && !inEdit ? `${model.topology}:${model.version}:${frame.table}:${frame.row}:${frame.read}:${frame.compared}` : '';
    if (key === walkRowKey) return;
    walkRowKey = key;
    if (!key) { walkRow.replaceChildren(); return; }
    const name = { vertex: 'vertices', edge: 'edges', face: 'faces' }[frame.table];
    const d = findDescriptor(ctx.api.tableDescriptors, 'winged-edge', name);
    const letters = NOTATION.default;
    const cells = rowCells(d, tableAt('winged-edge', name, frame.row).row(frame.row), letters);
    // Column k of the big table is cell k - 1 here (its first cell is the row's label).
    const mark = (k) => (k === frame.read ? 'is-read' : k === frame.compared ? 'is-compared' : null);
    walkRow.replaceChildren(h('table', { class: 'data-table walk-row-table' },
      h('caption', {}, `${d.title}: the row the walk reads`),
      h('thead', {}, headRows(headOf(d))),
      h('tbody', {}, h('tr', { class: 'is-highlighted' }, h('th', { scope: 'row' }, sub(letters[d.rows], frame.row)),
        cells.map((c, k) => h('td', { class: mark(k + 1) }, c))))));
  }

  // Walk marks (current row, the column read) plus the hovered and picked element.
  function markElements({ reveal = false, again = false } = {}) {
    if (!model) return;
    const frame = model.frame;
    const tab = ctx.state.tab;
    showWalkRow(frame, model.lastOperation && model.editStep < model.editSteps);
    // Every table's marks are written first and the rows scrolled into view after, so the
    // layout is read once for all tables, not once per table between their marks.
    const reveals = [];
    // The half-edge tab first: the cell its walk reads at this frame comes from it.
    if (tab === 'half-edge') halfEdgeTab.update(model);
    for (const name of tabTables[tab] ?? []) {
      const kind = tableKind[name];
      const rows = { 'is-hovered': [], 'is-picked': [], 'is-highlighted': [] };
      const read = [];
      const compared = [];
      if (selection.hover?.kind === kind) rows['is-hovered'].push(selection.hover.index);
      if (selection.pick?.kind === kind) rows['is-picked'].push(selection.pick.index);
      // A half-edge table marks both halves of the hovered or picked edge.
      if (kind === 'halfedge' && selection.hover?.kind === 'edge') rows['is-hovered'].push(2 * selection.hover.index, 2 * selection.hover.index + 1);
      if (kind === 'halfedge' && selection.pick?.kind === 'edge') rows['is-picked'].push(2 * selection.pick.index, 2 * selection.pick.index + 1);
      // While the edit player is inside an edit, its cell is the one marked, not the walk's.
      const inEdit = model.lastOperation && model.editStep < model.editSteps;
      // The walk's row in this table, if the frame reads one of its rows.
      let walkRow = null;
      if (frame && tab === 'winged' && !inEdit) {
        const walkTable = frame.table === 'edge' ? 'wingedEdge' : frame.table === 'vertex' ? 'wingedVertex' : 'wingedFace';
        if (walkTable === name) {
          walkRow = frame.row;
          if (frame.read !== null) read.push([frame.row, frame.read]);
          if (frame.compared !== null) compared.push([frame.row, frame.compared]);
        }
      }
      // The same walk in half-edge terms: the half-edge whose prev (or next) it reads.
      const heRead = frame && tab === 'half-edge' && !inEdit && kind === 'halfedge' ? halfEdgeTab.walkMark(model) : null;
      if (heRead) {
        walkRow = heRead.row;
        read.push([heRead.row, heRead.read]);
      }
      if (walkRow !== null) rows['is-highlighted'].push(walkRow);
      const editCell = tab === 'winged' ? markEdit(name, kind, rows, read, inEdit)
        : model.halfEdgePlayback ? markHalfEdgeEdit(name, rows, read, inEdit) : null;
      // A number a removed element left (until compact): its row stays, struck through.
      const gapList = model.gapLists?.[`${kind === 'vertex' ? 'vertices' : kind === 'edge' || kind === 'halfedge' ? 'edges' : 'faces'}`];
      if (gapList?.length) rows['is-gap'] = kind === 'halfedge' ? Array.from(gapList).flatMap((e) => [2 * e, 2 * e + 1]) : Array.from(gapList);
      tables[name].mark({ rows, read, compared });
      // A table with nothing of the walk's or the player's marked forgets what it revealed, so
      // a step back to a row it showed before reveals that row again.
      if (!rows['is-highlighted'].length && !editCell) { delete revealed[name]; delete revealedEdit[name]; }
      if (reveal && selection.pick?.kind === kind) {
        const picked = selection.pick.index; // read now: the reveal runs at the next frame
        reveals.push(() => tables[name].reveal(picked));
      }
      else if ((frame || editCell) && (tab === 'winged' || tab === 'half-edge') && (rows['is-highlighted'].length || editCell)) {
        // The walk's (or the edit player's) row is scrolled into view when it moves, not on
        // every mark (a hover, a re-render): a person who scrolled the table keeps the place.
        // The edit's cell while the edit plays, and once more when the player reaches its last
        // assignment (the line reads "Last assignment: ..."); the walk's row when the walk moves.
        const key = `${model.topology}:${model.version}:${model.walkKind}:${model.walkElement}:${model.stepIndex}:${model.editStep}:${tab}`;
        const editKey = `${model.version}:${model.editStep}`;
        if (revealed[name] !== key) {
          const editMoved = revealedEdit[name] !== editKey;
          revealed[name] = key;
          revealedEdit[name] = editKey;
          // Revealing again after the column changed size shows what was shown before it.
          const toEdit = Boolean(editCell && (inEdit || editMoved || !frame || (tab === 'half-edge' && walkRow === null) || (again && revealedWhat[name] === 'edit')));
          revealedWhat[name] = toEdit ? 'edit' : 'walk';
          const target = toEdit ? editCell : [walkRow ?? frame.row, null];
          reveals.push(() => {
            const row = tables[name].reveal(target[0]);
            // The walk's row (or the edit player's) is also brought into the side column's view
            // (never the page's), so it is on screen at every step (on a projector too); the edit
            // player's buttons sit above the column (panels.js) and do not move with it. The
            // edit's cell itself, not only its row, so a wide table shows its column too.
            const table = row?.closest('table') ?? null;
            const cell = target[1] !== null ? row?.children[target[1]] ?? row : row;
            revealInBoxes(cell, { context: table, inset: table?.tHead?.offsetHeight ?? 0 });
          });
        }
      }
    }
    if (reveals.length) {
      // The rows are scrolled into view at the start of the next frame, when the browser has
      // laid this one out: a row's place is then read without a layout of its own. Read here,
      // right after the marks were written, it forced a layout of the whole page on every
      // walk step and edit (about a third of a lecture-mesh step).
      pendingReveals.push(...reveals);
      if (!revealFrame) {
        revealFrame = requestAnimationFrame(() => {
          revealFrame = 0;
          const runs = pendingReveals;
          pendingReveals = [];
          for (const run of runs) run();
        });
      }
    }
  }

  // The edit player's marks (edit-panel.js) in winged-edge table `name`: the rows written so
  // far and those still to be written, and the current assignment's cell (its row highlighted
  // while the edit plays; at the last step only the cell, beside the walk's row). Returns that
  // cell [row, column] when it is in this table.
  function markEdit(name, kind, rows, read, inEdit) {
    const record = model.lastOperation;
    const steps = visibleSteps(record);
    if (!steps.length) return null;
    const table = { wingedVertex: 'vertex', wingedEdge: 'edge', wingedFace: 'face' }[name];
    rows['is-edited'] = [];
    rows['is-pending'] = rowsNotYetWritten(record, model.editStep)[kind] ?? [];
    for (let i = 0; i < model.editStep; i += 1) if (steps[i].table === table) rows['is-edited'].push(steps[i].row);
    const current = steps[model.editStep - 1];
    if (!current || current.table !== table) return null;
    const cell = [current.row, table === 'edge' ? 1 + EDGE_FIELDS.indexOf(current.field)
      : current.coordinate ? 1 + COORDINATES.indexOf(current.field) : table === 'vertex' ? VERTEX_EDGE_COLUMN : FACE_EDGE_COLUMN];
    if (inEdit) rows['is-highlighted'].push(current.row);
    read.push(cell);
    return cell;
  }

  // The same marks in half-edge table `name` while the player plays the edit's half-edge
  // entries (model.halfEdgePlayback): the rows written so far, the rows of the elements the
  // edit added that no entry has reached yet, and the current entry's cell.
  function markHalfEdgeEdit(name, rows, read, inEdit) {
    const table = { heHalfedge: 'halfedge', heVertex: 'vertex', heFace: 'face' }[name];
    const steps = halfEdgeSteps(model.lastOperation);
    if (!table || !steps.length) return null;
    rows['is-edited'] = [];
    const written = new Set();
    for (let i = 0; i < model.editStep; i += 1) if (steps[i].table === table) { rows['is-edited'].push(steps[i].row); written.add(steps[i].row); }
    const added = model.lastOperation.added ?? {};
    const addedRows = table === 'halfedge' ? Array.from(added.edges ?? []).flatMap((e) => [2 * e, 2 * e + 1]) : Array.from(added[table === 'vertex' ? 'vertices' : 'faces'] ?? []);
    rows['is-pending'] = addedRows.filter((r) => !written.has(r));
    const current = steps[model.editStep - 1];
    if (!current || current.table !== table) return null;
    const cell = [current.row, table === 'halfedge' ? 1 + HALF_EDGE_COLUMNS.indexOf(current.field) : 1];
    if (inEdit) rows['is-highlighted'].push(current.row);
    read.push(cell);
    return cell;
  }

  function describeChange(change) {
    if (!change) return 'Drag a vertex: this line counts the stored entries each representation had to rewrite.';
    const c = change.changed.changedEntries;
    const label = `v${change.vertex + 1}`;
    const others = Object.entries(c).filter(([name]) => name !== 'independent-faces')
      .map(([name, n]) => `${(SHORT_NAMES[name] ?? name)} rewrote ${n}`).join(', ');
    const copies = c['independent-faces'];
    return `Last move of ${label}: independent faces rewrote ${copies} coordinate triple${copies === 1 ? '' : 's'} (one per face at ${label}); ${others}.`;
  }

  // Entries and bytes of each representation, counted by the core from its real arrays,
  // next to the lectures' pros and cons.
  // The series against mesh size, once per page: storage, and each query kind's.
  const growth = new Map();
  const growthOf = (kind) => {
    if (!growth.has(kind)) growth.set(kind, kind ? querySeries(ctx.api, kind) : storageSeries(ctx.api));
    return growth.get(kind);
  };
  function updateStorage() {
    storageGrowth.update(growthOf(null));
    const c = model.counts;
    // Once per mesh version; the half-edge's from its own view of the same mesh.
    if (!model.derived.storage) model.derived.storage = { ...model.mesh.storage(), 'half-edge': model.mesh.halfEdgeStorage() };
    storageRows = Object.entries(model.derived.storage);
    storageCounts.textContent = `V = ${c.vertices}, E = ${c.edges}, F = ${c.faces}; boundary edges ${c.boundaryEdges}, boundary loops ${c.boundaryLoops}; Euler characteristic V − E + F = ${c.euler}.`;
    storageTable.refresh(storageRows.length);
  }


  // The planes of the faces in blocks of PLANE_BLOCK rows, each asked of the core when a row
  // of it is first shown, once per mesh version (lesson.js resets derived.planes): showing
  // the tab costs the rows in view, not a pass over every face (0.6 s at a million faces).
  function planeRow(f) {
    const planes = model.derived.planes;
    const b = Math.floor(f / PLANE_BLOCK);
    if (!planes.blocks.has(b)) planes.blocks.set(b, model.mesh.planeArrays({ offset: b * PLANE_BLOCK, limit: Math.min(PLANE_BLOCK, model.F - b * PLANE_BLOCK) }));
    return { ...planes.blocks.get(b), at: f - b * PLANE_BLOCK };
  }

  // The largest residual, a whole-mesh figure: measured in pieces of PLANE_SCAN faces, one
  // task each, after the tab is shown (the note says how far it has got); a new mesh version
  // stops the scan of the old one.
  function scanPlanes(planes) {
    const piece = () => {
      if (model.derived.planes !== planes || planes.scanned >= model.F) return;
      const limit = Math.min(PLANE_SCAN, model.F - planes.scanned);
      for (const r of model.mesh.planeArrays({ offset: planes.scanned, limit }).residual) planes.worst = Math.max(planes.worst, r);
      planes.scanned += limit;
      showPlaneNote();
      if (planes.scanned < model.F) setTimeout(piece, 0);
    };
    piece();
  }

  function showPlaneNote() {
    const { worst, scanned } = model.derived.planes;
    const so = scanned < model.F ? `so far ${num(worst, 3)}, measured over ${count(scanned)} of ${count(model.F)} faces` : num(worst, 3);
    planeNote.textContent = model.is3dMesh
      ? `Largest planarity residual: ${so} (0 for planar faces). The cross product uses only the first three vertices; Newell averages over all of them.`
      : 'This mesh lies in the plane z = 0, so every normal is ±(0, 0, 1): choose the tetrahedron, cube or sphere, or drag in the 3D view, to see real planes.';
  }

  function ensurePlanes() {
    if (!model.derived.planes) {
      model.derived.planes = { blocks: new Map(), worst: 0, scanned: 0 };
      if (model.is3dMesh) scanPlanes(model.derived.planes);
    }
    showPlaneNote();
  }

  return {
    root,
    walkRow,
    markElements,
    // The column's size changed (the page laid out, presentation mode, a window resize,
    // a longer narration): the walk's row is brought into view again.
    revealAgain() {
      for (const name of Object.keys(revealed)) delete revealed[name];
      markElements({ again: true });
    },
    update(next, state) {
      model = next;
      for (const id of tabIds) {
        const on = state.tab === id;
        buttons[id].setAttribute('aria-selected', String(on));
        buttons[id].tabIndex = on ? 0 : -1;
        panels[id].hidden = !on;
      }
      const dataKey = `${model.topology}:${model.version}:${model.editStep}`;
      for (const name of tabTables[state.tab] ?? []) {
        if (name === 'planes') ensurePlanes();
        if (drawnVersion[name] !== dataKey) {
          drawnVersion[name] = dataKey;
          tables[name].refresh(counts[tableKind[name]]());
        }
      }
      const change = describeChange(model.lastChange);
      for (const note of Object.values(notes)) note.textContent = change;
      if (state.tab === 'winged') storedEdge.update(model);
      if (state.tab === 'storage') updateStorage();
      if (state.tab === 'queries') queryPanel.update(model, state);
      markElements();
    },
  };
}

// "Faces around v", "edges of F", "faces sharing e" (and two more): every representation
// answers the same query in the core, which counts the table entries it read, so the
// lecture's cost argument (O(output) for the winged edge, a scan for the face tables) is
// visible as numbers.
const QUERY_LABELS = {
  'faces-around-vertex': ['faces around v', 'vertex', 'F'], 'edges-around-vertex': ['edges around v', 'vertex', 'e'],
  'edges-of-face': ['edges of F', 'face', 'e'], 'neighbours-of-face': ['faces next to F', 'face', 'F'], 'faces-of-edge': ['faces sharing e', 'edge', 'F'],
};
const LETTER = { vertex: 'v', face: 'F', edge: 'e' };

function createQueryPanel(ctx, growthOf) {
  const kind = h('select', { id: 'query-kind', 'aria-label': 'Query' }, Object.entries(QUERY_LABELS).map(([id, [label]]) => h('option', { value: id }, label)));
  const element = h('input', { type: 'number', id: 'query-element', min: 1, step: 1, 'aria-label': 'Element number (1-based)' });
  const prefix = h('span', { 'aria-hidden': 'true' }, 'v');
  const result = h('div', { id: 'query-result', 'aria-live': 'polite' });
  const limitOf = (model, f) => ({ vertex: model.V, face: model.F, edge: model.E }[f]);
  kind.addEventListener('change', () => ctx.commit({ ...ctx.state, query: { ...ctx.state.query, kind: kind.value } }, { history: false }));
  element.addEventListener('change', () => {
    const f = QUERY_LABELS[ctx.state.query.kind][1];
    const limit = limitOf(ctx.model, f);
    const n = Number(element.value) - 1;
    if (!Number.isInteger(n) || n < 0 || n >= limit) {
      ctx.message.error(`Choose ${LETTER[f]}1 to ${LETTER[f]}${limit}`, 'invalid-element');
      return;
    }
    ctx.commit({ ...ctx.state, query: { ...ctx.state.query, [f]: n } }, { history: false });
  });
  // One row per representation, through the same table as every other tab's.
  let answerRows = [];
  let answerLetter = 'F';
  const label = (i) => (i >= 0 ? `${answerLetter}${i + 1}` : 'none');
  const text = (answer) => (answer.length ? Array.from(answer, label).join(', ') : '—');
  const table = createVirtualTable({ id: 'query-table', className: 'data-table', caption: '', head: [['representation', 'answer', 'table entries read']],
    cellClasses: ['', 'entries-read'], rowLabel: (i) => PROS_CONS[answerRows[i][0]]?.title ?? answerRows[i][0],
    rowAttributes: (i) => ({ 'data-representation': answerRows[i][0] }),
    row: (i) => { const r = answerRows[i][1]; return [text(r.answer), r.entriesRead.toLocaleString('en')]; } });
  const cheapestNote = h('p', { class: 'hint' });
  // Where this (small) mesh makes the winged edge look dear: said with the core's numbers.
  const smallNote = h('p', { class: 'hint', id: 'query-small-note' });
  const queryGrowth = createGrowthPlot(ctx, { id: 'query-growth', yLabel: 'entries read', faces: COST_FACES,
    caption: 'The same query against mesh size: the middle element of grids of 22 × 22 to 708 × 708 quads, each split into two triangles, about a thousand to a million faces (the core\'s counts; log-log axes). A line that stays flat reads in proportion to the answer; a rising one scans the mesh.',
    names: (rep) => PROS_CONS[rep]?.title ?? rep });
  result.append(table.root, cheapestNote, smallNote, queryGrowth.root);
  const removedNote = h('p', { class: 'hint', id: 'query-removed', 'aria-live': 'polite', hidden: true });
  const root = h('div', { class: 'query-panel' },
    h('div', { class: 'query-choice' }, h('label', {}, 'Query ', kind), ' ', prefix, element), removedNote, result);

  return {
    root,
    update(model, state) {
      const q = state.query.kind;
      const [, f, letter] = QUERY_LABELS[q];
      const target = queryTarget(model, state.query, f);
      const index = target.index;
      kind.value = q;
      prefix.textContent = LETTER[f];
      element.value = index + 1;
      element.max = limitOf(model, f);
      // A number an edit removed: nothing to ask, and said.
      removedNote.hidden = !target.removed;
      result.hidden = target.removed;
      if (target.removed) {
        removedNote.textContent = `${whyNot(model, target)}: choose another ${f}.`;
        return;
      }
      const key = `${model.topology}:${q}:${index}`;
      if (model.derived.queryKey !== key) {
        model.derived.queryKey = key;
        model.derived.query = { ...model.mesh.query(q, index), 'half-edge': model.mesh.halfEdgeQuery(q, index) };
      }
      const answers = model.derived.query;
      answerLetter = letter;
      answerRows = Object.entries(answers);
      table.setCaption(`${QUERY_LABELS[q][0]} ${LETTER[f]}${index + 1}: each representation answers`);
      table.refresh(answerRows.length);
      const cheapest = Math.min(...Object.values(answers).map((r) => r.entriesRead));
      cheapestNote.textContent = `Fewest entries read: ${cheapest.toLocaleString('en')}. The winged edge reads only the records along the answer (cost proportional to the output); a representation without adjacency has to scan its face table (cost proportional to the mesh).`;
      const winged = answers['winged-edge']?.entriesRead;
      const cheaper = Object.entries(answers).filter(([rep, r]) => rep !== 'winged-edge' && r.entriesRead < winged);
      smallNote.hidden = !cheaper.length;
      if (cheaper.length) {
        const list = cheaper.map(([rep, r]) => `${PROS_CONS[rep]?.title ?? rep} ${r.entriesRead.toLocaleString('en')}`).join(', ');
        smallNote.textContent = `On this mesh the winged edge reads ${winged.toLocaleString('en')} entries and ${list}: its walk reads a whole edge record (S, E, the wings) for every step, while a table this small is cheap to scan. The plot below shows the same query on growing meshes, where the scan grows with the mesh and the walk does not.`;
      }
      queryGrowth.update(growthOf(q));
    },
  };
}
