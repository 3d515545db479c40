"""``hmi --serve`` (issue 26): one panel process per browser tab, each on a private copy of
the NC data, bounded in number. The server itself is textual-serve's; these tests check
what the project adds, without opening a port (no network in tests)."""

from __future__ import annotations

import shlex
import sys

import pytest

from hmi.app import main
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
