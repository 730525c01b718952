// @ts-check
// The GPU picture of a mesh: one small WebGL2 renderer on the plain API, drawing
// into the canvas the stage keeps under the 2D one (app/stage.js `underlay`). It draws what
// the 2D painter would draw as batched paths (the face fills and, on a big mesh, the plain
// edges); labels, arrows and the walk's highlights stay on the 2D canvas above it, and the
// SVG export still goes through the painter. No geometry of the mesh is computed here:
// the positions, faces and edges are the core's, the rotation is the view's (ui/mesh/view.js).
//
// Buffers follow the mesh: `setMesh` uploads once per (mesh id, version) key; a rotation or
// a pan only changes uniforms. Positions are uploaded as float32 relative to the view's
// centre (the bounding-box centre), so a mesh far from the origin keeps its precision.
//
// A big mesh costs the GPU per triangle (about 0.2 us each in SwiftShader, the software
// GPU of a machine without one): while the view moves, the renderer draws the mesh's display
// proxy (the core's vertex clustering, about PROXY_TRIANGLES triangles) if it has one, and the
// lesson draws the whole mesh again once the view is still. A frame whose view, style and mesh
// equal the last one's is not drawn again (the canvas keeps its picture), so a hover or a walk
// step costs the GPU nothing. Picking is the core's (mesh.pick), not the GPU's: an id-buffer
// pass cost ~230 ms for 100k faces here.

/** @typedef {{ positions: Float64Array, faceOffsets: Int32Array, faceVertices: Int32Array,
 *   edges: Int32Array, edgeStride: number, edgeGap: Uint8Array | null, centre: number[],
 *   normals?: Float64Array | null }} GlMeshData */

const FACE_VS = `#version 300 es
layout(location = 0) in vec3 aPos;
uniform mat3 uR;
uniform vec2 uOffset;
uniform vec2 uScale;
uniform float uDepth;
out vec3 vView;
void main() {
  vec3 p = uR * aPos;
  vView = p;
  gl_Position = vec4((p.xy + uOffset) * uScale, -p.z * uDepth, 1.0);
}`;

// Faces: the fill colour at the face's alpha (2D and small meshes, like the painter), or, on
// a big mesh in 3D, a nearest-surface picture lit by the screen-space normal so its shape reads.
const FACE_FS = `#version 300 es
precision highp float;
in vec3 vView;
uniform vec4 uFill;
uniform float uBackAlpha;
uniform float uLit;
uniform vec3 uBackground;
out vec4 outColor;
void main() {
  float a = gl_FrontFacing ? uFill.a : uBackAlpha;
  if (uLit > 0.5) {
    // Opaque (blending off): the fill over the background at a strength set by the light,
    // so the nearest surface hides what is behind it whatever order triangles come in.
    vec3 n = normalize(cross(dFdx(vView), dFdy(vView)));
    if (n.z < 0.0) n = -n; // the side seen
    a = 0.08 + 0.5 * max(0.0, dot(n, normalize(vec3(-0.35, 0.45, 0.82))));
    outColor = vec4(mix(uBackground, uFill.rgb, a), 1.0);
    return;
  }
  outColor = vec4(uFill.rgb * a, a);
}`;

