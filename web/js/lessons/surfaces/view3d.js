// @ts-check
// The camera of the surface lesson: a turntable view of a z-up scene (yaw about z, then a
// pitch towards looking down), orthographic or with a simple perspective divide. It maps
// 3D points the core returned to the 2D world of the stage, and a 2D drag back to a move
// in the view plane. Viewing only: no patch mathematics here.
const EYE_DISTANCE = 14; // world units from the scene centre, for the perspective divide

export function createCamera({ yaw, pitch, perspective }) {
  const y = (yaw * Math.PI) / 180;
  const p = (pitch * Math.PI) / 180;
  const cy = Math.cos(y); const sy = Math.sin(y);
  const cp = Math.cos(p); const sp = Math.sin(p);
  // view = Rx(p) Rz(y) world; screen x = view.x, screen up = view.z, depth = view.y.
  function toView(x, yy, z) {
    const x1 = cy * x - sy * yy;
    const y1 = sy * x + cy * yy;
    return [x1, cp * y1 - sp * z, sp * y1 + cp * z];
  }
  const scaleAt = (depth) => (perspective ? EYE_DISTANCE / (EYE_DISTANCE + depth) : 1);
  return {
    // [screenX, screenY, depth]; larger depth is farther from the eye.
    project(x, yy, z) {
      const [vx, depth, vz] = toView(x, yy, z);
      const s = scaleAt(depth);
      return [vx * s, vz * s, depth];
    },
    // The world vector that moves a point at `depth` by (dx, dy) on the screen.
    screenDelta(dx, dy, depth) {
      const s = scaleAt(depth);
      const right = [cy, -sy, 0];
      const up = [sy * sp, cy * sp, cp];
      return [0, 1, 2].map((k) => (dx * right[k] + dy * up[k]) / s);
    },
    // Unit vector from the scene towards the eye, for shading and back faces.
    towardsEye: [-sy * cp, -cy * cp, sp],
  };
}

// Projects a flat list of 3D points ([3*i + k]) to flat 2D ([2*i]) plus depths.
export function projectAll(camera, values) {
  const n = values.length / 3;
  const xy = new Float64Array(2 * n);
  const depth = new Float64Array(n);
  for (let i = 0; i < n; i += 1) {
    const [sx, sy, d] = camera.project(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    xy[2 * i] = sx; xy[2 * i + 1] = sy; depth[i] = d;
  }
  return { xy, depth };
}
