"""Property (issue 22, Done-when 2): for a blank anywhere and an approach from any side, JOG the
3D probe to contact, then "Measure edge" (the trigger position + the ball radius in the approach
direction, written with Set WO at the setpoint) makes the blank's true face read the setpoint in
the WCS — at any JOG feed and feed override, in continuous JOG and in INC; the probe never passes
the face without switching (its trigger is on the face's plane, it stops inside the overtravel).

Hand values: probe T1 (type 710, length 150 to the ball centre, ball radius 2); the blank a
60 × 40 × 30 box whose low corner is drawn; the probe starts ``gap`` outside the face at the
face's middle (Z: above the top), ball centre at Z −230 for the side faces.

Two conditions the property needs, found by ``make fuzz`` (each a correct crash, not a fault of the
measuring): the probe, loaded at the machine zero (X0 Y0), goes up and down that column before
it moves over the blank, so a blank over X0 Y0 is in its way; and the approach must be slow enough
to brake inside the stylus's overtravel (``PROBE_OVERTRAVEL_MM``, 2 mm): braking from v at the
axis's MD32300 acceleration a takes v²/2a (mill3: Z 2.0 m/s², X and Y 2.5 m/s²), and the stop
starts a cycle or two after the switch, so the drawn cases keep v²/2a within three quarters of
the overtravel. What happens beyond it is its own test below.
"""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings, strategies as st

from nck.commands import (Accepted, CycleStart, Jog, SelectIncrement, SelectMachineFunction, SelectMode,
                          SetActualValue, SetMdaProgram, SetOverride)
from nck.kernel import Nck
from nck.kernel_contact import PROBE_OVERTRAVEL_MM
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from nck.queries import ContactEvents, answer, edge_position, z_surface
from nck.workpiece import Box, MachineSetup

BALL_MM = 2.0
LENGTH_MM = 150.0
SIZE = (60.0, 40.0, 30.0)
SIM_BUDGET_S = 40.0  # simulated seconds per JOG motion: the slowest draw needs < 25

FACES = {  # face: (axis, approach direction)
    "left": ("X", 1), "right": ("X", -1), "front": ("Y", 1), "back": ("Y", -1), "top": ("Z", -1),
}


def kernel(low: tuple[float, float, float], jog_mm_min: float) -> tuple[Nck, Box]:
    machine = load_machine("mill3")
    machine.md["MD32020"] = {axis: jog_mm_min for axis in ("X", "Y", "Z")}  # JOG_VELO
    blank = Box(low, (low[0] + SIZE[0], low[1] + SIZE[1], low[2] + SIZE[2]))
    data = NcData()
    data.machine_setup = MachineSetup(blank=blank)
    data.tools[(1, 1)] = ToolEdge({1: 710.0, 3: LENGTH_MM, 6: BALL_MM})
    return Nck(machine=machine, data=data, referenced=True), blank


def start_outside(nck: Nck, blank: Box, face: str, gap: float) -> None:
    """Probe T1 loaded, its ball centre ``gap`` outside ``face`` at the face's middle (MDA, G500)."""
    (x0, y0, z0), (x1, y1, z1) = blank.low_mcs, blank.high_mcs
    middle = {"X": (x0 + x1) / 2, "Y": (y0 + y1) / 2, "Z": z1 - 10.0}
    outside = {"left": ("X", x0 - BALL_MM - gap), "right": ("X", x1 + BALL_MM + gap),
               "front": ("Y", y0 - BALL_MM - gap), "back": ("Y", y1 + BALL_MM + gap),
               "top": ("Z", z1 + BALL_MM + gap)}[face]
    middle[outside[0]] = outside[1]
    text = (f"T1 D1 M6\nG0 G90 Z{z1 + 60.0:.4f}\nX{middle['X']:.4f} Y{middle['Y']:.4f}\n"
            f"Z{middle['Z']:.4f}\n")
    for command in (SelectMode("MDA"), SetMdaProgram(text), CycleStart()):
        assert nck.submit(command) == Accepted()
    assert nck.run_until(lambda k: k.situation.channel != "active", SIM_BUDGET_S, 2500)
    assert nck.submit(SelectMode("JOG")) == Accepted()


def jog_to_contact(nck: Nck, axis: str, direction: int, increment: int | None) -> None:
    """Continuous JOG (``increment`` None) or INC presses until the probe has switched."""
    if increment is not None:
        assert nck.submit(SelectMachineFunction("INC")) == Accepted()
        assert nck.submit(SelectIncrement(increment)) == Accepted()
    for _ in range(60):  # INC: at most 60 presses (the gap is below 60 increments)
        assert nck.submit(Jog(axis, direction)) == Accepted()
        assert nck.run_until(lambda k: k.situation.channel != "active", SIM_BUDGET_S, 16)
        nck.submit(Jog(axis, 0))
        if any(e.kind == "probe" for e in answer(nck, ContactEvents())) or increment is None:
            return


