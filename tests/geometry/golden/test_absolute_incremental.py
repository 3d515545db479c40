"""Property: the same path written in G90 and in G91 reaches the same end points (WCS and MCS)."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from .helpers import mill_data, run

coord = st.floats(min_value=-200, max_value=200, allow_nan=False).map(lambda v: round(v, 3))
angle = st.floats(min_value=10, max_value=350, allow_nan=False).map(lambda v: round(v, 3))


@st.composite
def path(draw):
    """A list of moves: ('G1', x, y, z) or ('G2'/'G3', i, j, sweep_deg, dz)."""
    moves = []
    for _ in range(draw(st.integers(min_value=1, max_value=6))):
        if draw(st.booleans()):
            moves.append(("G1", draw(coord), draw(coord), draw(coord)))
        else:
            i, j = draw(coord), draw(coord)
            if math.hypot(i, j) < 1.0:
                i += 5.0
            moves.append((draw(st.sampled_from(["G2", "G3"])), i, j, draw(angle), draw(coord)))
    return moves


frame_blocks = st.lists(
    st.sampled_from(["TRANS X10 Y-5", "AROT RPL=30", "ASCALE X2 Y2", "AMIRROR X0", "ATRANS Z3",
                     "AROT X20", "G54"]),
    max_size=3,
)


def programs(moves, frames: list[str]) -> tuple[str, str]:
    """Write the moves twice: absolute (G90) and incremental (G91)."""
    absolute, incremental = list(frames) + ["G0 G90 X0 Y0 Z0", "T1 M6 D1"], list(frames) + ["G0 G90 X0 Y0 Z0", "T1 M6 D1"]
    x = y = z = 0.0
    for move in moves:
        if move[0] == "G1":
            _, nx, ny, nz = move
            absolute.append(f"G90 G1 X{nx:.3f} Y{ny:.3f} Z{nz:.3f} F1000")
            incremental.append(f"G91 G1 X{nx - x:.3f} Y{ny - y:.3f} Z{nz - z:.3f} F1000")
        else:
            kind, i, j, sweep, dz = move
            cx, cy = x + i, y + j
            turn = math.radians(sweep) * (-1 if kind == "G2" else 1)
            rx, ry = x - cx, y - cy
            nx = round(cx + rx * math.cos(turn) - ry * math.sin(turn), 3)
            ny = round(cy + rx * math.sin(turn) + ry * math.cos(turn), 3)
            nz = round(z + dz, 3)
            absolute.append(f"G90 {kind} X{nx:.3f} Y{ny:.3f} Z{nz:.3f} I{i:.3f} J{j:.3f} F1000")
            incremental.append(f"G91 {kind} X{nx - x:.3f} Y{ny - y:.3f} Z{nz - z:.3f} I{i:.3f} J{j:.3f} F1000")
        x, y, z = (nx, ny, nz)
    return "\n".join(absolute + ["M30"]) + "\n", "\n".join(incremental + ["M30"]) + "\n"


@settings(max_examples=40, deadline=None)
@given(path(), frame_blocks)
def test_g90_and_g91_reach_the_same_points(moves, frames) -> None:
    absolute, incremental = programs(moves, frames)
    data = mill_data({"X": 100.0, "Y": 50.0, "Z": -20.0}, length_mm=80.0)
    a = run(absolute, data)
    b = run(incremental, mill_data({"X": 100.0, "Y": 50.0, "Z": -20.0}, length_mm=80.0))
    assert len(a.motions) == len(b.motions)
    for ma, mb in zip(a.motions, b.motions):
        for axis in ("X", "Y", "Z"):
            assert math.isclose(ma.end_mcs[axis], mb.end_mcs[axis], abs_tol=1e-6)
            assert math.isclose(ma.end_wcs[axis], mb.end_wcs[axis], abs_tol=1e-6)
        if ma.center_mcs is not None:
            for axis in ("X", "Y"):
                assert math.isclose(ma.center_mcs[axis], mb.center_mcs[axis], abs_tol=1e-6)


def test_worked_example_from_the_manual() -> None:
    # 840C guide L1665: from P1 (20,10), G90 X60 Y30 and G91 X40 Y20 reach the same point.
    a = run("G0 X20 Y10\nG90 G1 X60 Y30 F100\nM30\n")
    b = run("G0 X20 Y10\nG91 G1 X40 Y20 F100\nM30\n")
    assert a.motions[-1].end_mcs == b.motions[-1].end_mcs == {"X": 60.0, "Y": 30.0, "Z": 0.0}
