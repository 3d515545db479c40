"""Selection, deselection, NORM/KONT, dummy blocks, D changes, mirroring, streaming."""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError
from nck.geometry.radius_comp import (
    ContourElement,
    RadiusCompensator,
    TrcSettings,
    compensate,
    with_state,
)
from tests.radius_comp.helpers import assert_continuous, assert_path, circ, lin


def straight(approach_from, retract_to, approach="NORM", mode="G450", retract_mode=None):
    """Approach to (0,0), one block (0,0)→(50,0) with G41 r=5, G40 to ``retract_to``."""
    return [
        lin(approach_from, (0, 0), "N10", approach=approach, corner_mode=mode),
        lin((0, 0), (50, 0), "N20", approach=approach, corner_mode=mode),
        lin((50, 0), retract_to, "N30", side="G40", approach=approach,
            corner_mode=retract_mode or mode),
    ]


def test_norm_approach_and_retract_go_to_the_normal_points():
    """Digest 828d-3 rank 22 (G41 centre path R to the left; G40 ends on the programmed point, NORM)."""
    # NORM: straight to (0, 5), perpendicular to the first block at its start,
    # and straight from (50, 5) to the end point — wherever the start/end point is.
    out = compensate(straight((20, -10), (30, -10)))
    assert_path(out, [
        ("N10", "G1", (20, -10), (0, 5)),
        ("N20", "G1", (0, 5), (50, 5)),
        ("N30", "G1", (50, 5), (30, -10)),
    ])
    assert out[0].role == "approach" and out[-1].role == "retract"


def test_kont_from_behind_goes_round_the_contour_point():
    # Start (20, −10) lies behind the contour start (0, 0) on the material side.
    # KONT: to the normal point of the approach line at (0,0), i.e. r to its left:
    # a = (−2, 1)/√5, left (−1, −2)/√5 → (−√5, −2√5); then a G2 arc R5 about (0,0)
    # to (0, 5). Retraction to (30, −10) mirrors it about x = 25.
    m = (-math.sqrt(5), -2 * math.sqrt(5))
    out = compensate(straight((20, -10), (30, -10), approach="KONT"))
    assert_path(out, [
        ("N10", "G1", (20, -10), m),
        ("N10", "G2", m, (0, 5), (0, 0)),
        ("N20", "G1", (0, 5), (50, 5)),
        ("N30", "G2", (50, 5), (50 - m[0], m[1]), (50, 0)),
        ("N30", "G1", (50 - m[0], m[1]), (30, -10)),
    ])
    assert out[1].inserted and out[3].inserted
    assert_continuous(out)


def test_kont_in_front_of_the_contour_equals_norm():
    front = straight((-20, -10), (70, -10), approach="KONT")
    norm = straight((-20, -10), (70, -10), approach="NORM")
    assert [(o.start, o.end) for o in compensate(front)] == [(o.start, o.end) for o in compensate(norm)]


def test_kont_g451_from_behind_uses_the_intersection():
    # Start (20, −40): approach direction (−1, 2)/√5 turns 116.6° onto +X, behind
    # the contour. Above MD20210 = 100° G451 inserts the circle; with MD20210 = 120°
    # the approach ends at the intersection of its offset line with y = 5, which lies
    # r·tan(θ/2) before the corner: θ/2 = 58.28°, tan = (1 + √5)/2 → x = −8.0902.
    blocks = straight((20, -40), (70, 0), approach="KONT", mode="G451")
    assert compensate(blocks)[1].kind == "G2"
    out = compensate(blocks, TrcSettings(corner_limit_deg=120))
    x = -5 * (1 + math.sqrt(5)) / 2
    assert_path(out[:2], [
        ("N10", "G1", (20, -40), (x, 5)),
        ("N20", "G1", (x, 5), (50, 5)),
    ])


def test_selection_only_in_linear_block_10753():
    """Digest 828d-3 rank 22 (G41 in a G2 block is refused)."""
    block = circ((0, 0), (10, 10), (0, 10), "N10", ccw=True)
    comp = RadiusCompensator()
    with pytest.raises(NcAlarmError) as info:
        comp.feed(block)
    assert info.value.number == 10753 and info.value.trc_source == "N10"
    assert not comp.active


