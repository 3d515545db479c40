"""Batched IPO cycles give the same run as cycle-by-cycle stepping.

The kernel hands many IPO cycles to the planned motion at once; the motion
ends such a batch with the cycle of the next block event. These tests run the
same program once with ``batch_cycles=1`` (one cycle per kernel step, the
reference) and once batched, and compare the recorded setpoint trace, the
final state, the machine time and every alarm with the cycle it came in.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck


def _contour(blocks: int) -> str:
    lines = ["N1 G90 G17 G64 G0 X40 Y0 Z5", "N2 G1 Z-1 F800", "N3 S1200 M3 F2500"]
    n = 4
    for k in range(blocks):
        angle = 2.0 * math.pi * (k + 1) / blocks
        r = 40.0 + 4.0 * math.sin(7.0 * angle)
        x, y = r * math.cos(angle), r * math.sin(angle)
        if k % 5 == 4:
            lines.append(f"N{n} G3 X{x:.3f} Y{y:.3f} CR={math.hypot(x, y):.3f}")
        else:
            lines.append(f"N{n} G1 X{x:.3f} Y{y:.3f}")
        n += 1
    return "\n".join(lines) + "\n"


MIXED = _contour(24) + (
    "N100 G60 G1 X10 Y10\n"        # exact stop fine: waits for the window
    "N110 G4 F0.3\n"               # dwell
    "N120 G64 SOFT G1 X-20 Y5 F4000\n"
    "N130 M8\n"                    # an auxiliary function between motions
    "N140 G1 X-25 Y-10\n"
    "N150 R1=$AA_IM[X]\n"          # implicit STOPRE: waits for the axes to stop
    "N160 BRISK G0 X0 Y0 Z10\n"
    "N170 G9 G1 X5 F1000\n"        # non-modal exact stop
    "N180 M30\n"
)


def _run(program: str, batch: int, *, setup=None, pause_cycles: int | None = None, action=None,
         max_s: float = 120.0) -> dict:
    nck = Nck(programs=MemorySource({"P.MPF": program}), referenced=True, batch_cycles=batch)
    nck.motion.enable_trace()
    sizes = _count_steps(nck)
    if setup is not None:
        setup(nck)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    if pause_cycles is not None:
        nck.step(pause_cycles)
        action(nck)
    nck.run_until(lambda k: k.situation.channel != "active", max_s, max_batch_cycles=nck.batch_cycles)
    times, rows = nck.motion.trace()
    return {
        "nck": nck,
        "time_s": nck.time_s,
        "cycles": nck.cycles_done,
        "times": times,
        "rows": rows,
        "positions": nck.positions_mcs(),
        "state": (nck.situation.channel, nck.situation.program),
        "alarms": [(e.number, round(e.came_s / nck.ipo_cycle_s)) for e in nck.alarm_history()],
        "r1": nck.data.r[1],
        "blocks": nck.blocks_interpreted,
        "steps": len(sizes),
        "sizes": sizes,
    }


def _assert_same(single: dict, batched: dict) -> None:
    assert batched["cycles"] == single["cycles"]
    assert batched["time_s"] == pytest.approx(single["time_s"], abs=1e-9)
    assert batched["state"] == single["state"]
    assert batched["alarms"] == single["alarms"]
    assert batched["blocks"] == single["blocks"]
    assert batched["r1"] == pytest.approx(single["r1"], abs=1e-9)
    assert batched["positions"] == pytest.approx(single["positions"], abs=1e-9)
    assert batched["times"].shape == single["times"].shape
    np.testing.assert_allclose(batched["times"], single["times"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(batched["rows"], single["rows"], rtol=0, atol=1e-9)


def _count_steps(nck: Nck) -> list[int]:
    """Wrap the kernel step so the test can see that batching really happened."""
    sizes: list[int] = []
    inner = nck._guarded_cycle

    def counted(limit: int) -> int:
        done = inner(limit)
        sizes.append(done)
        return done

    nck._guarded_cycle = counted  # type: ignore[method-assign]
    return sizes


def test_mixed_program_batched_equals_cycle_by_cycle() -> None:
    single = _run(MIXED, 1)
    batched = _run(MIXED, 2500)
    assert single["state"] == ("reset", "aborted") and single["alarms"] == []
    assert single["r1"] == pytest.approx(-25.0, abs=1e-3)
    _assert_same(single, batched)
    # The batched run really ran long batches (far fewer kernel steps than cycles).
    assert single["steps"] == single["cycles"]
    assert batched["steps"] < single["cycles"] / 8
    assert max(batched["sizes"]) > 20


def test_short_cam_blocks_batched_equal_cycle_by_cycle() -> None:
    """0.5 mm chords at F3000: two or three IPO cycles per block (the Python-float servo path)."""
    lines = ["N1 G90 G17 G64 G1 F3000"]
    for k in range(150):
        angle = k * 0.01
        lines.append(f"G1 X{50.0 * math.cos(angle):.3f} Y{50.0 * math.sin(angle):.3f} Z{-(k % 10) * 0.01:.3f}")
    lines.append("M30")
    program = "\n".join(lines) + "\n"
    single = _run(program, 1)
    batched = _run(program, 2500)
    assert single["state"] == ("reset", "aborted") and single["alarms"] == []
    _assert_same(single, batched)
    assert batched["steps"] < single["cycles"] / 10


def test_feed_override_between_steps_gives_the_same_run() -> None:
    def slower(nck: Nck) -> None:
        assert isinstance(nck.submit(c.SetOverride("feed", 40.0)), c.Accepted)

    single = _run(MIXED, 1, pause_cycles=900, action=slower)
    batched = _run(MIXED, 2500, pause_cycles=900, action=slower)
    _assert_same(single, batched)
    plain = _run(MIXED, 2500)
    assert batched["time_s"] > plain["time_s"] + 0.5  # the override really acted


def test_monitoring_alarm_comes_in_the_same_cycle() -> None:
    program = "N10 G1 X60 F3000\nN20 G1 Y30\nN30 M30\n"

    def jam(nck: Nck) -> None:
        nck.motion.inject_fault("X", jam_at_mm=25.0)

    single = _run(program, 1, setup=jam)
    batched = _run(program, 2500, setup=jam)
    assert single["alarms"], "the jam must trip a monitor"
    assert single["alarms"][0][0] in (25050, 25040, 25060, 25080)
    _assert_same(single, batched)


def test_limit_switch_alarm_before_the_block_is_the_same() -> None:
    program = "N10 G1 X100 F2000\nN20 G1 X700\nN30 M30\n"
    single = _run(program, 1)
    batched = _run(program, 2500)
    assert [number for number, _ in single["alarms"]] == [10720]
    _assert_same(single, batched)


def test_monitor_without_fault_trips_in_the_same_cycle() -> None:
    """A speed-setpoint limit (MD36210) too low for the programmed feed: 25060 mid-block."""
    from tests.motion.helpers import machine

    program = "N10 G1 X5 F500\nN20 G1 X80 F6000\nN30 M30\n"
    low = machine(MD36210={"X": 10.0})

    def run(batch: int) -> dict:
        nck = Nck(machine=low, programs=MemorySource({"P.MPF": program}), referenced=True, batch_cycles=batch)
        nck.motion.enable_trace()
        for command in (c.SelectMode("AUTO"), c.SelectProgram("P.MPF"), c.CycleStart()):
            assert nck.submit(command) == c.Accepted()
        nck.run_until(lambda k: k.situation.channel != "active", 60.0, max_batch_cycles=nck.batch_cycles)
        times, rows = nck.motion.trace()
        return {"alarms": [(e.number, round(e.came_s / nck.ipo_cycle_s)) for e in nck.alarm_history()],
                "times": times, "rows": rows, "cycles": nck.cycles_done, "x": nck.positions_mcs()["X"]}

    single, batched = run(1), run(2500)
    assert [number for number, _ in single["alarms"]] == [25060]
    assert 5.0 < single["x"] < 80.0  # tripped during the second block
    assert batched["alarms"] == single["alarms"]
    assert batched["cycles"] == single["cycles"]
    assert batched["x"] == pytest.approx(single["x"], abs=1e-9)
    np.testing.assert_allclose(batched["rows"], single["rows"], rtol=0, atol=1e-9)


def _golden_cases() -> list[str]:
    from tests.reliability.harness import golden_programs

    return sorted(golden_programs())


@pytest.mark.parametrize("case", _golden_cases())
def test_golden_program_batched_equals_cycle_by_cycle(case: str) -> None:
    """Every golden program: same end time, state, alarms and R parameters batched or not."""
    from tests.reliability.harness import golden_programs, golden_subprograms

    text = golden_programs()[case]
    sources = dict(golden_subprograms())
    sources["P.MPF"] = text
    results = []
    for batch in (1, 2500):
        nck = Nck(programs=MemorySource(sources), referenced=True, batch_cycles=batch)
        nck.motion.enable_trace()
        nck.submit(c.SelectMode("AUTO"))
        nck.submit(c.SelectProgram("P.MPF"))
        nck.submit(c.CycleStart())
        nck.run_until(lambda k: k.situation.channel != "active", 30.0, max_batch_cycles=nck.batch_cycles)
        times, rows = nck.motion.trace()
        results.append({
            "cycles": nck.cycles_done,
            "state": (nck.situation.channel, nck.situation.program),
            "alarms": [(e.number, round(e.came_s / nck.ipo_cycle_s)) for e in nck.alarm_history()],
            "r": dict(nck.data.r) if hasattr(nck.data.r, "items") else list(nck.data.r),
            "rows": rows,
            "blocks": nck.blocks_interpreted,
        })
    single, batched = results
    assert batched["cycles"] == single["cycles"]
    assert batched["state"] == single["state"]
    assert batched["alarms"] == single["alarms"]
    assert batched["blocks"] == single["blocks"]
    assert batched["r"] == single["r"]
    assert batched["rows"].shape == single["rows"].shape
    np.testing.assert_allclose(batched["rows"], single["rows"], rtol=0, atol=1e-9)
