"""The blank on the mill's table is milled (issue 22, "Contact": a rapid move into the blank is a
crash; nck.milled_blank): what a cutter removed at feed with the spindle turning is gone for the
moves that follow — a rapid back into a drilled hole or through a milled slot is no crash, a
rapid into material still there is one (90002, trainer alarm), exactly where the surface is.

Hand values: the default mill set-up (nck.workpiece): blank X -50…50, Y -40…40, top Z -220
(MCS); T2 an end mill of radius 5 and length 100 (tip = machine Z − 100). The model's grid for
this 100 × 80 blank: sqrt(100·80 / 262144) = 0.1747 mm, the next multiple of 0.005 is 0.175
mm; a cut removes the cells within radius + half a cell diagonal (0.175·√½ = 0.1237 mm) and
0.001 mm below the end face (nck.milled_blank's trainer choices).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from nck.commands import Accepted, WriteMachineSetup
from nck.contact import BALL, CUTTER, ToolBody, point_along
from nck import milled_blank
from nck.milled_blank import MAX_CELLS, MilledBlank, cell_size_mm
from nck.workpiece import Box, MachineSetup, default_machine_setup
from tests.setup_job.test_contact_kernel import events, kernel, mda

DRILL_10_DEEP = "T2 D1 M6\nM3 S1000\nG0 X0 Y0 Z-210\nG1 Z-230 F500\nG0 Z-210\n"  # the tip: 10 above, 10 into the top
FLOAT32_MM = 1e-5  # the Z-map keeps heights as float32: at 230 mm one step is 1.5e-5 mm


def alarm_numbers(nck) -> list[int]:
    return [a.number for a in nck.alarms.active]


def test_the_grid_is_chosen_from_the_blank_and_stays_bounded() -> None:
    blank = default_machine_setup("mill").blank
    milled = MilledBlank.of(blank)
    assert milled.zmap.resolution_mm == pytest.approx(0.175)
    assert (milled.zmap.nx, milled.zmap.ny) == (572, 458)  # ceil(100 / 0.175), ceil(80 / 0.175)
    assert milled.zmap.nx * milled.zmap.ny <= MAX_CELLS
    assert cell_size_mm(10.0, 10.0) == 0.05  # a small blank: the finest grid
    assert cell_size_mm(1000.0, 1000.0) == pytest.approx(1.955)  # sqrt(1e6 / 262144) = 1.9531 → 1.955


def test_rapid_back_into_a_drilled_hole_is_free_and_below_its_bottom_a_crash() -> None:
    nck = kernel()
    mda(nck, DRILL_10_DEEP + "G0 Z-229.5\nG0 Z-210\nM30\n")  # back down to 0.5 mm above the bottom
    assert alarm_numbers(nck) == []
    (scratch,) = events(nck)  # one contact for the whole hole: the top face, tip -220
    assert scratch.kind == "scratch" and scratch.position_mcs["Z"] == pytest.approx(-120.0, abs=1e-6)
    mda(nck, "G0 Z-235\n")  # 5 mm deeper than drilled: meets the bottom left 0.001 below -230
    assert alarm_numbers(nck) == [90002]
    assert events(nck)[-1].position_mcs["Z"] == pytest.approx(-130.001, abs=FLOAT32_MM)


@pytest.mark.parametrize("x", [10.5, 30.0])
def test_rapid_into_the_uncut_material_beside_the_hole_is_a_crash_at_the_top(x: float) -> None:
    """At X 10.5 the tool covers X 5.5…15.5, beside the hole's wall at X 5 (+ 0.12)."""
    nck = kernel()
    mda(nck, DRILL_10_DEEP + f"G0 X{x}\nG0 Z-225\n")
    assert alarm_numbers(nck) == [90002]
    crash = events(nck)[-1]
    assert crash.kind == "crash" and crash.position_mcs["Z"] == pytest.approx(-120.0, abs=1e-6)


def test_a_new_blank_clamped_brings_the_whole_material_back() -> None:
    nck = kernel()
    mda(nck, DRILL_10_DEEP)
    blank = Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0))  # the same block, clamped again
    assert nck.submit(WriteMachineSetup(MachineSetup(blank=blank))) == Accepted()
    mda(nck, "G0 Z-225\n")
    assert alarm_numbers(nck) == [90002]
    assert events(nck)[-1].position_mcs["Z"] == pytest.approx(-120.0, abs=1e-6)


