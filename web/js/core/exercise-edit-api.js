// @ts-check
// The edit exercise's part of the API (docs/api-mesh.md, "Checking the rows an edit
// rewrites"): api.editQuestion and api.checkEditAnswer over the core's exercise_edit.h. The
// mesh, the answer cells and the findings cross as the other exercise checks' do
// (exercise-api.js); the operations as the lesson state stores them (mesh-api.js reads them).
import { unwrap, fail, isNumberArray } from './errors.js';
import { operationValues } from './mesh-api.js';
import { exerciseMesh, flatAnswer, plainFindings, walkNumbering } from './exercise-api.js';

// The mesh before is the exercise mesh (with its positions and the slide's numbering, if any)
// after `edits` replayed in order; the question's operation is a lesson state's {op, ...} record. The answer: per table (vertices,
// edges, faces) {cells, removed, labels}: cells 8 per edge row (S E L R S:L S:R E:L E:R), 1 per
// vertex or face row (its edge), the listed rows then the new ones; removed: one flag per row;
// labels: the new rows' labels. Labels 0-based, -1 none, -2 blank.
const EDIT_TABLES = Object.freeze(['vertices', 'edges', 'faces']);

function editMeshArguments(mesh, registry, edits, operation) {
  const [faceOffsets, faceVertices, vertexCount] = exerciseMesh(mesh);
  const positions = mesh.positions === undefined ? new Float64Array(3 * vertexCount) : mesh.positions;
  if (!isNumberArray(positions) || positions.length !== 3 * vertexCount) fail('invalid-argument', 'the exercise mesh\'s positions must hold x, y, z for each vertex');
  if (!Array.isArray(edits)) fail('invalid-argument', 'the edits before the question must be a list of operations such as {op: \'flip-edge\', e: 2}');
  const asValue = (op) => {
    const [edit, values] = operationValues(registry, op);
    return { name: edit.name, args: Float64Array.from(values) };
  };
  // Among the edits, the lesson's Compact step renumbers; a moved vertex changes no table.
  const before = edits.filter((op) => op?.op !== 'move-vertex').map((op) => (op?.op === 'compact' ? { name: 'compact', args: new Float64Array(0) } : asValue(op)));
  return [Float64Array.from(positions), faceOffsets, faceVertices, ...walkNumbering(mesh), before, asValue(operation)];
}

// The half-edge edit exercise's tables (exercise_half_edge_edit.h): cells 4 per half-edge row
// (origin, face, next, prev), 1 per vertex or face row (its half-edge); labels stay empty (the
// new elements take the core's numbers).
const HALF_EDGE_EDIT_TABLES = Object.freeze(['vertices', 'halfedges', 'faces']);

function editAnswer(answer, tables = EDIT_TABLES) {
  if (answer === null || typeof answer !== 'object') fail('invalid-answer', `the answer to an edit is {${tables.join(', ')}}`);
  const out = {};
  for (const key of tables) {
    const t = answer[key];
    if (t === null || typeof t !== 'object') fail('invalid-answer', `the answer's ${key} must be {cells, removed, labels}`);
    const removed = Array.isArray(t.removed) ? t.removed.map((x) => (x ? 1 : 0)) : t.removed;
    out[key] = {
      cells: flatAnswer(t.cells, `${key}.cells`, (i) => `${key}.cells[${i}]`),
      removed: flatAnswer(removed, `${key}.removed`, (i) => `${key}.removed[${i}]`),
      labels: flatAnswer(t.labels, `${key}.labels`, (i) => `${key}.labels[${i}]`),
    };
  }
  return out;
}

const plainEditAnswer = (w, tables = EDIT_TABLES) => Object.fromEntries(tables.map((key) => [key, {
  cells: Array.from(w[key].cells), removed: Array.from(w[key].removed, (x) => x !== 0), labels: Array.from(w[key].labels),
}]));

export function createExerciseEditApi(raw) {
  let registry = null; // the operations' registry, read once per API
  const operations = () => (registry ??= unwrap(raw.meshOperationDescriptors()));
  return {
    // The edit exercise's question: which existing rows `operation` rewrites or removes on the
    // mesh before (labels 0-based, ascending) and how many new rows each table gains:
    // {rows: {vertices, edges, faces}, added: {vertices, edges, faces}, operation: 'flip e3'}.
    // Errors: the operation's refusal (its own code), 'invalid-argument', 'invalid-faces'.
    editQuestion(mesh, edits, operation) {
      const r = unwrap(raw.exerciseEditQuestion(...editMeshArguments(mesh, operations(), edits, operation)));
      return {
        rows: Object.fromEntries(EDIT_TABLES.map((key) => [key, Array.from(r.rows[key])])),
        added: { vertices: r.added.vertices, edges: r.added.edges, faces: r.added.faces },
        operation: r.operation,
      };
    },
    // Checks an answer to the edit question (the core compares it with the operation's change
    // record; new elements under any labels, see exercise_edit.h): {correct, findings: [{table,
    // row, field, index, given, expected, code, reason}], worked} (worked: the right answer in
    // the student's labels, the answer's shape). `reason` never holds the right value.
    // Errors: 'invalid-answer' (the answer's shape), the operation's refusal, 'invalid-faces'.
    checkEditAnswer(mesh, edits, operation, answer) {
      const args = editMeshArguments(mesh, operations(), edits, operation);
      const r = unwrap(raw.exerciseCheckEdit(...args, editAnswer(answer)));
      const findings = plainFindings(r.findings);
      return { correct: findings.length === 0, findings, worked: plainEditAnswer(r.worked) };
    },
    // The same edit in half-edge terms: the rows of the half-edge view (origin, face, next,
    // prev per half-edge; one half-edge per vertex and per face) that `operation` changes,
    // existing then new, 0-based and ascending, and each table's row count before (a row at or
    // past it is new, numbered as the core numbers it): {rows: {vertices, halfedges, faces},
    // beforeCount: {vertices, halfedges, faces}, operation}. Errors as editQuestion's.
    halfEdgeEditQuestion(mesh, edits, operation) {
      const r = unwrap(raw.exerciseHalfEdgeEditQuestion(...editMeshArguments(mesh, operations(), edits, operation)));
      return {
        rows: Object.fromEntries(HALF_EDGE_EDIT_TABLES.map((key) => [key, Array.from(r.rows[key])])),
        beforeCount: { vertices: r.beforeCount.vertices, halfedges: r.beforeCount.halfedges, faces: r.beforeCount.faces },
        operation: r.operation,
      };
    },
    // Checks an answer to it ({vertices, halfedges, faces}, each {cells, removed, labels: []}):
    // {correct, findings (table 'edge' for a half-edge row), worked}. A vertex's half-edge is
    // right when it leaves the vertex (a boundary one on the boundary), a face's when it lies on
    // the face. Errors as checkEditAnswer's.
    checkHalfEdgeEditAnswer(mesh, edits, operation, answer) {
      const args = editMeshArguments(mesh, operations(), edits, operation);
      const r = unwrap(raw.exerciseCheckHalfEdgeEdit(...args, editAnswer(answer, HALF_EDGE_EDIT_TABLES)));
      const findings = plainFindings(r.findings);
      return { correct: findings.length === 0, findings, worked: plainEditAnswer(r.worked, HALF_EDGE_EDIT_TABLES) };
    },
  };
}
