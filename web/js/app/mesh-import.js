// @ts-check
// The page's side of a mesh file import: starts the import worker
// (mesh-import-worker.js) for one File, shows its progress (a <progress> with a label naming
// the stage: reading, parsing, checking, building) and a Cancel button (Escape cancels too),
// and turns the worker's flat arrays into the imported value of a lesson state in pieces, so
// no task of the page runs long. Cancelling terminates the worker: nothing of the page's state
// was touched, and the message says so.
import { WingsplineError } from '../core/errors.js';
import { h } from './dom.js';
import { rememberContent } from './share-link.js';
import { IMPORT_STAGES } from './mesh-import-job.js';
import { copyInto } from './imported-mesh.js';

// Faces turned into arrays per task while building the imported value (about 10 ms each for
// triangles on a school laptop).
const FACES_PER_TASK = 50000;

// The flat arrays of an imported value, for the lessons' bulk build (api.buildMesh accepts
// {positions, faceOffsets, faceVertices}): no second conversion of a million faces.
const flatArrays = new WeakMap();
/** @returns {{positions: Float64Array, faceOffsets: Int32Array, faceVertices: Int32Array} | null} */
export function importedArrays(value) {
  return (value && flatArrays.get(value)) ?? null;
}

const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });
const mb = (bytes) => (bytes / 2 ** 20).toFixed(1);

// The core mesh of an imported value, built in steps while the progress showed 'building'
// (api.buildMeshInSteps: one phase of the core's build per task, so a million faces never
// hold the page for 110 ms at once). A lesson's mesh source takes it (takeImportedMesh)
// instead of building the same mesh again; one not taken is disposed when the import ends.
const prebuiltMeshes = new WeakMap();
/** @returns {any} the Mesh built for `value`, now the caller's; null if there is none */
export function takeImportedMesh(value) {
  const mesh = (value && prebuiltMeshes.get(value)) ?? null;
  if (mesh) prebuiltMeshes.delete(value);
  return mesh;
}

/**
 * @param {{ message: import('./contract.js').MessageLine, contents: any, announceStatus: (text: string) => void, api?: () => any }} parts
 */
