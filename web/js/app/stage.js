// The lesson canvas: size (device pixels), the world-to-screen transform from the state's
// view {cx, cy, zoom}, and the interaction a person expects: drag a handle (mouse, touch,
// pen), drag empty space to pan, wheel or pinch to zoom, and the keyboard: [ and ] select
// the previous/next handle, arrows nudge it (Shift: finer), Escape deselects, + and -
// zoom. Handles come from the lesson; the stage only finds the nearest one.
import { Transform } from './painter.js';
import { createGlMesh } from '../ui/gl-mesh.js';

const HIT_RADIUS_PX = 14;

export function createStage(canvas, hooks) {
  const g = canvas.getContext('2d');
  let cssWidth = 300;
  let cssHeight = 150;
  let dpr = 1;
  const pointers = new Map(); // pointerId -> {x, y}
  let gesture = null; // {type:'handle', id} | {type:'pan', ...} | {type:'pinch', ...}

  function transform() {
    const v = hooks.getView();
    return new Transform({ cx: v.cx, cy: v.cy, zoom: v.zoom, width: cssWidth, height: cssHeight });
  }

  // The WebGL2 canvas under this one (issue 17), made on a lesson's first request:
  // { canvas, renderer } once made, false where the browser has no WebGL2 (or lost it).
  let underlay = null;
  function placeUnderlay() {
    if (!underlay) return;
    const style = underlay.canvas.style;
    style.left = `${canvas.offsetLeft}px`;
    style.top = `${canvas.offsetTop}px`;
    style.width = `${cssWidth}px`;
    style.height = `${cssHeight}px`;
  }
  function noWebGl(reason) {
    underlay = false;
    canvas.classList.remove('over-gl');
    if (canvas.parentElement?.querySelector('.stage-note')) return;
    const note = document.createElement('p');
    note.className = 'stage-note';
    note.setAttribute('role', 'status');
    note.textContent = `Drawn with the 2D canvas: ${reason}, so big meshes draw slowly.`;
    canvas.after(note);
  }
  function makeUnderlay() {
    const glCanvas = document.createElement('canvas');
    glCanvas.className = 'gl-underlay';
    glCanvas.setAttribute('aria-hidden', 'true');
    let renderer = null;
    try {
      renderer = createGlMesh(glCanvas);
    } catch (err) {
      renderer = null;
      console.warn(err);
    }
    if (!renderer) { noWebGl('this browser has no WebGL2'); return; }
    canvas.before(glCanvas);
    canvas.classList.add('over-gl');
    glCanvas.addEventListener('webglcontextlost', (event) => {
      event.preventDefault();
      glCanvas.remove();
      noWebGl('the graphics card stopped answering (WebGL2 context lost)');
      hooks.onResize();
    });
    underlay = { canvas: glCanvas, renderer };
    placeUnderlay();
  }

  function resize() {
    const rect = canvas.getBoundingClientRect();
    dpr = window.devicePixelRatio || 1;
    cssWidth = Math.max(1, rect.width);
    cssHeight = Math.max(1, rect.height);
    canvas.width = Math.round(cssWidth * dpr);
    canvas.height = Math.round(cssHeight * dpr);
    placeUnderlay();
    hooks.onResize();
  }
  new ResizeObserver(resize).observe(canvas);

  function local(event) {
    const rect = canvas.getBoundingClientRect();
    return [event.clientX - rect.left, event.clientY - rect.top];
  }

  function hit(sx, sy, radius = HIT_RADIUS_PX * hooks.handleScale()) {
    const t = transform();
    let best = null;
    let bestD = radius;
    for (const handle of hooks.getHandles()) {
      const [hx, hy] = t.toScreen(handle.x, handle.y);
      const d = Math.hypot(hx - sx, hy - sy);
      if (d <= bestD) { best = handle; bestD = d; }
    }
    return best;
  }

  function zoomAt(sx, sy, factor) {
    const v = hooks.getView();
    const t = transform();
    const [wx, wy] = t.toWorld(sx, sy);
    const zoom = Math.min(1e5, Math.max(1, v.zoom * factor));
    // keep the world point under the cursor fixed
    const cx = wx - (sx - cssWidth / 2) / zoom;
    const cy = wy + (sy - cssHeight / 2) / zoom;
    hooks.setView({ cx, cy, zoom });
  }

  canvas.addEventListener('pointerdown', (event) => {
    canvas.focus({ preventScroll: true });
    const [sx, sy] = local(event);
    pointers.set(event.pointerId, { x: sx, y: sy });
    canvas.setPointerCapture(event.pointerId);
    if (pointers.size === 2) {
      const [a, b] = [...pointers.values()];
      gesture = { type: 'pinch', dist: Math.hypot(a.x - b.x, a.y - b.y), view: hooks.getView() };
      return;
    }
    const radius = (event.pointerType === 'touch' ? 24 : HIT_RADIUS_PX) * hooks.handleScale();
    const handle = hit(sx, sy, radius);
    if (handle && handle.draggable !== false) {
      gesture = { type: 'handle', id: handle.id, pointerId: event.pointerId };
      hooks.select(handle.id);
      hooks.dragStart(handle.id);
    } else if (handle) {
      hooks.select(handle.id);
      gesture = null;
    } else if (hooks.click && hooks.click(...transform().toWorld(sx, sy), event)) {
      gesture = null;
    } else {
      gesture = { type: 'pan', x: sx, y: sy, view: hooks.getView() };
    }
    event.preventDefault();
  });

  canvas.addEventListener('pointermove', (event) => {
    const [sx, sy] = local(event);
    if (pointers.has(event.pointerId)) pointers.set(event.pointerId, { x: sx, y: sy });
    if (!gesture) {
      const handle = hit(sx, sy);
      canvas.style.cursor = handle ? 'grab' : 'default';
      hooks.hover(handle ? handle.id : null, ...transform().toWorld(sx, sy));
      return;
    }
    if (gesture.type === 'handle' && event.pointerId === gesture.pointerId) {
      // Coalesced events carry every intermediate position; the last one is enough here.
      const [wx, wy] = transform().toWorld(sx, sy);
      hooks.drag(gesture.id, wx, wy);
    } else if (gesture.type === 'pan') {
      const v = gesture.view;
      hooks.setView({ cx: v.cx - (sx - gesture.x) / v.zoom, cy: v.cy + (sy - gesture.y) / v.zoom, zoom: v.zoom });
    } else if (gesture.type === 'pinch' && pointers.size === 2) {
      const [a, b] = [...pointers.values()];
      const dist = Math.hypot(a.x - b.x, a.y - b.y);
      if (gesture.dist > 0) {
        const factor = dist / gesture.dist;
        hooks.setView({ ...gesture.view, zoom: Math.min(1e5, Math.max(1, gesture.view.zoom * factor)) });
      }
    }
  });

  function endPointer(event) {
    pointers.delete(event.pointerId);
    if (gesture?.type === 'handle' && event.pointerId === gesture.pointerId) hooks.dragEnd(gesture.id);
    if (pointers.size === 0) gesture = null;
  }
  canvas.addEventListener('pointerup', endPointer);
  canvas.addEventListener('pointercancel', endPointer);
  canvas.addEventListener('pointerleave', () => { if (!gesture) hooks.hover(null); });

  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const [sx, sy] = local(event);
    zoomAt(sx, sy, Math.exp(-event.deltaY * 0.0015));
  }, { passive: false });

  canvas.addEventListener('keydown', (event) => {
    const handles = hooks.getHandles();
    const selected = hooks.getSelected();
    const index = handles.findIndex((h) => h.id === selected);
    if (event.key === ']' || event.key === '[') {
      if (!handles.length) return;
      const step = event.key === ']' ? 1 : -1;
      const next = handles[(index + step + handles.length) % handles.length] ?? handles[0];
      hooks.select(next.id);
      event.preventDefault();
      event.stopPropagation();
    } else if (event.key.startsWith('Arrow') && index >= 0 && handles[index].draggable !== false && !event.ctrlKey && !event.altKey) {
      const px = event.shiftKey ? 1 : 10;
      const d = px / hooks.getView().zoom;
      const h = handles[index];
      const dx = event.key === 'ArrowLeft' ? -d : event.key === 'ArrowRight' ? d : 0;
      const dy = event.key === 'ArrowUp' ? d : event.key === 'ArrowDown' ? -d : 0;
      hooks.dragStart(h.id);
      hooks.drag(h.id, h.x + dx, h.y + dy);
      hooks.dragEnd(h.id);
      event.preventDefault();
      event.stopPropagation();
    } else if (event.key === 'Escape' && selected !== null) {
      hooks.select(null);
      event.stopPropagation();
    } else if (event.key === '+' || event.key === '=' || event.key === '-') {
      zoomAt(cssWidth / 2, cssHeight / 2, event.key === '-' ? 1 / 1.25 : 1.25);
      event.preventDefault();
      event.stopPropagation();
    }
  });

  return {
    canvas,
    context2d: g,
    get size() { return { width: cssWidth, height: cssHeight, dpr }; },
    transform,
    // Screen (page CSS pixel) position of a world point: what a browser test needs to drag.
    toClient(x, y) {
      const rect = canvas.getBoundingClientRect();
      const [sx, sy] = transform().toScreen(x, y);
      return { x: rect.left + sx, y: rect.top + sy };
    },
    // The WebGL2 mesh renderer under the canvas (ui/gl-mesh.js), or null where the browser
    // has none: the lesson then draws with the 2D painter, and a note under the canvas says so.
    gl() {
      if (underlay === null) makeUnderlay(); // placed when made and on every resize
      return underlay ? underlay.renderer : null;
    },
    // The picture as the person sees it, as a PNG: the WebGL2 canvas (drawn again in this
    // task, so its buffer is still there) with the 2D canvas over it.
    png() {
      let out = canvas;
      if (underlay) {
        underlay.renderer.redraw();
        out = document.createElement('canvas');
        out.width = canvas.width;
        out.height = canvas.height;
        const g2 = out.getContext('2d');
        g2.drawImage(underlay.canvas, 0, 0, out.width, out.height);
        g2.drawImage(canvas, 0, 0);
      }
      return new Promise((resolve) => out.toBlob(resolve, 'image/png'));
    },
    beginFrame() {
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
      return g;
    },
    // The view that shows the box [minX,maxX] x [minY,maxY] with a margin.
    // Measured from the canvas's current layout: on a page's first frame the size the
    // ResizeObserver last reported can still be the default 300 x 150.
    fit(minX, minY, maxX, maxY, margin = 0.12) {
      const rect = canvas.getBoundingClientRect();
      const w = Math.max(maxX - minX, 1e-9);
      const hgt = Math.max(maxY - minY, 1e-9);
      const zoom = Math.min(rect.width / (w * (1 + 2 * margin)), rect.height / (hgt * (1 + 2 * margin)));
      return { cx: (minX + maxX) / 2, cy: (minY + maxY) / 2, zoom: Math.min(1e5, Math.max(1, zoom)) };
    },
  };
}
