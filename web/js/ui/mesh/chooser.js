// @ts-check
// The mesh chooser of the mesh lessons: a list of meshes, the size fields of the generated
// ones (only the chosen mesh's are shown) and "Open OFF/OBJ…". A size that is not a whole
// number in its bounds is refused on the message line; choosing "Your file" before any file
// was imported opens the file dialog instead.
// Offers: createMeshChooser(ctx, options) -> { elements, sync(state) }: elements go into the
//   lesson's controls, sync shows a state's choice.
// Needs: a state with a mesh choice (mesh-choice.js: meshKind, fanSize, grid, sphere,
//   imported); options: kinds [{id, label}], sizes {fan|grid|sphere: [[min, max], ...]} (the
//   bounds of each size field, in the order the groups are shown), choose(patch) (the
//   lesson commits the new choice), importClass (the button's class); the page's
//   #import-file input (app/file-io.js) and ctx.message.
import { h } from '../../app/dom.js';

const labelled = (text, control) => h('label', {}, text, ' ', control);

// Each generated mesh's size fields: the input's id, its accessible name, its short label,
// and where the state keeps the value.
const SIZE_FIELDS = {
  fan: [{ id: 'fan-size', name: 'Fan triangles', label: 'triangles', get: (s) => s.fanSize, patch: (s, n) => ({ fanSize: n }) }],
  grid: [
    { id: 'grid-nx', name: 'Grid quads across', label: 'nx', get: (s) => s.grid.nx, patch: (s, n) => ({ grid: { ...s.grid, nx: n } }) },
    { id: 'grid-ny', name: 'Grid quads down', label: 'ny', get: (s) => s.grid.ny, patch: (s, n) => ({ grid: { ...s.grid, ny: n } }) },
  ],
  sphere: [
    { id: 'sphere-slices', name: 'Sphere slices', label: 'slices', get: (s) => s.sphere.slices, patch: (s, n) => ({ sphere: { ...s.sphere, slices: n } }) },
    { id: 'sphere-stacks', name: 'Sphere stacks', label: 'stacks', get: (s) => s.sphere.stacks, patch: (s, n) => ({ sphere: { ...s.sphere, stacks: n } }) },
  ],
};

/**
 * @param {any} ctx
 * @param {{ kinds: {id: string, label: string}[], sizes: Record<string, number[][]>, choose: (patch: object) => void, importClass?: string }} options
 */
export function createMeshChooser(ctx, { kinds, sizes, choose, importClass = 'tool' }) {
  const state = () => ctx.state;
  const select = h('select', { id: 'mesh-kind', 'aria-label': 'Mesh' }, kinds.map((k) => h('option', { value: k.id }, k.label)));
  const inputs = [];
  const groups = {};
  for (const [kind, bounds] of Object.entries(sizes)) {
    const fields = SIZE_FIELDS[kind].map((field, i) => {
      const [min, max] = bounds[i];
      const input = h('input', { type: 'number', id: field.id, min, max, step: 1, 'aria-label': field.name });
      input.addEventListener('change', () => {
        const n = Number(input.value);
        if (!Number.isInteger(n) || n < min || n > max) {
          ctx.message.error(`${field.name} must be a whole number from ${min} to ${max}`, 'invalid-size');
          sync(state());
          return;
        }
        choose(field.patch(state(), n));
      });
      inputs.push({ input, field });
      return labelled(field.label, input);
    });
    groups[kind] = h('span', { class: 'size-group' }, ...fields);
  }
  const openFile = () => document.getElementById('import-file')?.click();
  const importButton = h('button', { type: 'button', class: importClass, onclick: openFile }, 'Open OFF/OBJ…');
  select.addEventListener('change', () => {
    if (select.value === 'file' && !state().imported) {
      sync(state());
      openFile();
      return;
    }
    choose({ meshKind: select.value });
  });

  function sync(s) {
    select.value = s.meshKind;
    for (const [kind, group] of Object.entries(groups)) group.hidden = s.meshKind !== kind;
    for (const { input, field } of inputs) input.value = field.get(s);
  }

  return { elements: [labelled('Mesh', select), ...Object.values(groups), importButton], sync };
}
