// Every table tab of the mesh lesson on a big mesh: each table is windowed (a
// bounded number of rows in the DOM whatever the mesh), tells assistive technology how many
// rows the whole table has and where each drawn row sits in it, can be scrolled to its end
// from the keyboard, and its last rows then show what the core's own tables hold (read here
// from a fresh mesh built through the page's api, not from the lesson); the walk's row
// stays in view at every step.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useSiteAndBrowser } from '../../helpers/browser.mjs';
import { chooseSphere } from '../../helpers/mesh-page.mjs';

// docs/benchmarks.md's sphere kind: 100 slices x 101 stacks = 2 * 100 * 100 = 20,000 triangles,
// V = 100 * 100 + 2 = 10,002, E = 30,000: enough to show windowing.
const SLICES = 100;
const STACKS = 101;
const FACES = 2 * SLICES * (STACKS - 1);
// Rows a windowed table may hold in the DOM: a 22rem view of ~26 px rows plus the margin
// above and below is under 60; 200 leaves room for a tall phone view (60vh).
const MAX_DOM_ROWS_PER_TABLE = 200;
// Table cells round numbers to 4 significant digits (3 for the normal and the residual):
// a shown number x of a core value y satisfies |x - y| <= SHOWN_RELATIVE * |y| + SHOWN_ZERO
// (the mesh is of size 1: radius 1; num() shows |y| < 1e-12 as 0).
const SHOWN_RELATIVE = 5e-3;
const SHOWN_ZERO = 1e-9;

// The tables of each tab: table id -> [representation, table name] (the planes table is
// the core's planes and normals, not a representation).
const TAB_TABLES = {
  winged: { 'we-vertex-table': ['winged-edge', 'vertices'], 'we-edge-table': ['winged-edge', 'edges'], 'we-face-table': ['winged-edge', 'faces'] },
  faces: { 'independent-face-table': ['independent-faces', 'faces'] },
  'vertex-face': { 'vf-vertex-table': ['vertex-face-tables', 'vertices'], 'vf-face-table': ['vertex-face-tables', 'faces'] },
  adjacency: {
    'adj-vertex-table': ['adjacency-lists', 'vertices'], 'adj-edge-table': ['adjacency-lists', 'edges'], 'adj-face-table': ['adjacency-lists', 'faces'],
    'partial-vertex-table': ['partial-adjacency-lists', 'vertices'], 'partial-edge-table': ['partial-adjacency-lists', 'edges'], 'partial-face-table': ['partial-adjacency-lists', 'faces'],
  },
  'edge-list': { 'foley-vertex-table': ['edge-list', 'vertices'], 'foley-edge-table': ['edge-list', 'edges'], 'foley-polygon-table': ['edge-list', 'polygons'] },
  planes: { 'plane-table': null },
  'half-edge': { 'he-halfedge-table': ['half-edge', 'halfedges'], 'he-vertex-table': ['half-edge', 'vertices'], 'he-face-table': ['half-edge', 'faces'] },
};
// Tables whose rows are few whatever the mesh, drawn whole (no windowing): the half-edge
// tab's correspondence (one row per winged-edge field) and its walk (one row per edge
// around the walked vertex or face: at most SLICES, the poles' valence).
const SMALL_TABLES = { 'he-correspondence': 8, 'he-walk': SLICES };
// Independent faces, vertex and face tables, adjacency lists, partial adjacency lists, the
// edge list and the winged edge (lectures 000, 001, 003), and the half-edge beside them.
const REPRESENTATIONS = 7;
// The slides' letters per element kind (Foley's edge list: V, E, P).
const LETTERS = { default: { vertex: 'v', edge: 'e', face: 'F' }, 'edge-list': { vertex: 'V', edge: 'E', face: 'P' } };

const env = useSiteAndBrowser();
const settle = (page) => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));

async function openSphere() {
  const page = await env.openPage(`${env.site.url}mesh.html`);
  await page.waitForSelector('body[data-ready=true]', { timeout: 15000 });
  await chooseSphere(page, SLICES, STACKS);
  assert.equal(await page.evaluate(() => window.wingspline.model.F), FACES);
  await settle(page);
  return page;
}

async function showTab(page, tab) {
  await page.click(`#tab-${tab}`);
  await settle(page);
}

