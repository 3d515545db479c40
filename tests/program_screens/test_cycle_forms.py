"""Cycle forms of the program editor (issue 23, as Operate's programGUIDE), written by hand:
the softkeys of the cycle level, form → call line at the cursor → Recompile with the line's
values → replaced line, the modal call switch, refusals.

Parameter order: data/cycles/README.md (PGZ chapter 2: CYCLE81(RTP, RFP, SDIS, DP, DPR);
CYCLE83(RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI, _AXN, _MDEP, _VRT, _DTD,
_DIS1); CYCLE84(RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT, PIT, POSS, SST, SST1, _AXN);
HOLES2(CPA, CPO, RAD, STA1, INDA, NUM); CYCLE802(_XA, _YA, _X0, _Y0, …); CYCLE95(NPP, MID, …)
with NPP a program name). The expected lines are written out here from those lists.
Keys (docs/screens_added.md): Shift+F7 Cycles / Recompile; on the cycle level F1 Drilling,
F2 Milling, F3 Turning, F8 Back; drilling keys Shift+F1 Centering, Shift+F3 Deep hole
drilling, Shift+F5 Thread (Shift+F1 Tapping), Shift+F6 Positions (Shift+F2 Circle, Shift+F4
Any positions), Shift+F7 Modal call on / off.
"""

from __future__ import annotations

from pathlib import Path

from hmi.cycle_form_dialog import CycleFormDialog
from tests.burst import burst
from tests.program_screens.conftest import SIZE, lathe_program_app, make_program_app



async def _open_demo(pilot) -> None:
    await pilot.press("alt+n", "f3")  # PROGRAM MANAGER, open DEMO.MPF
    await pilot.pause()


def _message(form: CycleFormDialog) -> str:
    return str(form.query_one("#cycle-message").render())


async def test_form_inserts_then_recompiles_key_by_key(data_dir: Path) -> None:
    """CYCLE81 with typed values lands at the cursor; Shift+F7 on it shows them and replaces the line."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await _open_demo(pilot)
        screen = app.screen
        await pilot.press("down", "down")  # cursor on N20
        await pilot.press("shift+f7")  # Cycles: the drilling keys
        await pilot.pause()
        assert screen.current_menu().find("cycle.CYCLE81") == "v1"
        await pilot.press("shift+f1")  # Centering
        await pilot.pause()
        assert isinstance(app.screen, CycleFormDialog) and app.screen.form.cycle == "CYCLE81"
        for key in ["5", "0", "enter", "enter", "2", "enter", "-", "2", "5", "enter", "enter"]:
            await pilot.press(key)  # RTP 50, RFP 0, SDIS 2, DP -25, DPR 0 → OK
        await pilot.pause()
        lines = screen.editor.text.splitlines()
        assert lines[2] == "CYCLE81(50,0,2,-25,0)"
        assert lines[3] == "N20 G1 Z-1 F200"  # the line at the cursor moved down
        await pilot.press("f8")  # << Back: the editor's own softkeys
        await pilot.pause()
        assert screen.current_menu().find("program.cycles") == "v7"
        await pilot.press("shift+f7")  # Recompile: the cursor stands on the call
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog)
        assert [f.value for f in form.fields()] == ["50", "0", "2", "-25", "0"]
        await pilot.press("down", "down", "down", *"-30", "enter", "enter")  # DP -30, OK
        await pilot.pause()
        lines = screen.editor.text.splitlines()
        assert lines[2] == "CYCLE81(50,0,2,-30,0)"
        assert len(lines) == 10


async def test_drilled_flange_from_the_forms_in_bursts(data_dir: Path) -> None:
    """MCALL CYCLE83 + HOLES2 + MCALL, then MCALL CYCLE84 + HOLES2 + MCALL: the flange's cycle lines."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("G17 G0 X0 Y0 Z100\nM30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "down")  # cursor on M30
        await pilot.pause()
        editor = app.screen.editor
        # Deep hole drilling: RTP 10, RFP 0, SDIS 2, DP -18, DPR 0, FDEP -6, FDPR 0, DAM 2,
        # DTB 0, DTS 0, FRF 1, VARI 1 (swarf removal), the last five empty (not programmed)
        cycle83 = ["10", "0", "2", "-18", "0", "-6", "0", "2", "0", "0", "1", "1"]
        await burst(pilot, "shift+f7", "shift+f3")
        await pilot.pause()
        keys = [k for value in cycle83 for k in (*value, "enter")] + ["backspace", "enter"] * 5
        await burst(pilot, *keys, "shift+f7")  # OK on the last field, then Modal call on
        await pilot.pause()
        await burst(pilot, "down", "shift+f6", "shift+f2")  # Positions, Circle
        await pilot.pause()
        await burst(pilot, *"0", "enter", *"0", "enter", *"40", "enter", *"0", "enter", *"60", "enter",
                    *"6", "enter")
        await pilot.pause()
        await burst(pilot, "down", "f1", "shift+f7")  # back to the drilling keys, Modal call off
        await pilot.pause()
        # Tapping: RTP 10, RFP 0, SDIS 2, DP -15, DPR 0, DTB 0, SDAC 3, MPIT 10, PIT 0, POSS 0,
        # SST 300, SST1 600, _AXN empty
        cycle84 = ["10", "0", "2", "-15", "0", "0", "3", "10", "0", "0", "300", "600"]
        await burst(pilot, "down", "shift+f5", "shift+f1")
        await pilot.pause()
        await burst(pilot, *[k for value in cycle84 for k in (*value, "enter")], "backspace", "enter")
        await pilot.pause()
        await burst(pilot, "f1", "shift+f7")
        await pilot.pause()
        assert editor.text.splitlines() == [
            "G17 G0 X0 Y0 Z100",
            "MCALL CYCLE83(10,0,2,-18,0,-6,0,2,0,0,1,1)",
            "HOLES2(0,0,40,0,60,6)",
            "MCALL",
            "MCALL CYCLE84(10,0,2,-15,0,0,3,10,0,0,300,600)",
            "M30",
        ]


