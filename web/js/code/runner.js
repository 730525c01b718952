// @ts-check
// Runs a student's JavaScript against the lecture's mesh tables inside QuickJS (a JavaScript
// engine compiled to WebAssembly): the student's code sees a `mesh` object and nothing of the
// page or of Node (no DOM, no network, no storage), runs under an operation budget (an
// interrupt handler with a deadline), a memory limit and a stack limit, and every table entry
// it reads or writes is traced. Pure: no DOM, no module-level state; the same file runs in the
// sandbox worker (sandbox-worker.js) and under Node (quickjs-node.js).
//
// One case = one fresh QuickJS runtime and context: the prelude (PRELUDE, its own script) builds
// the frozen `mesh` over a few host functions, the student's source is evaluated as its own
// script (STUDENT_FILE, so an error's line and column are the student's own), then
// entry(mesh, ...args) is called and its return value converted to plain JSON data inside the
// engine with intrinsics captured before the student's code ran (a polluted prototype cannot
// change the conversion). Every QuickJS handle is disposed before the runtime is.

/** @typedef {import('quickjs-emscripten-core').QuickJSWASMModule} QuickJSWASMModule */
/** @typedef {import('quickjs-emscripten-core').QuickJSContext} QuickJSContext */
/** @typedef {import('quickjs-emscripten-core').QuickJSHandle} QuickJSHandle */

/**
 * @typedef {{ positions: Float64Array, vertexEdge: Int32Array, edges: Int32Array, faceEdge: Int32Array,
 *   edgeFields: string[] }} WingedSnapshot
 *   positions[3*v + k], edges[8*e + k] = field edgeFields[k] of edge e; -1 = none.
 * @typedef {{ origin: Int32Array, face: Int32Array, next: Int32Array, prev: Int32Array,
 *   vertexHalfedge: Int32Array, faceHalfedge: Int32Array }} HalfEdgeSnapshot
 *   twin(h) = h ^ 1 is not stored.
 * @typedef {{ winged?: WingedSnapshot, halfEdge?: HalfEdgeSnapshot }} MeshSnapshot
 *   A removed element's row is all -1.
 * @typedef {{ args?: unknown[], mesh: MeshSnapshot }} RunCase
 * @typedef {{ source: string, entry: string, cases: RunCase[], writable?: boolean, budgetMs?: number }} RunRequest
 * @typedef {'syntax'|'runtime'|'timeout'|'memory'|'result'|'request'|'engine'} ErrorKind
 *   request: a malformed request; engine: the engine itself failed (the next run loads a new one)
 * @typedef {{ kind: ErrorKind, message: string, line: number|null, column: number|null }} RunError
 * @typedef {{ count: number, total: number, cut: boolean, limit: number,
 *   names: { op: readonly string[], table: readonly string[], field: readonly string[] },
 *   op: Uint8Array, table: Uint8Array, row: Int32Array, field: Int8Array, value: Float64Array,
 *   positions: Float64Array }} Trace
 *   Entry i: names.op[op[i]] on names.table[table[i]] row row[i], field names.field[field[i]]
 *   (-1 for 'add'), value[i]; for the field 'position' value[i] = p and the position is
 *   positions[3*p + k].
 * @typedef {{ writes: { table: string, row: number, field: string, value: number|number[] }[],
 *   added: { vertex: number[][], edge: number, face: number, halfEdge: number } }} Transaction
 * @typedef {{ ok: true, value: unknown, returnedUndefined?: boolean } | { ok: false, error: RunError }} CaseOutcome
 * @typedef {CaseOutcome & { trace: Trace, reads: number, writes: number, adds: number, logs: string[],
 *   transaction?: Transaction, engineFailed?: boolean }} CaseResult
 */

export const STUDENT_FILE = 'your-code.js';
const PRELUDE_FILE = 'wingspline-mesh.js';
const ENTRY_FILE = 'wingspline-entry.js';

export const DEFAULT_BUDGET_MS = 1500;
// The prelude (the mesh object, the removed globals) before the student's code: ours, and quick;
// this only stops an engine that would hang in it.
const PRELUDE_BUDGET_MS = 10_000;
export const MEMORY_LIMIT_BYTES = 32 * 1024 * 1024;
// QuickJS counts the stack in its own frames, while the host's (V8's) stack holds the wasm
// frames of the interpreter: measured under Node, 128 KB of QuickJS stack could overflow the
// host's first (a host RangeError inside the wasm leaves QuickJS unusable); 64 KB stops a
// plain recursion at about 330 calls, far below it, with room for callbacks (map, sort).
export const STACK_LIMIT_BYTES = 64 * 1024;
export const TRACE_LIMIT = 100_000;
const LOG_LINES = 200;
const LOG_CHARS = 2000;
const RESULT_CHARS = 1_000_000;

export const TABLES = Object.freeze(['vertex', 'edge', 'face', 'halfEdge']);
export const TRACE_OPS = Object.freeze(['read', 'write', 'add']);
const WINGED_FIELDS = ['start', 'end', 'left', 'right', 'startLeft', 'startRight', 'endLeft', 'endRight'];
export const FIELDS = Object.freeze(['edge', 'position', 'halfEdge', ...WINGED_FIELDS,
  'origin', 'face', 'next', 'prev', 'twin', 'target']);
const FIELD = Object.fromEntries(FIELDS.map((name, i) => [name, i]));
const T_VERTEX = 0, T_EDGE = 1, T_FACE = 2, T_HALF = 3;

