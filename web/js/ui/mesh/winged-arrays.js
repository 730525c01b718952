// @ts-check
// The winged-edge tables as flat arrays (mesh.wingedEdgeArrays(): positions, vertexEdge,
// edges, faceEdge, edgeFields), kept in step with the mesh after an edit by reading again only
// the rows its change record names: the rows it rewrote, the elements it added and removed
// and the vertices it moved. Copying the whole tables after every edit cost about 0.6 s on a
// million faces; an edit touches a handful of rows (docs/benchmarks.md, "ui_edit").
// Offers: followEdit(we, mesh, record) -> the arrays after the edit (the same arrays written
//   in place when the added rows fit, otherwise new ones with room to grow), or after an undo
//   (mesh.undo()'s record: the rows it wrote back, the tables cut to where they ended);
//   followPositions(positions, mesh, record) -> the positions alone, the same way;
//   followRows(table, stride, n, touched, rowOf) -> any per-row table the same way (the
//   projected positions); followFaces(csr, mesh, we, record) -> the faces as CSR;
//   recordEdges(record) -> the edges a record names.
// Needs: the mesh (tables('winged-edge', {offset, limit}) reads rows through views of the
//   core's own arrays) and its change record (mesh.apply: rows, added, removed, positions).

/** @typedef {{ positions: Float64Array, vertexEdge: Int32Array, edges: Int32Array, faceEdge: Int32Array }} Room */
/** @typedef {{ positions: Float64Array, vertexEdge: Int32Array, edges: Int32Array, faceEdge: Int32Array, edgeFields: string[], room?: Room }} WingedArrays */

// How many rows table `list` ('vertices', 'edges', 'faces') has after a change, from `n`
// before it: an edit's new elements are rows at the end; an undo's removed ones were the
// last rows (the table ends where it ended before the edit it took back).
function rowsAfter(n, record, list) {
  const removed = Array.from(record.removed[list]);
  if (record.op === 'undo') return removed.length ? Math.min(...removed) : n;
  return Math.max(n, ...Array.from(record.added[list], (i) => i + 1));
}

// A view of `n` entries of `buffer`, or a new buffer twice as big with the old entries when it
// has no room (amortised: appending a row costs O(1)).
function sized(buffer, n, used) {
  if (n <= buffer.length) return buffer;
  const bigger = new /** @type {any} */ (buffer.constructor)(Math.max(n, 2 * buffer.length, 64));
  bigger.set(buffer.subarray(0, used));
  return bigger;
}

/**
 * @param {WingedArrays} we the arrays before the edit (as wingedEdgeArrays gave them, or as
 *   this function returned them)
 * @param {any} mesh the mesh after the edit
 * @param {{ op: string, rows: { table: string, row: number }[], added: { vertices: ArrayLike<number>, edges: ArrayLike<number>, faces: ArrayLike<number> },
 *   removed: { vertices: ArrayLike<number>, edges: ArrayLike<number>, faces: ArrayLike<number> }, positions: { vertex: number }[] }} record
 * @returns {WingedArrays}
 */
