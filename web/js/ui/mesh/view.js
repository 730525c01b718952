// @ts-check
// The view of a mesh shared by the mesh lessons: an orthographic picture rotated by a yaw and
// a pitch about the mesh's centre, and the view that fits it. Only the view's arithmetic (a
// rotation of the positions the core returned); no geometry of the mesh.
// Offers: viewRotation(state), projectAll(positions, R, centre), facesAway(R, n),
//   unprojectDelta(R, dx, dy), fitProjected(projected, stage, margin).
// Needs: a state with `mode3d` and `rotation: {yaw, pitch}`; positions as the core's flat
//   arrays (positions[3*v + k]); a stage with `fit(minX, minY, maxX, maxY, margin)`.

// Orthographic view: R = Rx(pitch) Ry(yaw); screen-plane (X, Y) = first two rows of R p,
// depth = third row (towards the viewer). In 2D the rotation is the identity.
export function viewRotation(state) {
  if (!state.mode3d) return [1, 0, 0, 0, 1, 0, 0, 0, 1];
  const { yaw, pitch } = state.rotation;
  const cy = Math.cos(yaw); const sy = Math.sin(yaw);
  const cp = Math.cos(pitch); const sp = Math.sin(pitch);
  return [cy, 0, sy, sp * sy, cp, -sp * cy, -cp * sy, sp, cp * cy];
}

// The view turns about `centre` (the core's bounding-box centre):
// R (p - c) + c, so the mesh spins in place instead of swinging round the world origin and
// leaving the canvas; in 2D (R = I) positions are shown as they are.
export function projectAll(positions, R, centre = [0, 0, 0]) {
  const n = positions.length / 3;
  const out = new Float64Array(3 * n);
  const [cx, cy, cz] = centre;
  for (let v = 0; v < n; v += 1) {
    const x = positions[3 * v] - cx; const y = positions[3 * v + 1] - cy; const z = positions[3 * v + 2] - cz;
    out[3 * v] = R[0] * x + R[1] * y + R[2] * z + cx;
    out[3 * v + 1] = R[3] * x + R[4] * y + R[5] * z + cy;
    out[3 * v + 2] = R[6] * x + R[7] * y + R[8] * z + cz;
  }
  return out;
}

// Whether a normal n points away from the viewer: its component along the view's depth
// axis (third row of R, towards the viewer) is negative. A CCW walk about such a normal
// appears clockwise on screen.
export function facesAway(R, n) {
  return R[6] * n[0] + R[7] * n[1] + R[8] * n[2] < 0;
}

// A screen-plane displacement (dx, dy) back to world coordinates: R^T (dx, dy, 0).
export function unprojectDelta(R, dx, dy) {
  return [R[0] * dx + R[3] * dy, R[1] * dx + R[4] * dy, R[2] * dx + R[5] * dy];
}


// The view that shows every projected vertex (projected[3*v], projected[3*v + 1]) with a
// margin (a fraction of the canvas; room for the labels beside the vertices): a lesson's
// fitView hook.
export function fitProjected(projected, stage, margin) {
  let minX = Infinity; let minY = Infinity; let maxX = -Infinity; let maxY = -Infinity;
  for (let i = 0; i < projected.length; i += 3) {
    minX = Math.min(minX, projected[i]); maxX = Math.max(maxX, projected[i]);
    minY = Math.min(minY, projected[i + 1]); maxY = Math.max(maxY, projected[i + 1]);
  }
  return stage.fit(minX, minY, maxX, maxY, margin);
}