// The fields each table shows the student.
const TABLE_FIELDS = [
  ['edge', 'position', 'halfEdge'],
  WINGED_FIELDS,
  ['edge', 'halfEdge'],
  ['origin', 'face', 'next', 'prev', 'twin', 'target'],
];
// The table a field's value indexes (what a written value is checked against).
/** @type {Record<string, number>} */
const TARGET_TABLE = {
  edge: T_EDGE, halfEdge: T_HALF, start: T_VERTEX, end: T_VERTEX, left: T_FACE, right: T_FACE,
  startLeft: T_EDGE, startRight: T_EDGE, endLeft: T_EDGE, endRight: T_EDGE,
  origin: T_VERTEX, face: T_FACE, next: T_HALF, prev: T_HALF, twin: T_HALF, target: T_VERTEX,
};
const HALF_EDGE_FIELDS = new Set(['halfEdge', 'origin', 'face', 'next', 'prev', 'twin', 'target']);
const PLURAL = ['vertices', 'edges', 'faces', 'half-edges'];
const SINGULAR = ['vertex', 'edge', 'face', 'half-edge'];

// Names a page or Node would offer and the sandbox does not: their ReferenceError says why.
export const FORBIDDEN_GLOBALS = Object.freeze(['fetch', 'document', 'window', 'localStorage', 'sessionStorage',
  'indexedDB', 'importScripts', 'postMessage', 'XMLHttpRequest', 'WebSocket', 'Worker', 'navigator',
  'location', 'self', 'require', 'process', 'module']);

// Typed arrays and their buffers keep their bytes outside the engine's memory accounting
// (measured: 2 GB of Float64Arrays under a 32 MB limit), so the sandbox has none: the
// prelude deletes these globals, and the student uses ordinary arrays. WeakRef and
// FinalizationRegistry go too: they depend on when the collector runs, so a run would not repeat.
export const REMOVED_GLOBALS = Object.freeze(['ArrayBuffer', 'SharedArrayBuffer', 'DataView', 'Atomics',
  'Int8Array', 'Uint8Array', 'Uint8ClampedArray', 'Int16Array', 'Uint16Array', 'Int32Array', 'Uint32Array',
  'Float16Array', 'Float32Array', 'Float64Array', 'BigInt64Array', 'BigUint64Array', 'WeakRef', 'FinalizationRegistry']);

const READ_ONLY = 'this task only reads the structure; the mesh cannot be changed here';
const ONLY = { winged: 'this task gives the winged edge only', halfEdge: 'this task gives the half-edge only' };

