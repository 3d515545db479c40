"""Cycle softkeys of the program editor (as Operate's programGUIDE): menus, forms, Recompile.

A mixin of :class:`screens.program.ProgramScreen` (which provides ``editor``, ``say``, the
softkey levels and the app). Vertical softkey ``Cycles / Recompile`` (Shift+F7):

* with the cursor on a call of a cycle that has a form, the form opens with the line's values
  and OK replaces the call in that line (block number, MCALL and comment stay);
* elsewhere it opens the cycle level: horizontal softkeys ``Drilling``, ``Milling``, ``Turning``
  (the lathe only) and ``<< Back``; vertical softkeys the chosen menu's keys
  (``data/cycles/cycles.toml`` ``[menus.*]``). A key of one cycle opens its form, a key of
  several shows them on a vertical sub-level, ``Modal call on / off`` puts ``MCALL`` in front
  of the drilling call on the cursor's line, takes it away, or inserts a lone ``MCALL`` (modal
  call off). OK inserts the call as a new line at the cursor's line (an empty line is filled).
"""

from __future__ import annotations

from typing import Any

from hmi.cycle_form_dialog import CycleFormDialog
from hmi.cycle_forms import (CallLine, CycleForm, CycleMenu, called_cycle, cycle_forms, cycle_menus,
                             is_modal_call_off, modal_call_toggled, read_call)
from hmi.i18n import _, data_text
from hmi.softkeys import Softkey, SoftkeyMenu

BACK_ID = "cycles.back"
"""The id of the ``<< Back`` softkey that every cycle level carries."""


def _writable(screen: Any) -> bool:
    return screen.program is not None and not screen.editor.read_only


class CycleActions:
    """The cycle softkeys of the program editor (mixin)."""

    editor: Any
    app: Any
    say: Any
    cycle_menu_id = ""
    """The menu whose keys the cycle level shows (``drilling`` …)."""

    def action_cycles(self) -> None:
        """Cycles / Recompile: reopen the call under the cursor, else show the cycle level."""
        row = self.editor.cursor_location[0]
        found = read_call(self.editor.document.get_line(row))
        if isinstance(found, str):
            self.say(found)
            return
        if isinstance(found, CallLine):
            self._open_form(found.form, found.texts, row, found)
            return
        self.action_cycle_menu(cycle_menus()[0].menu_id)

    def action_cycle_menu(self, menu_id: str) -> None:
        """A horizontal softkey of the cycle level: show that menu's keys."""
        menu = next(m for m in cycle_menus() if m.menu_id == menu_id)
        while self.current_menu().find(BACK_ID) is not None:  # type: ignore[attr-defined]
            self.pop_softkeys()  # type: ignore[attr-defined]
        self.cycle_menu_id = menu_id
        self.push_softkeys(self._cycle_level(menu))  # type: ignore[attr-defined]

    def action_cycle_group(self, menu_id: str, index: int) -> None:
        """A vertical key holding several cycles: show them on a vertical sub-level."""
        menu = next(m for m in cycle_menus() if m.menu_id == menu_id)
        forms = cycle_forms()
        vertical: list[Softkey | None] = [
            Softkey(f"cycle.{cycle}", data_text("cycle_form", cycle, "key", forms[cycle].key_label),
                    f"cycle_form('{cycle}')", enabled=_writable)
            for cycle in menu.keys[index].cycles
        ]
        vertical += [None] * (7 - len(vertical)) + [Softkey(BACK_ID, "<<\nBack", "pop_menu")]
        self.push_softkeys(SoftkeyMenu.of(self._cycle_bar(), vertical))  # type: ignore[attr-defined]

    def action_cycle_form(self, cycle: str) -> None:
        """A cycle's softkey: recompile its call under the cursor, else a new call."""
        row = self.editor.cursor_location[0]
        line = self.editor.document.get_line(row)
        form = cycle_forms()[cycle]
        if called_cycle(line) == cycle:
            found = read_call(line)
            if isinstance(found, str):
                self.say(found)
                return
            if isinstance(found, CallLine):
                self._open_form(form, found.texts, row, found)
                return
        self._open_form(form, form.defaults(), row, None)

    def action_modal_call(self) -> None:
        """Modal call on / off: MCALL before the drilling call on the cursor's line, or a lone MCALL."""
        row = self.editor.cursor_location[0]
        line = self.editor.document.get_line(row)
        toggled = modal_call_toggled(line)
        if toggled is not None:
            self.editor.replace(toggled, (row, 0), (row, len(line)))
            self.say(_("Modal call on") if len(toggled) > len(line) else _("Modal call off"))
        elif is_modal_call_off(line):
            self.say(_("MCALL: the modal call is switched off on this line already"))
            return
        else:
            self._put_line("MCALL", row)
            self.say(_("MCALL inserted: the modal call is off from here"))
        self.editor.move_cursor((row, 0))

    def _cycle_bar(self) -> list[Softkey | None]:
        """The horizontal softkeys of the cycle level: one per menu, ``<< Back`` on F8."""
        keys: list[Softkey | None] = [
            Softkey(f"cycles.{menu.menu_id}", data_text("cycle_menu", menu.menu_id, "label", menu.label),
                    f"cycle_menu('{menu.menu_id}')",
                    enabled=(lambda s: s.on_lathe) if menu.machine == "lathe" else None,
                    active=lambda s, menu_id=menu.menu_id: s.cycle_menu_id == menu_id)
            for menu in cycle_menus()
        ]
        return keys + [None] * (7 - len(keys)) + [Softkey(BACK_ID, "<<\nBack", "pop_menu")]

    def _cycle_level(self, menu: CycleMenu) -> SoftkeyMenu:
        vertical = []
        for index, key in enumerate(menu.keys):
            label = data_text("cycle_menu_key", f"{menu.menu_id}.{index}", "label", key.label)
            if key.mcall:
                vertical.append(Softkey("cycles.mcall", label, "modal_call", enabled=_writable))
            elif len(key.cycles) == 1:
                cycle = key.cycles[0]
                vertical.append(Softkey(f"cycle.{cycle}", label, f"cycle_form('{cycle}')", enabled=_writable))
            else:
                vertical.append(Softkey(f"cycles.{menu.menu_id}.{index}", label,
                                        f"cycle_group('{menu.menu_id}', {index})", enabled=_writable))
        return SoftkeyMenu.of(self._cycle_bar(), vertical)

    def _put_line(self, text: str, row: int) -> None:
        """Write ``text`` into the empty line ``row``, else insert it as a new line there."""
        line = self.editor.document.get_line(row)
        if not line.strip():
            self.editor.replace(text, (row, 0), (row, len(line)))
        else:
            self.editor.insert(text + "\n", (row, 0))

    def _open_form(self, form: CycleForm, texts: list[str], row: int, old: CallLine | None) -> None:
        def confirmed(call: str | None) -> None:
            if call is None:
                return
            if old is not None:
                line = self.editor.document.get_line(row)
                self.editor.replace(old.with_call(call), (row, 0), (row, len(line)))
            else:
                self._put_line(call, row)
            self.editor.move_cursor((row, 0))
            self.say((_("{cycle} recompiled") if old else _("{cycle} inserted")).format(cycle=form.cycle))

        self.app.push_screen(CycleFormDialog(form, texts, recompile=old is not None), confirmed)
