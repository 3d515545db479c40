"""``hmi --serve`` (issue 26): one panel process per browser tab, each on a private copy of
the NC data, bounded in number. The server itself is textual-serve's; these tests check
what the project adds, without opening a port (no network in tests)."""

from __future__ import annotations

import importlib.util
import shlex
import sys

import pytest
import textual.constants
import textual.drivers.web_driver
from textual import events
from textual.app import App

from hmi.app import HmiApp, main
from nck.paths import default_data_dir
from hmi.browser_driver import PanelBrowserDriver
from hmi.serve import BUSY_TEXT, SessionSlots, make_server, panel_command


def test_each_browser_panel_runs_on_a_private_copy() -> None:
    words = shlex.split(panel_command("lathe2", "/srv/class data"))
    assert words == [sys.executable, "-m", "hmi", "--ephemeral", "--machine", "lathe2", "--data-dir", "/srv/class data"]
    assert shlex.split(panel_command()) == [sys.executable, "-m", "hmi", "--ephemeral"]


def test_sessions_are_bounded_and_given_back() -> None:
    slots = SessionSlots(2)
    assert slots.take() and slots.take()
    assert not slots.take()  # the third browser tab gets BUSY_TEXT
    slots.give_back()
    assert slots.take()
    with pytest.raises(ValueError):
        SessionSlots(0)
    assert "All 2 panels" in BUSY_TEXT.format(limit=2)


def test_server_serves_the_panel_command() -> None:
    pytest.importorskip("textual_serve", reason="textual-serve is not installed (make installs it)")
    server = make_server("127.0.0.1", 8123, 3)
    assert server.command == panel_command()
    assert server.slots.limit == 3 and (server.host, server.port) == ("127.0.0.1", 8123)


def test_bad_serve_options_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--serve", "--max-sessions", "0"]) == 2
    assert "--max-sessions needs 1 or more" in capsys.readouterr().err


class Packets:
    """textual-serve's stream to one panel: packets of type, length (4 bytes, big-endian), payload."""

    def __init__(self, *packets: tuple[bytes, bytes]) -> None:
        self.chunks = [kind + len(payload).to_bytes(4, "big") + payload for kind, payload in packets]
        self.closed = False

    def __iter__(self):
        return iter(self.chunks)

    def close(self) -> None:
        self.closed = True


class RecordingBrowserDriver(PanelBrowserDriver):
    def __init__(self, packets: Packets, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setattr(textual.drivers.web_driver, "InputReader", lambda: packets)  # not standard input
        super().__init__(App())
        self.messages: list[object] = []

    def process_message(self, message) -> None:
        self.messages.append(message)


def test_a_browser_tab_runs_on_the_panels_key_reader(monkeypatch: pytest.MonkeyPatch, fake_app: HmiApp) -> None:
    # textual-serve names Textual's web driver in TEXTUAL_DRIVER
    monkeypatch.setattr(textual.constants, "DRIVER", "textual.drivers.web_driver:WebDriver")
    assert fake_app.get_driver_class() is PanelBrowserDriver


async def test_alt_keys_from_a_browser_are_panel_keys_never_text(monkeypatch: pytest.MonkeyPatch) -> None:
    """The browser's terminal sends Alt+D as ESC d (keymap: Alt+D = MDA, Alt+G = CYCLE START);
    Textual's web driver would report a printable 'd'. Typed text stays text."""
    packets = Packets((b"D", b"\x1bd"), (b"D", b"G0"), (b"D", b"\x1bg\x1bg"), (b"M", b'{"type": "exit"}'),
                      (b"D", b"X"))
    driver = RecordingBrowserDriver(packets, monkeypatch)
    driver.run_input_thread()
    keys = [(m.key, m.character) for m in driver.messages if isinstance(m, events.Key)]
    assert keys == [("alt+d", None), ("G", "G"), ("0", "0"), ("alt+g", None), ("alt+g", None)]
    assert packets.closed  # "exit" ended the input: the X after it is not read


def test_serve_in_german_gives_each_panel_the_language(monkeypatch: pytest.MonkeyPatch) -> None:
    """``hmi --serve --lang de``: every browser tab's panel process starts with ``--lang de``."""
    import hmi.app

    started: list[tuple] = []

    def serve(*args) -> int:
        started.append(args)
        return 0

    monkeypatch.setattr(hmi.app, "serve", serve)
    assert main(["--serve", "--lang", "de"]) == 0
    lang, class_dir = started[0][-2:]
    assert lang == "de"
    assert class_dir == str(default_data_dir().absolute())  # packs go to the directory served
    words = shlex.split(panel_command(lang=lang))
    assert words[words.index("--lang") + 1] == "de" and "--ephemeral" in words
    if importlib.util.find_spec("textual_serve") is not None:
        assert make_server("127.0.0.1", 8123, 3, lang="de").command == panel_command(lang="de")
