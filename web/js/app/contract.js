// @ts-check
// The lesson contract: the one place it is written down. A lesson module exports one object
// of type Lesson; runLesson(lesson) (shell.js) runs it. `setup` runs first and returns the
// lesson's view: a plain object holding everything the lesson builds or caches (DOM
// references, panels, players, per-lesson caches). The shell keeps it and passes it as the
// first argument to every later hook. No hook writes onto the lesson object, onto ctx, or
// into module-level variables. Hooks are read from the lesson object each time they are
// called, so optional hooks may be absent.
//
// Checked by `tsc --noEmit -p jsconfig.json` (the `types` layer of npm test): every
// lesson.js carries `// @ts-check` and annotates its lesson object with
// `/** @type {import('../../app/contract.js').Lesson} */`, so a hook whose parameters do not
// match fails the layer. This file holds no code: nothing to run, only types to import.

/**
 * The lesson's state: one plain, JSON-safe object, validated field by field by `schema`.
 * Every lesson keeps the 2D view of the stage in `state.view`. No state field is named like
 * a member of Ctx (typed `never` here), so a hook written with its parameters shifted (the
 * state where ctx belongs) fails the type check where it uses ctx.
 * @typedef {{ view: CameraView, api?: never, ui?: never, colors?: never, commit?: never,
 *   message?: never, stage?: never, keymap?: never, panels?: never, controls?: never,
 *   [field: string]: any }} State
 */

/**
 * What the stage shows: the world point at the canvas centre and pixels per world unit.
 * @typedef {{ cx: number, cy: number, zoom: number }} CameraView
 */

/**
 * What a lesson's compute returned: everything draw, update and the other hooks show. Opaque
 * to the shell.
 * @typedef {any} Model
 */

/**
 * What a lesson's setup built and returns (DOM references, panels, players, caches). Opaque
 * to the shell, which only hands it back to the lesson's hooks.
 * @typedef {Object<string, any>} View
 */

/**
 * A drawable point of the lesson (world coordinates). `draggable: false` shows it without
 * letting it move.
 * @typedef {{ id: string, x: number, y: number, label: string, draggable?: boolean, [extra: string]: any }} Handle
 */

/**
 * Drawing style for a painter call: stroke and fill colours, width and dash in CSS pixels,
 * font size in pixels, text alignment, alpha, and for text an offset (dx, dy) and a halo;
 * a text is a label (app/label-layout.js): `priority` (higher placed first: the selected
 * element), `fixed` (only its asked place, else dropped).
 * @typedef {{ stroke?: string, fill?: string, width?: number, dash?: number[], font?: number,
 *   align?: string, baseline?: string, alpha?: number, dx?: number, dy?: number, halo?: string,
 *   priority?: number, fixed?: boolean,
 *   [extra: string]: any }} Style
 */

/**
 * The world -> screen transform of a frame (y up in the world, down on screen).
 * @typedef {{ cx: number, cy: number, zoom: number, width: number, height: number,
 *   toScreen(x: number, y: number): number[], toWorld(sx: number, sy: number): number[] }} Transform
 */

/**
 * What draw receives: the canvas painter on screen, the SVG painter for an exported figure;
 * both have this interface (app/painter.js). `xy` is a flat array x0, y0, x1, y1, ... with
 * the given stride (2, or 3 with z ignored). The canvas context itself is not part of the
 * contract: side canvases (plots) are drawn in afterFrame.
 * @typedef {{
 *   t: Transform,
 *   scale: number,
 *   background: string,
 *   clear(): void,
 *   line(ax: number, ay: number, bx: number, by: number, style?: Style): void,
 *   polyline(xy: ArrayLike<number>, style?: Style, stride?: number): void,
 *   polygon(xy: ArrayLike<number>, style?: Style, stride?: number): void,
 *   polygons(xy: ArrayLike<number>, offsets: ArrayLike<number>, style?: Style): void,
 *   segments(xy: ArrayLike<number>, style?: Style): void,
 *   circle(x: number, y: number, radiusPx: number, style?: Style): void,
 *   text(x: number, y: number, string: string, style?: Style): void,
 *   arrow(ax: number, ay: number, bx: number, by: number, style?: Style): void,
 *   legend(entries: Array<Array<any>>): void,
 * }} Painter
 */