def test_deselection_only_in_linear_block_10754():
    comp = RadiusCompensator()
    comp.feed(lin((-10, 0), (0, 0), "N10"))
    comp.feed(lin((0, 0), (20, 0), "N20"))
    with pytest.raises(NcAlarmError) as info:
        comp.feed(circ((20, 0), (30, 10), (20, 10), "N30", ccw=True, side="G40"))
    assert info.value.number == 10754
    assert comp.active  # unchanged: the block can be corrected


def test_d0_while_active_raises_10750_and_keeps_compensation():
    """Digest 828d-3 rank 22 (D0 while G41 active: 10750, compensation kept)."""
    comp = RadiusCompensator()
    comp.feed(lin((-10, 0), (0, 0), "N10"))
    comp.feed(lin((0, 0), (20, 0), "N20"))
    with pytest.raises(NcAlarmError) as info:
        comp.feed(lin((20, 0), (20, 20), "N30", edge=0))
    assert info.value.number == 10750
    assert comp.active
    out = comp.feed(lin((20, 0), (20, 20), "N30")) + comp.flush()
    assert any(o.source == "N30" for o in out)


def test_d0_selects_nothing():
    """Digest 828d-3 rank 22 (G41 with D0: no compensation)."""
    blocks = [lin((-10, 0), (0, 0), "N10", edge=0), lin((0, 0), (20, 0), "N20", edge=0)]
    out = compensate(blocks)
    assert [o.role for o in out] == ["uncompensated", "uncompensated"]
    assert [o.end for o in out] == [(0, 0), (20, 0)]


def test_g40_in_the_block_after_selection_selects_nothing():
    blocks = [lin((-10, 0), (0, 0), "N10"), lin((0, 0), (20, 0), "N20", side="G40")]
    out = compensate(blocks)
    assert [(o.source, o.start, o.end) for o in out] == [
        ("N10", (-10, 0), (0, 0)), ("N20", (0, 0), (20, 0))]


def test_selection_waits_for_plane_motion():
    # G41 in a block that only moves Z: selection happens in the next plane block.
    blocks = [
        ContourElement("G1", (0, 0), (0, 0), source="N10", side="G41", radius_mm=5),
        lin((0, 0), (10, 0), "N20"),
        lin((10, 0), (10, 20), "N30"),
        lin((10, 20), (0, 30), "N40", side="G40"),
    ]
    out = compensate(blocks)
    assert out[0].role == "uncompensated" and out[0].source == "N10"
    assert out[1].source == "N20" and out[1].role == "approach"
    assert out[1].end == pytest.approx((5.0, 0.0))  # left normal point of N30 at (10, 0)


def dummy(n, **state):
    return ContourElement("G1", (20, 0), (20, 0), source=n, side="G41", radius_mm=5, **state)


