"""Animation frames loaded when the reader comes to the animation, not with the page.

An animation of the course (``balancelab.viz.player``) embeds every frame in the page as a WebP
data URI: 24 to 48 frames, most of a chapter's first visit. After the build, every
player's script keeps its first frame (what the page shows, and what the printed course prints)
and writes the others as image files ``_images/frames/<hash>.webp`` (``.png`` for PNG frames;
binary: a quarter smaller than their base64 text), which a loader gives to the player when it
comes within a screen of the window (or the reader touches or focuses it). A frame that repeats another (in the same or in
another animation) is one file. Plain image addresses keep the site working when it is opened
from the disk (``file://``).

Layer: the book's build (Sphinx extension). Tested by tests/test_book.py (every animation's
picture changes when played) and measured by benchmarks/bench_book.py (first-visit weight).
"""
from __future__ import annotations

import base64
import hashlib
import json
import re
from pathlib import Path

#: One player's instantiation script (matplotlib's ``to_jshtml`` template).
BLOCK = re.compile(r'var img_id = "_anim_img(?P<id>\w+)";.*?\}\)\(\)', re.DOTALL)
#: One embedded frame: its index and its data URI (matplotlib splits it with backslash-newlines).
FRAME = re.compile(r'\s*frames\[(?P<i>\d+)\] = "(?P<data>data:image/[a-z]+;base64,[^"]*)";?')
FOLDER = "_images/frames"

LOADER = """
  for (var i = 1; i < frames.length; i++) { frames[i] = frames[0]; }
  (function (id, files) {
    var asked = false;
    function load() {
      if (asked) { return; }
      var a = window["anim" + id];
      if (!a) { setTimeout(load, 50); return; }
      asked = true;
      files.forEach(function (f, i) { a.frames[i + 1].src = f; });
      // the picture of the frame shown now (not set_frame: the player's words stay as they are)
      document.getElementById(a.img_id).src = a.frames[a.current_frame].src;
    }
    var img = document.getElementById("_anim_img" + id);
    var box = (img && img.closest("div.animation")) || img;
    if (!box || !("IntersectionObserver" in window)) { load(); return; }
    new IntersectionObserver(function (seen, watcher) {
      if (seen.some(function (e) { return e.isIntersecting; })) { watcher.disconnect(); load(); }
    }, {rootMargin: "100%% 0px"}).observe(box);
    ["pointerdown", "focusin", "keydown"].forEach(function (kind) { box.addEventListener(kind, load, true); });
  })(%(id)s, %(files)s);
"""


def _frame_file(data_uri: str) -> tuple[str, bytes]:
    """The file name (its content's hash, the extension of its image type) and the bytes of a
    frame's data URI."""
    head, data = data_uri.split(",", 1)
    kind = head[len("data:image/"):].split(";", 1)[0]
    image = base64.b64decode(data)
    return hashlib.sha1(image).hexdigest()[:16] + "." + kind, image


def lazy_page(html: str, prefix: str) -> tuple[str, dict]:
    """Rewrite a page's players; return the new page and the frame files {name: bytes}.

    Parameters
    ----------
    html : str
        The page.
    prefix : str
        Relative path from the page to the site's root ("../" for a page in ``book/``).

    Returns
    -------
    tuple of (str, dict)

    Examples
    --------
    >>> aaa, bbb, ccc = (base64.b64encode(t).decode() for t in (b"A", b"B", b"C"))
    >>> page = ('<script>(function() { var img_id = "_anim_imgAB"; var frames = new Array(4);\\n'
    ...         f'frames[0] = "data:image/png;base64,{aaa}"\\nframes[1] = "data:image/png;base64,{bbb}"\\n'
    ...         f'frames[2] = "data:image/png;base64,{ccc}"\\nframes[3] = "data:image/png;base64,{bbb}"\\n'
    ...         '})()</script>')
    >>> new, files = lazy_page(page, "../")
    >>> bbb in new, aaa in new, sorted(files.values())   # the first frame stays; B is one file
    (False, True, [b'B', b'C'])
    >>> new.count("../_images/frames/")   # the player's list of its frames 2 to 4
    3
    """
    files: dict = {}

    def block(m: re.Match) -> str:
        text = m.group(0)
        frames = [(int(f.group("i")), f.group("data").replace("\\\n", "")) for f in FRAME.finditer(text)]
        if len(frames) < 2 or [i for i, _ in frames] != list(range(len(frames))):
            return text
        names = []
        for _, data in frames[1:]:
            name, png = _frame_file(data)
            files[name] = png
            names.append(f"{prefix}{FOLDER}/{name}")
        first = True

        def keep_first(f: re.Match) -> str:
            nonlocal first
            out = f.group(0) if first else ""
            first = False
            return out

        text = FRAME.sub(keep_first, text)
        loader = LOADER % {"id": json.dumps(m.group("id")), "files": json.dumps(names)}
        cut = text.rindex("})()")
        return text[:cut] + loader + text[cut:]

    return BLOCK.sub(block, html), files


def lazy_site(outdir) -> int:
    """Rewrite every page of a built site; return the number of frame files written."""
    root = Path(outdir)
    count = 0
    for page in root.rglob("*.html"):
        if page.relative_to(root).parts[0] in ("vendor", "_static", "_sources"):
            continue
        html = page.read_text(encoding="utf-8")
        if "_anim_img" not in html:
            continue
        prefix = "../" * (len(page.relative_to(root).parts) - 1)
        new, files = lazy_page(html, prefix)
        if not files:
            continue
        folder = root / FOLDER
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in files.items():
            (folder / name).write_bytes(data)
        page.write_text(new, encoding="utf-8")
        count += len(files)
    _drop_unused(root)
    return count


def _drop_unused(root: Path) -> None:
    """Delete the frame files no page names (left by an earlier build in the same folder)."""
    folder = root / FOLDER
    if not folder.is_dir():
        return
    named = set()
    for page in root.rglob("*.html"):
        if page.relative_to(root).parts[0] not in ("vendor", "_static", "_sources"):
            named |= set(re.findall(FOLDER + r"/([0-9a-f]+\.[a-z]+)", page.read_text(encoding="utf-8", errors="replace")))
    for path in folder.iterdir():
        if path.name not in named:
            path.unlink()


def _finished(app, exception) -> None:
    if exception is None and app.builder.format == "html":
        lazy_site(app.outdir)


def setup(app):
    app.connect("build-finished", _finished)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