// The engine side: builds `mesh` over the host functions and calls the entry. It captures
// every intrinsic it uses before the student's code runs, reads no prototype at call time,
// and converts the result to JSON text itself (no toJSON, no iterator, no Array methods).
const PRELUDE = `(function (host, writable, layoutJson, argsJson) {
  'use strict';
  const freeze = Object.freeze, define = Object.defineProperty, create = Object.create, keys = Object.keys;
  const isArray = Array.isArray, getProto = Object.getPrototypeOf, objectProto = Object.prototype;
  const quote = JSON.stringify, parse = JSON.parse, apply = Reflect.apply, Err = Error, isFiniteNumber = Number.isFinite;
  const check = host.check, read = host.read, write = host.write, position = host.position,
    writePosition = host.writePosition, add = host.add, count = host.count, log = host.log;
  const layout = parse(layoutJson);
  const args = parse(argsJson);
  for (let i = 0; i < layout.removed.length; i++) delete globalThis[layout.removed[i]];
  function fail(message) { throw new Err(message); }
  function reject(message) { throw 'E' + message; }
  function valueOf(r) { if (typeof r === 'string') fail(r); return r; }
  function describe(v) {
    if (typeof v === 'string') return quote(v);
    if (v === null || v === undefined) return '' + v;
    if (isArray(v)) return 'an array';
    if (typeof v === 'object') return 'an object';
    if (typeof v === 'function') return 'a function';
    return typeof v;
  }
  function element(table, index) {
    const problem = check(table, typeof index === 'number' ? index : NaN, typeof index === 'number' ? '' : describe(index));
    if (problem !== '') fail(problem);
    const o = create(null);
    const fields = layout.tableFields[table];
    for (let i = 0; i < fields.length; i++) {
      const name = fields[i], code = layout.field[name];
      const get = name === 'position'
        ? () => valueOf(position(index))
        : () => valueOf(read(table, index, code));
      let set;
      if (!writable) set = () => fail(layout.readOnly);
      else if (name === 'position') set = (p) => {
        if (!isArray(p) || p.length !== 3) fail('a position is an array [x, y, z] of three numbers, not ' + describe(p));
        const x = p[0], y = p[1], z = p[2];
        if (!isFiniteNumber(x) || !isFiniteNumber(y) || !isFiniteNumber(z)) fail('a position is an array [x, y, z] of three finite numbers');
        const r = writePosition(index, x, y, z);
        if (r !== '') fail(r);
      };
      else set = (v) => {
        const r = write(table, index, code, typeof v === 'number' ? v : NaN, typeof v === 'number' ? '' : describe(v));
        if (r !== '') fail(r);
      };
      define(o, name, { get, set, enumerable: true });
    }
    return freeze(o);
  }
  const countOf = (table) => () => valueOf(count(table));
  const noCount = (what) => () => fail(writable ? 'mesh.' + what + ' is counted, not set: add an element instead' : layout.readOnly);
  const adder = (table) => writable
    ? (p) => {
      let x = NaN, y = NaN, z = NaN;
      if (table === 0) {
        if (!isArray(p) || p.length !== 3 || !isFiniteNumber(p[0]) || !isFiniteNumber(p[1]) || !isFiniteNumber(p[2])) {
          fail('mesh.addVertex takes a position [x, y, z] of three finite numbers');
        }
        x = p[0]; y = p[1]; z = p[2];
      }
      return valueOf(add(table, x, y, z));
    }
    : () => fail(layout.readOnly);
  const mesh = create(null);
  const names = ['vertexCount', 'edgeCount', 'faceCount', 'halfEdgeCount'];
  for (let t = 0; t < 4; t++) define(mesh, names[t], { get: countOf(t), set: noCount(names[t]), enumerable: true });
  const elementNames = ['vertex', 'edge', 'face', 'halfEdge'];
  for (let t = 0; t < 4; t++) {
    const table = t;
    define(mesh, elementNames[t], { value: (i) => element(table, i), enumerable: true });
  }
  define(mesh, 'addVertex', { value: adder(0), enumerable: true });
  define(mesh, 'addEdge', { value: adder(1), enumerable: true });
  define(mesh, 'addFace', { value: adder(2), enumerable: true });
  define(mesh, 'addHalfEdgePair', { value: adder(3), enumerable: true });
  freeze(mesh);

  // console.log and friends write lines the page can show; the text is made here.
  function text(v) {
    if (typeof v === 'string') return v;
    const r = plain(v, 64);
    return r[0] === 'J' ? r.slice(1) : describe(v);
  }
  function logger(...items) {
    let line = '';
    for (let i = 0; i < items.length; i++) line += (i ? ' ' : '') + text(items[i]);
    log(line);
  }
  const consoleObject = freeze({ log: logger, info: logger, warn: logger, error: logger });
  define(globalThis, 'console', { value: consoleObject, writable: true, configurable: true });

  // The entry's value as JSON text ('J' + text) or why it is not plain data ('E' + message).
  function plain(value, maxDepth) {
    const ancestors = create(null);
    let size = 0;
    function at(path) { return path === '' ? '' : ' at ' + path; }
    function walk(v, depth, path) {
      if (size > ${RESULT_CHARS}) return reject('your function returned too much data (over ${RESULT_CHARS} characters)');
      if (v === null) return 'null';
      const type = typeof v;
      if (type === 'number') {
        if (!isFiniteNumber(v)) return reject('your function returned ' + v + at(path) + '; return finite numbers');
        return v === 0 ? '0' : '' + v;
      }
      if (type === 'string') { size += v.length; return quote(v); }
      if (type === 'boolean') return v ? 'true' : 'false';
      if (type === 'undefined') return reject('your function returned undefined' + at(path) + '; use null for "none"');
      if (type === 'function') return reject('your function returned a function' + at(path) + ' (did you forget to call it?)');
      if (type !== 'object') return reject('your function returned a ' + type + at(path) + '; return numbers, arrays and plain objects');
      for (let i = 0; i < depth; i++) {
        if (ancestors[i] === v) return reject('your function returned a cycle: the value' + at(path) + ' contains itself');
      }
      if (depth >= maxDepth) return reject('your function returned data nested deeper than ' + maxDepth + ' levels');
      ancestors[depth] = v;
      let out;
      if (isArray(v)) {
        const n = v.length;
        out = '[';
        for (let i = 0; i < n; i++) { out += (i ? ',' : '') + walk(v[i], depth + 1, path + '[' + i + ']'); size += 1; }
        out += ']';
      } else {
        const proto = getProto(v);
        if (proto !== objectProto && proto !== null) {
          return reject('your function returned an object that is not plain data' + at(path) + ' (a Map, a Set, a typed array or a class instance); return numbers, arrays and plain objects');
        }
        const ks = keys(v);
        out = '{';
        for (let i = 0; i < ks.length; i++) {
          const k = ks[i];
          out += (i ? ',' : '') + quote(k) + ':' + walk(v[k], depth + 1, path + '.' + k);
          size += k.length + 2;
        }
        out += '}';
      }
      ancestors[depth] = undefined;
      return out;
    }
    try {
      return 'J' + walk(value, 0, '');
    } catch (e) {
      if (typeof e === 'string' && e[0] === 'E') return e;
      throw e;
    }
  }
  const list = parse('[null' + (args.length ? ',' : '') + argsJson.slice(1));
  list[0] = mesh;
  return freeze({
    call(fn) {
      const value = apply(fn, undefined, list);
      if (value === undefined) return 'U';
      return plain(value, 64);
    },
  });
})`;

// ---------------------------------------------------------------------------------------
// The host side of one case: the tables (with the transaction's overlay), the trace.

/** @param {number} n @param {number} capacity */
function grow(n, capacity) { return Math.max(16, capacity * 2, n); }

function createTrace() {
  let capacity = 0;
  let count = 0;
  let total = 0;
  let op = new Uint8Array(0), table = new Uint8Array(0), row = new Int32Array(0), field = new Int8Array(0), value = new Float64Array(0);
  /** @type {number[]} */
  const positions = [];
  return {
    /** @param {number} o @param {number} t @param {number} r @param {number} f @param {number} v @param {ArrayLike<number>=} p */
    record(o, t, r, f, v, p) {
      total++;
      if (count >= TRACE_LIMIT) return;
      if (count === capacity) {
        capacity = Math.min(TRACE_LIMIT, grow(count + 1, capacity));
        const o2 = new Uint8Array(capacity); o2.set(op); op = o2;
        const t2 = new Uint8Array(capacity); t2.set(table); table = t2;
        const r2 = new Int32Array(capacity); r2.set(row); row = r2;
        const f2 = new Int8Array(capacity); f2.set(field); field = f2;
        const v2 = new Float64Array(capacity); v2.set(value); value = v2;
      }
      op[count] = o; table[count] = t; row[count] = r; field[count] = f;
      if (p) { value[count] = positions.length / 3; positions.push(p[0], p[1], p[2]); } else value[count] = v;
      count++;
    },
    /** @returns {Trace} */
    done() {
      return {
        count, total, cut: total > count, limit: TRACE_LIMIT,
        names: { op: TRACE_OPS, table: TABLES, field: FIELDS },
        op: op.slice(0, count), table: table.slice(0, count), row: row.slice(0, count),
        field: field.slice(0, count), value: value.slice(0, count), positions: Float64Array.from(positions),
      };
    },
  };
}

