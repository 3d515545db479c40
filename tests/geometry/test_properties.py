"""Property tests: frame inverse, arcs on their circle, contour aids tangent."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from nck.errors import NcAlarmError
from nck.geometry.circles import arc_from_center, arc_from_radius, arc_through_point
from nck.geometry.frames import Frame
from nck.geometry.planes import plane

coord = st.floats(min_value=-500, max_value=500, allow_nan=False)
angle = st.floats(min_value=-360, max_value=360, allow_nan=False)
factor = st.floats(min_value=0.1, max_value=10, allow_nan=False)
planes = st.sampled_from(["G17", "G18", "G19"])


@st.composite
def frames(draw) -> Frame:
    frame = Frame.identity()
    for _ in range(draw(st.integers(min_value=1, max_value=5))):
        kind = draw(st.sampled_from(["trans", "rot", "scale", "mirror", "rpl"]))
        if kind == "trans":
            frame = frame.atrans({"X": draw(coord), "Y": draw(coord), "Z": draw(coord)})
        elif kind == "rot":
            frame = frame.arot({"X": draw(angle), "Y": draw(angle), "Z": draw(angle)})
        elif kind == "rpl":
            frame = frame.arot_plane(plane(draw(planes)), draw(angle))
        elif kind == "scale":
            frame = frame.ascale({"X": draw(factor), "Y": draw(factor), "Z": draw(factor)})
        else:
            frame = frame.amirror({draw(st.sampled_from(["X", "Y", "Z"])): 0})
    return frame


@settings(max_examples=60, deadline=None)
@given(frames(), coord, coord, coord)
def test_frame_followed_by_its_inverse_is_identity(frame: Frame, x: float, y: float, z: float) -> None:
    t = frame.to_transform()
    assert (t @ t.inverse()).is_identity(1e-6)
    assert (t.inverse() @ t).is_identity(1e-6)
    back = t.inverse().apply(t.apply({"X": x, "Y": y, "Z": z}))
    assert math.isclose(back["X"], x, abs_tol=1e-6)
    assert math.isclose(back["Y"], y, abs_tol=1e-6)
    assert math.isclose(back["Z"], z, abs_tol=1e-6)


def on_circle(arc) -> None:
    for point in (arc.start, arc.end, arc.point_at(0.37)):
        radial = [p - c for p, c in zip(point, arc.center)]
        along = sum(r * a for r, a in zip(radial, arc.axis))
        in_plane = math.sqrt(max(sum(r * r for r in radial) - along * along, 0.0))
        assert math.isclose(in_plane, arc.radius, rel_tol=1e-7, abs_tol=1e-7)
    # The end of the sweep is the programmed end point.
    assert all(math.isclose(a, b, abs_tol=1e-6) for a, b in zip(arc.point_at(1.0), arc.end))


@settings(max_examples=80, deadline=None)
@given(planes, coord, coord, coord, coord, st.floats(min_value=1, max_value=300), st.booleans(),
       st.booleans(), st.integers(min_value=0, max_value=3), coord)
def test_radius_arcs_start_and_end_on_their_circle(code, sa, so, ea, eo, r, cw, large, turns, app) -> None:
    p = plane(code)
    start = p.from_plane((sa, so, 0.0))
    end = p.from_plane((ea, eo, app))
    try:
        arc = arc_from_radius(p, start, end, -r if large else r, cw, turns)
    except NcAlarmError as alarm:
        assert alarm.number in (14040, 14095)
        chord = math.hypot(ea - sa, eo - so)
        assert chord < 1e-9 or r < chord / 2 + 1e-2
        return
    on_circle(arc)
    assert arc.clockwise_in(p) == cw


@settings(max_examples=80, deadline=None)
@given(planes, coord, coord, coord, coord, st.booleans(), st.integers(min_value=0, max_value=2), coord)
def test_center_arcs_start_and_end_on_their_circle(code, sa, so, ca, co, cw, turns, app) -> None:
    p = plane(code)
    start = p.from_plane((sa, so, 0.0))
    r = math.hypot(sa - ca, so - co)
    if r < 1e-3:
        return
    # An end point on the same circle, at 1 radian from the start.
    ang = math.atan2(so - co, sa - ca) + 1.0
    end = p.from_plane((ca + r * math.cos(ang), co + r * math.sin(ang), app))
    arc = arc_from_center(p, start, end, (ca, co), cw, turns)
    on_circle(arc)


@settings(max_examples=60, deadline=None)
@given(st.lists(coord, min_size=9, max_size=9))
def test_cip_arcs_pass_through_all_three_points(v: list[float]) -> None:
    s, m, e = tuple(v[0:3]), tuple(v[3:6]), tuple(v[6:9])
    try:
        arc = arc_through_point(s, m, e)
    except NcAlarmError:
        return
    if arc is None:
        return
    for point in (s, m, e):
        assert math.isclose(math.dist(point, arc.center), arc.radius, rel_tol=1e-6, abs_tol=1e-6)
    on_circle(arc)
