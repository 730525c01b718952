// @ts-check
// Reshaping control data between the lessons' state (arrays of [x, y] pairs, readable in a
// share link) and the core's flat layout (Float64Array, points[2*i + k]), and the parameter
// lists the lessons sample a curve at. Data plumbing only: no curve mathematics here.

// [[x, y], ...] -> Float64Array [x0, y0, x1, y1, ...]
export function flat(pairs) {
  const out = new Float64Array(pairs.length * 2);
  pairs.forEach(([x, y], i) => { out[2 * i] = x; out[2 * i + 1] = y; });
  return out;
}

// [x0, y0, x1, y1, ...] -> [[x, y], ...] (every `stride` numbers, the first two of each)
export function pairs(xy, stride = 2) {
  const out = [];
  for (let i = 0; i + 1 < xy.length; i += stride) out.push([xy[i], xy[i + 1]]);
  return out;
}

// n parameters t_j = a + (b - a) j/(n-1), uniform in the parameter (as the lectures sample a
// curve), the last exactly b (no rounding past the domain end).
export function linspace(a, b, n) {
  const out = new Float64Array(n);
  for (let j = 0; j < n; j += 1) out[j] = a + ((b - a) * j) / (n - 1);
  out[n - 1] = b;
  return out;
}
