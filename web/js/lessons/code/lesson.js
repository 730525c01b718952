// @ts-check
// "Program the structure": the student writes the lecture's walks as JavaScript over the
// winged-edge (or half-edge) tables; Run tries the function in a sandbox (web/js/code/) on
// the slide's mesh and on hidden meshes the core builds (cases.js), grades every answer
// against the core's (grading.js), and Step plays back every entry the function read, as
// the mesh lesson plays the lecture's walk: the row and column in the tables, the element on
// the drawing, the count of reads beside the lecture's rule's.
// The student's code is the lesson state (state.code: one text per task), so it is kept in
// the history, in a share link and in the saved work, and exported as a .js file. A run's
// results live in the view (they belong to the code they were made from, not to the state).
import { oneOf, integer, text, object, viewSchema } from '../../app/schema.js';
import { h, panel } from '../../app/dom.js';
import { createVirtualTable } from '../../ui/virtual-table.js';
import { sub, num } from '../../ui/mesh/tables.js';
import { createSandbox } from '../../code/sandbox.js';
import { loadWingspline } from '../../core/wingspline.js';
import { elementLabel } from '../../core/element-labels.js';
import { TASKS, TASK_IDS, taskOf, API_REFERENCE } from './tasks.js';
import { lectureCase, HIDDEN_KINDS } from './cases.js';
import { failureText, describeAnswer, countsAsRead } from './grading.js';
import { runTask, resultOfRun, workedLines } from './check.js';
import { projectCase, drawCase } from './draw.js';

// The longest program a state keeps per task (a share link carries the state: docs/code-lesson.md).
export const MAX_CODE_CHARS = 20000;
const COMMIT_AFTER_MS = 400; // typing is committed to the state this long after the last key

const codeSchema = object(Object.fromEntries(TASK_IDS.map((id) => [id, text({ maxLength: MAX_CODE_CHARS })])), { optional: TASK_IDS });

function defaultState() {
  return { task: TASKS[0].id, code: {}, shown: 0, step: 0, view: { cx: 1, cy: 0.5, zoom: 120 } };
}

const sourceOf = (state) => state.code[state.task] ?? taskOf(state.task).starter;

