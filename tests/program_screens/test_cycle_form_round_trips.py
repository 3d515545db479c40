"""Form → call line → Recompile → changed call line, for every cycle that has a form (issue 23,
done-when "pilot tests for form → call line → recompile round trips for every cycle").

Each cycle is reached as an operator reaches it: Shift+F7 Cycles, the menu's horizontal softkey
(F1 Drilling, F2 Milling, F3 Turning on the lathe), the cycle's vertical softkey (or its group's
softkey, then the cycle's on the sub-level). OK on the last field inserts the call with every
field as it stands; Shift+F7 on that line reopens the form with the line's values; one field
changed and OK replaces the call. The expected lines are written from the typed texts by the
rule of the call line (parameters in the form's order, separated by commas, trailing
unprogrammed parameters left out, a program name in quotes), not taken from the form's code.
"""

from __future__ import annotations

from decimal import Decimal
from pathlib import Path

import pytest

from hmi.cycle_form_dialog import CycleFormDialog
from hmi.cycle_forms import CycleForm, CycleParam, cycle_forms, cycle_menus
from tests.burst import burst
from tests.program_screens.conftest import SIZE, lathe_program_app, make_program_app


def _written(param: CycleParam, text: str) -> str:
    """How the call writes a field text: a name in capitals and quotes, a number without trailing zeros."""
    if param.kind == "name":
        return f'"{text.upper()}"'
    if not text:
        return ""
    digits = format(Decimal(text), "f")
    if "." in digits:
        digits = digits.rstrip("0").rstrip(".")
    return "0" if digits == "-0" else digits


def _expected_line(form: CycleForm, texts: list[str]) -> str:
    args = [_written(param, text) for param, text in zip(form.params, texts)]
    while args and not args[-1]:
        args.pop()
    return f"{form.cycle}({','.join(args)})"


def _changed_field(form: CycleForm) -> tuple[int, str]:
    """The first numeric field and a permitted value other than its default."""
    for index, param in enumerate(form.params):
        if param.kind == "name" or param.choices:
            continue
        for value in ("7", "3", "1", "0.5", "0.01"):
            if param.refusal(value) is None and _written(param, value) != _written(param, param.default):
                return index, value
    raise AssertionError(f"{form.cycle}: no field to change")


async def _round_trip(pilot, screen, form: CycleForm, menu_index: int, row: int) -> None:
    """From the editor's softkeys with the cursor on ``M30`` in ``row``: insert, recompile, change."""
    cycle = form.cycle
    menu = cycle_menus()[menu_index]
    await burst(pilot, "shift+f7", f"f{menu_index + 1}")  # Cycles, the menu
    await pilot.pause()
    key = screen.current_menu().find(f"cycle.{cycle}")
    if key is None:  # the cycle sits on a sub-level behind its group's key
        group = next(i for i, k in enumerate(menu.keys) if cycle in k.cycles)
        group_key = screen.current_menu().find(f"cycles.{menu.menu_id}.{group}")
        await burst(pilot, f"shift+f{group_key[1:]}")
        await pilot.pause()
        key = screen.current_menu().find(f"cycle.{cycle}")
    assert key is not None and key.startswith("v"), cycle
    await burst(pilot, f"shift+f{key[1:]}")
    await pilot.pause()
    dialog = pilot.app.screen
    assert isinstance(dialog, CycleFormDialog) and dialog.form.cycle == cycle
    texts = [field.value for field in dialog.fields()]
    assert texts == form.defaults(), cycle
    if form.params[0].kind == "name":  # a contour program's name must be given
        texts[0] = "shaft_contour"
        await burst(pilot, *"shaft_contour")
    await burst(pilot, *["enter"] * len(texts))  # every field as it stands, OK on the last
    await pilot.pause()
    assert pilot.app.screen is screen, cycle
    lines = screen.editor.text.splitlines()
    assert lines[row:] == [_expected_line(form, texts), "M30"], cycle

    while screen.current_menu().find("program.cycles") is None:
        await burst(pilot, "f8")  # << Back to the editor's softkeys
        await pilot.pause()
    await burst(pilot, "shift+f7")  # Recompile: the cursor stands on the call
    await pilot.pause()
    dialog = pilot.app.screen
    assert isinstance(dialog, CycleFormDialog) and dialog.form.cycle == cycle
    shown = [field.value for field in dialog.fields()]
    assert [_written(p, t) for p, t in zip(form.params, shown)] == [
        _written(p, t) for p, t in zip(form.params, texts)], cycle
    changed, value = _changed_field(form)
    await burst(pilot, *["down"] * changed, *value, *["enter"] * (len(texts) - changed))
    await pilot.pause()
    assert pilot.app.screen is screen, cycle
    texts[changed] = value
    assert screen.editor.text.splitlines()[row:] == [_expected_line(form, texts), "M30"], cycle
    assert screen.editor.text.splitlines()[:row] == lines[:row], cycle  # the calls before stay


MENU_OF = {cycle: index for index, menu in enumerate(cycle_menus()) for cycle in menu.cycles()}


@pytest.mark.parametrize("cycle", sorted(MENU_OF))
async def test_form_call_recompile_round_trip(data_dir: Path, cycle: str) -> None:
    """OK inserts the cycle's call, Recompile shows its values, a changed field replaces it."""
    menu = cycle_menus()[MENU_OF[cycle]]
    (data_dir / "MPF" / "DEMO.MPF").write_text("M30\n")
    app = lathe_program_app(data_dir) if menu.machine == "lathe" else make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3")  # PROGRAM MANAGER, open DEMO
        await pilot.pause()
        await _round_trip(pilot, app.screen, cycle_forms()[cycle], MENU_OF[cycle], 0)


def test_every_cycle_with_a_form_is_on_a_menu() -> None:
    """The round trips above cover every form."""
    assert sorted(MENU_OF) == sorted(cycle_forms())
