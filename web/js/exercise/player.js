// @ts-check
// The exercise player: in a lesson page opened with an exercise link
// (exercise/link.js), a panel at the top of the side column holds the question, the answer
// for its kind (kinds/), Check (or Enter in the answer), the feedback that names what is
// wrong, the worked answer on request, and the progress kept in this browser
// (progress.js). The lesson keeps its drawing and interaction; the panels the exercise hides
// are hidden. Nothing of the person's own saved lesson work is read or written meanwhile.
import { h, setChildren } from '../app/dom.js';
import { readEnvelope } from '../app/share-link.js';
import { KINDS, ExerciseError, feedbackOf } from './format.js';
import { writeProgress, clearProgress } from './progress.js';
import { createTableKind } from './kinds/table.js';
import { createWalkKind } from './kinds/walk.js';
import { createJointKind } from './kinds/joint.js';
import { createValueKind } from './kinds/value.js';
import { createPropertyKind } from './kinds/property.js';
import { createEditKind } from './kinds/edit.js';
import { createSubdivideKind } from './kinds/subdivide.js';
import { createCodeKind } from './kinds/code.js';

// What this exercise's feedback will and will not tell, in one line (the author's level).
export function levelSentence({ level, hintAfter }) {
  const tries = `${hintAfter} wrong check${hintAfter === 1 ? '' : 's'}`;
  if (level === 'check') return 'Feedback: Check says whether your answer is right and where it is wrong, with the rule to re-read. It never shows the right value; no hints, no worked answer.';
  if (level === 'hint') return `Feedback: Check says where your answer is wrong and the rule to re-read; after ${tries} it adds a hint for each mistake. It never shows the right value; no worked answer.`;
  return `Feedback: Check says where your answer is wrong and the rule to re-read; after ${tries} it adds hints; the worked answer is on offer (and recorded as seen).`;
}

// Typed arrays as plain lists, to compare two subjects.
const plain = (key, value) => (ArrayBuffer.isView(value) ? Array.from(/** @type {any} */ (value)) : value);

export const CREATE = { table: createTableKind, walk: createWalkKind, joint: createJointKind, value: createValueKind, property: createPropertyKind, subdivide: createSubdivideKind,
  edit: createEditKind, code: createCodeKind };

/**
 * The lesson state of an exercise, read like a share link's (migrated, validated); a field
 * the lesson refuses refuses the exercise, naming it.
 * @param {import('../app/contract.js').Lesson} lesson
 */
export function readExerciseState(lesson, exercise) {
  if (exercise.lesson !== lesson.id) throw new ExerciseError(`it is an exercise of the ${exercise.lesson} lesson, not of ${lesson.title}`, 'exercise.lesson');
  const support = lesson.exercise;
  if (!support || !support.kinds.includes(exercise.check.kind)) {
    throw new ExerciseError(`${lesson.title} has no exercises of the kind "${exercise.check.kind}" (it has ${support?.kinds.join(', ') || 'none'})`, 'exercise.check.kind');
  }
  let read;
  try {
    read = readEnvelope(lesson, { format: 'wingspline', lesson: lesson.id, version: exercise.stateVersion, state: exercise.state });
  } catch (err) {
    throw new ExerciseError(`its state cannot be used: ${err.message}`, 'exercise.state');
  }
  // validatePartial's sentences start with the field's path inside the state.
  if (read.problems.length) throw new ExerciseError(`its field exercise.state.${read.problems[0].replace(/^state\.?/, '')}`, 'exercise.state');
  return read.state;
}

/**
 * @param {{ api: any, ctx: any, lesson: any, view: () => any, exercise: any, key: string, hash?: string | null, loaded: { progress: any, problem: string | null, stuck?: boolean }, panels: HTMLElement, reset: () => void, initialState: any }} parts
 */
