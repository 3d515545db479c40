"""Small builders for radius compensation tests."""

from __future__ import annotations

from nck.geometry.radius_comp import CompensatedElement, ContourElement

TOL = 1e-6


def chain(points, side="G41", radius=5.0, kind="G1", first_n=10, **state):
    """Lines through ``points`` as blocks N10, N20, … with one compensation state."""
    out = []
    for index, (a, b) in enumerate(zip(points, points[1:])):
        out.append(
            ContourElement(kind, a, b, source=f"N{first_n + 10 * index}", side=side,
                           radius_mm=radius, **state)
        )
    return out


def lin(a, b, n, side="G41", radius=5.0, kind="G1", **state):
    """One linear block."""
    return ContourElement(kind, a, b, source=n, side=side, radius_mm=radius, **state)


def circ(a, b, centre, n, ccw, side="G41", radius=5.0, **state):
    """One arc block (G3 if ``ccw``)."""
    return ContourElement("G3" if ccw else "G2", a, b, source=n, center=centre, side=side,
                          radius_mm=radius, **state)


def rounded(out: list[CompensatedElement], digits: int = 4):
    """(source, kind, start, end, centre) tuples rounded for comparison."""
    def r(p):
        return None if p is None else (round(p[0], digits) + 0.0, round(p[1], digits) + 0.0)
    return [(o.source, o.kind, r(o.start), r(o.end), r(o.center)) for o in out]


def assert_path(out, expected, tol=TOL):
    """Compare output elements with (source, kind, start, end[, centre]) expectations."""
    assert len(out) == len(expected), rounded(out)
    for got, want in zip(out, expected):
        source, kind, start, end = want[:4]
        centre = want[4] if len(want) > 4 else None
        assert got.source == source, (rounded([got]), want)
        assert got.kind == kind, (rounded([got]), want)
        assert abs(got.start[0] - start[0]) < tol and abs(got.start[1] - start[1]) < tol, (rounded([got]), want)
        assert abs(got.end[0] - end[0]) < tol and abs(got.end[1] - end[1]) < tol, (rounded([got]), want)
        if centre is not None:
            assert got.center is not None
            assert abs(got.center[0] - centre[0]) < tol and abs(got.center[1] - centre[1]) < tol


def assert_continuous(out, tol=TOL):
    """Every element starts where the previous one ended."""
    for a, b in zip(out, out[1:]):
        assert abs(a.end[0] - b.start[0]) < tol and abs(a.end[1] - b.start[1]) < tol, rounded([a, b])
