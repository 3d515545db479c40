"""Single block (SBL1) on the real interpreter and motion: the stops keep in step with the motion.

002 L18071-18094: in single block mode the program stops after every block; with tool radius
compensation it stops after every intermediate block the control inserts, and blocks generated
during decoding are processed individually. Radius compensation and RND hold a block's motion
back until the next block is known; the stops must still come one segment at a time, at the
segment's end, with that segment's block displayed.
"""

from __future__ import annotations

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.ncdata import NcData, ToolEdge


def stops(text: str) -> list[tuple[float, float, int]]:
    """(X, Y, displayed line) at every single-block stop until the program ends."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 6: 2.0})  # end mill, radius 2 mm
    nck = Nck(programs=MemorySource({"P.MPF": text}), data=data, referenced=True)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.SetProgramControl("single_block", "SBL1"))
    seen = []
    for _ in range(30):
        assert nck.submit(c.CycleStart()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.program != "running", 60.0)
        if nck.situation.channel == "reset":
            return seen
        assert nck.situation.program == "stopped"
        position = nck.positions_mcs()
        block = nck.status().channel.current_block
        seen.append((round(position["X"], 6), round(position["Y"], 6), block.line if block else 0))
    raise AssertionError("the program did not end")


def test_single_block_with_radius_compensation_stops_at_every_compensated_corner() -> None:
    # G41 (tool left of the contour), radius 2, inside a square: the end points are the
    # intersections of the offset lines: (10,12) after the approach N30 (perpendicular to N40),
    # (28,12), (28,28), (10,28) (perpendicular to N60 before G40), then (0,0).
    text = ("N10 T1 M6 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 Y10 F1000\nN40 X30\nN50 Y30\nN60 X10\n"
            "N70 G40 X0 Y0\nN80 M30\n")
    assert stops(text) == [
        (0.0, 0.0, 1), (0.0, 0.0, 2), (10.0, 12.0, 3), (28.0, 12.0, 4), (28.0, 28.0, 5),
        (10.0, 28.0, 6), (0.0, 0.0, 7),
    ]


def test_single_block_with_rnd_stops_before_and_after_each_rounding() -> None:
    # RND=2 between two perpendicular lines: the line ends 2 mm before the corner, the
    # rounding arc 2 mm after it; each is a segment of its own.
    text = "N20 G0 X0 Y0\nN30 G1 X10 Y0 RND=2 F1000\nN40 Y10 RND=2\nN50 X0\nN60 M30\n"
    assert stops(text) == [
        (0.0, 0.0, 1), (8.0, 0.0, 2), (10.0, 2.0, 2), (10.0, 8.0, 3), (8.0, 10.0, 3), (0.0, 10.0, 4),
    ]


def test_plain_blocks_stop_once_each() -> None:
    assert stops("N10 G1 X5 F1000\nN20 Y5\nN30 M30\n") == [(5.0, 0.0, 1), (5.0, 5.0, 2)]


def test_single_block_with_g42_stops_after_each_inserted_corner_arc() -> None:
    """002 L18071-18073: with radius compensation processing stops after every intermediate
    block inserted by the control. G42 (tool right of the contour), G450: at each outside
    corner of the square (10,10)-(30,10)-(30,30)-(10,30) the control inserts an arc of the
    tool radius 2 round the corner point: N40 ends at (30,8), the arc to (32,10) is a stop of
    its own (shown with N50, the block it leads into), N50 ends at (32,30), the arc to
    (30,32), N60 ends at (10,32) (perpendicular to N60 before G40), then (0,0)."""
    text = ("N10 T1 M6 D1\nN20 G0 X0 Y0\nN30 G42 G1 X10 Y10 F1000\nN40 X30\nN50 Y30\nN60 X10\n"
            "N70 G40 X0 Y0\nN80 M30\n")
    assert stops(text) == [
        (0.0, 0.0, 1), (0.0, 0.0, 2), (10.0, 8.0, 3), (30.0, 8.0, 4), (32.0, 10.0, 5),
        (32.0, 30.0, 5), (30.0, 32.0, 6), (10.0, 32.0, 6), (0.0, 0.0, 7),
    ]