/**
 * The trace as a list of plain entries, in order: {op, table, row, field, value}; an 'add'
 * has no field or value; a position's value is [x, y, z].
 * @param {Trace} trace
 */
export function traceEntries(trace) {
  const out = [];
  for (let i = 0; i < trace.count; i++) {
    const op = trace.names.op[trace.op[i]];
    const table = trace.names.table[trace.table[i]];
    if (op === 'add') { out.push({ op, table, row: trace.row[i] }); continue; }
    const field = trace.names.field[trace.field[i]];
    const p = trace.value[i];
    const value = field === 'position' ? Array.from(trace.positions.subarray(3 * p, 3 * p + 3)) : p;
    out.push({ op, table, row: trace.row[i], field, value });
  }
  return out;
}

/**
 * The case's tables behind the host functions. Reads see the transaction's writes: a table is
 * copied on its first write or add (the snapshot is never changed).
 * @param {MeshSnapshot} snapshot
 * @param {boolean} writable
 */
function createStore(snapshot, writable) {
  const w = snapshot.winged;
  const h = snapshot.halfEdge;
  const fieldIndex = w ? Object.fromEntries(w.edgeFields.map((name, k) => [name, k])) : {};
  /** @type {Record<string, Int32Array|Float64Array>} */
  const arrays = {};
  if (w) Object.assign(arrays, { positions: w.positions, vertexEdge: w.vertexEdge, edges: w.edges, faceEdge: w.faceEdge });
  if (h) Object.assign(arrays, { origin: h.origin, face: h.face, next: h.next, prev: h.prev, vertexHalfedge: h.vertexHalfedge, faceHalfedge: h.faceHalfedge });
  const counts = [
    w ? w.vertexEdge.length : h.vertexHalfedge.length,
    w ? w.edges.length / 8 : h.origin.length / 2,
    w ? w.faceEdge.length : h.faceHalfedge.length,
    h ? h.origin.length : 0,
  ];
  const original = counts.slice();
  const copied = new Set();
  const trace = createTrace();
  let reads = 0, writes = 0, adds = 0;
  /** @type {Transaction} */
  const transaction = { writes: [], added: { vertex: [], edge: 0, face: 0, halfEdge: 0 } };

  /** @param {string} name @param {number} length */
  function own(name, length) {
    const a = arrays[name];
    if (!copied.has(name) || a.length < length) {
      const b = a instanceof Float64Array ? new Float64Array(Math.max(length, a.length)) : new Int32Array(Math.max(length, a.length));
      b.set(a);
      arrays[name] = b;
      copied.add(name);
    }
    return arrays[name];
  }

  // Where field `name` of row `row` of `table` lives: [array name, index], or a sentence.
  /** @param {number} table @param {number} row @param {string} name @returns {[string, number] | string} */
  function slot(table, row, name) {
    if (table === T_EDGE) return ['edges', 8 * row + fieldIndex[name]];
    if (table === T_VERTEX) return name === 'edge' ? ['vertexEdge', row] : ['vertexHalfedge', row];
    if (table === T_FACE) return name === 'edge' ? ['faceEdge', row] : ['faceHalfedge', row];
    return [name, row];
  }
  /** @param {number} table @param {string} name */
  function structureProblem(table, name) {
    const halfEdgeField = table === T_HALF || HALF_EDGE_FIELDS.has(name);
    if (halfEdgeField && !h) return ONLY.winged;
    if (!halfEdgeField && !w) return ONLY.halfEdge;
    return '';
  }
  /** @param {number} table @param {number} row */
  function removed(table, row) {
    if (row >= original[table]) return false;
    if (table === T_EDGE) return w ? w.edges.subarray(8 * row, 8 * row + 8).every((x) => x === -1) : false;
    if (table === T_HALF) return h.origin[row] === -1 && h.face[row] === -1 && h.next[row] === -1 && h.prev[row] === -1;
    if (table === T_FACE) return (!w || w.faceEdge[row] === -1) && (!h || h.faceHalfedge[row] === -1);
    return (!w || (w.vertexEdge[row] === -1 && w.positions[3 * row] === -1 && w.positions[3 * row + 1] === -1 && w.positions[3 * row + 2] === -1))
      && (!h || h.vertexHalfedge[row] === -1);
  }
  /** @param {number} table @param {number} index @param {string} shown */
  function indexProblem(table, index, shown) {
    const n = counts[table];
    const what = shown === '' ? String(index) : shown;
    if (!Number.isInteger(index) || index < 0 || index >= n) {
      const range = n === 0 ? `this mesh has no ${PLURAL[table]}` : `the ${PLURAL[table]} are 0 to ${n - 1}`;
      const none = index === -1 ? ' (-1 means "none")' : '';
      return `there is no ${SINGULAR[table]} ${what}: ${range}${none}`;
    }
    // A removed element's row stays and reads -1 in every entry, as the lesson's tables show it
    // (a count over the rows tells the removed ones by that).
    return '';
  }

  return {
    trace, transaction, counts,
    get reads() { return reads; }, get writes() { return writes; }, get adds() { return adds; },
    /** @param {number} table @param {number} index @param {string} shown */
    check(table, index, shown) {
      if (table === T_EDGE && !w) return ONLY.halfEdge;
      if (table === T_HALF && !h) return ONLY.winged;
      return indexProblem(table, index, shown);
    },
    /** @param {number} table */
    count(table) {
      if (table === T_HALF && !h) return ONLY.winged;
      return counts[table];
    },
    /** @param {number} table @param {number} row @param {number} code @returns {number|string} */
    read(table, row, code) {
      const name = FIELDS[code];
      const problem = structureProblem(table, name);
      if (problem) return problem;
      let value;
      if (name === 'twin') value = row ^ 1;
      else if (name === 'target') value = /** @type {number} */ (arrays.origin[row ^ 1]);
      else { const [array, i] = /** @type {[string, number]} */ (slot(table, row, name)); value = arrays[array][i]; }
      reads++;
      trace.record(0, table, row, code, value);
      return value;
    },
    /** @param {number} row @returns {number[]|string} */
    position(row) {
      if (!w) return ONLY.halfEdge;
      const p = Array.from(arrays.positions.subarray(3 * row, 3 * row + 3));
      reads++;
      trace.record(0, T_VERTEX, row, FIELD.position, 0, p);
      return p;
    },
    /** @param {number} table @param {number} row @param {number} code @param {number} value @param {string} shown */
    write(table, row, code, value, shown) {
      const name = FIELDS[code];
      const problem = structureProblem(table, name);
      if (problem) return problem;
      if (name === 'twin') return 'twin is h ^ 1: it is not stored, so it cannot be set';
      if (name === 'target') return "target is the origin of the twin: set mesh.halfEdge(h ^ 1).origin instead";
      const target = TARGET_TABLE[name];
      const n = counts[target];
      if (!Number.isInteger(value) || value < -1 || value >= n) {
        const what = shown === '' ? String(value) : shown;
        const article = SINGULAR[target] === 'edge' ? 'an' : 'a';
        const range = n === 0 ? `-1 for none: there are no ${PLURAL[target]} yet` : `a whole number from 0 to ${n - 1} or -1 for none`;
        return `${name} must be ${article} ${SINGULAR[target]} index (${range}), not ${what}`;
      }
      const [array, i] = /** @type {[string, number]} */ (slot(table, row, name));
      own(array, arrays[array].length)[i] = value;
      writes++;
      trace.record(1, table, row, code, value);
      transaction.writes.push({ table: TABLES[table], row, field: name, value });
      return '';
    },
    /** @param {number} row @param {number} x @param {number} y @param {number} z */
    writePosition(row, x, y, z) {
      if (!w) return ONLY.halfEdge;
      own('positions', arrays.positions.length).set([x, y, z], 3 * row);
      writes++;
      trace.record(1, T_VERTEX, row, FIELD.position, 0, [x, y, z]);
      transaction.writes.push({ table: 'vertex', row, field: 'position', value: [x, y, z] });
      return '';
    },
    /** @param {number} table @param {number} x @param {number} y @param {number} z @returns {number|string} */
    add(table, x, y, z) {
      if (table === T_EDGE && !w) return ONLY.halfEdge;
      if (table === T_HALF && !h) return ONLY.winged;
      const row = counts[table];
      /** @param {string} name @param {number} stride @param {number} rows */
      const extend = (name, stride, rows) => {
        if (!(name in arrays)) return;
        const a = own(name, stride * (row + rows));
        a.fill(-1, stride * row, stride * (row + rows));
      };
      if (table === T_VERTEX) {
        extend('vertexEdge', 1, 1); extend('vertexHalfedge', 1, 1);
        if (w) own('positions', 3 * (row + 1)).set([x, y, z], 3 * row);
        transaction.added.vertex.push([x, y, z]);
      } else if (table === T_EDGE) {
        extend('edges', 8, 1);
        transaction.added.edge++;
      } else if (table === T_FACE) {
        extend('faceEdge', 1, 1); extend('faceHalfedge', 1, 1);
        transaction.added.face++;
      } else {
        for (const name of ['origin', 'face', 'next', 'prev']) extend(name, 1, 2);
        transaction.added.halfEdge += 2;
        counts[T_EDGE] += w ? 0 : 1;
      }
      counts[table] += table === T_HALF ? 2 : 1;
      adds++;
      trace.record(2, table, row, -1, NaN);
      return row;
    },
  };
}

