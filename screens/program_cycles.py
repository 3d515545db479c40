"""Cycle softkeys of the program editor: Drilling opens a cycle's input form.

A mixin of :class:`screens.program.ProgramScreen` (which provides ``editor``, ``say`` and the
app). With the cursor on a call of a cycle of the menu the softkey recompiles it: the form
opens with the line's values and OK replaces the call in that line (block number, MCALL and
comment stay). Otherwise a list of the menu's cycles comes first, and OK inserts the call as
a new line at the cursor's line (an empty line is filled instead).
"""

from __future__ import annotations

from typing import Any

from hmi.cycle_forms import CallLine, CycleForm, cycle_forms, forms_of_menu, read_call
from hmi.dialogs import ChoiceDialog
from hmi.cycle_form_dialog import CycleFormDialog


class CycleActions:
    """The Drilling softkey of the program editor (mixin)."""

    editor: Any
    app: Any
    say: Any

    def action_cycle_form(self, menu: str) -> None:
        """Drilling softkey: recompile the call under the cursor, else choose a new cycle."""
        row = self.editor.cursor_location[0]
        line = self.editor.document.get_line(row)
        found = read_call(line, menu)
        if isinstance(found, str):
            self.say(found)
            return
        if isinstance(found, CallLine):
            self._open_form(found.form, found.texts, row, found)
            return
        forms = forms_of_menu(menu)
        choices = [f"{form.cycle}  {form.title}" for form in forms]

        def chosen(choice: str | None) -> None:
            if choice is not None:
                form = cycle_forms()[choice.split()[0]]
                self._open_form(form, form.defaults(), row, None)

        self.app.push_screen(ChoiceDialog(f"{menu.capitalize()}: choose the cycle", choices), chosen)

    def _open_form(self, form: CycleForm, texts: list[str], row: int, old: CallLine | None) -> None:
        def confirmed(call: str | None) -> None:
            if call is None:
                return
            line = self.editor.document.get_line(row)
            if old is not None:
                self.editor.replace(old.with_call(call), (row, 0), (row, len(line)))
            elif not line.strip():
                self.editor.replace(call, (row, 0), (row, len(line)))
            else:
                self.editor.insert(call + "\n", (row, 0))
            self.editor.move_cursor((row, 0))
            self.say(f"{form.cycle} {'recompiled' if old else 'inserted'}")

        self.app.push_screen(CycleFormDialog(form, texts, recompile=old is not None), confirmed)
