"""G641 with ADIS / ADISPOS: corners rounded by a path distance (nck.geometry.rounding_distance)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck import canon
from nck.errors import NcAlarmError
from nck.geometry.circles import Arc, arc_from_center
from nck.geometry.contour_aids import LineElement
from nck.geometry.planes import plane
from nck.geometry.rounding_distance import round_by_distance
from nck.headless import interpret_only, run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.motion.helpers import derivatives
from tests.motion.test_dynamics import AMAX, OVL, VMAX

MILL = load_machine("mill3")
G17 = plane("G17")
MANUAL_EXAMPLE = "N1 G641 Y50 F10 ADIS=0.5\nN2 X50\nN3 X50.7\nN4 Y50.5\nN5 Y51\nN6 X55\nN7 M30\n"


def _motions(text: str) -> list[canon.Motion]:
    out: list[canon.Motion] = []
    result = interpret_only(MILL, MemorySource({"P.MPF": text}), NcData(), "P.MPF",
                            on_command=lambda c: out.append(c) if isinstance(c, canon.Motion) else None)
    assert not result.alarms, result.alarms
    return out


def _xy(motion: canon.Motion) -> tuple[float, float]:
    return motion.end_wcs["X"], motion.end_wcs["Y"]


def _arcs(motions: list[canon.Motion]) -> list[canon.Motion]:
    return [m for m in motions if m.kind in ("G2", "G3")]


def test_the_manual_example_rounds_with_the_distance_and_the_short_block_rule() -> None:
    motions = _motions(MANUAL_EXAMPLE)
    ends = [(m.source.line, m.kind, _xy(m)) for m in motions]
    assert ends == [
        (1, "G1", (0.0, 49.5)), (1, "G2", (0.5, 50.0)),  # 90° corner: 0.5 before and after
        (2, "G1", (50.0, 50.0)),  # N2 → N3 straight on: tangential, nothing inserted
        (3, "G1", (50.5, 50.0)), (3, "G3", (50.7, 50.2)),  # N4 is 0.5 long (< 4·ADIS): 40 % = 0.2
        (4, "G1", (50.7, 50.5)),  # N4 → N5 straight on
        (5, "G1", (50.7, 50.8)), (5, "G2", (50.9, 51.0)),  # N5 is 0.5 long again: 0.2
        (6, "G1", (55.0, 51.0)),
    ]
    first = motions[1]
    assert first.center_wcs is not None
    assert (first.center_wcs["X"], first.center_wcs["Y"]) == pytest.approx((0.5, 49.5))


def test_line_line_tangent_points_are_the_distance_from_the_corner_and_tangent() -> None:
    for degrees in (20.0, 60.0, 90.0, 135.0, 170.0):
        turn = math.radians(degrees)
        first = LineElement((0.0, 0.0, 0.0), (10.0, 0.0, 0.0))
        second = LineElement((10.0, 0.0, 0.0), (10.0 + 10 * math.cos(turn), 10 * math.sin(turn), 0.0))
        cut = round_by_distance(G17, first, second, 1.5)
        arc = cut.inserted
        assert isinstance(arc, Arc)
        assert math.dist(cut.first.end, (10.0, 0.0, 0.0)) == pytest.approx(1.5)
        assert math.dist(cut.second.start, (10.0, 0.0, 0.0)) == pytest.approx(1.5)
        # Tangency: the radius at each end is perpendicular to the line there.
        assert (arc.start[0] - arc.center[0]) * 1.0 == pytest.approx(0.0, abs=1e-9)
        radial_end = (arc.end[0] - arc.center[0], arc.end[1] - arc.center[1])
        assert radial_end[0] * math.cos(turn) + radial_end[1] * math.sin(turn) == pytest.approx(0.0, abs=1e-9)


def test_a_corner_with_an_arc_stays_within_the_distance() -> None:
    first = LineElement((0.0, 0.0, 0.0), (10.0, 0.0, 0.0))
    second = arc_from_center(G17, (10.0, 0.0, 0.0), (20.0, 10.0, 0.0), (20.0, 0.0, 0.0), clockwise=False)
    cut = round_by_distance(G17, first, second, 1.0)
    assert cut.inserted is not None
    assert math.dist(cut.first.end, (10.0, 0.0, 0.0)) <= 1.0 + 1e-9
    assert second.radius * second.sweep_rad - cut.second.radius * cut.second.sweep_rad <= 1.0 + 1e-9


def test_g641_without_a_distance_is_g64() -> None:
    body = "G90 G17 G1 X0 Y0 F1000\nX40\nY40\nX0 Y0\nM30\n"
    plain = _motions(body.replace("G90", "G64 G90"))
    g641 = _motions(body.replace("G90", "G641 G90"))
    assert [(m.source.line, m.kind, _xy(m)) for m in g641] == [(m.source.line, m.kind, _xy(m)) for m in plain]
    assert not _arcs(g641)


def test_exact_stop_blocks_are_not_rounded() -> None:
    # G60 belongs to the same G group as G641: it ends continuous-path mode (ADIS stays set).
    with_g60 = _motions("G641 ADIS=1 G1 X10 F500\nY10\nG60 X0\nY0\nM30\n")
    # The block that ends at a corner decides: N1 and N2 (G641) are rounded, N3 (G60) is not.
    assert [m.source.line for m in _arcs(with_g60)] == [1, 2]
    with_g9 = _motions("G641 ADIS=1 G1 X10 F500\nG9 Y10\nX0\nM30\n")
    assert [m.source.line for m in _arcs(with_g9)] == [1]  # N2 ends with G9: its corner stays sharp


def test_g0_uses_adispos_and_the_smaller_value_at_a_change_to_feed() -> None:
    motions = _motions("G641 ADIS=0.5 ADISPOS=3 G0 X20 Y0\nG1 Y20 F800\nX0\nG0 X0 Y0\nX-20\nM30\n")
    arcs = _arcs(motions)
    # G0 → G1: min(0.5, 3); G1 → G1: 0.5; G1 → G0: 0.5; G0 → G0: not rounded (no rapid circles).
    assert [m.source.line for m in arcs] == [1, 2, 3]
    first = motions[0]
    assert _xy(first) == pytest.approx((19.5, 0.0))


def test_a_block_with_outputs_in_between_ends_the_rounding() -> None:
    motions = _motions("G641 ADIS=2 G1 X50 F3000\nM8\nY50\nX0\nM30\n")
    assert [m.source.line for m in _arcs(motions)] == [3]  # not at N1 (M8 after it), at N3


def test_reading_main_run_data_releases_the_held_block_first() -> None:
    text = "G641 ADIS=2 G1 X50 F3000\nY50\nR1=$AA_IM[Y]\nX0\nM30\n"
    result = run_program(MILL, MemorySource({"P.MPF": text}), NcData(), "P.MPF")
    assert result.status == "ended" and not result.alarms
    # N2 is executed to its end point before N3 reads the position (no rounding into N4).
    data = NcData()
    run_program(MILL, MemorySource({"P.MPF": text}), data, "P.MPF")
    assert data.r[1] == pytest.approx(50.0, abs=1e-6)


def test_rnd_before_a_main_run_read_is_released_too() -> None:
    data = NcData()
    text = "G90 G17 G1 X0 Y0 F3000\nX50 RND=5\nR1=$AA_IM[X]\nY50\nM30\n"
    run_program(MILL, MemorySource({"P.MPF": text}), data, "P.MPF")
    assert data.r[1] == pytest.approx(50.0, abs=1e-6)


def test_negative_distance_is_16500_and_reset_clears_the_distance() -> None:
    with pytest.raises(NcAlarmError) as raised:
        from nck.interp.interpreter import Interpreter

        interp = Interpreter(MILL, MemorySource({}), NcData())
        interp.start_text("P.MPF", "G641 ADIS=-1 G1 X1 F100\n")
        interp.step()
    assert raised.value.number == 16500
    interp = Interpreter(MILL, MemorySource({}), NcData())
    interp.start_text("P.MPF", "G641 ADIS=1 ADISPOS=2 G1 X1 F100\nM30\n")
    interp.step()
    geometry = interp.modal.geometry
    assert (geometry.adis_mm, geometry.adispos_mm) == (1.0, 2.0)
    interp.reset()
    assert (interp.modal.geometry.adis_mm, interp.modal.geometry.adispos_mm) == (0.0, 0.0)


def test_the_manual_example_checks_clean(tmp_path) -> None:
    from nck.cli import main

    path = tmp_path / "ADIS.MPF"
    path.write_text(MANUAL_EXAMPLE)
    assert main(["check", "--ephemeral", "--data-dir", str(tmp_path / "data"), str(path)]) == 0


def _zigzag(mode: str) -> str:
    lines = ["G90 G17 G0 X0 Y0 Z0", f"{mode} G1 F3000"]
    lines += [f"X{10 * (k + 1)} Y{10 if k % 2 == 0 else 0}" for k in range(20)]
    return "\n".join(lines + ["M30"]) + "\n"


RUN_BUDGET_S = 600.0
"""Simulated seconds a traced run may take (the drawn contours need under 100 s): a property
test that runs programs has a time budget."""


def _run_traced(text: str):
    motions: list = []

    def trace(motion) -> None:
        motion.enable_trace()
        motions.append(motion)

    result = run_program(MILL, MemorySource({"P.MPF": text}), NcData(), "P.MPF", on_motion=trace,
                         timeout_s=RUN_BUDGET_S)
    assert result.status == "ended" and not result.alarms
    return result, motions[-1]


def test_rounding_makes_a_zigzag_faster_and_keeps_the_axis_limits() -> None:
    g64, _ = _run_traced(_zigzag("G64"))
    g641, motion = _run_traced(_zigzag("G641 ADIS=2"))
    # 90° corners: G64 slows almost to a stop, the 2 mm circles are passed at ≈ 50 mm/s.
    assert g641.machine_time_s < g64.machine_time_s * 0.95
    _assert_within_machine_data(motion)


def _assert_within_machine_data(motion) -> None:
    rows, v, a, _j = derivatives(motion)
    assert np.all(np.abs(v) <= VMAX * (1 + 1e-6) + 1e-6)
    assert np.all(np.abs(a) <= AMAX * OVL * (1 + 1e-6) + 1e-3)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.integers(-40, 40), st.integers(-40, 40)), min_size=2, max_size=10),
       st.sampled_from([0.2, 1.0, 5.0]), st.sampled_from([800, 4000, 12000]))
def test_random_g641_contours_keep_the_axis_limits(points, distance, feed) -> None:
    lines = ["G90 G17 G0 X0 Y0 Z0", f"G641 ADIS={distance} F{feed}"]
    lines += [f"G1 X{x} Y{y}" for x, y in points]
    _, motion = _run_traced("\n".join(lines + ["M30"]) + "\n")
    _assert_within_machine_data(motion)
    x, y = points[-1]
    assert motion.positions_mcs()["X"] == pytest.approx(x, abs=1e-6)
    assert motion.positions_mcs()["Y"] == pytest.approx(y, abs=1e-6)


def test_the_transition_feed_is_limited_to_the_distance_per_ipo_cycle() -> None:
    motions = _motions("G90 G17 G641 ADIS=0.1 G1 X10 F20000\nY10\nX0\nM30\n")
    arcs = _arcs(motions)
    assert len(arcs) == 2
    limit_mm_min = 0.1 / 0.004 * 60.0  # ADIS / IPO cycle (MD10050 · MD10070 = 4 ms)
    assert all(m.feed_mm_min == pytest.approx(limit_mm_min) and m.feed == 20000.0 for m in arcs)
    assert all(m.feed_mm_min == 20000.0 for m in motions if m.kind == "G1")
    slow = _motions("G90 G17 G641 ADIS=0.1 G1 X10 F500\nY10\nM30\n")
    assert _arcs(slow)[0].feed_mm_min == 500.0  # below the limit: the programmed feed


def test_the_plain_block_path_does_not_bypass_the_rounding() -> None:
    # Straight G1 blocks after a first one are what the interpreter's fast path takes.
    text = "G90 G17 G1 X0 Y0 F1000\nG641 ADIS=0.5\n" + "".join(
        f"X{10 * (k + 1)} Y{10 * (k % 2)}\n" for k in range(8)) + "M30\n"
    assert [m.source.line for m in _arcs(_motions(text))] == [3, 4, 5, 6, 7, 8, 9]


def test_stopre_and_dwell_end_the_rounding_computations_do_not() -> None:
    for stop in ("STOPRE", "G4 F0.1"):
        motions = _motions(f"G641 ADIS=1 G1 X10 F500\n{stop}\nY10\nX0\nM30\n")
        assert [m.source.line for m in _arcs(motions)] == [3]
    assert [m.source.line for m in _arcs(_motions("G641 ADIS=1 G1 X10 F500\nR1=5\nY10\nM30\n"))] == [1]


def test_the_other_rounding_modes_stay_g64() -> None:
    # G642 … G645 round within tolerances (MD20480 etc.): not modelled, the corner is passed as under G64.
    for mode in ("G642", "G643", "G644", "G645"):
        assert not _arcs(_motions(f"{mode} ADIS=1 G1 X10 F500\nY10\nX0\nM30\n"))
