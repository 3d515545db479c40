"""`nck run --json` / `--segments` with frames, tool length and spindle (cli.md example numbers)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nck.cli import main

PROGRAM = """N10 G54 G17 T1 M6 D1
N20 S2000 M3
N30 G0 X10 Y5 Z-1
N40 G1 X12 F200
N50 M0
"""


def test_json_final_state_and_segments(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = tmp_path / "PART1.MPF"
    program.write_text(PROGRAM)
    segments = tmp_path / "seg.jsonl"
    code = main([
        "run", str(program), "--json", "--ephemeral", "--data-dir", str(tmp_path / "data"),
        "--segments", str(segments),
        "--set", "$TC_DP1[1,1]=120", "--set", "$TC_DP3[1,1]=100",
        "--set", "$P_UIFR[1,X,TR]=100", "--set", "$P_UIFR[1,Y,TR]=50", "--password", "CUSTOMER",
    ])
    out = capsys.readouterr().out
    assert code == 0
    state = json.loads(out.strip().splitlines()[-1])
    # G54 (100,50,0) + tool length 100 on Z: WCS (12,5,-1) is machine (112,55,99).
    assert state["position"]["mcs"] == pytest.approx({"X": 112.0, "Y": 55.0, "Z": 99.0})
    # The program end keeps group 8 on the shipped mill (MD20152[7] = 1; the cli.md example shows
    # "8": "G54" after the run): the WCS still reads through G54 (12, 5, -1).
    assert state["gcodes"]["8"] == "G54"
    assert state["position"]["wcs"] == pytest.approx({"X": 12.0, "Y": 5.0, "Z": -1.0})
    assert state["tool"] == {"T": 1, "D": 1}
    # The program runs out without M2/M30: no program end in the sense of MD35040 (002
    # L51017-51035), so the spindle keeps S and direction (nck.canon.SPINDLE_RESET_ENDS).
    assert state["spindle"]["state"] == "M3" and state["spindle"]["S"] == pytest.approx(2000.0)
    assert state["gcodes"]["6"] == "G17"
    lines = [json.loads(line) for line in segments.read_text().splitlines()]
    first = lines[0]
    assert first["n"] == 30 and first["motion"] == "G0"
    assert first["end"] == {"X": 10.0, "Y": 5.0, "Z": -1.0}
    assert first["end_mcs"] == {"X": 110.0, "Y": 55.0, "Z": 99.0}
