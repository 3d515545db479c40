"""The panel in a browser for the classroom: ``hmi --serve`` (issue 26).

textual-serve (an optional extra, installed by ``make``) serves a page that runs one
``hmi`` process per browser connection, over a websocket. Each process works on its own
temporary copy of the NC data directory (``--ephemeral``): two trainees never share a
data directory (one directory cannot be worked on twice: it is locked), and the copy
is removed when the process ends — when the browser tab closes, textual-serve tells the
process to quit. The number of panels at once is bounded (:data:`DEFAULT_MAX_SESSIONS`,
``--max-sessions``): each is a simulated machine that computes all the time, and the
machine has few cores. A connection beyond the bound gets a line saying so and is closed.
Exercise reports are written outside the copies, into one folder for every tab
(``--reports-dir``, default ``exercise_reports`` of the data directory served). Class packs
imported in a tab go into the data directory served (``--class-dir``), not into the tab's
copy: every tab lists them the next time it shows its exercises.
"""

from __future__ import annotations

import shlex
import sys
from typing import Any

DEFAULT_MAX_SESSIONS = 4
DEFAULT_PORT = 8000


class SessionSlots:
    """At most ``limit`` sessions at once: :meth:`take` a slot (False: all taken), :meth:`give_back` it."""

    def __init__(self, limit: int) -> None:
        if limit < 1:
            raise ValueError("at least one session")
        self.limit = limit
        self.in_use = 0

    def take(self) -> bool:
        """Take a slot; False when every slot is in use."""
        if self.in_use >= self.limit:
            return False
        self.in_use += 1
        return True

    def give_back(self) -> None:
        """Return a slot taken before."""
        self.in_use = max(0, self.in_use - 1)


def panel_command(machine: str | None = None, data_dir: str | None = None, reports_dir: str | None = None,
                  lang: str | None = None, class_dir: str | None = None) -> str:
    """The shell command of one browser session's panel: this Python, ``-m hmi --ephemeral``
    (a private copy of ``data_dir``, or of the user's data directory), writing exercise
    reports into ``reports_dir`` and class packs into ``class_dir`` — outside the copy, which
    goes with the tab — and showing its texts in ``lang`` (None: the language kept in the
    copied data)."""
    words = [sys.executable, "-m", "hmi", "--ephemeral"]
    if lang:
        words += ["--lang", lang]
    if machine:
        words += ["--machine", machine]
    if data_dir:
        words += ["--data-dir", data_dir]
    if reports_dir:
        words += ["--reports-dir", reports_dir]
    if class_dir:
        words += ["--class-dir", class_dir]
    return shlex.join(words)


BUSY_TEXT = "All {limit} panels of this trainer are in use: close one, or try again later.\r\n"


def make_server(host: str, port: int, max_sessions: int, machine: str | None = None,
                data_dir: str | None = None, reports_dir: str | None = None, lang: str | None = None,
                class_dir: str | None = None) -> Any:
    """A textual-serve server of the panel, bounded to ``max_sessions`` at once.

    Raises ImportError when textual-serve is not installed.
    """
    from aiohttp import web
    from textual_serve.server import Server

    class PanelServer(Server):  # type: ignore[misc]
        """textual-serve's server, with a bound on the sessions at once."""

        slots = SessionSlots(max_sessions)

        async def handle_index(self, request: web.Request) -> web.StreamResponse:
            # Not kept in the browser's back/forward cache: a tab that leaves the page
            # must close its connection, so that its panel ends and gives its slot back.
            response: web.StreamResponse = await super().handle_index(request)
            response.headers["Cache-Control"] = "no-store"
            return response

        async def handle_websocket(self, request: web.Request) -> web.WebSocketResponse:
            if not self.slots.take():
                websocket = web.WebSocketResponse()
                await websocket.prepare(request)
                await websocket.send_bytes(BUSY_TEXT.format(limit=self.slots.limit).encode("utf-8"))
                await websocket.close()
                return websocket
            try:
                return await super().handle_websocket(request)
            finally:
                self.slots.give_back()

    return PanelServer(panel_command(machine, data_dir, reports_dir, lang, class_dir), host=host, port=port,
                       title="SINUMERIK Operate trainer")


def serve(host: str, port: int, max_sessions: int, machine: str | None = None,
          data_dir: str | None = None, reports_dir: str | None = None, lang: str | None = None,
          class_dir: str | None = None) -> int:
    """Serve the panel until Ctrl+C; return the exit code (2: textual-serve missing)."""
    try:
        server = make_server(host, port, max_sessions, machine, data_dir, reports_dir, lang, class_dir)
    except ImportError:
        print("hmi: --serve needs textual-serve (installed by make: pip install -e '.[serve]')",
              file=sys.stderr)
        return 2
    server.serve()
    return 0
