"""The blank from ``WORKPIECE(...)`` (parameter facts in nck/simulation/blank.py's docstring)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from nck.ncdata import NcData, ToolEdge
from nck.simulation.blank import blank_from_text
from nck.simulation.run import simulate


def test_box_with_absolute_corners() -> None:
    blank = blank_from_text('G17\nWORKPIECE(,"",,"BOX",240,25,0,0,-30,-20,30,20)\nM30\n')
    assert blank is not None and blank.kind == "box" and blank.line == 2
    assert (blank.x_mm, blank.y_mm, blank.z_mm) == ((-30.0, 30.0), (-20.0, 20.0), (0.0, 25.0))


def test_box_with_lengths_and_relative_bottom() -> None:
    # bits 0: X1/Y1 are lengths from X0/Y0, Z1 is measured from Z0: X -2..182, Y -2..168, Z -28..2.
    blank = blank_from_text('WORKPIECE(,"",,"BOX",0,2,-30,-80,-2,-2,184,170)')
    assert blank is not None
    assert (blank.x_mm, blank.y_mm, blank.z_mm) == ((-2.0, 182.0), (-2.0, 168.0), (-28.0, 2.0))


def test_cylinder() -> None:
    blank = blank_from_text('N10 WORKPIECE(,,,"CYLINDER",192,0,-50,-80,60)')
    assert blank is not None and blank.kind == "cylinder" and blank.diameter_mm == 60.0
    assert blank.z_mm == (-50.0, 0.0)
    assert blank.volume_mm3 == pytest.approx(math.pi * 900.0 * 50.0)


def test_other_forms_are_not_read() -> None:
    assert blank_from_text('WORKPIECE(,"",,"PIPE",192,0,-50,-80,60,40)') is None
    assert blank_from_text("G0 X10\nM30\n") is None


def test_the_control_runs_the_statement_as_a_no_op_and_the_simulation_uses_it() -> None:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 60.0, 6: 5.0})
    text = ('N10 WORKPIECE(,,,"CYLINDER",192,0,-20,-80,60)\nN20 T1 M6\nN30 D1 S1000 M3\n'
            "N40 G0 X-40 Y0 Z2\nN50 G1 Z-5 F300\nN60 X40\nN70 G0 Z10\nN80 M30\n")
    result = simulate("P.MPF", text, data=data, resolution_mm=0.1)
    assert result.status == "ended" and result.alarms == []
    assert result.blank.kind == "cylinder"
    zmap = result.zmap
    # Outside the cylinder there is no material; the slot across it (width 10, 5 deep) cuts
    # the chord band |y| <= 5 of the D60 disc: 2 * (y sqrt(R² - y²) + R² asin(y / R)) at y = 5
    # = 2 * (5 * sqrt(875) + 900 * asin(1/6)) = 2 * (147.902 + 150.699) = 597.20 mm², 5 deep.
    band = 2.0 * (5.0 * math.sqrt(875.0) + 900.0 * math.asin(5.0 / 30.0))
    assert zmap.removed_volume_mm3() == pytest.approx(band * 5.0, rel=0.01)
    assert zmap.height_at(29.0, 29.0) == pytest.approx(-20.0)  # outside the disc: no material


def _slot_data(hidden: bool = False):
    from nck.workpiece import Box, MachineSetup

    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 60.0, 6: 5.0})
    # Clamped in the MCS: X 100..200, Y 50..130, Z -230..-200; G54 puts the workpiece zero at
    # its top left corner (X100 Y50 Z-200).
    data.machine_setup = MachineSetup(blank=Box((100.0, 50.0, -230.0), (200.0, 130.0, -200.0)), hidden=hidden)
    data.settable_frame("G54").trans.update({"X": 100.0, "Y": 50.0, "Z": -200.0})
    return data


SETUP_SLOT = ("N10 G54 T1 M6\nN20 D1 S1000 M3\nN30 G0 X20 Y40 Z2\nN40 G1 Z-5 F300\nN50 X80\n"
              "N60 G0 Z10\nN70 M30\n")


def test_without_workpiece_the_clamped_blank_of_the_machine_set_up_is_the_stock() -> None:
    result = simulate("P.MPF", SETUP_SLOT, data=_slot_data(), resolution_mm=0.1)
    assert result.status == "ended" and result.alarms == []
    # MCS box minus the work offset (100, 50, -200): X 0..100, Y 0..80, Z -30..0 in the WCS.
    assert (result.blank.x_mm, result.blank.y_mm, result.blank.z_mm) == ((0.0, 100.0), (0.0, 80.0), (-30.0, 0.0))
    assert result.zmap.removed_volume_mm3() == pytest.approx((60.0 * 10.0 + math.pi * 25.0) * 5.0, rel=0.01)


def test_a_hidden_blank_is_not_shown() -> None:
    result = simulate("P.MPF", SETUP_SLOT, data=_slot_data(hidden=True), resolution_mm=0.5)
    assert result.blank.kind == "path"


def test_a_box_clamped_at_an_angle_keeps_its_angle() -> None:
    """The set-up's box 80 x 20 turned by 90° about its centre stands 20 wide and 80 long; at
    30° its corners (by hand: half sides 40, 10; cos 30° = 0.8660, sin 30° = 0.5) are
    (-40, -10) → (-29.641, -28.660), (40, -10) → (39.641, 11.340) and their opposites about the
    centre, and it holds 80 · 20 · height of material."""
    from nck.simulation.blank import blank_from_setup
    from nck.simulation.zmap import ZMap
    from nck.workpiece import Box

    upright = blank_from_setup(Box((100.0, 200.0, 0.0), (180.0, 220.0, 30.0), 90.0), (100.0, 200.0, 30.0))
    assert upright.x_mm == pytest.approx((30.0, 50.0)) and upright.y_mm == pytest.approx((-30.0, 50.0))
    turned = blank_from_setup(Box((100.0, 200.0, 0.0), (180.0, 220.0, 30.0), 30.0), (140.0, 210.0, 30.0))
    assert turned.centre_xy_mm == pytest.approx((0.0, 0.0)) and turned.z_mm == (-30.0, 0.0)
    corners = turned.outline_xy()
    assert corners.ravel().tolist() == pytest.approx([-29.641, -28.660, 39.641, 11.340, 29.641, 28.660,
                                                      -39.641, -11.340], abs=1e-3)
    assert turned.x_mm == pytest.approx((-39.641, 39.641), abs=1e-3)
    assert turned.volume_mm3 == pytest.approx(80.0 * 20.0 * 30.0)
    # material along the box's own axis, none at the extents' corner
    mask = turned.material_mask(np.array([30.0, 38.0, 0.0]), np.array([17.0, 0.0, 12.0]))
    assert mask.tolist() == [True, False, False]  # (30, 17): 34.5 along, -0.3 across; (38, 0): 19 across; (0, 12): 10.4 across
    zmap = ZMap(turned, 0.25)
    assert float((zmap.heights > zmap.bottom_mm).sum()) * 0.25 ** 2 == pytest.approx(1600.0, rel=0.01)
