"""Data writes through kernel commands: protection levels, validation, MD activation."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as c
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory
from nck.persistence import Session


@pytest.fixture()
def session(tmp_path: Path) -> Session:
    return Session.open(tmp_path, install_samples=False)


def kernel(session: Session, **kwargs) -> Nck:
    nck = Nck(**session.kernel_arguments(), **kwargs)
    nck.md_store = session.md
    return nck


def rejected(result: object) -> str:
    assert isinstance(result, c.Rejected), result
    return result.reason


def test_keyswitch_0_cannot_write_a_work_offset_customer_can(session: Session) -> None:
    nck = kernel(session)
    reason = rejected(nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 12.5)))
    assert "level 6" in reason
    assert nck.data.settable_frames["G54"].trans.get("X", 0.0) == 0.0
    assert nck.submit(c.EnterPassword("CUSTOMER")) == c.Accepted()
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 12.5)) == c.Accepted()
    assert nck.submit(c.WriteData("$P_UIFR[1,Z,RT]", 30)) == c.Accepted()
    assert nck.data.settable_frames["G54"].trans["X"] == 12.5
    assert nck.data.settable_frames["G54"].rot["Z"] == 30.0
    assert nck.submit(c.WriteData("$P_UBFR[Y,TR]", -4)) == c.Accepted()
    assert nck.data.base_frame.trans["Y"] == -4.0


@pytest.mark.parametrize(("name", "value", "words"), [
    ("$P_UIFR[1,X,RT]", 400, "rotation"),
    ("$P_UIFR[1,X,SC]", 0, "scale"),
    ("$P_UIFR[1,Q,TR]", 1, "no axis"),
    ("$P_UIFR[1,X,TR]", float("nan"), "out of range"),
    ("$TC_DP1[1,1]", 1.5, "whole number"),
    ("$TC_DP3[1,13]", 10, "D13"),
    ("$TC_DP6[1,1]", 1e9, "outside"),
    ("R1", "abc", ""),
    ("SD41110", -5, "below"),
])
def test_bad_values_are_refused_and_change_nothing(session: Session, name: str, value: object,
                                                   words: str) -> None:
    nck = kernel(session)
    nck.submit(c.EnterPassword("SUNRISE"))
    before = (dict(nck.data.tools), nck.data.settable_frames["G54"], list(nck.data.r),
              dict(nck.data.setting_data))
    assert words in rejected(nck.submit(c.WriteData(name, value)))
    assert nck.data.tools == before[0]
    assert nck.data.settable_frames["G54"] == before[1]
    assert nck.data.r == before[2]
    assert nck.data.setting_data == before[3]


def test_tools_are_added_and_deleted_at_the_tool_level(session: Session) -> None:
    nck = kernel(session)
    assert "level 4" in rejected(nck.submit(c.WriteData("$TC_DP1[7,1]", 120)))
    nck.submit(c.SetKeyswitch(3))  # level 4
    assert nck.submit(c.WriteData("$TC_DP1[7,1]", 120)) == c.Accepted()
    assert nck.submit(c.WriteData("$TC_DP3[7,1]", 80.5)) == c.Accepted()
    assert nck.submit(c.WriteData("$TC_DP6[7,2]", 4)) == c.Accepted()
    assert nck.data.tools[(7, 2)].tool_type == 120  # a new edge keeps the tool type
    assert nck.data.tools[(7, 1)].get(3) == 80.5
    nck.submit(c.SetKeyswitch(1))  # level 6: wear only
    assert nck.submit(c.WriteData("$TC_DP12[7,1]", -0.1)) == c.Accepted()
    assert "level 4" in rejected(nck.submit(c.WriteData("$TC_DP3[7,1]", 1)))
    assert "level 4" in rejected(nck.submit(c.DeleteToolEdge(7, 2)))
    nck.submit(c.SetKeyswitch(3))
    assert nck.submit(c.DeleteToolEdge(7, 2)) == c.Accepted()
    assert set(nck.data.tools) == {(7, 1)}
    assert nck.submit(c.DeleteToolEdge(7)) == c.Accepted()
    assert nck.data.tools == {}
    assert "does not exist" in rejected(nck.submit(c.DeleteToolEdge(7)))


def test_r_parameters_and_clear_all(session: Session) -> None:
    nck = kernel(session)
    assert "level 6" in rejected(nck.submit(c.WriteData("R3", 1)))
    nck.submit(c.SetKeyswitch(1))
    assert nck.submit(c.WriteData("R3", 1.5)) == c.Accepted()
    assert "level 5" in rejected(nck.submit(c.ClearRParameters()))
    nck.submit(c.SetKeyswitch(2))
    assert nck.submit(c.ClearRParameters()) == c.Accepted()
    assert set(nck.data.r) == {0.0}


def test_user_variables_keep_their_type(session: Session) -> None:
    session.ncdata.gud.update({"COUNT": 3, "LIMIT": 2.5, "FLAG": False, "TAB": [1.0, 2.0]})
    nck = kernel(session)
    assert "level 4" in rejected(nck.submit(c.WriteData("GUD:COUNT", 4)))
    nck.submit(c.SetKeyswitch(3))
    assert nck.submit(c.WriteData("GUD:COUNT", "7")) == c.Accepted()
    assert "whole number" in rejected(nck.submit(c.WriteData("GUD:COUNT", 7.5)))
    assert nck.submit(c.WriteData("GUD:FLAG", "TRUE")) == c.Accepted()
    assert nck.submit(c.WriteData("GUD:TAB[1]", 9)) == c.Accepted()
    assert "not defined" in rejected(nck.submit(c.WriteData("GUD:NOPE", 1)))
    assert nck.data.gud == {"COUNT": 7, "LIMIT": 2.5, "FLAG": True, "TAB": [1.0, 9.0]}


def test_setting_data_need_their_level_and_limits(session: Session) -> None:
    nck = kernel(session)
    assert "level 4" in rejected(nck.submit(c.WriteData("SD41110", 800)))
    nck.submit(c.SetKeyswitch(3))
    assert nck.submit(c.WriteData("SD41110", 800)) == c.Accepted()
    assert nck.data.setting_data["SD41110"] == 800


def test_md32000_needs_evening_and_takes_effect_at_reset(session: Session) -> None:
    nck = kernel(session, referenced=True)
    nck.submit(c.EnterPassword("CUSTOMER"))
    assert "level 2" in rejected(nck.submit(c.WriteData("MD32000[X]", 1200)))
    nck.submit(c.EnterPassword("EVENING"))
    assert nck.submit(c.WriteData("MD32000[X]", 1200)) == c.Accepted()
    assert session.md.is_pending("MD32000[X]")
    assert nck.machine.md_value("MD32000", "X", None) != 1200
    nck.submit(c.Reset())
    assert not session.md.is_pending("MD32000[X]")
    assert nck.machine.md_value("MD32000", "X", None) == 1200
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G0 X100"))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    start = nck.time_s
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 99.999, 30.0)
    assert nck.time_s - start == pytest.approx(100 / 1200 * 60, rel=0.05)


def test_set_md_active_and_password_change(session: Session) -> None:
    nck = kernel(session)
    nck.submit(c.EnterPassword("EVENING"))
    nck.submit(c.WriteData("MD32000[Y]", 2000))
    assert nck.submit(c.ActivateMachineData()) == c.Accepted()
    assert nck.machine.md_value("MD32000", "Y", None) == 2000
    assert "level 1" in rejected(nck.submit(c.ChangePassword(1, "NEWONE")))
    assert nck.submit(c.ChangePassword(2, "NIGHT")) == c.Accepted()
    nck.submit(c.DeletePassword())
    assert isinstance(nck.submit(c.EnterPassword("EVENING")), c.Rejected)
    assert nck.submit(c.EnterPassword("NIGHT")) == c.Accepted()
    assert nck.status().access_level == 2


def test_bare_kernel_is_unprotected() -> None:
    nck = Nck()
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 3)) == c.Accepted()
    assert nck.submit(c.WriteData("SD42100", 2000.0)) == c.Accepted()
    assert nck.data.setting_data["SD42100"] == 2000.0


def test_a_work_offset_written_by_command_acts_when_g54_is_selected(session: Session) -> None:
    nck = kernel(session, referenced=True)
    nck.submit(c.EnterPassword("CUSTOMER"))
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 10)) == c.Accepted()
    assert nck.submit(c.WriteData("$TC_DP3[2,1]", 0)) == c.Accepted()
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G54 G0 X5 Y0 Z0"))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.status().channel.channel_state == "reset", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(15.0)


def test_md_written_while_a_program_is_stopped_waits_for_the_reset(session: Session) -> None:
    session.files.create("PART.MPF", "N10 G1 X50 F600\nN20 M30\n")
    nck = kernel(session, referenced=True)
    nck.submit(c.EnterPassword("EVENING"))
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram("PART.MPF")) == c.Accepted()
    nck.submit(c.CycleStart())
    nck.run_until(lambda k: k.positions_mcs()["X"] > 1.0, 10.0)
    nck.submit(c.CycleStop())
    nck.step(200)
    assert nck.submit(c.WriteData("MD32200[0,X]", 3)) == c.Accepted()  # POSCTRL_GAIN, so
    assert isinstance(nck.submit(c.ActivateMachineData()), c.Rejected)  # not while interrupted
    assert gain(nck) != 3
    nck.submit(c.CycleStart())  # the stopped program goes on
    assert nck.run_until(lambda k: k.status().channel.channel_state == "reset", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(50.0, abs=1e-3)
    nck.submit(c.Reset())
    assert gain(nck) == 3


def gain(nck: Nck) -> float:
    """MD32200[0,X] as the kernel's machine has it."""
    value = nck.machine.md_value("MD32200", "X", None)
    return value[0] if isinstance(value, list) else value


def test_the_active_tool_of_a_running_program_cannot_be_deleted(session: Session) -> None:
    # 002 L58406-58407: active compensation data blocks (D numbers) cannot be deleted;
    # after RESET (the program no longer runs) the tool may go.
    nck = kernel(session, motion_factory=instant_motion_factory, referenced=True)
    nck.submit(c.SetKeyswitch(3))  # level 4: tool geometry
    for tool in (7, 8):
        assert nck.submit(c.WriteData(f"$TC_DP1[{tool},1]", 120)) == c.Accepted()
        assert nck.submit(c.WriteData(f"$TC_DP3[{tool},1]", 50)) == c.Accepted()
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("T7 D1 M6\nG1 X100 F100\nM30"))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.positions_mcs()["X"] > 1.0, 10.0)
    assert nck.status().channel.channel_state == "active"
    assert "active tool" in rejected(nck.submit(c.DeleteToolEdge(7)))
    assert (7, 1) in nck.data.tools
    assert nck.submit(c.DeleteToolEdge(8)) == c.Accepted()
    nck.submit(c.Reset())
    assert nck.submit(c.DeleteToolEdge(7)) == c.Accepted()
    assert (7, 1) not in nck.data.tools
