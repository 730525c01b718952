// @ts-check
// A classic (non-module) script: it still runs from file://, where Chrome refuses module
// scripts, so the page can say how to serve the site instead of hanging at "loading".
(function () {
  if (window.location.protocol !== 'file:') return;
  document.documentElement.classList.add('from-file');
  function explain() {
    var box = document.getElementById('file-warning');
    if (box) box.hidden = false;
    var status = document.querySelector('[data-core-status]');
    if (status) status.textContent = 'Not loaded: this page was opened from a file.';
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', explain);
  else explain();
})();