// ---------------------------------------------------------------------------------------
// Errors in the student's words.

/** @param {string} stack @returns {{ name: string, file: string, line: number, column: number }[]} */
function stackFrames(stack) {
  const frames = [];
  for (const text of String(stack ?? '').split('\n')) {
    const m = text.match(/^\s*at (?:(.*) \()?([^()]*?):(\d+):(\d+)\)?\s*$/);
    if (m) frames.push({ name: m[1] ?? '', file: m[2], line: Number(m[3]), column: Number(m[4]) });
  }
  return frames;
}

/**
 * Where the loop that ran out of time starts. QuickJS stops a loop at its backward jump and
 * reports the last position it recorded before the loop's head (often the function's first
 * line: an empty loop body records none), so the loop is the first `for`, `while` or `do` at
 * or after that position, comments and strings skipped. For the top level (topLevel), loops
 * outside any braces come first, since the functions above it are not running.
 * @param {string} source @param {number} line @param {number} column @param {boolean} [topLevel]
 * @returns {{ line: number, column: number }}
 */
export function loopAfter(source, line, column, topLevel = false) {
  const lines = source.split('\n');
  let offset = 0;
  for (let i = 0; i < line - 1 && i < lines.length; i++) offset += lines[i].length + 1;
  offset += Math.max(0, column - 1);
  const re = /\/\/[^\n]*|\/\*[\s\S]*?\*\/|'(?:\\.|[^'\\\n])*'|"(?:\\.|[^"\\\n])*"|`(?:\\.|[^`\\])*`|([{}])|(?<![.\w$])(for|while|do)(?![\w$])/g;
  let depth = 0;
  /** @type {number | null} */
  let first = null;
  /** @type {number | null} */
  let outermost = null;
  let m;
  while ((m = re.exec(source))) {
    if (m[1]) depth += m[1] === '{' ? 1 : -1;
    else if (m[2] && m.index >= offset) {
      first ??= m.index;
      if (depth === 0) { outermost = m.index; break; }
      if (!topLevel) break;
    }
  }
  const found = topLevel ? (outermost ?? first) : first;
  if (found === null) return { line, column };
  const before = source.slice(0, found);
  return { line: before.split('\n').length, column: found - before.lastIndexOf('\n') };
}

