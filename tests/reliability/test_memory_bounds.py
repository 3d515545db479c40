"""Programs cannot make the simulator allocate without bound (issue 19, "memory bounds").

Variables take memory of the channel: MD28040 MM_LUD_VALUES_MEM, "memory size for local user
variables" in KB (002 L26506), and MD18150 MM_GUD_VALUES_MEM for global ones (004 L496); a
program that needs more ends with the control's alarm 12380 (memory capacity reached).
A formatted SPRINT result longer than a string can hold ends with 14099 before it is built.
The budgets are measured with tracemalloc (memory, never time).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
import tracemalloc

import pytest

from nck.check import check_text
from nck.headless import run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.machine_data import MachineDataStore
from nck.ncdata import NcData
from nck.writes import DataWriter, WriteRefused
from tests.reliability.harness import run_hostile

PEAK_BYTES = 20_000_000


def _peak(action) -> tuple[object, int]:
    tracemalloc.start()
    try:
        result = action()
        return result, tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("template", ["%.999999999F", "%.401F", "%.1000000E", "%." + "9" * 30 + "F"])
def test_sprint_refuses_a_huge_precision_before_building_it(template: str) -> None:
    text = f'DEF STRING[200] TXT\nTXT=SPRINT("{template}",1)\nM30\n'
    result, peak = _peak(lambda: run_hostile(text))
    assert [a.number for a in result.alarms][:1] == [14099]
    assert peak < PEAK_BYTES


def test_sprint_within_the_bound_still_formats() -> None:
    result = run_hostile('DEF STRING[200] TXT\nTXT=SPRINT("%.3F",1.23456)\nIF TXT<>"1.235" GOTOF BAD\nM30\n'
                         'BAD: SETAL(65000)\nM30\n')
    assert result.status == "ended" and result.alarms == []


def test_many_large_arrays_end_with_12380_without_allocating() -> None:
    text = "\n".join(f"DEF REAL ARR{i}[1000,1000]" for i in range(300)) + "\nM30\n"
    result, peak = _peak(lambda: run_hostile(text))
    assert [a.number for a in result.alarms] == [12380]
    assert "MD28040" in result.alarms[0].params[-1]
    assert peak < PEAK_BYTES


def _run(text: str, lud_kb: int | None = None, subprograms: dict[str, str] | None = None):
    machine = load_machine()
    if lud_kb is not None:
        machine = dataclasses.replace(machine, md={**machine.md, "MD28040": lud_kb})
    return run_program(machine, MemorySource(subprograms or {}), NcData(), "P.MPF", text=text,
                       timeout_s=60.0)


def test_the_budget_is_md28040_in_kilobytes() -> None:
    # 64 KB = 65,536 bytes = 8,192 REAL values of 8 bytes
    assert _run("DEF REAL VALS[8192]\nM30\n").alarms == []
    assert [a.number for a in _run("DEF REAL VALS[8192]\nDEF INT CNT\nM30\n").alarms] == [12380]
    assert _run("DEF REAL VALS[8192]\nDEF REAL MORE[8192]\nM30\n", lud_kb=128).alarms == []
    # STRING[n] takes n + 1 bytes: 2 x 1000 STRING[31] = 64,000 bytes fit, a third array does not
    assert _run("DEF STRING[31] TXA[1000]\nDEF STRING[31] TXB[1000]\nM30\n").alarms == []
    assert [a.number for a in _run("DEF STRING[31] TXA[1000]\nDEF STRING[31] TXB[1000]\n"
                                   "DEF STRING[31] TXC[100]\nM30\n").alarms] == [12380]


def test_a_subprogram_gives_its_memory_back_at_the_return() -> None:
    sub = {"BIG.SPF": "PROC BIG\nDEF REAL VALS[6000]\nM17\n"}
    assert _run("DEF INT CNT\nFOR CNT=1 TO 20\nBIG\nENDFOR\nM30\n", subprograms=sub).alarms == []
    nested = {"BIG.SPF": "PROC BIG\nDEF REAL VALS[6000]\nM17\n"}
    main = "DEF REAL MINE[3000]\nBIG\nM30\n"  # 24,000 + 48,000 bytes > 64 KB while BIG runs
    assert [a.number for a in _run(main, subprograms=nested).alarms] == [12380]


def test_global_user_data_count_against_md18150() -> None:
    # MD18150 = 12 KB (data/md/general.toml): 1,536 REAL values
    assert _run("DEF NCK REAL GLOB1[1500]\nM30\n").alarms == []
    assert [a.number for a in _run("DEF NCK REAL GLOB1[1500]\nDEF NCK REAL GLOB2[100]\nM30\n").alarms] == [12380]


def test_the_editor_check_of_the_hostile_program_stays_small() -> None:
    text = 'DEF STRING[200] TXT\nTXT=SPRINT("%.999999999F",1)\nM30\n'
    found, peak = _peak(lambda: check_text("HOSTILE.MPF", text))
    assert [a.number for a in found] == [14099]
    assert peak < PEAK_BYTES


@pytest.mark.parametrize("loop", [
    'LBL: MSG("A"<<R1)\nR1=R1+1\nGOTOB LBL\nM30\n',  # no motion at all: the machine is idle
    'LBL: G4 F0.001\nMSG("A"<<R1)\nR1=R1+1\nGOTOB LBL\nM30\n',  # a dwell executes, no path motion
    'G91 G1 F1000\nLBL: X0.001\nMSG("A"<<R1)\nR1=R1+1\nGOTOB LBL\nM30\n',
])
def test_a_run_hands_commands_on_as_they_execute_and_holds_none_back(loop: str) -> None:
    """``nck run`` hands every command on (``on_command``: --segments) once the machine has
    executed it; what the interpreter ran ahead is held back, never more than the look-ahead.
    Found in the attack pass: a loop of messages or dwells held every command until the run
    ended (nck run: +0.8 MB per simulated second, 168 MB after two minutes)."""
    data = NcData()
    lags: list[int] = []

    def on_command(command) -> None:
        if type(command).__name__ == "Message":  # "A<R1 when interpreted>"; R1 counts on
            lags.append(int(data.r[1]) - int(command.text[1:]))

    run = run_program(load_machine(), MemorySource({}), data, "P.MPF", text=loop, timeout_s=1.0,
                      keep_commands=False, on_command=on_command)
    assert run.status == "timeout" and data.r[1] > 150 and len(lags) > 100
    assert max(lags) <= 100, max(lags)  # the look-ahead: 64 passes of the motion loop, 1 without motion


def test_the_tool_offset_memory_holds_md18100_cutting_edges() -> None:
    """002 L58292-58296: a D number written for the first time stores a new data block; MD18100
    sets how many the memory holds. A program filling it ends with 12380, not with a tool list
    that grows without end (found beyond the issue's list: 30,000 edges from a 6-line loop)."""
    fill = "DEF INT CNT\nFOR CNT=1 TO 3\n$TC_DP1[CNT,1]=120\nENDFOR\n"
    machine = dataclasses.replace(load_machine(), md={**load_machine().md, "MD18100": 3})
    full = NcData()
    assert run_program(machine, MemorySource({}), full, "P.MPF", text=fill + "$TC_DP3[2,1]=50\nM30\n",
                       timeout_s=60.0).alarms == []  # three edges fit; writing one of them again too
    assert len(full.tools) == 3
    over = run_program(machine, MemorySource({}), NcData(), "P.MPF", text=fill + "$TC_DP3[3,2]=50\nM30\n",
                       timeout_s=60.0)
    assert [a.number for a in over.alarms] == [12380]
    assert "MD18100" in over.alarms[0].params[-1]


def test_a_data_write_beyond_md18100_is_refused() -> None:
    """The same bound on the one write path of the panel, nck md/run --tools and archive import."""
    machine = dataclasses.replace(load_machine(), md={**load_machine().md, "MD18100": 2})
    data = NcData()
    writer = DataWriter(data, MachineDataStore(machine), None)
    writer.write("$TC_DP1[1,1]", 120)
    writer.write("$TC_DP1[2,1]", 120)
    writer.write("$TC_DP3[2,1]", 50)
    with pytest.raises(WriteRefused, match="MD18100"):
        writer.write("$TC_DP1[3,1]", 120)
    assert sorted(data.tools) == [(1, 1), (2, 1)]



def _rss_kb(field: str) -> int:
    """``VmRSS`` (now) or ``VmHWM`` (peak since the last reset) of this process in KB (Linux)."""
    status = Path("/proc/self/status").read_text()
    return int(next(line.split()[1] for line in status.splitlines() if line.startswith(field + ":")))


async def test_opening_the_hostile_program_in_the_editor_stays_small(tmp_path: Path) -> None:
    """Issue 19: merely opening the 3-line SPRINT program in the editor took the HMI from 79 MB
    to 1.9 GB (the background check formatted the 1 GB string). Open it as an operator does
    (Program manager, Open) and let the check finish: 14099 on line 2, and the process's peak
    resident memory (reset before the opening: ``/proc/self/clear_refs``) grows by little."""
    from tests.program_screens.conftest import SIZE, make_program_app, nc_files, settle

    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "HOSTILE.MPF").write_text('DEF STRING[200] TXT\nTXT=SPRINT("%.999999999F",1)\nM30\n')
    app = make_program_app(root)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        Path("/proc/self/clear_refs").write_text("5")  # the peak starts again from what is resident now
        before_kb = _rss_kb("VmRSS")
        await pilot.press("alt+n", "f3")  # Program manager, Open the selected program
        await settle(pilot)
        grown_kb = _rss_kb("VmHWM") - before_kb
        screen = app.screen
        assert screen.program == "MPF/HOSTILE.MPF"
        assert [(m.line, m.number) for m in screen.editor.error_marks.values()] == [(1, 14099)]
    assert grown_kb < 100 * 1024, f"{grown_kb} KB"
