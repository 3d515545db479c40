"""Every cycle form, as an operator uses it: softkeys to the form, a value typed into every
field (typed fast: the whole form's keys in one burst, so no key may be lost or land in the
wrong field), OK → the call line at the cursor → Recompile (the same line reopens with those values)
(the cycle's softkey again, with the cursor on the call) → one field changed → OK → the call is
replaced by one with the changed value (issue 23 done-when, Operate's programGUIDE).

The cycle level and its keys are the editor's (docs/screens_added.md "Program editor: cycle
input forms"): Shift+F7 Cycles, F1 Drilling / F2 Milling / F3 Turning, Shift+F<n> the n-th key
of the menu, Shift+F<m> the m-th cycle of a key that holds several. The expected call line is
the cycle name and the typed values in the order of the parameter list
(data/cycles/README.md, from the PGZ), a program name in quotes.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hmi.app import HmiApp
from hmi.cycle_form_dialog import CycleFormDialog
from hmi.cycle_forms import CycleParam, cycle_forms
from tests.burst import burst
from tests.program_screens.conftest import (SIZE, keys_to_form, lathe_program_app, make_program_app,
                                            on_lathe)

PROGRAM = "N10 G0 X0\nN20 M30\n"


def typed_value(param: CycleParam, index: int) -> str:
    """A value of the parameter's range that differs from field to field (its position + 0.25)."""
    if param.kind == "name":
        return "SHAFT_CONTOUR"
    if param.choices:
        return str(param.choices[-1])
    value = 2.0 if param.integer else index + 1.25
    if param.max_value is not None:
        value = min(value, param.max_value)
    if param.min_value is not None:
        value = max(value, param.min_value)
    return str(int(value)) if value == int(value) else str(value)


def changed_field(params: list[CycleParam], values: list[str]) -> tuple[int, str]:
    """The first numeric field and a value its range permits other than the one typed."""
    for index, param in enumerate(params):
        if param.kind == "name" or param.choices:
            continue
        for value in ("7", "3", "1", "0.5", "0.01"):
            if param.refusal(value) is None and value != values[index]:
                return index, value
    raise AssertionError("no field to change")


CYCLES_PER_PANEL = 6
"""Cycles one panel takes in turn: a panel per form cost three minutes of make test, all of a
machine's forms in one panel ran past the test timeout on a loaded machine."""


def panel_batches() -> list[tuple[str, list[str]]]:
    """The cycles in batches of one machine each, at most :data:`CYCLES_PER_PANEL` per batch."""
    batches = []
    for machine in ("mill", "lathe"):
        cycles = [cycle for cycle in sorted(cycle_forms()) if on_lathe(cycle) == (machine == "lathe")]
        for start in range(0, len(cycles), CYCLES_PER_PANEL):
            batches.append((machine, cycles[start:start + CYCLES_PER_PANEL]))
    return batches


@pytest.mark.parametrize(("machine", "cycles"), panel_batches(),
                         ids=[f"{machine}-{cycles[0]}" for machine, cycles in panel_batches()])
async def test_form_call_line_and_recompile_round_trip(machine: str, cycles: list[str],
                                                       data_dir: Path) -> None:
    """For each cycle of the batch: type a value into every field; the call line holds them in
    order; Recompile gives them back; a changed field replaces the call.

    One panel takes the batch's forms one after another; between two cycles the program is put
    back and the editor's softkeys return to their first level, as an operator leaving the cycle
    level would find them."""
    (data_dir / "MPF" / "DEMO.MPF").write_text(PROGRAM)
    app = lathe_program_app(data_dir) if machine == "lathe" else make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3")  # open DEMO.MPF
        await pilot.pause()
        screen = app.screen
        editor = screen.editor
        for cycle in cycles:
            editor.text = PROGRAM
            editor.cursor_location = (1, 0)  # on N20
            screen.clear_softkey_levels()
            await pilot.pause()
            await round_trip(pilot, app, editor, cycle)


async def round_trip(pilot, app: HmiApp, editor, cycle: str) -> None:
    """The form of ``cycle`` filled, its call checked, reopened by Recompile, changed and checked."""
    form = cycle_forms()[cycle]
    values = [typed_value(param, index) for index, param in enumerate(form.params)]
    await burst(pilot, *keys_to_form(cycle))
    await pilot.pause()
    dialog = app.screen
    assert isinstance(dialog, CycleFormDialog) and dialog.form.cycle == cycle, cycle
    await burst(pilot, *[key for value in values for key in (*value, "enter")])  # typed fast, one burst
    args = [f'"{v}"' if p.kind == "name" else v for p, v in zip(form.params, values)]
    call = f"{cycle}({','.join(args)})"
    assert editor.text == f"N10 G0 X0\n{call}\nN20 M30\n", cycle
    await burst(pilot, *keys_to_form(cycle)[1:])  # the same softkey on the call: Recompile
    await pilot.pause()
    dialog = app.screen
    assert isinstance(dialog, CycleFormDialog) and dialog.form.cycle == cycle, cycle
    assert [field.value for field in dialog.fields()] == values, cycle
    changed, value = changed_field(form.params, values)
    await burst(pilot, *["down"] * changed, *value, *["enter"] * (len(values) - changed))
    await pilot.pause()
    args[changed] = value
    assert editor.text == f"N10 G0 X0\n{cycle}({','.join(args)})\nN20 M30\n", cycle  # replaced