/**
 * The lesson canvas (app/stage.js): its element, the current transform, the view fitting a
 * box, and where a world point is on the page.
 * @typedef {{
 *   canvas: HTMLCanvasElement,
 *   transform(): Transform,
 *   fit(minX: number, minY: number, maxX: number, maxY: number, margin?: number): CameraView,
 *   toClient(x: number, y: number): { x: number, y: number },
 *   [extra: string]: any,
 * }} Stage
 */

/**
 * The message line under the toolbar. `action` adds one button (an offer such as "Restore
 * your previous work"). A message shown before an accepted change is cleared by it (the
 * shell: clearIfBefore(the epoch taken when the change began)).
 * @typedef {{
 *   info(text: string, options?: { code?: string, action?: { id?: string, label: string, run(): void } | null, sticky?: boolean }): void,
 *   warn(text: string, options?: { code?: string, action?: { id?: string, label: string, run(): void } | null, sticky?: boolean }): void,
 *   error(text: string, code?: string): void,
 *   clear(): void,
 *   epoch(): number,
 *   clearIfBefore(epoch: number): void,
 *   readonly text: string,
 * }} MessageLine
 */

/**
 * The page's key map (app/keymap.js): a lesson registers its keys in setup. `shownWith`: the
 * panel whose keys they are; they act only while it is shown (in an embed without it they
 * are free for the slides around it).
 * @typedef {{
 *   add(binding: { keys: string[], label: string, group?: string, when?: (event: KeyboardEvent) => boolean, action?: (event: KeyboardEvent) => void, shownWith?: Element }): void,
 *   [extra: string]: any,
 * }} Keymap
 */

/**
 * The presenter-remote actions a lesson may bind (all optional): PageDown/PageUp, Space/k,
 * Home, o/b/. reach them.
 * @typedef {{ next?: () => void, prev?: () => void, playPause?: () => void, reset?: () => void, toggleOverlays?: () => void }} PresenterActions
 */

/**
 * Options of a change: history:false for a change that is not an undo step; coalesce: a key
 * that merges a gesture's many changes into one undo step; recompute:false for a change the
 * model does not depend on (the view).
 * @typedef {{ history?: boolean, coalesce?: string | null, recompute?: boolean }} CommitOptions
 */

/**
 * What a lesson may use (the second-to-last argument of most hooks).
 * @typedef {{
 *   api: any,
 *   readonly state: State,
 *   readonly model: Model,
 *   commit(next: State, options?: CommitOptions): boolean,
 *   setView(view: CameraView): void,
 *   fitView(): void,
 *   render(): void,
 *   refresh(): void,
 *   message: MessageLine,
 *   keymap: Keymap,
 *   ui: { selected: string | null, hover: string | null, hoverPoint: number[] | null, present: boolean, exercise: string | null, exerciseStructure?: string | null },
 *   stage: Stage,
 *   readonly colors: { background: string, ink: string, muted: string, highlight: string, series: string[], [name: string]: any },
 *   panels: HTMLElement,
 *   controls: HTMLElement,
 *   setPresenter(actions: PresenterActions): void,
 *   endGesture(): void,
 * }} Ctx
 *
 * `state` is the accepted state and `model` the model computed from it (null before the
 * first compute). `commit(next)` checks `next` against the schema, recomputes, and keeps
 * the old state with a message if either refuses (returns false). `fitView()` fits the view
 * to the lesson's drawing (lesson.fitView); `endGesture()` ends a coalesced gesture so the
 * next change is its own undo step. `render()` redraws; `refresh()` also updates the panels.
 */

/**
 * One export of the lesson's Export menu; `make` returns the file's content.
 * @typedef {{ label: string, filename: string | ((state: State) => string), type: string,
 *   make(view: View, model: Model, state: State, ctx: Ctx): string | Blob | Promise<string | Blob | null> }} ExportItem
 */

/**
 * A mesh file as the import worker hands it over (app/mesh-import.js): `value` is the
 * imported mesh of a state ({name, positions: number[], faces: number[][]}), `problems`
 * every problem validateMesh found (refuse the file if one is an error).
 * @typedef {{ value: { name: string, positions: number[], faces: number[][] }, problems: any[] }} ImportedMesh
 */

