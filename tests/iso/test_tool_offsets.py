"""ISO M tool offsets (section 9 item 10, milling): $TC_DPH H numbers, G43 H / G41 D through
them, 17183 for a duplicate H, G10 L10–L13 offset writes; the manual's square example."""

from __future__ import annotations

import pytest

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.iso.translate import translate
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge

from tests.iso.conftest import ends

SETUP = ("G290\n$TC_DP1[2,3]=120 $TC_DP3[2,3]=15 $TC_DP6[2,3]=4\n$TC_DPH[2,3]=4\n"
         "$TC_DP1[2,4]=120 $TC_DP3[2,4]=30 $TC_DPH[2,4]=5\nG291\n")


def _run(text: str, data: NcData | None = None, dialect: str = "iso-m"):
    machine = load_machine(None)
    machine.md.update(MD22550=0)  # the manual's recommended setting: offsets act on T/H/D
    return interpret_only(machine, MemorySource(), data or NcData(), "T.MPF", dialect=dialect,
                          text=text, max_blocks=2000)


def test_g43_h_applies_length_of_the_edge_with_that_h_number():
    """Digest iso-dialects-840d rank 10 (000 L2917-2985)."""
    result = _run(SETUP + "T2 G43 H4 Z0\nG00 X1.\nM30\n")
    assert result.status == "ended", result.alarms
    assert ends(result, "mcs")[0][1] == {"X": 0.0, "Y": 0.0, "Z": 15.0}  # T2 D3, not D4
    assert ends(result, "wcs")[-1][1]["Z"] == 0.0
    assert result.interpreter.modal.edge == 3


def test_h_number_of_the_active_tool_in_a_later_block():
    result = _run(SETUP + "T2\nG43 H5 Z0\nM30\n")
    assert result.status == "ended", result.alarms
    assert ends(result, "mcs")[-1][1]["Z"] == 30.0


def test_unknown_h_number_raises_an_alarm():
    """Digest iso-dialects-840d rank 10."""
    result = _run(SETUP + "T2 G43 H9 Z0\nM30\n")
    assert result.status == "alarm"
    assert result.alarms[0].number == 12550


def test_h_number_of_another_tool_is_not_found():
    result = _run(SETUP + "T1 G43 H4 Z0\nM30\n")
    assert result.alarms[0].number == 12550


def test_duplicate_h_number_raises_17183_with_its_holder():
    """Digest iso-dialects-840d rank 10."""
    result = _run(SETUP + "G290\n$TC_DPH[1,1]=4\nM30\n")
    assert result.alarms[0].number == 17183
    assert result.alarms[0].params[-2:] == ("2", "3")


def test_rewriting_the_same_edge_and_h0_are_allowed():
    result = _run(SETUP + "G290\n$TC_DPH[2,3]=4\n$TC_DPH[1,1]=0\nR1=$TC_DPH[2,3]\nM30\n")
    assert result.status == "ended", result.alarms
    assert result.interpreter.r(1) == 4.0


def test_dph_is_kept_in_the_tool_data():
    data = NcData()
    result = _run(SETUP + "M30\n", data)
    assert result.status == "ended", result.alarms
    from nck.iso.tool_offsets import H_NUMBER_PARAM
    assert data.tools[(2, 3)].params[H_NUMBER_PARAM] == 4.0


def test_without_any_h_numbers_the_number_is_the_edge():
    data = NcData()
    data.tools[(1, 2)] = ToolEdge({1: 120, 3: 12.0})
    result = _run("T1 G43 H2 Z0\nM30\n", data)
    assert result.status == "ended", result.alarms
    assert ends(result, "mcs")[-1][1]["Z"] == 12.0


@pytest.mark.parametrize("block, param, value", [("G10 L10 P4 R20.", 3, 20.0),
                                                 ("G10 L11 P4 R0.5", 12, 0.5),
                                                 ("G10 L1 P4 R0.25", 12, 0.25),
                                                 ("G10 L12 P4 R6.", 6, 6.0),
                                                 ("G10 L13 P4 R-0.1", 15, -0.1)])