def test_dummy_blocks_run_at_the_end_of_the_previous_offset():
    blocks = [
        lin((-10, 10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        dummy("N21"), dummy("N22"), dummy("N23"),
        lin((20, 0), (20, -20), "N30"),
        lin((20, -20), (40, -40), "N40", side="G40"),
    ]
    out = compensate(blocks)
    sources = [o.source for o in out]
    assert sources == ["N10", "N20", "N21", "N22", "N23", "N30", "N30", "N40"]
    # They sit at the end normal point of N20, before the transition circle of N30.
    for o in out[2:5]:
        assert o.kind == "dummy" and o.start == o.end
        assert o.end == pytest.approx((20.0, 5.0))
    assert out[5].kind == "G2"


def test_too_many_dummy_blocks_10762():
    comp = RadiusCompensator(TrcSettings(max_dummy_blocks=3))
    comp.feed(lin((-10, 10), (0, 0), "N10"))
    comp.feed(lin((0, 0), (20, 0), "N20"))
    for n in ("N21", "N22", "N23"):
        comp.feed(dummy(n))
    with pytest.raises(NcAlarmError) as info:
        comp.feed(dummy("N24"))
    assert info.value.number == 10762 and info.value.trc_source == "N24"


def test_g40_with_only_an_infeed_axis_deselects():
    blocks = [
        lin((-10, 10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        ContourElement("G1", (20, 0), (20, 0), source="N30", side="G40", geometry_axis=True),
        lin((20, 0), (30, 0), "N40", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (-10, 10), (0, 5)),
        ("N20", "G1", (0, 5), (20, 5)),
        ("N30", "G1", (20, 5), (20, 0)),
        ("N40", "G1", (20, 0), (30, 0)),
    ])
    assert out[-1].role == "uncompensated"


def test_mirroring_swaps_g41_and_g42():
    plain = [lin((-10, 10), (0, 0), "N10", side="G42"), lin((0, 0), (20, 0), "N20", side="G42"),
             lin((20, 0), (30, 10), "N30", side="G40")]
    mirrored = [with_state(b, side="G41" if b.side == "G42" else b.side, mirrored=True) for b in plain]
    assert [(o.start, o.end) for o in compensate(plain)] == [(o.start, o.end) for o in compensate(mirrored)]
    assert compensate(mirrored)[1].start == pytest.approx((0.0, -5.0))


def test_change_of_d_on_a_straight_line_inserts_a_link():
    # Same direction, radius 5 then 8: the end normal (20, 5) and the start normal
    # (20, 8) are joined by an inserted line that belongs to the new block.
    blocks = [
        lin((-10, -10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        lin((20, 0), (40, 0), "N30", radius=8.0, edge=2),
        lin((40, 0), (50, -10), "N40", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (-10, -10), (0, 5)),
        ("N20", "G1", (0, 5), (20, 5)),
        ("N30", "G1", (20, 5), (20, 8)),
        ("N30", "G1", (20, 8), (40, 8)),
        ("N40", "G1", (40, 8), (50, -10)),
    ])
    assert out[2].inserted and out[2].role == "link"


def test_change_of_d_at_an_inside_corner_uses_both_radii():
    # Old radius 5 at the block start intersection, new radius 2 for the next block:
    # y = 5 meets x = 20 − 2 = 18.
    blocks = [
        lin((-10, -10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        lin((20, 0), (20, 30), "N30", radius=2.0, edge=2),
        lin((20, 30), (30, 40), "N40", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out[1:3], [("N20", "G1", (0, 5), (18, 5)), ("N30", "G1", (18, 5), (18, 30))])


def test_change_of_side_links_the_normal_points():
    blocks = [
        lin((-10, -10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        lin((20, 0), (40, 0), "N30", side="G42"),
        lin((40, 0), (50, 0), "N40", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out[1:4], [
        ("N20", "G1", (0, 5), (20, 5)),
        ("N30", "G1", (20, 5), (20, -5)),
        ("N30", "G1", (20, -5), (40, -5)),
    ])


def test_streaming_lags_by_the_look_ahead_and_matches_batch():
    points = [(0, 0), (30, 0), (30, 30), (60, 30), (60, 0), (90, 0), (90, 40)]
    blocks = [lin((-10, -10), (0, 0), "N5")]
    blocks += [lin(a, b, f"N{10 * (i + 1)}") for i, (a, b) in enumerate(zip(points, points[1:]))]
    blocks.append(lin((90, 40), (100, 50), "N99", side="G40"))
    comp = RadiusCompensator(TrcSettings(max_check_blocks=2))
    streamed = []
    released_after = []
    for block in blocks:
        got = comp.feed(block)
        streamed += got
        released_after.append({o.source for o in got})
    streamed += comp.flush()
    assert [(o.source, o.start, o.end) for o in streamed] == [
        (o.source, o.start, o.end) for o in compensate(blocks, TrcSettings(max_check_blocks=2))]
    # The first contour block is released only once two more blocks are known.
    assert "N10" not in released_after[1] | released_after[2]
    assert "N10" in released_after[3]
    # Every block is in the output exactly as often as it has elements, in order.
    order = [o.source for o in streamed]
    assert order.index("N10") < order.index("N20") < order.index("N60") < order.index("N99")


def test_flush_ends_at_the_offset_point_and_restart_links():
    comp = RadiusCompensator()
    out = comp.feed(lin((-10, -10), (0, 0), "N10")) + comp.feed(lin((0, 0), (20, 0), "N20"))
    out += comp.flush()  # preprocessing stop
    assert out[-1].end == pytest.approx((20.0, 5.0))
    more = comp.feed(lin((20, 0), (20, 20), "N30")) + comp.flush()
    # The block after the stop starts with a line to its own start normal point (15, 0).
    assert_path(more, [
        ("N30", "G1", (20, 5), (15, 0)),
        ("N30", "G1", (15, 0), (15, 20)),
    ])


def test_settings_from_machine_data():
    class FakeMachine:
        def md_value(self, ident, axis=None, default=None):
            return {"MD20210": 120, "MD20250": 5}.get(ident, default)

    settings = TrcSettings.from_machine(FakeMachine())
    assert settings.corner_limit_deg == 120 and settings.max_dummy_blocks == 5
    assert settings.max_check_blocks == 3


def test_cdon_finds_the_bottleneck_past_an_adjacent_intersection():
    # A groove 2 mm wide and 2 mm deep in a wall, tool r = 5 on top (G41). The tool
    # cannot enter: its centre runs round the groove edge (20, 0) and then round the
    # edge (22, 0); the two transition circles R5 cross at (21, √24). With CDON that
    # crossing is found past the groove blocks, which are left out (warning 10763).
    # With CDOF only neighbouring blocks are searched and the groove gives 10751.
    points = [(0, 0), (20, 0), (20, -2), (22, -2), (22, 0), (40, 0)]

    def blocks(cdon):
        out = [lin((-10, 10), (0, 0), "N10", collision_detection=cdon)]
        out += [lin(a, b, f"N{20 + 10 * i}", collision_detection=cdon)
                for i, (a, b) in enumerate(zip(points, points[1:]))]
        out.append(lin((40, 0), (50, 10), "N99", side="G40"))
        return out

    out = compensate(blocks(True))
    y = math.sqrt(24)
    assert_path(out, [
        ("N10", "G1", (-10, 10), (0, 5)),
        ("N20", "G1", (0, 5), (20, 5)),
        ("N30", "G2", (20, 5), (21, y), (20, 0)),
        ("N40", "dummy", (21, y), (21, y)),
        ("N50", "dummy", (21, y), (21, y)),
        ("N60", "G2", (21, y), (22, 5), (22, 0)),
        ("N60", "G1", (22, 5), (40, 5)),
        ("N99", "G1", (40, 5), (50, 10)),
    ])
    assert [o.source for o in out if o.warning == 10763] == ["N40", "N50"]
    assert_continuous(out)
    with pytest.raises(NcAlarmError) as info:
        compensate(blocks(False))
    assert info.value.number == 10751


def test_short_last_block_g462_extends_it_by_its_end_tangent():
    # Manual example (W1 G461/G462): G42, r = 20; N10 along −X on y = 0, N20 only
    # 10 mm up, then G40 to (50, 50). The offsets y = 20 (N10) and x = 20 (N20, y 0…10)
    # do not meet; G462 extends N20 by its end tangent (x = 20 upwards) to (20, 20):
    # the tool stops there and retracts; N20 itself has no motion left in the plane.
    blocks = [
        lin((130, 20), (110, 0), "N5", side="G42", radius=20),
        lin((110, 0), (0, 0), "N10", side="G42", radius=20),
        lin((0, 0), (0, 10), "N20", side="G42", radius=20),
        lin((0, 10), (50, 50), "N30", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N5", "G1", (130, 20), (110, 20)),
        ("N10", "G1", (110, 20), (20, 20)),
        ("N20", "dummy", (20, 20), (20, 20)),
        ("N30", "G1", (20, 20), (50, 50)),
    ])
