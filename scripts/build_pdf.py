"""Print the built course into one PDF, offline, with Debian's Chromium (no TeX).

Usage::

    python scripts/build_pdf.py        # after scripts/build_book.py; writes _build/html/balancelab-course.pdf

Every page of ``_toc.yml`` is taken, in order, from the built site (``_build/html``): its
article, with its numbered equations and figures, MathJax rendered by the browser. The pages
are put one after the other on a single temporary page that uses the site's own style sheets
plus :data:`PRINT_CSS`; each chapter starts on a new sheet, the solutions of a chapter's
exercises are moved to a "Solutions" section at its end, animations show their first frame,
and nothing is cut at a page edge (a figure or formula wider than the text is scaled down, a
figure never breaks across sheets). Chromium's ``page.pdf()`` prints it. The check of what
was printed (:func:`layout_report`) is saved next to the PDF as ``balancelab-course.json``
(the tests read it).
"""
from __future__ import annotations

import functools
import http.server
import json
import re
import shutil
import sys
import threading
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
SITE = ROOT / "_build" / "html"
PDF_NAME = "balancelab-course.pdf"
REPORT_NAME = "balancelab-course.json"
TEMP_PAGE = "book/_print_course.html"

PRINT_CSS = """
@page { size: A4; margin: 16mm 14mm 18mm 14mm; }
html, body { background: #fff !important; }
.bd-header, .bd-sidebar-primary, .bd-sidebar-secondary, .bd-header-article, .prev-next-area,
.bd-footer, .bd-footer-article, .bd-footer-content, .header-article-items, .anim-buttons,
.anim-controls, .anim-state, div.animation input, div.animation form, .toggle-button,
.copybtn, .headerlink, #pst-back-to-top, .search-button-field, .skip-link,
.onlyprint, .bl-launch { display: none !important; }
.bd-main .bd-content .bd-article-container { max-width: none !important; padding: 0 !important; }
.bd-page-width { max-width: none !important; }
section.bl-chapter { break-before: page; }
section.bl-chapter h1, .bl-title-page h1 { display: block !important; visibility: visible !important; }
section.bl-chapter:first-of-type { break-before: auto; }
img, figure, .bl-figure, div.animation, mjx-container[display="true"], table, pre,
.admonition-title, h1, h2, h3, h4 { break-inside: avoid; }
h1, h2, h3, h4, .admonition-title { break-after: avoid; }
.bl-figure { overflow: visible !important; flex-wrap: wrap; }
img { max-width: 100% !important; height: auto !important; min-width: 0 !important; }
.bl-figure img.bl-panel { min-width: 0 !important; flex: 0 1 auto !important; }
pre { white-space: pre-wrap !important; overflow-wrap: anywhere; overflow: visible !important; }
mjx-container[display="true"], span.math, div.math { overflow: visible !important; }
.toggle-hidden { display: block !important; visibility: visible !important; opacity: 1 !important; }
.bl-title-page { text-align: center; padding-top: 30%; break-after: page; }
/* no rounded corners or shadows on paper: Chromium prints each rounded or shadowed box with a
   soft mask, a 1 MP picture per box (5 MB for the course). :is() with an id outranks the theme's
   own !important rules (.admonition's shadow) */
:is(#bl-print, *) { border-radius: 0 !important; box-shadow: none !important; }
.bl-title-page h1 { font-size: 2.2rem; }
"""

PREPARE_JS = """
async () => {
  document.querySelectorAll(".toggle-hidden").forEach(e => e.classList.remove("toggle-hidden"));
  document.querySelectorAll("details").forEach(d => { d.open = true; });
  // each chapter's solutions go to a "Solutions" section at its end
  for (const chapter of document.querySelectorAll("section.bl-chapter")) {
    const sols = Array.from(chapter.querySelectorAll("div.solution"));
    if (!sols.length) continue;
    const part = document.createElement("section");
    part.className = "bl-solutions";
    const h = document.createElement("h2");
    h.textContent = "Solutions";
    part.appendChild(h);
    sols.forEach(s => part.appendChild(s));
    chapter.appendChild(part);
  }
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
    if (MathJax.typesetPromise) { await MathJax.typesetPromise(); }
  }
  await Promise.all(Array.from(document.images).map(i => i.complete ? null :
    new Promise(r => { i.onload = i.onerror = r; })));
}
"""

