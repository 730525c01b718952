// @ts-check
// The import worker: a module worker that loads its own copy of the core, runs one
// mesh file import (mesh-import-job.js) and posts back progress, then the result as flat typed
// arrays (transferred, not copied) or the error. The imported value's JSON text is put into
// the content store (IndexedDB) from here, so the page only learns its hash and length. The
// page terminates the worker after each import (and to cancel one): its memory goes with it.
import { loadWingspline } from '../core/wingspline.js';
import { importMeshFile } from './mesh-import-job.js';
import { createContentStore } from './content-store.js';

const post = (message, transfer = []) => /** @type {any} */ (self).postMessage(message, transfer);

self.addEventListener('message', async (event) => {
  const { file, format, name } = event.data;
  try {
    const api = await loadWingspline({ parts: ['mesh'] });
    const r = await importMeshFile(api, file, { format, name, onProgress: (progress) => post({ type: 'progress', ...progress }) });
    let content = null;
    if (r.content) {
      let stored = false;
      try {
        await createContentStore().put(r.content.hash, r.content.json);
        stored = true;
      } catch {
        // No IndexedDB here (some private modes): the page keeps the mesh in its state.
      }
      content = { chars: r.content.chars, hash: r.content.hash, stored };
    }
    post({ type: 'done', positions: r.positions, faceOffsets: r.faceOffsets, faceVertices: r.faceVertices, problems: r.problems, content },
      [r.positions.buffer, r.faceOffsets.buffer, r.faceVertices.buffer]);
  } catch (err) {
    post({ type: 'error', code: err?.code ?? 'import-error', message: String(err?.message ?? err), line: err?.line });
  }
});
