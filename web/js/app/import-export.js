// @ts-check
// Files in and out of a lesson. Export: the state (JSON), the figure (SVG, PNG) and the
// lesson's own exports. Import: a state (JSON) or a file one of the lesson's importers
// reads, from the file picker or dropped on the page. An imported file is read, checked
// against the schema and computed before anything changes (the shell's accept); a refusal
// names the file (as text) and the reason, and the lesson keeps what it had.
import { WingsplineError } from '../core/errors.js';
import { readEnvelopeResolved, envelopeJson } from './share-link.js';
import { checkChange } from './schema.js';
import { download, installImport } from './file-io.js';
import { h } from './dom.js';
import { errorText } from './message-line.js';
import { createMeshImport } from './mesh-import.js';

/**
 * @typedef {import('./contract.js').Lesson} Lesson
 * @typedef {import('./contract.js').State} State
 * @param {{
 *   lesson: Lesson,
 *   contents: any,
 *   hookArgs: () => [import('./contract.js').View, import('./contract.js').Model, State, import('./contract.js').Ctx],
 *   svgFigure: () => string,
 *   pngFigure: () => Promise<Blob | null>,
 *   accept: (next: State, reason: string, report: (err: any) => void) => boolean,
 *   message: import('./contract.js').MessageLine,
 *   announceStatus: (text: string) => void,
 * }} parts
 */
export function createImportExport({ lesson, contents, hookArgs, svgFigure, pngFigure, accept, message, announceStatus }) {
  const state = () => hookArgs()[2];
  /** @type {import('./contract.js').ExportItem[]} */
  const exportItems = [
    { label: 'Lesson state (JSON)', filename: `${lesson.id}-state.json`, type: 'application/json',
      make: () => envelopeJson(lesson, state()) },
    { label: 'Figure (SVG)', filename: `${lesson.id}.svg`, type: 'image/svg+xml', make: svgFigure },
    { label: 'Figure (PNG)', filename: `${lesson.id}.png`, type: 'image/png',
      make: pngFigure },
    ...(lesson.exports ?? []),
  ];

  async function runExport(item) {
    try {
      const content = await item.make(...hookArgs());
      download(typeof item.filename === 'function' ? item.filename(state()) : item.filename, content, item.type);
    } catch (err) {
      message.error(`Export failed: ${errorText(err)}`);
    }
  }

  const meshTypes = Object.keys(lesson.meshImporters ?? {});
  const importTypes = ['.json', ...[...Object.keys(lesson.importers ?? {}), ...meshTypes].map((ext) => `.${ext}`)];
  // The picker is opened by a real button (visible focus, keyboard); the input stays hidden.
  const fileInput = /** @type {HTMLInputElement} */ (h('input', { type: 'file', accept: importTypes.join(','), hidden: true, id: 'import-file', tabindex: '-1', 'aria-label': 'Import a file' }));

  // The state a file holds, checked; throws an 'import-error' naming the reason.
  async function readImport(name, text) {
    const ext = name.toLowerCase().split('.').pop();
    const refuse = (reason) => { throw new WingsplineError('import-error', reason); };
    let next;
    if (ext === 'json') {
      let data;
      try { data = JSON.parse(text); } catch { refuse('it is not valid JSON'); }
      let read;
      try { read = await readEnvelopeResolved(lesson, data, { contents }); } catch (err) { refuse(err.message); }
      if (read.problems.length) refuse(`it does not hold a valid state (${read.problems[0]})`);
      next = read.state;
    } else if (lesson.importers?.[ext]) {
      const [view, , current, ctx] = hookArgs();
      next = lesson.importers[ext](view, text, current, name, ctx);
    } else {
      refuse(`this lesson imports ${importTypes.join(', ')} files`);
    }
    // The same limits as a link read back (a face of 1001 corners, a coordinate of 5e9).
    const outside = checkChange(lesson.schema, next, state(), lesson.checkState);
    if (outside) refuse(outside);
    return next;
  }

  // A lesson's importer may refuse with one way out (err.offer: {id, label, run}), e.g. the
  // subdivision lesson's "Use Catmull-Clark" for a quad mesh under Loop.
  const refusal = (name) => (err) => (err?.offer
    ? message.warn(`${name} was not imported: ${errorText(err)}`, { code: err.code, action: err.offer })
    : message.error(`${name} was not imported: ${errorText(err)}`, err?.code ?? 'import-error'));

  function acceptImport(name, next, refused) {
    if (accept(next, 'import', refused)) {
      message.info(`Imported ${name}`);
      announceStatus(`Imported ${name}`);
    }
  }

  async function importFile({ name, text }) {
    const refused = refusal(name);
    let next;
    try {
      next = await readImport(name, text);
    } catch (err) {
      refused(err);
      return;
    }
    acceptImport(name, next, refused);
  }

  // Mesh files: read, parsed and checked by the import worker, with progress and
  // Cancel; the lesson turns the result into a state, checked as any import is.
  const meshImport = meshTypes.length ? createMeshImport({ message, contents, announceStatus, api: () => hookArgs()[3].api }) : null;
  async function importMeshFile(file, ext) {
    const name = file.name;
    const refused = refusal(name);
    try {
      const result = await meshImport.run(file, ext, name);
      if (!result) return; // cancelled: nothing changed
      const [view, , current, ctx] = hookArgs();
      const next = lesson.meshImporters[ext](view, result, current, name, ctx);
      const outside = checkChange(lesson.schema, next, state(), lesson.checkState);
      if (outside) throw new WingsplineError('import-error', outside);
      // The check of a million faces and the lesson's compute are a task each (no task
      // of an import over 50 ms).
      await new Promise((resolve) => { setTimeout(resolve, 0); });
      acceptImport(name, next, refused);
    } catch (err) {
      refused(err);
    } finally {
      meshImport.finish();
    }
  }
  const onRawFile = (file) => {
    const ext = file.name.toLowerCase().split('.').pop();
    if (!meshImport || !meshTypes.includes(ext)) return false;
    importMeshFile(file, ext);
    return true;
  };
  installImport({ input: fileInput, dropTarget: document.body, onFile: importFile, onRawFile, onError: (text) => message.error(text, 'import-error') });

  return { exportItems, runExport, fileInput };
}
