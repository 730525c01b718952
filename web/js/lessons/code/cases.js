// @ts-check
// The meshes a student's function is tried on: the slide's mesh first, then hidden meshes the
// grader makes from a seed the student does not see (the lesson lists their kinds, not the
// seed). Every mesh is built by the core (its generators, its checked edits); the seed only
// chooses which elements are asked about, which edits are made and which stored edges are
// turned around. A case carries what the sandbox reads (snapshot: the tables as flat arrays,
// a removed element's row all -1), what the page draws (positions, faces) and what the core
// says the answer is (expected) and how many entries the lecture's rule reads (referenceReads).

// The kinds of hidden meshes, in the order they are tried, as the lesson names them.
export const HIDDEN_KINDS = [
  'an open fan of 6 triangles (a vertex task asks at its centre, on the boundary)',
  'a tetrahedron (every vertex of valence 3)',
  'a cube of quads',
  'a sphere of 50 slices (its poles have valence 50)',
  'a grid whose faces an edit joined into polygons (removed rows stay, every entry -1)',
  'a sphere after random flips, splits and collapses',
  'the slide\'s mesh with every stored edge turned around (S and E swapped)',
  'a grid with some stored edges turned around',
];

// A small seeded generator (mulberry32): the same seed, the same cases.
export function seeded(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return { next, int: (n) => Math.floor(next() * n) };
}

// The mesh's tables as the sandbox reads them: the winged edge's and the half-edge's arrays,
// every entry of a removed element's row -1 (the core keeps its old numbers until compact).
export function snapshotOf(mesh) {
  const w = mesh.wingedEdgeArrays();
  const gaps = mesh.gaps();
  const edges = Int32Array.from(w.edges);
  const vertexEdge = Int32Array.from(w.vertexEdge);
  const faceEdge = Int32Array.from(w.faceEdge);
  for (const e of gaps.edges) edges.fill(-1, 8 * e, 8 * e + 8);
  const positions = Float64Array.from(w.positions);
  for (const v of gaps.vertices) { vertexEdge[v] = -1; positions.fill(-1, 3 * v, 3 * v + 3); }
  for (const f of gaps.faces) faceEdge[f] = -1;
  const he = mesh.halfEdgeArrays();
  return {
    winged: { positions, vertexEdge, edges, faceEdge, edgeFields: [...w.edgeFields] },
    halfEdge: {
      origin: Int32Array.from(he.origin), face: Int32Array.from(he.face), next: Int32Array.from(he.next), prev: Int32Array.from(he.prev),
      vertexHalfedge: Int32Array.from(he.vertexHalfedge), faceHalfedge: Int32Array.from(he.faceHalfedge),
    },
  };
}

// What the sandbox is given of a case: the structure the task reads, and only that (a
// half-edge task's function cannot read the winged edge's pointers; a winged-edge task's the
// half-edge's).
export function sandboxMesh(task, c) {
  return task.structure === 'half-edge' ? { halfEdge: c.snapshot.halfEdge } : { winged: c.snapshot.winged };
}

const live = (count, removed) => {
  const gone = new Set(Array.from(removed));
  const out = [];
  for (let i = 0; i < count; i += 1) if (!gone.has(i)) out.push(i);
  return out;
};

// The edges of a mesh as [start, end] pairs, `turn(e)` saying which to store the other way
// round (the build then numbers and orients the edges as given).
function edgePairs(mesh, turn) {
  const w = mesh.wingedEdgeArrays();
  const pairs = [];
  for (let e = 0; e < w.edges.length / 8; e += 1) {
    const s = w.edges[8 * e]; const t = w.edges[8 * e + 1];
    pairs.push(turn(e) ? [t, s] : [s, t]);
  }
  return pairs;
}

// Up to `count` random edits by the core's operations, each checked first (an edit the
// core refuses is skipped): the mesh then has polygons, new elements and removed rows.
function randomEdits(mesh, rng, count, names) {
  let made = 0;
  for (let tries = 0; made < count && tries < 20 * count; tries += 1) {
    const name = names[rng.int(names.length)];
    const { edges } = mesh.counts();
    const removed = new Set(Array.from(mesh.gaps().edges));
    const e = rng.int(edges + removed.size);
    if (removed.has(e)) continue;
    const op = name === 'flip-edge' || name === 'join-faces' ? { op: name, e } : { op: name, e, t: 0.5 };
    if (!mesh.check(op).ok) continue;
    mesh.apply(op);
    made += 1;
  }
}

/**
 * The cases of one run: the slide's mesh with the task's own arguments, then one of each
 * hidden kind with arguments the seed picks among the live elements.
 * @param {any} api the core's JS API
 * @param {import('./tasks.js').Task} task
 * @param {number} seed
 */
