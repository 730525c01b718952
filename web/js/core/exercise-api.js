// Exercise part of the API (issue 19): checking a student's winged-edge table (exercise kind
// 1). Plain values in and out: the mesh as faces (or CSR) with its vertex count, the answer as
// flat arrays of whole numbers (edges: 8 per row, S E L R S:L S:R E:L E:R; the student's row r
// is their edge e(r+1)); -1 = none, -2 = blank. See docs/api-mesh.md, "Checking a student's
// winged-edge table".
import { unwrap, fail, isNumberArray } from './errors.js';
import { facesToCsr } from './mesh-api.js';

const INT32_MAX = 2147483647;

// Cell values with a meaning of their own.
const ANSWER_CELLS = Object.freeze({ none: -1, blank: -2 });

function exerciseMesh(mesh) {
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

function cells(value, what) {
  if (!isNumberArray(value)) fail('invalid-argument', `${what} must be an array of whole numbers (-1 = none, -2 = blank)`);
  const out = new Int32Array(value.length);
  for (let i = 0; i < value.length; i += 1) {
    const x = value[i];
    if (!Number.isInteger(x) || x > INT32_MAX || x < -INT32_MAX) {
      fail('invalid-argument', `${what} entry ${i} must be a whole number (-1 = none, -2 = blank), not ${String(x).slice(0, 40)}`);
    }
    out[i] = x;
  }
  return out;
}

function answerArguments(mesh, answer) {
  if (answer === null || typeof answer !== 'object') fail('invalid-argument', 'expected the answer {edges, vertexEdges, faceEdges}');
  return [...exerciseMesh(mesh), cells(answer.edges, 'edges'), cells(answer.vertexEdges, 'vertexEdges'),
    cells(answer.faceEdges, 'faceEdges')];
}

export function createExerciseApi(raw) {
  return {
    answerCells: ANSWER_CELLS,
    // {correct, findings: [{table: 'vertex'|'edge'|'face', row, field, given, expected, code,
    // reason}], rowEdges (the mesh edge each row was matched to, -1 none), rowReversed}.
    // Any consistent numbering and either orientation of each edge is right. Errors:
    // 'invalid-answer' (row length, table length, a cell below -2), 'invalid-faces', or the
    // mesh's validation code for faces a winged edge cannot hold.
    checkWingedEdgeAnswer(mesh, answer) {
      const r = unwrap(raw.exerciseCheckWingedEdge(...answerArguments(mesh, answer)));
      const findings = Array.from(r.findings, ({ table, row, field, given, expected, code, reason }) => ({
        table, row, field, given, expected, code, reason,
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
  };
}