export function createMeshImport({ message, contents, announceStatus, api = () => null }) {
  const label = h('label', { for: 'import-progress', id: 'import-stage' });
  const bar = /** @type {HTMLProgressElement} */ (h('progress', { id: 'import-progress', max: '1' }));
  const cancelButton = h('button', { type: 'button', class: 'tool', id: 'import-cancel', onclick: () => cancel() }, 'Cancel');
  const box = h('div', { class: 'import-progress', id: 'import-box', role: 'group', 'aria-label': 'Import', hidden: true }, label, bar, cancelButton);
  let running = null; // { worker, name, cancelled, resolve }

  function placeBox() {
    if (box.isConnected) return;
    const anchor = document.getElementById('message');
    if (anchor) anchor.after(box); else document.body.prepend(box);
  }

  function show(name, stage, done, total) {
    const names = { reading: 'Reading', parsing: 'Parsing', checking: 'Checking', building: 'Building' };
    const amount = stage === 'reading' && total ? `: ${mb(done)} of ${mb(total)} MB` : '…';
    label.textContent = `${names[stage] ?? stage} ${name}${amount}`;
    box.dataset.stage = stage;
    if (stage === 'reading' && total) bar.value = done / total;
    else bar.removeAttribute('value'); // indeterminate: the core does not report within a stage
    box.hidden = false;
  }

  let focusBefore = null; // where the keyboard was before Cancel took it: given back after
  function hide() {
    const hadFocus = box.contains(document.activeElement);
    box.hidden = true;
    window.removeEventListener('keydown', onKey, true);
    if (hadFocus && focusBefore?.isConnected) focusBefore.focus({ preventScroll: true });
    focusBefore = null;
  }

  function onKey(event) {
    if (event.key !== 'Escape' || !running) return;
    event.preventDefault();
    event.stopPropagation();
    cancel();
  }

  function cancel() {
    if (!running) return;
    const { worker, name, resolve, value } = running;
    running.cancelled = true;
    running = null;
    takeImportedMesh(value)?.dispose(); // built already: nobody will take it
    worker.terminate();
    hide();
    const text = `Import of ${name} cancelled; your mesh and work are unchanged.`;
    message.info(text);
    announceStatus(text);
    resolve(null);
  }

  // Resolves to { value, problems } (value: {name, positions, faces}, its flat arrays kept
  // for importedArrays), or null when cancelled; rejects with the worker's error (code,
  // message, line). The progress stays shown at 'building' until finish().
  function run(file, format, name) {
    if (running) cancel();
    placeBox();
    return new Promise((resolve, reject) => {
      const worker = new Worker(new URL('../app/mesh-import-worker.js', import.meta.url), { type: 'module', name: 'mesh-import' });
      const job = { worker, name, cancelled: false, resolve, value: null };
      running = job;
      window.addEventListener('keydown', onKey, true);
      show(name, 'reading', 0, file.size);
      focusBefore = box.contains(document.activeElement) ? focusBefore : document.activeElement;
      cancelButton.focus({ preventScroll: true });
      const fail = (err) => {
        if (running === job) running = null;
        worker.terminate();
        hide();
        reject(err);
      };
      worker.addEventListener('error', (event) => {
        event.preventDefault();
        fail(new WingsplineError('import-error', `the import worker stopped (${event.message || 'it could not be started'})`));
      });
      worker.addEventListener('message', async (event) => {
        const m = event.data;
        if (job.cancelled) return;
        if (m.type === 'progress') { show(name, m.stage, m.done, m.total); return; }
        if (m.type === 'error') {
          const err = new WingsplineError(m.code, m.message);
          if (m.line !== undefined) /** @type {any} */ (err).line = m.line;
          fail(err);
          return;
        }
        worker.terminate();
        show(name, 'building');
        try {
          const value = await buildValue(job, name, m);
          if (!value) return; // cancelled while building
          job.value = value;
          // A mesh with errors is not built: the lesson's importer shows the whole report.
          const buildable = !(m.problems ?? []).some((p) => p.severity === 'error');
          if (buildable && !(await prebuild(job, value, m))) return; // cancelled while building
          if (m.content?.stored) {
            rememberContent(value, m.content);
            contents?.markStored?.(m.content.hash);
          }
          // A task of its own for what follows (the lesson's importer and the state check).
          await nextTask();
          if (job.cancelled) return;
          resolve({ value, problems: m.problems });
        } catch (err) {
          fail(err);
        }
      });
      worker.postMessage({ file, format, name });
    });
  }

  // The imported value (the flat form, imported-mesh.js) from the worker's typed arrays, in
  // pieces of FACES_PER_TASK faces per task; null if cancelled.
  async function buildValue(job, name, { positions, faceOffsets, faceVertices }) {
    const F = faceOffsets.length - 1;
    const faceSizes = [];
    const corners = [];
    const points = [];
    for (let first = 0; first < F; first += FACES_PER_TASK) {
      const end = Math.min(F, first + FACES_PER_TASK);
      for (let f = first; f < end; f += 1) faceSizes.push(faceOffsets[f + 1] - faceOffsets[f]);
      copyInto(corners, faceVertices, faceOffsets[first], faceOffsets[end]);
      await nextTask();
      if (job.cancelled) return null;
    }
    for (let first = 0; first < positions.length; first += 3 * FACES_PER_TASK) {
      copyInto(points, positions, first, Math.min(positions.length, first + 3 * FACES_PER_TASK));
      await nextTask();
      if (job.cancelled) return null;
    }
    const value = { name: name.slice(0, 120), positions: points, faceSizes, faceVertices: corners };
    flatArrays.set(value, { positions, faceOffsets, faceVertices });
    return value;
  }

  // The core mesh of the value, in steps (takeImportedMesh); false if cancelled meanwhile.
  async function prebuild(job, value, { positions, faceOffsets, faceVertices }) {
    const core = api();
    if (!core?.buildMeshInSteps) return true;
    const build = core.buildMeshInSteps({ positions, faceOffsets, faceVertices });
    for (;;) {
      await nextTask();
      if (job.cancelled) { build.cancel(); return false; }
      if (build.step()) break;
    }
    if (job.cancelled) { build.mesh.dispose(); return false; }
    prebuiltMeshes.set(value, build.mesh);
    return true;
  }

  // The import is over (accepted or refused): the progress goes, Escape is the page's again,
  // and a core mesh built for it that no lesson took is freed.
  function finish() {
    const value = running?.value;
    if (running && !running.cancelled) running = null;
    takeImportedMesh(value)?.dispose();
    hide();
  }

  return { run, finish, cancel, stages: IMPORT_STAGES, get busy() { return running !== null; } };
}
