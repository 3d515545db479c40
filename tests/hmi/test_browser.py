"""The panel in a real browser (issue 26): ``hmi --serve`` driven by headless Chromium.

Chromium (Debian's ``chromium`` and ``chromium-driver``, installed by ``make`` when it
runs as root) opens the served page; the test reads what the browser's terminal
shows from the terminal's own screen buffer, presses keys as a trainee would, and
checks the server's side: one panel process and one private data directory per
browser tab, no more than ``--max-sessions`` of them, all gone when the tabs close.
Everything stays on this machine: the server listens on 127.0.0.1 and Chromium
resolves no other host name (the page asks for a web font, which falls back).
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from nck.paths import EPHEMERAL_PREFIX

webdriver = pytest.importorskip("selenium.webdriver", reason="selenium is not installed (make installs it)")
pytest.importorskip("textual_serve", reason="textual-serve is not installed (make installs it)")

from selenium.common.exceptions import TimeoutException  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

CHROMIUM = shutil.which("chromium")
CHROMEDRIVER = shutil.which("chromedriver")
pytestmark = pytest.mark.skipif(
    CHROMIUM is None or CHROMEDRIVER is None,
    reason="no Chromium here: the browser test needs Debian's chromium and chromium-driver "
           "(make installs them when it runs as root: apt-get install chromium chromium-driver)")

WAIT_S = 60.0
"""Longest wait for the page to show something (two busy cores start a panel in seconds)."""

MAX_SESSIONS = 2

# Before the page's own script runs: keep the terminal it makes (xterm.js) where the test
# can read its screen buffer — the text is drawn on a canvas, not into the page.
KEEP_TERMINAL = """
Object.defineProperty(Object.prototype, 'terminal', {configurable: true, set(value) {
  window.panelTerminal = value;
  Object.defineProperty(this, 'terminal', {value, writable: true, configurable: true, enumerable: true});
}});
"""

SCREEN_TEXT = """
const terminal = window.panelTerminal;
if (!terminal) return '';
const lines = [];
for (let row = 0; row < terminal.rows; row++) {
  const line = terminal.buffer.active.getLine(row);
  lines.push(line ? line.translateToString(true) : '');
}
return lines.join('\\n');
"""


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def wait_for_port(port: int, server: subprocess.Popen[bytes]) -> None:
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        assert server.poll() is None, "hmi --serve ended before it listened"
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
            return
        except OSError:
            time.sleep(0.05)
    pytest.fail(f"hmi --serve did not listen on port {port} within {WAIT_S} s")


def descendants(pid: int) -> list[int]:
    """The processes below ``pid`` (from /proc)."""
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                parent = int((entry / "stat").read_text().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(parent, []).append(int(entry.name))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def panel_processes(server_pid: int) -> list[int]:
    """The ``hmi`` panels the server runs (one per browser tab)."""
    panels = []
    for pid in descendants(server_pid):
        try:
            words = Path(f"/proc/{pid}/cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if b"hmi" in words and b"--ephemeral" in words and words[0] != b"/bin/sh":
            panels.append(pid)
    return panels


def private_copies(temp_dir: Path) -> list[Path]:
    return sorted(temp_dir.glob(f"{EPHEMERAL_PREFIX}*"))


@pytest.fixture
def served(tmp_path: Path) -> Iterator[tuple[str, int, Path]]:
    """``hmi --serve`` on a free port of 127.0.0.1: (url, server pid, its temporary directory)."""
    temp_dir = tmp_path / "server-tmp"
    temp_dir.mkdir()
    port = free_port()
    env = dict(os.environ, TMPDIR=str(temp_dir), NCK_DATA_DIR=str(tmp_path / "nc-data"))
    log = (tmp_path / "server.log").open("wb")
    server = subprocess.Popen(
        [sys.executable, "-m", "hmi", "--serve", "--port", str(port), "--max-sessions", str(MAX_SESSIONS)],
        env=env, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
    try:
        wait_for_port(port, server)
        yield f"http://127.0.0.1:{port}/", server.pid, temp_dir
    finally:
        server.send_signal(signal.SIGINT)
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        log.close()


@pytest.fixture
def browser(tmp_path: Path) -> Iterator[webdriver.Chrome]:
    """Headless Chromium on a profile of its own, reaching no host but this one."""
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--window-size=1400,1000", f"--user-data-dir={tmp_path / 'chromium-profile'}",
                     "--no-first-run", "--disable-background-networking", "--disable-component-update",
                     "--disable-sync", "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"):
        options.add_argument(argument)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)  # a driver path: no Selenium Manager
    try:
        yield driver
    finally:
        driver.quit()


def screen(driver: webdriver.Chrome) -> str:
    """The text the current tab's terminal shows."""
    return str(driver.execute_script(SCREEN_TEXT))


def wait_for(driver: webdriver.Chrome, what: str, shown: Callable[[str], bool]) -> str:
    """The tab's screen once ``shown(screen)`` holds; fails with the screen after WAIT_S."""
    try:
        WebDriverWait(driver, WAIT_S, poll_frequency=0.1).until(lambda d: shown(screen(d)))
    except TimeoutException:
        pytest.fail(f"the browser did not show {what} within {WAIT_S} s; it shows:\n{screen(driver)}")
    return screen(driver)


