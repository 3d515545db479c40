"""Retained data with the kernel: MD changes reach the axes after the restart they need."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as c
from nck.access import Action, AccessDenied
from nck.kernel import Nck
from nck.persistence import Session


def rapid_time_s(session: Session) -> float:
    """Seconds a kernel built from the session needs for G0 X100 in MDA."""
    nck = Nck(machine=session.active_machine(), data=session.ncdata,
              programs=session.files, referenced=True)
    assert nck.submit(c.SelectMode("MDA")) == c.Accepted()
    assert nck.submit(c.SetMdaProgram("G0 X100")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 99.999, 60.0)
    return nck.status().time_s


def test_evening_changes_md32000_and_it_limits_rapid_after_new_config(tmp_path: Path) -> None:
    session = Session.open(tmp_path, install_samples=False)
    fast = rapid_time_s(session)
    with pytest.raises(AccessDenied):
        session.md.write("MD32000[X]", 1200, level=session.access.level)
    session.access.enter_password("EVENING")
    result = session.md.write("MD32000[X]", 1200, level=session.access.level)
    assert result.takes_effect.startswith("at NEW CONFIG")
    assert rapid_time_s(session) == pytest.approx(fast)  # stored, not active yet
    session.md.activate("new_config")
    slow = rapid_time_s(session)
    assert slow == pytest.approx(100 / 1200 * 60, rel=0.05)
    assert slow > 10 * fast
    session.save()
    assert rapid_time_s(Session.open(tmp_path, install_samples=False)) == pytest.approx(slow)


def test_keyswitch_0_cannot_change_work_offset_customer_can(tmp_path: Path) -> None:
    session = Session.open(tmp_path, install_samples=False)
    with pytest.raises(AccessDenied):
        session.access.require_write("$P_UIFR[1,X,TR]")
    session.access.enter_password("CUSTOMER")
    session.access.require_write("$P_UIFR[1,X,TR]")
    session.ncdata.settable_frame("G54").trans["X"] = 10.0
    session.save()
    restarted = Session.open(tmp_path, install_samples=False)
    assert restarted.ncdata.settable_frames["G54"].trans["X"] == 10.0
    assert restarted.access.level == 3


def test_programs_of_the_data_dir_run_in_the_kernel(tmp_path: Path) -> None:
    session = Session.open(tmp_path, install_samples=False)
    session.files.create("PART1.MPF", "N10 G0 X20\nN20 L10\nN30 M30\n")
    session.files.create("L10.SPF", "N10 G0 Y5\nN20 M17\n")
    nck = Nck(machine=session.active_machine(), data=session.ncdata,
              programs=session.files, referenced=True)
    assert session.access.may(Action.READ_PROGRAM)
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram("PART1.MPF")) == c.Accepted()
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.status().channel.channel_state == "reset", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(20.0)
    assert nck.positions_mcs()["Y"] == pytest.approx(5.0)


def test_kernel_arguments_and_startup_alarms(tmp_path: Path) -> None:
    Session.open(tmp_path, install_samples=False).save()
    (tmp_path / "retained" / "counters.json").write_text("garbage")
    session = Session.open(tmp_path, install_samples=False)
    nck = Nck(**session.kernel_arguments(), referenced=True)
    for alarm in session.startup_alarms:
        nck.raise_alarm(alarm)
    numbers = [a.number for a in nck.status().alarms]
    assert numbers == [4060]
    assert "counters.json" in nck.status().alarms[0].text
    session.access.set_keyswitch(3)
    assert nck.status().access_level == 4
