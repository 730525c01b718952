// @ts-check
// Kind code: write a function of "Program the structure" (the walk, the Euler characteristic,
// the flip...). The answer is the student's code, kept in the lesson state (the editor is the
// lesson's own), so the kind keeps the state (`keepsState`) and asks it as it is now. Check
// runs the function as the lesson's Run does: on the slide's mesh and on hidden meshes from a
// new seed, graded against the core's answers (lessons/code/check.js, reached through the
// lesson's `exercise.code`). The grader runs the same in Node, in the same QuickJS sandbox.
import { h } from '../../app/dom.js';
import { ExerciseError } from '../format.js';
import { unreadable } from './grading.js';

/**
 * Grades the code a submission holds (the grader, in Node). `run` is the sandbox's.
 * @param {{ api: any, check: any, subject: any, answer?: any, support?: any, run?: (request: any) => Promise<any> }} parts
 * @returns {Promise<import('./grading.js').GradeResult>}
 */
export async function gradeCode({ api, check, subject, support, run }) {
  if (!support?.code) throw new ExerciseError('this lesson has no code tasks', 'exercise.check.kind');
  if (!run) throw new ExerciseError('code is graded in the sandbox, which this grader was not given', 'exercise.check');
  if (!subject?.code || typeof subject.code !== 'object') return unreadable('the lesson state with the code');
  return support.code.grade({ api, task: check.task, subject, run });
}

/** @param {any} parts */
export function createCodeKind({ check, support, ctx, view }) {
  const code = support.code;
  const task = code?.tasks.find((t) => t.id === check.task);
  if (!task) throw new ExerciseError(`its field exercise.check.task names "${check.task}", which is not a task of this lesson (${code?.tasks.map((t) => t.id).join(', ') ?? 'none'})`, 'exercise.check.task');
  let last = null; // the last check's run, for the worked answer
  const root = h('div', { class: 'exercise-code-box' },
    h('p', {}, 'Write ', h('code', {}, `${task.entry}(mesh${task.params.map((p) => `, ${p[0]}`).join('')})`), ' in the editor below ("Your code"). Check runs it as Run does: on the slide\'s mesh and on hidden meshes made from a new seed, and compares every answer with the core\'s.'),
    h('p', { class: 'hint' }, 'Your code is kept with the exercise in this browser, and goes into the file you hand in.'));
  return {
    root,
    // The answer is the state's code (kept with the progress as the state).
    answer: () => null,
    restore() {},
    focus: () => view().focusEditor?.(),
    async check() {
      // The lesson may show another task now: the exercise asks for its own.
      if (ctx.state.task !== task.id) return { correct: false, incomplete: true, findings: [{ text: `This exercise asks for "${task.title}": choose it under The task, then Check.` }] };
      const ran = await code.check(view(), task.id);
      if (!ran) return { correct: false, incomplete: true, findings: [{ text: 'A run is already going: wait for it, then check again.' }] };
      last = ran;
      return code.result(task.id, ran);
    },
    worked: () => code.worked(task.id, last),
  };
}
