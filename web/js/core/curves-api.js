// @ts-check
// Curves part of the API; documented in docs/api-curves.md.
// Plain values in, typed arrays out, one wasm call per curve batch (never per point).
// Every curve is a plain object:
//   { kind, dim, points, degree?, knots?, weights?, tangents?, tension?, nodes? }
// kind: 'bezier' | 'bspline' | 'nurbs' | 'hermite' | 'catmull-rom' | 'cardinal' | 'interpolation'
// points[dim*i + k] (dim 2 or 3). This module only checks types and fills defaults; the
// core checks the values (finite, knots non-decreasing, weights positive, domain, ...) and
// names the offending element in its message.
import { unwrap, fail, isNumberArray } from './errors.js';
import { EMPTY, CUBIC_BASES, MAX_SAMPLES, numbers, optionalNumbers, dimension, wholeNumber, finiteNumber, normalizeCurve, derivativeOrder } from './curve-spec.js';
import { createCurveSamplingApi } from './curve-sampling-api.js';

export { normalizeCurve } from './curve-spec.js';

function guaranteesOut(r) {
  return { parametric: r.parametric, geometric: r.geometric, joints: r.joints, interpolated: Array.from(r.interpolated) };
}

function cubicBasis(kind, what) {
  if (typeof kind !== 'string' || !CUBIC_BASES.includes(kind)) {
    fail('unknown-basis', `${what} is ${JSON.stringify(kind)?.slice(0, 40)}; expected ${CUBIC_BASES.join(', ')}`);
  }
  return kind;
}

function transpose(m, n) {
  const t = new Float64Array(n * n);
  for (let r = 0; r < n; r += 1) for (let c = 0; c < n; c += 1) t[c * n + r] = m[r * n + c];
  return t;
}

// The fields of a core result a caller sees (the core's ok flag stays behind).
function pick(r, keys) {
  const out = {};
  for (const k of keys) out[k] = r[k];
  return out;
}

function curveList(segments, what = 'segments') {
  if (!Array.isArray(segments) || segments.length === 0) fail('invalid-argument', `${what} must be a non-empty list of curves`);
  return segments.map((c, i) => normalizeCurve(c, `${what}[${i}]`));
}

function sampleCount(n) {
  return wholeNumber(n, 'the number of samples', 2, 1_000_000);
}

function patchKind(kind) {
  if (kind !== 'hermite' && kind !== 'bezier') fail('unknown-basis', `patch kind must be 'hermite' or 'bezier', not ${JSON.stringify(kind)?.slice(0, 40)}`);
  return kind;
}

const PLANE_MAP_KINDS = ['affine', 'perspective'];
// { kind, angle (degrees), scale, shear, tx, ty, px, py } with the identity's defaults.
function planeMap(t) {
  if (t === null || typeof t !== 'object') fail('invalid-argument', "transform must be an object like { kind: 'affine', angle: 30 }");
  if (!PLANE_MAP_KINDS.includes(t.kind)) fail('invalid-argument', `transform.kind is ${JSON.stringify(t.kind)?.slice(0, 40)}; expected affine or perspective`);
  const defaults = { angle: 0, scale: 1, shear: 0, tx: 0, ty: 0, px: 0, py: 0 };
  const out = { kind: t.kind };
  for (const [k, d] of Object.entries(defaults)) out[k] = t[k] === undefined ? d : finiteNumber(t[k], `transform.${k}`);
  return out;
}

