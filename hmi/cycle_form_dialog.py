"""The input form of a standard cycle in the program editor (as Operate's programGUIDE).

One row per parameter (name, field, unit, permitted range; a long form scrolls), the help line
of the parameter under the cursor and a small sketch of the geometry with that parameter
marked. An empty field is a parameter that is not programmed (the cycle's own default). ↑/↓ move
between the fields, Enter checks the field and goes to the next one; Enter on the last field
is OK: every field is checked and the dialog returns the call line. A refused value keeps the
cursor in its field and the reason stands in the form's message line. F10 / Esc cancel.
"""

from __future__ import annotations

import re

from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Input, Static

from hmi.cycle_forms import CycleForm, CycleParam
from hmi.dialog import AreaDialog
from hmi.focus import focus_now
from hmi.i18n import _, data_text
from hmi.widgets.field_input import FieldInput


class CycleFormDialog(AreaDialog[str | None]):
    """The form of ``form`` with the field texts ``texts``; returns the call (without the line's rest)."""

    DEFAULT_CSS = """
    CycleFormDialog { align: center middle; }
    #cycle-box { width: 110; height: auto; background: $surface; border: thick $primary; padding: 0 1; }
    #cycle-rows { height: auto; max-height: 20; scrollbar-size-vertical: 1; }
    #cycle-box .cycle-row { height: 1; }
    #cycle-box .cycle-name { width: 8; }
    #cycle-box FieldInput { width: 16; height: 1; border: none; padding: 0 1; background: $panel; }
    #cycle-box FieldInput:focus { border: none; background: $boost; text-style: bold; }
    #cycle-box .cycle-unit { width: 8; padding: 0 1; color: $secondary; }
    #cycle-box .cycle-range { width: 1fr; color: $secondary; }
    #cycle-help { height: 1; }
    #cycle-message { height: 1; color: $error; }
    #cycle-sketch { height: auto; color: $secondary; }
    #cycle-keys { color: $secondary; }
    """
    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    def __init__(self, form: CycleForm, texts: list[str], recompile: bool = False) -> None:
        super().__init__(classes="cycle-dialog")
        self.form = form
        self._texts = texts
        self._recompile = recompile
        self._fields: list[Input] = []

    def compose(self) -> ComposeResult:
        """Title, the parameter rows, help, message, sketch and keys."""
        verb = _("Recompile") if self._recompile else _("New")
        with Vertical(id="cycle-box"):
            title = data_text("cycle_form", self.form.cycle, "title", self.form.title)
            yield Static(f"{self.form.cycle} {title} ({verb})", id="cycle-title", markup=False)
            with VerticalScroll(id="cycle-rows"):
                for index, (param, text) in enumerate(zip(self.form.params, self._texts)):
                    with Horizontal(classes="cycle-row"):
                        yield Static(param.name, classes="cycle-name", markup=False)
                        field = FieldInput(text, id=f"cycle-field-{index}", select_on_focus=True)
                        field.cursor_blink = False
                        yield field
                        yield Static(param.unit, classes="cycle-unit", markup=False)
                        yield Static(param.range_text(), classes="cycle-range", markup=False)
            yield Static("", id="cycle-help", markup=False)
            yield Static("", id="cycle-message", markup=False)
            yield Static(self._sketch_text(), id="cycle-sketch", markup=False)
            yield Static(_("↑/↓ field   Enter next field / OK on the last   F10 / Esc cancel"), id="cycle-keys")

    def on_mount(self) -> None:
        """The cursor on the first field."""
        self._fields = list(self.query(FieldInput))
        focus_now(self._fields[0])
        self._show_param(0)

    def fields(self) -> list[Input]:
        """The fields in the order of the parameters (the form's rows never change)."""
        return self._fields

    def on_descendant_focus(self) -> None:
        """The cursor moved: help and sketch follow the parameter under it."""
        focused = self.focused
        if isinstance(focused, FieldInput) and focused in self.fields():
            self._show_param(self.fields().index(focused))

    def param_help(self, param: CycleParam) -> str:
        """The help line of ``param`` in the language shown now."""
        return data_text("cycle_param", f"{self.form.cycle}.{param.name}", "help", param.help)

    def _sketch_text(self) -> Text:
        """The form's sketch in the language shown now, nothing marked."""
        return Text(data_text("cycle_sketch", self.form.sketch_name, "text", self.form.sketch).strip("\n"))

    def _show_param(self, index: int) -> None:
        # The help and message lines are one row high and marking a name keeps the sketch's
        # shape, so these updates repaint the lines without laying out the whole form again.
        param = self.form.params[index]
        self.query_one("#cycle-help", Static).update(Text(f"{param.name}: {self.param_help(param)}"),
                                                     layout=False)
        sketch = self._sketch_text()
        sketch.highlight_regex(rf"(?<![A-Z0-9_]){re.escape(param.name)}(?![A-Z0-9_])", "reverse")
        self.query_one("#cycle-sketch", Static).update(sketch, layout=False)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter: check the field; next field, or OK on the last one."""
        event.stop()
        fields = self.fields()
        index = fields.index(event.input)
        if self._refuse(index):
            return
        if index + 1 < len(fields):
            focus_now(fields[index + 1])
            return
        for other in range(len(fields)):
            if self._refuse(other):
                return
        self.dismiss(self.form.call_line([f.value for f in fields]))

    def _refuse(self, index: int) -> bool:
        """Show why field ``index`` is refused and put the cursor there; False when it is good."""
        field = self.fields()[index]
        reason = self.form.params[index].refusal(field.value)
        self.query_one("#cycle-message", Static).update(Text(reason or ""), layout=False)
        if reason is not None:
            focus_now(field)
            return True
        return False

    def action_cancel(self) -> None:
        """Close without inserting."""
        self.dismiss(None)
