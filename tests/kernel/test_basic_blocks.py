"""The basic block display: the blocks as the NCK executes them, those of a cycle included, with
absolute end positions in the WCS (002 L23515-23530, L23656-23760; nck/basic_blocks.py).

The expected blocks are written by hand: the cycles' motion from their documented sequence
(data/cycles/README.md: CYCLE81 rapid to RFP+SDIS, at the feed to the depth, rapid to RTP;
HOLES1's row from SPCA/SPCO, FDIS and DBH), the form of each display block from the manual's
rules (G group 1 only when changed, L23663; no block number under DISPLOF, L23677; the programmed
axes with absolute positions, L23726-23733; values instead of variables, L23738-23742).
"""

from __future__ import annotations

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory


def _selected(program: str, **kwargs: object) -> Nck:
    nck = Nck(programs=MemorySource({"P.MPF": program}), referenced=True, **kwargs)  # type: ignore[arg-type]
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    return nck


def _marked(nck: Nck) -> str:
    channel = nck.status().channel
    assert channel.basic_block_index >= 0
    return channel.basic_blocks[channel.basic_block_index].text


def _basic_blocks_after_run(program: str) -> list[str]:
    """The basic block display's texts after ``program`` ran to its end in AUTO."""
    nck = _selected(program, motion_factory=instant_motion_factory)
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    return [block.text for block in nck.status().channel.basic_blocks]


def _single_block_stops(program: str) -> list[tuple[str, str, float, float, float]]:
    """At every SBL1 stop: (the program display's block number, the marked basic block, X, Y, Z)."""
    nck = _selected(program)
    assert nck.submit(c.SetProgramControl("single_block", "SBL1")) == c.Accepted()
    stops = []
    for _ in range(40):
        assert nck.submit(c.CycleStart()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.program != "running", 60.0)
        if nck.situation.channel == "reset":
            return stops
        channel = nck.status().channel
        assert channel.current_block is not None
        position = nck.positions_mcs()
        stops.append((channel.current_block.text.split()[0], _marked(nck),
                      round(position["X"], 3), round(position["Y"], 3), round(position["Z"], 3)))
    raise AssertionError("the program did not end")


def test_single_block_through_cycle81_shows_the_cycles_blocks() -> None:
    # CYCLE81(RTP=10, RFP=0, SDIS=2, DP=-5): rapid to RFP+SDIS = 2, G1 to -5 at the caller's F300,
    # rapid to RTP = 10. The program's display stays on the call N40 (DISPLOF); the basic block
    # display shows each motion of the cycle without a block number; G0 after N30's G0 is not
    # repeated, G1 and G0 are shown where group 1 changes, F with the first feed move.
    program = "N10 G17 G90 F300\nN20 S1000 M3\nN30 G0 X10 Y20 Z50\nN40 CYCLE81(10, 0, 2, -5)\nN50 M30\n"
    assert _single_block_stops(program) == [
        ("N20", "N20 S1000 M3", 0.0, 0.0, 0.0),
        ("N30", "N30 G0 X10 Y20 Z50", 10.0, 20.0, 50.0),
        ("N40", "Z2", 10.0, 20.0, 2.0),
        ("N40", "G1 Z-5 F300", 10.0, 20.0, -5.0),
        ("N40", "G0 Z10", 10.0, 20.0, 10.0),
    ]


def test_modal_cycle81_on_a_row_of_holes() -> None:
    # HOLES1(SPCA=10, SPCO=20, STA1=0, FDIS=5, DBH=15, NUM=3): holes at X = 10+5 = 15, 30, 45 on
    # Y20, each drilled by the modal CYCLE81 (Z2, G1 Z-5, G0 Z10); only X changes between holes.
    program = ("N10 G17 G90 F300\nN20 G0 X0 Y0 Z20\nN30 MCALL CYCLE81(10, 0, 2, -5)\n"
               "N40 HOLES1(10, 20, 0, 5, 15, 3)\nN50 MCALL\nN60 G0 Z50\nN70 M30\n")
    drilled = [("Z2", 2.0), ("G1 Z-5", -5.0), ("G0 Z10", 10.0)]
    expected = [("N20", "N20 G0 X0 Y0 Z20", 0.0, 0.0, 20.0), ("N40", "X15 Y20", 15.0, 20.0, 20.0)]
    expected += [("N40", "G1 Z-5 F300" if text == "G1 Z-5" else text, 15.0, 20.0, z) for text, z in drilled]
    for x in (30.0, 45.0):
        expected.append(("N40", f"X{x:g}", x, 20.0, 10.0))
        expected += [("N40", text, x, 20.0, z) for text, z in drilled]
    expected.append(("N60", "N60 Z50", 45.0, 20.0, 50.0))
    assert _single_block_stops(program) == expected


