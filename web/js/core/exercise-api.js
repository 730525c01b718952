// @ts-check
// Exercise part of the API: checking a student's winged-edge table (exercise kind
// 1). Plain values in and out: the mesh as faces (or CSR) with its vertex count, the answer as
// flat arrays of whole numbers (edges: 8 per row, S E L R S:L S:R E:L E:R; the student's row r
// is their edge e(r+1)); -1 = none, -2 = blank. See docs/api-mesh.md, "Checking a student's
// winged-edge table".
import { unwrap, fail, isNumberArray, integerIn, INT32_MAX } from './errors.js';
import { facesToCsr } from './mesh-api.js';


// Cell values with a meaning of their own.
const ANSWER_CELLS = Object.freeze({ none: -1, blank: -2 });

export function exerciseMesh(mesh) {
  if (mesh === null || typeof mesh !== 'object') fail('invalid-argument', 'expected the exercise mesh {faces, vertexCount}');
  let csr;
  if (mesh.faces === undefined && mesh.faceOffsets !== undefined) {
    if (!(mesh.faceOffsets instanceof Int32Array) || !(mesh.faceVertices instanceof Int32Array)) {
      fail('invalid-argument', 'faceOffsets and faceVertices must be Int32Arrays');
    }
    csr = { faceOffsets: mesh.faceOffsets, faceVertices: mesh.faceVertices };
  } else {
    csr = facesToCsr(mesh.faces);
  }
  let { vertexCount } = mesh;
  if (vertexCount === undefined && isNumberArray(mesh.positions)) vertexCount = Math.floor(mesh.positions.length / 3);
  if (!Number.isInteger(vertexCount) || vertexCount < 0 || vertexCount > INT32_MAX) {
    fail('invalid-argument', 'the exercise mesh needs vertexCount (a whole number) or positions (x, y, z per vertex)');
  }
  return [csr.faceOffsets, csr.faceVertices, vertexCount];
}

// `name(i)` says which row and field entry i is, as the tables label them.
function cells(value, what, name) {
  if (!isNumberArray(value)) fail('invalid-argument', `${what} must be an array of whole numbers (-1 = none, -2 = blank)`);
  const out = new Int32Array(value.length);
  for (let i = 0; i < value.length; i += 1) {
    const x = value[i];
    if (!Number.isInteger(x) || x > INT32_MAX || x < -INT32_MAX) {
      fail('invalid-argument', `${name(i)} must be a whole number (-1 = none, -2 = blank), not ${String(x).slice(0, 40)}`);
    }
    out[i] = x;
  }
  return out;
}

function answerArguments(mesh, answer) {
  if (answer === null || typeof answer !== 'object') fail('invalid-argument', 'expected the answer {edges, vertexEdges, faceEdges}');
  return [...exerciseMesh(mesh), cells(answer.edges, 'edges', WINGED_EDGE_CELLS.edges),
    cells(answer.vertexEdges, 'vertexEdges', WINGED_EDGE_CELLS.vertexEdges), cells(answer.faceEdges, 'faceEdges', WINGED_EDGE_CELLS.faceEdges)];
}

// ---- checkMeshTableAnswer and checkWalkStep (exercise kinds 1 and 2; docs/api-mesh.md,
// "Checking a student's ..."). A malformed answer is 'invalid-answer' naming the row and field.
const MESH_TABLES = Object.freeze(['winged-edge', 'faces', 'edge-list', 'adjacency', 'half-edge']);

function answerCell(x, what) {
  if (!Number.isInteger(x) || x > INT32_MAX || x < -INT32_MAX) {
    fail('invalid-answer', `${what} must be a whole number (-1 = none, -2 = blank), not ${String(x).slice(0, 40)}`);
  }
  return x;
}

// A flat row table (number[]) -> Int32Array; `name(i)` says which row and field entry i is.
export function flatAnswer(value, key, name) {
  if (!isNumberArray(value)) fail('invalid-answer', `the answer's ${key} must be an array of whole numbers (-1 = none, -2 = blank)`);
  const out = new Int32Array(value.length);
  for (let i = 0; i < value.length; i += 1) out[i] = answerCell(value[i], name(i));
  return out;
}

// A list table (number[][], one list per row) -> {offsets, cells}.
function listAnswer(value, key, rowName) {
  if (!Array.isArray(value)) fail('invalid-answer', `the answer's ${key} must be an array with one list per ${rowName(null)}`);
  const offsets = new Int32Array(value.length + 1);
  const cells = [];
  value.forEach((row, r) => {
    if (!Array.isArray(row) && !isNumberArray(row)) fail('invalid-answer', `${key}: ${rowName(r)} must be a list of whole numbers (-2 = blank)`);
    for (let i = 0; i < row.length; i += 1) cells.push(answerCell(row[i], `${key}: ${rowName(r)}, item ${i + 1}`));
    offsets[r + 1] = cells.length;
  });
  return { offsets, cells: Int32Array.from(cells) };
}

