// @ts-check
// The lesson registry: every lesson page the site has, in course order. The landing page
// lists them; a lesson whose page is not built yet is shown as "coming".
export const lessons = [
  {
    id: 'mesh',
    title: 'Mesh representations',
    page: 'mesh.html',
    lectures: '000, 001, 003',
    summary: 'Independent faces, vertex and face tables, adjacency lists, edge lists and the winged edge; watch the CCW traversal around a vertex.',
    ready: true,
  },
  {
    id: 'curves',
    title: 'Curve explorer',
    page: 'curves.html',
    lectures: '000 to 004',
    summary: 'Hermite, Bezier, B-splines, NURBS and Catmull-Rom: drag control points, watch the blending functions, the matrices and de Casteljau.',
    ready: true,
  },
  {
    id: 'continuity',
    title: 'Continuity lab',
    page: 'continuity.html',
    lectures: '000, 001, 002, 004',
    summary: 'C0, C1, C2 against G1, G2, measured at every joint of a piecewise curve.',
    ready: true,
  },
  {
    id: 'comparison',
    title: 'Comparison lab',
    page: 'comparison.html',
    lectures: '001, 002, 003',
    summary: 'One control polygon under several curve families; the comparison tables checked live; basis conversion.',
    ready: true,
  },
  {
    id: 'surfaces',
    title: 'Surface patches',
    page: 'surfaces.html',
    lectures: '002',
    summary: 'Bicubic Hermite and Bezier patches with their control nets and twist vectors.',
    ready: true,
  },
  {
    id: 'subdivision',
    title: 'Subdivision',
    page: 'subdivision.html',
    lectures: '000, 003, 004',
    summary: 'Loop and Catmull-Clark one phase at a time on the winged edge: every new point with its mask, levels 0 to 5, limit positions; beside it Chaikin and cubic subdivision of a polygon converging to its B-spline.',
    ready: true,
  },
  {
    id: 'code',
    title: 'Program the structure',
    page: 'code.html',
    lectures: '000, 003',
    summary: 'Write the winged-edge and half-edge walks yourself: your code runs in a sandbox, every entry it reads lights up in the tables, and it is graded on the slide\'s mesh and on hidden meshes.',
    ready: true,
    // It carries a code editor (docs/architecture.md, "Module size"); the sandbox's engine
    // is fetched on the first Run and is not part of the page's load.
    weightBudget: 450_000,
  },
];
