/*
 * Two small fixes of the themes' behaviour, on every page.
 *
 * 1. The theme button: pydata-sphinx-theme cycles light -> auto -> dark (or dark -> auto ->
 *    light); when "auto" resolves to the theme already shown, a click changes nothing visible.
 *    Before the theme's own handler runs, a mode that would look the same is skipped, so every
 *    click switches between light and dark.
 * 2. Search excerpts: Sphinx builds them from the text of the page's [role=main] element, which
 *    here also holds the launch and download buttons ("Binder", ".ipynb" ...), the print-only
 *    contents and the previous/next links; they are removed before the excerpt is taken, and the
 *    excerpt is taken around the searched word (see makeSearchSummary below).
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

  var CHROME = [".bd-header-article", ".header-article-items", ".prev-next-area", ".bd-footer-article", ".onlyprint",
                "#jb-print-docs-body", "h1",
                ".bd-sidebar-secondary", ".toggle-details__summary", ".anim-buttons", "script", "style"];

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