def test_positions_are_absolute_and_values_replace_variables() -> None:
    # 002 L23733: N20 G91 X1 after X10.123 is shown N20 X11.123; L23740-23742: Z=R1 is shown
    # with R1's value; F=FEED with its value (L23752-23756); a circle's end point and its
    # centre as absolute values; a dwell and M codes as programmed.
    program = ("N1 DEF REAL FEED=150\nN5 G0 X0 Y0 Z0\nN10 G90 X10.123\nN20 G91 X1\nN30 G90 R1=-67.5\n"
               "N40 Z=R1\nN60 G1 Y5 F=FEED\nN70 G2 X21.123 Y15 I10 J0\nN80 G4 F2\nN90 M30\n")
    stops = _single_block_stops(program)
    assert [marked for _, marked, *_ in stops] == [
        "N5 G0 X0 Y0 Z0", "N10 X10.123", "N20 X11.123", "N40 Z-67.5", "N60 G1 Y5 F150",
        "N70 G2 X21.123 Y15 I=AC(21.123) J=AC(5)", "N80 G4 F2",
    ]


def test_the_block_in_execution_is_marked_and_prepared_blocks_follow_it() -> None:
    # Instant motion: F300 = 5 mm/s. N30 G1 Z-5 from Z2 takes 1.4 s; half-way the marked block is
    # N30's, and the blocks the interpreter has prepared (N40, N50, N60) follow it in the list.
    program = "N10 G0 X0 Y0 Z2\nN20 F300\nN30 G1 Z-5\nN40 G0 Z10\nN50 X20\nN60 M30\n"
    nck = _selected(program, motion_factory=instant_motion_factory, batch_cycles=1)
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: -3.0 > k.positions_mcs()["Z"] > -4.0, 10.0)
    channel = nck.status().channel
    texts = [block.text for block in channel.basic_blocks]
    assert texts[channel.basic_block_index] == "N30 G1 Z-5 F300"
    assert texts[channel.basic_block_index + 1:] == ["N40 G0 Z10", "N50 X20", "N60 M30"]


def test_block_search_writes_no_display_blocks() -> None:
    # 002 L23610: the basic block display is off during block search. After a search with
    # calculation to N40 the only display block is N40's, with the axis it programs (L23726-23728)
    # and its G code and F (nothing before it was shown).
    program = "N10 G0 X5 Y5 Z5\nN20 X10\nN30 Y20\nN40 G1 Z-1 F100\nN50 M30\n"
    nck = _selected(program, motion_factory=instant_motion_factory)
    assert nck.submit(c.StartBlockSearch("N40", "contour")) == c.Accepted()
    assert nck.status().channel.stop_reason == "search target found"
    # only the target block, pending (its motion is prepared by the NC STARTs that follow)
    assert [b.text.split()[0] for b in nck.status().channel.basic_blocks] == ["N40"]
    assert nck.submit(c.SetProgramControl("single_block", "SBL1")) == c.Accepted()
    for _ in range(4):  # the actions (alarm 10208), then the approach and N40
        assert nck.submit(c.CycleStart()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.program != "running", 10.0)
        if nck.positions_mcs()["Z"] < 0.0:
            break
    assert nck.positions_mcs()["Z"] == -1.0 and nck.situation.program == "stopped"
    assert [b.text for b in nck.status().channel.basic_blocks][:1] == ["N40 G1 Z-1 F100"]


def test_programmed_positions_are_shown_to_the_display_resolution() -> None:
    # The display shows positions to 0.001 mm (MD9004's default, nck/basic_blocks.py _shown):
    # 10.0001 and 10.0004 read X10, 0.9996 reads Z1, 10.0006 reads X10.001; every programmed
    # axis is shown, also where its text equals the last one (002 L23726-23728).
    program = "N5 G0 X0 Y0 Z0\nN10 X10 Z1\nN20 G1 X10.0001 F100\nN30 X10.0004 Z0.9996\nN40 X10.0006\nN50 M30\n"
    texts = _basic_blocks_after_run(program)
    assert texts[1:5] == ["N10 X10 Z1", "N20 G1 X10 F100", "N30 X10 Z1", "N40 X10.001"]


def test_a_block_shows_the_axes_it_programs_and_no_other() -> None:
    # 002 L23726-23728: "Programmed axis positions are represented as absolute positions"; the
    # display block is derived from the programmed block (L23674). The run starts at X0 Y0 Z0:
    # N10 programs X only (Y and Z are not shown, though nothing was shown before); N30 programs
    # X10 Y5 where the axes already stand and shows both; N40 G91 X0 shows X absolute, X10
    # (as N20 G91 X1 is shown N20 X11.123, L23733).
    program = "N10 G0 X10\nN20 G1 X10 Y5 F100\nN30 X10 Y5\nN40 G0 G91 X0\nN50 M30\n"
    texts = _basic_blocks_after_run(program)
    assert texts == ["N10 G0 X10", "N20 G1 X10 Y5 F100", "N30 X10 Y5", "N40 G0 X10", "N50 M30"]