function listRows({ offsets, cells }) {
  const rows = [];
  for (let r = 0; r + 1 < offsets.length; r += 1) rows.push(Array.from(cells.subarray(offsets[r], offsets[r + 1])));
  return rows;
}

const COLUMNS_8 = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
const COLUMNS_4 = ['v1', 'v2', 'p1', 'p2'];
const COLUMNS_HALF_EDGE = ['origin', 'face', 'next', 'prev', 'twin'];
const vertexRow = (v) => (v === null ? 'vertex' : `vertex v${v + 1}`);
const faceRow = (f) => (f === null ? 'face' : `face F${f + 1}`);
// The winged-edge answer's cells, each named by its row and field.
const WINGED_EDGE_CELLS = Object.freeze({
  edges: (i) => `edges: row e${Math.floor(i / 8) + 1}, ${COLUMNS_8[i % 8]}`,
  vertexEdges: (i) => `vertexEdges: ${vertexRow(i)}`,
  faceEdges: (i) => `faceEdges: ${faceRow(i)}`,
});

// message and hint: the value-free words (where, the rule; a nudge), for feedback levels
// check and hint; reason: with the values, for the worked answer and the lecturer.
export function plainFindings(list) {
  return Array.from(list, ({ table, row, field, index, given, expected, code, reason, message, hint }) => ({
    table, row, field, index, given, expected, code, reason, message, hint,
  }));
}

// The mesh's numbering for a walk: a slide's edges ([S, E] per edge) and vertex/face edges, if given.
export function walkNumbering(mesh) {
  const edges = mesh.edges ?? [];
  if (!Array.isArray(edges)) fail('invalid-argument', 'the mesh\'s edges must be [S, E] pairs, one per edge');
  const pairs = new Int32Array(2 * edges.length);
  edges.forEach((e, i) => {
    if (!isNumberArray(e) || e.length !== 2 || !Number.isInteger(e[0]) || !Number.isInteger(e[1])) {
      fail('invalid-argument', `the mesh's edges[${i}] (e${i + 1}) must be [S, E], two vertex numbers`);
    }
    pairs[2 * i] = e[0];
    pairs[2 * i + 1] = e[1];
  });
  return [pairs, cells(mesh.vertexEdges ?? [], 'vertexEdges'), cells(mesh.faceEdges ?? [], 'faceEdges')];
}


