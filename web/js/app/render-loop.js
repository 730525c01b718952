// @ts-check
// Drawing on demand: at most one canvas frame per animation frame, asked by a change or by
// the lesson (ctx.render); no free-running loop. The panels (lesson.update), the drawing's
// description and the toolbar are brought up to date only when asked (refresh: the state
// changed, a selection), never for a pan or zoom alone. The same draw hook makes the SVG
// figure. The drawing colours are the theme's, read again when it changes (recolor).
import { CanvasPainter, SvgPainter } from './painter.js';
import { watchScrollRegions } from './dom.js';
import { drawingColors } from './theme.js';

/**
 * @param {{
 *   lesson: import('./contract.js').Lesson,
 *   ctx: import('./contract.js').Ctx,
 *   view: () => import('./contract.js').View,
 *   model: () => import('./contract.js').Model,
 *   panels: HTMLElement,
 *   description: HTMLElement,
 *   player: () => import('./contract.js').ExercisePlayer | null,
 *   toolbar: () => { update(): void },
 *   inspector: () => { update(): void } | null,
 * }} parts the page's parts, read at every frame (some are made after this)
 */
export function createRenderLoop({ lesson, ctx, view, model, panels, description, player, toolbar, inspector }) {
  let needsPanelUpdate = true;
  let frame = 0;
  let colors = drawingColors();
  const scale = () => (ctx.ui.present ? 1.6 : 1);

  function refresh() {
    needsPanelUpdate = true;
    scheduleRender();
  }

  function scheduleRender() {
    if (frame) return;
    frame = requestAnimationFrame(renderNow);
  }

  function renderNow() {
    frame = 0;
    const state = ctx.state;
    if (needsPanelUpdate) {
      needsPanelUpdate = false;
      lesson.update?.(view(), model(), state, ctx);
      watchScrollRegions(panels?.parentElement ?? document);
      const text = player()?.description ?? lesson.describe?.(view(), model(), state);
      if (text && description && description.textContent !== text) description.textContent = text;
      toolbar().update();
    }
    inspector()?.update();
    const g = ctx.stage.beginFrame();
    const painter = new CanvasPainter(g, ctx.stage.transform(), { scale: scale(), background: colors.background });
    painter.clear();
    lesson.draw(view(), painter, model(), state, ctx);
    player()?.draw(painter, colors);
    painter.finish(); // the labels, placed together (app/label-layout.js), and the legend
    lesson.afterFrame?.(view(), model(), state, ctx);
  }

  return {
    refresh,
    scheduleRender,
    /** Draws at once (a resize cleared the canvas; the first frame). */
    renderNow,
    get colors() { return colors; },
    /** The figure as SVG text: the lesson's draw through the SVG painter (no side plots). */
    svgFigure() {
      const painter = new SvgPainter(ctx.stage.transform(), { scale: scale(), background: colors.background });
      painter.clear();
      lesson.draw(view(), painter, model(), ctx.state, ctx);
      return painter.toString();
    },
    /** The theme changed: the drawing's colours again, drawn at once (`now`) or next frame. */
    recolor({ now = false } = {}) {
      colors = drawingColors();
      if (now) renderNow(); else refresh();
    },
  };
}