async def test_recompile_keeps_block_number_mcall_and_empty_places(data_dir: Path) -> None:
    """A hand-written MCALL CYCLE83 with empty places reopens; OK writes it back as it was (spaces aside)."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("N10 MCALL CYCLE83(10, 0, 2, , 20, , 5, 1, , , , 1) ; deep\nN20 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "shift+f7")
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog) and form.form.cycle == "CYCLE83"
        values = [f.value for f in form.fields()]
        assert values[:12] == ["10", "0", "2", "", "20", "", "5", "1", "", "", "", "1"]
        assert values[12:] == [""] * 5
        await burst(pilot, *["enter"] * 17)  # take every field, OK on the last
        await pilot.pause()
        assert app.screen.editor.text.splitlines()[0] == "N10 MCALL CYCLE83(10,0,2,,20,,5,1,,,,1) ; deep"


async def test_positions_and_a_contour_name(data_dir: Path) -> None:
    """CYCLE802 with three positions, CYCLE95 on the lathe with its contour name in quotes."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "shift+f7", "shift+f6", "shift+f4")  # Any positions
        await pilot.pause()
        # _XA 101 / _YA 111: X of the second position incremental; positions 10/5, +20/15, 40/25
        await burst(pilot, *"101", "enter", *"111", "enter", *"10", "enter", *"5", "enter",
                    *"20", "enter", *"15", "enter", *"40", "enter", *"25", "enter", *["enter"] * 12)
        await pilot.pause()
        assert app.screen.editor.text.splitlines()[0] == "CYCLE802(101,111,10,5,20,15,40,25)"


async def test_stock_removal_form_on_the_lathe(data_dir: Path) -> None:
    """CYCLE95("SHAFT_CONTOUR", 2, 0.2, 0.2, 0, 0.3, 0.15, 0.3, 1, 0, 0, 1), the sample shaft's roughing."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("M30\n")
    app = lathe_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "shift+f7", "f3", "shift+f1")  # Turning, Stock removal
        await pilot.pause()
        values = ["shaft_contour", "2", "0.2", "0.2", "0", "0.3", "0.15", "0.3", "1", "0", "0", "1"]
        await burst(pilot, *[k for value in values for k in (*value, "enter")])
        await pilot.pause()
        assert app.screen.editor.text.splitlines()[0] == 'CYCLE95("SHAFT_CONTOUR",2,0.2,0.2,0,0.3,0.15,0.3,1,0,0,1)'


async def test_turning_is_greyed_on_the_mill(data_dir: Path) -> None:
    """On the milling machine F3 Turning cannot be used: the drilling keys stay."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "shift+f7", "f3")
        await pilot.pause()
        screen = app.screen
        assert screen.current_menu().find("cycle.CYCLE81") == "v1"
        assert "not possible" in screen.area_hint
        await burst(pilot, "f2")  # Milling
        await pilot.pause()
        assert screen.current_menu().find("cycle.CYCLE61") == "v1"
        assert screen.current_menu().find("cycle.CYCLE832") == "v5"


async def test_bad_value_is_refused_with_the_reason(data_dir: Path) -> None:
    """A negative safety distance, VARI 2 and a broken number are refused in the form; nothing is inserted."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await _open_demo(pilot)
        before = app.screen.editor.text
        await pilot.press("shift+f7", "shift+f3")  # CYCLE83
        await pilot.pause()
        form = app.screen
        assert isinstance(form, CycleFormDialog) and form.form.cycle == "CYCLE83"
        await pilot.press("enter", "enter", "-", "1", "enter")  # SDIS -1
        await pilot.pause()
        assert _message(form) == "SDIS: value below the lower limit 0"
        assert form.focused is form.fields()[2]  # the cursor stays in the refused field
        await burst(pilot, "backspace", "backspace", "1", *["enter"] * 9, "2", "enter")  # SDIS 1 … VARI 2
        await pilot.pause()
        assert _message(form) == "VARI: only 0 / 1 permitted"
        assert form.focused is form.fields()[11]
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
        assert "RTP = R1 cannot be shown in the form" in app.screen.area_hint
