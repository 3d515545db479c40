"""Where ``nck run`` says the machine is after a run that stopped early.

002 L2397-2416: a part-program block whose motion would overrun the software
limit switch is not started (alarm 10720): the axes stay where the block
before it ended. ``--json`` "position" and the last ``--segments`` line report
that point, not the programmed target of the refused block or of blocks the
interpreter had already prepared behind it.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nck.cli import main

REFUSED = """N10 G90 G0 X10 Y10 Z0
N20 TRANS X5
N30 G1 F1000 X20
N40 X99999
N50 X30 Y40
N60 M30
"""


def _run(tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, *extra: str) -> tuple[int, dict, list[dict]]:
    prog = tmp_path / "STOP.MPF"
    prog.write_text(text)
    segments = tmp_path / "seg.jsonl"
    code = main(["run", str(prog), "--ephemeral", "--json", "--segments", str(segments), *extra])
    state = json.loads(capsys.readouterr().out)
    return code, state, [json.loads(line) for line in segments.read_text().splitlines()]


def test_refused_block_leaves_the_axes_at_the_previous_end_point(tmp_path: Path, capsys) -> None:
    code, state, segments = _run(tmp_path, capsys, REFUSED)
    assert code == 1
    assert [a["number"] for a in state["alarms"]] == [10720]
    # N30 ends at WCS X20 = MCS X25 (TRANS X5); N40 is not started (002 L2397-2416), N50 never runs.
    assert state["position"]["mcs"] == {"X": 25.0, "Y": 10.0, "Z": 0.0}
    assert state["position"]["wcs"] == {"X": 20.0, "Y": 10.0, "Z": 0.0}
    assert [s["n"] for s in segments] == [10, 30]
    assert segments[-1]["end"] == state["position"]["wcs"]
    assert segments[-1]["end_mcs"] == state["position"]["mcs"]


def test_timeout_reports_the_point_reached_inside_the_block(tmp_path: Path, capsys) -> None:
    # 100 mm at F600 takes 10 s; after 2 s of simulated time the axis is short of 20 mm.
    code, state, segments = _run(tmp_path, capsys, "N10 G90 G1 F600 X100\nN20 X0\nM30\n", "--timeout", "2")
    assert code == 3
    x = state["position"]["mcs"]["X"]
    assert 15.0 < x <= 20.0
    assert [s["n"] for s in segments] == [10]
    assert segments[-1]["end_mcs"]["X"] == x


def test_timeout_inside_a_dwell_reports_nothing_after_it(tmp_path: Path, capsys) -> None:
    # N20 dwells 35 s (G4 F in seconds, 001 L6410-6415); stopped 20 s into the run, N30 never started.
    code, state, segments = _run(tmp_path, capsys, "N10 G90 G0 X10\nN20 G4 F35\nN30 G1 F600 X20\nM30\n",
                                 "--timeout", "20")
    assert code == 3
    assert [s["n"] for s in segments] == [10]
    assert state["position"]["mcs"]["X"] == 10.0


def test_ended_run_reports_every_segment_and_the_programmed_end(tmp_path: Path, capsys) -> None:
    code, state, segments = _run(tmp_path, capsys, "N10 G90 G0 X10\nN20 TRANS Y2\nN30 G1 F2000 Y5\nM30\n")
    assert code == 0
    assert [s["n"] for s in segments] == [10, 30]
    assert state["position"]["mcs"] == {"X": 10.0, "Y": 7.0, "Z": 0.0}
