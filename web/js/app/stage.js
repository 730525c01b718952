// @ts-check
// The lesson canvas: size (device pixels), the world-to-screen transform from the state's
// view {cx, cy, zoom}, its Fit button, and the interaction a person expects: drag a handle
// (mouse, touch, pen), drag empty space to pan (mouse, pen; one finger scrolls the page),
// wheel or two fingers to pan and zoom, and the keyboard: [ and ] select
// the previous/next handle, arrows nudge it (Shift: finer), Escape deselects, + and -
// zoom. Handles come from the lesson; the stage only finds the nearest one.
//
// The WebGL2 canvas under this one is made by the caller's `hooks.gpuRenderer` (the page
// entry hands ui/gl-mesh.js's createGlMesh to the shell): the skeleton imports nothing
// above app/, and a page without a renderer draws everything with the 2D painter.
import { Transform } from './painter.js';

const HIT_RADIUS_PX = 14;

/**
 * What the stage asks and tells its owner (the shell, and handles.js for the handles).
 * `gpuRenderer`: makes the WebGL2 renderer drawn under the canvas (null: none).
 * @typedef {{
 *   getView(): import('./contract.js').CameraView,
 *   setView(view: import('./contract.js').CameraView): void,
 *   getHandles(): import('./contract.js').Handle[],
 *   getSelected(): string | null,
 *   handleScale(): number,
 *   select(id: string | null): void,
 *   hover(id: string | null, x?: number, y?: number): void,
 *   dragStart(id: string): void,
 *   drag(id: string, x: number, y: number): void,
 *   dragEnd(id?: string): void,
 *   click(...xyEvent: any[]): boolean,
 *   fitView: (() => void) | null,
 *   onResize(): void,
 *   gpuRenderer: ((canvas: HTMLCanvasElement) => any) | null,
 * }} StageHooks
 * @param {HTMLCanvasElement} canvas
 * @param {StageHooks} hooks
 */
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

  // The WebGL2 canvas under this one, made on a lesson's first request: { canvas, renderer }
  // once made, false where the browser has no WebGL2 (or lost it), or the page has no renderer.
  /** @type {{ canvas: HTMLCanvasElement, renderer: any } | null | false} */
  let underlay = hooks.gpuRenderer ? null : false;
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
      renderer = hooks.gpuRenderer(glCanvas);
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

  // The Fit button: one per page, on the canvas's bottom-right corner (the legends
  // are at the top left, the WebGL note at the top); after the canvas in the tab order; its
  // key is the page's 0 (toolbar.js). site.css sizes it (44 x 44 CSS px on a phone).
  let fitButton = null;
  if (hooks.fitView) {
    fitButton = document.createElement('button');
    fitButton.type = 'button';
    fitButton.className = 'stage-fit';
    fitButton.textContent = 'Fit';
    fitButton.title = 'Fit the drawing to the canvas (0)';
    fitButton.setAttribute('aria-label', 'Fit the drawing to the canvas');
    fitButton.setAttribute('aria-keyshortcuts', '0');
    fitButton.addEventListener('click', () => hooks.fitView());
    canvas.after(fitButton);
  }
  function placeFit() {
    if (!fitButton) return;
    fitButton.style.left = `${canvas.offsetLeft + cssWidth}px`;
    fitButton.style.top = `${canvas.offsetTop + cssHeight}px`;
  }

  function resize() {
    const rect = canvas.getBoundingClientRect();
    dpr = window.devicePixelRatio || 1;
    cssWidth = Math.max(1, rect.width);
    cssHeight = Math.max(1, rect.height);
    canvas.width = Math.round(cssWidth * dpr);
    canvas.height = Math.round(cssHeight * dpr);
    placeUnderlay();
    placeFit();
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

  // Fingers (a phone): one finger scrolls the page unless it starts on a
  // handle, which it then drags; a one-finger tap picks as a click does; two fingers pan
  // (their midpoint) and zoom (their distance) the view about their midpoint. The canvas's
  // CSS (touch-action: pan-x pan-y) lets the browser scroll the page with one finger and
  // never pinch-zoom it; this listener keeps the browser out when the touch starts on a
  // draggable handle or when a second finger comes down. Mouse and pen are unchanged.
  const TOUCH_RADIUS_PX = 24;
  const TAP_SLOP_PX = 10; // a finger that moved farther is not a tap
  const onHandle = (sx, sy, radius) => {
    const handle = hit(sx, sy, radius * hooks.handleScale());
    return handle && handle.draggable !== false ? handle : null;
  };
  canvas.addEventListener('touchstart', (event) => {
    const rect = canvas.getBoundingClientRect();
    const first = event.touches[0];
    if (event.touches.length >= 2 || onHandle(first.clientX - rect.left, first.clientY - rect.top, TOUCH_RADIUS_PX)) event.preventDefault();
  }, { passive: false });
  canvas.addEventListener('touchmove', (event) => {
    if (event.touches.length >= 2 && event.cancelable) event.preventDefault();
  }, { passive: false });

  // Two fingers: the world point under their midpoint at the start stays under their
  // midpoint; the zoom follows the ratio of their distances.
  function startPinch() {
    const [a, b] = [...pointers.values()];
    const mid = [(a.x + b.x) / 2, (a.y + b.y) / 2];
    return { type: 'pinch', dist: Math.hypot(a.x - b.x, a.y - b.y), world: transform().toWorld(...mid), view: hooks.getView() };
  }
  function movePinch() {
    const [a, b] = [...pointers.values()];
    const dist = Math.hypot(a.x - b.x, a.y - b.y);
    const zoom = gesture.dist > 0 ? Math.min(1e5, Math.max(1, gesture.view.zoom * dist / gesture.dist)) : gesture.view.zoom;
    const [mx, my] = [(a.x + b.x) / 2, (a.y + b.y) / 2];
    const [wx, wy] = gesture.world;
    hooks.setView({ cx: wx - (mx - cssWidth / 2) / zoom, cy: wy + (my - cssHeight / 2) / zoom, zoom });
  }

  canvas.addEventListener('pointerdown', (event) => {
    canvas.focus({ preventScroll: true });
    const [sx, sy] = local(event);
    const touch = event.pointerType === 'touch';
    pointers.set(event.pointerId, { x: sx, y: sy });
    canvas.setPointerCapture(event.pointerId);
    if (pointers.size === 2) {
      if (gesture?.type === 'handle') hooks.dragEnd(gesture.id); // a second finger: the view, not the handle
      gesture = startPinch();
      return;
    }
    if (pointers.size > 2) return;
    const radius = (touch ? TOUCH_RADIUS_PX : HIT_RADIUS_PX) * hooks.handleScale();
    const handle = hit(sx, sy, radius);
    if (handle && handle.draggable !== false) {
      gesture = { type: 'handle', id: handle.id, pointerId: event.pointerId };
      hooks.select(handle.id);
      hooks.dragStart(handle.id);
    } else if (handle) {
      hooks.select(handle.id);
      gesture = null;
    } else if (touch) {
      // Off the handles a finger belongs to the page (it scrolls); released where it went
      // down it is a tap, a click (picks an element).
      gesture = { type: 'tap', pointerId: event.pointerId, x: sx, y: sy };
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
      if (event.pointerType === 'touch') return;
      const handle = hit(sx, sy);
      canvas.style.cursor = handle ? 'grab' : 'default';
      hooks.hover(handle ? handle.id : null, ...transform().toWorld(sx, sy));
      return;
    }
    if (gesture.type === 'handle' && event.pointerId === gesture.pointerId) {
      // Coalesced events carry every intermediate position; the last one is enough here.
      const [wx, wy] = transform().toWorld(sx, sy);
      hooks.drag(gesture.id, wx, wy);
    } else if (gesture.type === 'tap' && Math.hypot(sx - gesture.x, sy - gesture.y) > TAP_SLOP_PX) {
      gesture = { type: 'scroll' }; // the browser scrolls the page; nothing here
    } else if (gesture.type === 'pan') {
      const v = gesture.view;
      hooks.setView({ cx: v.cx - (sx - gesture.x) / v.zoom, cy: v.cy + (sy - gesture.y) / v.zoom, zoom: v.zoom });
    } else if (gesture.type === 'pinch' && pointers.size === 2) {
      movePinch();
    }
  });

  function endPointer(event) {
    pointers.delete(event.pointerId);
    if (gesture?.type === 'handle' && event.pointerId === gesture.pointerId) hooks.dragEnd(gesture.id);
    if (gesture?.type === 'tap' && event.type === 'pointerup' && event.pointerId === gesture.pointerId) {
      const [sx, sy] = local(event);
      gesture = null;
      hooks.click?.(...transform().toWorld(sx, sy), event);
    }
    // One finger of two lifted: the other does nothing more until it is lifted too.
    if (gesture?.type === 'pinch' && pointers.size === 1) gesture = { type: 'scroll' };
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
    // The WebGL2 mesh renderer under the canvas (hooks.gpuRenderer), or null where the
    // browser has none (the lesson then draws with the 2D painter, and a note under the canvas
    // says so) or the page gave no renderer.
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
