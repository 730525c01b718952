// ui_edit (docs/benchmarks.md): each operation of the mesh lesson's edit panel, and its undo
// and redo, from the command to the frame drawn with every table updated, on sphere_1000,
// sphere_100000 and sphere_1000000, in ms (median of REPETITIONS per operation; 5 on the
// million faces, where each repetition's set-up is slow), headless Chromium.
// The command is the commit the edit panel makes (the state with the operation added, as
// edit-ops.js withEdit writes it); undo and redo are Ctrl+Z and Ctrl+Y. Timed: the command
// itself plus the animation frame that follows, from the frame's start to a callback queued
// after the command (walk.bench.mjs). The elements, spread over the mesh: repetition r of
// R takes the first element from number floor((r + 0.5) / R * count) on that the
// operation's check accepts:
//   flip-edge, split-edge (t = 0.5), collapse-edge (t = 0.5), join-faces: an edge;
//   poke-face: a face;
//   split-face: a quad made first by a join-faces of an edge (not timed), split by its other
//     diagonal (corners 2 and 4 of the joined face);
//   split-vertex: a vertex, between its first and third neighbour (t = 0.5).
// Each repetition starts from the sphere as generated (the state's edits cleared, not timed).
// Never run by npm test.
//   WINGSPLINE_EDIT_SITES=before=/tmp/dist-old,after=dist node tests/bench/browser/edit.bench.mjs
import { wants, report } from '../wasm/harness.mjs';
import { benchSites } from './sites.mjs';
import { startSite, launchBrowser, openPage } from '../../helpers/browser.mjs';
import { chooseSphere } from '../../helpers/mesh-page.mjs';

const TASK = 'ui_edit';
const SPHERES = (process.env.WINGSPLINE_EDIT_SPHERES ?? '20x26x20,250x201x20,1000x501x5').split(',').map((s) => s.split('x').map(Number)); // slices x stacks x repetitions
const OPERATIONS = ['flip-edge', 'split-edge', 'split-face', 'join-faces', 'collapse-edge', 'poke-face', 'split-vertex'];

// In the page: one repetition of `op` (its set-up untimed), then its undo and redo.
async function measureOne(page, op, r, repetitions) {
  return page.evaluate(async ([name, rep, reps]) => {
    const w = window.wingspline;
    const frame = () => new Promise((resolve) => requestAnimationFrame((ts) => resolve({ start: ts, end: performance.now() })));
    async function timed(run) {
      const t0 = performance.now();
      run();
      const t1 = performance.now();
      const f = await frame();
      return (t1 - t0) + (f.end - Math.max(f.start, t1));
    }
    const key = (k, mods = {}) => document.activeElement.dispatchEvent(new KeyboardEvent('keydown', { key: k, bubbles: true, cancelable: true, ...mods }));
    const commitOps = (ops) => w.ctx.commit({ ...w.state, ops, moved: [], step: 0, editStep: -1 });
    // From the sphere as generated.
    if (w.state.ops.length) { commitOps([]); await frame(); }
    const m = () => w.model;
    const first = (count, ok) => {
      const from = Math.floor(((rep + 0.5) / reps) * count);
      for (let k = 0; k < count; k += 1) {
        const i = (from + k) % count;
        const operation = ok(i);
        if (operation && m().mesh.check(operation).ok) return operation;
      }
      throw new Error(`no element for ${name}`);
    };
    let setup = [];
    let operation;
    if (['flip-edge', 'split-edge', 'collapse-edge', 'join-faces'].includes(name)) {
      operation = first(m().E, (e) => ({ op: name, e, ...(name === 'split-edge' || name === 'collapse-edge' ? { t: 0.5 } : {}) }));
    } else if (name === 'poke-face') {
      operation = first(m().F, (f) => ({ op: name, f }));
    } else if (name === 'split-vertex') {
      operation = first(m().V, (v) => {
        const n = m().mesh.adjacency('vertices-around-vertex', v);
        return n.length >= 4 ? { op: name, v, a: n[0], b: n[2], t: 0.5 } : null;
      });
    } else {
      const join = first(m().E, (e) => ({ op: 'join-faces', e }));
      const sides = [m().we.edges[8 * join.e + 2], m().we.edges[8 * join.e + 3]];
      setup = [join];
      commitOps(setup);
      await frame();
      // The face that stays (the join removes the other).
      const f = sides.find((x) => !Array.from(w.model.lastOperation.removed.faces).includes(x));
      const corners = m().mesh.adjacency('vertices-of-face', f);
      operation = { op: 'split-face', f, a: corners[1], b: corners[3] };
      if (!m().mesh.check(operation).ok) operation = { op: 'split-face', f, a: corners[0], b: corners[2] };
    }
    const apply = await timed(() => commitOps([...setup, operation]));
    if (w.state.ops.length !== setup.length + 1) throw new Error(`${name} was not applied: ${w.message()}`);
    const undo = await timed(() => key('z', { ctrlKey: true }));
    if (w.state.ops.length !== setup.length) throw new Error(`undo of ${name} did not undo`);
    const redo = await timed(() => key('y', { ctrlKey: true }));
    if (w.state.ops.length !== setup.length + 1) throw new Error(`redo of ${name} did not redo`);
    return { apply, undo, redo, checksum: w.model.V + w.model.E + w.model.F };
  }, [op, r, repetitions]);
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

for (const { label, root } of wants(TASK) ? benchSites('WINGSPLINE_EDIT_SITES') : []) {
  const site = await startSite({ root });
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, `${site.url}mesh.html`);
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.waitForSelector('body[data-ready=true]', { timeout: 20000 });
    for (const [slices, stacks, repetitions] of SPHERES) {
      await chooseSphere(page, slices, stacks, { timeout: 240000 });
      await page.click('#walk-title');
      const input = `sphere_${2 * slices * (stacks - 1)}`;
      for (const op of OPERATIONS) {
        const rows = [];
        for (let r = 0; r < repetitions; r += 1) rows.push(await measureOne(page, op, r, repetitions));
        for (const phase of ['apply', 'undo', 'redo']) {
          const times = rows.map((x) => x[phase]);
          report({ task: TASK, build: 'browser', input, operation: op, phase, ...(label ? { site: label } : {}), n: 1, seconds: times,
            checksum: rows.reduce((a, x) => a + x.checksum, 0), unit: 'ms', median_ms: median(times) });
        }
      }
    }
    if (page.problems.length) throw new Error(page.problems.join('\n'));
  } finally {
    await browser.close();
    await site.close();
  }
}