export function followEdit(we, mesh, record) {
  const rows = { vertex: new Set(), edge: new Set(), face: new Set() };
  for (const r of record.rows) rows[r.table]?.add(r.row);
  for (const [kind, list] of [['vertex', 'vertices'], ['edge', 'edges'], ['face', 'faces']]) {
    for (const i of record.added[list]) rows[kind].add(i);
    for (const i of record.removed[list]) rows[kind].add(i);
  }
  for (const p of record.positions) rows.vertex.add(p.vertex);
  const V = rowsAfter(we.vertexEdge.length, record, 'vertices');
  const E = rowsAfter(we.edges.length / 8, record, 'edges');
  const F = rowsAfter(we.faceEdge.length, record, 'faces');
  // Each array's room (a property the spread of `we` does not copy): the typed arrays the
  // views are cut from.
  const room = we.room ?? { positions: we.positions, vertexEdge: we.vertexEdge, edges: we.edges, faceEdge: we.faceEdge };
  const grown = {
    positions: sized(room.positions, 3 * V, we.positions.length),
    vertexEdge: sized(room.vertexEdge, V, we.vertexEdge.length),
    edges: sized(room.edges, 8 * E, we.edges.length),
    faceEdge: sized(room.faceEdge, F, we.faceEdge.length),
  };
  const out = {
    positions: grown.positions.subarray(0, 3 * V),
    vertexEdge: grown.vertexEdge.subarray(0, V),
    edges: grown.edges.subarray(0, 8 * E),
    faceEdge: grown.faceEdge.subarray(0, F),
    edgeFields: we.edgeFields,
  };
  Object.defineProperty(out, 'room', { value: grown, enumerable: false });
  // One row of each table per read: the views make it a copy of that row only.
  const read = (i) => mesh.tables('winged-edge', { offset: i, limit: 1 });
  // (An undo's removed rows are past the end: there is nothing to read.)
  for (const v of rows.vertex) {
    if (v >= V) continue;
    const { arrays } = read(v).vertices;
    out.positions.set(arrays.positions, 3 * v);
    out.vertexEdge[v] = arrays.vertexEdge[0];
  }
  for (const e of rows.edge) if (e < E) out.edges.set(read(e).edges.arrays.edges, 8 * e);
  for (const f of rows.face) if (f < F) out.faceEdge[f] = read(f).faces.arrays.faceEdge[0];
  return out;
}

/**
 * The vertex positions (x, y, z per vertex) after an edit or an undo, from `positions` before it: the
 * vertices the record moved or added read again from the core, the rest kept.
 * @param {Float64Array & { room?: Float64Array }} positions @param {any} mesh the mesh after the edit
 * @param {{ op: string, added: { vertices: ArrayLike<number> }, removed: { vertices: ArrayLike<number> }, positions: { vertex: number }[] }} record
 * @returns {Float64Array & { room?: Float64Array }}
 */
export function followPositions(positions, mesh, record) {
  const touched = new Set([...record.positions.map((p) => p.vertex), ...Array.from(record.added.vertices)]);
  const V = rowsAfter(positions.length / 3, record, 'vertices');
  return followRows(positions, 3, V, touched, (v) => mesh.tables('winged-edge', { offset: v, limit: 1 }).vertices.arrays.positions);
}

/**
 * A table of `n` rows of `stride` numbers after a change of the rows `touched`: the rows of
 * `table` kept (in place when it has room, the views of the same room: followEdit's rule),
 * each touched row set to rowOf(row).
 * @template {Float64Array | Int32Array} T
 * @param {T & { room?: T }} table @param {number} stride @param {number} n
 * @param {Iterable<number>} touched @param {(row: number) => ArrayLike<number>} rowOf
 * @returns {T & { room?: T }}
 */
export function followRows(table, stride, n, touched, rowOf) {
  const room = sized(table.room ?? table, stride * n, table.length);
  const out = /** @type {T & { room?: T }} */ (room.subarray(0, stride * n));
  Object.defineProperty(out, 'room', { value: room, enumerable: false });
  for (const row of touched) if (row < n) out.set(rowOf(row), stride * row);
  return out;
}

// out[i] = from[i] + delta for i in [start, end).
function shifted(out, from, start, end, delta) {
  for (let i = start; i < end; i += 1) out[i] = from[i] + delta;
}

/**
 * The edges an edit's record names: the rows it rewrote, the edges it added and removed.
 * @param {{ rows: { table: string, row: number }[], added: { edges: ArrayLike<number> }, removed: { edges: ArrayLike<number> } }} record
 * @returns {Set<number>}
 */
export function recordEdges(record) {
  const edges = new Set([...Array.from(record.added.edges), ...Array.from(record.removed.edges)]);
  for (const r of record.rows) if (r.table === 'edge') edges.add(r.row);
  return edges;
}

