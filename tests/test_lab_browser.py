"""End to end: a lab in JupyterLab, driven by headless Debian chromium through playwright.

Starts JupyterLab on 127.0.0.1 with a token, opens lab 1, runs all cells, moves a slider of
the first live explorer and checks that both the picture and the balance report changed.
Screenshots before and after are saved under ``_build/lab_browser/``.
"""
import json
import os
import secrets
import shutil
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from conftest import CHROMIUM, CHROMIUM_ARGS, NEEDS_CHROMIUM, free_port

ROOT = Path(__file__).resolve().parent.parent
SHOTS = ROOT / "_build" / "lab_browser"
LAB = ROOT / "labs" / "solutions" / "lab1_counterweights.ipynb"

pytestmark = [
    pytest.mark.slow,
    pytest.mark.browser,
    NEEDS_CHROMIUM,
]


@pytest.fixture(scope="module")
def jupyterlab(tmp_path_factory):
    work = tmp_path_factory.mktemp("jlab")
    shutil.copy(LAB, work / "lab1.ipynb")
    port, token = free_port(), secrets.token_hex(16)
    env = {**os.environ, "JUPYTER_CONFIG_DIR": str(work / ".config"),
           "JUPYTER_RUNTIME_DIR": str(work / ".runtime"), "JUPYTERLAB_WORKSPACES_DIR": str(work / ".ws")}
    cmd = [sys.executable, "-m", "jupyter", "lab", "--no-browser", "--ServerApp.ip=127.0.0.1",
           "--ServerApp.allow_root=True", "--LabApp.extension_manager=readonly",
           f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
           f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={work}",
           "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
           f"--LabApp.user_settings_dir={work / '.settings'}", "--LabApp.expose_app_in_browser=True",
           f"--LabApp.workspaces_dir={work / '.ws'}"]
    # Start the notebook's own kernel without asking ("Select Kernel" otherwise appears at random
    # and cells queued meanwhile are dropped) and fetch no news: a test waits for conditions only.
    settings = work / ".settings"
    for plugin, values in (("notebook-extension/tracker", {"autoStartDefaultKernel": True}),
                           ("apputils-extension/notification", {"fetchNews": "false"})):
        path = settings / "@jupyterlab" / f"{plugin}.jupyterlab-settings"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values))
    log = open(work / "server.log", "w")
    proc = subprocess.Popen(cmd, cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}"
    try:
        for _ in range(120):
            try:
                with urllib.request.urlopen(f"{url}/api/status?token={token}", timeout=2) as r:
                    json.load(r)
                break
            except OSError:
                if proc.poll() is not None:
                    pytest.fail("JupyterLab exited: " + (work / "server.log").read_text()[-2000:])
                time.sleep(0.5)
        else:
            pytest.fail("JupyterLab did not answer within 60 s: " + (work / "server.log").read_text()[-2000:])
        yield url, token
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
        log.close()


def _fail_with_screenshot(page, what: str) -> None:
    page.screenshot(path=str(SHOTS / "failure.png"), full_page=True)
    pytest.fail(f"{what}; see {SHOTS / 'failure.png'}")


#: true once the open notebook is loaded and its kernel is connected and idle (JupyterLab's own state)
KERNEL_READY = """() => {
    const app = window.jupyterapp;
    const panel = app && app.shell.currentWidget;
    if (!panel || !panel.sessionContext || !panel.context || !panel.context.isReady) return false;
    const kernel = panel.sessionContext.session && panel.sessionContext.session.kernel;
    return panel.sessionContext.isReady && !!kernel && kernel.connectionStatus === "connected"
        && kernel.status === "idle";
}"""


#: true once every code cell of the open notebook has run and its kernel is idle again
ALL_CELLS_RUN = """() => {
    const app = window.jupyterapp;
    const panel = app && app.shell.currentWidget;
    const kernel = panel && panel.sessionContext.session && panel.sessionContext.session.kernel;
    if (!kernel || kernel.status !== "idle") return false;
    const cells = panel.content.widgets.filter(c => c.model.type === "code");
    return cells.length > 0 && cells.every(c => c.model.executionCount !== null);
}"""
#: the text of the first explorer's report, read afresh each time (widgets re-render it)
REPORT_TEXT = """() => {
    const el = document.querySelector(".widget-vbox .widget-html-content");
    return el ? el.textContent : "";
}"""
KERNEL_IDLE = """() => {
    const panel = window.jupyterapp.shell.currentWidget;
    const kernel = panel.sessionContext.session && panel.sessionContext.session.kernel;
    return !!kernel && kernel.status === "idle";
}"""


def _run_all_once(page) -> None:
    """Run every cell, exactly once, when the notebook's kernel is connected and idle."""
    page.wait_for_function(KERNEL_READY, timeout=120_000)
    if page.locator(".jp-Dialog").count():
        _fail_with_screenshot(page, "JupyterLab opened a dialog: " + page.locator(".jp-Dialog").inner_text())
    page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")