// Opaque shaded faces (the subdivision lesson): brightness s = |n . light| of the normal given
// per vertex (the lesson passes the core's: a vertex normal, or a face's normal on each of
// its own corners; none: the triangle's own plane), coloured along the lesson's ramp
// hsl(205 50% L), L = 16% + 62% s, which is linear in L on each side of 50% (uRamp: the
// colours at L = 16%, 50%, 78%).
const SHADED_VS = `#version 300 es
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat3 uR;
uniform vec2 uOffset;
uniform vec2 uScale;
uniform float uDepth;
out vec3 vView;
out vec3 vNormal;
void main() {
  vec3 p = uR * aPos;
  vView = p;
  vNormal = uR * aNormal;
  gl_Position = vec4((p.xy + uOffset) * uScale, -p.z * uDepth, 1.0);
}`;
const SHADED_FS = `#version 300 es
precision highp float;
in vec3 vView;
in vec3 vNormal;
uniform vec3 uRamp[3];
out vec4 outColor;
void main() {
  vec3 n = dot(vNormal, vNormal) > 0.0 ? normalize(vNormal) : normalize(cross(dFdx(vView), dFdy(vView)));
  float s = abs(dot(n, normalize(vec3(-0.35, 0.45, 0.82))));
  float l = 0.16 + 0.62 * s;
  vec3 c = l <= 0.5 ? mix(uRamp[0], uRamp[1], (l - 0.16) / 0.34) : mix(uRamp[1], uRamp[2], (l - 0.5) / 0.28);
  outColor = vec4(c, 1.0);
}`;

const LINE_FS = `#version 300 es
precision highp float;
uniform vec4 uFill;
out vec4 outColor;
void main() { outColor = vec4(uFill.rgb * uFill.a, uFill.a); }`;

// What one frame may ask of the GPU. Calibrated on SwiftShader, the software GPU of a machine
// without one (headless Chromium here): about 0.2 us per triangle filled and 0.08 us per
// edge line on a small picture; a frame of a million-face sphere's chunks measured 1.5 to 2
// times that, so the budget is 12 ms of the model (20-25 ms measured). A picture over the
// budget is drawn over several frames, so no frame blocks the page for long; a real GPU
// finishes it in the first frames.
const FRAME_BUDGET_MS = 12;
const TRIANGLE_US = 0.2;
const EDGE_US = 0.08;
const costMs = (triangles, edges) => (triangles * TRIANGLE_US + edges * EDGE_US) / 1000;

function compile(gl, vs, fs) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`WebGL2 shader: ${gl.getShaderInfoLog(shader)}`);
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`WebGL2 program: ${gl.getProgramInfoLog(program)}`);
  const uniforms = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; i += 1) {
    const name = gl.getActiveUniform(program, i).name;
    uniforms[name] = gl.getUniformLocation(program, name);
  }
  return { program, uniforms };
}

// '#rrggbb' or 'rgb(r, g, b)' -> [r, g, b] in 0..1 (the theme's colours are one of these).
export function parseColour(css) {
  const s = String(css).trim();
  if (s.startsWith('#')) {
    const hex = s.length === 4 ? s.slice(1).split('').map((c) => c + c).join('') : s.slice(1, 7);
    return [0, 2, 4].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255);
  }
  const m = s.match(/rgba?\(([^)]*)\)/);
  if (m) return m[1].split(/[ ,/]+/).slice(0, 3).map((x) => Number(x) / 255);
  return [0.5, 0.5, 0.5];
}

// Fan triangle indices of every face that has corners (a removed face has none), and each
// face's first triangle in them (faceTriangle[f] .. faceTriangle[f + 1]).
function fanIndices(faceOffsets, faceVertices) {
  const F = faceOffsets.length - 1;
  const faceTriangle = new Int32Array(F + 1);
  for (let f = 0; f < F; f += 1) faceTriangle[f + 1] = faceTriangle[f] + Math.max(0, faceOffsets[f + 1] - faceOffsets[f] - 2);
  const index = new Uint32Array(3 * faceTriangle[F]);
  let k = 0;
  for (let f = 0; f < F; f += 1) {
    const start = faceOffsets[f]; const end = faceOffsets[f + 1];
    for (let i = start + 1; i + 1 < end; i += 1) {
      index[k] = faceVertices[start]; index[k + 1] = faceVertices[i]; index[k + 2] = faceVertices[i + 1];
      k += 3;
    }
  }
  return { index, faceTriangle };
}

// WebGL 2 always restarts primitives at the largest index (PRIMITIVE_RESTART_FIXED_INDEX):
// a triangle or line of these indices is not drawn, whatever the other indices do.
const RESTART = 0xffffffff;

