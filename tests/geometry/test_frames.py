"""Frames: components, chain order, additive commands, suppression.

Expected values are worked out by hand: a rotation by +90° about Z turns the
X axis onto +Y (right-hand rule), so a WCS point (10, 0, 0) lies at (0, 10, 0)
in the parent; translations add; scale multiplies; mirror negates.
"""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.geometry.chain import FrameChain, frame_from_work_offset
from nck.geometry.frames import Frame
from nck.geometry.planes import plane
from nck.ncdata import WorkOffset

ORIGIN = {"X": 0.0, "Y": 0.0, "Z": 0.0}


def approx(point: dict[str, float]) -> dict[str, object]:
    return {axis: pytest.approx(value, abs=1e-9) for axis, value in point.items()}


def apply(frame: Frame, **point: float) -> dict[str, float]:
    full = dict(ORIGIN)
    full.update(point)
    return frame.to_transform().apply(full)


def test_trans_then_atrans_adds_up() -> None:
    # Digest K2 §11.1: TRANS X10 Y10 Z10 then ATRANS X5 Y5 gives (15, 15, 10).
    frame = Frame.ctrans({"X": 10, "Y": 10, "Z": 10}).atrans({"X": 5, "Y": 5})
    assert apply(frame) == approx({"X": 15.0, "Y": 15.0, "Z": 10.0})


def test_g58_replaces_coarse_and_g59_the_fine_part() -> None:
    """Digest 828d-2 rank 21: totals (15,15,10) -> (25,15,10) -> (30,20,10) (002 L28592-28598)."""
    # Digest K2 §11.1 bookkeeping: (15,15,10) -> G58 X20 -> (25,15,10) -> G59 X10 Y10 -> (30,20,10).
    frame = Frame.ctrans({"X": 10, "Y": 10, "Z": 10}).atrans({"X": 5, "Y": 5})
    assert apply(frame) == approx({"X": 15.0, "Y": 15.0, "Z": 10.0})
    frame = frame.g58({"X": 20})
    assert apply(frame) == approx({"X": 25.0, "Y": 15.0, "Z": 10.0})
    frame = frame.g59({"X": 10, "Y": 10})
    assert apply(frame) == approx({"X": 30.0, "Y": 20.0, "Z": 10.0})


def test_rot_z90_turns_x_onto_y() -> None:
    """Digest 828d-2 rank 20 (rotation part; program form in tests/digests/test_828d_2.py)."""
    # Digest K2 test 20: after ROT Z90, G1 X10 from the WCS origin ends at BCS Y+10.
    assert apply(Frame.crot({"Z": 90}), X=10) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})


def test_rpl_rotates_about_the_applicate_of_each_plane() -> None:
    # G18 (Z-X plane): RPL=90 turns the abscissa Z onto the ordinate X.
    assert apply(Frame.crpl(plane("G18"), 90), Z=10) == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})
    # G19 (Y-Z plane): RPL=90 turns Y onto Z.
    assert apply(Frame.crpl(plane("G19"), 90), Y=10) == approx({"X": 0.0, "Y": 0.0, "Z": 10.0})


def test_rotation_order_is_z_then_y_then_x() -> None:
    # ROT X90 Z90: R = Rz(90)·Rx(90). WCS +Y -> Rx -> +Z -> Rz -> +Z.  WCS +Z -> Rx -> -Y -> Rz -> +X.
    frame = Frame.crot({"X": 90, "Z": 90})
    assert apply(frame, Y=1) == approx({"X": 0.0, "Y": 0.0, "Z": 1.0})
    assert apply(frame, Z=1) == approx({"X": 1.0, "Y": 0.0, "Z": 0.0})
    assert frame.rotation_deg == pytest.approx((90.0, 0.0, 90.0))


def test_atrans_after_rot_moves_along_rotated_axes() -> None:
    # ROT Z90 then ATRANS X10: the shift runs along the rotated X, i.e. parent +Y.
    frame = Frame.crot({"Z": 90}).atrans({"X": 10})
    assert apply(frame) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    assert frame.offset("Y") == pytest.approx(10.0)
    assert frame.fine["Y"] == pytest.approx(10.0)  # ATRANS books into the fine part


def test_ascale_scales_later_translations() -> None:
    # SCALE X2 Y2 then ATRANS X5: the shift is scaled to 10; a point X1 then lies at 10 + 2.
    frame = Frame.cscale({"X": 2, "Y": 2}).atrans({"X": 5})
    assert apply(frame, X=1) == approx({"X": 12.0, "Y": 0.0, "Z": 0.0})
    assert frame.ascale({"X": 3}).scale["X"] == pytest.approx(6.0)


def test_zero_scale_factor_is_an_alarm() -> None:
    with pytest.raises(NcAlarmError) as info:
        Frame.cscale({"X": 0})
    assert info.value.number == 18309
    with pytest.raises(NcAlarmError):
        Frame.identity().ascale({"Y": 0.0})