export function makeCases(api, task, seed) {
  const rng = seeded(seed);
  const made = [];
  const lecture = api.lectureExample();
  const build = (label, input, { pickVertex = null, edits = null } = {}) => {
    const mesh = api.buildMesh(input);
    try {
      edits?.(mesh);
      const gaps = mesh.gaps();
      const counts = mesh.counts();
      const vertices = live(counts.vertices + gaps.vertices.length, gaps.vertices);
      const faces = live(counts.faces + gaps.faces.length, gaps.faces);
      // An edit's cases have no removed rows (the check reads the tables whole), nor a
      // subdivision point's (the core subdivides a mesh without gaps): compacted.
      if ((task.answer === 'edit' || task.answer === 'position') && (gaps.vertices.length || gaps.edges.length || gaps.faces.length)) {
        mesh.compact();
        build(label, { ...mesh.faceSet(), positions: mesh.wingedEdgeArrays().positions }, { pickVertex });
        return;
      }
      const args = task.params.map((kind) => {
        if (kind === 'vertex') return pickVertex ?? vertices[rng.int(vertices.length)];
        if (kind === 'edge') {
          // An edge the task's operation accepts (the core's check), or none: not asked.
          const edges = live(counts.edges + gaps.edges.length, gaps.edges).filter((e) => !task.op || mesh.check({ op: task.op, e, ...task.opArgs }).ok);
          return edges.length ? edges[rng.int(edges.length)] : null;
        }
        // The face with the most sides (ties: the seed), or any face.
        let best = [];
        let most = 0;
        const sizes = mesh.faceSet();
        for (const f of faces) {
          const n = sizes.faceOffsets[f + 1] - sizes.faceOffsets[f];
          if (n > most) { most = n; best = [f]; } else if (n === most) best.push(f);
        }
        return most > 3 ? best[rng.int(best.length)] : faces[rng.int(faces.length)];
      });
      // Loop's rules are for triangles: a mesh with polygons is not asked.
      const polygons = task.scheme === 'loop' && !triangles(mesh);
      if (polygons) made.push({ label, args: null, skipped: 'it has faces that are not triangles, and Loop\'s rules are for triangles', ...picture(mesh) });
      else if (args.includes(null)) made.push({ label, args: null, skipped: `no edge of it can take the ${task.editName ?? task.op}`, ...picture(mesh) });
      else made.push(caseOf(api, mesh, task, label, args));
    } finally {
      mesh.dispose();
    }
  };
  made.push(lectureCase(api, task));
  build(HIDDEN_KINDS[0], api.generateMesh('fan', { n: 6 }), { pickVertex: 0 });
  build(HIDDEN_KINDS[1], api.generateMesh('tetrahedron'));
  build(HIDDEN_KINDS[2], api.generateMesh('cube'));
  build(HIDDEN_KINDS[3], api.generateMesh('sphere', { slices: 50, stacks: 4 }), { pickVertex: rng.int(2) === 0 ? 0 : 151 });
  build(HIDDEN_KINDS[4], api.generateMesh('grid', { nx: 4, ny: 3 }), { edits: (mesh) => randomEdits(mesh, rng, 4, ['join-faces']) });
  build(HIDDEN_KINDS[5], api.generateMesh('sphere', { slices: 8, stacks: 5 }), { edits: (mesh) => randomEdits(mesh, rng, 6, ['flip-edge', 'split-edge', 'collapse-edge']) });
  {
    const slide = api.buildMesh(lecture);
    let turned;
    try { turned = edgePairs(slide, () => true); } finally { slide.dispose(); }
    build(HIDDEN_KINDS[6], { positions: lecture.positions, faces: lecture.faces, edges: turned });
  }
  {
    const input = api.generateMesh('grid', { nx: 3, ny: 2 });
    const plain = api.buildMesh(input);
    let turned;
    try { turned = edgePairs(plain, () => rng.next() < 0.5); } finally { plain.dispose(); }
    build(HIDDEN_KINDS[7], { ...input, edges: turned });
  }
  return made;
}

// The slide's mesh (lecture 000, the slide's numbering) asked with the task's own arguments.
export function lectureCase(api, task) {
  const mesh = api.buildMesh(api.lectureExample());
  try {
    return caseOf(api, mesh, task, 'the slide\'s mesh (lecture 000)', task.lectureArgs);
  } finally {
    mesh.dispose();
  }
}

// One case of a built mesh: its tables (snapshot), its picture (positions, faces), the
// arguments, and the core's answer and read count.
function caseOf(api, mesh, task, label, args) {
  const shown = picture(mesh);
  // The answer last: an edit task's expected() edits the mesh.
  const expected = task.expected(mesh, args, api);
  return { label, args, ...shown, expected, referenceReads: task.referenceReads(mesh, args, expected) };
}

// Every face a triangle (the faces as the core lists them).
function triangles(mesh) {
  const { faceOffsets } = mesh.faceSet();
  for (let f = 0; f + 1 < faceOffsets.length; f += 1) if (faceOffsets[f + 1] - faceOffsets[f] !== 3) return false;
  return true;
}

// What the page draws and the sandbox reads of a mesh as it is.
function picture(mesh) {
  const faces = mesh.faceSet();
  return {
    snapshot: snapshotOf(mesh),
    faceOffsets: Int32Array.from(faces.faceOffsets),
    faceVertices: Int32Array.from(faces.faceVertices),
    counts: mesh.counts(),
  };
}
