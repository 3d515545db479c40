"""Issue 22: a blank clamped at an angle (a box turned about Z around its centre) in the contact
model, so that the rotated-corner measuring (Measure workpiece ⇧F3) has something to find.

Hand values: the default 100 × 80 × 30 box centred on X 0 Y 0 (X -50…50, Y -40…40, top Z -220),
turned 20° counter-clockwise; its corner (-50, -40) turned by 20° lies at
(-50·cos20° + 40·sin20°, -50·sin20° - 40·cos20°). Probe T1: type 710, ball radius 2, L 150.
"""

from __future__ import annotations

import math

import pytest

from nck.contact import BALL, CUTTER, ToolBody, clearance
from nck.measuring import rotated_corner
from nck.setup_fields import setup_fields, with_field
from nck.workpiece import Box, MachineSetup, setup_from_plain, setup_to_plain
from tests.setup_job.test_contact_kernel import events, jog_until_stopped, kernel, mda

ANGLE_DEG = 20.0
TURNED = Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0), ANGLE_DEG)


def test_gap_to_a_turned_face_along_its_normal() -> None:
    """A ball 10 mm outside the turned +X face, on its normal through the centre: gap 10 − 2;
    a cutter beside the turned −Y face 3 mm off, tip below the top: gap 3 − 5 = −2 (in)."""
    c, s = math.cos(math.radians(ANGLE_DEG)), math.sin(math.radians(ANGLE_DEG))
    ball = ToolBody(BALL, 2.0)
    assert clearance(ball, TURNED, (60.0 * c, 60.0 * s, -230.0)) == pytest.approx(8.0, abs=1e-9)
    cutter = ToolBody(CUTTER, 5.0, 75.0)
    assert clearance(cutter, TURNED, (43.0 * s, -43.0 * c, -230.0)) == pytest.approx(-2.0, abs=1e-9)
    # the same ball beside the box not turned: beyond its +X face and its +Y face
    assert clearance(ball, Box(TURNED.low_mcs, TURNED.high_mcs), (60.0 * c, 60.0 * s, -230.0)) \
        == pytest.approx(math.hypot(60.0 * c - 50.0, max(60.0 * s - 40.0, 0.0)) - 2.0, abs=1e-9)


def test_probing_a_turned_blank_gives_its_angle_and_corner() -> None:
    """P1, P2 on the turned −Y face (JOG Y+ at X −20 and X +20), P3 on the −X face (JOG X+ at
    Y 0): the rotated corner of nck.measuring finds 20° and the turned corner to 1 µm."""
    touches = []
    for start, axis in (("X-20 Y-90", "Y"), ("X20 Y-90", "Y"), ("X-90 Y0", "X")):
        nck = kernel(MachineSetup(blank=TURNED))
        mda(nck, f"T1 D1 M6\nG0 {start} Z-230\n")
        jog_until_stopped(nck, axis, +1)
        (event,) = events(nck)
        assert event.kind == "probe"
        touches.append((event.position_mcs["X"], event.position_mcs["Y"]))
    found = rotated_corner(touches[0], touches[1], (0.0, 1.0), touches[2], (1.0, 0.0), 2.0)
    c, s = math.cos(math.radians(ANGLE_DEG)), math.sin(math.radians(ANGLE_DEG))
    assert found.angle_deg == pytest.approx(ANGLE_DEG, abs=1e-6)
    assert found.x_mm == pytest.approx(-50.0 * c + 40.0 * s, abs=1e-3)
    assert found.y_mm == pytest.approx(-50.0 * s - 40.0 * c, abs=1e-3)


def test_rotation_is_a_field_of_the_set_up_and_retained_in_the_plain_form() -> None:
    turned = with_field(MachineSetup(blank=Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0))),
                        "blank.rotation_z", "20")
    assert turned.blank == TURNED
    assert with_field(turned, "blank.x", "-120").blank == Box((-120.0, -40.0, -250.0), (-20.0, 40.0, -220.0), 20.0)
    assert {f.name: f.text for f in setup_fields(turned)}["blank.rotation_z"] == "20"
    assert setup_from_plain(setup_to_plain(turned)) == turned
    assert "rotation_z_deg" not in setup_to_plain(MachineSetup(blank=Box((0, 0, 0), (1, 1, 1))))["blank"]