export function mountExercise({ api, ctx, lesson, view, exercise, key, hash = null, loaded, panels, reset, initialState }) {
  const support = lesson.exercise;
  const { check } = exercise;
  // What the check is asked of. A question is about the exercise's drawing: its subject is
  // taken once, as the exercise opens; only "move points until it holds" asks the drawing as
  // it is now. If the drawing is changed meanwhile, the panel says so and offers it back.
  const live = () => support.subject(view(), ctx.model, ctx.state, ctx);
  // (code: the answer is the code in the state, typed after the exercise opened)
  const asksNow = check.kind === 'property' || check.kind === 'code';
  const keepsState = Boolean(support.keepsState?.includes(check.kind));
  const asOpened = asksNow ? null : live();
  const subject = asksNow ? live : () => asOpened;
  const same = (a, b) => JSON.stringify(a, plain) === JSON.stringify(b, plain);
  const feedbackLevel = feedbackOf(exercise);
  /** @type {any} */
  let progress = loaded.progress ?? { status: 'started', checks: 0, answer: null, state: null, solvedAt: null, title: exercise.title, lesson: exercise.lesson };
  const feedback = h('div', { class: 'exercise-feedback', id: 'exercise-feedback', role: 'status', 'aria-live': 'polite' });
  const worked = h('div', { class: 'exercise-worked-lines', id: 'exercise-worked', hidden: true });
  const status = h('p', { class: 'exercise-status', id: 'exercise-status' });
  const drift = h('p', { class: 'exercise-drift callout warning', id: 'exercise-drift', hidden: true },
    'The drawing has changed since the exercise began; the question is about its starting drawing. ',
    h('button', { type: 'button', id: 'exercise-back-to-drawing', onclick: () => reset() }, 'Back to the exercise\'s drawing'));
  let unsaved = false; // this browser refuses to keep progress
  let leaving = false; // Start again: the page reloads, nothing more is saved
  let saveTimer = 0;

  const kind = CREATE[check.kind]({ api, check, subject, support, ctx, view });
  if (loaded.progress) kind.restore(progress.answer);

  const checkButton = h('button', { type: 'button', class: 'primary', id: 'exercise-check', onclick: () => runCheck() }, 'Check');
  // The worked answer is offered only where the author allows it (level worked).
  const workedButton = feedbackLevel.level === 'worked' ? h('button', { type: 'button', id: 'exercise-show-worked', onclick: () => showWorked() }, 'Show the worked answer') : null;
  const againButton = h('button', { type: 'button', id: 'exercise-start-again', onclick: () => startAgain() }, 'Start again');
  const root = h('section', { class: 'exercise-panel callout', id: 'exercise-panel', 'aria-labelledby': 'exercise-title' },
    h('p', { class: 'exercise-kind' }, `Exercise · ${KINDS[check.kind].label}`),
    h('h2', { id: 'exercise-title' }, exercise.title),
    exercise.source ? h('p', { class: 'exercise-source hint lecture-note' }, exercise.source) : null,
    h('p', { class: 'exercise-question', id: 'exercise-question' }, exercise.question),
    h('p', { class: 'exercise-level hint', id: 'exercise-level', 'data-level': feedbackLevel.level }, levelSentence(feedbackLevel)),
    drift,
    kind.root,
    h('div', { class: 'exercise-actions' }, checkButton, workedButton, againButton),
    feedback, worked, status,
    h('p', { class: 'exercise-leave' }, h('a', { href: `./${lesson.id}.html`, id: 'exercise-leave' }, 'Leave the exercise'), ' · ', h('a', { href: './exercises.html' }, 'All exercises'), ' · ', h('a', { href: './exercises.html#hand-in-title', id: 'exercise-hand-in' }, 'Hand in your answers')));
  // Enter in a typed answer checks it (a radio group's Enter too).
  kind.root.addEventListener('keydown', (event) => {
    if (event.key === 'Enter' && !event.isComposing && event.target instanceof HTMLInputElement) {
      event.preventDefault();
      runCheck();
    }
  });
  kind.root.addEventListener('input', () => save());
  kind.root.addEventListener('change', () => save());
  showStatus();
  kind.start?.();
  kind.stateChanged?.();
  panels.prepend(root); // (only a panel whose kind started is shown)

  function save() {
    window.clearTimeout(saveTimer);
    saveTimer = 0;
    if (leaving) return;
    // Which exercise this is, for a submission file (submission.js): the content hash tells
    // the version answered from the lecturer's copy.
    progress = { ...progress, id: exercise.id ?? null, hash, kind: check.kind, feedback: feedbackLevel.level, answer: kind.answer(), state: keepsState ? ctx.state : null };
    const kept = writeProgress(key, progress);
    if (kept === unsaved) { unsaved = !kept; showStatus(); }
  }
  // A drawing dragged or played writes its progress once it rests, not at every frame.
  function saveSoon() {
    if (!saveTimer) saveTimer = window.setTimeout(save, 300);
  }
  window.addEventListener('pagehide', () => { if (saveTimer) save(); });

  function showStatus() {
    const solved = progress.status === 'solved';
    status.dataset.status = progress.status;
    setChildren(status, solved ? (progress.sawWorked ? '✓ Solved (after the worked answer)' : '✓ Solved') : 'Not solved yet',
      ` · ${progress.checks} check${progress.checks === 1 ? '' : 's'}`,
      progress.hintsShown ? ` · ${progress.hintsShown} hint${progress.hintsShown === 1 ? '' : 's'} shown` : '',
      unsaved ? ' · this browser does not keep progress (its storage is full or disabled): your answer stays on this page until you leave it' : ' · kept in this browser');
  }

  // A kind's check is a result, or a promise of one (code: the function runs in the sandbox);
  // Check is disabled while it runs.
  function runCheck() {
    let result;
    try {
      result = kind.check();
    } catch (err) {
      return cannotCheck(err);
    }
    if (result && typeof result.then === 'function') {
      checkButton.disabled = true;
      feedback.dataset.result = 'running';
      setChildren(feedback, h('p', {}, 'Checking…'));
      return result.then(showResult, cannotCheck).finally(() => { checkButton.disabled = false; });
    }
    return showResult(result);
  }

  function cannotCheck(err) {
    delete feedback.dataset.result;
    setChildren(feedback, h('p', { class: 'exercise-wrong' }, `This answer could not be checked: ${err?.message ?? err}`));
    return null;
  }

  function showResult(result) {
    // A wrong check: something named wrong (a walk's wrong pick after right steps too).
    const wrong = !result.correct && !result.incomplete && result.findings.length > 0;
    if (!result.incomplete) {
      progress = { ...progress, checks: progress.checks + 1 };
      if (wrong) progress = { ...progress, wrongChecks: (progress.wrongChecks ?? 0) + 1 };
      if (result.correct && progress.status !== 'solved') progress = { ...progress, status: 'solved', solvedAt: new Date().toISOString() };
    }
    // Hints: at level hint or worked, once the student has checked wrongly hintAfter times.
    const hinting = feedbackLevel.level !== 'check' && (progress.wrongChecks ?? 0) >= feedbackLevel.hintAfter;
    const findings = result.findings.slice(0, 40);
    const hints = hinting && wrong ? findings.filter((f) => f.hint).length : 0;
    if (hints) progress = { ...progress, hintsShown: (progress.hintsShown ?? 0) + hints };
    feedback.dataset.result = result.correct ? 'right' : wrong || result.incomplete ? 'wrong' : 'partial';
    if (result.correct) {
      setChildren(feedback, h('p', { class: 'exercise-right' }, '✓ Right.', result.note ? ` ${result.note}` : ''));
    } else if (result.partial && !result.findings.length) {
      setChildren(feedback, h('p', { class: 'exercise-right' }, result.note ?? 'Right so far.'));
    } else {
      setChildren(feedback, h('p', { class: 'exercise-wrong' }, result.findings.length === 1 ? 'Not yet:' : `Not yet: ${result.findings.length} things to look at.`),
        h('ul', {}, findings.map((f) => h('li', {}, f.text, hinting && wrong && f.hint ? h('span', { class: 'exercise-hint' }, ` Hint: ${f.hint}`) : null))),
        result.findings.length > 40 ? h('p', {}, `… and ${result.findings.length - 40} more.`) : null,
        result.note ? h('p', {}, result.note) : null,
        !hinting && wrong && feedbackLevel.level !== 'check' && findings.some((f) => f.hint)
          ? h('p', { class: 'exercise-hint-later hint' }, `Hints come after ${feedbackLevel.hintAfter} wrong check${feedbackLevel.hintAfter === 1 ? '' : 's'} (${progress.wrongChecks ?? 0} so far).`) : null);
    }
    save();
    showStatus();
    return result;
  }

  function showWorked() {
    if (feedbackLevel.level !== 'worked') return;
    let lines;
    try {
      lines = kind.worked().lines;
    } catch (err) {
      lines = [`The worked answer could not be made: ${err.message}`];
    }
    setChildren(worked, lines.length ? [h('h3', {}, 'Worked answer'), h('ol', {}, lines.map((l) => h('li', {}, l)))] : null);
    worked.hidden = lines.length === 0;
    if (progress.status !== 'solved' && !progress.sawWorked) {
      progress = { ...progress, sawWorked: true };
      save();
    }
  }

  function startAgain() {
    // Nothing more is written on the way out (a pending save would bring the attempt back),
    // and an entry that could not be read nor moved aside stays as it was.
    window.clearTimeout(saveTimer);
    saveTimer = 0;
    leaving = true;
    if (!loaded.stuck) clearProgress(key, { lesson: lesson.id, version: lesson.stateVersion });
    progress = { status: 'started', checks: 0, answer: null, state: null, solvedAt: null, title: exercise.title, lesson: exercise.lesson };
    window.location.reload();
  }

  return {
    root,
    problem: loaded.problem,
    initialState,
    // What the drawing's description says while the exercise is answered: the question, not
    // the lesson's live values (they would read the answer out).
    description: asksNow ? null : `Exercise: ${exercise.title}. ${exercise.question}`,
    stateChanged() {
      kind.stateChanged?.();
      if (keepsState) saveSoon();
      if (!asksNow) {
        try {
          drift.hidden = same(live(), asOpened);
        } catch {
          drift.hidden = false; // (a drawing the exercise cannot be asked of: an edited mesh)
        }
      }
    },
    draw(painter, colors) { kind.draw?.(painter, colors); },
    reset,
    check: runCheck,
  };
}