// What the page shows of a table: its header row count, aria-rowcount, and each drawn
// data row's aria-rowindex and cell texts (the row header first).
const shownTable = (page, id) => page.$eval(`#${id}`, (table) => ({
  headRows: table.tHead.rows.length,
  rowCount: Number(table.getAttribute('aria-rowcount')),
  rows: [...table.tBodies[0].querySelectorAll('tr[data-row]')].map((r) => ({
    row: Number(r.dataset.row), rowIndex: Number(r.getAttribute('aria-rowindex')), cells: [...r.children].map((c) => c.textContent.trim()),
  })),
}));

// The core's last row of a table, from a fresh mesh built in the page: the tokens a person
// reads in it, in order: references as [letter, 1-based number], numbers as numbers.
function coreLastRow(page, spec) {
  return page.evaluate(({ slices, stacks, spec, letters }) => {
    const api = window.wingspline.api;
    const mesh = api.buildMesh(api.generateMesh('sphere', { slices, stacks }));
    try {
      if (spec === null) {
        const F = mesh.counts().faces;
        const p = mesh.planes()[F - 1];
        const n = mesh.normals();
        return { total: F, label: ['F', F], tokens: [...p.cross, ...p.newell, n[3 * F - 3], n[3 * F - 2], n[3 * F - 1], p.residual] };
      }
      const [representation, name] = spec;
      if (representation === 'half-edge') {
        // The last row of the half-edge view, from its flat arrays: a half-edge's row is
        // origin, target (its twin's origin), face, next, prev, twin; a vertex's or a face's
        // its half-edge. The last two half-edges are one edge's pair.
        const { vertices, faces, edges } = mesh.counts();
        const total = { halfedges: 2 * edges, vertices, faces }[name];
        const a = mesh.halfEdgeArrays({ offset: name === 'halfedges' ? total - 2 : total - 1, limit: name === 'halfedges' ? 2 : 1 });
        const ref = (letter, i) => (i >= 0 ? [[letter, i + 1]] : []);
        const tokens = name === 'halfedges'
          ? [...ref('v', a.origin[1]), ...ref('v', a.origin[0]), ...ref('F', a.face[1]), ...ref('h', a.next[1]), ...ref('h', a.prev[1]), ['h', total - 1]]
          : ref('h', name === 'vertices' ? a.vertexHalfedge[0] : a.faceHalfedge[0]);
        return { total, label: [{ halfedges: 'h', vertices: 'v', faces: 'F' }[name], total], tokens };
      }
      const whole = mesh.tables(representation, { offset: 0, limit: 0 })[name];
      const total = whole.total;
      const table = mesh.tables(representation, { offset: total - 1, limit: 1 })[name];
      const L = letters[representation] ?? letters.default;
      const row = table.row(total - 1);
      const tokens = [];
      const push = (column, value) => {
        if (Array.isArray(value)) { for (const x of value) push(column, x); return; }
        if (column.refers === null) tokens.push(value);
        else if (value >= 0) tokens.push([L[column.refers], value + 1]);
      };
      for (const c of table.columns) push(c, row[c.name]);
      return { total, label: [L[table.kind], total], tokens };
    } finally {
      mesh.dispose?.();
    }
  }, { slices: SLICES, stacks: STACKS, spec, letters: LETTERS });
}

// Tokens of shown cells: "v5001" -> ['v', 5001]; "(0.1, -2, 3e-5)" -> 0.1, -2, 3e-5.
function tokensOf(cells) {
  const out = [];
  for (const text of cells) {
    for (const m of text.matchAll(/([A-Za-zλ]+)(\d+)|(-?\d+(?:\.\d+)?(?:e[-+]?\d+)?)/g)) {
      out.push(m[1] ? [m[1], Number(m[2])] : Number(m[3]));
    }
  }
  return out;
}

function assertRowMatches(shown, expected, where) {
  assert.equal(shown.length, expected.length, `${where}: ${JSON.stringify(shown)} vs the core's ${JSON.stringify(expected)}`);
  expected.forEach((want, k) => {
    const got = shown[k];
    if (Array.isArray(want)) assert.deepEqual(got, want, `${where}, item ${k}`);
    else assert.ok(typeof got === 'number' && Math.abs(got - want) <= SHOWN_RELATIVE * Math.abs(want) + SHOWN_ZERO, `${where}, item ${k}: shown ${got}, core ${want}`);
  });
}