export function createCurvesApi(raw) {
  const api = {
    ...createCurveSamplingApi(raw),
    // The row-major 4x4 basis matrix M of P(u) = [u^3 u^2 u 1] M G (lectures 000, 003);
    // lecture 001's Q(t) = G M T uses its transpose (segmentMatrices gives both).
    basisMatrix(kind, form = 'descending') {
      return unwrap(raw.basisMatrix(String(kind), String(form))).matrix;
    },
    // The same matrix as on the slide, {denominator, numerators} (1/6 [...] for the
    // uniform B-spline, 1/2 [...] for Catmull-Rom). form: 'descending' (lectures 000, 003),
    // 'ascending' (002: u = (1, u, u^2, u^3), C = M g, the rows reversed) or 'transposed'
    // (001: Q(t) = G M T); an unknown form throws 'unknown-form'.
    basisMatrixRational(kind, form = 'descending') {
      return unwrap(raw.basisMatrix(String(kind), String(form))).rational;
    },
    // Lecture 000's Hermite derivation, computed: the constraint matrix and its inverse.
    hermiteFromConstraints() {
      const r = unwrap(raw.hermiteFromConstraints());
      return { constraints: r.constraints, matrix: r.matrix };
    },

    // Blending functions (B = M T of lecture 001; Cox-de Boor N_i,p; NURBS R_i,p) of every
    // control item at every param: values[count*j + i]. Hermite: count = 2K, items 0..K-1
    // are the points p_i, K..2K-1 the tangents t_i. order > 0 gives their derivatives.
    blendingFunctions(curve, params, order = 0) {
      const r = unwrap(raw.curveBlending(normalizeCurve(curve), numbers(params, 'params'), derivativeOrder(order)));
      return { count: r.count, values: r.values };
    },
    // The matrix form of one polynomial piece: P(u) = [u^p .. u 1] M G, C = M G; MT = M^T
    // for lecture 001's Q(t) = G M^T T. Matrices row-major; G and C have `columns` numbers
    // per row (dim, or dim+1 homogeneous for rational curves).
    // options.form: `shown` holds M, G, C as that lecture writes them
    // ({form, M, G, C, size, geometryRows, geometryColumns, rational}); default 'descending'.
    segmentMatrices(curve, segmentIndex = 0, { form = 'descending' } = {}) {
      wholeNumber(segmentIndex, 'segmentIndex', 0, 2 ** 31 - 1, 'segment-out-of-range');
      const r = unwrap(raw.curveSegment(normalizeCurve(curve), segmentIndex, String(form)));
      const n = r.degree + 1;
      return {
        segment: r.segment,
        segmentCount: r.segmentCount,
        degree: r.degree,
        basis: r.basis,
        M: r.M,
        MT: transpose(r.M, n),
        // M as the slides write it, (1/denominator) . numerators (row-major
        // integers), from the core; null when M has no small common denominator.
        rational: r.rational,
        G: r.G,
        C: r.C,
        columns: r.columns,
        rows: n,
        controlIndices: r.controlIndices,
        labels: r.labels,
        start: r.start,
        end: r.end,
        localParameter: r.localParameter,
        homogeneous: r.homogeneous,
        shown: r.shown,
        convention: r.localParameter
          ? `P(t) = [u^${r.degree} .. u 1] M G with u = (t - ${r.start}) / (${r.end} - ${r.start}); Q(u) = G^T M^T [u^${r.degree} .. u 1]^T`
          : `P(u) = [u^${r.degree} .. u 1] M G with the global parameter u`,
      };
    },

    // de Casteljau with every level: levels[r] holds n+1-r points (dim each); levels[n]
    // is the point on the curve. Rational: pass weights; levelWeights[r] then holds theirs.
    deCasteljau(points, dim, t, weights = undefined) {
      const r = unwrap(raw.bezierDeCasteljau(numbers(points, 'points'), dimension(dim), finiteNumber(t, 't'),
        optionalNumbers(weights, 'weights')));
      const levels = Array.from(r.levels);
      const out = { degree: r.degree, levels, point: levels[levels.length - 1] };
      if (weights !== undefined && weights !== null) out.levelWeights = Array.from(r.levelWeights);
      return out;
    },
    // The two Bezier curves that together trace the original exactly (lecture 002).
    subdivideBezier(points, dim, t = 0.5, weights = undefined) {
      const r = unwrap(raw.bezierSubdivide(numbers(points, 'points'), dimension(dim), finiteNumber(t, 't'),
        optionalNumbers(weights, 'weights')));
      const out = { left: r.left, right: r.right };
      if (weights !== undefined && weights !== null) Object.assign(out, { leftWeights: r.leftWeights, rightWeights: r.rightWeights });
      return out;
    },
    // S_L, S_R ((n+1)x(n+1), row-major) with left = S_L P, right = S_R P; degree 3 at
    // t = 1/2 gives lecture 002's G_B^L and G_B^R.
    bezierSubdivisionMatrices(degree = 3, t = 0.5) {
      wholeNumber(degree, 'degree', 1, 20, 'degree-out-of-range');
      const r = unwrap(raw.bezierSubdivisionMatrices(degree, finiteNumber(t, 't')));
      // leftRational / rightRational: {denominator, numerators} as the slide writes
      // them (1/8 [integers] for lecture 002), or null for a t without a small denominator.
      return { left: r.left, right: r.right, size: degree + 1, leftRational: r.leftRational, rightRational: r.rightRational };
    },
    // Degree n -> n+1, the same curve: { points, weights? }.
    elevateDegree(points, dim, weights = undefined) {
      const r = unwrap(raw.bezierElevate(numbers(points, 'points'), dimension(dim), optionalNumbers(weights, 'weights')));
      return weights !== undefined && weights !== null ? { points: r.points, weights: r.weights } : { points: r.points };
    },
    // Lecture 002: the geometry q (4 rows) in basis toKind giving the same cubic segment as
    // points (4 rows) in basis fromKind: q = M_to^-1 M_from P.
    convertBasis(points, dim, fromKind, toKind) {
      return unwrap(raw.basisConvert(numbers(points, 'points'), dimension(dim), cubicBasis(fromKind, 'fromKind'),
        cubicBasis(toKind, 'toKind'))).points;
    },

    // ---- B-splines and NURBS (bezier and uniform B-splines are taken with their implicit knots)
    // de Boor with every intermediate point: levels[r] holds p+1-r points (dim each); entry j
    // of level r is d_(firstIndex+r+j); levels[p] is the point. alphas[r-1][j] is the
    // interpolation factor of that entry. { span, degree, firstIndex, levels, alphas, point, levelWeights? }
    deBoor(curve, u) {
      const spec = normalizeCurve(curve);
      const r = unwrap(raw.bsplineDeBoor(spec, finiteNumber(u, 'u')));
      const levels = Array.from(r.levels);
      const out = { span: r.span, degree: r.degree, firstIndex: r.firstIndex, levels, alphas: Array.from(r.alphas), point: levels[levels.length - 1] };
      if (spec.kind === 'nurbs' || (spec.kind === 'bezier' && spec.weights.length > 0)) out.levelWeights = Array.from(r.levelWeights);
      return out;
    },
    // Boehm's insertion of one knot u: { curve (same curve, one more point and knot), span,
    // insertedIndex (of u in the new knots), recomputed (indices i = span-p+1..span with
    // Q_i = a_i P_i + (1-a_i) P_i-1), alphas (a_i), newPoints (the i with 0 < a_i < 1) }.
    insertKnot(curve, u) {
      const r = unwrap(raw.bsplineInsertKnot(normalizeCurve(curve), finiteNumber(u, 'u')));
      return { curve: r.curve, span: r.span, insertedIndex: r.insertedIndex, recomputed: r.recomputed, alphas: r.alphas, newPoints: r.newPoints };
    },
    // Every non-empty span as a Bezier curve of degree p: [{ points, weights?, start, end }].
    bsplineToBezier(curve) {
      return Array.from(unwrap(raw.bsplineToBezier(normalizeCurve(curve))).segments);
    },
    // Distinct knot values: { values, multiplicities, firstIndices, interior (1 = a joint
    // inside the domain), continuity (C^(p-m) at that knot; -1: the curve may jump) }.
    knotMultiplicities(curve) {
      const r = unwrap(raw.bsplineKnotMultiplicities(normalizeCurve(curve)));
      return { knots: r.knots, values: r.values, multiplicities: r.multiplicities, firstIndices: r.firstIndices, interior: r.interior, continuity: r.continuity };
    },
    // The index of the segment (as segmentMatrices numbers them) holding the parameter u:
    // B-splines count the non-empty knot spans, the end of the domain is in the last segment.
    segmentAt(curve, u) {
      return unwrap(raw.curveSegmentAt(normalizeCurve(curve), finiteNumber(u, 'u'))).segment;
    },
    isClampedKnots(knots, degree) {
      return unwrap(raw.knotsClamped(numbers(knots, 'knots'), wholeNumber(degree, 'degree', 1, 2 ** 31 - 1, 'degree-out-of-range'))).clamped;
    },
    // Lecture 002: {0,0,0,0,1,1,1,1} makes the cubic B-spline a cubic Bezier. True
    // when the B-spline on these knots is exactly the Bezier curve of its points.
    isBezierInDisguise(knots, degree) {
      return unwrap(raw.knotsClamped(numbers(knots, 'knots'), wholeNumber(degree, 'degree', 1, 2 ** 31 - 1, 'degree-out-of-range'))).bezier;
    },
    // Continuity constraints of a piecewise curve (4 entries per segment: Bezier P0..P3 or
    // Hermite p0, p1, t0, t1; dim numbers each), mode 'free' | 'C0' | 'G1' | 'C1' | 'C2':
    // the entries after dragging entry `index` to `to`, after applying the mode at every
    // joint, or with one more segment (B-spline and Catmull-Rom windows: one more point).
    dragWithConstraint(points, dim, family, mode, index, to) {
      return unwrap(raw.jointConstraint('drag', numbers(points, 'points'), dimension(dim), cubicBasis(family, 'family'), String(mode),
        wholeNumber(index, 'index', 0, 2 ** 31 - 1), numbers(to, 'to'))).points;
    },
    enforceConstraint(points, dim, family, mode) {
      return unwrap(raw.jointConstraint('enforce', numbers(points, 'points'), dimension(dim), cubicBasis(family, 'family'), String(mode), 0, EMPTY)).points;
    },
    appendSegment(points, dim, family, mode) {
      return unwrap(raw.jointConstraint('append', numbers(points, 'points'), dimension(dim), cubicBasis(family, 'family'), String(mode), 0, EMPTY)).points;
    },
    // Exact conics as NURBS curves (degree 2), ready for evaluateCurve.
    nurbsCircle({ center = [0, 0], radius = 1, dim = center.length } = {}) {
      return unwrap(raw.nurbsPreset('circle', numbers(center, 'center'), EMPTY, EMPTY, dimension(dim), Float64Array.of(finiteNumber(radius, 'radius')))).curve;
    },
    nurbsArc({ center = [0, 0], radius = 1, startAngle = 0, endAngle = Math.PI / 2, dim = center.length } = {}) {
      return unwrap(raw.nurbsPreset('arc', numbers(center, 'center'), EMPTY, EMPTY, dimension(dim),
        Float64Array.of(finiteNumber(radius, 'radius'), finiteNumber(startAngle, 'startAngle'), finiteNumber(endAngle, 'endAngle')))).curve;
    },
    nurbsEllipse({ center = [0, 0], rx = 2, ry = 1, dim = center.length } = {}) {
      return unwrap(raw.nurbsPreset('ellipse', numbers(center, 'center'), EMPTY, EMPTY, dimension(dim),
        Float64Array.of(finiteNumber(rx, 'rx'), finiteNumber(ry, 'ry')))).curve;
    },
    // The conic arc from p0 to p2 with tangents towards p1 and middle weight w:
    // { curve, conicType: 'ellipse' (w < 1) | 'parabola' (w = 1) | 'hyperbola' (w > 1) }.
    /** @param {{ p0?: ArrayLike<number>, p1?: ArrayLike<number>, p2?: ArrayLike<number>, weight?: number, dim?: number }} [options] */
    nurbsConic({ p0, p1, p2, weight = Math.SQRT1_2, dim = p0?.length } = {}) {
      const r = unwrap(raw.nurbsPreset('conic', numbers(p0, 'p0'), numbers(p1, 'p1'), numbers(p2, 'p2'), dimension(dim),
        Float64Array.of(finiteNumber(weight, 'weight'))));
      return { curve: r.curve, conicType: r.conicType };
    },

    // ---- differential geometry
    // { curvature, signedCurvature (dim 2 only, else empty), speed |P'|, tangent (unit,
    // dim per param), singular (Uint8Array, 1 where P' = 0: tangent and curvature undefined, stored as 0;
    // show 'undefined', never the 0) }
    curvature(curve, params) {
      const r = unwrap(raw.curveCurvature(normalizeCurve(curve), numbers(params, 'params')));
      return { curvature: r.curvature, signedCurvature: r.signedCurvature, speed: r.speed, tangent: r.tangent, singular: r.singular };
    },
    // Length between parameters a <= b (default: the whole domain), Gauss-Legendre.
    arcLength(curve, a = undefined, b = undefined) {
      const spec = normalizeCurve(curve);
      let start = a;
      let end = b;
      if (start === undefined || end === undefined) {
        const d = unwrap(raw.curveDomain(spec));
        if (start === undefined) start = d.start;
        if (end === undefined) end = d.end;
      }
      return unwrap(raw.curveArcLength(spec, finiteNumber(start, 'a'), finiteNumber(end, 'b'))).length;
    },
    // n parameters with equal arc length between neighbours: { params, lengths, total }.
    arcLengthParams(curve, n = 50) {
      wholeNumber(n, 'the number of parameters', 2, MAX_SAMPLES);
      const r = unwrap(raw.curveArcLengthParams(normalizeCurve(curve), n));
      return { params: r.params, lengths: r.lengths, total: r.total };
    },
    // Continuity where curve a ends and curve b starts: { parametric: k, geometric: k
    // (k = -1..2), evidence: { tolerance, a, b ([P, P', P''] at the joint, dim each),
    // positionGap, d1Gap, d2Gap, ratio |b'|/|a'|, tangentAngle, curvatureA, curvatureB,
    // curvatureVectorGap, zeroTangent, zeroTangentA, zeroTangentB, notes }, wordings: [{ id,
    // source, wording, geometric, reason }] } (curvatureA/B are null where that side's P' = 0).
    // Scale-free: positions are compared relative to the joint's bounding box, derivatives and
    // curvature vectors relative to the larger of the two (docs/api-curves.md).
    jointContinuity(a, b, { tolerance = 1e-9 } = {}) {
      const r = unwrap(raw.curveJointContinuity(normalizeCurve(a, 'a'), normalizeCurve(b, 'b'), finiteNumber(tolerance, 'tolerance')));
      const e = r.evidence;
      return {
        parametric: r.parametric,
        geometric: r.geometric,
        evidence: {
          tolerance: e.tolerance, a: e.a, b: e.b, positionGap: e.positionGap, size: e.size, relativeGap: e.relativeGap, d1Gap: e.d1Gap, d2Gap: e.d2Gap,
          ratio: e.ratio, tangentAngle: e.tangentAngle, curvatureA: e.curvatureA, curvatureB: e.curvatureB,
          curvatureVectorGap: e.curvatureVectorGap, zeroTangent: e.zeroTangent, zeroTangentA: e.zeroTangentA,
          zeroTangentB: e.zeroTangentB, notes: Array.from(e.notes),
        },
        wordings: Array.from(r.wordings, (w) => ({ id: w.id, source: w.source, wording: w.wording, geometric: w.geometric, reason: w.reason })),
      };
    },

    // ---- The derivation of a cubic family's matrix, exact: { family, size,
    // constraint, inverse, basis, rhs (B-spline) | null, substitution (Bezier) | null,
    // conditions (one line per constraint row) }; each matrix { rows, cols, num, den }.
    cubicDerivation(family) {
      const r = unwrap(raw.cubicDerivation(cubicBasis(family, 'family')));
      return { family: r.family, size: r.size, constraint: r.constraint, inverse: r.inverse, basis: r.basis,
        rhs: r.rhs, substitution: r.substitution, conditions: Array.from(r.conditions) };
    },

    // ---- polynomial interpolation (lecture 000): the curve through the points, and its
    // Vandermonde system: { curve, nodes, vandermonde (V, rows u_i^n .. 1), inverse (V^-1),
    // coefficients (C = V^-1 P: row r holds a_(n-r), dim numbers) }.
    interpolatePolynomial(points, dim, nodes = undefined) {
      const curve = { kind: 'interpolation', dim: dimension(dim), points: numbers(points, 'points') };
      if (nodes !== undefined && nodes !== null) curve.nodes = numbers(nodes, 'nodes');
      const r = unwrap(raw.interpolationSystem(normalizeCurve(curve)));
      return { curve: { ...curve, nodes: r.nodes }, nodes: r.nodes, vandermonde: r.vandermonde, inverse: r.inverse, coefficients: r.coefficients };
    },

    // The core's limits: { maxInterpolationPoints, maxDegree } (lessons read them here
    // instead of keeping a copy).
    curveLimits() {
      const r = unwrap(raw.curveLimits());
      return { maxInterpolationPoints: r.maxInterpolationPoints, maxDegree: r.maxDegree };
    },

    // ---- bicubic patches (lecture 002): p(u,v) = u^T M P M^T v, kind 'hermite' | 'bezier';
    // points: the 4x4 geometry matrix of 3D vectors, points[3*(4*i + j) + k] (see
    // docs/api-curves.md for the Hermite layout). Returns { nu, nv, positions, normals, du,
    // dv (all [3*(nv*i + j) + k] at u = i/(nu-1), v = j/(nv-1)), twists (p_uv at the corners
    // (0,0), (0,1), (1,0), (1,1): [3*c + k]) }.
    // ---- Guarantees: what holds for EVERY control polygon, from the basis.
    // A chain of cubic segments of one basis: slot j is a control point (isPoint[j] true) or a
    // tangent vector; maps[s] is segment s's 4 x slots matrix (row-major: weight of slot j in
    // geometry row r at maps[s][slots*r + j]). -> {parametric, geometric, joints, interpolated}:
    // the weakest C^k / G^k over the joints and the slots every curve passes through.
    /** @param {{ basis?: string, slots?: number, maps?: ArrayLike<number>[], isPoint?: ArrayLike<boolean> }} [options] */
    chainGuarantees({ basis, slots, maps, isPoint } = {}) {
      cubicBasis(basis, 'basis');
      wholeNumber(slots, 'slots', 1, 4096);
      if (!Array.isArray(maps) || maps.length === 0) fail('invalid-argument', 'maps must be a non-empty list of 4 x slots matrices');
      const flat = new Float64Array(maps.length * 4 * slots);
      maps.forEach((m, s) => {
        const rows = numbers(m, `maps[${s}]`);
        if (rows.length !== 4 * slots) fail('invalid-argument', `maps[${s}] has ${rows.length} weights, not 4 x ${slots}`);
        flat.set(rows, 4 * slots * s);
      });
      if (!Array.isArray(isPoint) || isPoint.length !== slots) fail('invalid-argument', `isPoint needs one true/false per slot (${slots})`);
      return guaranteesOut(unwrap(raw.chainGuarantees(basis, slots, flat, Int32Array.from(isPoint, (v) => (v ? 1 : 0)))));
    },
    // A B-spline's guarantees from its knots: C^k at the weakest interior knot (p - m for a knot
    // of multiplicity m, computed from the basis functions' derivatives) and the control points
    // whose basis function reaches 1 (interpolated for every polygon).
    /** @param {{ knots?: ArrayLike<number>, degree?: number, count?: number }} [options] */
    bsplineGuarantees({ knots, degree = 3, count } = {}) {
      wholeNumber(degree, 'degree', 1, 20);
      wholeNumber(count, 'count', 1, 1_000_000);
      return guaranteesOut(unwrap(raw.bsplineGuarantees(numbers(knots, 'knots'), degree, count)));
    },

    /** @param {{ kind?: string, points?: ArrayLike<number>, nu?: number, nv?: number }} [options] */
    samplePatch({ kind, points, nu = 16, nv = 16 } = {}) {
      patchKind(kind);
      wholeNumber(nu, 'nu', 2, 4096);
      wholeNumber(nv, 'nv', 2, 4096);
      const r = unwrap(raw.patchSample(kind, numbers(points, 'points'), nu, nv));
      return { nu: r.nu, nv: r.nv, positions: r.positions, normals: r.normals, du: r.du, dv: r.dv, twists: r.twists };
    },

    // ---- comparison measurements (docs/api-curves.md "Comparison
    // measurements"): the numbers behind the comparison lesson's cells, with tolerances
    // relative to the size of what is compared.
    // The convex hull of plane points (flat, dim 2): { indices (Int32Array into the points,
    // counter-clockwise from the lowest x, then lowest y; collinear points dropped), tolerance }.
    convexHull(points) {
      return pick(unwrap(raw.convexHull(numbers(points, 'points'))), ['indices', 'tolerance']);
    },
    // The map x' = (a x + b y + tx)/w, y' = (c x + d y + ty)/w, w = px x + py y + 1 with
    // [a b; c d] = scale R(angle in degrees) [1 shear; 0 1]; kind 'affine' ignores px, py.
    // -> { points, w }: w(P_i) are the weights of the rational curve that follows the map.
    // A point with w <= 0 is refused ('perspective-behind-eye'), named as `what` + index.
    mapPoints(points, dim, transform, { what = 'point ' } = {}) {
      const t = planeMap(transform);
      return pick(unwrap(raw.mapPoints(numbers(points, 'points'), dimension(dim), t.kind === 'perspective', t.angle, t.scale,
        t.shear, t.tx, t.ty, t.px, t.py, String(what))), ['points', 'w']);
    },
    // The largest distance between corresponding points of a and b (dim 1..3; e.g. two curves
    // sampled at the same parameters): { distance, index }.
    maxDistance(a, b, dim) {
      return pick(unwrap(raw.maxDistance(numbers(a, 'a'), numbers(b, 'b'), wholeNumber(dim, 'dim', 1, 3, 'invalid-dimension'))), ['distance', 'index']);
    },
    // Lecture 003's convex hull row from the blending weights of every segment (sampled at
    // `samples` parameters over its domain): { tangentWeight, weightsPoints, minWeight,
    // minWeightAt (the parameter where it first occurs), sumError, convexHull, tolerance }.
    blendingWeightCheck(segments, samples = 101) {
      return pick(unwrap(raw.blendingWeightCheck(curveList(segments), sampleCount(samples))),
        ['tangentWeight', 'weightsPoints', 'minWeight', 'minWeightAt', 'sumError', 'convexHull', 'tolerance']);
    },
    // Distance from every control point to the sampled segments: { distances, interpolated
    // (Int32Array, the points within tolerance), farthest, nearestMissed (-1: none), tolerance }.
    pointCurveDistances(points, dim, segments, samples = 101) {
      return pick(unwrap(raw.pointCurveDistances(numbers(points, 'points'), dimension(dim), curveList(segments), sampleCount(samples))),
        ['distances', 'interpolated', 'farthest', 'nearestMissed', 'tolerance']);
    },
    // Every cubic segment split at u = 1/2 (converted to Bezier first): { error (largest
    // distance of the halves from the original), segments }.
    splitCheck(segments) {
      return pick(unwrap(raw.splitCheck(curveList(segments))), ['error', 'segments']);
    },
    // One knot inserted in the middle of every span (Boehm): { error, inserted, pointsBefore, pointsAfter }.
    knotRefinementCheck(curve, samples = 101) {
      return pick(unwrap(raw.knotRefinementCheck(normalizeCurve(curve), sampleCount(samples))), ['error', 'inserted', 'pointsBefore', 'pointsAfter']);
    },

    // Tangents from the points (lecture 002's Catmull-Rom conditions): t_i = (P_i+1 - P_i-1)/2
    // inside, the one-sided chords at the ends; Float64Array, same layout as the points.
    catmullRomTangents(points, dim) {
      return unwrap(raw.catmullRomTangents(numbers(points, 'points'), dimension(dim))).tangents;
    },
    // The same bicubic patch in the other basis (hermite <-> bezier): Q = C P C^T with
    // C = M_to^-1 M_from; same layout as samplePatch's points (Float64Array of 48).
    convertPatchBasis(points, fromKind, toKind) {
      return unwrap(raw.convertPatchBasis(patchKind(fromKind), patchKind(toKind), numbers(points, 'points'))).points;
    },
    // The curvature comb (lecture 004), dim 2: { teeth (Float64Array, [x, y, kx, ky] per
    // param: the point and the curvature vector kappa N, N the left normal), maxCurvature,
    // singular (how many params have P' = 0; their tooth is 0) }.
    curvatureComb(curve, params) {
      return pick(unwrap(raw.curvatureComb(normalizeCurve(curve), numbers(params, 'params'))), ['teeth', 'maxCurvature', 'singular']);
    },
    // Control points in homogeneous coordinates (w x, w y, [w z,] w), stride dim + 1.
    homogeneousLift(points, dim, weights) {
      return unwrap(raw.homogeneousLift(numbers(points, 'points'), dimension(dim), numbers(weights, 'weights'))).points;
    },
    // Bicubic patches (samplePatch's nets): the corners p(0,0), p(0,1), p(1,0), p(1,1) against
    // the net entries holding them: { corners: [{ entry, distance, interpolated }], tolerance }.
    /** @param {{ kind?: string, points?: ArrayLike<number> }} [options] */
    patchCornerCheck({ kind, points } = {}) {
      const r = unwrap(raw.patchCornerCheck(patchKind(kind), numbers(points, 'points')));
      return { corners: Array.from(r.corners, (c) => ({ entry: c.entry, distance: c.distance, interpolated: c.interpolated })), tolerance: r.tolerance };
    },
    // Patch a's u = 1 edge against patch b's u = 0 edge at `samples` values of v:
    // { positionGap, duGap, c0, c1, tolerance }.
    /** @param {{ kind?: string, a?: ArrayLike<number>, b?: ArrayLike<number>, samples?: number }} [options] */
    patchJoinCheck({ kind, a, b, samples = 17 } = {}) {
      return pick(unwrap(raw.patchJoinCheck(patchKind(kind), numbers(a, 'a'), numbers(b, 'b'), sampleCount(samples))),
        ['positionGap', 'duGap', 'c0', 'c1', 'tolerance']);
    },

    // Affine map of flat points: matrix is (dim+1)x(dim+1) row-major homogeneous (last row
    // 0 .. 0 1), e.g. for the affine-invariance demo. Returns a new Float64Array.
    transformPoints(points, dim, matrix) {
      const p = numbers(points, 'points');
      const d = dimension(dim);
      const m = numbers(matrix, 'matrix');
      const n = d + 1;
      if (m.length !== n * n) fail('invalid-argument', `matrix must have ${n * n} numbers ((dim+1) x (dim+1)), not ${m.length}`);
      for (let i = 0; i < m.length; i += 1) if (!Number.isFinite(m[i])) fail('non-finite-input', `matrix entry ${i} is ${m[i]}, not a finite number`);
      if (p.length % d !== 0) fail('invalid-points', `points has ${p.length} numbers, which is not a multiple of dim = ${d}`);
      const out = new Float64Array(p.length);
      for (let i = 0; i < p.length; i += d) {
        for (let r = 0; r < d; r += 1) {
          let s = m[r * n + d];
          for (let c = 0; c < d; c += 1) s += m[r * n + c] * p[i + c];
          out[i + r] = s;
        }
      }
      return out;
    },
  };
  return api;
}