"""ISO dialect T tool words and offsets (ranked item 10, ISO T part; manual example L3126-3202).

MD 10888 = 2: ``T<tool: 2 digits><offset>``; ``G10 P<n>`` writes geometry of offset n,
``G10 P<100+n>`` its wear (MD 20734 bit 1 = 0). Offsets are the edges of the Siemens tool.
"""

from __future__ import annotations

import pytest

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.iso.translate import IsoSettings, translate
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge


def _data() -> NcData:
    data = NcData()
    for edge in (1, 2, 3, 4):  # tool 1 with cutting edges D1..D4 (turning tool type 500)
        data.tools[(1, edge)] = ToolEdge({1: 500.0, 2: 3.0})
    return data


def _run(text: str, data: NcData):
    return interpret_only(load_machine("lathe2"), MemorySource({}), data, "TOOLS.MPF", text=text,
                          max_blocks=1000, dialect="iso-t")


@pytest.mark.parametrize("word, expected", [("T0102", "T1 D2"), ("T1234", "T12 D34"),
                                            ("T123", "T12 D3"), ("T0100", "T1 D0")])
def test_tool_word_is_tool_then_offset(word, expected):
    """Digest iso-dialects-840d rank 10."""
    assert translate(word, "iso-t")[0].blocks == [expected]


def test_md10888_sets_the_number_of_tool_digits():
    """Digest iso-dialects-840d rank 10."""
    settings = IsoSettings(tool_digits=3)
    assert translate("T1234", "iso-t", settings)[0].blocks == ["T123 D4"]


def test_manual_example_g10_writes_geometry_and_wear_and_t0105_raises():
    """Digest iso-dialects-840d rank 10."""
    data = _data()
    text = ("N640 T0101\nN650 G10 P2 X10.\nN655 G10 P102 X1.\nN670 T0102\nN680 G00 X0 Z0\n"
            "N675 T0105\nM30\n")
    result = _run(text, data)
    assert data.edge(1, 2).get(3) == 10.0  # geometry length 1 (X) of edge 2
    assert data.edge(1, 2).get(12) == 1.0  # its wear
    assert data.edge(1, 1).get(3) == 0.0  # edge 1 untouched
    # with T0102 active, length 1 (geometry + wear = 11 mm, a radius) acts on X
    assert round(result.segments[0].end_mcs["X"], 3) == 11.0
    assert result.alarms[0].number == 17180 and result.alarms[0].n == 675


def test_g10_radius_edge_position_z_and_incremental_u_w():
    data = _data()
    text = "T0101\nG10 P3 X2. Z5. R0.8 Q2\nG10 P3 U1. W-1.\nG10 P103 Z0.2 R0.05\nM30\n"
    result = _run(text, data)
    assert result.status == "ended", result.alarms
    edge = data.edge(1, 3)
    assert (edge.get(3), edge.get(4), edge.get(6), edge.get(2)) == (3.0, 4.0, 0.8, 2.0)
    assert (edge.get(13), edge.get(15)) == (0.2, 0.05)


def test_g10_p0_raises():
    result = _run("T0101\nG10 P0 X1.\nM30\n", _data())
    assert result.alarms[0].number == 12550
