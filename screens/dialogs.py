"""Shared modal dialogs: key help (F11), a choice list (program selection …), a value input.

Each dialog returns its result with ``dismiss()``; F10 (MENU RECALL) closes
any dialog without a result.
"""

from __future__ import annotations

from typing import Sequence

from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.widgets import Input, OptionList, Static
from textual.widgets.option_list import Option

from hmi.dialog import AreaDialog
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
        self.query_one("#help-box").focus()

    def action_dismiss_help(self) -> None:
        """Close the overlay."""
        self.dismiss(None)


class ChoiceDialog(AreaDialog[str | None]):
    """Choose one entry of a list with the arrow keys and Enter (F10 cancels)."""

    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    def __init__(self, title: str, choices: Sequence[str], selected: str | None = None,
                 empty_text: str = "nothing to choose") -> None:
        super().__init__(classes="choice-dialog")
        self._title = title
        self._choices = list(choices)
        self._selected = selected
        self._empty_text = empty_text

    def compose(self) -> ComposeResult:
        """Title and list."""
        with Vertical(id="choice-box"):
            yield Static(self._title, id="choice-title")
            if self._choices:
                options = [Option(choice, id=f"choice-{i}") for i, choice in enumerate(self._choices)]
                yield OptionList(*options, id="choice-list")
            else:
                yield Static(self._empty_text, id="choice-empty")
            yield Static("↑/↓ choose   Enter confirm   F10 cancel", id="choice-keys")

    def on_mount(self) -> None:
        """Put the cursor on the preselected entry."""
        if self._choices:
            lst = self.query_one(OptionList)
            if self._selected in self._choices:
                lst.highlighted = self._choices.index(self._selected)
            else:
                lst.highlighted = 0
            lst.focus()

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        """Enter on an entry: return it."""
        self.dismiss(self._choices[event.option_index])

    def action_cancel(self) -> None:
        """Close without a choice."""
        self.dismiss(None)


class ValueDialog(AreaDialog[str | None]):
    """Enter one value (Enter confirms, F10 or Escape cancels); returns the text typed."""

    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    def __init__(self, title: str, initial: str = "", hint: str = "") -> None:
        super().__init__(classes="value-dialog")
        self._title = title
        self._initial = initial
        self._hint = hint

    def compose(self) -> ComposeResult:
        """Title, field and the key hint."""
        with Vertical(id="value-box"):
            yield Static(self._title, id="value-title")
            yield Input(self._initial, id="value-input")
            yield Static(self._hint or "Enter confirm   F10 cancel", id="value-keys")

    def on_mount(self) -> None:
        """The field has the focus, its text selected for overtyping."""
        field = self.query_one(Input)
        field.cursor_blink = False
        field.focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter: return the value."""
        self.dismiss(event.value.strip())

    def action_cancel(self) -> None:
        """Close without a value."""
        self.dismiss(None)
