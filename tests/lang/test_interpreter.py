"""Interpreter behaviour that golden traces do not show: atomicity, skip runs, search, scopes."""

from __future__ import annotations

import dataclasses

import pytest

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.interpreter import BLOCK_COST_S, Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge


def make(text: str, subprograms: dict[str, str] | None = None, data: NcData | None = None,
         machine=None) -> Interpreter:
    interp = Interpreter(machine or load_machine(), MemorySource(subprograms or {}), data or NcData())
    interp.start_text("MAIN.MPF", text)
    return interp


def run_all(interp: Interpreter, limit: int = 10_000) -> list[canon.CanonCommand]:
    out: list[canon.CanonCommand] = []
    for _ in range(limit):
        if interp.finished:
            return out
        out.extend(interp.step().commands)
    raise AssertionError("program did not end")


def test_failing_block_changes_nothing() -> None:
    data = NcData()
    interp = make(
        "DEF INT CNT=1\nDEF REAL VALS[2]\nG0 X5\n"
        "CNT=2 VALS[1]=3 R1=7 $TC_DP1[1,1]=120 G91 G1 X1 F100 R2=1/0\n"
        "M30\n", data=data)
    for _ in range(3):
        interp.step()
    before = (list(data.r), dict(data.tools), interp.variable("CNT"), interp.variable("VALS[1]"),
              dict(interp.modal.position_wcs), dict(interp.modal.gcodes), interp.modal.feed)
    source = interp.current_source()
    with pytest.raises(NcAlarmError) as info:
        interp.step()
    assert info.value.number == 14051
    assert (info.value.line, info.value.file) == (4, "MAIN.MPF")
    after = (list(data.r), dict(data.tools), interp.variable("CNT"), interp.variable("VALS[1]"),
             dict(interp.modal.position_wcs), dict(interp.modal.gcodes), interp.modal.feed)
    assert after == before
    assert interp.current_source() == source  # the same block would run again


def test_failing_call_leaves_the_call_stack_alone() -> None:
    interp = make("R1=1\nSUB(1, 2)\nM30\n", {"SUB.SPF": "PROC SUB(INT AA)\nM17\n"})
    interp.step()
    with pytest.raises(NcAlarmError) as info:
        interp.step()
    assert info.value.number == 12340
    assert interp.level() == 1 and interp.current_source().line == 2


def test_every_block_costs_time_and_step_after_end_is_harmless() -> None:
    interp = make("R1=1\nM30\n")
    first = interp.step()
    assert first.cost_s == BLOCK_COST_S and not first.action_block
    last = interp.step()
    assert last.finished and isinstance(last.commands[-1], canon.ProgramEnd)
    again = interp.step()
    assert again.finished and again.commands == ()


def test_skip_level_runs_are_sampled_at_their_first_block() -> None:
    # 840C example: /1 and /2 on at the start; /1 switched off between N15 and N20.
    text = "N5\n/N10\n/1 N15\n/1 N20\n/1 N25\n/1 N30\n/2 N35\n/2 N40\n/3 N45\n/1 N50\n"
    interp = make(text)
    interp.skip_levels = frozenset({0, 1, 2})
    executed = []
    while not interp.finished:
        result = interp.step()
        if result.source.n == 15:
            interp.skip_levels = frozenset({0, 2})
        if result.text and not result.extras.get("skipped"):
            executed.append(result.source.n)
    assert executed == [5, 45, 50]


def test_program_global_data_visible_in_subprograms_only_with_md11120() -> None:
    main = "DEF INT SHARED=3\nSUB\nM30\n"
    sub = {"SUB.SPF": "R1=SHARED\nM17\n"}
    with pytest.raises(NcAlarmError) as info:
        run_all(make(main, sub))
    assert info.value.number == 12550 and info.value.file == "SUB.SPF"
    machine = load_machine()
    machine = dataclasses.replace(machine, md={**machine.md, "MD11120": 1})
    data = NcData()
    run_all(make(main, sub, data=data, machine=machine))
    assert data.r[1] == 3.0


def test_local_variables_vanish_after_return() -> None:
    with pytest.raises(NcAlarmError) as info:
        run_all(make("SUB\nR1=INNER\nM30\n", {"SUB.SPF": "DEF INT INNER=4\nRET\n"}))
    assert info.value.number == 12550 and info.value.line == 2


