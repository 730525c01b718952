// Reading the malformed-input corpus of tests/corpus/ for the wasm hardening tests; the
// native tests read the same files (tests/native/files/corpus.h).
import fs from 'node:fs';

export const corpusUrl = new URL('../corpus/', import.meta.url);

function records(text) {
  return text.split('\n').map((line) => line.replace(/#.*/, '').trim()).filter(Boolean).map((line) => line.split(/\s+/));
}

// A file as the page gets it: UTF-8 text decoded (a byte-order mark kept, so the core's
// handling of it is what is tested); bytes that are not UTF-8 one character per byte
// (binary garbage stays garbage).
const utf8 = new TextDecoder('utf-8', { fatal: true, ignoreBOM: true });
export function readCorpusFile(relative) {
  const bytes = fs.readFileSync(new URL(relative, corpusUrl));
  try {
    return utf8.decode(bytes);
  } catch {
    return bytes.toString('latin1');
  }
}

export function meshCases() {
  return records(fs.readFileSync(new URL('mesh/expected.txt', corpusUrl), 'utf8')).map(([file, format, outcome, code, ...rest]) => ({
    file, format, outcome, code,
    line: outcome === 'parse-error' ? Number(rest[0]) : undefined,
    names: outcome === 'parse-error' ? [] : rest,
  }));
}

export function curveFiles() {
  return fs.readdirSync(new URL('curves/', corpusUrl)).filter((f) => f.endsWith('.curve')).sort();
}

// A .curve file as { curve, params, expect, names }.
export function readCurve(name) {
  const r = Object.fromEntries(records(fs.readFileSync(new URL(`curves/${name}`, corpusUrl), 'utf8')).map(([k, ...v]) => [k, v]));
  // Read like strtod: nan, inf and -inf are numbers.
  const numbers = (words) => words.map((w) => ({ nan: NaN, inf: Infinity, '-inf': -Infinity }[w.toLowerCase()] ?? Number(w)));
  const dim = Number(r.dim[0]);
  let points = r.points ? numbers(r.points) : [];
  if (r.repeat) {
    const point = numbers(r.repeat.slice(1));
    points = Array.from({ length: Number(r.repeat[0]) }, () => point).flat();
  }
  const curve = { kind: r.kind[0], dim, points };
  if (r.degree) curve.degree = Number(r.degree[0]);
  if (r.knots) curve.knots = numbers(r.knots);
  if (r.weights) curve.weights = numbers(r.weights);
  return { curve, params: numbers(r.params), expect: r.expect[0], names: r.names ?? [] };
}
