"""Part programs write setting data at their protection level (issue 20; 004 L245-249,
002 L62080-62106)."""

from __future__ import annotations

import pytest

from nck.ncdata import NcData, ToolEdge
from tests.lang.conftest import run_text


def _tool_data() -> NcData:
    data = NcData()
    # end mill T1 D1: length L1 = 100 mm, length wear 1 mm (002 L62088-62092 does the same with
    # the radius; the length shows the sign on a straight G0 Z move without radius compensation)
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0, 12: 1.0})
    return data


def test_the_manuals_wear_sign_example_writes_the_setting_datum() -> None:
    # 002 L62080-62106: $SC_WEAR_SIGN = 0 → wear added (100 + 1 = 101);
    # $SC_WEAR_SIGN = 1 → sign inverted, active at the next D selection (100 - 1 = 99).
    result = run_text(
        "N10 $SC_WEAR_SIGN = 0\n"
        "N20 T1 M6 D1\n"
        "N30 G0 Z0\n"
        "N40 $SC_WEAR_SIGN = 1\n"
        "N50 D1\n"
        "N60 G0 Z0\n"
        "N70 R1 = $SC_WEAR_SIGN\n"
        "N80 M30\n", data=_tool_data(), timeout_s=5.0)
    assert result.status == "ended", result.alarms
    ends = [round(m.end_mcs["Z"], 6) for m in result.segments]
    assert ends == [101.0, 99.0]
    assert result.interpreter.data.r[1] == 1
    assert bool(result.interpreter.data.setting_data["SD42930"]) is True


@pytest.mark.parametrize("value, alarm", [(20, 17090), (-20, 17080)])
def test_setting_data_limits_are_alarms(value: int, alarm: int) -> None:
    # SD42940 TOOL_LENGTH_CONST takes -19 … 19 (catalogue limits): outside → 17080 / 17090.
    result = run_text(f"$SC_TOOL_LENGTH_CONST = {value}\nM30\n", timeout_s=5.0)
    assert [a.number for a in result.alarms] == [alarm]
    assert "SD42940" not in result.interpreter.data.setting_data


def test_a_failing_block_leaves_the_setting_datum_alone() -> None:
    data = NcData()
    result = run_text("$SC_WEAR_SIGN = 1 R1 = 1/0\nM30\n", data=data, timeout_s=5.0)
    assert result.status == "alarm"
    assert not data.setting_data.get("SD42930", False)


def test_machine_data_stay_write_protected_for_part_programs() -> None:
    """Digest job-planning-variables rank 11 (machine data)."""
    # 004 L245-249: only data with immediate effect; the machine data come from the machine
    # configuration the running program cannot change → 17070.
    result = run_text("$MA_MAX_AX_VELO[X] = 1000\nM30\n", timeout_s=5.0)
    assert [a.number for a in result.alarms] == [17070]


def test_the_protection_level_of_the_datum_decides(monkeypatch) -> None:
    """Digest job-planning-variables rank 11."""
    # 004 L245-249: "the access level which is active when the part program/cycle is executed
    # permits write access". A datum protected at level 3: refused at level 7 (17070) …
    from nck.machine_data import DataDefinition
    monkeypatch.setattr(DataDefinition, "write_level", property(lambda self: 3))
    result = run_text("$SC_WEAR_SIGN = 1\nM30\n", timeout_s=5.0)
    assert [a.number for a in result.alarms] == [17070]
    # … and written at level 2 (password), through the same path.
    from nck.headless import interpret_only
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine

    data = NcData()
    interp = Interpreter(load_machine(None), MemorySource({}), data)
    interp.access_level = lambda: 2
    interp.start_text("TEST.MPF", "$SC_WEAR_SIGN = 1\nM30\n")
    while not interp.finished:
        interp.step()
    assert data.setting_data["SD42930"] is True
    assert interpret_only  # the headless runner builds its interpreter the same way


def test_array_setting_data_take_the_programmed_index() -> None:
    # SD42160 EXTERN_FIXED_FEEDRATE_F1_F9 has ten elements (003 L645-647 writes them from a
    # program); an index outside 0 … 9 is 17020.
    data = NcData()
    result = run_text("$SC_EXTERN_FIXED_FEEDRATE_F1_F9[2] = 500\nR1 = $SC_EXTERN_FIXED_FEEDRATE_F1_F9[2]\n"
                      "M30\n", data=data, timeout_s=5.0)
    assert result.status == "ended", result.alarms
    assert data.r[1] == 500
    result = run_text("$SC_EXTERN_FIXED_FEEDRATE_F1_F9[10] = 500\nM30\n", timeout_s=5.0)
    assert [a.number for a in result.alarms] == [17020]
