"""Property: G71 roughing passes never cut into the contour plus its finishing allowance.

Random monotonic outside contours (Z falling, diameter rising, type I as G71 requires) and
random depths: every pass lies at start radius - k * depth, stays outside the shifted start
radius, never crosses the shifted contour, ends on it (or at the contour's end), and the
cycle returns to its start point.
"""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from tests.iso.test_turning import run_lathe

STEPS = st.lists(st.tuples(st.integers(0, 20), st.integers(0, 8)), min_size=1, max_size=5)


def _contour(r0: float, steps: list[tuple[int, int]], du: float, dw: float):
    """Shifted contour polyline [(z, r)] starting at Z2."""
    points = [(2.0 + dw, r0 + du / 2)]
    z, r = 2.0, r0
    for dz, dr in steps:
        z, r = z - (dz + 1), r + dr
        points.append((z + dw, r + du / 2))
    return points


def _radii_at(points, z: float) -> list[float]:
    out = []
    for (z0, r0), (z1, r1) in zip(points, points[1:]):
        low, high = min(z0, z1), max(z0, z1)
        if low - 1e-9 <= z <= high + 1e-9:
            out.append(r0 if abs(z1 - z0) < 1e-12 else r0 + (r1 - r0) * (z - z0) / (z1 - z0))
    return out


@settings(max_examples=30, deadline=None)
@given(r0=st.integers(3, 15), steps=STEPS, depth=st.sampled_from([0.7, 1.0, 1.5, 2.5]),
       margin=st.integers(1, 6), du=st.sampled_from([0.0, 0.4]), dw=st.sampled_from([0.0, 0.1]))
def test_g71_passes_stay_outside_the_shifted_contour(r0, steps, depth, margin, du, dw):
    contour = _contour(r0, steps, du, dw)
    top = max(r for _, r in contour) + margin
    lines = [f"G00 X{2 * top:.3f} Z2.", f"G71 U{depth} R0.3", f"G71 P10 Q{10 + len(steps)} "
             f"U{du} W{dw} F0.2", f"N10 G00 X{2 * r0}."]
    z, r = 2.0, float(r0)
    for index, (dz, dr) in enumerate(steps, start=1):
        z, r = z - (dz + 1), r + dr
        lines.append(f"N{10 + index} G01 X{2 * r:.3f} Z{z:.3f}")
    lines.append("M30")
    result = run_lathe("\n".join(lines) + "\n")
    assert result.status == "ended", result.alarms
    cycle = [m for m in result.segments if m.source.line == 3]
    start_r = contour[0][1]
    profile_start = next(i for i, m in enumerate(cycle) if m.kind == "G0"
                         and abs(m.end_wcs["X"] - 2 * start_r) < 1e-6
                         and abs(m.end_wcs["Z"] - contour[0][0]) < 1e-6)
    roughing = cycle[:profile_start]
    assert len(roughing) % 4 == 0  # rapid in, cut, lift, rapid back
    passes = [(roughing[i], roughing[i + 1]) for i in range(0, len(roughing), 4)]
    assert all(cut.kind == "G1" for _, cut in passes)
    for k, (approach, cut) in enumerate(passes, start=1):
        level = cut.end_wcs["X"] / 2
        assert level > start_r
        assert abs((top - level) / depth - round((top - level) / depth)) < 1e-6
        z_end = cut.end_wcs["Z"]
        for share in (0.0, 0.25, 0.5, 0.75, 0.999):
            z_probe = 2.0 + (z_end - 2.0) * share
            assert all(rc <= level + 1e-5 for rc in _radii_at(contour, z_probe))
        ends_on_contour = any(abs(rc - level) < 1e-5 for rc in _radii_at(contour, z_end))  # 1e-6 mm blocks
        assert ends_on_contour or abs(z_end - contour[-1][0]) < 1e-6
    last = cycle[-1].end_wcs
    assert (round(last["X"], 6), round(last["Z"], 6)) == (round(2 * top, 6), 2.0)


WORDS = st.sampled_from(["G00", "G01", "G02", "G03", "G32", "G70", "G71", "G72", "G73", "G74",
                         "G75", "G76", "G77", "G78", "G79", "G90", "G91", "G92", "G96", "G97",
                         "G10", "G28", "M03", "M98"])
ADDRESSES = st.sampled_from(list("XZUWPQRFSTIK"))
NUMBERS = st.sampled_from(["0", "1", "10", "-5.", "2.5", "100", "0.001", "012060", "-0.4"])


@st.composite
def _programs(draw):
    lines = []
    for number in range(1, draw(st.integers(1, 8)) + 1):
        words = [f"N{number * 10}"] + [draw(WORDS) for _ in range(draw(st.integers(0, 2)))]
        words += [draw(ADDRESSES) + draw(NUMBERS) for _ in range(draw(st.integers(0, 4)))]
        lines.append(" ".join(words))
    return "G00 X50. Z5.\n" + "\n".join(lines) + "\nM30\n"


@settings(max_examples=60, deadline=None)
@given(text=_programs(), system=st.sampled_from([0, 1]))
def test_random_iso_t_programs_raise_only_nc_alarms(text, system):
    """No traceback: every problem in a random ISO T program is an NC alarm of its line."""
    from nck.errors import NcAlarmError
    result = run_lathe(text, {"MD10881": system})
    assert result.status in ("ended", "alarm", "timeout")
    assert all(isinstance(alarm, NcAlarmError) for alarm in result.alarms)
