"""F11 key help: the softkeys of the current level, the area's own keys and every key of the panel.

Everything listed is generated from the data the keys work by: the softkey menu on display,
the bindings in force on the area screen (its own and its focused widget's, e.g. the arrow
keys that select an alarm or move the editor's cursor) and the keymap (``data/keymap.toml``).
"""

from __future__ import annotations

from rich.table import Table
from rich.text import Text
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.screen import Screen
from textual.widgets import Static

from hmi.dialog import AreaDialog
from hmi.focus import focus_now
from hmi.i18n import N_, _, data_text
from hmi.keymap import Keymap, display_key
from hmi.softkeys import SoftkeyMenu, one_line

SCOPE_TITLES = {"op": N_("Operator panel"), "mcp": N_("Machine control panel"), "softkey": N_("Softkeys")}

AreaKey = tuple[str, str]
"""One line of an area's keys: the keys in panel notation and what they do."""


def area_keys(screen: Screen) -> list[AreaKey]:
    """The keys the screen and its focused widget bind themselves, one line per meaning, the
    meaning in the panel's language (the panel's own bindings and Textual's widgets'
    descriptions, :mod:`hmi.widget_keys`, are in the catalogue).

    The app's bindings (the keymap) are left out: the keymap's section lists them.
    """
    keys_by_meaning: dict[str, list[str]] = {}
    for key, active in screen.active_bindings.items():
        if isinstance(active.node, App) or not active.binding.description or not active.enabled:
            continue
        if "super" in key.split("+"):
            continue  # the Command key of a Mac keyboard: a terminal does not send it
        keys_by_meaning.setdefault(one_line(_(active.binding.description)), []).append(key)
    return [(", ".join(display_key(key) for key in keys), meaning) for meaning, keys in keys_by_meaning.items()]


def help_table(keymap: Keymap, menu: SoftkeyMenu, own_keys: list[AreaKey] | None = None,
               area_title: str = "") -> Table:
    """Return the table of the keys in force: softkeys of the current level, the area's own keys,
    then all keys of the keymap."""
    table = Table(expand=True, show_edge=False, box=None, padding=(0, 1))
    # wide enough for a key and its browser-safe alternative ("Ctrl+PgDn, Ctrl+Shift+Down")
    table.add_column(_("Key"), style="bold", width=26)
    table.add_column(_("Panel key"), width=18)
    table.add_column(_("Meaning"))
    for prefix, bar, fkey in (("h", menu.horizontal, "F"), ("v", menu.vertical, "Shift+F")):
        for index, softkey in enumerate(bar, start=1):
            if softkey is not None:
                table.add_row(f"{fkey}{index}", f"{prefix.upper()}SK{index}", one_line(_(softkey.label)))
    if own_keys:
        table.add_row("", "", "")
        heading = (_("Keys of {area}").format(area=area_title) if area_title else _("Keys of this area"))
        table.add_row("", "", Text(heading, style="bold underline"))
        for key, description in own_keys:
            table.add_row(key, "", description)
    for scope in ("op", "mcp"):
        table.add_row("", "", "")
        table.add_row("", "", Text(_(SCOPE_TITLES[scope]), style="bold underline"))
        for binding in keymap.bindings:
            if binding.scope == scope:
                table.add_row(binding.key_display, binding.panel, data_text("key", binding.id, "label", binding.label))
    return table


class HelpScreen(AreaDialog[None]):
    """F11: the keys in force (current softkeys and the whole panel)."""

    BINDINGS = [Binding("escape", "dismiss_help", "Close", show=False)]

    def __init__(self, keymap: Keymap, menu: SoftkeyMenu, own_keys: list[AreaKey] | None = None,
                 area_title: str = "") -> None:
        super().__init__(id="help")
        self._keymap = keymap
        self._menu = menu
        self._own_keys = own_keys or []
        self._area_title = area_title

    def compose(self) -> ComposeResult:
        """One scrollable table."""
        with VerticalScroll(id="help-box"):
            yield Static(_("HELP — keys in force   (F11 or F10 closes)"), id="help-title")
            yield Static(help_table(self._keymap, self._menu, self._own_keys, self._area_title),
                         id="help-table")

    def on_mount(self) -> None:
        """Focus the list so the arrow keys and PgUp/PgDn scroll it."""
        focus_now(self.query_one("#help-box"))

    def action_dismiss_help(self) -> None:
        """Close the overlay."""
        self.dismiss(None)
