/*
 * Display formulas that fit the column (loaded on every page, see _config.yml).
 *
 * MathJax 3 cannot break a long line. A display formula wider than its column is set in a
 * smaller size, down to FLOOR of the text size (about 13 px on a phone), which is enough for the
 * formulas that are a little too wide; the chapters split the longer ones over several lines
 * themselves (tests/test_book.py checks that nothing is wider than the column at 390 px). Each
 * formula is measured again whenever its column changes width: a phone turned sideways, or a
 * solution opened (a hidden formula has no width until then).
 */
(function () {
  "use strict";

  var FLOOR = 0.8;

  function fit(e) {
    var box = e.parentElement ? e.parentElement.clientWidth : 0;
    if (!box) { return; }
    e.style.fontSize = "";
    var drawn = e.querySelector(":scope > mjx-math");   // not the hidden MathML beside it
    var need = drawn ? drawn.getBoundingClientRect().width : e.scrollWidth;
    if (need > box + 1) {
      e.style.fontSize = (100 * Math.max(FLOOR, (box - 2) / need)).toFixed(1) + "%";
    }
  }

  function start() {
    if (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) { return; }
    MathJax.startup.promise.then(function () {
      var shown = document.querySelectorAll('mjx-container[jax="CHTML"][display="true"]');
      if (!("ResizeObserver" in window)) { shown.forEach(fit); return; }
      var widths = new WeakMap();
      // only a change of width refits, and outside the observer's callback (no resize loop)
      var watch = new ResizeObserver(function (changes) {
        var changed = changes.filter(function (c) {
          var w = Math.round(c.contentRect.width);
          if (widths.get(c.target) === w) { return false; }
          widths.set(c.target, w);
          return true;
        });
        if (!changed.length) { return; }
        requestAnimationFrame(function () {
          changed.forEach(function (c) {
            c.target.querySelectorAll(':scope > mjx-container[jax="CHTML"][display="true"]').forEach(fit);
          });
        });
      });
      var parents = new Set();
      shown.forEach(function (e) { if (e.parentElement) { parents.add(e.parentElement); } });
      parents.forEach(function (p) { watch.observe(p); });
    });
  }

  if (document.readyState === "complete") { start(); } else { window.addEventListener("load", start); }
})();