#: In print layout: what is wider than the text is scaled down to fit; then report what is still
#: cut, how many images there are, and the chapters' titles.
FIT_AND_REPORT_JS = """
() => {
  const main = document.querySelector("main") || document.body;
  const width = main.getBoundingClientRect().width;
  const left = main.getBoundingClientRect().left, right = left + width;
  // a heading stays on one line (scaled down when long): Chromium drops the space at a line
  // break from the heading's bookmark ("andcounterweights")
  for (const h of document.querySelectorAll('h1, h2, h3, h4')) {
    h.style.whiteSpace = "nowrap";
    const w = h.getBoundingClientRect().width;
    if (h.scrollWidth > w) { h.style.zoom = (w / h.scrollWidth).toFixed(3); }
  }
  for (const e of document.querySelectorAll('mjx-container, table')) {
    const r = e.getBoundingClientRect(), w = Math.max(e.scrollWidth, r.width);
    if (r.left + w > right) { e.style.zoom = ((right - r.left) / w).toFixed(3); }
  }
  const cut = [];
  for (const e of document.querySelectorAll('img, mjx-container, pre, table')) {
    const r = e.getBoundingClientRect();
    if (!r.width) continue;
    if (r.left < left - 1 || r.right > right + 1) {
      cut.push((e.alt || e.textContent || e.tagName).slice(0, 60) + ` (${Math.round(r.left)}..${Math.round(r.right)} of ${Math.round(left)}..${Math.round(right)})`);
    }
  }
  const chapters = Array.from(document.querySelectorAll("section.bl-chapter")).map(s => {
    const h = s.querySelector("h1");
    return {page: s.dataset.page, title: h ? h.textContent.replace(/#$/, "").trim() : "",
            images: s.querySelectorAll("img").length,
            solutions: s.querySelectorAll(".bl-solutions div.solution").length};
  });
  return {cut, chapters, images: document.images.length, width};
}
"""


