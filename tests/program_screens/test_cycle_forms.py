"""Cycle forms of the program editor (issue 23, as Operate's programGUIDE): Drilling softkey,
form → call line at the cursor → Recompile with the line's values → replaced line, refusals.

Parameter order and ranges: data/cycles/README.md "Drilling" (PGZ chapter 2: CYCLE81(RTP, RFP,
SDIS, DP, DPR), CYCLE82 adds DTB, CYCLE83 VARI 0 chip breaking / 1 swarf removal; SDIS is
unsigned). Keys: Shift+F7 is the vertical softkey 7 (Drilling), Enter takes a field.
"""

from __future__ import annotations

from pathlib import Path

from hmi.cycle_form_dialog import CycleFormDialog
from tests.program_screens.conftest import SIZE, make_program_app

SEVEN_ENTERS = ["enter"] * 7


async def _open_demo(pilot) -> None:
    await pilot.press("alt+n", "f3")  # PROGRAM MANAGER, open DEMO.MPF
    await pilot.pause()


async def test_form_inserts_then_recompiles_key_by_key(data_dir: Path) -> None:
    """CYCLE81 with typed values lands at the cursor; Recompile shows them and replaces the line."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await _open_demo(pilot)
        screen = app.screen
        await pilot.press("down", "down")  # cursor on N20
        await pilot.press("shift+f7")  # Drilling: list of the drilling cycles
        await pilot.pause()
        await pilot.press("enter")  # CYCLE81 (first entry)
        await pilot.pause()
        assert isinstance(app.screen, CycleFormDialog) and app.screen.form.cycle == "CYCLE81"
        for key in ["5", "0", "enter", "enter", "2", "enter", "-", "2", "5", "enter", "enter"]:
            await pilot.press(key)  # RTP 50, RFP 0, SDIS 2, DP -25, DPR 0 → OK
        await pilot.pause()
        lines = screen.editor.text.splitlines()
        assert lines[2] == "CYCLE81(50,0,2,-25,0)"
        assert lines[3] == "N20 G1 Z-1 F200"  # the line at the cursor moved down
        # Recompile: the cursor stands on the call; the form shows its values
        await pilot.press("shift+f7")
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog)
        assert [f.value for f in form.fields()] == ["50", "0", "2", "-25", "0"]
        await pilot.press("down", "down", "down", *"-30", "enter", "enter")  # DP -30, OK
        await pilot.pause()
        lines = screen.editor.text.splitlines()
        assert lines[2] == "CYCLE81(50,0,2,-30,0)"
        assert len(lines) == 10


async def test_recompile_keeps_block_number_and_mcall_in_a_burst(data_dir: Path) -> None:
    """A hand-written MCALL CYCLE83 with empty parameters reopens; OK keeps N and MCALL, fills defaults."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("N10 MCALL CYCLE83(10,0,2,,20,,5,1,,,,1) ; deep\nN20 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3", "shift+f7")
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog) and form.form.cycle == "CYCLE83"
        values = [f.value for f in form.fields()]
        assert values[:8] == ["10", "0", "2", "-30", "20", "-5", "5", "1"]  # empty: the form's default
        assert values[11] == "1"  # VARI swarf removal
        await pilot.press(*["enter"] * 17)  # take every field, OK on the last
        await pilot.pause()
        assert app.screen.editor.text.splitlines()[0] == (
            "N10 MCALL CYCLE83(10,0,2,-30,20,-5,5,1,0,0,1,1,0,0,0,0,0) ; deep")


async def test_bad_value_is_refused_with_the_reason(data_dir: Path) -> None:
    """A negative safety distance and VARI 2 are refused in the form; nothing is inserted."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await _open_demo(pilot)
        before = app.screen.editor.text
        await pilot.press("shift+f7", "down", "enter")  # CYCLE82
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog) and form.form.cycle == "CYCLE82"
        await pilot.press("enter", "enter", "-", "1", "enter")  # SDIS -1
        await pilot.pause()
        message = str(form.query_one("#cycle-message").render())
        assert "SDIS" in message and "lower limit 0" in message
        assert form.focused is form.fields()[2]  # the cursor stays in the refused field
        await pilot.press("escape")
        await pilot.pause()
        assert app.screen.editor.text == before


async def test_hand_edited_call_with_a_variable_says_why_not(data_dir: Path) -> None:
    """A call with R1 as a parameter cannot be shown: the dialog line says why, no form opens."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("CYCLE81(R1,0,2,-10)\nM30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3", "shift+f7")
        await pilot.pause()
        assert not isinstance(app.screen, CycleFormDialog)
        assert "RTP = R1 is not a number" in app.screen.area_hint
