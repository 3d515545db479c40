"""Property tests of the interpreter: failing blocks are atomic; G90 and G91 agree."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

MACHINE = load_machine()
values = st.integers(min_value=-1000, max_value=1000)
writes = st.lists(st.tuples(st.integers(min_value=1, max_value=20), values), min_size=1, max_size=8)
failures = st.sampled_from(["R99=1/0", "R99=SQRT(-1)", "R99=UNDEFINED", "R[200]=1", "VALS[9]=1",
                            "G1234", "R99=LN(0)", "CNT=2147483648"])


@settings(max_examples=60, deadline=None)
@given(writes, writes, failures)
def test_a_failing_block_changes_no_state(setup, block_writes, failure) -> None:
    data = NcData()
    lines = ["DEF INT CNT", "DEF REAL VALS[3]"]
    lines += [f"R{i}={v} CNT={v} VALS[{abs(v) % 3}]={v}" for i, v in setup]
    lines.append(" ".join(f"R{i}={v + 1} CNT=CNT+1 VALS[0]={v}" for i, v in block_writes)
                 + f" G91 G1 X1 F100 $TC_DP1[1,1]=5 {failure}")
    interp = Interpreter(MACHINE, MemorySource(), data)
    interp.start_text("P.MPF", "\n".join(lines) + "\nM30\n")
    for _ in range(len(lines) - 1):
        interp.step()
    before = (list(data.r), dict(data.tools), interp.variable("CNT"),
              [interp.variable(f"VALS[{i}]") for i in range(3)],
              dict(interp.modal.gcodes), dict(interp.modal.position_wcs))
    try:
        interp.step()
    except NcAlarmError:
        pass
    else:  # pragma: no cover - every failure text must raise
        raise AssertionError("block did not fail")
    after = (list(data.r), dict(data.tools), interp.variable("CNT"),
             [interp.variable(f"VALS[{i}]") for i in range(3)],
             dict(interp.modal.gcodes), dict(interp.modal.position_wcs))
    assert after == before


moves = st.lists(st.tuples(st.integers(-50, 50), st.integers(-50, 50), st.integers(-20, 20)),
                 min_size=1, max_size=10)


def _ends(text: str) -> list[dict[str, float]]:
    interp = Interpreter(MACHINE, MemorySource(), NcData())
    interp.start_text("P.MPF", text)
    out = []
    while not interp.finished:
        out += [dict(c.end_wcs) for c in interp.step().commands if isinstance(c, canon.Motion)]
    return out


@settings(max_examples=40, deadline=None)
@given(moves)
def test_absolute_and_incremental_programs_reach_the_same_points(points) -> None:
    absolute = ["G90 G1 F500"] + [f"X{x} Y{y} Z{z}" for x, y, z in points]
    incremental = ["G91 G1 F500"]
    last = (0, 0, 0)
    for point in points:
        dx, dy, dz = (p - q for p, q in zip(point, last))
        incremental.append(f"X{dx} Y{dy} Z{dz}".replace("X-", "X-").replace("--", ""))
        last = point
    a = _ends("\n".join(absolute) + "\nM30\n")
    b = _ends("\n".join(incremental) + "\nM30\n")
    assert len(a) == len(b) == len(points)
    for p, q in zip(a, b):
        assert all(abs(p[k] - q[k]) < 1e-9 for k in p)