/**
 * A large field stored by content hash (docs/state-format.md, "Large fields").
 * @typedef {{ what?: string, file?: string, export?: string, label(value: any): string, [extra: string]: any }} ContentField
 */

/**
 * What a lesson offers exercises (docs/exercises.md; web/js/exercise/). `kinds`:
 * the kinds of check its drawing gives (exercise/format.js KINDS); `subject`: what a check
 * is asked of, from the lesson's model (exercise/subjects.js lists the shapes); `keepsState`:
 * the kinds whose answer is the drawing itself (kept with the exercise's progress);
 * `usesModel`: `subject` reads the model, so a caller without a page (the grader, in Node)
 * computes it first with `lesson.compute({}, state, { api })`; without it `subject` gets
 * `view = {}` and `model = null` there and works from the state;
 * `showWalk`: the drawing follows a walk being predicted; `markSubdividePoint`: the drawing
 * marks the new point a subdivide exercise asks about; `suggest`: the authoring dialog's
 * starting check, hidden panels and question for a kind, from the view shown (and, where the
 * exercise starts from another drawing, its state: an edit's question starts before the edit).
 * `code`: the code lesson's tasks for the code kind: `check` runs the page's Run (resolving to
 * the run, null when none was made), `result` and `worked` read a run as a check result and
 * a worked answer, `grade` runs a submitted state's code with the grader's sandbox `run`.
 * @typedef {{
 *   kinds: string[],
 *   subject(view: View, model: Model, state: State, ctx: Ctx): { mesh?: any, loaded?: any, edits?: any[], curve?: any, curves?: Object<string, any>, joints?: Array<{ a: any, b: any }>, patch?: any, subdivision?: any, code?: { task: string, sources: Object<string, string> } },
 *   keepsState?: string[],
 *   usesModel?: boolean,
 *   showWalk?: (ctx: Ctx, around: string, element: number) => void,
 *   markSubdividePoint?: (ctx: Ctx, painter: Painter, colors: any, asked: { corners: number[], type: string, label: string }) => void,
 *   suggest?: (kind: string, state: State, asked: { api: any, subject: any }) => { check: any, hide: string[], question: string, state?: State },
 *   code?: {
 *     tasks: Array<{ id: string, title: string, entry: string, params: string[] }>,
 *     check(view: View, task: string): Promise<any>,
 *     result(task: string, ran: any): any,
 *     worked(task: string, ran: any): { lines: string[] },
 *     grade(parts: { api: any, task: string, subject: any, run: (request: any) => Promise<any> }): Promise<any>,
 *   },
 * }} ExerciseSupport
 */

/**
 * The lesson object.
 * @typedef {{
 *   id: string,
 *   title: string,
 *   core: ('mesh' | 'subdivision' | 'curves')[],
 *   stateVersion: number,
 *   exercise?: ExerciseSupport,
 *   schema: Object<string, any>,
 *   migrations?: Object<number, (old: any) => any>,
 *   checkState?: (state: State) => string | null,
 *   contentFields?: Object<string, ContentField>,
 *   defaultState(): State,
 *   setup(ctx: Ctx): View,
 *   compute(view: View, state: State, ctx: Ctx): Model,
 *   update?: (view: View, model: Model, state: State, ctx: Ctx) => void,
 *   draw(view: View, painter: Painter, model: Model, state: State, ctx: Ctx): void,
 *   afterFrame?: (view: View, model: Model, state: State, ctx: Ctx) => void,
 *   handles?: (view: View, model: Model, state: State) => Handle[],
 *   moveHandle?: (view: View, state: State, id: string, x: number, y: number, model: Model) => State | null,
 *   describe?: (view: View, model: Model, state: State) => string,
 *   summarize?: (state: State) => string,
 *   fitView?: (view: View, model: Model, stage: Stage) => CameraView,
 *   click?: (view: View, x: number, y: number, ctx: Ctx, event: PointerEvent) => boolean,
 *   onSelect?: (view: View, id: string | null, ctx: Ctx) => void,
 *   usesHoverPoint?: boolean,
 *   inspector?: false,
 *   exports?: ExportItem[],
 *   importers?: Object<string, (view: View, text: string, state: State, name: string, ctx: Ctx) => State>,
 *   meshImporters?: Object<string, (view: View, mesh: ImportedMesh, state: State, name: string, ctx: Ctx) => State>,
 * }} Lesson
 *
 * `setup` builds panels and controls, registers keys and returns the view. `compute` makes
 * every core call (it may throw: bad input). `update` refreshes the DOM panels (not on pure
 * view changes). `draw` draws on the canvas or the SVG figure, no mathematics. `afterFrame`
 * draws side canvases (plots) after each canvas frame, never for the SVG export. `handles`
 * lists the draggable points; `moveHandle` returns the state with one moved (null: refused).
 * `describe` is the text for screen readers. `summarize` is one line of what a state holds
 * ("grid 4 x 3, 2 edits"), shown with each entry of the History. `click` on empty canvas returns true if the
 * lesson consumed it. `onSelect` follows the selected handle. `usesHoverPoint`: redraw on
 * every pointer move, not only when the hovered handle changes. `inspector: false`: no shell
 * inspector (the lesson has its own inputs). `importers[ext]` turns a file into a state.
 * `meshImporters[ext]` turns a mesh file the import worker read, parsed and checked into a
 * state (app/mesh-import.js: progress, Cancel).
 */

