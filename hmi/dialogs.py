"""Modal dialogs shared by the app and the areas: a choice list (program selection …), a value
input, a yes/no question. Their base class is :class:`hmi.dialog.AreaDialog`.

Each dialog returns its result with ``dismiss()``; F10 (MENU RECALL) closes
any dialog without a result.
"""

from __future__ import annotations

from typing import Sequence

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import Input, OptionList, Static
from textual.widgets.option_list import Option

from hmi.dialog import AreaDialog
from hmi.i18n import N_, _
from hmi.focus import focus_now
from hmi.widgets.fixed_size_input import FixedSizeInput


class ChoiceDialog(AreaDialog[str | None]):
    """Choose one entry of a list with the arrow keys and Enter (F10 cancels).

    With ``translate`` the entries are texts of the catalogue as the caller wrote them in
    English and are shown in the panel's language; without it they are shown as given (names,
    labels the caller has translated). The chosen one is returned as given. The title is shown
    as given (the caller translates it)."""

    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    def __init__(self, title: str, choices: Sequence[str], selected: str | None = None,
                 empty_text: str = N_("nothing to choose"), *, translate: bool = True) -> None:
        super().__init__(classes="choice-dialog")
        self._title = title
        self._choices = list(choices)
        self._selected = selected
        self._empty_text = empty_text
        self._translate = translate

    def compose(self) -> ComposeResult:
        """Title and list."""
        with Vertical(id="choice-box"):
            yield Static(self._title, id="choice-title")
            if self._choices:
                options = [Option(_(choice) if self._translate else choice, id=f"choice-{i}")
                           for i, choice in enumerate(self._choices)]
                yield OptionList(*options, id="choice-list")
            else:
                yield Static(_(self._empty_text), id="choice-empty")
            yield Static(_("↑/↓ choose   Enter confirm   F10 cancel"), id="choice-keys")

    def on_mount(self) -> None:
        """Put the cursor on the preselected entry."""
        if self._choices:
            lst = self.query_one(OptionList)
            if self._selected in self._choices:
                lst.highlighted = self._choices.index(self._selected)
            else:
                lst.highlighted = 0
            focus_now(lst)

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        """Enter on an entry: return it."""
        self.dismiss(self._choices[event.option_index])

    def action_cancel(self) -> None:
        """Close without a choice."""
        self.dismiss(None)


class ValueDialog(AreaDialog[str | None]):
    """Enter one value or a password: Enter confirms, F10 or Esc cancels; returns the text typed.

    ``hint`` is a line about the value (unit, limits, activation) above the field. A value
    is returned without surrounding blanks; a password exactly as typed. The value shown is
    selected, so that typing replaces it; ``typed`` is input already begun (a character typed
    on a table cell): the cursor stands behind it and the typing goes on.
    """

    DEFAULT_CSS = """
    #value-hint { height: auto; color: $secondary; }
    """
    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    def __init__(self, title: str, value: str = "", hint: str = "", password: bool = False,
                 typed: str = "") -> None:
        super().__init__(classes="value-dialog")
        self._title = title
        self._value = typed or value
        self._typed = bool(typed)
        self._hint = hint
        self._password = password

    def compose(self) -> ComposeResult:
        """Title, hint, input field, keys."""
        with Vertical(id="value-box"):
            yield Static(self._title, id="value-title", markup=False)
            if self._hint:
                yield Static(self._hint, id="value-hint", markup=False)
            yield FixedSizeInput(self._value, password=self._password, id="value-input",
                        select_on_focus=not self._typed)
            yield Static(_("Enter confirm   F10 / Esc cancel"), id="value-keys")

    def on_mount(self) -> None:
        """The field has the focus; no blinking cursor (stable screenshots)."""
        field = self.query_one(Input)
        field.cursor_blink = False
        focus_now(field)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter: return the text."""
        event.stop()
        self.dismiss(event.value if self._password else event.value.strip())

    def action_cancel(self) -> None:
        """Close without a value."""
        self.dismiss(None)


class ConfirmDialog(AreaDialog[bool]):
    """A yes/no question: ``Y`` or Enter confirms, ``N``, F10 or Esc cancels."""

    DEFAULT_CSS = """
    ConfirmDialog { align: center middle; }
    #confirm-box { width: 64; height: auto; background: $surface; border: thick $warning; padding: 0 1; }
    #confirm-keys { color: $secondary; }
    """
    BINDINGS = [
        Binding("y,enter", "answer(True)", "Yes", show=False),
        Binding("n,escape", "answer(False)", "No", show=False),
    ]

    def __init__(self, question: str) -> None:
        super().__init__(classes="confirm-dialog")
        self._question = question

    def compose(self) -> ComposeResult:
        """The question and the keys."""
        with Vertical(id="confirm-box"):
            yield Static(self._question, id="confirm-question", markup=False)
            yield Static(_("Y / Enter: yes     N / F10 / Esc: no"), id="confirm-keys")

    def action_answer(self, yes: bool) -> None:
        """Close with the answer."""
        self.dismiss(bool(yes))