SLOT = ("T2 D1 M6\nM3 S1000\nG0 X-70 Y0 Z-215\nG1 Z-225 F2000\n"  # beside the blank, tip -225
        "G1 X70 F1000\n")  # a slot 5 deep, 10 wide, right through the blank along X


def test_rapid_through_a_milled_slot_at_its_depth_is_free() -> None:
    nck = kernel()
    mda(nck, SLOT + "G0 X-70\nG0 X0\nG0 Z-224.5\nG0 X70\nM30\n")
    assert alarm_numbers(nck) == []
    assert [e.kind for e in events(nck)] == ["scratch"]  # the left face at X -55
    assert events(nck)[0].position_mcs["X"] == pytest.approx(-55.0, abs=1e-6)


def test_rapid_sideways_out_of_the_slot_meets_its_wall_at_once() -> None:
    """The wall the model leaves: uncut cells have their centre more than 5 + 0.1237 from the
    slot's axis, so their edge lies between 5 + 0.1237 − 0.0875 and 5 + 0.1237 + 0.0875."""
    nck = kernel()
    mda(nck, SLOT + "G0 X0\nG0 Y10\n")
    assert alarm_numbers(nck) == [90002]
    half_diagonal, half_cell = 0.175 * math.sqrt(0.5), 0.175 / 2.0
    assert half_diagonal - half_cell < events(nck)[-1].position_mcs["Y"] <= half_diagonal + half_cell + 1e-9


def test_rapid_along_the_slot_deeper_than_it_was_cut_is_a_crash() -> None:
    nck = kernel()
    mda(nck, SLOT + "G0 Z-227\nG0 X0\n")  # from X 70 back at tip -227: 2 mm below the slot's floor
    assert alarm_numbers(nck) == [90002]
    assert events(nck)[-1].position_mcs["X"] == pytest.approx(55.0, abs=1e-6)  # the right face, uncut there


def test_the_spindle_at_rest_in_the_hole_is_still_a_crash_at_its_bottom() -> None:
    nck = kernel()
    mda(nck, DRILL_10_DEEP + "M5\nG1 Z-229.5 F500\n")  # in the hole at feed: nothing there
    assert alarm_numbers(nck) == []
    mda(nck, "G1 Z-235 F500\n")  # on into the bottom with the spindle at rest
    assert alarm_numbers(nck) == [90001]
    assert events(nck)[-1].position_mcs["Z"] == pytest.approx(-130.001, abs=FLOAT32_MM)


def test_a_deep_hole_cycle_rapids_back_into_its_own_hole() -> None:
    """The report of issue 22: CYCLE83 retracts at rapid and comes back into its hole at rapid
    (to the safety distance above the last depth); DRILL_FLANGE alarmed 90002 there."""
    nck = kernel()
    nck.data.settable_frame("G54").trans["Z"] = -220.0  # G54 Z0 on the blank's top
    mda(nck, "G54 T2 D1 M6\nS1200 M3 F300\nG0 X20 Y10 Z10\n"
             "CYCLE83(10, 0, 2, -18, 0, -6, 0, 2, 0, 0, 1, 1)\nG0 Z50\nM30\n")
    assert alarm_numbers(nck) == []
    assert nck.situation.channel == "reset"


def test_first_contact_with_what_is_left_is_found_exactly_in_one_step() -> None:
    """A step starting above the hole and ending 2 mm under its bottom: the cutter enters the
    material left at -230.001 after 20.001 mm of the 22 mm step; beside the hole the top face
    (uncut: exact) after 10 mm."""
    milled = MilledBlank.of(Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0)))
    tool = ToolBody(CUTTER, 5.0, 100.0)
    milled.cut(tool, (0.0, 0.0, -210.0), (0.0, 0.0, -230.0))
    assert milled.first_contact(tool, (0.0, 0.0, -210.0), (0.0, 0.0, -229.0)) is None
    assert milled.first_contact(tool, (0.0, 0.0, -210.0), (0.0, 0.0, -232.0)) == pytest.approx(20.001 / 22.0, abs=FLOAT32_MM / 22.0)
    assert milled.first_contact(tool, (12.0, 0.0, -210.0), (12.0, 0.0, -232.0)) == pytest.approx(10.0 / 22.0, abs=1e-12)