/**
 * @param {QuickJSContext} ctx @param {QuickJSHandle} errorHandle
 * @returns {{ name: string, message: string, stack: string, lineNumber: number|null }}
 */
function errorParts(ctx, errorHandle) {
  if (ctx.typeof(errorHandle) !== 'object') {
    let message = '';
    try { message = String(ctx.dump(errorHandle)); } catch { message = 'an error'; }
    return { name: '', message, stack: '', lineNumber: null };
  }
  /** @param {string} key */
  const prop = (key) => {
    const hd = ctx.getProp(errorHandle, key);
    try {
      const t = ctx.typeof(hd);
      return t === 'string' ? ctx.getString(hd) : t === 'number' ? ctx.getNumber(hd) : undefined;
    } finally { hd.dispose(); }
  };
  const name = prop('name');
  const message = prop('message');
  const stack = prop('stack');
  const lineNumber = prop('lineNumber');
  return {
    name: typeof name === 'string' ? name : '',
    message: typeof message === 'string' ? message : String(message ?? ''),
    stack: typeof stack === 'string' ? stack : '',
    lineNumber: typeof lineNumber === 'number' ? lineNumber : null,
  };
}

/** @param {number|null} line @param {number|null} column @param {string} text */
function at(line, column, text) {
  if (line === null) return text;
  return column === null ? `Line ${line}: ${text}` : `Line ${line}, column ${column}: ${text}`;
}

/**
 * @param {ReturnType<typeof errorParts>} parts @param {{ interrupted: boolean, source: string }} how
 * @param {number} budgetMs @returns {RunError}
 */
function runError(parts, how, budgetMs) {
  const frames = stackFrames(parts.stack);
  const index = frames.findIndex((f) => f.file === STUDENT_FILE);
  let line = index >= 0 ? frames[index].line : null;
  let column = index >= 0 ? frames[index].column : null;
  if (how.interrupted) {
    // The innermost frame is the student's own: its position is the stale one (see loopAfter).
    if (index === 0) ({ line, column } = loopAfter(how.source, line, column, frames[0].name === '<eval>'));
    const seconds = budgetMs / 1000;
    return { kind: 'timeout', line, column,
      message: at(line, column, `your code ran longer than ${seconds} s and was stopped: is there a loop that never ends?`) };
  }
  if (/out of memory/i.test(parts.message)) {
    return { kind: 'memory', line, column,
      message: at(line, column, `your code used more than ${MEMORY_LIMIT_BYTES / (1024 * 1024)} MB of memory and was stopped`) };
  }
  if (/stack overflow/i.test(parts.message)) {
    return { kind: 'runtime', line, column,
      message: at(line, column, 'too much recursion (the call stack overflowed): does your function stop calling itself?') };
  }
  let text = parts.message;
  const ref = parts.name === 'ReferenceError' ? parts.message.match(/^'?([\w$]+)'? is not defined$/) : null;
  if (ref && FORBIDDEN_GLOBALS.includes(ref[1])) {
    text = `${ref[1]} is not available: your code runs in a sandbox that sees only the mesh`;
  } else if (ref && REMOVED_GLOBALS.includes(ref[1])) {
    text = `${ref[1]} is not available in the sandbox: use an ordinary array`;
  } else if (parts.name && parts.name !== 'Error') {
    text = `${parts.name}: ${parts.message}`;
  }
  return { kind: 'runtime', line, column, message: at(line, column, text) };
}

/** @param {ReturnType<typeof errorParts>} parts @returns {RunError} */
function syntaxError(parts) {
  const frames = stackFrames(parts.stack);
  const frame = frames.find((f) => f.file === STUDENT_FILE);
  const line = frame ? frame.line : parts.lineNumber;
  const column = frame ? frame.column : null;
  return { kind: 'syntax', line, column, message: at(line, column, parts.message) };
}

// ---------------------------------------------------------------------------------------

/**
 * A QuickJS call's outcome as two fields, one of them null.
 * @param {unknown} result
 * @returns {{ error: QuickJSHandle | null, value: QuickJSHandle | null }}
 */
function settle(result) {
  const r = /** @type {{ error?: QuickJSHandle, value?: QuickJSHandle }} */ (result);
  return { error: r.error ?? null, value: r.error ? null : r.value };
}

