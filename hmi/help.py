"""F11 key help: the softkeys of the current level and every key of the panel."""

from __future__ import annotations

from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.widgets import Static

from hmi.dialog import AreaDialog
from hmi.focus import focus_now
from hmi.keymap import Keymap
from hmi.softkeys import SoftkeyMenu

SCOPE_TITLES = {"op": "Operator panel", "mcp": "Machine control panel", "softkey": "Softkeys"}


def help_table(keymap: Keymap, menu: SoftkeyMenu) -> Table:
    """Return the table of the keys in force: softkeys of the current level, then all keys."""
    table = Table(expand=True, show_edge=False, box=None, padding=(0, 1))
    table.add_column("Key", style="bold", width=14)
    table.add_column("Panel key", width=18)
    table.add_column("Meaning")
    for prefix, bar, fkey in (("h", menu.horizontal, "F"), ("v", menu.vertical, "Shift+F")):
        for index, softkey in enumerate(bar, start=1):
            if softkey is not None:
                table.add_row(f"{fkey}{index}", f"{prefix.upper()}SK{index}",
                              softkey.label.replace("\n", " "))
    for scope in ("op", "mcp"):
        table.add_row("", "", "")
        table.add_row("", "", Text(SCOPE_TITLES[scope], style="bold underline"))
        for binding in keymap.bindings:
            if binding.scope == scope:
                table.add_row(binding.key_display, binding.panel, binding.label)
    return table


class HelpScreen(AreaDialog[None]):
    """F11: the keys in force (current softkeys and the whole panel)."""

    BINDINGS = [Binding("escape", "dismiss_help", "Close", show=False)]

    def __init__(self, keymap: Keymap, menu: SoftkeyMenu) -> None:
        super().__init__(id="help")
        self._keymap = keymap
        self._menu = menu

    def compose(self) -> ComposeResult:
        """One scrollable table."""
        with VerticalScroll(id="help-box"):
            yield Static("HELP — keys in force   (F11 or F10 closes)", id="help-title")
            yield Static(help_table(self._keymap, self._menu), id="help-table")

    def on_mount(self) -> None:
        """Focus the list so the arrow keys and PgUp/PgDn scroll it."""
        focus_now(self.query_one("#help-box"))

    def action_dismiss_help(self) -> None:
        """Close the overlay."""
        self.dismiss(None)
