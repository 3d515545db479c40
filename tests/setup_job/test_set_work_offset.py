"""Issue 22: Set WO / PRESET / scratching as kernel commands, ``$P_SETFR`` and its RESET
behaviour (002 L30600-30612 system frames, L31279 PRESET, L31280-31290 MD24006,
L31398-31408 MD24007). Expected values are hand-computed: WCS = MCS − offsets."""

from __future__ import annotations

from dataclasses import replace

import pytest

from nck.access import AccessControl, AccessState
from nck.commands import (Accepted, CycleStart, DeleteActiveWorkOffset, Rejected, Reset, SelectMode,
                          SetActualValue, SetMdaProgram, SetWorkOffsetRotation)
from nck.kernel import Nck
from nck.machine import load_machine
from nck.motion.instant import instant_motion_factory
from nck.ncdata import ToolEdge


RESET_G54 = [0] * 7 + [2] + [0] * 52  # MD20150[7] = 2: G group 8 resets to its 2nd member, G54


def kernel(**md: object) -> Nck:
    machine = load_machine()
    machine = replace(machine, md={**machine.md, **md})
    return Nck(machine=machine, motion_factory=instant_motion_factory, referenced=True)


def mda(nck: Nck, text: str) -> None:
    assert nck.submit(SelectMode("MDA")) == Accepted()
    assert nck.submit(SetMdaProgram(text)) == Accepted()
    assert nck.submit(CycleStart()) == Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0, 2500)
    assert nck.alarms.active == ()


def wcs(nck: Nck) -> dict[str, float]:
    return {a.name: a.position_wcs for a in nck.status().axes if a.kind == "linear"}


def test_set_wo_under_g54_writes_g54_and_shows_at_once() -> None:
    nck = kernel(MD20150=RESET_G54)
    mda(nck, "G54 G0 X30 Y-20 Z5\n")  # G54 is zero: MCS = WCS
    assert nck.submit(SelectMode("JOG")) == Accepted()
    assert nck.submit(SetActualValue("X", 0.0)) == Accepted()
    assert nck.submit(SetActualValue("Y", 10.0)) == Accepted()
    # X: 30 - T = 0 -> T = 30; Y: -20 - T = 10 -> T = -30
    assert nck.data.settable_frames["G54"].trans == pytest.approx({"X": 30.0, "Y": -30.0})
    assert wcs(nck)["X"] == pytest.approx(0.0, abs=1e-9)
    assert wcs(nck)["Y"] == pytest.approx(10.0, abs=1e-9)
    assert nck.data.setframe.trans == {}
    mda(nck, "G54 G0 X0 Y0\n")  # a program now goes to the new zero
    mcs = {a.name: a.position_mcs for a in nck.status().axes}
    assert (mcs["X"], mcs["Y"]) == pytest.approx((30.0, -30.0))


def test_preset_under_g500_goes_into_p_setfr_readable_in_programs() -> None:
    nck = kernel()
    mda(nck, "G500 G0 X40 Y0 Z0\n")
    assert nck.submit(SetActualValue("X", 15.0)) == Accepted()
    assert nck.data.setframe.trans == pytest.approx({"X": 25.0})  # 40 - 25 = 15
    assert wcs(nck)["X"] == pytest.approx(15.0)
    assert nck.data.settable_frames["G54"].trans == {}
    mda(nck, "R1=$P_SETFR[X,TR]\n$P_SETFR[Y,TR]=-4\nG500\nG0 Y0\n")
    assert nck.data.r[1] == pytest.approx(25.0)
    assert {a.name: a.position_mcs for a in nck.status().axes}["Y"] == pytest.approx(-4.0)


def test_workpiece_point_gets_the_value_without_the_tool_offset() -> None:
    nck = kernel()
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0, 6: 5.0})
    mda(nck, "T1 D1 G54 G0 X0 Y0 Z50\n")
    # The measured edge X = -50 (MCS) becomes X 0 of G54; Z surface -220 becomes Z 0.
    assert nck.submit(SetActualValue("X", 0.0, "G54", {"X": -50.0, "Y": 0.0, "Z": 0.0})) == Accepted()
    assert nck.submit(SetActualValue("Z", 0.0, "G54", {"X": 0.0, "Y": 0.0, "Z": -220.0})) == Accepted()
    assert nck.data.settable_frames["G54"].trans == pytest.approx({"X": -50.0, "Z": -220.0})


