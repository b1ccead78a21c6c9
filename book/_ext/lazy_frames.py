"""Animation frames loaded when the reader comes to the animation, not with the page.

An animation of the course (``balancelab.viz.player``) embeds every frame in the page as a PNG
data URI: 24 to 48 frames, 0.7 to 2 MB of a chapter's first visit. After the build, every
player's script keeps its first frame (what the page shows, and what the printed course prints)
and moves the others into ``_images/frames/<hash>.js``, one small script per animation, which a
loader adds to the page when the player comes within a screen of the window (or the reader
touches or focuses it). A frame that repeats an earlier one is stored once. A script tag rather
than ``fetch`` keeps the site working when opened from the disk (``file://``).

Layer: the book's build (Sphinx extension). Tested by tests/test_book.py (every animation
advances when played) and measured by benchmarks/bench_book.py (first-visit weight).
"""
from __future__ import annotations

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
  (function (id, src) {
    var asked = false;
    function fill() {
      var a = window["anim" + id], d = (window.blFrames || {})[id];
      if (!a || !d) { setTimeout(fill, 50); return; }
      d.index.forEach(function (k, i) { a.frames[i + 1].src = d.frames[k]; });
      // the picture of the frame shown now (not set_frame: the player's words stay as they are)
      document.getElementById(a.img_id).src = a.frames[a.current_frame].src;
    }
    function load() {
      if (asked) { return; }
      asked = true;
      var s = document.createElement("script");
      s.src = src;
      s.onload = fill;
      document.head.appendChild(s);
    }
    var img = document.getElementById("_anim_img" + id);
    var box = (img && img.closest("div.animation")) || img;
    if (!box || !("IntersectionObserver" in window)) { load(); return; }
    new IntersectionObserver(function (seen, watcher) {
      if (seen.some(function (e) { return e.isIntersecting; })) { watcher.disconnect(); load(); }
    }, {rootMargin: "100%% 0px"}).observe(box);
    ["pointerdown", "focusin", "keydown"].forEach(function (kind) { box.addEventListener(kind, load, true); });
  })(%(id)s, %(src)s);
"""


def _frames_script(anim_id: str, frames: list[str]) -> tuple[str, bytes]:
    """The file name and text of one animation's frames after the first (repeats stored once)."""
    unique, index = [], []
    for data in frames:
        if data not in unique:
            unique.append(data)
        index.append(unique.index(data))
    payload = json.dumps({"frames": unique, "index": index}, separators=(",", ":"))
    text = f"window.blFrames = window.blFrames || {{}};\nwindow.blFrames[{json.dumps(anim_id)}] = {payload};\n"
    name = hashlib.sha1(text.encode()).hexdigest()[:16] + ".js"
    return name, text.encode()


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
    >>> page = ('<script>(function() { var img_id = "_anim_imgAB"; var frames = new Array(3);\\n'
    ...         'frames[0] = "data:image/png;base64,AAA"\\nframes[1] = "data:image/png;base64,BBB"\\n'
    ...         'frames[2] = "data:image/png;base64,CCC"\\nframes[3] = "data:image/png;base64,BBB"\\n'
    ...         '})()</script>')
    >>> new, files = lazy_page(page, "../")
    >>> "BBB" in new, "AAA" in new, len(files)   # the first frame stays, the others move
    (False, True, 1)
    >>> b'"index":[0,1,0]' in next(iter(files.values()))   # BBB is stored once
    True
    """
    files: dict = {}

    def block(m: re.Match) -> str:
        text = m.group(0)
        frames = [(int(f.group("i")), f.group("data").replace("\\\n", "")) for f in FRAME.finditer(text)]
        if len(frames) < 2 or [i for i, _ in frames] != list(range(len(frames))):
            return text
        name, data = _frames_script(m.group("id"), [d for _, d in frames[1:]])
        files[name] = data
        first = True

        def keep_first(f: re.Match) -> str:
            nonlocal first
            out = f.group(0) if first else ""
            first = False
            return out

        text = FRAME.sub(keep_first, text)
        loader = LOADER % {"id": json.dumps(m.group("id")), "src": json.dumps(f"{prefix}{FOLDER}/{name}")}
        cut = text.rindex("})()")
        return text[:cut] + loader + text[cut:]

    return BLOCK.sub(block, html), files


def lazy_site(outdir) -> int:
    """Rewrite every page of a built site; return the number of animations changed."""
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
    return count


def _finished(app, exception) -> None:
    if exception is None and app.builder.format == "html":
        lazy_site(app.outdir)


def setup(app):
    app.connect("build-finished", _finished)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
