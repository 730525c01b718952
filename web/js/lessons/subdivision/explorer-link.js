// @ts-check
// The link from the curve beside the mesh to the curve explorer (issue 16: "linked to the
// curve explorer's knot insertion"): the same polygon as a uniform B-spline (degree 2 for
// Chaikin, 3 for the cubic rule) over the core's uniform knots, with Boehm's knot insertion
// shown at the middle of the first span (one cubic step inserts a knot in the middle of
// every span). The link is written as the shell writes share links (share-link.js), with the
// curve explorer's own lesson object, loaded when the link is first made.
import { encodeState } from '../../app/share-link.js';

/**
 * @param {HTMLElement} anchor
 * @param {any} ctx
 */
export function createExplorerLink(anchor, ctx) {
  let made = 0;       // the newest link asked for: an older answer arriving late is dropped
  let curves = null;  // the curve explorer's lesson module, once loaded
  return {
    async update(model, state) {
      const ticket = ++made;
      const c = model.curve;
      const points = [];
      for (let i = 0; i < c.control.length; i += 2) points.push([c.control[i], c.control[i + 1]]);
      curves ??= await import('../curves/lesson.js');
      const { lesson } = curves;
      let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
      for (const [x, y] of points) { minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y); }
      const base = lesson.defaultState();
      const next = {
        ...base,
        family: 'bspline',
        points,
        degree: c.degree,
        knots: Array.from(ctx.api.uniformKnots(points.length, c.degree)),
        weights: points.map(() => 1),
        tangents: points.map(() => [1, 0]),
        // the domain of uniform knots t_j = j - p starts at 0: 0.5 is the middle of the first span
        u: 0.5,
        construction: { kind: 'insert-knot', step: 1 },
        view: { ...base.view, cx: (minX + maxX) / 2, cy: (minY + maxY) / 2 },
      };
      const code = await encodeState(lesson, next);
      if (ticket === made) anchor.setAttribute('href', `curves.html#s=${code}`);
    },
  };
}