def toc_pages() -> list[str]:
    """The pages of ``_toc.yml`` in reading order (``book/intro`` ...)."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    pages = [toc["root"]]
    for part in toc.get("parts", []):
        pages += [c["file"] for c in part.get("chapters", [])]
    return pages


def _article(html: str) -> str:
    start = html.index('<article class="bd-article"')
    start = html.index(">", start) + 1
    return html[start:html.rindex("</article>")]


def combined_page(site: Path = SITE) -> str:
    """One HTML page holding every chapter's article, with the site's head and the print CSS."""
    first = (site / "book" / "intro.html").read_text(encoding="utf-8")
    head = first[:first.index("</head>")]
    head = re.sub(r"<title>.*?</title>", "<title>Static balancing of linkages (printable course)</title>", head,
                  flags=re.S)
    body = ['<div class="bl-title-page"><h1>Static balancing of linkages</h1>'
            '<p>The balancelab course: chapters, figures, exercises and their solutions.</p>'
            f'<p>Printed {time.strftime("%Y-%m-%d")}</p></div>']
    for page in toc_pages():
        name = page.split("/")[-1]
        html = (site / "book" / f"{name}.html").read_text(encoding="utf-8")
        body.append(f'<section class="bl-chapter" data-page="{name}">{_article(html)}</section>')
    return (head + f"<style>{PRINT_CSS}</style></head>\n<body><main class=\"bd-main\"><div class=\"bd-content\">"
            "<div class=\"bd-article-container\"><article class=\"bd-article\">" + "\n".join(body)
            + "</article></div></div></main></body></html>")


def _indexed(rgb):
    """``(palette bytes, index bytes)`` of an RGB pixel array of at most 256 colours, else ``None``."""
    import numpy as np

    packed = (rgb[..., 0].astype(np.uint32) << 16) | (rgb[..., 1].astype(np.uint32) << 8) | rgb[..., 2]
    colours, index = np.unique(packed.ravel(), return_inverse=True)
    if len(colours) > 256:
        return None
    palette = np.stack([(colours >> 16) & 255, (colours >> 8) & 255, colours & 255], axis=1)
    return palette.astype(np.uint8).tobytes(), index.astype(np.uint8).tobytes()


def _shrink_image(xobj) -> bool:
    """Store one RGB image XObject of at most 256 colours as an indexed image (lossless)."""
    import zlib

    import numpy as np
    from pypdf.generic import ArrayObject, ByteStringObject, NameObject, NumberObject

    space = xobj.get("/ColorSpace")
    rgb = space == "/DeviceRGB" or (isinstance(space, list) and space[0] == "/ICCBased"
                                    and space[1].get_object().get("/N") == 3)
    if not rgb or xobj.get("/BitsPerComponent") != 8:
        return False
    w, h = int(xobj["/Width"]), int(xobj["/Height"])
    raw = xobj.get_data()
    if len(raw) != w * h * 3:
        return False
    found = _indexed(np.frombuffer(raw, np.uint8).reshape(h, w, 3))
    if found is None:
        return False
    palette, index = found
    data = zlib.compress(index, 9)
    if len(data) >= len(xobj._data):
        return False
    xobj._data = data
    xobj[NameObject("/Filter")] = NameObject("/FlateDecode")
    xobj.pop("/DecodeParms", None)
    xobj[NameObject("/ColorSpace")] = ArrayObject([NameObject("/Indexed"), space,
                                                   NumberObject(len(palette) // 3 - 1),
                                                   ByteStringObject(palette)])
    return True


_DOUBLED = re.compile(r"^(.*?)\1(.{4,})\2$", re.S)


def undouble(title: str) -> str:
    """A bookmark title Chromium wrote with each run of text twice, written once.

    Chromium's tagged outline sometimes repeats a heading's text runs ("SolutionsSolutions",
    "3.1. 3.1. Initial tensionInitial tension"); a title that is not so doubled is kept.

    >>> undouble("SolutionsSolutions"), undouble("3.1. 3.1. Initial tensionInitial tension")
    ('Solutions', '3.1. Initial tension')
    >>> undouble("3.2. A string over a pulley"), undouble("1.1. Why balance?")
    ('3.2. A string over a pulley', '1.1. Why balance?')
    """
    m = _DOUBLED.match(title)
    return m.group(1) + m.group(2) if m else title


def _undouble_outline(writer) -> None:
    """Write every bookmark title of ``writer`` once (see :func:`undouble`)."""
    from pypdf.generic import NameObject, TextStringObject

    outlines = writer._root_object.get("/Outlines")
    todo = [outlines.get_object().get("/First")] if outlines is not None else []
    while todo:
        node = todo.pop()
        while node is not None:
            node = node.get_object()
            title = node.get("/Title")
            if title is not None and undouble(str(title)) != str(title):
                node[NameObject("/Title")] = TextStringObject(undouble(str(title)))
            if node.get("/First") is not None:
                todo.append(node["/First"])
            node = node.get("/Next")


def shrink_pdf(path: Path) -> tuple[int, int]:
    """Rewrite a PDF printed by Chromium smaller; return its sizes (bytes) before and after.

    * Chromium stores every picture as deflated RGB pixels; the course's figures are palette
      PNGs of at most 256 colours, so each is stored back as an indexed image with the same
      pixels (lossless), and an alpha mask that hides nothing is dropped;
    * Chromium's structure tags (one element per line of text: 56,000 objects, a third of the
      file) are dropped: the PDF is for printing, the site is the accessible form of the course
      (book/accessibility.md); the bookmarks (the outline) stay;
    * identical objects (a picture or a font subset printed twice) are kept once.
    """
    import numpy as np
    from pypdf import PdfReader, PdfWriter
    from pypdf.generic import NameObject, StreamObject

    before = path.stat().st_size
    reader = PdfReader(str(path))
    writer = PdfWriter()
    writer.append(reader)   # the pages and the outline, not the structure tree
    _undouble_outline(writer)
    if reader.metadata:
        writer.add_metadata(reader.metadata)
    for obj in list(writer._objects):
        if not isinstance(obj, StreamObject) or obj.get("/Subtype") != "/Image":
            continue
        mask = obj.get("/SMask")
        if mask is not None and np.frombuffer(mask.get_object().get_data(), np.uint8).min(initial=255) == 255:
            del obj["/SMask"]
        _shrink_image(obj)
    for page in writer.pages:
        page.pop(NameObject("/StructParents"), None)
        for annot in page.get("/Annots", []):
            annot.get_object().pop(NameObject("/StructParent"), None)
    writer.compress_identical_objects()   # duplicates and orphans
    tmp = path.with_suffix(".tmp.pdf")
    with open(tmp, "wb") as f:
        writer.write(f)
    tmp.replace(path)
    return before, path.stat().st_size


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def build_pdf(site: Path = SITE) -> dict:
    """Print the course into ``site / PDF_NAME``; return the layout report (also saved as JSON).

    Raises
    ------
    SystemExit
        When Chromium or playwright is missing, or when something is cut at a page edge.
    """
    chromium = shutil.which("chromium")
    if chromium is None:
        raise SystemExit("the printable course needs Debian's chromium (bash scripts/setup_extras.sh)")
    from playwright.sync_api import sync_playwright

    t0 = time.perf_counter()
    temp = site / TEMP_PAGE
    temp.write_text(combined_page(site), encoding="utf-8")
    handler = functools.partial(_Quiet, directory=str(site))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium,
                                        args=["--headless", "--no-sandbox", "--disable-gpu"])
            page = browser.new_page(viewport={"width": 800, "height": 1100})
            page.set_default_timeout(180_000)
            page.route("**/*", lambda r: r.continue_() if r.request.url.startswith(
                ("data:", "blob:", "http://127.0.0.1")) else r.abort())
            page.goto(f"http://127.0.0.1:{httpd.server_address[1]}/{TEMP_PAGE}", wait_until="load")
            page.evaluate(PREPARE_JS)
            page.emulate_media(media="print")
            report = page.evaluate(FIT_AND_REPORT_JS)
            page.pdf(path=str(site / PDF_NAME), format="A4", print_background=True, prefer_css_page_size=True,
                     outline=True, tagged=True,
                     display_header_footer=True, header_template="<span></span>",
                     footer_template='<div style="font-size:8px;width:100%;text-align:center;">'
                                     '<span class="pageNumber"></span> / <span class="totalPages"></span></div>')
            browser.close()
    finally:
        httpd.shutdown()
        httpd.server_close()
        temp.unlink(missing_ok=True)
    report["printed_bytes"], report["bytes"] = shrink_pdf(site / PDF_NAME)
    report["seconds"] = round(time.perf_counter() - t0, 1)
    (site / REPORT_NAME).write_text(json.dumps(report, indent=1), encoding="utf-8")
    if report["cut"]:
        raise SystemExit("the printable course cuts content at the page edge:\n" + "\n".join(report["cut"][:20]))
    return report


def main() -> int:
    if not (SITE / "book" / "intro.html").is_file():
        raise SystemExit("build the site first: python scripts/build_book.py")
    r = build_pdf()
    print(f"printable course: {SITE / PDF_NAME} ({len(r['chapters'])} pages of the site, {r['images']} images, "
          f"{r['seconds']} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
