/*
 * Small fixes of the themes' behaviour, on every page.
 *
 * 1. The theme button: pydata-sphinx-theme cycles light -> auto -> dark (or dark -> auto ->
 *    light); when "auto" resolves to the theme already shown, a click changes nothing visible.
 *    Before the theme's own handler runs, a mode that would look the same is skipped, so every
 *    click switches between light and dark.
 * 2. Search excerpts: Sphinx builds them from the text of the page's [role=main] element, which
 *    here also holds the launch and download buttons ("Binder", ".ipynb" ...), the print-only
 *    contents and the previous/next links; they are removed before the excerpt is taken, and the
 *    excerpt is taken around the searched word (see makeSearchSummary below).
 * 3. The title of a solution (a dropdown) opens it: sphinx-togglebutton handles a click on the
 *    title bar itself, but a click on the title's link ("Solution to Exercise 1.1") followed the
 *    link to the exercise and threw "ReferenceError: button is not defined" (togglebutton.js).
 *    A click anywhere in a toggle's title is turned into a click of its button.
 * 4. Search excerpts read as text: maths (\(\theta = 90°\)) becomes plain symbols, code is left out.
 */
(function () {
  "use strict";

  var media = window.matchMedia("(prefers-color-scheme: dark)");

  function resolve(mode) {
    return mode === "auto" ? (media.matches ? "dark" : "light") : mode;
  }

  document.addEventListener(
    "click",
    function (event) {
      if (!(event.target instanceof Element) || !event.target.closest(".theme-switch-button")) {
        return;
      }
      var loop = media.matches ? ["auto", "light", "dark"] : ["auto", "dark", "light"];
      var mode = localStorage.getItem("mode") || document.documentElement.dataset.defaultMode || "auto";
      var next = loop[(loop.indexOf(mode) + 1) % loop.length];
      if (resolve(next) === resolve(mode)) {
        localStorage.setItem("mode", next); // the theme's handler then moves one step further
      }
    },
    true
  );

  document.addEventListener(
    "click",
    function (event) {
      if (!(event.target instanceof Element)) {
        return;
      }
      var title = event.target.closest(".toggle .admonition-title, .dropdown .admonition-title");
      if (!title || event.target === title || event.target.closest(".toggle-button")) {
        return;
      }
      var button = title.querySelector(".toggle-button");
      if (!button) {
        return;
      }
      event.preventDefault();
      event.stopImmediatePropagation();
      button.click();
    },
    true
  );

  var GREEK = {alpha: "α", beta: "β", gamma: "γ", delta: "δ", epsilon: "ε", varepsilon: "ε", zeta: "ζ",
               eta: "η", theta: "θ", vartheta: "ϑ", kappa: "κ", lambda: "λ", mu: "μ", nu: "ν", xi: "ξ",
               pi: "π", rho: "ρ", sigma: "σ", tau: "τ", phi: "φ", varphi: "φ", chi: "χ", psi: "ψ",
               omega: "ω", Gamma: "Γ", Delta: "Δ", Theta: "Θ", Lambda: "Λ", Pi: "Π", Sigma: "Σ",
               Phi: "Φ", Psi: "Ψ", Omega: "Ω", ell: "ℓ", cdot: "·", times: "×", approx: "≈",
               le: "≤", leq: "≤", ge: "≥", geq: "≥", ne: "≠", neq: "≠", pm: "±", infty: "∞",
               partial: "∂", sum: "Σ", to: "→", rightarrow: "→", circ: "°", degree: "°"};

  // TeX as a reader would read it aloud on a plain line: \theta -> θ, \frac{a}{b} -> a/b
  function texToText(tex) {
    return tex
      .replace(/\\[()\[\]]/g, "")
      .replace(/\\frac\{([^{}]*)\}\{([^{}]*)\}/g, "($1)/($2)")
      .replace(/\\(?:mathrm|mathbf|text|operatorname|boldsymbol|mathit)\{([^{}]*)\}/g, "$1")
      .replace(/\\([A-Za-z]+)/g, function (m, name) { return GREEK[name] || (name.length > 1 ? "" : name); })
      .replace(/\\[,;:! ]/g, " ")
      .replace(/[{}]/g, "")
      .replace(/\$/g, "");
  }

  var CHROME = [".bd-header-article", ".header-article-items", ".prev-next-area", ".bd-footer-article", ".onlyprint",
                "#jb-print-docs-body", "h1",
                ".bd-sidebar-secondary", ".toggle-details__summary", ".anim-buttons", "script", "style",
                ".cell_input", "div.highlight", "pre", ".bl-figure", "div.animation"];

  function patchSearch() {
    if (typeof Search === "undefined" || typeof Search.htmlToText !== "function" || Search._blPatched) {
      return;
    }
    var original = Search.htmlToText;
    Search.htmlToText = function (htmlString, anchor) {
      var doc = new DOMParser().parseFromString(htmlString, "text/html");
      CHROME.forEach(function (query) {
        doc.querySelectorAll(query).forEach(function (el) { el.remove(); });
      });
      doc.querySelectorAll(".math").forEach(function (el) { el.textContent = texToText(el.textContent); });
      return original(doc.documentElement.outerHTML, anchor);
    };
    // Sphinx looks for the *stemmed* words ("pulley" -> "pullei") in the text and, finding none,
    // quotes the page's first 240 characters. Look for the longest prefix of each stem instead
    // and quote the text around it, with its whitespace collapsed.
    Search.makeSearchSummary = function (htmlText, keywords, anchor) {
      var text = Search.htmlToText(htmlText, anchor).replace(/\s+/g, " ").trim();
      if (text === "") {
        return null;
      }
      var lower = text.toLowerCase();
      var at = -1;
      Array.from(keywords).forEach(function (word) {
        for (var n = word.length; n >= Math.min(4, word.length) && at < 0; n--) {
          at = lower.indexOf(word.toLowerCase().slice(0, n));
        }
      });
      var start = Math.max((at < 0 ? 0 : at) - 100, 0);
      var summary = document.createElement("p");
      summary.classList.add("context");
      summary.textContent = (start > 0 ? "..." : "") + text.substr(start, 240).trim() +
        (start + 240 < text.length ? "..." : "");
      return summary;
    };
    Search._blPatched = true;
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", patchSearch);
  } else {
    patchSearch();
  }
})();