/** @param {unknown} request @returns {string} */
function requestProblem(request) {
  if (!request || typeof request !== 'object') return 'the request must be an object';
  const r = /** @type {Record<string, unknown>} */ (request);
  if (typeof r.source !== 'string') return 'request.source must be the program text';
  if (typeof r.entry !== 'string' || !/^[A-Za-z_$][\w$]*$/.test(r.entry)) return 'request.entry must be a function name';
  if (!Array.isArray(r.cases)) return 'request.cases must be an array';
  if (r.budgetMs !== undefined && !(typeof r.budgetMs === 'number' && r.budgetMs > 0 && r.budgetMs <= 60_000)) return 'request.budgetMs must be between 0 and 60000 ms';
  for (const [i, c] of r.cases.entries()) {
    if (!c || typeof c !== 'object' || !c.mesh || typeof c.mesh !== 'object') return `case ${i} has no mesh`;
    if (c.args !== undefined && !Array.isArray(c.args)) return `case ${i}: args must be an array`;
    const { winged: w, halfEdge: h } = c.mesh;
    if (!w && !h) return `case ${i}: the mesh has neither a winged edge nor a half-edge structure`;
    if (w && !(w.positions instanceof Float64Array && w.vertexEdge instanceof Int32Array && w.edges instanceof Int32Array
      && w.faceEdge instanceof Int32Array && Array.isArray(w.edgeFields) && WINGED_FIELDS.every((f) => w.edgeFields.includes(f))
      && w.edgeFields.length === 8 && w.edges.length % 8 === 0 && w.positions.length === 3 * w.vertexEdge.length)) {
      return `case ${i}: the winged-edge snapshot is malformed`;
    }
    if (h && !(['origin', 'face', 'next', 'prev', 'vertexHalfedge', 'faceHalfedge'].every((k) => h[k] instanceof Int32Array)
      && h.origin.length % 2 === 0 && ['face', 'next', 'prev'].every((k) => h[k].length === h.origin.length))) {
      return `case ${i}: the half-edge snapshot is malformed`;
    }
    if (w && h && (w.vertexEdge.length !== h.vertexHalfedge.length || w.faceEdge.length !== h.faceHalfedge.length)) {
      return `case ${i}: the two structures count different vertices or faces`;
    }
    try { JSON.stringify(c.args ?? []); } catch { return `case ${i}: args must be JSON data`; }
  }
  return '';
}

/**
 * Whether `source` parses as a script, without running it.
 * @param {QuickJSWASMModule} QuickJS @param {string} source
 * @returns {{ ok: true } | { ok: false, error: RunError }}
 */
export function checkSyntax(QuickJS, source) {
  const runtime = QuickJS.newRuntime();
  try {
    runtime.setMemoryLimit(MEMORY_LIMIT_BYTES);
    runtime.setMaxStackSize(STACK_LIMIT_BYTES);
    const deadline = Date.now() + DEFAULT_BUDGET_MS;
    runtime.setInterruptHandler(() => Date.now() > deadline);
    const ctx = runtime.newContext();
    try {
      const result = settle(ctx.evalCode(source, STUDENT_FILE, { type: 'global', compileOnly: true }));
      if (result.error) {
        const parts = errorParts(ctx, result.error);
        result.error.dispose();
        return { ok: false, error: parts.name === 'SyntaxError' ? syntaxError(parts) : { kind: 'syntax', line: null, column: null, message: parts.message } };
      }
      result.value.dispose();
      return { ok: true };
    } finally {
      ctx.dispose();
    }
  } finally {
    runtime.dispose();
  }
}

/**
 * Runs the student's program once per case. Returns {results} (one CaseResult per case, in
 * order) or {error} when the request is malformed or the program does not parse (then no case
 * runs). A case whose engine failed at the host level (engineFailed) leaves the QuickJS module
 * unusable: the caller loads a new one.
 * @param {QuickJSWASMModule} QuickJS @param {RunRequest} request
 * @returns {{ results: CaseResult[] } | { error: RunError }}
 */
export function runStudentCode(QuickJS, request) {
  const problem = requestProblem(request);
  if (problem) return { error: { kind: 'request', message: problem, line: null, column: null } };
  const syntax = checkSyntax(QuickJS, request.source);
  if (!syntax.ok) return { error: /** @type {{ error: RunError }} */ (syntax).error };
  const results = [];
  for (const c of request.cases) {
    const result = runCase(QuickJS, request, c);
    results.push(result);
    if (result.engineFailed) break;
  }
  return { results };
}

/**
 * @param {QuickJSWASMModule} QuickJS @param {RunRequest} request @param {RunCase} c
 * @returns {CaseResult}
 */
function runCase(QuickJS, request, c) {
  const writable = request.writable === true;
  const budgetMs = request.budgetMs ?? DEFAULT_BUDGET_MS;
  const store = createStore(c.mesh, writable);
  /** @type {string[]} */
  const logs = [];
  /** @param {CaseOutcome} outcome @param {boolean} [engineFailed] @returns {CaseResult} */
  const finish = (outcome, engineFailed = false) => ({
    ...outcome, trace: store.trace.done(), reads: store.reads, writes: store.writes, adds: store.adds, logs,
    ...(writable ? { transaction: store.transaction } : {}),
    ...(engineFailed ? { engineFailed } : {}),
  });
  // The student's budget starts when the prelude is built (evaluate sets how.deadline): on a
  // slow or busy machine the prelude's own time never counts against the student's code (a
  // 100 ms budget was once spent before the student's first line). The prelude has its own,
  // generous limit.
  const how = { interrupted: false, source: request.source, deadline: Date.now() + PRELUDE_BUDGET_MS };
  let runtime;
  try {
    runtime = QuickJS.newRuntime();
  } catch (err) {
    return finish({ ok: false, error: { kind: 'engine', line: null, column: null, message: `the sandbox could not start: ${err?.message ?? err}` } }, true);
  }
  let healthy = true;
  try {
    runtime.setMemoryLimit(MEMORY_LIMIT_BYTES);
    runtime.setMaxStackSize(STACK_LIMIT_BYTES);
    runtime.setInterruptHandler(() => {
      if (Date.now() > how.deadline) how.interrupted = true;
      return how.interrupted;
    });
    const ctx = runtime.newContext();
    /** @type {QuickJSHandle[]} */
    const handles = [];
    /** @param {QuickJSHandle} hd */
    const keep = (hd) => { handles.push(hd); return hd; };
    try {
      return finish(evaluate(ctx, keep, store, logs, request, c, writable, how, budgetMs));
    } catch (err) {
      healthy = false;
      const message = err instanceof RangeError
        ? 'too much recursion: the sandbox ran out of stack'
        : `the sandbox failed: ${err?.message ?? err}`;
      return finish({ ok: false, error: { kind: 'engine', line: null, column: null, message } }, true);
    } finally {
      if (healthy) {
        for (const hd of handles.reverse()) if (hd.alive) hd.dispose();
        ctx.dispose();
      }
    }
  } finally {
    // A host-level failure inside the wasm (its stack, an abort) leaves QuickJS's heap in an
    // unknown state: freeing it could abort again, so the runtime is dropped with the module.
    if (healthy) runtime.dispose();
  }
}