def test_mirror_and_amirror_toggle() -> None:
    frame = Frame.cmirror(["X"])
    assert apply(frame, X=10, Y=5) == approx({"X": -10.0, "Y": 5.0, "Z": 0.0})
    assert frame.to_transform().reverses_arcs(plane("G17"))
    # AMIRROR X0 with MIRROR_TOGGLE = 1 switches it off again.
    assert frame.amirror({"X": 0}).mirror == frozenset()
    # With MIRROR_TOGGLE = 0 the value decides: X0 switches off, X1 on.
    assert frame.amirror({"X": 1}, toggle=False).mirror == frozenset({"X"})
    assert frame.amirror({"X": 0}, toggle=False).mirror == frozenset()
    # Mirroring two plane axes keeps the circle direction.
    both = Frame.cmirror(["X", "Y"])
    assert not both.to_transform().reverses_arcs(plane("G17"))
    # Mirroring Z does not reverse a G17 circle but does reverse a G18 one.
    assert not Frame.cmirror(["Z"]).to_transform().reverses_arcs(plane("G17"))
    assert Frame.cmirror(["Z"]).to_transform().reverses_arcs(plane("G18"))


def test_arot_after_mirror_turns_the_other_way_in_the_parent() -> None:
    # MIRROR X0 then AROT Z90: WCS +X -> rotated to +Y -> mirror X leaves (0, 10).
    # WCS +Y -> rotated to -X -> mirrored to +X.
    frame = Frame.cmirror(["X"]).arot({"Z": 90})
    assert apply(frame, X=10) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    assert apply(frame, Y=10) == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})


def test_rotation_of_a_special_axis_is_refused() -> None:
    with pytest.raises(NcAlarmError) as info:
        Frame.crot({"A": 10})
    assert info.value.number == 14092


def test_special_axis_translation_and_scale() -> None:
    frame = Frame.ctrans({"A": 30}).ascale({"A": 2})
    assert frame.to_transform().apply({"X": 0, "Y": 0, "Z": 0, "A": 10}) == approx(
        {"X": 0.0, "Y": 0.0, "Z": 0.0, "A": 50.0}
    )


def test_chain_order_and_suppression() -> None:
    # Digest K2 test 20: G54 X=100, TRANS X10; WCS X = 40 at machine X = 150.
    g54 = frame_from_work_offset(WorkOffset(trans={"X": 100.0}))
    chain = FrameChain(settable_code="G54", settable=g54, programmable=Frame.ctrans({"X": 10}))
    t = chain.transform()
    assert t.inverse().apply({"X": 150.0, "Y": 0.0, "Z": 0.0})["X"] == pytest.approx(40.0)
    # G53: no settable and no programmable frame.
    assert chain.transform("G53").apply(ORIGIN)["X"] == pytest.approx(0.0)
    # G500 (zero frame) removes the settable part: WCS 140.
    g500 = chain.with_settable("G500", Frame())
    assert g500.transform().inverse().apply({"X": 150.0, "Y": 0, "Z": 0})["X"] == pytest.approx(140.0)


def test_base_frame_is_applied_outside_and_g153_suppresses_it() -> None:
    chain = FrameChain(
        base=Frame.ctrans({"Z": 5}),
        settable=Frame.crot({"Z": 90}),
        programmable=Frame.ctrans({"X": 10}),
    )
    # WCS origin -> prog (10,0,0) -> settable rot -> (0,10,0) -> base (0,10,5).
    assert chain.transform().apply(ORIGIN) == approx({"X": 0.0, "Y": 10.0, "Z": 5.0})
    assert chain.transform("G53").apply(ORIGIN) == approx({"X": 0.0, "Y": 0.0, "Z": 5.0})
    assert chain.transform("G153").apply(ORIGIN) == approx(ORIGIN)
    assert chain.transform("SUPA").apply(ORIGIN) == approx(ORIGIN)


def test_work_offset_conversion_keeps_all_components() -> None:
    offset = WorkOffset(
        trans={"X": 100.0, "Y": 50.0},
        fine={"X": 0.5},
        rot={"Z": 90.0},
        scale={"X": 2.0, "Y": 2.0},
        mirror={"Y": True},
    )
    frame = frame_from_work_offset(offset)
    assert frame.offset("X") == pytest.approx(100.5)
    assert frame.rotation_deg == pytest.approx((0.0, 0.0, 90.0))
    # WCS (1,0): scale 2 -> (2,0) -> rot 90 -> (0,2) -> shift -> (100.5, 52).
    assert apply(frame, X=1) == approx({"X": 100.5, "Y": 52.0, "Z": 0.0})
    # WCS (0,1): mirror Y and scale -> (0,-2) -> rot 90 -> (2,0) -> (102.5, 50).
    assert apply(frame, Y=1) == approx({"X": 102.5, "Y": 50.0, "Z": 0.0})
    # Inch data: translations scale by 25.4.
    assert frame_from_work_offset(WorkOffset(trans={"X": 1.0}), data_mm=25.4).offset("X") == pytest.approx(25.4)


def test_describe_lists_components() -> None:
    info = Frame.ctrans({"X": 5}).arot({"Z": 30}).describe()
    assert info["X"]["trans"] == 5.0
    assert info["Z"]["rot"] == pytest.approx(30.0)
    assert info["Y"]["mirror"] is False