def test_lab_explorer_reacts_to_a_slider(jupyterlab):
    from playwright.sync_api import sync_playwright

    url, token = jupyterlab
    SHOTS.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1000})
            page.goto(f"{url}/lab/tree/lab1.ipynb?token={token}")
            page.wait_for_selector(".jp-Notebook", timeout=60_000)
            _run_all_once(page)
            explorer = page.locator(".widget-vbox").first
            try:
                page.wait_for_function(ALL_CELLS_RUN, timeout=180_000)
                image = explorer.locator("img").first
                image.wait_for(timeout=60_000)
                page.wait_for_function(f"() => ({REPORT_TEXT})().includes('lamp arm')", timeout=60_000)
            except Exception as err:  # noqa: BLE001 - any wait that times out is the failure
                _fail_with_screenshot(page, f"the notebook did not run to its explorer: {err}")
            explorer.scroll_into_view_if_needed()
            page.wait_for_function("img => img.complete && img.naturalWidth > 0", arg=image.element_handle(),
                                   timeout=30_000)
            text_before = page.wait_for_function(
                f"() => {{ const t = ({REPORT_TEXT})(); return t.includes('lamp arm') ? t : null; }}",
                timeout=30_000).json_value()
            img_before = image.screenshot()
            src_before = image.get_attribute("src")
            page.screenshot(path=str(SHOTS / "before.png"))

            # move the r_c slider (counterweight distance) with the keyboard: 8 steps of 5 mm
            sliders = explorer.locator(".widget-slider")
            labels = [sliders.nth(i).inner_text() for i in range(sliders.count())]
            idx = next(i for i, t in enumerate(labels) if t.strip().startswith("r_c"))
            handle = sliders.nth(idx).locator(".noUi-handle").first
            handle.click()
            for _ in range(8):
                handle.press("ArrowRight")
            page.wait_for_function(f"old => {{ const t = ({REPORT_TEXT})(); return t !== old && t.includes('lamp arm'); }}",
                                   arg=text_before, timeout=30_000)
            page.wait_for_function("([el, old]) => el.getAttribute('src') !== old",
                                   arg=[image.element_handle(), src_before], timeout=30_000)
            page.wait_for_function(KERNEL_IDLE, timeout=30_000)
            page.wait_for_function("img => img.complete && img.naturalWidth > 0", arg=image.element_handle(),
                                   timeout=30_000)
            text_after = page.wait_for_function(
                f"old => {{ const t = ({REPORT_TEXT})(); return t !== old && t.includes('lamp arm') ? t : null; }}",
                arg=text_before, timeout=30_000).json_value()
            img_after = image.screenshot()
            page.screenshot(path=str(SHOTS / "after.png"))
        finally:
            browser.close()
    assert text_after != text_before
    assert "lamp arm" in text_before and "lamp arm" in text_after
    assert img_after != img_before
    assert (SHOTS / "before.png").stat().st_size > 10_000 and (SHOTS / "after.png").stat().st_size > 10_000


#: the focused slider handle: its accessible name, description and spoken value (noUiSlider keeps
#: aria-valuenow at the first value and updates aria-valuetext, which screen readers read)
FOCUSED_HANDLE = """() => {
    const e = document.activeElement;
    if (!e || !e.classList.contains("noUi-handle")) return null;
    const d = document.getElementById(e.getAttribute("aria-describedby") || "");
    return {name: e.getAttribute("aria-label") || "", role: e.getAttribute("role"),
            description: d ? d.textContent : "", value: e.getAttribute("aria-valuetext")};
}"""
#: the first explorer's report, only if it is a polite live region (what a screen reader hears)
LIVE_REPORT = """() => {
    const el = document.querySelector(".bl-explorer [role=status][aria-live=polite]");
    return el ? el.textContent : null;
}"""


def test_lab_explorer_by_keyboard_alone(jupyterlab):
    """Tab from the explorer's cell to the r_c slider, move it with the arrow keys, hear the report."""
    from playwright.sync_api import sync_playwright

    url, token = jupyterlab
    SHOTS.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1000})
            page.goto(f"{url}/lab/tree/lab1.ipynb?token={token}")
            page.wait_for_selector(".jp-Notebook", timeout=60_000)
            _run_all_once(page)
            try:
                page.wait_for_function(ALL_CELLS_RUN, timeout=180_000)
                page.wait_for_function(f"() => ({LIVE_REPORT})() && ({LIVE_REPORT})().includes('lamp arm')",
                                       timeout=60_000)
                page.wait_for_function("() => document.querySelector('.bl-explorer .noUi-handle[aria-label]')",
                                       timeout=30_000)
            except Exception as err:  # noqa: BLE001 - any wait that times out is the failure
                _fail_with_screenshot(page, f"the explorer was not labelled for assistive technology: {err}")
            before = page.evaluate(LIVE_REPORT)
            # the keyboard starts on the explorer's cell (command mode, as after Shift+Enter)
            page.evaluate("""() => {
                const nb = window.jupyterapp.shell.currentWidget.content;
                const i = nb.widgets.findIndex(c => c.node.querySelector('.bl-explorer'));
                nb.activeCellIndex = i; nb.mode = 'command'; nb.activeCell.node.focus();
            }""")
            for _presses in range(1, 61):
                page.keyboard.press("Tab")
                handle = page.evaluate(FOCUSED_HANDLE)
                if handle and handle["name"] == "r_c":
                    break
            else:
                _fail_with_screenshot(page, "60 presses of Tab from the explorer's cell never reached the r_c slider")
            assert handle["role"] == "slider"
            assert "r_c" in handle["description"] and " to " in handle["description"], handle
            for _ in range(4):
                page.keyboard.press("ArrowRight")
            after = page.wait_for_function(
                f"old => {{ const t = ({LIVE_REPORT})(); return t && t !== old && t.includes('lamp arm') ? t : null; }}",
                arg=before, timeout=30_000).json_value()
            # the slider says its new value too, and keeps the focus
            moved = page.wait_for_function(
                f"old => {{ const h = ({FOCUSED_HANDLE})(); return h && h.value !== old ? h : null; }}",
                arg=handle["value"], timeout=30_000).json_value()
            page.screenshot(path=str(SHOTS / "keyboard.png"))
        finally:
            browser.close()
    assert moved is not None and moved["name"] == "r_c", "the focus left the slider"
    assert float(moved["value"]) > float(handle["value"])
    assert after != before and "lamp arm" in after
