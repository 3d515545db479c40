"""``nck run --trace``: one CSV row per IPO cycle with the MCS setpoints."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from nck.cli import main


def test_run_writes_trace_every_ipo_cycle(tmp_path: Path, capsys) -> None:
    program = tmp_path / "T1.MPF"
    program.write_text("N10 G0 X10 Y5\nN20 G1 X40 F3000\nN30 M30\n", encoding="utf-8")
    trace = tmp_path / "trace.csv"
    code = main(["run", str(program), "--trace", str(trace), "--ephemeral"])
    assert code == 0
    rows = list(csv.reader(trace.open(encoding="utf-8")))
    assert rows[0] == ["t_s", "X", "Y", "Z"]
    times = [float(r[0]) for r in rows[1:]]
    assert times[0] == pytest.approx(0.004)
    assert all(b - a == pytest.approx(0.004) for a, b in zip(times, times[1:]))
    assert float(rows[-1][1]) == pytest.approx(40.0)
    assert float(rows[-1][2]) == pytest.approx(5.0)
    # The motion ramps: the first steps are small (acceleration-limited).
    assert float(rows[2][1]) - float(rows[1][1]) < 1.0