// Each face's place in the triangles, from fanIndices' faceTriangle: its first triangle and
// how many it has room for.
function faceSlots(faceTriangle) {
  const F = faceTriangle.length - 1;
  const start = faceTriangle.slice(0, F);
  const count = new Int32Array(F);
  for (let f = 0; f < F; f += 1) count[f] = faceTriangle[f + 1] - faceTriangle[f];
  return { start, count };
}

// The room followMesh has before a buffer must grow: vertices and triangles.
const ROOM_VERTICES = 4096;
const ROOM_TRIANGLES = 8192;

// `array` and `extra` more entries of `value`.
function padded(array, extra, value) {
  const out = new /** @type {any} */ (array.constructor)(array.length + extra);
  out.set(array);
  out.fill(value, array.length);
  return out;
}

// A typed array with room for n entries: `room` itself, or a new one twice as big holding
// its first `used` entries (amortised: growing by one costs O(1)).
function withRoom(room, n, used) {
  if (n <= room.length) return room;
  const bigger = new /** @type {any} */ (room.constructor)(Math.max(n, 2 * room.length, 1024));
  bigger.set(room.subarray(0, used));
  return bigger;
}

// Positions as float32 relative to `centre`; returns them and the largest distance from it.
function relativeTo(positions, centre) {
  const n = positions.length / 3;
  const out = new Float32Array(3 * n);
  let r2 = 0;
  for (let v = 0; v < n; v += 1) {
    const x = positions[3 * v] - centre[0]; const y = positions[3 * v + 1] - centre[1]; const z = positions[3 * v + 2] - centre[2];
    out[3 * v] = x; out[3 * v + 1] = y; out[3 * v + 2] = z;
    r2 = Math.max(r2, x * x + y * y + z * z);
  }
  return { relative: out, radius: Math.sqrt(r2) || 1 };
}

/**
 * A renderer on a WebGL2 context, or null when the browser has none.
 * @param {HTMLCanvasElement} canvas
 */
