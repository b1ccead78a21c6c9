/*
 * Display formulas that fit the column (loaded on every page, see _config.yml).
 *
 * MathJax 3 cannot break a long line. A display formula wider than its column is set in a
 * smaller size, down to FLOOR of the text size (about 13 px on a phone), which is enough for the
 * formulas that are a little too wide; the chapters split the longer ones over several lines
 * themselves (tests/test_book.py checks that nothing is wider than the column at 390 px). The
 * size is set again when the window changes width (a phone turned sideways).
 */
(function () {
  "use strict";

  var FLOOR = 0.8;

  function fit() {
    var shown = document.querySelectorAll('mjx-container[jax="CHTML"][display="true"]');
    shown.forEach(function (e) { e.style.fontSize = ""; });
    shown.forEach(function (e) {
      var box = e.parentElement ? e.parentElement.clientWidth : 0;
      var drawn = e.querySelector(":scope > mjx-math");   // not the hidden MathML beside it
      var need = drawn ? drawn.getBoundingClientRect().width : e.scrollWidth;
      if (!box || need <= box + 1) { return; }
      var scale = Math.max(FLOOR, (box - 2) / need);
      e.style.fontSize = (100 * scale).toFixed(1) + "%";
    });
  }

  function start() {
    if (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) { return; }
    MathJax.startup.promise.then(function () {
      fit();
      var last = window.innerWidth;
      window.addEventListener("resize", function () {
        if (window.innerWidth !== last) { last = window.innerWidth; fit(); }
      });
    });
  }

  if (document.readyState === "complete") { start(); } else { window.addEventListener("load", start); }
})();