def _oracle_overlaps(milled: MilledBlank, body: ToolBody, start: tuple, end: tuple, ts: np.ndarray,
                     slack_mm: float = 0.0) -> np.ndarray:
    """Independent: at which parameters ``ts`` of the step does the tool overlap a column of what
    is left (a cell's square clipped to the block, from the bottom to the cell's height; uncut:
    the top)? Every cell within 1 mm of the tool's reach along the step is looked at; the tool
    counts ``slack_mm`` larger (negative: it must be that deep in)."""
    zmap, block = milled.zmap, milled.blank
    res = zmap.resolution_mm
    (lx, ly, bottom), (hx, hy, top) = block.low_mcs, block.high_mcs
    reach = body.radius_mm + 1.0
    radius = body.radius_mm + slack_mm
    ix = np.arange(max(int((min(start[0], end[0]) - reach - zmap.x0_mm) / res), 0),
                   min(int((max(start[0], end[0]) + reach - zmap.x0_mm) / res) + 1, zmap.nx))
    iy = np.arange(max(int((min(start[1], end[1]) - reach - zmap.y0_mm) / res), 0),
                   min(int((max(start[1], end[1]) + reach - zmap.y0_mm) / res) + 1, zmap.ny))
    if len(ix) == 0 or len(iy) == 0:
        return np.zeros(len(ts), dtype=bool)
    x0 = np.clip(zmap.x0_mm + ix * res, lx, hx)[None, :]
    x1 = np.clip(zmap.x0_mm + (ix + 1) * res, lx, hx)[None, :]
    y0 = np.clip(zmap.y0_mm + iy * res, ly, hy)[:, None]
    y1 = np.clip(zmap.y0_mm + (iy + 1) * res, ly, hy)[:, None]
    cells = np.ix_(iy, ix)
    heights = np.where(zmap.heights[cells] < zmap.initial[cells], zmap.heights[cells].astype(np.float64), top)
    result = []
    for t in ts:
        x, y, z = point_along(start, end, float(t))
        dx = np.maximum(np.maximum(x0 - x, x - x1), 0.0)
        dy = np.maximum(np.maximum(y0 - y, y - y1), 0.0)
        if body.shape == CUTTER:
            inside = ((dx * dx + dy * dy <= radius ** 2) & (z <= heights + slack_mm)
                      & (z + body.length_mm >= bottom - slack_mm))
        else:
            dz = np.maximum(np.maximum(bottom - z, z - heights), 0.0)
            inside = dx * dx + dy * dy + dz * dz <= radius ** 2
        result.append(bool((inside & (heights > bottom)).any()))
    return np.array(result)


STEPS = dict(cut_x=st.floats(-8.0, 8.0), cut_y=st.floats(-8.0, 8.0), depth=st.floats(0.5, 6.0),
             start=st.tuples(st.floats(-14.0, 14.0), st.floats(-14.0, 14.0), st.floats(-12.0, 4.0)),
             move=st.tuples(st.floats(-6.0, 6.0), st.floats(-6.0, 6.0), st.floats(-6.0, 6.0)),
             probe=st.booleans())


@settings(max_examples=12, deadline=None)
@given(**STEPS)
def test_no_contact_with_what_is_left_is_ever_missed(cut_x, cut_y, depth, start, move, probe) -> None:
    check_first_contact(cut_x, cut_y, depth, start, move, probe)


@pytest.mark.fuzz
@settings(max_examples=300, deadline=None)
@given(**STEPS)
def test_first_contact_fuzz(cut_x, cut_y, depth, start, move, probe) -> None:
    check_first_contact(cut_x, cut_y, depth, start, move, probe)