test('on a 20,000-face sphere every table of every tab keeps a bounded number of rows in the DOM, its ARIA row count and indices true to the whole table', async () => {
  const page = await openSphere();
  const tabs = await page.$$eval('[role=tab][data-tab]', (b) => b.map((x) => x.dataset.tab));
  assert.equal(tabs.length, 9);
  for (const tab of tabs) {
    await showTab(page, tab);
    const ids = await page.$$eval(`#tabpanel-${tab} table`, (t) => t.map((x) => x.id));
    for (const id of ids) {
      const t = await shownTable(page, id);
      const bodyRows = await page.$$eval(`#${id} tbody tr`, (r) => r.filter((x) => !x.classList.contains('spacer')).length);
      assert.ok(bodyRows <= MAX_DOM_ROWS_PER_TABLE, `${tab}/${id}: ${bodyRows} rows in the DOM`);
      if (Object.hasOwn(SMALL_TABLES, id)) {
        assert.ok(bodyRows > 0 && bodyRows <= SMALL_TABLES[id], `${tab}/${id}: ${bodyRows} rows, at most ${SMALL_TABLES[id]}`);
        continue;
      }
      // The queries and storage tables: one row per representation (the lectures' six).
      const spec = TAB_TABLES[tab]?.[id];
      const { total } = spec === undefined ? { total: REPRESENTATIONS } : await coreLastRow(page, spec);
      assert.ok(t.rows.length > 0, `${id} shows rows`);
      assert.equal(t.rowCount, t.headRows + total, `${id}: aria-rowcount = ${t.headRows} header rows + ${total} rows`);
      for (const r of t.rows) assert.equal(r.rowIndex, t.headRows + r.row + 1, `${id}: row ${r.row} is row ${t.headRows + r.row + 1} of the whole table`);
    }
    // Every table the test expects is on the tab.
    const expected = TAB_TABLES[tab] ? Object.keys(TAB_TABLES[tab]) : { queries: ['query-table', 'query-growth-table'], storage: ['storage-table', 'storage-growth-table'] }[tab];
    for (const id of expected) assert.ok(ids.includes(id), `${tab} holds ${id}`);
  }
  assert.deepEqual(page.problems, []);
});

test('End on a focused table scrolls it (not the walk) to the last row, which shows the core\'s last row', async () => {
  const page = await openSphere();
  for (const [tab, tables] of Object.entries(TAB_TABLES)) {
    await showTab(page, tab);
    for (const [id, spec] of Object.entries(tables)) {
      const step = await page.evaluate(() => window.wingspline.state.step);
      await page.focus(`#${id} >> xpath=ancestor::div[contains(@class, 'table-scroll')]`);
      await page.keyboard.press('End');
      await settle(page);
      await settle(page);
      assert.equal(await page.evaluate(() => window.wingspline.state.step), step, `End in ${id} leaves the walk where it was`);
      const t = await shownTable(page, id);
      const expected = await coreLastRow(page, spec);
      const last = t.rows.at(-1);
      assert.equal(last.row, expected.total - 1, `${id} shows its last row`);
      assert.equal(last.rowIndex, t.rowCount, `${id}: the last row is the last of aria-rowcount`);
      assert.deepEqual(tokensOf([last.cells[0]]), [expected.label], `${id}: the last row's label`);
      assertRowMatches(tokensOf(last.cells.slice(1)), expected.tokens, `${id}, last row`);
      // Visible to a sighted person, not only present in the DOM.
      const visible = await page.$eval(`#${id} tr[data-row="${expected.total - 1}"]`, (tr) => {
        const s = tr.closest('.table-scroll').getBoundingClientRect();
        const r = tr.getBoundingClientRect();
        // Its end is in view (a pole's row of adjacency lists can be taller than the view).
        return r.bottom > s.top && r.bottom <= s.bottom + 1 && (r.top >= s.top - 1 || r.height > s.height / 2);
      });
      assert.ok(visible, `${id}: the table's view ends with the last row`);
      // Home brings back the first row.
      await page.keyboard.press('Home');
      await settle(page);
      await settle(page);
      const first = await shownTable(page, id);
      assert.equal(first.rows[0].row, 0, `${id}: Home shows the first row`);
    }
  }
  assert.deepEqual(page.problems, []);
});

