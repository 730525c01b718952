// @ts-check
// An embed (#embed=1&..., docs/embed.md): the canvas and its few controls, fitted to the
// frame; its theme and presentation mode come from the link and are not remembered; it
// reads and writes nothing of the person's saved work. share-link.js reads the options;
// this file applies them to the page.
import { readEmbedOptions, embedProblemsText } from './share-link.js';
import { setTheme, showPresenting } from './theme.js';

/**
 * The embed options of an address, applied to the page (after the stored theme, which an
 * embed's own theme overrides); null for a page that is no embed.
 * @param {string} hash
 */
export function applyEmbed(hash) {
  const embed = readEmbedOptions(hash);
  if (embed) {
    document.documentElement.dataset.embed = '';
    if (embed.controls) document.documentElement.dataset.embedControls = '';
    if (embed.theme) setTheme(embed.theme, { remember: false });
    showPresenting(embed.present);
  }
  return embed;
}

/**
 * Shows an embed's side panels: only those its link lists (panels=a,b), by their ids. Says
 * in one text what of its link cannot be used, a listed name that is no panel of this
 * lesson included; null when everything could.
 * @param {NonNullable<ReturnType<typeof readEmbedOptions>>} embed
 * @param {HTMLElement} panels the side column
 */
export function showEmbedPanels(embed, panels) {
  const ids = embed.panels;
  const found = [];
  for (const el of /** @type {HTMLElement[]} */ ([...(panels?.children ?? [])])) {
    if (el.id && ids.includes(el.id)) { el.dataset.embedShown = ''; found.push(el.id); }
  }
  if (found.length) document.documentElement.dataset.embedPanels = '';
  const missing = ids.filter((id) => !found.includes(id)).map((id) => `panels lists "${id}", which is not a panel of this lesson`);
  return embedProblemsText([...embed.problems, ...missing]);
}