def test_global_user_data_survive_reset() -> None:
    data = NcData()
    run_all(make("DEF NCK REAL GLOBALV=2.5\nGLOBALV=GLOBALV*2\nM30\n", data=data))
    assert data.gud["GLOBALV"] == 5.0
    interp = make("R1=GLOBALV\nM30\n", data=data)
    run_all(interp)
    assert data.r[1] == 5.0


@pytest.mark.parametrize("text, number", [
    ("DEF INT AA REAL BB\n", 12080),
    ("DEF INT $ABC\n", 12080),
    ("DEF INT A1\n", 12080),
    ("DEF INT " + "A" * 32 + "\n", 12420),
    ("DEF INT X\n", 12080),
    ("DEF STRING[300] TXT\n", 12160),
    ("DEF INT GOTOF\n", 12080),
    ("DEF REAL G1\n", 12080),
    ("DEF INT BRISK\n", 12170),
])
def test_def_rules(text: str, number: int) -> None:
    with pytest.raises(NcAlarmError) as info:
        run_all(make(text))
    assert info.value.number == number


def test_subprogram_nesting_limit_is_sixteen_levels() -> None:
    sub = {"DEEP.SPF": "PROC DEEP(INT LEFT)\nIF LEFT>0\nDEEP(LEFT-1)\nENDIF\nR1=MAXVAL(R1,$P_STACK)\nRET\n"}
    data = NcData()
    run_all(make("DEEP(14)\nM30\n", sub, data=data))  # main + 15 subprogram levels
    assert data.r[1] == 16
    with pytest.raises(NcAlarmError) as info:
        run_all(make("DEEP(15)\nM30\n", sub))
    assert info.value.number == 14012


def test_actual_position_comes_from_the_position_source() -> None:
    interp = make("G0 X10\nR1=$AA_IM[X]\nM30\n")
    interp.position_source = lambda axis: {"X": 9.5}.get(axis, 0.0)
    run_all(interp)
    assert interp.r(1) == 9.5


def test_reset_restores_reset_state_and_allows_restart() -> None:
    interp = make("G91 G1 X1 F100\nX1\nX1\nM30\n")
    interp.step()
    interp.reset()
    assert interp.finished and interp.modal.gcodes[14] == "G90" and interp.modal.feed == 0.0
    interp.start_text("MAIN.MPF", "G1 X1 F10\nM30\n")
    commands = run_all(interp)
    assert [dict(c.end_wcs)["X"] for c in commands if isinstance(c, canon.Motion)] == [1.0]


def test_start_of_missing_program_is_alarm_14011() -> None:
    interp = Interpreter(load_machine(), MemorySource(), NcData())
    with pytest.raises(NcAlarmError) as info:
        interp.start("NOPE.MPF")
    assert info.value.number == 14011


def test_subprogram_call_runs_after_the_words_of_its_block() -> None:
    data = NcData()
    run_all(make("R1=5 SUB\nM30\n", {"SUB.SPF": "R2=R1*2\nM17\n"}, data=data))
    assert data.r[2] == 10.0


def test_m17_in_main_ends_the_program() -> None:
    commands = run_all(make("G0 X1\nM17\nG0 X2\n"))
    assert isinstance(commands[-1], canon.ProgramEnd) and commands[-1].kind == "M17"


def test_modal_view_reports_tool_feed_spindle() -> None:
    data = NcData()
    data.tools[(2, 1)] = ToolEdge({1: 120.0})  # T2 needs its data set (17191, 002 L58219)
    interp = make("T2 M6 D1 S800 M4 G1 X1 F300\nM30\n", data=data)
    interp.step()
    view = interp.modal_view()
    assert (view.tool, view.edge, view.feed, view.spindle_speed_rpm, view.spindle_state) == (2, 1, 300.0, 800.0, "M4")
    assert view.gcodes[1] == "G1"


def test_blocks_reading_main_run_data_ask_for_a_preprocessing_stop() -> None:
    interp = make("G0 X10\nR1=$AA_IM[X]+1\nIF $AA_IW[Y]>0 GOTOF END\nR2=$P_EP[X]\nEND: M30\n")
    flags = []
    while not interp.finished:
        flags.append(interp.needs_preprocessing_stop())
        result = interp.step()
        assert result.extras.get("preprocessing_stop", False) == flags[-1]
    assert flags == [False, True, True, False, False]
