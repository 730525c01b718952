// @ts-check
// One Run of a student's function, as the lesson's Run button, the code exercise's Check and
// the grader (`wingspline grade`, in Node) all make it: the cases from a seed (cases.js), the
// function tried one mesh at a time in a sandbox (`run`: the page's worker, or QuickJS in
// Node), every answer graded against the core's (grading.js). An edit is checked by the
// core's winged-edge table check against the faces of the core's own edit of the same mesh.
import { makeCases, sandboxMesh } from './cases.js';
import { gradeRun, failureText, caseWhere, describeAnswer, tablesAfter, addedPositions, samePoint, meshScale } from './grading.js';
import { elementLabel } from '../../core/element-labels.js';

// Per mesh: an endless loop stops after this (web/js/code/runner.js).
export const BUDGET_MS = 1500;

/**
 * @param {{
 *   api: any,
 *   checker: () => any | Promise<any>,
 *   task: import('./tasks.js').Task,
 *   source: string,
 *   seed: number,
 *   run: (request: any) => Promise<{ results?: any[], error?: any }>,
 *   onMesh?: (k: number, of: number) => void,
 * }} parts `checker` gives the core with its exercise checkers (fetched only for an edit task)
 * @returns {Promise<{ cases: any[], grade: any, error: any }>} error: the code could not run at
 *   all (a syntax error); grade: gradeRun's, with the first failing case
 */
export async function runTask({ api, checker, task, source, seed, run, onMesh }) {
  const cases = makeCases(api, task, seed);
  // One mesh at a time, the slide's first: an endless loop stops the run at the mesh it was
  // found on (each would take the whole budget).
  const results = [];
  const asked = cases.filter((c) => c.args);
  for (const c of asked) {
    onMesh?.(results.length + 1, asked.length);
    const one = await run({ source, entry: task.entry, writable: task.writable === true, budgetMs: BUDGET_MS, cases: [{ args: c.args, mesh: sandboxMesh(task, c) }] });
    if (one.error) return { cases, grade: null, error: one.error };
    results.push(one.results?.[0]);
    if (one.results?.[0]?.error?.kind === 'timeout') break;
  }
  const core = task.answer === 'edit' ? await checker() : null;
  const checkEdit = (c, r) => {
    const tables = core.checkMeshTableAnswer(
      { faceOffsets: c.expected.faceOffsets, faceVertices: c.expected.faceVertices, vertexCount: c.expected.vertexCount },
      'winged-edge', tablesAfter(c.snapshot, r.transaction));
    return tables.correct && c.expected.newPositions ? checkNewPositions(task, c, r.transaction) : tables;
  };
  return { cases, grade: gradeRun(task, cases, results, { checkEdit }), error: null };
}

// The vertices an edit adds are where the core's edit puts them (a split: the midpoint),
// each coordinate within 1e-9 of the mesh's size (samePoint: a few rounding steps).
function checkNewPositions(task, c, transaction) {
  const got = addedPositions(c.snapshot, transaction);
  const first = c.snapshot.winged.vertexEdge.length;
  for (let k = 0; k < c.expected.newPositions.length; k += 1) {
    if (!samePoint(c.expected.newPositions[k], got[k], meshScale(c.snapshot))) {
      return {
        correct: false,
        findings: [{ message: `The vertex table, row ${elementLabel('vertex', first + k)}: its position is not ${task.positionRule ?? 'where the edit puts it'}.`, hint: 'Re-read the statement: the new vertex\'s position is given there.' }],
      };
    }
  }
  return { correct: true, findings: [] };
}

/**
 * A run as an exercise's check result (exercise/kinds/grading.js GradeResult): right when every
 * mesh asked passed. A failure is one finding naming the mesh, the element asked, the answer
 * returned and where it parts from the core's; the core's answer itself is never in it (the
 * exercise's feedback levels: only the worked answer shows a value). Its hint, shown at level
 * hint or worked after the wrong checks the exercise asks for, points to the rule and to Step.
 * @param {import('./tasks.js').Task} task
 * @param {{ grade: any, error: any }} ran
 */
export function resultOfRun(task, ran) {
  if (ran.error) {
    const at = ran.error.line ? `Line ${ran.error.line}${ran.error.column ? `, column ${ran.error.column}` : ''}: ` : '';
    return { correct: false, findings: [{ text: /^Line \d/.test(ran.error.message) ? ran.error.message : `${at}${ran.error.message}` }] };
  }
  const { grade } = ran;
  if (grade.firstFail === null) return { correct: true, findings: [], note: `All ${grade.asked} meshes passed.` };
  const g = grade.cases[grade.firstFail];
  const where = `${grade.passed} of ${grade.asked} meshes passed.`;
  const hint = `Choose that mesh under Results and Step through it: every entry your function read is marked in its tables. The lecture's rule: ${task.rule.join('; ')}.`;
  if (g.error || g.check) return { correct: false, findings: [{ text: `${failureText(task, g)} ${where}`, hint }] };
  const asked = `On ${caseWhere(task, g)}`;
  const part = task.answer === 'position' ? ' It is not the core\'s point (each coordinate within 1e-9 of the mesh\'s size, its largest coordinate).'
    : Array.isArray(g.expected) && g.partsAt >= 0 ? ` It parts from the core's answer at entry ${g.partsAt + 1}.` : ' It is not the core\'s answer.';
  return { correct: false, findings: [{ text: `${asked}: your function returned ${describeAnswer(task, g.value)}.${part} ${where}`, hint }] };
}

/**
 * The worked answer of a code exercise: the lecture's rule, and on the mesh the last check
 * failed on, the core's answer beside the function's.
 * @param {import('./tasks.js').Task} task
 * @param {{ grade: any, error: any } | null} ran
 */
export function workedLines(task, ran) {
  const lines = [`The lecture's rule (lecture ${task.lecture}): ${task.rule.join('; ')}.`];
  const g = ran?.grade && ran.grade.firstFail !== null ? ran.grade.cases[ran.grade.firstFail] : null;
  if (g && !g.error && !g.check) lines.push(`${failureText(task, { ...g, error: null, check: null })}`);
  else if (g?.check) lines.push(`The core's ${task.editName ?? 'edit'} of the same mesh is played assignment by assignment in the mesh lesson (Edit, then Step).`);
  else if (!ran) lines.push('Check your code first: the worked answer then shows the core\'s answer on the first mesh it fails.');
  return { lines };
}
