"""End to end: a lab in JupyterLab, driven by headless Debian chromium through playwright.

Starts JupyterLab on 127.0.0.1 with a token, opens lab 1, runs all cells, moves a slider of
the first live explorer and checks that both the picture and the balance report changed.
Screenshots before and after are saved under ``_build/lab_browser/``.
"""
import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SHOTS = ROOT / "_build" / "lab_browser"
LAB = ROOT / "labs" / "solutions" / "lab1_counterweights.ipynb"
CHROMIUM = shutil.which("chromium")

pytestmark = [
    pytest.mark.slow,
    pytest.mark.browser,
    pytest.mark.skipif(CHROMIUM is None, reason="Debian chromium is not installed (the setup script "
                                                "installs it with apt: apt-get install chromium)"),
]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def jupyterlab(tmp_path_factory):
    work = tmp_path_factory.mktemp("jlab")
    shutil.copy(LAB, work / "lab1.ipynb")
    port, token = _free_port(), secrets.token_hex(16)
    env = {**os.environ, "JUPYTER_CONFIG_DIR": str(work / ".config"),
           "JUPYTER_RUNTIME_DIR": str(work / ".runtime"), "JUPYTERLAB_WORKSPACES_DIR": str(work / ".ws")}
    cmd = [sys.executable, "-m", "jupyter", "lab", "--no-browser", "--ServerApp.ip=127.0.0.1",
           "--ServerApp.allow_root=True", "--LabApp.extension_manager=readonly",
           f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
           f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={work}",
           "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
           f"--LabApp.user_settings_dir={work / '.settings'}",
           f"--LabApp.workspaces_dir={work / '.ws'}"]
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


def _accept_dialogs(page) -> bool:
    """Accept every dialog JupyterLab shows (e.g. "Select Kernel"); True if there was one."""
    seen = False
    for _ in range(10):
        button = page.locator(".jp-Dialog .jp-mod-accept")
        if not (button.count() and button.first.is_visible()):
            break
        button.first.click()
        seen = True
        page.wait_for_timeout(500)
    return seen


def _run_all(page) -> None:
    """Run > Run All Cells."""
    _accept_dialogs(page)
    page.locator(".lm-MenuBar-itemLabel", has_text="Run").first.click()
    page.locator(".lm-Menu-itemLabel", has_text="Run All Cells").first.click()


def _wait_through_kernel_dialog(page, locator, timeout_s: float) -> None:
    """Wait for ``locator`` while making sure the notebook's cells really run.

    JupyterLab sometimes asks which kernel to start even when the notebook names an
    installed one, and cells queued while the kernel's session is still being set up can
    be dropped. So: accept the "Select Kernel" dialog (its default is the notebook's own
    kernel), and whenever the kernel sits idle with no explorer on the page, run all the
    cells again.
    """
    idle = ".jp-Notebook-ExecutionIndicator[data-status='idle']"
    deadline = time.monotonic() + timeout_s
    last_run = time.monotonic()
    while time.monotonic() < deadline:
        if _accept_dialogs(page):
            page.wait_for_selector(idle, timeout=60_000)
            _run_all(page)
            last_run = time.monotonic()
        try:
            locator.wait_for(timeout=2_000)
            return
        except Exception:
            pass
        if time.monotonic() - last_run > 20 and page.locator(idle).count():
            _run_all(page)
            last_run = time.monotonic()
    page.screenshot(path=str(SHOTS / "failure.png"), full_page=True)
    pytest.fail(f"the explorer did not appear within {timeout_s:.0f} s; see {SHOTS / 'failure.png'}")


def test_lab_explorer_reacts_to_a_slider(jupyterlab):
    from playwright.sync_api import sync_playwright

    url, token = jupyterlab
    SHOTS.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True,
                                     args=["--headless", "--no-sandbox", "--disable-gpu",
                                           "--disable-background-networking"])
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1000})
            page.goto(f"{url}/lab/tree/lab1.ipynb?token={token}")
            page.wait_for_selector(".jp-Notebook", timeout=60_000)
            page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='idle']", timeout=60_000)
            _run_all(page)
            explorer = page.locator(".widget-vbox").first
            _wait_through_kernel_dialog(page, explorer, timeout_s=180)
            image = explorer.locator("img").first
            image.wait_for(timeout=60_000)
            report = explorer.locator(".widget-html-content").first
            page.wait_for_function("el => el.textContent.includes('balanced')", arg=report.element_handle(),
                                   timeout=60_000)
            explorer.scroll_into_view_if_needed()
            page.wait_for_timeout(500)
            text_before = report.inner_text()
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
            page.wait_for_function("([el, old]) => el.textContent !== old",
                                   arg=[report.element_handle(), text_before], timeout=30_000)
            page.wait_for_function("([el, old]) => el.getAttribute('src') !== old",
                                   arg=[image.element_handle(), src_before], timeout=30_000)
            page.wait_for_timeout(500)
            text_after = report.inner_text()
            img_after = image.screenshot()
            page.screenshot(path=str(SHOTS / "after.png"))
        finally:
            browser.close()
    assert text_after != text_before
    assert "lamp arm" in text_before and "lamp arm" in text_after
    assert img_after != img_before
    assert (SHOTS / "before.png").stat().st_size > 10_000 and (SHOTS / "after.png").stat().st_size > 10_000