/**
 * The faces as CSR after an edit, from `csr` before it: the faces whose
 * corners the edit can have changed read again from the core (mesh.faceSet({faces})), the
 * others' corners copied. Those faces: the face rows it rewrote, the faces it added or
 * removed, and the faces on either side of every edge it rewrote, added or removed (a face
 * whose corners changed lost or gained a side, so the edge before that side had its wing
 * rewritten, and it still bounds the face). `we`: the winged-edge arrays after the edit
 * (followEdit). The copy is two typed-array copies (a few ms for a million faces); reading
 * every face again through the core took about 0.25 s there.
 * @param {{ offsets: Int32Array, vertices: Int32Array }} csr the faces before the edit
 * @param {any} mesh the mesh after the edit
 * @param {WingedArrays} we its winged-edge arrays
 * @param {{ rows: { table: string, row: number }[], added: { edges: ArrayLike<number>, faces: ArrayLike<number> },
 *   removed: { edges: ArrayLike<number>, faces: ArrayLike<number> } }} record
 * @param {{ own?: boolean }} [options] own: `csr`'s arrays may be written (they are the caller's,
 *   read by nothing that needs the faces before the edit)
 * @returns {{ offsets: Int32Array, vertices: Int32Array, touched: Int32Array }} `touched`: the
 *   faces read again, increasing; the arrays are `csr`'s own, rewritten, when `own` and every
 *   face kept its number of corners, otherwise new
 */
export function followFaces(csr, mesh, we, record, { own = false } = {}) {
  const F = we.faceEdge.length;
  const faces = new Set([...Array.from(record.added.faces), ...Array.from(record.removed.faces)]);
  for (const r of record.rows) if (r.table === 'face') faces.add(r.row);
  for (const e of recordEdges(record)) {
    const left = we.edges[8 * e + 2]; const right = we.edges[8 * e + 3];
    if (left >= 0) faces.add(left);
    if (right >= 0) faces.add(right);
  }
  const touched = Int32Array.from([...faces].filter((f) => f >= 0 && f < F)).sort();
  const fresh = mesh.faceSet({ faces: touched });
  const oldF = csr.offsets.length - 1;
  const sides = (f) => (f < oldF ? csr.offsets[f + 1] - csr.offsets[f] : 0);
  let total = csr.offsets[Math.min(oldF, F)];
  for (let i = 0; i < touched.length; i += 1) total += fresh.faceOffsets[i + 1] - fresh.faceOffsets[i] - sides(touched[i]);
  // Every face keeps its number of corners (a flip, a move of an edge's end): the corners are
  // written in place when the arrays are the caller's own to write.
  if (own && F === oldF && total === csr.vertices.length && touched.every((t, i) => fresh.faceOffsets[i + 1] - fresh.faceOffsets[i] === sides(t))) {
    for (let i = 0; i < touched.length; i += 1) csr.vertices.set(fresh.faceVertices.subarray(fresh.faceOffsets[i], fresh.faceOffsets[i + 1]), csr.offsets[touched[i]]);
    return { offsets: csr.offsets, vertices: csr.vertices, touched };
  }
  const offsets = new Int32Array(F + 1);
  const vertices = new Int32Array(total);
  // Runs of untouched faces are copied whole, their offsets shifted by what the touched faces
  // before them gained or lost (a plain loop over the run; a copy where nothing shifted).
  let f = 0;
  let at = 0;
  for (let i = 0; i <= touched.length; i += 1) {
    const end = i < touched.length ? touched[i] : F;
    const top = Math.min(end, oldF);
    if (top > f) {
      const from = csr.offsets[f];
      const delta = at - from;
      vertices.set(csr.vertices.subarray(from, csr.offsets[top]), at);
      if (delta === 0) offsets.set(csr.offsets.subarray(f + 1, top + 1), f + 1);
      else shifted(offsets, csr.offsets, f + 1, top + 1, delta);
      at = offsets[top];
    }
    for (let g = Math.max(top, f); g < end; g += 1) offsets[g + 1] = at; // a new face the record did not name: none
    if (i === touched.length) break;
    const corners = fresh.faceVertices.subarray(fresh.faceOffsets[i], fresh.faceOffsets[i + 1]);
    vertices.set(corners, at);
    at += corners.length;
    offsets[end + 1] = at;
    f = end + 1;
  }
  return { offsets, vertices, touched };
}
