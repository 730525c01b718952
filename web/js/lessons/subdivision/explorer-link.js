// @ts-check
// The link from the curve beside the mesh to the curve explorer ("linked to the curve
// explorer's knot insertion"): the same polygon as a uniform B-spline (degree 2 for
// Chaikin, 3 for the cubic rule) over the core's uniform knots, with Boehm's knot insertion
// shown at the middle of the first span (one cubic step inserts a knot in the middle of
// every span). The curve explorer's own state builder writes the state (lessons/links.js).
import { curveExplorerHref } from '../links.js';

/**
 * @param {HTMLElement} anchor
 * @param {any} ctx
 */
export function createExplorerLink(anchor, ctx) {
  let made = 0; // the newest link asked for: an older answer arriving late is dropped
  return {
    async update(model, state) {
      const ticket = ++made;
      const c = model.curve;
      const points = [];
      for (let i = 0; i < c.control.length; i += 2) points.push([c.control[i], c.control[i + 1]]);
      const knots = Array.from(ctx.api.uniformKnots(points.length, c.degree));
      // the domain of uniform knots t_j = j - p starts at 0: 0.5 is the middle of the first span
      const href = await curveExplorerHref({ points, degree: c.degree, knots, u: 0.5 });
      if (ticket === made) anchor.setAttribute('href', href);
    },
  };
}
