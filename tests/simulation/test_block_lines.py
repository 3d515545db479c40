"""The simulation's blocks name lines of the main program (the editor's link): the motions of
a subprogram or cycle belong to the main program's block that called it (002: a subprogram
call is one block of the calling program)."""

from __future__ import annotations

from pathlib import Path

from nck.interp.sources import DirectorySource
from nck.ncdata import NcData
from nck.simulation.run import AlarmPlace, simulate

MAIN = ("N10 $TC_DP1[1,1]=120 $TC_DP3[1,1]=60 $TC_DP6[1,1]=5\n"
        "N20 G17 G90 T1 M6 D1 S1000 M3 F500\n"
        "N30 G0 X0 Y0 Z5\n"
        "N40 GROOVE\n"
        "N50 G0 X50\n"
        "N60 M30\n")
GROOVE = ("PROC GROOVE\n"
          "N1 G1 Z-2\n"
          "N2 X20\n"
          "N3 G0 Z5\n"
          "N4 M17\n")


def test_subprogram_motions_belong_to_the_calling_line(tmp_path: Path) -> None:
    (tmp_path / "GROOVE.SPF").write_text(GROOVE)
    result = simulate("MAIN.MPF", MAIN, data=NcData(), programs=DirectorySource(tmp_path), resolution_mm=1.0)
    assert result.alarms == []
    assert [line for line, _chords in result.blocks_in_order()] == [3, 4, 5]


def test_an_alarm_in_a_subprogram_belongs_to_the_calling_line(tmp_path: Path) -> None:
    # GROOVE's N1 feeds without a feed (none programmed before the call): 10860 at its line 2,
    # which belongs to the main program's N40 GROOVE (line 4) as its motions do.
    (tmp_path / "GROOVE.SPF").write_text(GROOVE)
    main = MAIN.replace(" F500", "")
    result = simulate("MAIN.MPF", main, data=NcData(), programs=DirectorySource(tmp_path), resolution_mm=1.0)
    assert [(a.number, a.file, a.line) for a in result.alarms] == [(10860, "GROOVE.SPF", 2)]
    assert result.alarm_places == [AlarmPlace(4, "GROOVE.SPF", 2)]
    # an alarm of the main program itself keeps its line
    own = simulate("MAIN.MPF", main.replace("N40 GROOVE", "N40 G1 X5"), data=NcData(), resolution_mm=1.0)
    assert own.alarm_places == [AlarmPlace(4)]