/**
 * What a page entry may hand the shell beside the lesson (runLesson(lesson, options)). The
 * skeleton imports nothing above it (docs/architecture.md, "Layers"): what a lesson page
 * needs from higher up is composed by the page entry (web/js/pages/lesson-page.js) and
 * passed in here. `exercises`: the exercise wiring (exercise/lesson-wiring.js); without it
 * a page opens no exercise link and offers no "Make an exercise". `gpuRenderer`: makes the
 * WebGL2 renderer the stage keeps under the canvas (ui/gl-mesh.js `createGlMesh`; it returns
 * null or throws where the browser has no WebGL2); without it `ctx.stage.gl()` is null and
 * lessons draw with the 2D painter.
 * @typedef {{ exercises?: ExerciseWiring, gpuRenderer?: (canvas: HTMLCanvasElement) => any }} ShellOptions
 */

/**
 * The exercise wiring, as the shell meets it at four points: `open` before the lesson
 * starts (null: the address names no exercise); the opening's `start` once the lesson's
 * panels are built; `named` when the address changes (a page given an exercise link opens
 * afresh); `author` behind "Make an exercise from this view".
 * @typedef {{
 *   open(lesson: Lesson): Promise<ExerciseOpening | null>,
 *   named(hash: string): boolean,
 *   author(parts: { ctx: Ctx, lesson: Lesson, view: View, message: MessageLine }): void,
 * }} ExerciseWiring
 */

/**
 * An exercise link read before the lesson starts. `ready`: its state can be shown (then
 * `restored` is what the page starts on, and the person's own work is neither read nor
 * written meanwhile); `shownOnStart`: the page started on it, so if it cannot be played
 * after all the shell shows the person's own work instead; `refuse(text)`: the core
 * refused its drawing; `start(parts)` says why it cannot be played, or mounts the player.
 * @typedef {{
 *   ready: boolean,
 *   shownOnStart?: boolean,
 *   restored?: any,
 *   refuse(text: string): void,
 *   start(parts: ExerciseParts): ExercisePlayer | null,
 * }} ExerciseOpening
 */

/**
 * What the shell hands a starting exercise: `accept(state, reason)` shows a whole new state
 * as one undoable step (false: refused, nothing changed); `keepInHistory(state, summary)`
 * puts a drawing into the history of replaced work (nothing where the page keeps no work).
 * @typedef {{
 *   ctx: Ctx,
 *   lesson: Lesson,
 *   view: () => View,
 *   panels: HTMLElement,
 *   message: MessageLine,
 *   accept(state: State, reason: string): boolean,
 *   keepInHistory(state: State, summary: string): void,
 * }} ExerciseParts
 */

/**
 * A mounted exercise: the drawing's description while it is answered (null: the lesson's
 * own), what it draws over the lesson's drawing, what it does when the state changes, and
 * the page's Reset (back to the exercise's starting drawing).
 * @typedef {{
 *   description: string | null,
 *   draw(painter: Painter, colors: Ctx['colors']): void,
 *   stateChanged(): void,
 *   reset(): void,
 * }} ExercisePlayer
 */

export {};