test('walking around the south pole of the big sphere keeps the highlighted edge row in view at every step', async () => {
  const page = await openSphere();
  await showTab(page, 'winged');
  // The south pole is the last vertex (docs/benchmarks.md's sphere), of valence SLICES: its edges are
  // the last ones of the edge table.
  const V = SLICES * (STACKS - 1) + 2;
  await page.fill('#walk-element', String(V));
  await page.press('#walk-element', 'Enter');
  await settle(page);
  await page.click('#walk-title');
  const steps = await page.evaluate(() => window.wingspline.model.frames.length - 1);
  assert.ok(steps > SLICES, `the walk has a step per edge (${steps})`);
  const inView = () => page.evaluate(() => {
    const rows = [...document.querySelectorAll('#tabpanel-winged tr.is-highlighted')];
    return rows.map((tr) => {
      const s = tr.closest('.table-scroll').getBoundingClientRect();
      const r = tr.getBoundingClientRect();
      return { id: tr.closest('table').id, row: Number(tr.dataset.row), visible: r.top >= s.top - 1 && r.bottom <= s.bottom + 1 };
    });
  });
  const checked = [0, 1, 2, 3, 4, 5, Math.floor(steps / 2), steps - 1, steps];
  let at = 0;
  await page.keyboard.press('Home');
  for (const target of checked) {
    while (at < target) { await page.keyboard.press('n'); at += 1; }
    await settle(page);
    const frame = await page.evaluate(() => { const f = window.wingspline.model.frame; return { table: f.table, row: f.row, step: window.wingspline.model.stepIndex }; });
    assert.equal(frame.step, target);
    const rows = await inView();
    const id = { edge: 'we-edge-table', vertex: 'we-vertex-table', face: 'we-face-table' }[frame.table];
    const mine = rows.find((r) => r.id === id && r.row === frame.row);
    assert.ok(mine, `step ${target}: row ${frame.row} of ${id} is highlighted (${JSON.stringify(rows)})`);
    assert.ok(mine.visible, `step ${target}: row ${frame.row} of ${id} is in view`);
  }
  assert.deepEqual(page.problems, []);
});

// Query cost and storage against mesh size, as a picture and as numbers; the
// lecture mesh's default query says where the winged edge reads more than the small tables.
test('the queries and storage tabs plot the core\'s figures against mesh size; the small mesh\'s exception is said', async () => {
  const page = await env.openLesson(`${env.site.url}mesh.html`);
  await page.click('#tab-queries');
  await page.waitForSelector('#query-growth-table tbody tr', { state: 'attached' }); // in a closed <details>
  // The numbers behind the plot: one row per representation, one column per grid size,
  // the first equal to the core's count on a real 22 x 22 grid asked here through the page's api.
  const { shown, expected } = await page.evaluate(() => {
    const api = window.wingspline.api;
    const shown = Object.fromEntries([...document.querySelectorAll('#query-growth-table tbody tr')]
      .map((tr) => [tr.dataset.representation, [...tr.querySelectorAll('td')].map((td) => Number(td.textContent.replace(/,/g, '')))]));
    const mesh = api.buildMesh(api.generateMesh('grid', { nx: 22, ny: 22, layout: 'csr' }));
    const middle = 11 * 23 + 11;
    const expected = Object.fromEntries(Object.entries(mesh.query('faces-around-vertex', middle)).map(([rep, a]) => [rep, a.entriesRead]));
    expected['half-edge'] = mesh.halfEdgeQuery('faces-around-vertex', middle).entriesRead;
    mesh.dispose();
    return { shown, expected };
  });
  // The lecture's six representations and the half-edge.
  assert.equal(Object.keys(shown).length, 7);
  for (const [rep, values] of Object.entries(shown)) {
    assert.equal(values.length, 4, rep);
    assert.equal(values[0], expected[rep], `${rep} on the 22 x 22 grid`);
  }
  assert.ok(await page.locator('#query-growth-plot').isVisible());
  // The lecture mesh, faces around v2: the winged edge reads more than the adjacency lists;
  // the note says so with the core's counts.
  const answers = await page.evaluate(() => window.wingspline.model.mesh.query('faces-around-vertex', 1));
  const note = await page.textContent('#query-small-note');
  assert.match(note, new RegExp(`winged edge reads ${answers['winged-edge'].entriesRead} entries`));
  assert.match(note, new RegExp(`Adjacency lists ${answers['adjacency-lists'].entriesRead}`));
  // Storage: its own plot and numbers, reached by keyboard.
  await page.focus('#tab-storage');
  await page.keyboard.press('Enter');
  await page.waitForSelector('#storage-growth-table tbody tr', { state: 'attached' });
  assert.equal(await page.locator('#storage-growth-table tbody tr').count(), 7);
  assert.deepEqual(page.problems, []);
});

