// @ts-check
// Downloads and uploads. Export: any text or Blob to a named file. Import: a file picker
// and drag-and-drop on the page; files are read as text and handed to the shell, which
// validates them before anything changes.

export function download(filename, content, type = 'text/plain') {
  const blob = content instanceof Blob ? content : new Blob([content], { type: `${type};charset=utf-8` });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export const MAX_IMPORT_BYTES = 64 * 1024 * 1024;

// Calls onFile({ name, text }) for a chosen or dropped file; onError(message) otherwise.
// A file that onRawFile(file) takes (returns true: a mesh file, read by the import worker)
// is not read here.
export function installImport({ input, dropTarget, onFile, onError, onRawFile = (file) => false }) {
  async function read(file) {
    if (!file) return;
    if (onRawFile(file)) return;
    if (file.size > MAX_IMPORT_BYTES) {
      onError(`${file.name} is ${(file.size / 1048576).toFixed(1)} MB; files up to ${MAX_IMPORT_BYTES / 1048576} MB can be imported`);
      return;
    }
    try {
      onFile({ name: file.name, text: await file.text() });
    } catch (err) {
      onError(`${file.name} could not be read: ${err.message}`);
    }
  }
  input.addEventListener('change', () => {
    read(input.files?.[0]);
    input.value = '';
  });
  dropTarget.addEventListener('dragover', (event) => {
    if ([...(event.dataTransfer?.types ?? [])].includes('Files')) {
      event.preventDefault();
      dropTarget.classList.add('is-dropping');
    }
  });
  dropTarget.addEventListener('dragleave', () => dropTarget.classList.remove('is-dropping'));
  dropTarget.addEventListener('drop', (event) => {
    event.preventDefault();
    dropTarget.classList.remove('is-dropping');
    read(event.dataTransfer?.files?.[0]);
  });
}

// CSV with a header row; numbers written in full precision (String(x) round-trips).
export function toCsv(header, rows) {
  const cell = (v) => {
    const s = typeof v === 'number' ? String(v) : String(v ?? '');
    return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
  };
  return [header, ...rows].map((r) => r.map(cell).join(',')).join('\n') + '\n';
}
