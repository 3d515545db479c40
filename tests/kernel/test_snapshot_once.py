"""The status snapshot is built once per tick or command, not per call, and reading it
creates nothing (issue 21: ``status()`` = the last built snapshot)."""

from __future__ import annotations

import pytest

import nck.kernel
from nck import commands as cmd
from nck.access import AccessControl, AccessState
from nck.build import build_nck
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.machine_data import MachineDataStore
from nck.motion.instant import instant_motion_factory
from nck.ncdata import NcData


def kernel(data: NcData | None = None, created: list | None = None, machine=None):
    return build_nck(machine or load_machine(), data if data is not None else NcData(),
                     MemorySource({"P.MPF": "G0 X10\nM30\n"}), referenced=True,
                     motion_factory=instant_motion_factory,
                     on_interpreter=created.append if created is not None else None)


def wcs(status, axis: str) -> float:
    return next(a.position_wcs for a in status.axes if a.name == axis)


def test_the_power_on_wcs_is_the_same_at_every_read() -> None:
    # A base frame of Z 2.5 (stored, as after power on): WCS Z = MCS Z - 2.5 at once,
    # the first snapshot as the second (the first showed WCS = MCS).
    data = NcData()
    data.base_frame.trans["Z"] = 2.5
    nck_ = kernel(data)
    first, second = nck_.status(), nck_.status()
    mcs_z = next(a.position_mcs for a in first.axes if a.name == "Z")
    assert wcs(first, "Z") == pytest.approx(mcs_z - 2.5)
    assert wcs(second, "Z") == wcs(first, "Z")


def test_frames_stored_after_the_kernel_was_built_show_at_power_on() -> None:
    # Until a program has run, the channel is in its power-on reset state: the WCS follows
    # the stored frames (the HMI's data may be filled after the kernel was wired).
    data = NcData()
    nck_ = kernel(data)
    nck_.status()
    data.base_frame.trans["X"] = -4.0
    nck_.step(1)
    assert wcs(nck_.status(), "X") == pytest.approx(nck_.positions_mcs()["X"] + 4.0)


def test_status_creates_no_interpreter() -> None:
    created: list = []
    nck_ = kernel(created=created)
    before = len(created)
    nck_.status()
    nck_.step(3)
    nck_.status()
    assert len(created) == before
    assert nck_.status().channel.modal.gcodes.get(8) == "G500"  # the reset G codes all the same


def test_the_snapshot_is_built_once_per_tick_not_per_call(monkeypatch: pytest.MonkeyPatch) -> None:
    builds = []
    real = nck.kernel.build_status
    monkeypatch.setattr(nck.kernel, "build_status", lambda src: builds.append(1) or real(src))
    nck_ = kernel()
    for _ in range(3):
        nck_.status()
    assert len(builds) == 1
    nck_.step(1)
    first = nck_.status()
    assert nck_.status() is first and len(builds) == 2
    nck_.submit(cmd.SelectMode("MDA"))
    assert nck_.status().channel.mode == "MDA" and len(builds) == 3
    nck_.status()
    assert len(builds) == 3


def test_the_snapshot_follows_alarms_raised_from_outside() -> None:
    from nck.errors import NcAlarmError

    nck_ = kernel()
    nck_.status()
    nck_.raise_alarm(NcAlarmError(10203, "X"))
    assert 10203 in [a.number for a in nck_.status().alarms]


def test_new_config_gives_the_channel_the_new_machines_interpreter() -> None:
    # After a program ended its interpreter held the channel's state; NEW CONFIG with a
    # changed machine datum replaces it by one of the new machine (it kept the old one).
    created: list = []
    machine = load_machine()
    data = NcData()
    nck_ = kernel(data, created, machine)
    nck_.md_store = MachineDataStore(machine, {}, data.setting_data)
    for command in (cmd.SelectMode("MDA"), cmd.SetMdaProgram("G0 X5\nM30"), cmd.CycleStart()):
        assert isinstance(nck_.submit(command), cmd.Accepted)
    assert nck_.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert isinstance(nck_.submit(cmd.WriteData("MD32000[Y]", 2000)), cmd.Accepted)
    assert isinstance(nck_.submit(cmd.ActivateMachineData()), cmd.Accepted)
    assert nck_.machine is not machine and nck_.machine.md_value("MD32000", "Y", None) == 2000
    holder = nck_.setup.frame_interpreter()
    assert holder.machine is nck_.machine
    assert created[-1] is holder


def test_an_access_level_changed_by_the_session_shows_at_once() -> None:
    # The kernel shares its access control with the data directory's session (nck.build).
    access = AccessControl(AccessState(keyswitch_position=0))
    nck_ = build_nck(load_machine(), NcData(), MemorySource(), access=access,
                     motion_factory=instant_motion_factory)
    assert nck_.status().access_level == 7
    access.set_keyswitch(3)
    assert nck_.status().access_level == 4


def test_any_change_of_the_shared_access_control_makes_the_kept_snapshot_stale() -> None:
    # One rule for every change outside the kernel: the access control's revision moved.
    # A change that leaves the level as it was builds the snapshot again too (same seq:
    # nothing in it changed); without a change the kept snapshot is handed out.
    access = AccessControl(AccessState(keyswitch_position=0))
    nck_ = build_nck(load_machine(), NcData(), MemorySource(), access=access,
                     motion_factory=instant_motion_factory)
    first = nck_.status()
    assert nck_.status() is first
    access.set_keyswitch(0)  # turned to where it was, by the session
    second = nck_.status()
    assert second is not first
    assert (second.seq, second.access_level) == (first.seq, 7)
    assert nck_.status() is second


def test_the_keyswitch_turned_by_the_session_under_a_password_shows_at_once() -> None:
    # 002 L1413-1452, L1455-1458: a password overrides the keyswitch; the switch (four
    # positions) still stands where it was turned, which the snapshot reports (the panel's
    # Alt+T turns on from it). The level stays 3.
    access = AccessControl(AccessState(keyswitch_position=3, password_level=3))
    nck_ = build_nck(load_machine(), NcData(), MemorySource(), access=access,
                     motion_factory=instant_motion_factory)
    assert (nck_.status().access_level, nck_.status().keyswitch_position) == (3, 3)
    access.set_keyswitch(1)
    assert (nck_.status().access_level, nck_.status().keyswitch_position) == (3, 1)
    assert nck_.submit(cmd.SetKeyswitch(0)) == cmd.Accepted()
    assert nck_.status().keyswitch_position == 0


def test_a_kernel_without_access_control_reports_no_keyswitch() -> None:
    assert kernel().status().keyswitch_position is None


def test_an_idle_machine_shows_the_same_snapshot() -> None:
    # The default mill's Z drive holds the axis against gravity: its thermal model warms it a
    # little in every IPO cycle (test_dynamics). The service screen shows r0035 to a tenth of a
    # degree, so the snapshot carries it so: an idle machine's snapshot changes only when a
    # shown tenth changes, and the panel does not redraw 20 times a second for nothing.
    nck_ = build_nck(load_machine("mill3"), NcData(), MemorySource({}), referenced=True)
    seqs = []
    for _ in range(200):                      # 10 s at the panel's 20 refreshes a second
        nck_.tick(0.05)
        seqs.append(nck_.status().seq)
    assert seqs[-1] - seqs[0] <= 1
    for axis in nck_.status().axes:
        temperature = axis.extra.get("motor_temperature_c")
        if temperature is not None:
            assert temperature == round(temperature, 1)
