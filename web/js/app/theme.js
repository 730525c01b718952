// Theme (system, light, dark) and presentation mode, both remembered in local storage.
const THEME_KEY = 'wingspline:theme';
const themes = ['system', 'light', 'dark'];

function stored(key) {
  try { return window.localStorage.getItem(key); } catch { return null; }
}
function store(key, value) {
  try { window.localStorage.setItem(key, value); } catch { /* storage disabled */ }
}

export function applyStoredTheme() {
  const theme = stored(THEME_KEY);
  setTheme(themes.includes(theme) ? theme : 'system');
}

export function currentTheme() {
  return document.documentElement.dataset.theme ?? 'system';
}

export function setTheme(theme) {
  if (theme === 'system') delete document.documentElement.dataset.theme;
  else document.documentElement.dataset.theme = theme;
  store(THEME_KEY, theme);
}

export function cycleTheme() {
  const next = themes[(themes.indexOf(currentTheme()) + 1) % themes.length];
  setTheme(next);
  return next;
}

export function isPresenting() {
  return document.documentElement.hasAttribute('data-present');
}

export async function setPresenting(on) {
  if (on) document.documentElement.setAttribute('data-present', '');
  else document.documentElement.removeAttribute('data-present');
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
