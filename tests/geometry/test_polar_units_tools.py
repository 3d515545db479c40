"""Polar coordinates, inch/metric rules, planes and tool length compensation."""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.geometry.planes import plane
from nck.geometry.polar import PolarState
from nck.geometry.tool_length import length_axes, length_offset, resolve_edge
from nck.geometry.units import UnitSystem
from nck.ncdata import NcData, ToolEdge


def test_planes_name_their_axes() -> None:
    assert plane("G17").axes == ("X", "Y", "Z")
    assert plane("G18").axes == ("Z", "X", "Y")
    assert plane("G19").axes == ("Y", "Z", "X")
    p = plane("G18")
    assert p.to_plane((1, 2, 3)) == (3, 1, 2)
    assert p.from_plane((3, 1, 2)) == (1, 2, 3)


def test_polar_move_around_g111_pole() -> None:
    """Digest programming-840c rank 16."""
    # G111 X20 Y10, RP=50 AP=30: (20 + 50·cos30, 10 + 50·sin30) = (63.3013, 35).
    state = PolarState().define_pole("G111", last_position=(0, 0), axes=(20.0, 10.0))
    state = state.with_values(radius_mm=50.0, angle_deg=30.0)
    assert state.target() == pytest.approx((20 + 25 * 3 ** 0.5, 35.0))


def test_pole_codes() -> None:
    state = PolarState().define_pole("G111", (0, 0), axes=(20.0, 10.0))
    # G110: relative to the last position (30, 5) -> (20, 25).
    assert state.define_pole("G110", (30.0, 5.0), axes=(-10.0, 20.0)).pole == (20.0, 25.0)
    # G112: relative to the last pole (20, 10) -> (60, 30).
    assert state.define_pole("G112", (30.0, 5.0), axes=(40.0, 20.0)).pole == (60.0, 30.0)
    # Polar pole definition: G112 RP=10 AP=90 from (20,10) -> (20, 20).
    assert state.define_pole("G112", (0, 0), polar=(10.0, 90.0)).pole == pytest.approx((20.0, 20.0))


def test_no_pole_means_wcs_origin_and_values_are_modal() -> None:
    state = PolarState().with_values(radius_mm=10.0, angle_deg=90.0)
    assert state.target() == pytest.approx((0.0, 10.0))
    state = state.with_values(angle_deg=180.0)  # RP stays 10
    assert state.target() == pytest.approx((-10.0, 0.0))
    with pytest.raises(NcAlarmError):
        state.with_values(radius_mm=-1.0)


def test_polar_from_point_round_trip() -> None:
    state = PolarState(pole=(5.0, 5.0)).from_point((5.0, 15.0))
    assert state.radius_mm == pytest.approx(10.0)
    assert state.angle_deg == pytest.approx(90.0)


def test_unit_rules() -> None:
    g70 = UnitSystem("G70")
    assert g70.position_to_mm(1.0) == pytest.approx(25.4)
    assert g70.feed_to_mm(100.0) == pytest.approx(100.0)  # G70: feed stays in the basic system
    assert g70.data_mm == 1.0
    g700 = UnitSystem("G700")
    assert g700.feed_to_mm(100.0) == pytest.approx(2540.0)  # manual: G700 F100 = 2540 mm/min
    assert g700.data_mm == pytest.approx(25.4)
    assert UnitSystem("G710").feed_to_mm(100.0) == 100.0
    assert UnitSystem("G71").position_from_mm(25.4) == 25.4
    assert UnitSystem("G70").position_from_mm(25.4) == pytest.approx(1.0)
    # Inch basic system: G71 positions in mm, G70 feeds in inch/min.
    inch_basic = UnitSystem("G71", basic_metric=False)
    assert inch_basic.position_mm == 1.0 and inch_basic.feed_mm == pytest.approx(25.4)
    with pytest.raises(ValueError):
        UnitSystem("G20")


def mill_edge() -> ToolEdge:
    # Type 120 end mill, L1 = 100 + wear 0.5 + base 10, L2 = 3, L3 = 2.
    return ToolEdge({1: 120, 3: 100.0, 4: 3.0, 5: 2.0, 6: 5.0, 12: 0.5, 21: 10.0})


def test_milling_tool_lengths_per_plane() -> None:
    assert length_offset(mill_edge(), "G17") == {"X": 2.0, "Y": 3.0, "Z": 110.5}
    assert length_offset(mill_edge(), "G18") == {"X": 3.0, "Y": 110.5, "Z": 2.0}
    assert length_offset(mill_edge(), "G19") == {"X": 110.5, "Y": 2.0, "Z": 3.0}
    assert length_offset(None, "G17") == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    # Wear sign inverted (SD42930): 100 - 0.5 + 10.
    assert length_offset(mill_edge(), "G17", wear_sign=1)["Z"] == pytest.approx(109.5)
    # Frozen assignment SD42940 = 17 keeps Z while G18 is active.
    assert length_offset(mill_edge(), "G18", length_const=17)["Z"] == pytest.approx(110.5)


def test_turning_tool_lengths() -> None:
    edge = ToolEdge({1: 500, 3: 20.0, 4: 40.0})
    # G18 turning: L1 -> X, L2 -> Z.
    assert length_offset(edge, "G18") == {"X": 20.0, "Y": 0.0, "Z": 40.0}
    assert length_axes(500, "G17") == (1, 0, 2)
    assert length_axes(500, "G18", length_const=-18) == (2, 0, 1)
    assert length_axes(120, "G17", length_const=5) == (2, 1, 0)  # other values count as 17
    assert length_axes(500, "G17", length_type=1) == (2, 1, 0)  # SD42950 = 1: as milling


def test_missing_edge_is_an_alarm() -> None:
    data = NcData()
    data.tools[(1, 1)] = mill_edge()
    assert resolve_edge(data, 1, 1) is data.tools[(1, 1)]
    assert resolve_edge(data, 1, 0) is None
    with pytest.raises(NcAlarmError) as info:
        resolve_edge(data, 1, 2)
    assert info.value.number == 17180
