/*
 * Keyboard access to content that scrolls sideways (WCAG 2.1.1; axe-core's
 * scrollable-region-focusable): a figure, an animation or a display formula wider than the
 * column can be scrolled only by a reader who can focus it. The theme does this for code
 * blocks and cell outputs; here the same for the course's figures (.bl-figure), animation
 * players and MathJax's formulas (an inline formula longer than a phone's line scrolls too).
 * Such a region gets tabindex=0 and a name that says it scrolls, while it is wider than its
 * box; it loses both when the window grows. Other formulas are not tab stops (MathJax's menu
 * option inTabOrder is off in _config.yml).
 * Loaded on every page by book/_ext/accessibility.py.
 */
(function () {
  "use strict";

  var SELECTOR = ".bl-figure, div.animation, mjx-container[display='true'], .math-wrapper, .bd-content span.math";
  var NAME = "scrollable content: use the arrow keys to see all of it";

  function update() {
    document.querySelectorAll(SELECTOR).forEach(function (el) {
      var style = getComputedStyle(el);
      // an axis scrolls only where its overflow is auto or scroll (a formula's overflow-y is
      // hidden: its glyphs may stick out by a pixel or two, which no one can scroll to)
      var scrolls = (/(auto|scroll)/.test(style.overflowX) && el.scrollWidth > el.clientWidth + 1) ||
        (/(auto|scroll)/.test(style.overflowY) && el.scrollHeight > el.clientHeight + 1);
      // MathJax gives every formula tabindex="-1" (kept out of the tab order, see _config.yml)
      var focusable = el.hasAttribute("tabindex") && el.getAttribute("tabindex") !== "-1";
      if (scrolls && !focusable) {
        el.dataset.blScrollFocus = el.getAttribute("tabindex") || "none";
        el.setAttribute("tabindex", "0");
        if (!el.hasAttribute("role")) {
          el.setAttribute("role", "group");
          el.setAttribute("aria-label", NAME);
          el.dataset.blScrollName = "1";
        }
      } else if (!scrolls && !el.hasAttribute("tabindex")) {
        // Chromium makes every scroll container a tab stop, even one whose glyphs stick out by a
        // pixel (overflow-y hidden): a silent stop on each inline formula. Not scrolling: none.
        el.setAttribute("tabindex", "-1");
      } else if (!scrolls && el.dataset.blScrollFocus) {
        if (el.dataset.blScrollFocus === "none") { el.removeAttribute("tabindex"); }
        else { el.setAttribute("tabindex", el.dataset.blScrollFocus); }
        delete el.dataset.blScrollFocus;
        if (el.dataset.blScrollName) {
          el.removeAttribute("role");
          el.removeAttribute("aria-label");
          delete el.dataset.blScrollName;
        }
      }
    });
  }

  var pending = null;
  function later() {
    if (pending) { clearTimeout(pending); }
    pending = setTimeout(function () { pending = null; update(); }, 150);
  }

  window.addEventListener("resize", later);
  window.addEventListener("load", update);
  if (document.readyState !== "loading") { update(); } else { document.addEventListener("DOMContentLoaded", update); }
  // MathJax typesets after load, and its web fonts arrive later still and change the formulas'
  // widths: look again whenever a region's size changes
  var watch = window.ResizeObserver ? new ResizeObserver(later) : null;
  function observe() {
    update();
    if (watch) {
      document.querySelectorAll(SELECTOR + ", mjx-container > mjx-math").forEach(function (el) { watch.observe(el); });
    }
    if (document.fonts && document.fonts.ready) { document.fonts.ready.then(later); }
  }
  var tries = 0;
  (function afterMath() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(observe);
    } else if (++tries < 50) {
      setTimeout(afterMath, 100);
    }
  })();
})();
