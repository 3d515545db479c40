"""An input window of the JOG screens (T,S,M, Set WO, Position, Settings): labelled fields.

A field is either a text field (:class:`textual.widgets.Input`) or a choice field
(:class:`ChoiceField`: the panel's toggle field, ←/→ or Space switch the value).
↑/↓ move between the fields, Enter goes to the next one. The keys of the keymap
(F keys, Alt and Ctrl keys) are app bindings with priority: they never reach a
field as text.
"""

from __future__ import annotations

from dataclasses import dataclass

from rich.text import Text
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widget import Widget
from textual.widgets import Input, Static

from hmi.i18n import _
from hmi.widgets.field_input import FIELD_KEYS, FieldInput


@dataclass(frozen=True)
class FieldSpec:
    """One field of a window: ``key`` names it, ``choices`` make it a choice field."""

    key: str
    label: str
    unit: str = ""
    choices: tuple[str, ...] = ()
    initial: str = ""


class FieldEdited(Message):
    """A field of a window changed (typed or chosen): the window may redraw what it derives."""


class ChoiceField(Static, can_focus=True):
    """A toggle field: one of ``choices``; ←/→ or Space choose the next or previous value."""

    BINDINGS = [
        Binding("right,space", "step(1)", "Next value", show=False),
        Binding("left", "step(-1)", "Previous value", show=False),
        *FIELD_KEYS,
    ]

    def __init__(self, choices: tuple[str, ...], initial: str = "", *, id: str) -> None:  # noqa: A002
        super().__init__("", id=id, classes="jog-choice", markup=False)
        self.choices = choices
        self.value = initial if initial in choices else choices[0]

    def on_mount(self) -> None:
        """Show the value."""
        self._show()

    def action_step(self, step: int) -> None:
        """Choose the next (+1) or previous (−1) value, round the list."""
        index = (self.choices.index(self.value) + step) % len(self.choices)
        self.value = self.choices[index]
        self._show()
        self.post_message(FieldEdited())

    def choose(self, value: str) -> None:
        """Set ``value`` (one of the choices)."""
        if value in self.choices:
            self.value = value
            self._show()

    def _show(self) -> None:
        # JogForm's CSS fixes the field at 24 × 1 cells: a new value cannot move anything, so
        # the field repaints without a layout of the whole screen (Static.update's default).
        self.update(Text(f"◂ {_(self.value)} ▸"), layout=False)


class JogForm(Vertical):
    """A titled window of labelled fields with a line of hints below.

    The title, the labels, the hint and the choices' values are English, as written in the
    code; the window shows them in the panel's language (the choices keep their English value).
    """

    DEFAULT_CSS = """
    JogForm { height: 1fr; background: $surface; }
    JogForm .jog-row { height: 1; }
    JogForm .jog-label { width: 32; padding: 0 1; }
    JogForm .jog-unit { width: 12; padding: 0 1; color: $secondary; }
    JogForm FieldInput { width: 24; height: 1; border: none; padding: 0 1; background: $panel; }
    JogForm FieldInput:focus { border: none; background: $boost; text-style: bold; }
    JogForm .jog-choice { width: 24; height: 1; padding: 0 1; background: $panel; }
    JogForm .jog-choice:focus { background: $boost; text-style: bold; }
    JogForm .jog-info { height: auto; padding: 0 1; }
    """

    def __init__(self, title: str, fields: tuple[FieldSpec, ...], hint: str, *, id: str) -> None:  # noqa: A002
        super().__init__(id=id)
        self.title = title
        self.fields = fields
        self.hint = hint
        self._built = False

    def build(self) -> None:
        """Mount the title, one row per field, the info line and the hint, the first time only.

        The window is composed empty: its rows are mounted when it is first used (shown,
        read or filled in), not when the Machine area starts. The area holds nine such
        windows with 39 fields, which were more than half of its widgets and ~45 % of the
        CPU of starting the panel (0.30 → 0.17 s per start and stop of the app, measured
        2026-11-28). The rows join the DOM at once, so the window's fields can be
        focused, read and set in the same key that opened it; the keys typed behind it
        wait in the field's queue until the field is mounted, in the order typed.
        """
        if self._built:
            return
        self._built = True
        rows = [Horizontal(classes="jog-row") for _spec in self.fields]
        self.mount_all([Static(f" {_(self.title)}", classes="view-title", markup=False), *rows,
                        Static("", classes="jog-info", id=f"{self.id}-info", markup=False),
                        Static(f" {_(self.hint)}", classes="jog-info", markup=False)])
        for row, spec in zip(rows, self.fields):
            if spec.choices:
                field: Widget = ChoiceField(spec.choices, spec.initial, id=self.field_id(spec.key))
            else:
                field = FieldInput(spec.initial, id=self.field_id(spec.key))
                field.cursor_blink = False
            # mounted into the row itself: children given to a container's constructor join
            # the DOM only when it composes, later than this key
            row.mount_all([Static(_(spec.label), classes="jog-label", markup=False), field,
                           Static(_(spec.unit), classes="jog-unit", markup=False)])

    def field_id(self, key: str) -> str:
        """The widget id of field ``key``."""
        return f"{self.id}-{key}"

    def field(self, key: str) -> Widget:
        """The widget of field ``key`` (an Input or a ChoiceField)."""
        self.build()
        return self.query_one(f"#{self.field_id(key)}")

    def value(self, key: str) -> str:
        """The text or choice of field ``key``."""
        widget = self.field(key)
        if isinstance(widget, Input):
            return widget.value
        assert isinstance(widget, ChoiceField)
        return widget.value

    def set_value(self, key: str, value: str) -> None:
        """Put ``value`` into field ``key``."""
        widget = self.field(key)
        if isinstance(widget, Input):
            widget.value = value
        elif isinstance(widget, ChoiceField):
            widget.choose(value)

    def show_info(self, content: Text | str) -> None:
        """The line under the fields (current values, what will happen)."""
        self.build()
        info = self.query_one(f"#{self.id}-info", Static)
        if getattr(info, "_shown_content", None) != content:
            info._shown_content = content  # type: ignore[attr-defined]
            info.update(content)

    def focus_first(self) -> None:
        """Put the focus on the first field unless a field of this window has it."""
        focused = self.screen.focused
        if focused is None or self not in focused.ancestors:
            self.screen.set_focus(self.field(self.fields[0].key))  # at once: the next key of a burst goes there

    def on_input_changed(self, event: Input.Changed) -> None:
        """Typing in a field: tell the screen (a preview may depend on it)."""
        event.stop()
        self.post_message(FieldEdited())

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter in a field goes to the next field."""
        event.stop()
        self.screen.focus_next()