def test_g10_l10_to_l13_write_the_edge_of_the_h_number(block, param, value):
    data = NcData()
    result = _run(SETUP + block + "\nM30\n", data)
    assert result.status == "ended", result.alarms
    assert data.tools[(2, 3)].get(param) == pytest.approx(value)


def test_g10_under_g91_adds_and_unknown_h_is_refused():
    data = NcData()
    result = _run(SETUP + "G91 G10 L10 P4 R1.\nM30\n", data)
    assert result.status == "ended", result.alarms
    assert data.tools[(2, 3)].get(3) == pytest.approx(16.0)
    result = _run(SETUP + "G10 L10 P77 R1.\nM30\n")
    assert result.alarms[0].number == 12550


def test_g10_outside_the_tool_value_limit_is_alarm_17090_and_writes_nothing():
    """The ISO door writes tool data under the same rule as every other door (issue 19: one
    write path; nck/writes.py tool values within ±100,000 mm; 17090 data/alarms/language.toml)."""
    data = NcData()
    result = _run(SETUP + "G10 L10 P4 R200000.\nM30\n", data)
    assert [a.number for a in result.alarms] == [17090]
    assert data.tools[(2, 3)].get(3) != 200000.0


def test_translation_selects_by_h_number():
    assert translate("T2 G43 H4 Z0")[0].blocks == ["Z0 T2 D=$TC_ISOH_EDGE[2,4]"]
    assert translate("G41 D7 X1.")[0].blocks == ["G41 X1 D=$TC_ISOH_EDGE[$P_TOOLNO,7]"]
    assert translate("G49 Z0")[0].blocks == ["Z0 D0"]


MANUAL_SQUARE = """G290
$TC_DP1[2,1]=120 $TC_DPH[2,1]=7
$TC_DP1[3,2]=120 $TC_DPH[3,2]=3
G291
G10 L12 P7 R5.
G10 L10 P3 R15.
G10 L12 P3 R10.
N8 G01 G40 F5000 X0 Y0 Z0
N30 T2
N33 G43 H7 Z0
N35 G41 X0 Y0 Z0 D7
N40 X50.
N45 Y50.
N50 X0
N55 Y0
N60 G40 X-10. Y-10.
N65 T3
N68 G43 H3 Z0
N70 G42 X0 Y0 Z0 D3
N75 X50.
N77 Y50.
N80 X0
N85 Y0
N90 G40 X-10. Y-10.
M30
"""

SIEMENS_SQUARE = """$TC_DP1[2,1]=120
$TC_DP6[2,1]=5
$TC_DP1[3,2]=120
$TC_DP3[3,2]=15
$TC_DP6[3,2]=10
N8 G01 G40 F5000 X0 Y0 Z0
N30 T2
N33 D1 Z0
N35 G41 X0 Y0 Z0 D1
N40 X50
N45 Y50
N50 X0
N55 Y0
N60 G40 X-10 Y-10
N65 T3
N68 D2 Z0
N70 G42 X0 Y0 Z0 D2
N75 X50
N77 Y50
N80 X0
N85 Y0
N90 G40 X-10 Y-10
M30
"""


def test_manual_square_with_h_and_d_numbers_matches_siemens_t_d():
    iso = _run(MANUAL_SQUARE)
    siemens = _run(SIEMENS_SQUARE, dialect="siemens")
    assert iso.status == "ended", iso.alarms
    assert siemens.status == "ended", siemens.alarms
    iso_path = [point for _, point in ends(iso, "mcs")]
    assert iso_path == [point for _, point in ends(siemens, "mcs")]
    # second tool: length 15 on Z, radius 10 outside the square (G42 going round it CCW)
    assert {"X": 60.0, "Y": 50.0, "Z": 15.0} in iso_path
    assert {"X": 0.0, "Y": 60.0, "Z": 15.0} in iso_path