export function createExerciseApi(raw) {
  return {
    answerCells: ANSWER_CELLS,
    // {correct, findings: [{table: 'vertex'|'edge'|'face', row, field, given, expected, code,
    // reason, message, hint}], rowEdges (the mesh edge each row was matched to, -1 none), rowReversed}.
    // Any consistent numbering and either orientation of each edge is right. Errors:
    // 'invalid-answer' (row length, table length, a cell below -2), 'invalid-faces', or the
    // mesh's validation code for faces a winged edge cannot hold.
    checkWingedEdgeAnswer(mesh, answer) {
      const r = unwrap(raw.exerciseCheckWingedEdge(...answerArguments(mesh, answer)));
      const findings = Array.from(r.findings, ({ table, row, field, given, expected, code, reason, message, hint }) => ({
        table, row, field, given, expected, code, reason, message, hint,
      }));
      return {
        correct: findings.length === 0,
        findings,
        rowEdges: r.rowEdges,
        rowReversed: Array.from(r.rowReversed, (x) => x !== 0),
      };
    },
    // The worked answer in the student's numbering where rows match: {edges, vertexEdges,
    // faceEdges} (Int32Arrays; a row that describes no edge is left blank, -2).
    workedWingedEdgeAnswer(mesh, answer) {
      const r = unwrap(raw.exerciseWorkedWingedEdge(...answerArguments(mesh, answer)));
      return { edges: r.edges, vertexEdges: r.vertexEdges, faceEdges: r.faceEdges };
    },
    // One entry point for every table of kind 1: table 'winged-edge' | 'faces' | 'edge-list' |
    // 'adjacency' | 'half-edge' (answer {halfedges: 5 per row, origin face next prev twin,
    // vertexHalfedges, faceHalfedges}; rows are the student's half-edges, any numbering). Returns {correct, findings: [{table, row, field, index, given, expected,
    // code, reason, message, hint}], worked} with worked the right answer in the answer's own shape (the
    // student's numbering where rows match). Errors: 'unknown-table', 'invalid-answer'
    // (naming the row and field), 'invalid-faces' or the mesh's validation code.
    checkMeshTableAnswer(mesh, table, answer) {
      if (!MESH_TABLES.includes(table)) {
        fail('unknown-table', `no exercise table ${JSON.stringify(table)?.slice(0, 40)}; use ${MESH_TABLES.join(', ')}`);
      }
      if (answer === null || typeof answer !== 'object') fail('invalid-answer', `the answer to a ${table} table must be an object`);
      const meshArgs = exerciseMesh(mesh);
      if (table === 'winged-edge') {
        const args = [...meshArgs,
          flatAnswer(answer.edges, 'edges', WINGED_EDGE_CELLS.edges),
          flatAnswer(answer.vertexEdges, 'vertexEdges', WINGED_EDGE_CELLS.vertexEdges),
          flatAnswer(answer.faceEdges, 'faceEdges', WINGED_EDGE_CELLS.faceEdges)];
        const findings = plainFindings(unwrap(raw.exerciseCheckWingedEdge(...args)).findings);
        const w = unwrap(raw.exerciseWorkedWingedEdge(...args));
        return {
          correct: findings.length === 0,
          findings,
          worked: { edges: Array.from(w.edges), vertexEdges: Array.from(w.vertexEdges), faceEdges: Array.from(w.faceEdges) },
        };
      }
      if (table === 'half-edge') {
        // The half-edge table (docs/api-mesh.md, "Checking a student's half-edge table"): the
        // rows are the student's half-edges, so a finding's table is 'halfedge' for them.
        const r = unwrap(raw.exerciseCheckHalfEdge(...meshArgs, ...walkNumbering(mesh),
          flatAnswer(answer.halfedges, 'halfedges', (i) => `halfedges: row h${Math.floor(i / 5) + 1}, ${COLUMNS_HALF_EDGE[i % 5]}`),
          flatAnswer(answer.vertexHalfedges, 'vertexHalfedges', (i) => `vertexHalfedges: ${vertexRow(i)}`),
          flatAnswer(answer.faceHalfedges, 'faceHalfedges', (i) => `faceHalfedges: ${faceRow(i)}`)));
        const findings = plainFindings(r.findings).map((f) => (f.table === 'edge' ? { ...f, table: 'halfedge' } : f));
        return {
          correct: findings.length === 0,
          findings,
          worked: { halfedges: Array.from(r.worked.halfedges), vertexHalfedges: Array.from(r.worked.vertexHalfedges), faceHalfedges: Array.from(r.worked.faceHalfedges) },
        };
      }
      let flat = new Int32Array(0);
      let list;
      if (table === 'faces') list = listAnswer(answer.faces, 'faces', faceRow);
      else if (table === 'adjacency') list = listAnswer(answer.vertexVertices, 'vertexVertices', vertexRow);
      else {
        flat = flatAnswer(answer.edges, 'edges', (i) => `edges: row e${Math.floor(i / 4) + 1}, ${COLUMNS_4[i % 4]}`);
        list = listAnswer(answer.polygons, 'polygons', (f) => (f === null ? 'polygon' : `polygon F${f + 1}`));
      }
      const r = unwrap(raw.exerciseCheckTable(...meshArgs, table, flat, list.offsets, list.cells));
      const findings = plainFindings(r.findings);
      const rows = listRows(r.worked);
      let worked;
      if (table === 'faces') worked = { faces: rows };
      else if (table === 'adjacency') worked = { vertexVertices: rows };
      else worked = { edges: Array.from(r.worked.flat), polygons: rows };
      return { correct: findings.length === 0, findings, worked };
    },
    // Kind 2: is `given` the next edge of the CCW walk around a vertex (along a face)? step k
    // (from 1) asks for the walk's edge k, edges 0..k-1 shown; the walk is the core's
    // (mesh.traversalSteps / faceEdgeSteps on the mesh built from these faces, with the
    // mesh's edges / vertexEdges / faceEdges numbering when given, as lectureExample()
    // returns them). Returns {correct, from, expected, done, reason, message, hint} (message and
    // hint: value-free, '' for a right step; from: the edge or half-edge step k starts from). Errors: 'invalid-argument',
    // 'index-out-of-range' (no such vertex or face), 'no-walk' (a vertex on no face),
    // 'invalid-step'.
    // structure 'half-edge' (default 'winged-edge') walks the half-edges instead: around a
    // vertex h -> twin(prev(h)), along a face h -> next(h), from the vertex's (face's)
    // half-edge; given and expected are half-edges (2e = S -> E, 2e + 1 = E -> S of edge e).
    checkWalkStep(mesh, question) {
      if (question === null || typeof question !== 'object') fail('invalid-argument', 'expected the step {around, element, step, given}');
      const { around, element, step, given, structure = 'winged-edge' } = question;
      if (around !== 'vertex' && around !== 'face') {
        fail('invalid-argument', `around must be 'vertex' or 'face', not ${JSON.stringify(around)?.slice(0, 40)}`);
      }
      if (structure !== 'winged-edge' && structure !== 'half-edge') {
        fail('invalid-argument', `structure must be 'winged-edge' or 'half-edge', not ${JSON.stringify(structure)?.slice(0, 40)}`);
      }
      integerIn(element, 'element', -INT32_MAX, INT32_MAX);
      integerIn(step, 'step', -INT32_MAX, INT32_MAX);
      integerIn(given, 'given', -INT32_MAX, INT32_MAX);
      const r = unwrap(raw.exerciseCheckWalkStep(...exerciseMesh(mesh), ...walkNumbering(mesh), around === 'face', element, step, given, structure === 'half-edge'));
      return { correct: r.correct, from: r.from, expected: r.expected, done: r.done, reason: r.reason, message: r.message, hint: r.hint };
    },
  };
}