export function createGlMesh(canvas) {
  /** @type {WebGL2RenderingContext | null} */
  const gl = canvas.getContext('webgl2', { antialias: false, premultipliedAlpha: true, alpha: false, depth: true, preserveDrawingBuffer: false });
  if (!gl) return null;
  const faceProgram = compile(gl, FACE_VS, FACE_FS);
  const lineProgram = compile(gl, FACE_VS, LINE_FS);
  const shadedProgram = compile(gl, SHADED_VS, SHADED_FS);
  // One set of buffers for the mesh, one for its proxy: {vao, positions, triangles, edges, counts}.
  const makeSet = () => ({ vao: gl.createVertexArray(), positions: gl.createBuffer(), normals: gl.createBuffer(), triangles: gl.createBuffer(), edges: gl.createBuffer(), triangleCount: 0, edgeCount: 0 });
  const full = makeSet();
  const proxy = makeSet();
  let meshKey = null;
  let proxyKey = null;
  let radius = 1;
  let centre = [0, 0, 0];
  let lastDrawn = null; // the signature of the picture on the canvas
  let lastArgs = null;  // the view and style it was drawn with (redraw)
  let showing = null;   // 'whole' | 'proxy' | null: what the canvas shows
  let closed = false;   // no boundary edge: a face turned away is hidden, not drawn (lit mode)
  let outward = true;   // ... and its faces wound counter-clockwise seen from outside
  let pendingLines = null; // the mesh data whose edge lines are not made yet
  // The shown mesh's buffers as the CPU wrote them, for followMesh: {relative, index,
  // faceTriangle, faceSlot: {start, count} per face once followed, lines, capacity}.
  let shown = null;

  function fill(set, relative, index, lines, normals = null) {
    gl.bindVertexArray(set.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, set.positions);
    gl.bufferData(gl.ARRAY_BUFFER, relative, gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    if (normals) {
      gl.bindBuffer(gl.ARRAY_BUFFER, set.normals);
      gl.bufferData(gl.ARRAY_BUFFER, Float32Array.from(normals), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(1);
      gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
    } else {
      gl.disableVertexAttribArray(1);
      gl.vertexAttrib3f(1, 0, 0, 0); // no normal: the shader uses the face's plane
    }
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, set.triangles);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, index, gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, set.edges);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, lines, gl.STATIC_DRAW);
    set.triangleCount = index.length / 3;
    set.edgeCount = lines.length / 2;
  }

  let job = null;         // a big picture being drawn over frames: {signature, triangles, edges, started}
  const target = { fbo: null, colour: null, depth: null, width: 0, height: 0 };

  // Edge e's line at lines[2e], or restart indices (nothing drawn) for an edge not drawn (a
  // gap, or one an edit player's step has not written yet).
  function writeLine(lines, { edges, edgeStride, edgeGap }, e) {
    const s0 = edges[edgeStride * e]; const t0 = edges[edgeStride * e + 1];
    const drawn = !edgeGap?.[e] && s0 >= 0 && t0 >= 0;
    lines[2 * e] = drawn ? s0 : RESTART; lines[2 * e + 1] = drawn ? t0 : RESTART;
  }

  function makeLines() {
    const data = pendingLines;
    pendingLines = null;
    const E = data.edges.length / data.edgeStride;
    const lines = new Uint32Array(2 * E);
    for (let e = 0; e < E; e += 1) writeLine(lines, data, e);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, full.edges);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, lines, gl.STATIC_DRAW);
    full.edgeCount = E;
    if (shown) { shown.lines = lines; shown.capacity.lines = lines.length; }
  }

  // The offscreen framebuffer a big picture is drawn into, at the canvas's size.
  function offscreen(width, height) {
    if (target.fbo && target.width === width && target.height === height) return target;
    if (target.fbo) { gl.deleteFramebuffer(target.fbo); gl.deleteRenderbuffer(target.colour); gl.deleteRenderbuffer(target.depth); }
    target.fbo = gl.createFramebuffer();
    target.colour = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, target.colour);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, width, height);
    target.depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, target.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.fbo);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, target.colour);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, target.depth);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    Object.assign(target, { width, height });
    return target;
  }

  // Triangles [t0, t1) and edge lines [e0, e1) of `set` into `into` (null: the canvas),
  // cleared first when `clear` (a whole picture always is).
  function render(set, view, style, into, [t0, t1], [e0, e1], clear = true) {
    gl.bindFramebuffer(gl.FRAMEBUFFER, into ? into.fbo : null);
    gl.viewport(0, 0, canvas.width, canvas.height);
    if (clear || !into) {
      const [br, bg, bb] = style.background;
      gl.clearColor(br, bg, bb, 1);
      gl.clearDepth(1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    }
    if (!meshKey) { gl.bindFramebuffer(gl.FRAMEBUFFER, null); return; }
    const R = view.R;
    // GLSL mat3 is column-major: column j holds R[0][j], R[1][j], R[2][j].
    const rotation = new Float32Array([R[0], R[3], R[6], R[1], R[4], R[7], R[2], R[5], R[8]]);
    const setFrame = (p) => {
      gl.uniformMatrix3fv(p.uniforms.uR, false, rotation);
      gl.uniform2f(p.uniforms.uOffset, view.offset[0], view.offset[1]);
      gl.uniform2f(p.uniforms.uScale, view.zoom / (view.width / 2), view.zoom / (view.height / 2));
      gl.uniform1f(p.uniforms.uDepth, 1 / (radius * 1.01));
    };
    gl.bindVertexArray(set.vao);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA); // premultiplied, like the 2D canvas
    if (style.lit || style.shade) {
      // The nearest surface only, pushed back a little so its own edges are drawn on top.
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LEQUAL);
      gl.enable(gl.POLYGON_OFFSET_FILL);
      gl.polygonOffset(1, 1);
      // A closed mesh's faces turned away are behind its front: not rasterised at all
      // (the software GPU is bound by the pixels it fills). Faces are CCW seen from outside.
      if (closed) { gl.enable(gl.CULL_FACE); gl.cullFace(gl.BACK); gl.frontFace(gl.CCW); }
    } else {
      gl.disable(gl.DEPTH_TEST);
    }
    if (t1 > t0) {
      if (style.shade) {
        gl.disable(gl.BLEND);
        gl.useProgram(shadedProgram.program);
        setFrame(shadedProgram);
        gl.uniform3fv(shadedProgram.uniforms['uRamp[0]'], style.shade.ramp.flat());
      } else {
        gl.useProgram(faceProgram.program);
        setFrame(faceProgram);
        gl.uniform4f(faceProgram.uniforms.uFill, style.fill[0], style.fill[1], style.fill[2], style.faceAlpha);
        gl.uniform1f(faceProgram.uniforms.uBackAlpha, style.backAlpha);
        gl.uniform1f(faceProgram.uniforms.uLit, style.lit ? 1 : 0);
        gl.uniform3f(faceProgram.uniforms.uBackground, style.background[0], style.background[1], style.background[2]);
        if (style.lit) gl.disable(gl.BLEND);
      }
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, set.triangles);
      gl.drawElements(gl.TRIANGLES, 3 * (t1 - t0), gl.UNSIGNED_INT, 12 * t0);
    }
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.enable(gl.BLEND);
    if (e1 > e0) {
      gl.useProgram(lineProgram.program);
      setFrame(lineProgram);
      gl.uniform4f(lineProgram.uniforms.uFill, style.ink[0], style.ink[1], style.ink[2], style.edgeAlpha);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, set.edges);
      gl.drawElements(gl.LINES, 2 * (e1 - e0), gl.UNSIGNED_INT, 8 * e0);
    }
    gl.bindVertexArray(null);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.CULL_FACE);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  return {
    gl,
    get meshKey() { return meshKey; },
    get radius() { return radius; },
    get triangleCount() { return full.triangleCount; },
    get hasProxy() { return proxyKey === meshKey && meshKey !== null; },
    // A big picture is still being drawn over frames (the proxy stands in).
    get busy() { return job !== null; },
    // What the canvas shows: 'whole' (the mesh), 'proxy', or null (nothing drawn yet).
    get showing() { return showing; },

    /** Uploads the mesh when `key` (mesh id and version) differs from the last one. */
    /**
     * What setMesh uploads, computed without touching the GPU (a page may do this and the
     * upload in separate tasks): {key, data, relative, radius, index, closed, outward}.
     */
    prepareMesh(key, /** @type {GlMeshData} */ data) {
      const { positions, faceOffsets, faceVertices, edges, edgeStride } = data;
      const c = data.centre.slice();
      const r = relativeTo(positions, c);
      const { index, faceTriangle } = fanIndices(faceOffsets, faceVertices);
      // Closed (no edge without a face on each side) and wound counter-clockwise seen from
      // outside (positive signed volume, the sum of p0 . (p1 x p2) over the fan triangles):
      // then the faces turned away are hidden and need not be drawn; wound the other way,
      // the faces turned towards the viewer are the hidden ones.
      let isClosed = true;
      const E = edges.length / edgeStride;
      for (let e = 0; e < E && isClosed; e += 1) {
        if (edges[edgeStride * e] >= 0 && (edges[edgeStride * e + 2] < 0 || edges[edgeStride * e + 3] < 0)) isClosed = false;
      }
      let volume = 0;
      const q = r.relative;
      for (let t = 0; isClosed && t < index.length; t += 3) {
        const a = 3 * index[t]; const b = 3 * index[t + 1]; const d = 3 * index[t + 2];
        volume += q[a] * (q[b + 1] * q[d + 2] - q[b + 2] * q[d + 1]) + q[a + 1] * (q[b + 2] * q[d] - q[b] * q[d + 2]) + q[a + 2] * (q[b] * q[d + 1] - q[b + 1] * q[d]);
      }
      return { key, data, centre: c, relative: r.relative, radius: r.radius, index, faceTriangle, closed: isClosed, outward: volume >= 0 };
    },

    /** Uploads a prepared mesh (prepareMesh), unless it is the one shown. */
    uploadMesh(prepared) {
      if (prepared.key === meshKey) return;
      ({ centre, radius, closed, outward } = prepared);
      // The edge lines are made when first drawn (a zoomed-out big mesh never draws them).
      pendingLines = prepared.data;
      // Room for the vertices and triangles of a few thousand edits (followMesh), uploaded
      // with the mesh so that they do not make the buffers grow (a mesh with its own normals
      // is not followed: it is uploaded whole).
      const followed = !prepared.data.normals;
      const relative = followed ? padded(prepared.relative, 3 * ROOM_VERTICES, 0) : prepared.relative;
      const index = followed ? padded(prepared.index, 3 * ROOM_TRIANGLES, RESTART) : prepared.index;
      fill(full, relative, index, new Uint32Array(0), prepared.data.normals ?? null);
      full.triangleCount = prepared.index.length / 3;
      shown = followed ? {
        relative, index, faceTriangle: prepared.faceTriangle, faces: prepared.faceTriangle.length - 1,
        faceSlot: null, lines: null, capacity: { positions: relative.length, index: index.length, lines: 0 },
      } : null;
      meshKey = prepared.key;
      proxyKey = null;
      lastDrawn = null;
    },

    /**
     * The mesh after a local change, from the one shown: `follow` names the faces, vertices
     * and edges that changed (an edit's record; an edit player's step changes edges alone)
     * and `from(key)` says whether the shown mesh's key is one it starts from. Rewrites only
     * their entries in the GPU's buffers (bufferSubData), so an edit of a million-face mesh
     * costs what it touched; a face whose triangles no longer fit its place is moved to the
     * end (its place left as empty triangles), and a buffer without room is made twice as big
     * (amortised O(1)). Returns false, changing nothing, when the shown mesh is not one it
     * follows (setMesh then uploads it whole).
     * @param {string} key @param {GlMeshData} data
     * @param {{ from: (key: string) => boolean, faces: Iterable<number>, vertices: Iterable<number>, edges: Iterable<number> }} follow
     */
    followMesh(key, data, follow) {
      if (key === meshKey) return true;
      if (!shown || !meshKey || !follow.from(meshKey)) return false;
      const V = data.positions.length / 3;
      const F = data.faceOffsets.length - 1;
      // Positions: the vertices it moved or added, relative to the centre the mesh was shown about.
      const grownPositions = 3 * V > shown.capacity.positions;
      shown.relative = withRoom(shown.relative, 3 * V, shown.relative.length);
      for (const v of follow.vertices) {
        if (v >= V) continue;
        for (let k = 0; k < 3; k += 1) shown.relative[3 * v + k] = data.positions[3 * v + k] - centre[k];
        radius = Math.max(radius, Math.hypot(shown.relative[3 * v], shown.relative[3 * v + 1], shown.relative[3 * v + 2]));
      }
      gl.bindBuffer(gl.ARRAY_BUFFER, full.positions);
      if (grownPositions) {
        shown.capacity.positions = shown.relative.length;
        gl.bufferData(gl.ARRAY_BUFFER, shown.relative, gl.STATIC_DRAW);
      } else {
        for (const v of follow.vertices) if (v < V) gl.bufferSubData(gl.ARRAY_BUFFER, 12 * v, shown.relative, 3 * v, 3);
      }
      // Triangles: each face's fan where it was when it fits, otherwise at the end.
      shown.faceSlot ??= faceSlots(shown.faceTriangle);
      const slot = shown.faceSlot;
      if (F > slot.start.length) {
        const start = withRoom(slot.start, F, slot.start.length); const count = withRoom(slot.count, F, slot.count.length);
        start.fill(0, slot.start.length); count.fill(0, slot.count.length);
        shown.faceSlot = { start, count };
      }
      const { start, count } = shown.faceSlot;
      let used = full.triangleCount;
      const written = [];
      // Faces past the end now (an undo cut the tables to where they ended): nothing drawn.
      for (let f = F; f < shown.faces; f += 1) {
        shown.index.fill(RESTART, 3 * start[f], 3 * (start[f] + count[f]));
        written.push([start[f], count[f]]);
        count[f] = 0;
      }
      shown.faces = F;
      for (const f of follow.faces) {
        if (f >= F) continue;
        const a = data.faceOffsets[f]; const b = data.faceOffsets[f + 1];
        const n = Math.max(0, b - a - 2);
        if (n > count[f]) {
          // Its old place becomes empty (restart indices: nothing drawn).
          shown.index.fill(RESTART, 3 * start[f], 3 * (start[f] + count[f]));
          written.push([start[f], count[f]]);
          shown.index = withRoom(shown.index, 3 * (used + n), 3 * used);
          start[f] = used; count[f] = n; used += n;
        }
        let k = 3 * start[f];
        for (let i = a + 1; i + 1 < b; i += 1) {
          shown.index[k] = data.faceVertices[a]; shown.index[k + 1] = data.faceVertices[i]; shown.index[k + 2] = data.faceVertices[i + 1];
          k += 3;
        }
        shown.index.fill(RESTART, k, 3 * (start[f] + count[f]));
        written.push([start[f], count[f]]);
      }
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, full.triangles);
      if (shown.index.length > shown.capacity.index) {
        shown.capacity.index = shown.index.length;
        gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, shown.index, gl.STATIC_DRAW);
      } else {
        for (const [t, n] of written) if (n) gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 12 * t, shown.index, 3 * t, 3 * n);
      }
      full.triangleCount = used;
      // Edge lines: one place per edge (an edge not drawn is an empty line), once made.
      if (shown.lines) {
        const E = data.edges.length / data.edgeStride;
        const grownLines = 2 * E > shown.capacity.lines;
        shown.lines = withRoom(shown.lines, 2 * E, 2 * full.edgeCount);
        shown.lines.fill(RESTART, 2 * full.edgeCount, 2 * E);
        const touched = [...follow.edges].filter((e) => e < E);
        for (const e of touched) writeLine(shown.lines, data, e);
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, full.edges);
        if (grownLines) {
          shown.capacity.lines = shown.lines.length;
          gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, shown.lines, gl.STATIC_DRAW);
        } else {
          for (let e = full.edgeCount; e < E; e += 1) gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 8 * e, shown.lines, 2 * e, 2);
          for (const e of touched) gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 8 * e, shown.lines, 2 * e, 2);
        }
        full.edgeCount = E;
      } else {
        pendingLines = data;
      }
      // The proxy (a coarse stand-in while the view moves or a big picture is drawn over
      // frames) is kept: made again it would cost a pass over the whole mesh per edit, and the
      // few triangles an edit changed are too small to change it.
      if (proxyKey === meshKey) proxyKey = key;
      meshKey = key;
      lastDrawn = null;
      return true;
    },

    /** Uploads the mesh when `key` (mesh id and version) differs from the last one. */
    setMesh(key, /** @type {GlMeshData} */ data) {
      if (key === meshKey) return;
      this.uploadMesh(this.prepareMesh(key, data));
    },

    /**
     * Draws the last picture again now, whole (not the proxy, not over frames): a caller that
     * reads the canvas (a PNG export) must do so in the same task, before it is presented.
     */
    redraw() {
      if (!lastArgs) return;
      lastDrawn = null;
      this.draw(lastArgs[0], { ...lastArgs[1], useProxy: false }, { complete: true });
    },

    /** Clears the canvas to `background` ([r, g, b]): the picture while a mesh is uploaded. */
    clearPicture(background) {
      job = null;
      lastDrawn = null;
      showing = null;
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.clearColor(background[0], background[1], background[2], 1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    },

    /** The proxy drawn while the view moves: {positions (xyz), triangles} from mesh.displayProxy. */
    setProxy(key, { positions, triangles }) {
      if (key !== meshKey) return;
      fill(proxy, relativeTo(positions, centre).relative, Uint32Array.from(triangles), new Uint32Array(0));
      proxyKey = key;
    },

    /**
     * Draws the mesh (or its proxy). view: {R (row-major 3x3), offset [x, y] (centre minus
     * view centre, world units), zoom, width, height (CSS px), dpr}; style: {background, fill,
     * ink: [r,g,b], faceAlpha, backAlpha, lit, shade, edges (draw the edge lines), edgeAlpha,
     * useProxy}; complete: draw a big mesh whole in this call (an export), not over frames.
     * Returns 'same' when the canvas already shows this picture, 'drawn', or 'more' when a big
     * mesh is being drawn over several frames (draw again next frame to go on; the proxy, if
     * the mesh has one, stands in meanwhile).
     */
    draw(view, style, { complete = false } = {}) {
      const width = Math.round(view.width * view.dpr); const height = Math.round(view.height * view.dpr);
      const set = style.useProxy && proxyKey === meshKey ? proxy : full;
      const signature = JSON.stringify([meshKey, set === proxy, view, style]);
      if (signature === lastDrawn && canvas.width === width && canvas.height === height) return 'same';
      if (canvas.width !== width || canvas.height !== height) { canvas.width = width; canvas.height = height; }
      lastArgs = [view, style];
      if (style.edges && set === full && pendingLines) makeLines();
      const edges = style.edges ? set.edgeCount : 0;
      if (!meshKey || complete || costMs(set.triangleCount, edges) <= FRAME_BUDGET_MS) {
        job = null;
        render(set, view, style, null, [0, set.triangleCount], [0, edges]);
        lastDrawn = signature;
        showing = set === proxy ? 'proxy' : 'whole';
        return 'drawn';
      }
      // A big picture, FRAME_BUDGET_MS of work per frame, into an offscreen framebuffer shown
      // when whole.
      const fresh = !job || job.signature !== signature;
      if (fresh) {
        if (job?.fence) gl.deleteSync(job.fence);
        job = { signature, triangles: 0, edges: 0, started: false, proxyShown: false, fence: null };
      }
      // Paced by the GPU: the next piece is sent only once the GPU has finished the last one
      // (a fence), so no work piles up that a later frame would have to wait for.
      if (job.fence) {
        if (gl.getSyncParameter(job.fence, gl.SYNC_STATUS) !== gl.SIGNALED) return 'more';
        gl.deleteSync(job.fence);
        job.fence = null;
      }
      const target = offscreen(width, height);
      const triangleChunk = Math.floor(FRAME_BUDGET_MS * 1000 / TRIANGLE_US);
      const edgeChunk = Math.floor(FRAME_BUDGET_MS * 1000 / EDGE_US);
      /** @type {[number, number]} */
      const t = [job.triangles, Math.min(set.triangleCount, job.triangles + triangleChunk)];
      /** @type {[number, number]} */
      const e = t[1] < set.triangleCount ? [job.edges, job.edges] : [job.edges, Math.min(edges, job.edges + (t[1] > job.triangles ? 0 : edgeChunk))];
      render(set, view, style, target, t, e, !job.started);
      job.started = true;
      job.triangles = t[1];
      job.edges = e[1];
      if (job.triangles < set.triangleCount || job.edges < edges) {
        job.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
        gl.flush();
        // The proxy stands in, drawn once per picture (the canvas keeps it between frames).
        if (proxyKey === meshKey && set !== proxy && !job.proxyShown) {
          render(proxy, view, { ...style, edges: false }, null, [0, proxy.triangleCount], [0, 0]);
          job.proxyShown = true;
          showing = 'proxy';
        }
        return 'more';
      }
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, target.fbo);
      gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
      gl.blitFramebuffer(0, 0, width, height, 0, 0, width, height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
      job = null;
      lastDrawn = signature;
      showing = 'whole';
      return 'drawn';
    },
  };
}