// What an edit touches is what the tables redraw: a row whose text did not change keeps its
// element (no layout or paint for it), a row whose text changed is drawn anew. Checked for
// every step of a flip's playback and for its undo, on the 20,000-face sphere's three
// winged-edge tables, by comparing each drawn row's text and element before and after.
test('a flip played step by step and undone redraws exactly the table rows whose text changed', async () => {
  const page = await openSphere();
  await showTab(page, 'winged');
  // An edge whose row is drawn, so its rewrites are in view: the middle drawn row of the edge table.
  const e = await page.$eval('#we-edge-table', (table) => {
    const rows = [...table.tBodies[0].querySelectorAll('tr[data-row]')];
    const m = window.wingspline.model.mesh;
    const drawn = rows.map((r) => Number(r.dataset.row));
    return drawn.slice(Math.floor(drawn.length / 2)).find((i) => m.check({ op: 'flip-edge', e: i }).ok);
  });
  assert.ok(Number.isInteger(e), 'a drawn edge can be flipped');
  await page.selectOption('#edit-kind', 'edge');
  await page.fill('#edit-element', String(e + 1));
  await page.press('#edit-element', 'Enter');
  await page.waitForFunction((want) => document.querySelector('#edit-picked')?.textContent === want, `Picked: e${e + 1}`);
  // Each drawn row of the three tables: its text, and the element itself kept in the page.
  const snapshot = () => page.evaluate(() => {
    window.__rows ??= new Map();
    const out = {};
    for (const id of ['we-vertex-table', 'we-edge-table', 'we-face-table']) {
      for (const tr of document.querySelectorAll(`#${id} tbody tr[data-row]`)) {
        const key = `${id}:${tr.dataset.row}`;
        const seen = window.__rows.get(key);
        out[key] = { text: tr.textContent, same: seen?.el === tr, before: seen?.text ?? null };
        window.__rows.set(key, { el: tr, text: tr.textContent });
      }
    }
    return out;
  });
  const check = (rows, where) => {
    let changed = 0;
    for (const [key, r] of Object.entries(rows)) {
      if (r.before === null) continue; // scrolled into the window now: new by necessity
      if (r.text !== r.before) { changed += 1; assert.equal(r.same, false, `${where}: ${key} changed its text and is drawn anew`); }
      else assert.equal(r.same, true, `${where}: ${key} kept its text and its element`);
    }
    return changed;
  };
  await snapshot();
  await page.click('button[data-op="flip-edge"]');
  await page.waitForFunction(() => window.wingspline.state.ops.length === 1);
  await page.click('#edit-restart');
  await page.waitForFunction(() => document.querySelector('#edit-step')?.textContent.startsWith('0 of'));
  await settle(page);
  await snapshot();
  const n = Number((await page.textContent('#edit-step')).match(/of (\d+)/)[1]);
  let changedInAll = 0;
  for (let k = 1; k <= n; k += 1) {
    await page.click('#edit-next');
    await page.waitForFunction((want) => document.querySelector('#edit-step')?.textContent.startsWith(`${want} of`), k);
    await settle(page);
    changedInAll += check(await snapshot(), `step ${k} of ${n}`);
  }
  // The flip rewrote rows in view (the flipped edge's own row at least), so the check saw change.
  assert.ok(changedInAll >= 1, `rows changed while the flip played (${changedInAll})`);
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.wingspline.state.ops.length === 0);
  await settle(page);
  assert.ok(check(await snapshot(), 'undo') >= 1, 'the undo changed rows in view');
  assert.deepEqual(page.problems, []);
});
