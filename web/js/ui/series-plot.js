// A small function plot for the side panels: one or more series over a shared parameter
// axis, drawn piece by piece so a jump at a joint stays a visible gap (a smooth-looking
// polyline across the joint would hide exactly what the continuity lesson teaches).
// It draws numbers the core returned; it computes nothing but the axis range.
//
//   drawSeriesPlot(canvas, {
//     series: [{ label, color, dash?, pieces: [{ u: Float64Array, v: Float64Array }] }],
//     marks: [u...]        vertical lines (joints), labelled marks[i].label if objects
//     cursor: u | null     the parameter of the travelling point
//     yLabel, colors: { ink, muted, grid, background }
//   })

const PAD = { left: 46, right: 10, top: 10, bottom: 22 };

function niceRange(lo, hi) {
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) return [0, 1];
  if (hi - lo < 1e-9) { const c = (hi + lo) / 2; const s = Math.max(Math.abs(c) * 0.1, 0.5); return [c - s, c + s]; }
  const span = hi - lo;
  return [lo - span * 0.08, hi + span * 0.08];
}

function tickLabel(x) {
  const a = Math.abs(x);
  if (a !== 0 && (a < 0.01 || a >= 1e4)) return x.toExponential(1);
  return String(Number(x.toPrecision(3)));
}

export function drawSeriesPlot(canvas, { series, marks = [], cursor = null, yLabel = '', colors }) {
  const rect = canvas.getBoundingClientRect();
  const dpr = window.devicePixelRatio || 1;
  const width = Math.max(1, rect.width);
  const height = Math.max(1, rect.height);
  if (canvas.width !== Math.round(width * dpr) || canvas.height !== Math.round(height * dpr)) {
    canvas.width = Math.round(width * dpr);
    canvas.height = Math.round(height * dpr);
  }
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.fillStyle = colors.background;
  g.fillRect(0, 0, width, height);

  let uMin = Infinity; let uMax = -Infinity; let vMin = Infinity; let vMax = -Infinity;
  for (const s of series) {
    for (const p of s.pieces) {
      for (let i = 0; i < p.u.length; i += 1) {
        if (!Number.isFinite(p.v[i])) continue;
        uMin = Math.min(uMin, p.u[i]); uMax = Math.max(uMax, p.u[i]);
        vMin = Math.min(vMin, p.v[i]); vMax = Math.max(vMax, p.v[i]);
      }
    }
  }
  if (!Number.isFinite(uMin)) { uMin = 0; uMax = 1; }
  [vMin, vMax] = niceRange(Math.min(vMin, 0), vMax);
  const plotW = width - PAD.left - PAD.right;
  const plotH = height - PAD.top - PAD.bottom;
  const X = (u) => PAD.left + ((u - uMin) / Math.max(uMax - uMin, 1e-12)) * plotW;
  const Y = (v) => PAD.top + (1 - (v - vMin) / (vMax - vMin)) * plotH;

  g.font = '11px system-ui, "DejaVu Sans", sans-serif';
  g.lineWidth = 1;
  g.strokeStyle = colors.grid;
  g.fillStyle = colors.muted;
  g.textAlign = 'right';
  g.textBaseline = 'middle';
  for (const v of [vMin, 0, vMax]) {
    if (v < vMin || v > vMax) continue;
    g.beginPath(); g.moveTo(PAD.left, Y(v)); g.lineTo(width - PAD.right, Y(v)); g.stroke();
    g.fillText(tickLabel(v), PAD.left - 4, Y(v));
  }
  g.textAlign = 'center';
  g.textBaseline = 'top';
  g.setLineDash([4, 3]);
  g.strokeStyle = colors.muted;
  for (const m of marks) {
    const u = typeof m === 'number' ? m : m.u;
    g.beginPath(); g.moveTo(X(u), PAD.top); g.lineTo(X(u), PAD.top + plotH); g.stroke();
    g.fillText(typeof m === 'number' ? `u=${tickLabel(u)}` : m.label, X(u), PAD.top + plotH + 4);
  }
  g.setLineDash([]);
  if (yLabel) {
    g.textAlign = 'left';
    g.fillStyle = colors.ink;
    g.fillText(yLabel, PAD.left + 4, PAD.top);
  }

  for (const s of series) {
    g.strokeStyle = s.color;
    g.lineWidth = 2;
    g.setLineDash(s.dash ?? []);
    for (const p of s.pieces) {
      g.beginPath();
      let started = false;
      for (let i = 0; i < p.u.length; i += 1) {
        if (!Number.isFinite(p.v[i])) { started = false; continue; }
        const x = X(p.u[i]);
        const y = Math.min(height, Math.max(0, Y(p.v[i])));
        if (started) g.lineTo(x, y); else { g.moveTo(x, y); started = true; }
      }
      g.stroke();
    }
  }
  g.setLineDash([]);
  if (cursor !== null && cursor !== undefined) {
    g.strokeStyle = colors.ink;
    g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(X(cursor), PAD.top); g.lineTo(X(cursor), PAD.top + plotH); g.stroke();
  }
  return { X, Y, uMin, uMax, vMin, vMax };
}