def test_rotated_work_offset_is_set_along_the_rotated_axes() -> None:
    nck = kernel(MD20150=RESET_G54)
    mda(nck, "G54 G0 X0 Y0 Z0\n")
    assert nck.submit(SetWorkOffsetRotation(30.0)) == Accepted()
    corner = {"X": 10.0, "Y": 20.0, "Z": 0.0}
    assert nck.submit(SetActualValue("X", 0.0, point_mcs=corner)) == Accepted()
    assert nck.submit(SetActualValue("Y", 0.0, point_mcs=corner)) == Accepted()
    # With T = corner, the corner is the WCS origin whatever the rotation.
    assert nck.data.settable_frames["G54"].trans == pytest.approx({"X": 10.0, "Y": 20.0})
    mda(nck, "G54 G0 X10 Y0\n")  # 10 mm along the rotated X axis
    mcs = {a.name: a.position_mcs for a in nck.status().axes}
    assert (mcs["X"], mcs["Y"]) == pytest.approx((10.0 + 10.0 * 0.8660254037844387, 20.0 + 5.0))


def test_delete_active_wo_and_reset_behaviour_of_p_setfr() -> None:
    nck = kernel()
    mda(nck, "G500 G0 X40\n")
    nck.submit(SetActualValue("X", 0.0))
    assert nck.submit(Reset()) == Accepted()
    assert wcs(nck)["X"] == pytest.approx(0.0)  # MD24006 bit 0 (trainer default 1): still active
    assert nck.submit(DeleteActiveWorkOffset()) == Accepted()
    assert nck.data.setframe.trans == {} and wcs(nck)["X"] == pytest.approx(40.0)


def test_md24007_deletes_and_md24006_deactivates_the_preset_frame_at_reset() -> None:
    cleared = kernel(MD24007=1)
    mda(cleared, "G500 G0 X40\n")
    cleared.submit(SetActualValue("X", 0.0))
    cleared.submit(Reset())
    assert cleared.data.setframe.trans == {} and wcs(cleared)["X"] == pytest.approx(40.0)
    inactive = kernel(MD24006=0)
    mda(inactive, "G500 G0 X40\n")
    inactive.submit(SetActualValue("X", 0.0))
    inactive.submit(Reset())
    assert inactive.data.setframe.trans == {"X": 40.0}  # kept in the data …
    assert wcs(inactive)["X"] == pytest.approx(40.0)  # … but inactive after RESET
    mda(inactive, "R2=1\n")  # a program without G500/G54 leaves it inactive
    assert wcs(inactive)["X"] == pytest.approx(40.0)
    mda(inactive, "R3=$AA_IW[X]\nG500\nR4=$AA_IW[X]\n")  # G500 activates it again (002 L30660-30664)
    assert (inactive.data.r[3], inactive.data.r[4]) == pytest.approx((40.0, 0.0))


def test_without_the_system_frame_preset_is_refused_and_the_variable_unknown() -> None:
    nck = kernel(MD28082=32)
    assert isinstance(nck.submit(SetActualValue("X", 0.0)), Rejected)  # G500 active
    assert nck.submit(SelectMode("MDA")) == Accepted()
    nck.submit(SetMdaProgram("R1=$P_SETFR[X,TR]\n"))
    nck.submit(CycleStart())
    nck.run_until(lambda k: k.situation.channel != "active", 5.0, 2500)
    assert 12550 in [a.number for a in nck.alarms.active]


def test_levels_work_offset_md9210_and_preset_md9220() -> None:
    nck = Nck(motion_factory=instant_motion_factory, referenced=True,
              access=AccessControl(AccessState(keyswitch_position=0)))  # level 7
    refused = nck.submit(SetActualValue("X", 0.0))  # PRESET needs level 5 (MD9220 default)
    assert isinstance(refused, Rejected)
    assert isinstance(nck.submit(SetActualValue("X", 0.0, "G54")), Rejected)
    assert nck.data.setframe.trans == {} and nck.data.settable_frames["G54"].trans == {}


def test_set_wo_is_refused_while_the_channel_is_active() -> None:
    nck = kernel()
    nck.submit(SelectMode("MDA"))
    nck.submit(SetMdaProgram("G1 X100 F100\n"))
    nck.submit(CycleStart())
    nck.step(5)
    assert isinstance(nck.submit(SetActualValue("X", 0.0)), Rejected)
