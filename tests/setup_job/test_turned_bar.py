"""The bar in the lathe's chuck is turned (issue 23: the sample shaft cuts the bar): what a
cutter removed with the spindle turning is gone for the rapid moves that follow; what it did
not reach is still a crash. A fresh lathe data directory starts with G54 on the bar's face.

Hand values: the default bar Ø60 (radius 30) from the chuck face Z 200 to its free end Z 300
(nck.workpiece); T1 an edge of radius 0.8 without lengths (tip = machine position); X is a
radius here (no DIAMON in these MDA blocks)."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from nck.contact import BALL, ToolBody, first_contact
from nck.machine import load_machine
from nck.persistence import Session
from nck.turned_bar import TurnedBar
from nck.workpiece import Cylinder, default_machine_setup
from tests.setup_job.test_contact_kernel import events, lathe_kernel, mda


def test_a_fresh_lathe_data_directory_has_g54_on_the_bars_face(tmp_path: Path) -> None:
    data = Session.open(tmp_path / "data", load_machine("lathe2")).ncdata
    assert data.settable_frame("G54").trans == {"X": 0.0, "Z": 300.0}  # chuck face 200 + 100 out
    mill = Session.open(tmp_path / "mill", load_machine("mill3")).ncdata
    assert mill.settable_frame("G54").trans == {}


def test_rapid_back_over_the_turned_length_is_free_and_into_the_uncut_bar_a_crash() -> None:
    nck = lathe_kernel()
    # cut radius 25 (edge 0.8: the bar is left at 24.2) from the face Z 300 down to Z 280
    mda(nck, "T1 D1\nG0 X100\nZ305\nM3 S500\nG95 F0.2\nG1 X25\nZ280\nG0 X26\nZ305\nG0 X26 Z285\nM30\n")
    assert nck.alarms.active == ()
    assert [e.kind for e in events(nck)] == ["scratch"]  # one contact for the whole cut
    nck = lathe_kernel()  # the same rapid on an uncut bar: radius 26 is inside radius 30
    mda(nck, "T1 D1\nG0 X100\nZ305\nM3 S500\nG0 X26 Z285\nM30\n")
    assert [a.number for a in nck.alarms.active] == [90002]
    nck = lathe_kernel()  # cut to Z 280 only: a rapid to Z 270 at radius 26 meets the shoulder left there
    mda(nck, "T1 D1\nG0 X100\nZ305\nM3 S500\nG95 F0.2\nG1 X25\nZ280\nG0 X26\nZ270\nM30\n")
    assert [a.number for a in nck.alarms.active] == [90002]
    shoulder = [e for e in events(nck) if e.kind == "crash"][0]
    # the edge (radius 0.8) rounded the shoulder's corner: material from Z 279.2 down is whole
    # (the cut's Z range widened to the 0.1 mm grid: 279.1), the edge meets it at once
    assert 279.1 + 0.8 - 0.1 <= shoulder.position_mcs["Z"] <= 280.0


def test_the_planar_entry_agrees_with_the_general_contact_search() -> None:
    """The exact entry of a ball into a disc in the X/Z plane equals nck.contact's search."""
    rng = random.Random(23)
    disc = Cylinder((0.0, 0.0, 200.0), 40.0, 30.0)
    bar = TurnedBar.of(disc)
    for _ in range(300):
        body = ToolBody(BALL, rng.uniform(0.0, 2.0))
        start = (rng.uniform(0.0, 40.0), 0.0, rng.uniform(180.0, 250.0))
        end = (rng.uniform(0.0, 40.0), 0.0, rng.uniform(180.0, 250.0))
        expected = first_contact(body, disc, start, end)
        found = bar.first_contact(body, start, end)
        assert (found is None) == (expected is None), (start, end, body)
        if expected is not None:
            assert found == pytest.approx(expected, abs=1e-6)


def test_cuts_leave_a_stack_of_discs_with_the_smallest_radius_turned() -> None:
    bar = TurnedBar.of(default_machine_setup("lathe").blank)  # type: ignore[arg-type]
    edge = ToolBody(BALL, 0.5)
    bar.cut(edge, (20.0, 0.0, 300.0), (20.0, 0.0, 280.0))  # radius 20 - 0.5 - 0.001 over Z 279.4 … 300.6
    bar.cut(edge, (15.0, 0.0, 300.0), (15.0, 0.0, 290.0))  # 14.499 over 289.4 … 300.6
    assert [(round(a, 3), round(b, 3), round(r, 3)) for a, b, r in zip(bar.starts, bar.ends, bar.radii)] == [
        (200.0, 279.4, 30.0), (279.4, 289.4, 19.499), (289.4, 300.0, 14.499)]
