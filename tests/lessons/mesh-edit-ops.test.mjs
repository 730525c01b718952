// The mesh lesson's state helpers for edits: what a state's operation list becomes when a
// person edits the mesh or chooses a stored edge, and the edit panel's operations as read
// from the core's registry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadWingspline } from 'wingspline';
import { withEdit, editOps, describeOperation } from '../../web/js/lessons/mesh/edit-ops.js';
import { withStoredEdge } from '../../web/js/lessons/mesh/stored-edge.js';

const base = { ops: [], moved: [], step: 3, editStep: 5 };

test('an edit appends its operation; vertices moved before it become move-vertex operations first, in order', () => {
  const state = { ...base, moved: [{ v: 1, p: [0.5, 0.25, 0] }, { v: 3, p: [2, 1, 0] }] };
  const next = withEdit(state, { op: 'split-edge', e: 2, t: 0.5 });
  assert.deepEqual(next.ops, [{ op: 'move-vertex', v: 1, p: [0.5, 0.25, 0] }, { op: 'move-vertex', v: 3, p: [2, 1, 0] }, { op: 'split-edge', e: 2, t: 0.5 }]);
  assert.deepEqual(next.moved, []);
  assert.equal(next.editStep, -1); // the player shows the new edit done
  assert.equal(next.step, 0);
  // The moves are copies: changing the old state's arrays does not reach the new list.
  state.moved[0].p[0] = 99;
  assert.equal(next.ops[0].p[0], 0.5);
});

test('every edit offered comes from the registry and makes the record the core takes', async () => {
  const api = await loadWingspline();
  const EDIT_OPS = editOps(api.meshOperations);
  // every operation with a key, in the registry's order; the stored-edge choices are made in the tables
  assert.deepEqual(EDIT_OPS.map((o) => o.op), api.meshOperations.operations.filter((o) => o.shortcut).map((o) => o.name));
  assert.ok(EDIT_OPS.some((o) => o.op === 'split-vertex'));
  const made = Object.fromEntries(EDIT_OPS.map((o) => [o.op, o.make(4, { t: 0.25, a: 1, b: 3 })]));
  assert.deepEqual(made['split-edge'], { op: 'split-edge', e: 4, t: 0.25 });
  assert.deepEqual(made['collapse-edge'], { op: 'collapse-edge', e: 4, t: 0.25 });
  assert.deepEqual(made['flip-edge'], { op: 'flip-edge', e: 4 });
  assert.deepEqual(made['join-faces'], { op: 'join-faces', e: 4 });
  assert.deepEqual(made['split-face'], { op: 'split-face', f: 4, a: 1, b: 3 });
  assert.deepEqual(made['poke-face'], { op: 'poke-face', f: 4 });
  assert.deepEqual(made['split-vertex'], { op: 'split-vertex', v: 4, a: 1, b: 3, t: 0.25 });
  assert.deepEqual(new Set(EDIT_OPS.map((o) => o.key)).size, EDIT_OPS.length, 'one key per operation');
  // The line describing an edit names elements as the slides do (from 1).
  const entry = (name) => api.meshOperations.operations.find((o) => o.name === name);
  assert.equal(describeOperation(entry('split-edge'), made['split-edge']), 'split e5 at t = 0.25');
  assert.equal(describeOperation(entry('split-face'), made['split-face']), 'split F5 by v2–v4');
  assert.equal(describeOperation(entry('split-vertex'), made['split-vertex']), 'split v5 between v2 and v4');
});

test('choosing a stored edge again supersedes the earlier choice only after the last edit', () => {
  let ops = withStoredEdge([], 'vertex', 1, 4);
  ops = withStoredEdge(ops, 'vertex', 1, 2);
  assert.deepEqual(ops, [{ op: 'set-vertex-edge', v: 1, e: 2 }]);
  // An edit in between: the choice before it stays (the edit may depend on it).
  ops = [...ops, { op: 'split-edge', e: 2, t: 0.5 }];
  ops = withStoredEdge(ops, 'vertex', 1, 7);
  assert.deepEqual(ops, [{ op: 'set-vertex-edge', v: 1, e: 2 }, { op: 'split-edge', e: 2, t: 0.5 }, { op: 'set-vertex-edge', v: 1, e: 7 }]);
  ops = withStoredEdge(ops, 'vertex', 1, 5);
  assert.deepEqual(ops.at(-1), { op: 'set-vertex-edge', v: 1, e: 5 });
  assert.equal(ops.length, 3);
  // Another row, or the face table, is not superseded.
  ops = withStoredEdge(ops, 'face', 1, 5);
  assert.equal(ops.length, 4);
});
