"""The HMI application (placeholder until the HMI shell lands)."""

from __future__ import annotations

from textual.app import App, ComposeResult
from textual.widgets import Static


class HmiApp(App):
    """SINUMERIK Operate trainer."""

    BINDINGS = [("ctrl+q", "quit", "Quit")]

    def compose(self) -> ComposeResult:
        """Show the start screen."""
        yield Static("SINUMERIK Operate trainer — starting")


def make_app() -> HmiApp:
    """Build the application (shared by the console script and the tests)."""
    return HmiApp()


def main() -> int:
    """Entry point of the ``hmi`` console script."""
    make_app().run()
    return 0