def check_first_contact(cut_x, cut_y, depth, start, move, probe) -> None:
    """Property (issue 22: "a contact is never missed because a step jumped over the surface"):
    after a slot is cut into a 20 × 20 × 10 block, for any step of a cutter or a probe the first
    contact found is where an independent check of every cell first sees the tool overlap what is
    left (checked at 401 points along the step), and no step that overlaps it is let through."""
    block = Box((-10.0, -10.0, -10.0), (10.0, 10.0, 0.0))
    milled = MilledBlank.of(block)
    cutter = ToolBody(CUTTER, 3.0, 50.0)
    milled.cut(cutter, (cut_x, cut_y, 5.0), (cut_x, cut_y, -depth))  # a hole …
    milled.cut(cutter, (cut_x, cut_y, -depth), (cut_x + 4.0, cut_y - 2.0, -depth))  # … and a slot from it
    body = ToolBody(BALL, 2.0) if probe else ToolBody(CUTTER, 2.5, 50.0)
    end = (start[0] + move[0], start[1] + move[1], start[2] + move[2])
    found = milled.first_contact(body, start, end)
    samples = np.linspace(0.0, 1.0, 401)
    seen = _oracle_overlaps(milled, body, start, end, samples, -1e-9)  # 1e-9 mm into what is left
    if seen.any():
        assert found is not None and found <= samples[seen.argmax()] + 1e-9
    if found is not None:  # touching where it was found (to rounding)
        assert _oracle_overlaps(milled, body, start, end, np.array([found]), 1e-9)[0]
        assert not seen[samples < found - 1e-6].any()


def test_scratching_the_reference_block_cuts_nothing_out_of_the_blank() -> None:
    """The reference block (X 150…190, Y -20…20, top -200) is not the blank: a cutter going on at
    feed on it leaves the blank whole, so a rapid into the blank after it is still a crash."""
    nck = kernel()
    mda(nck, "T2 D1 M6\nM3 S1000\nG0 X170 Y0 Z-190\nG1 Z-201 F500\nG1 X0 Y0 F2000\n")  # through the air
    assert alarm_numbers(nck) == []
    mda(nck, "G0 Z-225\n")
    assert alarm_numbers(nck) == [90002]
    assert events(nck)[-1].position_mcs["Z"] == pytest.approx(-120.0, abs=1e-6)


@settings(max_examples=25, deadline=None)
@given(**STEPS, overtravel=st.sampled_from([0.0, 2.0]))
def test_broad_phase_changes_no_contact_and_no_clearance(cut_x, cut_y, depth, start, move, probe, overtravel) -> None:
    """The broad phase (columns out of the tool's reach left out before the exact test) gives
    bit for bit the first contact (touching and ``overtravel`` deep, as for a probe driven on)
    and the clearance of the exact test of every column near the step."""
    block = Box((-10.0, -10.0, -10.0), (10.0, 10.0, 0.0))
    milled = MilledBlank.of(block)
    cutter = ToolBody(CUTTER, 3.0, 50.0)
    milled.cut(cutter, (cut_x, cut_y, 5.0), (cut_x, cut_y, -depth))
    milled.cut(cutter, (cut_x, cut_y, -depth), (cut_x + 4.0, cut_y - 2.0, -depth))
    body = ToolBody(BALL, 2.0) if probe else ToolBody(CUTTER, 2.5, 50.0)
    end = (start[0] + move[0], start[1] + move[1], start[2] + move[2])
    with_broad_phase = (milled.first_contact(body, start, end, overtravel), milled.clearance(body, start),
                        milled.clearance(body, end))
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(milled_blank, "_reachable", lambda reach, top, *_: np.ones(top.shape, dtype=bool))
        every_column = (milled.first_contact(body, start, end, overtravel), milled.clearance(body, start),
                        milled.clearance(body, end))
    assert with_broad_phase == every_column


def test_a_step_with_a_tiny_component_finds_the_contact_of_none(recwarn) -> None:
    """Found by fuzzing: a step of 1e-310 mm along Y overflowed the slab test's division (a
    warning). The parameter is then ±infinity, the limit the test takes for no movement along Y:
    the same first contact as the step without that component, and no warning."""
    block = Box((-10.0, -10.0, -10.0), (10.0, 10.0, 0.0))
    milled = MilledBlank.of(block)
    milled.cut(ToolBody(CUTTER, 3.0, 50.0), (0.0, 0.0, 5.0), (0.0, 0.0, -5.0))  # a hole: milled columns
    cutter = ToolBody(CUTTER, 2.5, 50.0)
    start = (-20.0, 0.0, -2.0)  # level with the side of the block, 2 mm below its top
    plain = milled.first_contact(cutter, start, (0.0, 0.0, -2.0))
    tiny = milled.first_contact(cutter, start, (0.0, 1e-310, -2.0))
    # touches X -10 with its radius 2.5: at X -12.5 of the 20 mm step, t = 7.5 / 20
    assert plain == pytest.approx(0.375, abs=1e-6) and tiny == plain
    assert not [w for w in recwarn if issubclass(w.category, RuntimeWarning)]
