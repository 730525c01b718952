// The mesh lesson's pure state helpers for edits (issue 15): what a state's operation list
// becomes when a person edits the mesh or chooses a stored edge. No core and no page needed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withEdit, checkArgs, EDIT_OPS } from '../../web/js/lessons/mesh/edit-ops.js';
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

test("every edit offered names the arguments the core checks, in the core's order", () => {
  const made = Object.fromEntries(EDIT_OPS.map((o) => [o.op, o.make(4, { t: 0.25, a: 1, b: 3 })]));
  assert.deepEqual(checkArgs(made['split-edge']), [4, 0.25]);
  assert.deepEqual(checkArgs(made['collapse-edge']), [4, 0.25]);
  assert.deepEqual(checkArgs(made['flip-edge']), [4]);
  assert.deepEqual(checkArgs(made['join-faces']), [4]);
  assert.deepEqual(checkArgs(made['split-face']), [4, 1, 3]);
  assert.deepEqual(checkArgs(made['poke-face']), [4]);
  assert.deepEqual(new Set(EDIT_OPS.map((o) => o.key)).size, EDIT_OPS.length, 'one key per operation');
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