// Which table and which of its columns a trace step names: the winged edge's and the
// half-edge's tables as this lesson draws them.
const WINGED_COLUMNS = { vertex: ['x', 'y', 'z', 'edge'], edge: ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'], face: ['edge'] };
const HALF_COLUMNS = { halfEdge: ['origin', 'twin', 'face', 'next', 'prev'], vertex: ['halfEdge'], face: ['halfEdge'] };
const REFERS = { edge: 'edge', start: 'vertex', end: 'vertex', left: 'face', right: 'face', startLeft: 'edge', startRight: 'edge', endLeft: 'edge', endRight: 'edge', origin: 'vertex', target: 'vertex', twin: 'halfedge', next: 'halfedge', prev: 'halfedge', halfEdge: 'halfedge' };
const FIELD_NAME = { startLeft: 'S:L', startRight: 'S:R', endLeft: 'E:L', endRight: 'E:R', start: 'S', end: 'E', left: 'L', right: 'R' };
const TABLE_KIND = { vertex: 'vertex', edge: 'edge', face: 'face', halfEdge: 'halfedge' };

// A trace step as the lesson says it: "e6.startLeft = e5".
function stepText(step) {
  const row = elementLabel(TABLE_KIND[step.table] ?? 'vertex', step.row);
  if (step.op === 'add') return `added ${row} (a new row)`;
  const value = step.field === 'position' ? `(${(step.value ?? []).map((x) => num(x)).join(', ')})`
    : REFERS[step.field] ? (step.value >= 0 ? elementLabel(REFERS[step.field], step.value) : 'none') : String(step.value);
  const what = step.op === 'write' ? 'wrote' : step.field === 'twin' ? 'twin (arithmetic)' : 'read';
  return `${row}.${step.field} = ${value}${what === 'read' ? '' : ` (${what})`}`;
}

/** @type {import('../../app/contract.js').Lesson} */
export const codeLesson = {
  id: 'code',
  title: 'Program the structure',
  // The subdivision tasks ask the core's subdivision step: the module with every mesh binding.
  core: ['mesh', 'subdivision'],
  stateVersion: 1,
  inspector: false,
  schema: {
    task: oneOf(...TASK_IDS),
    code: codeSchema,
    shown: integer({ min: 0, max: 64 }),
    step: integer({ min: 0, max: 1_000_000 }),
    view: viewSchema(),
  },
  defaultState,
  summarize: (state) => `${taskOf(state.task).title}${state.code[state.task] ? ', your code' : ', the starter'}`,

  // A code exercise (exercise/kinds/code.js): write one task's function; the code in the
  // state is the answer, checked as Run checks it (check.js), on the page and by the grader.
  exercise: {
    kinds: ['code'],
    keepsState: ['code'],
    subject: (view, model, state) => ({ code: { task: state.task, sources: state.code } }),
    // The exercise starts from the starter: the code in the author's editor (a solution,
    // perhaps) is not handed out.
    suggest: (kind, state) => {
      const task = taskOf(state.task);
      return { check: { kind: 'code', task: task.id }, hide: [], question: `Write ${task.entry} in the editor. ${task.statement[0]}`, state: { ...state, code: {}, shown: 0, step: 0 } };
    },
    code: {
      tasks: TASKS.map(({ id, title, entry, params }) => ({ id, title, entry, params })),
      // The page: the lesson's own Run (its results, trace and Step stay on the page).
      check: (view) => view.runNow(),
      result: (id, ran) => resultOfRun(taskOf(id), ran),
      worked: (id, ran) => workedLines(taskOf(id), ran),
      // The grader: the code the submission's state holds for the task (the starter when it
      // holds none), on hidden meshes from a seed of this grading.
      grade: async ({ api, task: id, subject, run }) => {
        const task = taskOf(id);
        const written = subject.code.sources?.[id];
        const source = typeof written === 'string' ? written : task.starter;
        const seed = globalThis.crypto.getRandomValues(new Uint32Array(1))[0];
        return resultOfRun(task, await runTask({ api, checker: () => api, task, source, seed, run }));
      },
    },
  },

  setup(ctx) {
    const view = {
      sandbox: null, // made on the first Run (web/js/code/sandbox.js: a worker with the engine)
      run: null, // the last run: {task, source, cases, grade}
      running: false,
      lecture: new Map(), // task id -> the slide's case (cases.js lectureCase), built once
      projected: new WeakMap(), // case -> its screen-plane positions
      commitTimer: 0,
      typing: false, // keys typed and not yet committed to the state
      focusCase: null, // the case button to focus again after the list is redrawn
      editor: null,
      tables: null,
    };

    // ------------------------------------------------------------------ the task
    const taskSelect = h('select', { id: 'code-task', onchange: () => chooseTask(taskSelect.value) },
      TASKS.map((t) => h('option', { value: t.id }, t.title)));
    const taskBody = panel(ctx.panels, { id: 'task-panel', title: 'The task' });
    const statement = h('div', { class: 'task-statement', id: 'task-statement' });
    const rule = h('ol', { class: 'pseudocode', id: 'task-rule', 'aria-label': 'The lecture\'s rule' });
    const tried = h('details', { class: 'hidden-kinds' }, h('summary', {}, 'The meshes your function is tried on'),
      h('ol', { id: 'hidden-kinds' }, h('li', {}, 'the slide\'s mesh (lecture 000), asked as the statement says'),
        HIDDEN_KINDS.map((k) => h('li', {}, k))),
      h('p', { class: 'hint' }, 'Each run makes the hidden meshes again from a new seed: the elements asked about, the edits and the turned edges change; the kinds stay.'));
    taskBody.append(h('label', { for: 'code-task' }, 'Task ', taskSelect), statement, rule, tried);

    // ------------------------------------------------------------------ the editor
    const codeBody = panel(ctx.panels, { id: 'code-panel', title: 'Your code' });
    const editorBox = h('div', { class: 'code-editor', id: 'code-editor' });
    const runButton = h('button', { type: 'button', id: 'code-run', class: 'primary', onclick: () => runNow() }, 'Run');
    const backButton = h('button', { type: 'button', id: 'code-back', onclick: () => stepBy(-1) }, 'Step back');
    const stepButton = h('button', { type: 'button', id: 'code-step', onclick: () => stepBy(1) }, 'Step');
    const resetButton = h('button', { type: 'button', id: 'code-reset', onclick: () => resetCode() }, 'Reset to the starter');
    const status = h('p', { class: 'code-status', id: 'code-status', role: 'status', 'aria-live': 'polite' });
    codeBody.append(editorBox, h('div', { class: 'button-row' }, runButton, backButton, stepButton, resetButton),
      h('p', { class: 'hint' }, 'Ctrl+Enter runs (in the editor too). Escape then Tab leaves the editor. Step and Step back (n and b outside the editor) go through every entry your function read.'), status);
    // The editor (CodeMirror, ui/code-editor.js) is fetched as a part of its own, so that
    // this lesson object loads without it where there is no page (the exercise grader in Node).
    editorBox.append(h('p', { class: 'hint', id: 'editor-loading' }, 'Loading the editor…'));
    import('../../ui/code-editor.js').then(({ createCodeEditor }) => {
      editorBox.replaceChildren();
      view.editor = createCodeEditor({
        parent: editorBox, label: 'Your code', doc: sourceOf(ctx.state),
        onChange: (source) => typed(source), onRun: () => runNow(),
      });
      editorBox.dataset.ready = 'true';
      ctx.refresh();
    }, (err) => {
      editorBox.replaceChildren(h('p', { class: 'callout warning' }, `The editor could not be loaded (${err?.message ?? err}). Reload the page to try again.`));
    });

    // ------------------------------------------------------------------ results and trace
    const resultBody = panel(ctx.panels, { id: 'result-panel', title: 'Results' });
    const caseList = h('ol', { class: 'case-list', id: 'case-list' });
    const verdict = h('p', { id: 'code-verdict' });
    const failure = h('p', { id: 'code-failure', class: 'callout', hidden: true });
    resultBody.append(verdict, failure, caseList);

    const apiBody = panel(ctx.panels, { id: 'api-panel', title: 'What your function can read', open: false });

    // Under the drawing: the trace's step and the tables of the case shown.
    const traceLine = h('p', { class: 'trace-line', id: 'trace-line', 'aria-live': 'polite' });
    const readsLine = h('p', { class: 'reads-line', id: 'reads-line' });
    const tablesBox = h('div', { class: 'code-tables', id: 'code-tables' });
    // What the function printed with console.log on the case shown (the sandbox keeps 200 lines).
    const logs = h('pre', { class: 'code-logs', id: 'code-logs', hidden: true, 'aria-label': 'What your function printed (console.log)' });
    ctx.controls.replaceChildren(h('div', { class: 'code-under' }, traceLine, readsLine, logs, tablesBox));

    // ------------------------------------------------------------------ actions
    const currentSource = () => view.editor?.text ?? sourceOf(ctx.state);
    function typed(source) {
      view.typing = true;
      clearTimeout(view.commitTimer);
      view.commitTimer = Number(setTimeout(() => commitCode(source), COMMIT_AFTER_MS));
      status.textContent = view.run && view.run.source !== source ? 'The code changed since the last run: Run again to see its results.' : status.textContent;
    }
    function commitCode(source) {
      clearTimeout(view.commitTimer);
      const state = ctx.state;
      // Refused (too long), the text stays the editor's: typing stays true, so no update
      // writes the older saved code over it.
      view.typing = source.length > MAX_CODE_CHARS;
      if (sourceOf(state) === source) return true;
      if (source.length > MAX_CODE_CHARS) {
        ctx.message.warn(`Your code is ${source.length.toLocaleString('en')} characters long; a saved lesson keeps at most ${MAX_CODE_CHARS.toLocaleString('en')} per task. Shorten it to keep it.`);
        return false;
      }
      return ctx.commit({ ...state, code: { ...state.code, [state.task]: source } }, { coalesce: `code-${state.task}` });
    }
    function chooseTask(id) {
      if (id === ctx.state.task) return;
      commitCode(currentSource());
      ctx.commit({ ...ctx.state, task: id, shown: 0, step: 0 });
    }
    // A change to the code from outside the editor drops the typing not yet committed.
    const dropTyping = () => { clearTimeout(view.commitTimer); view.typing = false; };
    function resetCode() {
      dropTyping();
      const state = ctx.state;
      const { [state.task]: _old, ...rest } = state.code;
      if (ctx.commit({ ...state, code: rest, shown: 0, step: 0 })) ctx.message.info('Back to the starter. Undo (Ctrl+Z outside the editor, or the History) brings your code back.');
    }
    function stepBy(delta) {
      const shown = shownCase(view, ctx.state);
      const n = shown.grade?.trace.length ?? 0;
      if (!n) { status.textContent = view.run ? 'This case has no reads to step through.' : 'Run your code first: Step goes through what it read.'; return; }
      const step = Math.max(0, Math.min(n, ctx.state.step + delta));
      ctx.commit({ ...ctx.state, step }, { history: false });
    }
    // Resolves to the run (check.js runTask's {cases, grade, error}), or null when none was
    // made (a run already going, code too long to keep).
    async function runNow() {
      if (view.running) return null;
      const source = currentSource();
      if (!commitCode(source) && sourceOf(ctx.state) !== source) return null;
      const task = taskOf(ctx.state.task);
      view.running = true;
      runButton.disabled = true;
      view.editor?.showError(null);
      status.textContent = 'Running on the slide\'s mesh and the hidden meshes…';
      try {
        const seed = crypto.getRandomValues(new Uint32Array(1))[0];
        view.sandbox ??= createSandbox();
        const sandbox = view.sandbox;
        const answer = await runTask({
          api: ctx.api, task, source, seed,
          checker: () => loadWingspline({ parts: [...codeLesson.core, 'exercises'] }),
          run: (request) => sandbox.run(request),
          onMesh: (k, of) => { status.textContent = `Running on mesh ${k} of ${of}…`; },
        });
        const { cases } = answer;
        if (answer.error) {
          view.run = { task: task.id, source, cases, grade: null, error: answer.error };
          if (ctx.state.task !== task.id) return answer;
          view.editor?.showError(answer.error.line ? answer.error : null);
          view.editor?.markLine(answer.error.line ?? null);
          status.textContent = answer.error.line ? `Line ${answer.error.line}${answer.error.column ? `, column ${answer.error.column}` : ''}: ${answer.error.message}` : answer.error.message;
        } else {
          const { grade } = answer;
          view.run = { task: task.id, source, cases, grade, error: null };
          // Switched to another task meanwhile: the results wait for it, the page stays put.
          if (ctx.state.task !== task.id) return answer;
          const failed = grade.firstFail;
          const err = failed !== null ? grade.cases[failed].error : null;
          view.editor?.showError(err?.line ? err : null);
          view.editor?.markLine(err?.line ?? null);
          status.textContent = failed === null ? `All ${grade.asked} meshes passed.` : `${grade.passed} of ${grade.asked} meshes passed; the first that did not is shown.`;
          if (ctx.commit({ ...ctx.state, shown: failed ?? 0, step: 0 }, { history: false })) ctx.fitView();
        }
        return answer;
      } catch (err) {
        status.textContent = `The run could not finish: ${err?.message ?? err}`;
        return { cases: [], grade: null, error: { kind: 'host', message: `The run could not finish: ${err?.message ?? err}`, line: null, column: null } };
      } finally {
        view.running = false;
        runButton.disabled = false;
        ctx.refresh();
      }
    }

    ctx.keymap.add({ keys: ['Ctrl+Enter'], label: 'run your code', group: 'Code', action: () => runNow() });
    ctx.keymap.add({ keys: ['n', 'PageDown', 'ArrowRight'], label: 'next entry your function read', group: 'Code', shownWith: codeBody, action: () => stepBy(1) });
    ctx.keymap.add({ keys: ['b', 'PageUp', 'ArrowLeft'], label: 'previous entry', group: 'Code', shownWith: codeBody, action: () => stepBy(-1) });
    ctx.keymap.add({ keys: ['Home'], label: 'before the first read', group: 'Code', shownWith: codeBody, action: () => stepBy(-Infinity) });
    ctx.keymap.add({ keys: ['End'], label: 'after the last read', group: 'Code', shownWith: codeBody, action: () => stepBy(Infinity) });
    ctx.setPresenter({ next: () => stepBy(1), prev: () => stepBy(-1), reset: () => stepBy(-Infinity) });

    Object.assign(view, { taskSelect, statement, rule, status, caseList, verdict, failure, apiBody, traceLine, readsLine, logs, tablesBox, runNow, stepBy, focusEditor: () => view.editor?.focus(), chooseCase: (i) => { view.focusCase = i; if (ctx.commit({ ...ctx.state, shown: i, step: 0 }, { history: false })) ctx.fitView(); } });
    return view;
  },

  compute(view, state, ctx) {
    const task = taskOf(state.task);
    if (!view.lecture.has(task.id)) view.lecture.set(task.id, lectureCase(ctx.api, task));
    const source = sourceOf(state);
    const shown = shownCase(view, state);
    return { task, source, shown, stale: Boolean(view.run && (view.run.task !== task.id || view.run.source !== source)) };
  },

  fitView(view, model, stage) {
    const P = projected(view, model.shown.case);
    const held = model.shown.case.snapshot.winged.vertexEdge; // -1: a removed vertex, not drawn
    let minX = Infinity; let minY = Infinity; let maxX = -Infinity; let maxY = -Infinity;
    for (let v = 0; v < held.length; v += 1) {
      if (held[v] < 0) continue;
      const k = 3 * v;
      minX = Math.min(minX, P[k]); maxX = Math.max(maxX, P[k]); minY = Math.min(minY, P[k + 1]); maxY = Math.max(maxY, P[k + 1]);
    }
    return stage.fit(minX, minY, maxX, maxY, 0.12);
  },

  update(view, model, state, ctx) {
    const { task, shown } = model;
    view.taskSelect.value = task.id;
    // The state's code, unless the student is typing (committed COMMIT_AFTER_MS after the last key).
    if (!view.typing) view.editor?.setText(model.source);
    view.statement.replaceChildren(...task.statement.map((p) => h('p', {}, p)));
    view.rule.replaceChildren(...task.rule.map((line) => h('li', {}, line)));
    view.apiBody.replaceChildren(h('dl', { class: 'api-reference', id: 'api-reference' },
      API_REFERENCE[task.structure].flatMap(([code, what]) => [h('dt', {}, h('code', {}, code)), h('dd', {}, what)])),
    h('p', { class: 'hint' }, 'Numbers are 0-based: the drawing\'s e₁ is edge 0. None is -1. Your code runs in a sandbox that sees only the mesh: no page, no storage, no network; a run stops after 1.5 s per mesh.'));

    // The results of the last run, if it was of this code.
    const run = view.run && !model.stale ? view.run : null;
    const grade = run?.grade ?? null;
    view.verdict.textContent = model.stale ? 'The code changed since the last run: Run to try it.'
      : !run ? 'Not run yet: Run tries your function on the slide\'s mesh, then on the hidden meshes.'
        : run.error ? 'Your code did not start: see the message under the editor.'
          : grade.firstFail === null ? `✓ Every mesh passed (${grade.passed} of ${grade.asked}).` : `✗ ${grade.passed} of ${grade.asked} meshes passed.`;
    view.verdict.dataset.passed = grade ? String(grade.firstFail === null) : '';
    const failed = grade && grade.firstFail !== null ? grade.cases[grade.firstFail] : null;
    view.failure.hidden = !failed;
    // While a code exercise is answered the core's answers stay hidden (its feedback levels):
    // the failure and the reads line say what the function returned and where, not the answer.
    const exercise = ctx.ui.exercise === 'code';
    view.failure.textContent = !failed ? '' : exercise ? resultOfRun(task, { grade, error: null }).findings[0].text : failureText(task, failed);
    const counted = (g) => (task.answer === 'edit'
      ? ` — ${g.reads} read${g.reads === 1 ? '' : 's'}, ${g.writes} written (the core's edit writes ${g.referenceReads})`
      : ` — ${g.reads} read${g.reads === 1 ? '' : 's'}${g.referenceReads === null ? '' : ` (the lecture's rule: ${g.referenceReads})`}`);
    view.caseList.replaceChildren(...(grade?.cases ?? []).map((g, i) => h('li', { class: !g.asked ? 'is-skipped' : g.ok ? 'is-passed' : 'is-failed', 'aria-current': i === state.shown ? 'true' : null },
      h('button', { type: 'button', class: 'link-button', 'data-case': i, onclick: () => view.chooseCase(i) }, `${!g.asked ? '–' : g.ok ? '✓' : '✗'} ${g.label}`),
      !g.asked ? ` — not asked: ${g.skipped}` : g.error?.kind === 'skipped' ? ' — not run' : counted(g))));
    // The list is drawn again: the case a person chose by keyboard keeps the focus.
    if (view.focusCase !== null) {
      /** @type {HTMLElement | null} */ (view.caseList.querySelector(`[data-case="${view.focusCase}"]`))?.focus();
      view.focusCase = null;
    }

    // The trace at the step, and the case's tables.
    const trace = shown.grade?.trace ?? [];
    const step = Math.min(state.step, trace.length);
    const current = step > 0 ? trace[step - 1] : null;
    const readsSoFar = trace.slice(0, step).filter(countsAsRead).length;
    const label = shown.case.label.charAt(0).toUpperCase() + shown.case.label.slice(1);
    view.traceLine.textContent = !shown.grade ? `${label}: run your code to trace what it reads.`
      : !shown.grade.asked ? `${label}: not asked.`
      : current ? `Read ${step} of ${trace.length}: ${stepText(current)}` : `${trace.length} entries read on ${shown.case.label}. Step to follow them.`;
    const g = shown.grade;
    view.readsLine.textContent = !g || !g.asked ? (g?.skipped ? `Not asked: ${g.skipped}.` : '')
      : task.answer === 'edit'
        ? `Your function read ${g.reads} entr${g.reads === 1 ? 'y' : 'ies'}${step ? ` (${readsSoFar} so far)` : ''} and wrote ${g.writes}; the core's ${task.op} writes ${g.referenceReads}. ${g.error ? 'It stopped with an error.' : g.ok ? 'The tables it left are the edited mesh\'s winged edge: applied.' : 'The tables it left were refused: nothing was applied.'}`
        : `Your function read ${g.reads} entr${g.reads === 1 ? 'y' : 'ies'}${step ? ` (${readsSoFar} so far)` : ''}${g.referenceReads === null ? '' : `; the lecture's rule reads ${g.referenceReads}`}. It returned ${g.error ? 'an error' : describeAnswer(task, g.value)}${exercise ? (g.ok ? ', the core\'s answer' : ', not the core\'s answer') : `; expected ${describeAnswer(task, shown.case.expected)}`}.`;
    const printed = g?.logs ?? [];
    view.logs.hidden = printed.length === 0;
    view.logs.textContent = printed.length ? `console.log:\n${printed.join('\n')}` : '';
    // An edit's tables show the entries written up to the step.
    const written = new Map();
    for (const t of trace.slice(0, step)) if (t.op === 'write') written.set(`${t.table}:${t.row}:${t.field}`, t.value);
    showTables(view, task, shown.case, current, written);
  },

  draw(view, painter, model, state, ctx) {
    const { shown, task } = model;
    const c = shown.case;
    const trace = shown.grade?.trace ?? [];
    const current = state.step > 0 ? trace[Math.min(state.step, trace.length) - 1] : null;
    const marked = { vertex: new Set(), edge: new Set(), face: new Set() };
    if (current) {
      const kind = TABLE_KIND[current.table];
      if (kind === 'halfedge') marked.edge.add(current.row >> 1);
      else marked[kind].add(current.row);
      const refers = REFERS[current.field];
      if (refers && current.value >= 0) {
        if (refers === 'halfedge') marked.edge.add(current.value >> 1); else marked[refers].add(current.value);
      }
    }
    const asked = { vertex: new Set(), edge: new Set(), face: new Set() };
    if (c.args) task.params.forEach((kind, k) => asked[kind].add(c.args[k]));
    drawCase(painter, c, projected(view, c), marked, asked, ctx.colors);
  },

  // The vertices of the case shown, to select and hear (not to drag: the drawing is a view
  // of the tables): ] and [ on the drawing go through them, and Fit brings them back.
  handles(view, model) {
    const c = model.shown.case;
    const P = projected(view, c);
    const V = c.snapshot.winged.vertexEdge;
    const out = [];
    for (let v = 0; v < V.length && out.length < 400; v += 1) {
      if (V[v] >= 0) out.push({ id: `v${v}`, x: P[3 * v], y: P[3 * v + 1], label: elementLabel('vertex', v), draggable: false });
    }
    return out;
  },

  describe(view, model) {
    return `The mesh of the case shown: ${model.shown.case.label}.`;
  },

  exports: [{
    label: 'Your code (.js)',
    filename: (state) => `${taskOf(state.task).entry}.js`,
    type: 'text/javascript',
    make: (view, model) => model.source,
  }],
  importers: {
    js: (view, source, state) => {
      clearTimeout(view.commitTimer);
      view.typing = false;
      if (source.length > MAX_CODE_CHARS) throw new Error(`the file has ${source.length.toLocaleString('en')} characters; a task keeps at most ${MAX_CODE_CHARS.toLocaleString('en')}`);
      return { ...state, code: { ...state.code, [state.task]: source }, shown: 0, step: 0 };
    },
  },
};

// The case on the drawing: the one picked among the last run's (if that run was of this
// task and code), else the slide's mesh.
function shownCase(view, state) {
  const run = view.run;
  const source = sourceOf(state);
  if (run && run.task === state.task && run.source === source && run.grade) {
    const i = Math.min(state.shown, run.cases.length - 1);
    return { case: run.cases[i], grade: run.grade.cases[i], index: i };
  }
  return { case: view.lecture.get(state.task), grade: null, index: 0 };
}

function projected(view, c) {
  if (!view.projected.has(c)) view.projected.set(c, projectCase(c));
  return view.projected.get(c);
}

// The tables of the case shown (the structure the task reads), the trace's row and column marked.
function showTables(view, task, c, current, written) {
  const key = `${task.structure}`;
  if (!view.tables || view.tables.key !== key) {
    view.tables = { key, list: makeTables(task.structure, view) };
    view.tablesBox.replaceChildren(...view.tables.list.map((t) => t.table.root));
  }
  view.tables.case = c;
  view.tables.written = written;
  for (const t of view.tables.list) {
    t.table.refresh(t.count(c));
    const hit = current && current.table === t.name ? current : null;
    const col = hit ? t.columns.indexOf(hit.field === 'position' ? 'x' : hit.field) + 1 : 0;
    t.table.mark({ rows: { 'is-highlighted': hit ? [hit.row] : [] }, read: hit && col > 0 ? [[hit.row, col]] : [] });
    if (hit) t.table.reveal(hit.row);
  }
}

function makeTables(structure, view) {
  const label = (kind, i) => (i >= 0 ? sub({ vertex: 'v', edge: 'e', face: 'F', halfedge: 'h' }[kind], i) : '');
  const cell = (field, value) => (REFERS[field] ? label(REFERS[field], value) : num(value));
  const make = (name, kind, columns, count, value, head) => {
    const table = createVirtualTable({
      id: `code-${name}-table`, caption: `${{ vertex: 'Vertex', edge: 'Edge', face: 'Face', halfEdge: 'Half-edge' }[name]} table`,
      head: head ?? [['', ...columns.map((c) => FIELD_NAME[c] ?? c)]],
      rowLabel: (i) => label(kind, i),
      row: (i) => columns.map((c) => {
        const key = `${name}:${i}:${c}`;
        return cell(c, view.tables.written?.has(key) ? view.tables.written.get(key) : value(view.tables.case, i, c));
      }),
    });
    return { name, columns, count, table };
  };
  if (structure === 'half-edge') {
    const he = (c) => c.snapshot.halfEdge;
    return [
      make('halfEdge', 'halfedge', HALF_COLUMNS.halfEdge, (c) => he(c).origin.length, (c, i, f) => (f === 'twin' ? (he(c).origin[i] >= 0 ? i ^ 1 : -1) : he(c)[f][i])),
      make('vertex', 'vertex', HALF_COLUMNS.vertex, (c) => he(c).vertexHalfedge.length, (c, i) => he(c).vertexHalfedge[i]),
      make('face', 'face', HALF_COLUMNS.face, (c) => he(c).faceHalfedge.length, (c, i) => he(c).faceHalfedge[i]),
    ];
  }
  const w = (c) => c.snapshot.winged;
  const edgeHead = [[{ text: '', colspan: 5 }, { text: 'S', colspan: 2 }, { text: 'E', colspan: 2 }], ['', 'S', 'E', 'L', 'R', 'L', 'R', 'L', 'R']];
  return [
    make('vertex', 'vertex', WINGED_COLUMNS.vertex, (c) => w(c).vertexEdge.length, (c, i, f) => (f === 'edge' ? w(c).vertexEdge[i] : w(c).positions[3 * i + 'xyz'.indexOf(f)])),
    make('edge', 'edge', WINGED_COLUMNS.edge, (c) => w(c).edges.length / 8, (c, i, f) => w(c).edges[8 * i + w(c).edgeFields.indexOf(f)], edgeHead),
    make('face', 'face', WINGED_COLUMNS.face, (c) => w(c).faceEdge.length, (c, i) => w(c).faceEdge[i]),
  ];
}
