"""The contact watch in batched kernel steps: every contact in the same cycle as cycle by cycle.

A batched step may run only as many IPO cycles as the tool surely cannot reach a solid in;
the bound is the motion's path velocity ceiling (the velocity now and the limit of every
buffered segment) and is counted again at every block event inside the step, because a block
buffered there can be faster (nck.kernel_contact). Each program runs once with
``batch_cycles=1`` (the reference: one cycle, one straight segment per step) and once batched;
the setpoint of every cycle, the contact events (kind, solid, exact MCS position, cycle) and
the alarms with their cycle must be the same (positions to 1e-9 mm, as in
test_batch_equivalence.py).

Hand values: blank X -50…50, Y -40…40, Z -250…-220 (the default mill set-up); cutter T2
(type 120, L 100, r 5), so the programmed tip touches the top at Z -220 and the left face
at X -55.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np
import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.ncdata import NcData, ToolEdge
from nck.workpiece import default_machine_setup


def _slow_blocks(count: int, z: float) -> list[str]:
    """``count`` 0.5 mm zigzag blocks at F300 (25 IPO cycles each): more than the look-ahead
    buffer (MD28060 = 64) holds, so what follows them is buffered inside a batched step."""
    return [f"G1 X{0.5 * (k % 2):.1f} Y{0.5 * (k // 2):.1f} Z{z}" for k in range(count)]


RAPID_AFTER_SLOW = "\n".join([
    "T2 D1 M6", "G0 X0 Y0 Z-150", "G64 G1 F300", *_slow_blocks(80, -150.0),
    "G0 Z-240",  # rapid into the blank, 70 mm below: 90002 at the top (Z -220)
    "M30",
]) + "\n"

FEED_INTO_BLANK = "\n".join([
    "T2 D1 M6", "G0 X-120 Y0 Z-230", "G64 G1 F300", *[f"G1 X{-120 + 0.5 * (k + 1):.1f}" for k in range(80)],
    "G1 X0 F6000",  # faster, spindle at rest: 90001 at the left face (X -55)
    "M30",
]) + "\n"

CUT_WITH_REVOLUTIONAL_FEED = "\n".join([
    "T2 D1 M6", "G0 X-120 Y0 Z-223", "M3 S2000 G95 F0.1", *[f"G1 X{-120 + 0.5 * (k + 1):.1f}" for k in range(70)],
    "S6000",  # three times the speed: the buffered revolutional feeds follow it
    "G1 X-45",  # cuts 10 mm into the left face (X -55) at 10 mm/s
    "G0 Z-150", "M30",
]) + "\n"


def _run(program: str, batch: int, *, action: Callable[[Nck], Any] | None = None, pause_cycles: int = 0,
         max_s: float = 120.0) -> dict:
    data = NcData()
    data.machine_setup = default_machine_setup("mill")
    data.tools[(2, 1)] = ToolEdge({1: 120.0, 3: 100.0, 6: 5.0})
    nck = Nck(data=data, programs=MemorySource({"P.MPF": program}), referenced=True, batch_cycles=batch)
    nck.motion.enable_trace()
    steps = [0]
    inner = nck._guarded_cycle

    def counted(limit: int) -> int:
        steps[0] += 1
        return inner(limit)

    nck._guarded_cycle = counted  # type: ignore[method-assign]
    for command in (c.SelectMode("AUTO"), c.SelectProgram("P.MPF"), c.CycleStart()):
        assert nck.submit(command) == c.Accepted()
    if action is not None:
        nck.step(pause_cycles)
        action(nck)
    nck.run_until(lambda k: k.situation.channel != "active", max_s, max_batch_cycles=nck.batch_cycles)
    times, rows = nck.motion.trace()
    return {
        "events": [(e.seq, e.kind, e.solid, e.position_mcs, e.tool, e.edge, round(e.time_s / nck.ipo_cycle_s))
                   for e in nck.contact_events()],
        "alarms": [(e.number, round(e.came_s / nck.ipo_cycle_s)) for e in nck.alarm_history()],
        "cycles": nck.cycles_done,
        "times": times,
        "rows": rows,
        "state": (nck.situation.channel, nck.situation.program),
        "steps": steps[0],
    }


def _assert_same(single: dict, batched: dict) -> None:
    """The same cycles; positions to 1e-9 mm (a batch samples with numpy, one cycle with floats)."""
    assert [event[:3] + event[4:] for event in batched["events"]] == [event[:3] + event[4:] for event in single["events"]]
    for mine, reference in zip(batched["events"], single["events"]):
        assert mine[3] == pytest.approx(reference[3], abs=1e-9)
    assert batched["alarms"] == single["alarms"]
    assert batched["cycles"] == single["cycles"]
    assert batched["state"] == single["state"]
    assert batched["rows"].shape == single["rows"].shape
    np.testing.assert_allclose(batched["times"], single["times"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(batched["rows"], single["rows"], rtol=0, atol=1e-9)
    assert batched["steps"] < single["steps"] / 4  # the batched run really ran long steps (not while cutting)


def test_rapid_buffered_inside_a_slow_step_crashes_in_the_same_cycle() -> None:
    """The slow blocks alone would let a step run ~2,800 cycles (70 mm at 5 mm/s); the rapid
    block is buffered inside such a step, and from there the step may run only as far as
    the rapid velocity allows — else the crash came late and elsewhere."""
    single = _run(RAPID_AFTER_SLOW, 1)
    batched = _run(RAPID_AFTER_SLOW, 2500)
    assert [a for a, _ in single["alarms"]] == [90002]
    (crash,) = single["events"]
    assert crash[1] == "crash" and crash[3]["Z"] == pytest.approx(-120.0, abs=1e-6)  # tip -220 + L 100
    _assert_same(single, batched)


def test_faster_feed_buffered_inside_a_step_crashes_in_the_same_cycle() -> None:
    single = _run(FEED_INTO_BLANK, 1)
    batched = _run(FEED_INTO_BLANK, 2500)
    assert [a for a, _ in single["alarms"]] == [90001]
    assert single["events"][0][3]["X"] == pytest.approx(-55.0, abs=1e-6)
    _assert_same(single, batched)


def test_feed_override_raised_between_steps_gives_the_same_contact() -> None:
    def faster(nck: Nck) -> None:
        assert nck.submit(c.SetOverride("feed", 200.0)) == c.Accepted()

    single = _run(FEED_INTO_BLANK, 1, action=faster, pause_cycles=700)
    batched = _run(FEED_INTO_BLANK, 2500, action=faster, pause_cycles=700)
    assert [a for a, _ in single["alarms"]] == [90001]
    _assert_same(single, batched)


def test_revolutional_feed_following_a_new_spindle_speed_cuts_the_same() -> None:
    """G95: a new S raises the feed of the buffered blocks (a replan inside a step)."""
    single = _run(CUT_WITH_REVOLUTIONAL_FEED, 1)
    batched = _run(CUT_WITH_REVOLUTIONAL_FEED, 2500)
    assert single["alarms"] == [] and single["state"] == ("reset", "aborted")
    assert [e[1] for e in single["events"]] == ["scratch"]
    _assert_same(single, batched)
