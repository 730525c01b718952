// @ts-check
// Curve drawing pieces for any painter (canvas or SVG, web/js/app/painter.js): the curve,
// the curve tinted by one control point's influence, the control polygon, convex hulls,
// derivative vectors, the curvature comb, knot and joint marks, sample points, and the
// construction steps. They draw what the core computed and nothing else. Reusable by the
// continuity, comparison and surface lessons.

export function drawCurve(painter, xy, style) {
  painter.polyline(xy, { width: 3, ...style });
}

// The curve in segments whose width and opacity follow the influence (blending value) of
// control item `item`: values[count*k + item] at m parameters spread like the n samples
// (both uniform over the domain), so sample j reads value k = round(j (m-1)/(n-1)).
// Grouped into bands so a 1,000-sample curve costs a few dozen strokes, not a thousand.
export function drawInfluence(painter, xy, values, count, item, color) {
  const n = xy.length / 2;
  const m = values.length / count;
  const BANDS = 12;
  let band = -1;
  let run = [];
  const flush = () => {
    if (run.length >= 4 && band > 0) painter.polyline(run, { stroke: color, width: 2 + 7 * (band / BANDS), alpha: 0.25 + 0.6 * (band / BANDS) });
  };
  for (let j = 0; j < n; j += 1) {
    const k = Math.round((j * (m - 1)) / (n - 1));
    const w = Math.min(1, Math.abs(values[count * k + item]));
    const b = Math.round(w * BANDS);
    if (b !== band) {
      run.push(xy[2 * j], xy[2 * j + 1]);
      flush();
      band = b;
      run = j > 0 ? [xy[2 * j - 2], xy[2 * j - 1]] : [];
    }
    run.push(xy[2 * j], xy[2 * j + 1]);
  }
  flush();
}

export function drawPolygon(painter, points, style) {
  if (points.length < 2) return;
  painter.polyline(points.flat(), { width: 1.5, dash: [6, 4], ...style });
}

export function drawHull(painter, hull, style) {
  if (hull.length < 3) return;
  painter.polygon(hull.flat(), { stroke: style.stroke, fill: style.fill, alpha: style.alpha ?? 0.12, width: 1 });
}

export function drawVector(painter, at, v, scale, style, label) {
  const bx = at[0] + v[0] * scale;
  const by = at[1] + v[1] * scale;
  painter.arrow(at[0], at[1], bx, by, { width: 2.5, ...style });
  if (label) painter.text(bx, by, label, { fill: style.stroke, font: 13, dx: 12, dy: -8, halo: style.halo });
}

// teeth[4j..4j+3] = foot (x, y) and curvature vector (kx, ky); scaled so the longest tooth
// is `lengthWorld` long.
export function drawComb(painter, comb, lengthWorld, style) {
  if (!comb || comb.maxCurvature <= 0) return;
  const s = lengthWorld / comb.maxCurvature;
  const tips = [];
  for (let j = 0; j < comb.count; j += 1) {
    const t = comb.teeth;
    const x = t[4 * j];
    const y = t[4 * j + 1];
    const tx = x + t[4 * j + 2] * s;
    const ty = y + t[4 * j + 3] * s;
    painter.line(x, y, tx, ty, { stroke: style.stroke, width: 1, alpha: 0.6 });
    tips.push(tx, ty);
  }
  painter.polyline(tips, { stroke: style.stroke, width: 1.5, alpha: 0.9 });
}

export function drawMarks(painter, xy, labels, style) {
  for (let j = 0; j < xy.length / 2; j += 1) {
    painter.circle(xy[2 * j], xy[2 * j + 1], 4, { fill: style.fill, stroke: style.stroke, width: 1.5 });
    if (labels?.[j]) painter.text(xy[2 * j], xy[2 * j + 1], labels[j], { fill: style.text, font: 12, dy: 16, halo: style.halo });
  }
}

export function drawSamples(painter, xy, every, style) {
  for (let j = 0; j < xy.length / 2; j += every) painter.circle(xy[2 * j], xy[2 * j + 1], 2.2, { fill: style.fill });
}

// The levels of de Casteljau or de Boor up to `step`: level r is a polygon of points,
// drawn in colour r with its points; the last level is the point on the curve. Level 0 (the
// control points that act) gets a ring. names[r][j] is the index i of entry j of level r
// (de Boor: d_i^r with the core's firstIndex; de Casteljau: b_j^r), written i^r.
export function drawLevels(painter, levels, step, colors, halo, { names = null, symbol = 'b' } = {}) {
  const last = Math.min(step, levels.length - 1);
  const n = levels.length - 1;
  const color0 = colors[3 % colors.length];
  levels[0].forEach(([x, y]) => painter.circle(x, y, 12, { stroke: color0, width: 2 }));
  for (let r = 1; r <= last; r += 1) {
    const level = levels[r];
    const color = colors[(r + 3) % colors.length];
    if (level.length > 1) painter.polyline(level.flat(), { stroke: color, width: 2 });
    level.forEach(([x, y], j) => {
      painter.circle(x, y, r === n ? 7 : 5, { fill: color, stroke: halo, width: 1.5 });
      const name = `${symbol}${sub(names ? names[r][j] : j)}${sup(r)}`;
      // the last level's name goes under the P(u) label (above it sit the level r-1 names)
      painter.text(x, y, r === n ? `${name} = P(u)` : name, { fill: color, font: 13, dx: 0, dy: r === n ? 36 : -15, halo });
    });
  }
}

const SUB = '₀₁₂₃₄₅₆₇₈₉';
const SUP = '⁰¹²³⁴⁵⁶⁷⁸⁹';
const sub = (k) => String(k).split('').map((d) => SUB[Number(d)]).join('');
const sup = (k) => String(k).split('').map((d) => SUP[Number(d)]).join('');

// The legend of the drawing: entries [color, words, dash?] go to painter.legend(), which
// shows them next to the canvas (HTML, app/canvas-legend.js) or under the SVG figure; never
// over the drawing.
export function drawLegend(painter, entries) {
  painter.legend(entries);
}

// The scale an arrow is drawn at, as the legend says it: 1/3, 1/6, 1/9 (a unit fraction)
// or the number itself.
export function arrowScale(scale) {
  const k = Math.round(1 / scale);
  return Math.abs(k * scale - 1) < 1e-12 ? `1/${k}` : String(scale);
}