/**
 * @param {QuickJSContext} ctx @param {(h: QuickJSHandle) => QuickJSHandle} keep
 * @param {ReturnType<typeof createStore>} store @param {string[]} logs @param {RunRequest} request
 * @param {RunCase} c @param {boolean} writable @param {{ interrupted: boolean, source: string, deadline: number }} how @param {number} budgetMs
 * @returns {CaseOutcome}
 */
function evaluate(ctx, keep, store, logs, request, c, writable, how, budgetMs) {
  /** @param {string} text */
  const str = (text) => ctx.newString(text);
  /** @param {number|string} v */
  const val = (v) => (typeof v === 'string' ? str(v) : ctx.newNumber(v));
  /** @param {QuickJSHandle} hd */
  const num = (hd) => (ctx.typeof(hd) === 'number' ? ctx.getNumber(hd) : NaN);
  const host = keep(ctx.newObject());
  /** @type {Record<string, (...args: QuickJSHandle[]) => QuickJSHandle>} */
  const functions = {
    check: (t, i, shown) => str(store.check(num(t), num(i), ctx.getString(shown))),
    count: (t) => val(store.count(num(t))),
    read: (t, r, f) => val(store.read(num(t), num(r), num(f))),
    position: (r) => {
      const p = store.position(num(r));
      if (typeof p === 'string') return str(p);
      const array = ctx.newArray();
      p.forEach((x, k) => { const n = ctx.newNumber(x); ctx.setProp(array, k, n); n.dispose(); });
      return array;
    },
    write: (t, r, f, v, shown) => str(store.write(num(t), num(r), num(f), num(v), ctx.getString(shown))),
    writePosition: (r, x, y, z) => str(store.writePosition(num(r), num(x), num(y), num(z))),
    add: (t, x, y, z) => val(store.add(num(t), num(x), num(y), num(z))),
    log: (line) => {
      if (logs.length < LOG_LINES) logs.push(ctx.getString(line).slice(0, LOG_CHARS));
      return ctx.undefined;
    },
  };
  for (const [name, fn] of Object.entries(functions)) {
    const hd = ctx.newFunction(name, fn);
    ctx.setProp(host, name, hd);
    hd.dispose();
  }
  const factory = settle(ctx.evalCode(PRELUDE, PRELUDE_FILE, { type: 'global' }));
  if (factory.error) { const parts = errorParts(ctx, factory.error); factory.error.dispose(); throw new Error(`prelude: ${parts.message}`); }
  keep(factory.value);
  const layout = JSON.stringify({ tableFields: TABLE_FIELDS, field: FIELD, readOnly: READ_ONLY, removed: REMOVED_GLOBALS });
  const made = settle(ctx.callFunction(factory.value, ctx.undefined, host, writable ? ctx.true : ctx.false,
    keep(str(layout)), keep(str(JSON.stringify(c.args ?? [])))));
  if (made.error) { const parts = errorParts(ctx, made.error); made.error.dispose(); throw new Error(`prelude: ${parts.message}`); }
  const api = keep(made.value);
  const call = keep(ctx.getProp(api, 'call'));
  how.deadline = Date.now() + budgetMs; // the student's code starts now

  /** @param {QuickJSHandle} errorHandle @returns {CaseOutcome} */
  const failed = (errorHandle) => {
    const parts = errorParts(ctx, errorHandle);
    errorHandle.dispose();
    if (parts.name === 'SyntaxError' && !how.interrupted && stackFrames(parts.stack)[0]?.file === STUDENT_FILE && parts.lineNumber !== null) {
      return { ok: false, error: syntaxError(parts) };
    }
    return { ok: false, error: runError(parts, how, budgetMs) };
  };

  const program = settle(ctx.evalCode(request.source, STUDENT_FILE, { type: 'global' }));
  if (program.error) return failed(program.error);
  program.value.dispose();

  const entry = settle(ctx.evalCode(`typeof ${request.entry} === 'function' ? ${request.entry} : undefined`, ENTRY_FILE, { type: 'global' }));
  if (entry.error) return failed(entry.error);
  keep(entry.value);
  if (ctx.typeof(entry.value) !== 'function') {
    return { ok: false, error: { kind: 'runtime', line: null, column: null, message: `define a function named ${request.entry}` } };
  }
  const returned = settle(ctx.callFunction(call, ctx.undefined, entry.value));
  if (returned.error) return failed(returned.error);
  const text = ctx.getString(returned.value);
  returned.value.dispose();
  if (text === 'U') return { ok: true, value: null, returnedUndefined: true };
  if (text[0] === 'E') return { ok: false, error: { kind: 'result', line: null, column: null, message: text.slice(1) } };
  return { ok: true, value: JSON.parse(text.slice(1)) };
}
