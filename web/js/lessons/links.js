// @ts-check
// Links from one lesson's page to another's: a lesson that links to another asks here, and
// the target lesson's own state builder writes the state, so no lesson imports another
// lesson or writes its state's shape. The target's modules load when a link is first made.
// Offers: curveExplorerHref(spline) -> the address of the curve explorer showing knot
//   insertion on that B-spline (lessons/curves/state.js knotInsertionState).
// Needs: app/share-link.js (the link's code, as the shell writes share links).
import { encodeState } from '../app/share-link.js';

/** @param {{ points: number[][], degree: number, knots: number[], u: number }} spline */
export async function curveExplorerHref(spline) {
  const [{ lesson }, { knotInsertionState }] = await Promise.all([import('./curves/lesson.js'), import('./curves/state.js')]);
  return `curves.html#s=${await encodeState(lesson, knotInsertionState(spline))}`;
}