def wait_until(condition: Callable[[], bool], what: str, state: Callable[[], str] = str) -> None:
    deadline = time.monotonic() + WAIT_S
    while not condition():
        if time.monotonic() > deadline:
            pytest.fail(f"{what} did not happen within {WAIT_S} s: {state()}")
        time.sleep(0.05)


def header(text: str) -> str:
    return text.splitlines()[0] if text else ""


def open_panel(driver: webdriver.Chrome, url: str) -> str:
    """Load the page in the current tab and wait for the panel's JOG screen."""
    driver.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": KEEP_TERMINAL})  # per tab
    driver.get(url)
    text = wait_for(driver, "the JOG screen", lambda s: "MACHINE" in header(s) and "JOG" in header(s))
    driver.execute_script("window.panelTerminal.focus()")
    return text


CELL_GEOMETRY = """
const terminal = window.panelTerminal;
const box = terminal.element.querySelector('.xterm-screen').getBoundingClientRect();
return [box.width / terminal.cols, box.height / terminal.rows, box.width, box.height];
"""


def click_on(driver: webdriver.Chrome, word: str) -> None:
    """Click the middle of ``word`` where the terminal shows it last (lowest row)."""
    rows = screen(driver).splitlines()
    row = max(i for i, line in enumerate(rows) if f" {word} " in f" {line} ")
    column = f" {rows[row]} ".index(f" {word} ") + len(word) / 2
    cell_w, cell_h, width, height = driver.execute_script(CELL_GEOMETRY)
    terminal_screen = driver.find_element("css selector", ".xterm-screen")
    ActionChains(driver).move_to_element_with_offset(
        terminal_screen, int(column * cell_w - width / 2), int((row + 0.5) * cell_h - height / 2)).click().perform()


def alt(driver: webdriver.Chrome, *letters: str) -> None:
    """Alt+letter for each letter, one burst."""
    chain = ActionChains(driver)
    for letter in letters:
        chain.key_down(Keys.ALT).send_keys(letter).key_up(Keys.ALT)
    chain.perform()


def test_the_panel_in_a_browser(served: tuple[str, int, Path], browser: webdriver.Chrome,
                                tmp_path: Path) -> None:
    url, server_pid, temp_dir = served
    first_tab = browser.current_window_handle
    text = open_panel(browser, url)
    assert "Position [mm]" in text and "F1 Act. val. MCS" in text
    shot = tmp_path / "panel.png"
    assert browser.save_screenshot(str(shot))
    assert shot.read_bytes().startswith(b"\x89PNG") and shot.stat().st_size > 20_000  # not a blank page

    # REF POINT, then each axis + (keymap: Alt+R, Alt+X/Y/Z, Ctrl+Right), all in one burst
    chain = ActionChains(browser).key_down(Keys.ALT).send_keys("r").key_up(Keys.ALT)
    for axis in "xyz":
        chain.key_down(Keys.ALT).send_keys(axis).key_up(Keys.ALT)
        chain.key_down(Keys.CONTROL).send_keys(Keys.ARROW_RIGHT).key_up(Keys.CONTROL)
    chain.perform()
    wait_for(browser, "the axes referenced", lambda s: "○" not in s and "Position [mm]" in s)

    # MDA (Alt+D): a block typed in the browser, CYCLE START (Alt+G) — the axes move there
    alt(browser, "d")
    wait_for(browser, "the MDA screen", lambda s: "MDA" in header(s))
    ActionChains(browser).send_keys("G0 X12.5 Y-7").perform()
    alt(browser, "g")
    text = wait_for(browser, "the MDA move's end point",
                    lambda s: "12.500" in s and "-7.000" in s and "Channel reset" in header(s))
    assert "10203" not in text  # NC START was not refused

    # One panel process with one private copy of the NC data per tab
    assert len(panel_processes(server_pid)) == 1 and len(private_copies(temp_dir)) == 1

    # A second tab at the same time: a panel of its own, which works
    browser.switch_to.new_window("tab")
    second_tab = browser.current_window_handle
    second = open_panel(browser, url)
    assert "○" in second  # its own machine: nothing referenced, no MDA move
    click_on(browser, "MDA")  # the machine control panel's key under the softkeys
    wait_for(browser, "MDA in the second tab", lambda s: "MDA" in header(s))
    assert len(panel_processes(server_pid)) == 2 and len(private_copies(temp_dir)) == 2

    # A third tab is one more than --max-sessions 2: told so, no third panel
    browser.switch_to.new_window("tab")
    browser.execute_cdp_cmd("Page.addScriptToEvaluateOnNewDocument", {"source": KEEP_TERMINAL})
    browser.get(url)
    wait_for(browser, "the 'all panels in use' line", lambda s: f"All {MAX_SESSIONS} panels" in s)
    assert len(panel_processes(server_pid)) == 2
    browser.close()

    browser.switch_to.window(first_tab)
    text = wait_for(browser, "the first tab unchanged", lambda s: "12.500" in s and "MDA" in header(s))

    # Closing a tab ends its panel and removes its private copy
    browser.switch_to.window(second_tab)
    browser.close()
    browser.switch_to.window(first_tab)
    wait_until(lambda: len(panel_processes(server_pid)) == 1 and len(private_copies(temp_dir)) == 1,
               "the second tab's panel ending and its copy removed")
    browser.get("about:blank")
    wait_until(lambda: not panel_processes(server_pid) and not private_copies(temp_dir),
               "the last panel ending and its copy removed", lambda: f"{panel_processes(server_pid)} {private_copies(temp_dir)} {descendants(server_pid)}")
