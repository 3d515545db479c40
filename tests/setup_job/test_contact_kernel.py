"""Issue 22: contact in the kernel — a 3D probe switches at the exact surface, a turning
cutter scratches, a crash stops the motion with a trainer alarm (90001-90003, not SINUMERIK
numbers) that is in the alarm log; in JOG, INC, MDA, at any override, never jumped over.

Hand values: blank X -50…50, Y -40…40, Z -250…-220 (the default mill set-up); probe T1
(type 710, length 150 to the ball centre, ball radius 2); cutter T2 (type 120, L 100, r 5).
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from nck.commands import (Accepted, CycleStart, Jog, Reset, SelectIncrement, SelectMachineFunction, SelectMode,
                          SetMdaProgram, SetOverride, WriteMachineSetup)
from nck.contact import clearance
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from nck.queries import AlarmHistory, ContactEvents, ProbeDeflected, answer
from nck.workpiece import Box, MachineSetup, default_machine_setup


def kernel(setup: MachineSetup | None = None) -> Nck:
    data = NcData()
    data.machine_setup = setup or default_machine_setup("mill")
    data.tools[(1, 1)] = ToolEdge({1: 710.0, 3: 150.0, 6: 2.0})
    data.tools[(2, 1)] = ToolEdge({1: 120.0, 3: 100.0, 6: 5.0})
    return Nck(data=data, referenced=True)


def mda(nck: Nck, text: str) -> None:
    assert nck.submit(SelectMode("MDA")) == Accepted()
    assert nck.submit(SetMdaProgram(text)) == Accepted()
    assert nck.submit(CycleStart()) == Accepted()
    assert nck.run_until(lambda k: k.situation.channel != "active", 120.0, 2500)


def jog_until_stopped(nck: Nck, axis: str, direction: int, rapid: bool = False) -> None:
    assert nck.submit(SelectMode("JOG")) == Accepted()
    assert nck.submit(Jog(axis, direction, rapid)) == Accepted()
    assert nck.run_until(lambda k: k.situation.channel != "active", 60.0, 16)
    nck.submit(Jog(axis, 0))


def events(nck: Nck) -> list:
    return list(answer(nck, ContactEvents()))


@pytest.mark.parametrize("start, axis, direction, trigger", [
    ("X-80 Y0 Z-230", "X", +1, {"X": -52.0}),   # left face -50, ball r 2
    ("X80 Y0 Z-230", "X", -1, {"X": 52.0}),     # right face 50
    ("X0 Y-70 Z-230", "Y", +1, {"Y": -42.0}),   # front face -40
    ("X0 Y0 Z-200", "Z", -1, {"Z": -68.0}),     # top -220: ball centre -218, machine Z -218 + 150
])
def test_probe_in_jog_switches_at_the_surface_and_stops(start: str, axis: str, direction: int,
                                                       trigger: dict[str, float]) -> None:
    nck = kernel()
    mda(nck, f"T1 D1 M6\nG0 {start}\n")
    jog_until_stopped(nck, axis, direction)
    (event,) = events(nck)
    assert event.kind == "probe" and event.solid == "blank" and event.tool == 1
    assert event.position_mcs[axis] == pytest.approx(trigger[axis], abs=1e-6)
    assert answer(nck, ProbeDeflected()) is True
    stop = nck.positions_mcs()[axis]
    assert 0.0 <= direction * (stop - trigger[axis]) < 2.0  # braked inside the probe's overtravel
    assert nck.alarms.active == ()


def test_inc_with_big_increments_at_200_percent_never_jumps_over_the_face() -> None:
    nck = kernel()
    mda(nck, "T1 D1 M6\nG0 X-81.3 Y0 Z-230\n")
    nck.submit(SelectMode("JOG"))
    nck.submit(SetOverride("feed", 200.0))
    nck.submit(SelectMachineFunction("INC"))
    nck.submit(SelectIncrement(10000))  # 10 mm per press
    for _ in range(3):
        assert nck.submit(Jog("X", +1)) == Accepted()
        nck.run_until(lambda k: k.situation.channel != "active", 30.0, 16)
    (event,) = events(nck)
    assert event.position_mcs["X"] == pytest.approx(-52.0, abs=1e-6)
    assert nck.positions_mcs()["X"] < -50.0


def test_probe_driven_on_is_a_crash_in_the_alarm_log() -> None:
    nck = kernel()
    mda(nck, "T1 D1 M6\nG0 X-80 Y0 Z-230\n")
    jog_until_stopped(nck, "X", +1)
    jog_until_stopped(nck, "X", +1)  # again into the surface
    crash = events(nck)[-1]
    assert crash.kind == "crash" and crash.position_mcs["X"] == pytest.approx(-50.0, abs=1e-6)  # 2 mm overtravel
    assert [a.number for a in nck.alarms.active] == [90003]
    assert 90003 in [entry.number for entry in answer(nck, AlarmHistory())]
    jog_until_stopped(nck, "X", +1)  # driven on once more: stopped again, one alarm
    assert nck.positions_mcs()["X"] < -49.0 and len(nck.alarms.active) == 1
    assert nck.submit(Reset()) == Accepted() and nck.alarms.active == ()


def test_cutter_with_the_spindle_at_rest_crashes_and_stops_the_program() -> None:
    nck = kernel()
    mda(nck, "T2 D1 M6\nG0 X-80 Y0 Z-230\nG1 X0 F500\n")
    assert [a.number for a in nck.alarms.active] == [90001]
    (crash,) = events(nck)
    assert crash.kind == "crash" and crash.position_mcs["X"] == pytest.approx(-55.0, abs=1e-6)
    assert nck.situation.channel == "interrupted"
    assert nck.positions_mcs()["X"] < -54.0  # braked after the contact, not through the blank


def test_rapid_into_the_blank_is_a_crash_even_with_the_spindle_turning() -> None:
    nck = kernel()
    mda(nck, "T2 D1 M6\nG0 X-80 Y0 Z-230\nM3 S1000\nG0 X0\n")
    assert [a.number for a in nck.alarms.active] == [90002]
    assert events(nck)[0].position_mcs["X"] == pytest.approx(-55.0, abs=1e-6)


def test_turning_cutter_scratches_without_an_alarm() -> None:
    nck = kernel()
    mda(nck, "T2 D1 M6\nG0 X-80 Y0 Z-221\nM3 S1000\nG1 X-54.99 F200\nG0 Z-150\nM30\n")
    assert nck.alarms.active == ()
    (scratch,) = events(nck)
    assert scratch.kind == "scratch" and scratch.position_mcs["X"] == pytest.approx(-55.0, abs=1e-6)
    assert nck.situation.channel == "reset"


BLANKS = dict(x=st.floats(-200, 200), y=st.floats(-150, 150), angle=st.floats(0, 360),
              feed=st.sampled_from([300, 2000, 8000]), override=st.sampled_from([50.0, 100.0, 200.0]))


@settings(max_examples=8, deadline=None)
@given(**BLANKS)
def test_probing_a_blank_anywhere_from_any_direction_triggers_on_its_surface(x, y, angle, feed, override) -> None:
    probe_blank(x, y, angle, feed, override)


@pytest.mark.fuzz
@settings(max_examples=200, deadline=None)
@given(**BLANKS)
def test_probing_fuzz(x, y, angle, feed, override) -> None:
    probe_blank(x, y, angle, feed, override)


def probe_blank(x: float, y: float, angle: float, feed: int, override: float) -> None:
    # Hypothesis: random blank position and approach direction in the XY plane, feed and override.
    blank = Box((x, y, -250.0), (x + 60.0, y + 40.0, -220.0))
    nck = kernel(MachineSetup(blank=blank))
    cx, cy = x + 30.0, y + 20.0
    dx, dy = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    sx, sy = cx - 45.0 * dx, cy - 45.0 * dy  # 45 mm from the centre: outside the 60 x 40 block
    nck.submit(SetOverride("feed", override))
    mda(nck, f"T1 D1 M6\nG0 X{sx:.4f} Y{sy:.4f}\nZ-230\nG1 X{cx:.4f} Y{cy:.4f} F{feed}\n")
    body, offset = nck.contact_watch.tool_body()
    found = events(nck)
    assert [e.kind for e in found] == ["probe", "crash"]  # switched, then driven on past overtravel
    assert [a.number for a in nck.alarms.active] == [90003]
    for event, depth in zip(found, (0.0, 2.0)):
        at = event.position_mcs
        assert clearance(body, blank, (at["X"], at["Y"], at["Z"] - offset[2])) == pytest.approx(-depth, abs=1e-6)
    assert nck.situation.channel == "interrupted"  # the crash stopped the program


def lathe_kernel() -> Nck:
    data = NcData()
    data.machine_setup = default_machine_setup("lathe")  # bar Ø60, chuck face Z 200, free end Z 300
    data.tools[(1, 1)] = ToolEdge({1: 500.0, 2: 3.0, 6: 0.8})  # roughing tool, cutting edge radius 0.8
    return Nck(machine=load_machine("lathe2"), data=data, referenced=True)


def test_lathe_tool_scratches_the_turning_bar_and_crashes_into_a_standing_one() -> None:
    nck = lathe_kernel()
    mda(nck, "T1 D1\nG0 X100\nZ250\nM3 S500\nG1 X29.99 F100\nG0 X100\nM30\n")
    (scratch,) = events(nck)  # the edge's radius touches the bar's radius 30 at X 30.8
    assert scratch.kind == "scratch" and scratch.position_mcs["X"] == pytest.approx(30.8, abs=1e-6)
    assert nck.alarms.active == ()
    nck = lathe_kernel()
    mda(nck, "T1 D1\nG0 X100\nZ320\nX20\nG94 G1 Z250 F300\n")  # the free end face, spindle at rest
    assert [a.number for a in nck.alarms.active] == [90001]
    assert events(nck)[0].position_mcs["Z"] == pytest.approx(300.8, abs=1e-6)


def test_meas_and_meaw_in_a_program_give_the_trigger_position_and_the_probe_status() -> None:
    nck = kernel()
    nck.data.settable_frame("G54").trans["X"] = -100.0  # WCS X = MCS X + 100
    mda(nck, "T1 D1 M6\nG54 G0 X20 Y0 Z-230\n"       # machine X -80
             "MEAS=1 G1 X100 F500\n"                  # towards machine X 0: switches at -52
             "R1=$AA_MM[X]\nR2=$AA_MW[X]\nR3=$AC_MEA[1]\nR7=$AA_IM[X]\n"
             "G1 X30\n"
             "MEAW=1 G1 X49 F300\n"                   # machine -51: switches at -52, goes on
             "R4=$AA_MM[X]\nR5=$AC_MEA[1]\nR8=$AA_IM[X]\n"
             "G0 X20\nMEAS=1 G1 X40\nR6=$AC_MEA[1]\nM30\n")  # ends before the face: no switch
    r = nck.data.r
    assert nck.alarms.active == ()
    assert (r[1], r[2], r[3]) == pytest.approx((-52.0, 48.0, 1.0), abs=1e-6)
    assert -52.0 < r[7] < -50.0  # MEAS deleted the distance to go: braked within the overtravel
    assert (r[4], r[5]) == pytest.approx((-52.0, 1.0), abs=1e-6)
    assert r[8] == pytest.approx(-51.0, abs=1e-6)  # MEAW: the block ran to its end
    assert r[6] == 0.0  # reached its end without a switch: status 0, no alarm (trainer choice)
    assert nck.positions_mcs()["X"] == pytest.approx(-60.0)


@pytest.mark.parametrize("depth_mm", [0.0, 1e-9])
def test_rapid_off_a_surface_the_tool_rests_on_is_no_crash(depth_mm: float) -> None:
    """The cutter's tip rests on the blank's top without having been seen arriving (found in
    tmux: ten INC 0.1 steps end a float's breadth from the top, then the tool length was
    measured; here the instructor moves the blank under the resting tool, its top where the tip
    is, WCS = MCS − L: tip Z -210): G0 up takes it off the surface, which is no contact — not
    crash 90002; back down 0.5 mm into the blank at rapid is still one."""
    nck = kernel()
    mda(nck, "T2 D1 M6\nM3 S1000\nG0 X0 Y0 Z-210\n")
    assert nck.alarms.active == () and events(nck) == []
    top = -210.0 + depth_mm
    assert nck.submit(WriteMachineSetup(MachineSetup(blank=Box((-50.0, -40.0, -250.0), (50.0, 40.0, top))))) \
        == Accepted()
    mda(nck, "G0 Z-150\n")
    assert nck.alarms.active == () and events(nck) == []
    mda(nck, "G0 Z-210.5\n")
    assert [a.number for a in nck.alarms.active] == [90002]
