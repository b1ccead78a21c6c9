/* balancelab course: let @jupyter-widgets/html-manager 1.0.x live beside MathJax 3.
 * The HTML manager typesets widget labels with MathJax 2's `MathJax.Hub.Queue(["Typeset", MathJax.Hub, el])`;
 * MathJax 3 has no `Hub`, so that call throws. This file maps it onto MathJax 3's `typesetPromise`. */
(function () {
  "use strict";
  function install() {
    var mj = window.MathJax;
    if (!mj || typeof mj !== "object" || mj.Hub) {
      return;
    }
    mj.Hub = {
      Queue: function () {
        var job = arguments[0];
        var el = Array.isArray(job) ? job[2] : undefined;
        var m = window.MathJax;
        if (m && typeof m.typesetPromise === "function") {
          m.typesetPromise(el ? [el] : undefined).catch(function () { /* nothing to typeset */ });
        }
      }
    };
  }
  install();
  document.addEventListener("DOMContentLoaded", install);
  window.addEventListener("load", install);
})();
