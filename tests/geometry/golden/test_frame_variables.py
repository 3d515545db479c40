"""Golden: frame components through system variables ($P_UIFR, $P_PFRAME, $P_UBFR, $AA_IW)."""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.ncdata import NcData

from .helpers import approx, lines, run


def test_settable_frame_written_by_the_program_acts_after_selection() -> None:
    data = NcData()
    r = run(lines(
        "N10 $P_UIFR[1,X,TR]=100 $P_UIFR[1,Y,TR]=50",
        "N20 G0 X0 Y0",                # G500 still active: machine (0,0)
        "N30 G54 X0 Y0",               # now G54 = (100,50)
        "N40 $P_PFRAME[X,TR]=10",      # programmable frame, effective at once
        "N50 X0",
        "N60 R1=$P_UIFR[1,X,TR] R2=$P_UIFRNUM R3=$P_PFRAME[X,TR] R4=$AA_IW[X]",
        "N70 $P_PFRAME[Z,RT]=90",
        "N80 X10 Y0",                  # (10,0) turned to (0,10), + (10,0) + (100,50)
        "N90 M30",
    ), data)
    assert r.end_mcs(20) == approx({"X": 0.0, "Y": 0.0, "Z": 0.0})
    assert r.end_mcs(30) == approx({"X": 100.0, "Y": 50.0, "Z": 0.0})
    assert r.end_mcs(50) == approx({"X": 110.0, "Y": 50.0, "Z": 0.0})
    assert data.r[1:4] == [100.0, 1.0, 10.0]
    assert data.settable_frames["G54"].trans == {"X": 100.0, "Y": 50.0}
    assert r.end_mcs(80) == approx({"X": 110.0, "Y": 60.0, "Z": 0.0})


def test_basic_frame_and_inch_data() -> None:
    data = NcData()
    r = run(lines("N10 $P_UBFR[Z,TR]=-5", "N20 G700", "N25 $P_UIFR[2,X,TR]=1",
                  "N30 G71 G55 G0 X0 Z0", "N40 M30"), data)
    # G700: stored data are written in inch: 1 inch = 25.4 mm.
    assert data.settable_frames["G55"].trans["X"] == pytest.approx(25.4)
    # The basic frame is read again at RESET / program start; this run started before the write,
    # so only G55 acts.
    assert r.end_mcs(30)["X"] == pytest.approx(25.4)


def test_bad_component_and_zero_scale() -> None:
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 $P_PFRAME[X,SC]=0", "N20 M30"))
    assert info.value.number == 18309
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 $P_UIFR[1,X]=5", "N20 M30"))
    assert info.value.number == 17020


def test_frame_functions_assigned_to_frame_variables() -> None:
    data = NcData()
    r = run(lines(
        "N10 G0 X100",
        "N20 $P_PFRAME=CTRANS(X,10)",   # digest K2 §10.5: X100 then shows WCS 100, machine 110
        "N30 X100",
        "N40 $P_UIFR[1]=CTRANS(X,100,Y,50)",
        "N50 G54 $P_PFRAME=CROT(Z,90)",
        "N60 X10 Y0",                   # (10,0) -> (0,10) -> + (100,50)
        "N70 $P_IFRAME=CTRANS()",       # active settable frame zeroed at once (data keep G54)
        "N80 X10 Y0",
        "N90 $P_PFRAME=CMIRROR(Y)",
        "N100 X10 Y10",
        "N110 M30",
    ), data)
    assert r.end_mcs(10)["X"] == pytest.approx(100.0)
    assert r.end_mcs(30)["X"] == pytest.approx(110.0)
    assert r.end_wcs(30)["X"] == pytest.approx(100.0)
    assert data.settable_frames["G54"].trans == {"X": 100.0, "Y": 50.0}
    assert r.end_mcs(60) == approx({"X": 100.0, "Y": 60.0, "Z": 0.0})
    assert r.end_mcs(80) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    assert r.end_mcs(100) == approx({"X": 10.0, "Y": -10.0, "Z": 0.0})
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 $P_PFRAME=CTRANS(X)", "N20 M30"))
    assert info.value.number == 14020


def test_frame_chain_operator() -> None:
    data = NcData()
    r = run(lines(
        "N10 $P_UIFR[1]=CTRANS(X,100,Y,50):CROT(Z,90)",  # shift, then turn about the new origin
        "N20 G54 G0 X10 Y0",                            # (10,0) -> (0,10) -> (100,60)
        "N30 $P_PFRAME=CROT(Z,90):CTRANS(X,5)",         # the shift runs along the turned X (= +Y)
        "N40 G0 X0 Y0",                                 # (0,0) -> (0,5); G54 turns it to (-5,0), + (100,50)
        "N50 M30",
    ), data)
    assert data.settable_frames["G54"].rot == {"Z": pytest.approx(90.0)}
    assert r.end_mcs(20) == approx({"X": 100.0, "Y": 60.0, "Z": 0.0})
    assert r.end_mcs(40) == approx({"X": 95.0, "Y": 50.0, "Z": 0.0})


def test_a_failing_block_undoes_its_frame_writes() -> None:
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine

    data = NcData()
    interp = Interpreter(load_machine("mill3"), MemorySource({}), data)
    interp.start_text("U.MPF", "N10 $P_PFRAME[X,TR]=5 $P_UIFR[1,X,TR]=7 $P_UIFR[1,Q,TR]=1\n")
    with pytest.raises(NcAlarmError):
        interp.step()
    assert interp.modal.geometry is None or interp.modal.geometry.frames.programmable.is_identity()
    assert "X" not in data.settable_frames["G54"].trans
