// @ts-check
// A guide page (dist/guide/*.html, built from docs/ by scripts/lib/guides.mjs): the reader's
// theme, and the offline copy of the site installed from here too (a teacher's first visit
// may be a guide linked from a course page).
import { registerServiceWorker } from '../app/sw-register.js';
import { applyStoredTheme } from '../app/theme.js';

applyStoredTheme();
registerServiceWorker();
