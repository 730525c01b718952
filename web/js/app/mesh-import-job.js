// @ts-check
// One mesh file import, as the import worker runs it (mesh-import-worker.js): read
// the File with byte progress, refuse it as early as possible when it is too large (its size,
// then the OFF header's counts, which the core reads from the first piece before the body is
// there), parse it with the core, check it (validateMesh: every problem), and hand back flat
// typed arrays. No DOM: it runs in a worker and under Node (tests/wasm/files/).
// The imported value of a lesson state ({name, positions, faces}) is written as JSON here too,
// and its SHA-256 taken, so the page never serialises or hashes a million faces itself
// (share-link.js rememberContent; docs/state-format.md, "Large fields").
import { WingsplineError } from '../core/errors.js';
import { stringifyExact, sha256 } from './share-link.js';
import { flatImportedValue } from './imported-mesh.js';

// The largest mesh file read: a mesh of the import limit (2,000,000 faces) written with full
// precision is about 100 MB as OFF; OBJ files with normals and texture lines are larger.
export const MAX_MESH_FILE_BYTES = 256 * 2 ** 20;
// The piece of an OFF file the core reads first to check the header's counts.
const HEAD_BYTES = 64 * 1024;
// Stages, in order, as the progress bar names them (the last runs on the page).
export const IMPORT_STAGES = ['reading', 'parsing', 'checking', 'building'];

const mb = (bytes) => `${(bytes / 2 ** 20).toFixed(1)} MB`;

/**
 * @param {any} api the core (loadWingspline())
 * @param {Blob & {name?: string}} file
 * @param {{ format: string, name: string, onProgress?: (p: {stage: string, done?: number, total?: number}) => void }} options
 * @returns {Promise<{ positions: Float64Array, faceOffsets: Int32Array, faceVertices: Int32Array, problems: any[], content: { chars: number, hash: string, json: string } | null }>}
 */
export async function importMeshFile(api, file, { format, name, onProgress = () => {} }) {
  const limits = api.meshLimits;
  if (file.size > MAX_MESH_FILE_BYTES) {
    throw new WingsplineError('too-large', `the file is ${mb(file.size)}; mesh files up to ${mb(MAX_MESH_FILE_BYTES)} can be imported (meshes up to ${limits.maxFaces.toLocaleString('en-US')} faces)`);
  }
  const text = await readText(api, file, format, onProgress);
  onProgress({ stage: 'parsing' });
  const parsed = api.parseMesh(text, { format, layout: 'csr' });
  onProgress({ stage: 'checking' });
  const report = api.validateMesh(parsed);
  const content = report.problems.some((p) => p.severity === 'error') ? null : await contentOf(name, parsed);
  return { positions: parsed.positions, faceOffsets: parsed.faceOffsets, faceVertices: parsed.faceVertices, problems: report.problems, content };
}

// The file's text, read piece by piece (progress in bytes). An OFF file whose header asks for
// more than the limits is refused from its first piece: the core reads the header's counts
// before anything else, so it says too-large there; any other answer (the piece ends before
// the body does) is left for the full parse.
async function readText(api, file, format, onProgress) {
  const total = file.size;
  const reader = file.stream().getReader();
  const decoder = new TextDecoder('utf-8');
  const parts = [];
  let done = 0;
  let headChecked = format !== 'off';
  onProgress({ stage: 'reading', done, total });
  for (;;) {
    const piece = await reader.read();
    if (piece.done) break;
    done += piece.value.length;
    parts.push(decoder.decode(piece.value, { stream: true }));
    if (!headChecked && (done >= HEAD_BYTES || done === total)) {
      headChecked = true;
      try {
        checkHead(api, parts.join(''));
      } catch (err) {
        await reader.cancel().catch(() => {});
        throw err;
      }
    }
    onProgress({ stage: 'reading', done, total });
  }
  parts.push(decoder.decode());
  return parts.join('');
}

function checkHead(api, head) {
  try {
    api.parseMesh(head, { format: 'off' });
  } catch (err) {
    if (err.code === 'too-large') throw err;
  }
}

// The imported value as the lessons keep it in their state, written as share-link.js writes
// it (stringifyExact), and its SHA-256: the text the content store keeps.
async function contentOf(name, { positions, faceOffsets, faceVertices }) {
  const value = flatImportedValue(name, positions, faceOffsets, faceVertices);
  const json = stringifyExact(value);
  return { chars: json.length, hash: await sha256(json), json };
}