def measure_edge(nck: Nck, blank: Box, face: str, setpoint: float) -> float:
    """Measure edge from the probe's trigger, Set WO at ``setpoint``; the WCS value of the true face."""
    axis, direction = FACES[face]
    found = [e for e in answer(nck, ContactEvents()) if e.kind == "probe"]
    assert found, "the probe passed the face without switching"
    trigger = found[0].position_mcs
    if axis == "Z":
        edge = z_surface(trigger["Z"], LENGTH_MM, BALL_MM)
    else:
        edge = edge_position(trigger[axis], direction, BALL_MM)
    point = dict(trigger)
    point[axis] = edge
    assert nck.submit(SetActualValue(axis, setpoint, point_mcs=point)) == Accepted()
    true_face = {"left": blank.low_mcs[0], "right": blank.high_mcs[0], "front": blank.low_mcs[1],
                 "back": blank.high_mcs[1], "top": blank.high_mcs[2]}[face]
    # with only a translation in force: WCS = MCS - translation (the PRESET frame, G500)
    return true_face - nck.data.setframe.trans.get(axis, 0.0)  # no entry: no translation


CASES = dict(
    x=st.floats(-300, 200), y=st.floats(-200, 150), z=st.floats(-300, -120),
    face=st.sampled_from(sorted(FACES)), gap=st.floats(0.5, 20.0),
    jog_mm_min=st.sampled_from([100.0, 800.0, 2000.0, 6000.0]),
    override=st.sampled_from([10.0, 50.0, 100.0, 120.0]),
    increment=st.sampled_from([None, 1000, 10000]), setpoint=st.floats(-100, 100),
)


ACCEL_MM_S2 = {"X": 2500.0, "Y": 2500.0, "Z": 2000.0}  # mill3 MD32300 (m/s² × 1000)


def brakes_inside_the_overtravel(axis: str, speed_mm_min: float) -> bool:
    """v²/2a within three quarters of the probe's overtravel (see the module's docstring)."""
    speed_mm_s = speed_mm_min / 60.0
    return speed_mm_s ** 2 / (2.0 * ACCEL_MM_S2[axis]) <= 0.75 * PROBE_OVERTRAVEL_MM


def clear_of_the_machine_zero(x: float, y: float) -> bool:
    """The blank's footprint, widened by the ball, leaves the column over X0 Y0 free."""
    return not (x - BALL_MM - 1.0 < 0.0 < x + SIZE[0] + BALL_MM + 1.0
                and y - BALL_MM - 1.0 < 0.0 < y + SIZE[1] + BALL_MM + 1.0)


def jog_and_measure(x, y, z, face, gap, jog_mm_min, override, increment, setpoint) -> None:
    if jog_mm_min * override / 100.0 < 150.0:
        override = 100.0  # budget: every motion of the draw ends within SIM_BUDGET_S
    assume(clear_of_the_machine_zero(x, y))
    assume(brakes_inside_the_overtravel(FACES[face][0], jog_mm_min * override / 100.0))
    nck, blank = kernel((x, y, z), jog_mm_min)
    start_outside(nck, blank, face, gap)
    assert nck.submit(SetOverride("feed", override)) == Accepted()
    axis, direction = FACES[face]
    jog_to_contact(nck, axis, direction, increment)
    events = answer(nck, ContactEvents())
    assert [e.kind for e in events][:1] == ["probe"], events
    assert not nck.alarms.active  # stopped inside the overtravel: no crash
    assert measure_edge(nck, blank, face, setpoint) == pytest.approx(setpoint, abs=1e-6)


@settings(max_examples=5, deadline=None)
@given(**CASES)
def test_jog_to_contact_and_measure_edge_reads_the_true_face(**case) -> None:
    jog_and_measure(**case)


@pytest.mark.fuzz
@settings(max_examples=150, deadline=None)
@given(**CASES)
def test_jog_to_contact_and_measure_edge_fuzz(**case) -> None:
    jog_and_measure(**case)


def test_jogging_onto_the_top_too_fast_crashes_the_probe() -> None:
    """JOG at 6 m/min down onto the top face: braking from 100 mm/s at Z's 2.0 m/s² takes
    100² / (2 · 2000) = 2.5 mm, more than the stylus's 2 mm overtravel — the probe switches, then
    the crash alarm 90003 stops the channel (the trainer's crash of a probe driven past it)."""
    assert not brakes_inside_the_overtravel("Z", 6000.0)
    nck, blank = kernel((3.0, -100.0, -250.0), 6000.0)
    start_outside(nck, blank, "top", 9.6)
    assert nck.submit(SetOverride("feed", 100.0)) == Accepted()
    jog_to_contact(nck, "Z", -1, None)
    assert [e.kind for e in answer(nck, ContactEvents())][:2] == ["probe", "crash"]
    assert [alarm.number for alarm in nck.alarms.active] == [90003]
