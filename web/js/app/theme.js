// @ts-check
// Theme (system, light, dark), remembered in local storage, and presentation mode (for this page only).
const THEME_KEY = 'wingspline:theme';
const themes = ['system', 'light', 'dark'];

function stored(key) {
  try { return window.localStorage.getItem(key); } catch { return null; }
}
function store(key, value) {
  try { window.localStorage.setItem(key, value); } catch { /* storage disabled */ }
}

export function applyStoredTheme() {
  // Re-applies what was read; writes nothing (an embed must not save a preference).
  const theme = stored(THEME_KEY);
  setTheme(themes.includes(theme) ? theme : 'system', { remember: false });
}

export function currentTheme() {
  return document.documentElement.dataset.theme ?? 'system';
}

// `remember: false` (an embed's theme= parameter, docs/embed.md): shown, not saved as the
// person's preference.
export function setTheme(theme, { remember = true } = {}) {
  if (theme === 'system') delete document.documentElement.dataset.theme;
  else document.documentElement.dataset.theme = theme;
  if (remember) store(THEME_KEY, theme);
}

export function cycleTheme() {
  const next = themes[(themes.indexOf(currentTheme()) + 1) % themes.length];
  setTheme(next);
  return next;
}

export function isPresenting() {
  return document.documentElement.hasAttribute('data-present');
}

// Large type and high contrast only, without full screen (an embed's present=1: a frame
// in a slide cannot take the screen without a gesture, and need not).
export function showPresenting(on) {
  if (on) document.documentElement.setAttribute('data-present', '');
  else document.documentElement.removeAttribute('data-present');
}

export async function setPresenting(on) {
  showPresenting(on);
  try {
    if (on && !document.fullscreenElement) await document.documentElement.requestFullscreen?.();
    if (!on && document.fullscreenElement) await document.exitFullscreen?.();
  } catch {
    // Full screen needs a user gesture and may be refused; the large-type mode still applies.
  }
}

// Colours for drawing, read from the CSS custom properties of the current theme.
export function drawingColors() {
  const css = getComputedStyle(document.documentElement);
  const v = (name) => css.getPropertyValue(name).trim();
  return {
    background: v('--canvas-bg') || v('--panel'),
    ink: v('--ink'),
    muted: v('--muted'),
    grid: v('--grid') || v('--line'),
    accent: v('--accent'),
    highlight: v('--focus'),
    series: [0, 1, 2, 3, 4, 5, 6, 7].map((i) => v(`--c${i}`)),
  };
}
