/*
 * Make the visible sidebar buttons work at every width.
 *
 * pydata-sphinx-theme 0.17 renders a second pair of `.primary-toggle` /
 * `.secondary-toggle` buttons in its top navbar (#pst-header), which
 * sphinx-book-theme hides in favour of the buttons in the article header.
 * Both themes attach their handlers with `document.querySelector(...)`, that is
 * to the first, hidden, button only; the visible buttons do nothing, and below
 * 992 px the table of contents cannot be opened at all
 * (pydata-sphinx-theme#2451, sphinx-book-theme#935).
 *
 * Fix: a click on any other toggle is forwarded to the first toggle of its kind,
 * which carries the themes' behaviour (a drawer below 992 px, collapsing the
 * sidebar above). When a theme release binds every button, the first button is
 * the visible one and this listener does nothing.
 */
(function () {
  "use strict";
  var KINDS = ["primary-toggle", "secondary-toggle"];

  document.addEventListener(
    "click",
    function (event) {
      if (!(event.target instanceof Element)) {
        return;
      }
      KINDS.forEach(function (kind) {
        var button = event.target.closest("." + kind);
        var bound = document.querySelector("." + kind);
        if (!button || !bound || button === bound) {
          return;
        }
        // Capture phase on the document: runs before any listener on `button`.
        event.preventDefault();
        event.stopImmediatePropagation();
        button.blur(); // dismiss its tooltip, as the theme does for the bound button
        bound.click();
      });
    },
    true,
  );
})();
