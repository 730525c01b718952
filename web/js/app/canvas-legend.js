// @ts-check
// A canvas's legend as HTML under the canvas: real text at the page's size,
// which can never cover the drawing. Entries [color, words, dash?] as a lesson gives them to
// painter.legend(); each row leads with a short line sample in the entry's colour and dash
// (the same dash the drawing uses), so the key differs by more than colour. An empty list
// hides the legend; an entry without a colour is a plain note (no sample). The SVG export draws the same entries in a band under the figure
// (app/painter.js).
const SVG_NS = 'http://www.w3.org/2000/svg';
const legends = new WeakMap(); // canvas -> { list, key, entries, scale }

function sample(color, dash, scale) {
  const svg = document.createElementNS(SVG_NS, 'svg');
  svg.setAttribute('width', '36');
  svg.setAttribute('height', '12');
  svg.setAttribute('viewBox', '0 0 36 12');
  svg.setAttribute('aria-hidden', 'true');
  const line = document.createElementNS(SVG_NS, 'line');
  line.setAttribute('x1', '2'); line.setAttribute('y1', '6'); line.setAttribute('x2', '34'); line.setAttribute('y2', '6');
  line.setAttribute('stroke', color);
  line.setAttribute('stroke-width', '3');
  line.setAttribute('stroke-linecap', 'butt');
  if (dash?.length) line.setAttribute('stroke-dasharray', dash.map((d) => d * Math.min(scale, 1)).join(' '));
  svg.append(line);
  return svg;
}

export function showLegend(canvas, entries, scale = 1) {
  let legend = legends.get(canvas);
  const key = JSON.stringify(entries);
  if (legend && legend.key === key && legend.list.isConnected) return;
  if (!legend || !legend.list.isConnected) {
    const list = document.createElement('ul');
    list.className = 'canvas-legend';
    list.setAttribute('aria-label', 'Legend of the drawing');
    if (canvas.id) list.id = `${canvas.id}-legend`;
    // After the canvas and the notes the stage puts right after it.
    let after = canvas;
    while (after.nextElementSibling?.classList.contains('stage-note')) after = after.nextElementSibling;
    after.after(list);
    legend = { list, key: '' };
    legends.set(canvas, legend);
  }
  legend.key = key;
  legend.entries = entries;
  legend.scale = scale;
  legend.list.hidden = entries.length === 0;
  legend.list.replaceChildren(...entries.map(([color, words, dash]) => {
    const item = document.createElement('li');
    const text = document.createElement('span');
    text.textContent = words;
    if (color) item.append(sample(color, dash, scale));
    item.append(text);
    return item;
  }));
}

// The client rectangles of every shown canvas legend (for tests).
export function legendRects() {
  return [...document.querySelectorAll('.canvas-legend')].filter((l) => l.getClientRects().length).map((l) => {
    const r = l.getBoundingClientRect();
    return { id: l.id, text: l.textContent, x: r.left, y: r.top, width: r.width, height: r.height };
  });
}

// The exported PNG carries the legend too: the picture (a PNG blob of the canvas, device
// pixels) with a band under it, one row per entry (line sample, then the words), in the
// page's ink on the canvas background. Without a legend the picture is returned as it is.
export async function withLegendBand(canvas, blob, { ink = '#000', background = '#fff' } = {}) {
  const legend = legends.get(canvas);
  const entries = legend?.entries ?? [];
  if (!blob || !entries.length) return blob;
  const image = await createImageBitmap(blob);
  const dpr = canvas.width / Math.max(1, canvas.getBoundingClientRect().width || canvas.width);
  const px = Math.round(16 * (legend.scale ?? 1) * dpr);
  const rowH = Math.round(px * 1.6);
  const out = document.createElement('canvas');
  out.width = image.width;
  out.height = image.height + rowH * entries.length + px;
  const g = out.getContext('2d');
  g.fillStyle = background;
  g.fillRect(0, 0, out.width, out.height);
  g.drawImage(image, 0, 0);
  g.font = `${px}px system-ui, "DejaVu Sans", sans-serif`;
  g.textBaseline = 'middle';
  entries.forEach(([color, words, dash], i) => {
    const y = image.height + px / 2 + rowH * (i + 0.5);
    if (color) {
      g.strokeStyle = color; g.lineWidth = 3 * dpr; g.setLineDash((dash ?? []).map((d) => d * dpr));
      g.beginPath(); g.moveTo(px, y); g.lineTo(3 * px, y); g.stroke();
    }
    g.fillStyle = ink;
    g.fillText(words, 3.6 * px, y);
  });
  return new Promise((resolve) => out.toBlob(resolve, 'image/png'));
}
