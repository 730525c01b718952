// @ts-check
// Exercise part of the API for the kind "subdivide" (docs/api-mesh.md, "Checking a
// subdivision step by hand"): the exact stencil of one new point of a Loop or Catmull-Clark
// step, the check of a student's mask (the rule chosen and weights as fractions of named old
// vertices) and of the counts V, E, F after a step. The mesh is the exercise's, as faces or
// CSR with its vertex count (exerciseMesh); elements are 0-based (0 is v1, e1, F1); the core
// does all of the arithmetic, in exact fractions.
import { unwrap, fail, elementIndex, integerIn } from './errors.js';
import { exerciseMesh } from './exercise-api.js';

const SCHEMES = Object.freeze(['loop', 'catmull-clark']);
const POINT_TYPES = Object.freeze(['vertex', 'edge', 'face']);
// The masks a new point can be made by, as the core names them (api.subdivisionSteps' ruleNames).
export const SUBDIVIDE_MASKS = Object.freeze(['face-point', 'edge-interior', 'edge-boundary', 'vertex-interior', 'vertex-boundary']);
// The largest whole number a fraction's numerator or denominator may be (exact in a double).
const LARGEST_WHOLE = 2 ** 53;

function schemeOf(scheme) {
  if (!SCHEMES.includes(scheme)) fail('unknown-scheme', `unknown subdivision scheme ${JSON.stringify(scheme)?.slice(0, 40)}: use 'loop' or 'catmull-clark'`);
  return scheme;
}

function pointOf(point) {
  if (point === null || typeof point !== 'object') fail('invalid-argument', 'expected the new point {type: \'vertex\' | \'edge\' | \'face\', element}');
  if (!POINT_TYPES.includes(point.type)) fail('invalid-argument', `point.type must be 'vertex', 'edge' or 'face', not ${JSON.stringify(point.type)?.slice(0, 40)}`);
  return [point.type, elementIndex(point.element, point.type)];
}

function whole(x, what) {
  if (!Number.isInteger(x) || Math.abs(x) > LARGEST_WHOLE) fail('invalid-answer', `${what} must be a whole number of at most 2^53, not ${String(x).slice(0, 40)}`);
  return x;
}

const findingsOf = (list) => Array.from(list, ({ code, row, vertex, count, text, hint }) => ({ code, row, vertex, count, text, hint }));

/** @param {any} raw */
export function createExerciseSubdivideApi(raw) {
  return {
    subdivideMasks: SUBDIVIDE_MASKS,
    // {rule, vertices: Int32Array, weights: [{num, den}] (lowest terms, den > 0), roles:
    // string[]}: the stencil of the vertex (edge, face) point of `point.element`, the scheme's
    // rule expanded onto the old vertices. Errors: 'unknown-scheme', 'invalid-element',
    // 'no-exact-mask', 'not-a-triangle-mesh', 'invalid-faces'.
    subdivideStencil(mesh, { scheme, point } = /** @type {any} */ ({})) {
      const r = unwrap(raw.exerciseSubdivideStencil(...exerciseMesh(mesh), schemeOf(scheme), ...pointOf(point)));
      const weights = Array.from(r.numerators, (num, i) => ({ num, den: r.denominators[i] }));
      return { rule: r.rule, vertices: r.vertices, weights, roles: Array.from(r.roles) };
    },
    // A student's mask: `mask` one of subdivideMasks or null (none chosen), `rows` [{vertex
    // (0-based; any whole number), num, den}]. Returns {correct, findings: [{code, row,
    // vertex, count, text, hint}]}; no finding holds the right value.
    checkSubdivideMask(mesh, { scheme, point, mask, rows } = /** @type {any} */ ({})) {
      if (mask !== null && !SUBDIVIDE_MASKS.includes(mask)) fail('invalid-answer', `mask must be null or one of ${SUBDIVIDE_MASKS.join(', ')}, not ${JSON.stringify(mask)?.slice(0, 40)}`);
      if (!Array.isArray(rows)) fail('invalid-answer', 'rows must be a list of {vertex, num, den}');
      const vertices = new Int32Array(rows.length);
      const nums = new Float64Array(rows.length);
      const dens = new Float64Array(rows.length);
      rows.forEach((row, i) => {
        if (row === null || typeof row !== 'object') fail('invalid-answer', `rows[${i}] must be {vertex, num, den}`);
        vertices[i] = integerIn(row.vertex, `rows[${i}].vertex`, -1, 2147483647);
        nums[i] = whole(row.num, `rows[${i}].num`);
        dens[i] = whole(row.den, `rows[${i}].den`);
        if (dens[i] === 0) fail('invalid-answer', `rows[${i}].den must not be 0`);
      });
      const r = unwrap(raw.exerciseCheckSubdivideMask(...exerciseMesh(mesh), schemeOf(scheme), ...pointOf(point), mask ?? '', vertices, nums, dens));
      const findings = findingsOf(r.findings);
      return { correct: findings.length === 0, findings };
    },
    // The counts after `steps` steps (1..4), null for a count left blank. Returns {correct,
    // findings} as checkSubdivideMask.
    checkSubdivideCounts(mesh, { scheme, steps = 1, vertices, edges, faces } = /** @type {any} */ ({})) {
      const given = [vertices, edges, faces].map((x, i) => (x === null ? -1 : integerIn(x, ['vertices', 'edges', 'faces'][i], 0, LARGEST_WHOLE)));
      const r = unwrap(raw.exerciseCheckSubdivideCounts(...exerciseMesh(mesh), schemeOf(scheme), integerIn(steps, 'steps', 1, 4), ...given));
      const findings = findingsOf(r.findings);
      return { correct: findings.length === 0, findings };
    },
    // {vertices, edges, faces} after `steps` steps (0..16) of the exercise's mesh.
    subdivisionCounts(mesh, { scheme, steps = 1 } = /** @type {any} */ ({})) {
      const r = unwrap(raw.exerciseSubdivisionCounts(...exerciseMesh(mesh), schemeOf(scheme), integerIn(steps, 'steps', 0, 16)));
      return { vertices: r.vertices, edges: r.edges, faces: r.faces };
    },
  };
}
