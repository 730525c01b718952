// The installed package's dist/ served as it is, imported by a plain module script.
import { loadWingspline } from './js/core/wingspline.js';
import { probe } from './probe.mjs';

probe(loadWingspline).then(
  (result) => { document.body.dataset.result = JSON.stringify(result); },
  (err) => { document.body.dataset.result = JSON.stringify({ error: `${err.code ?? ''} ${err.message}` }); },
);
