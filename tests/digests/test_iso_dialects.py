"""Digest iso-dialects-840d (manual 000, ISO Dialects for SINUMERIK): ranked items not proved
elsewhere. ``tests/README.md`` lists where the other items are proved (mostly ``tests/iso``).
"""

from __future__ import annotations

from nck.iso.dialect import dialect_for
from nck.headless import interpret_only
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def first_view(dialect: str) -> tuple[dict[int, str], dict[int, str]]:
    """(ISO groups, Siemens groups) after the first block of a main program."""
    interp = Interpreter(load_machine(None), MemorySource(), NcData(), dialect=dialect_for(dialect, load_machine(None)))
    interp.start_text("T.MPF", "G00 X1.\nM30\n")
    interp.step()
    view = interp.modal_view()
    return dict(view.iso_gcodes), dict(view.gcodes)


def test_digest_iso_dialects_rank_02_iso_m_start_up_g_codes() -> None:
    """Digest iso-dialects-840d rank 2: the ISO M reset values of MD20154 (000 L5005-5025):
    G00 G17 G90 G23 G94 G40 G49 G80 G98 G50 G67 G97 G54 G64 G69 G15 G50.1 G13.1, ISO mode on.
    Group 15 value 3 is G64 continuous path (000 L674-677), which also sets the shared Siemens
    group 10 (000 L749). Group 6 shows G21 on this metric machine (MD20154[5] follows the
    machine's unit, see ``tests/iso/test_switch.py::test_iso_start_unit_from_md20154``)."""
    iso, siemens = first_view("iso-m")
    expected = {1: "G00", 2: "G17", 3: "G90", 4: "G23", 5: "G94", 7: "G40", 8: "G49", 9: "G80",
                10: "G98", 11: "G50", 12: "G67", 13: "G97", 14: "G54", 15: "G64", 16: "G69",
                17: "G15", 22: "G50.1", 31: "G291"}
    assert {g: iso.get(g) for g in expected} == expected
    assert siemens[10] == "G64"


def test_digest_iso_dialects_rank_02_iso_t_start_up_g_codes() -> None:
    """Digest iso-dialects-840d rank 2: ISO T (code system B) starts in G18, G95, G97
    (000 L5035-5048: [1]=2 G97, [4]=2 G95, [15]=2 G18)."""
    iso, _siemens = first_view("iso-t")
    assert (iso[2], iso[5], iso[16], iso[31]) == ("G97", "G95", "G18", "G291")


def test_digest_iso_dialects_rank_05_frames_are_shared_with_siemens_mode() -> None:
    """Digest iso-dialects-840d rank 5: G10 L2 P1 X10 Y10 writes G54 (000 L4502-4518); after
    G290 the Siemens G54 frame reads X10 Y10, the offsets carry across (000 L442)."""
    data = NcData()
    text = "G10 L2 P1 X10. Y10.\nG290\nR1=$P_UIFR[1,X,TR] R2=$P_UIFR[1,Y,TR]\nM30\n"
    result = interpret_only(load_machine(None), MemorySource(), data, "T.MPF", text=text,
                            max_blocks=100, dialect="iso-m")
    assert result.status == "ended", result.alarms
    assert (data.r[1], data.r[2]) == (10.0, 10.0)
