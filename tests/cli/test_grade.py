"""``nck grade STUDENT --reference REF`` (issue 26): pairs of programs with deviations known by hand.

The expected deviations are plain geometry of the programmed contours (distance of a
point to a line, of two concentric circles), computed here by hand, not recorded from
the kernel. Both programs run on a fresh data directory, whose sample tool T1 is an
end mill of length 75 mm (data/sample_tools.toml): MCS Z = programmed Z + 75.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from nck.cli import main
from nck.grade import Polyline, path_deviation

SQUARE = """N10 G90 G54 G17 G0 X0 Y0 Z5
N20 T1 D1 M6
N30 G1 Z-1 F500
N40 G1 X50 F1000
N50 Y50
N60 X0
N70 Y0
N80 G0 Z5
N90 M30
"""


def grade(tmp_path: Path, capsys: pytest.CaptureFixture[str], student: str, reference: str,
          *options: str) -> tuple[int, dict, str]:
    """Run ``nck grade --json`` on the two texts; return exit code, report and stderr."""
    (tmp_path / "STUDENT.MPF").write_text(student)
    (tmp_path / "REF.MPF").write_text(reference)
    code = main(["grade", str(tmp_path / "STUDENT.MPF"), "--reference", str(tmp_path / "REF.MPF"),
                 "--data-dir", str(tmp_path / "data"), "--json", *options])
    captured = capsys.readouterr()
    return code, json.loads(captured.out) if captured.out else {}, captured.err


def test_same_program_scores_full_marks(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, report, _ = grade(tmp_path, capsys, SQUARE, SQUARE)
    assert code == 0
    assert report["score"] == 100 and report["same"] is True
    assert report["checks"]["path"]["max_deviation_mm"] == 0.0
    assert report["checks"]["tools"]["student"] == [1]


def test_shifted_corner_is_found_in_its_block(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # The corner of N50 is programmed at X50.3 instead of X50: the farthest point of the
    # trainee's path is that corner, 0.3 mm from the reference corner (50, 50); every
    # point of the reference lies nearer to the trainee's path than that.
    student = SQUARE.replace("N50 Y50", "N50 X50.3 Y50")
    code, report, _ = grade(tmp_path, capsys, student, SQUARE)
    assert code == 1
    path = report["checks"]["path"]
    assert path["max_deviation_mm"] == pytest.approx(0.3, abs=1e-4)
    assert path["student_block"] == "N50" and path["reference_block"] == "N50"
    assert path["at_mcs"] == {"X": 50.3, "Y": 50.0, "Z": 74.0}
    # path points: 35 x (1 - (0.3 - 0.01) / (1 - 0.01)) = 24.747; the rest is the same
    assert path["points"] == pytest.approx(24.75, abs=0.01)
    assert report["score"] == 90
    assert all(report["checks"][name]["same"] for name in ("alarms", "position", "tools", "time"))


def test_concentric_circles_differ_by_their_radii(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # Full circles about X0 Y0, radius 20 (reference) and 20.5 (trainee): 0.5 mm apart everywhere.
    circle = "N10 G90 G17 G0 X0 Y0 Z5\nN20 T1 D1 M6\nN30 G0 X-{r}\nN40 G1 Z-1 F500\nN50 G2 X-{r} Y0 I{r} J0 F800\nN60 G0 Z5\nN70 M30\n"
    code, report, _ = grade(tmp_path, capsys, circle.format(r="20.5"), circle.format(r="20"))
    assert code == 1
    assert report["checks"]["path"]["max_deviation_mm"] == pytest.approx(0.5, abs=1e-3)
    assert report["checks"]["position"]["same"] is False
    assert report["checks"]["position"]["student"]["X"] == pytest.approx(-20.5)


def test_a_left_out_move_counts_from_the_reference_side(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # The trainee leaves out N70 (X0 Y50 -> X0 Y0). The middle of that side, X0 Y25, is 25 mm
    # from the trainee's nearest moves (N40 along Y0 and N60 along Y50).
    student = SQUARE.replace("N70 Y0\n", "")
    code, report, err = grade(tmp_path, capsys, student, SQUARE)
    assert code == 1, err
    path = report["checks"]["path"]
    assert path["max_deviation_mm"] == pytest.approx(25.0, abs=1e-3)
    assert path["reference_block"] == "N70"
    assert path["points"] == 0.0
    assert "from the student's path" in path["details"][0]


def test_alarms_tools_and_time_are_compared(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # T2 instead of T1, and a syntax error in N75: alarm 12080 (000 L1702)
    student = SQUARE.replace("N20 T1 D1", "N20 T2 D1").replace("N80", "N75 X==\nN80")
    code, report, _ = grade(tmp_path, capsys, student, SQUARE)
    assert code == 1
    assert report["checks"]["alarms"]["student"] == [{"number": 12080, "block": "N75"}]
    assert report["checks"]["alarms"]["points"] == 0.0
    assert report["checks"]["tools"]["student"] == [2] and report["checks"]["tools"]["reference"] == [1]
    assert report["checks"]["tools"]["details"] == ["- reference: T1", "+ student:   T2"]


def test_an_alarm_in_a_cycle_names_the_cycle(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # The student drills without a feed: CYCLE82 stops at its line 8, the feed move to depth
    # (10860, data/cycles/CYCLE82.SPF); the block is the cycle's, so the cycle is named.
    reference = SQUARE.replace("N80 G0 Z5", "N80 G0 Z5\nN85 CYCLE82(5,0,2,-3,0,0)")
    student = reference.replace("N30 G1 Z-1 F500", "N30 G0 Z-1").replace("N40 G1 X50 F1000", "N40 G0 X50") \
        .replace("N50 Y50", "N50 G0 Y50")
    _, report, _ = grade(tmp_path, capsys, student, reference)
    assert report["checks"]["alarms"]["student"] == [{"number": 10860, "block": "CYCLE82.SPF line 8"}]


def test_a_dwell_shows_in_the_machining_time(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # G4 F2: a dwell of 2 s (002 L1253 programs it so; F under G4 is the dwell in seconds); path unchanged
    student = SQUARE.replace("N80", "N75 G4 F2\nN80")
    code, report, _ = grade(tmp_path, capsys, student, SQUARE)
    time = report["checks"]["time"]
    assert time["student_s"] - time["reference_s"] == pytest.approx(2.0, abs=0.05)
    assert report["checks"]["path"]["same"] is True
    assert code == (0 if time["same"] else 1)


def test_readable_report(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "S.MPF").write_text(SQUARE.replace("N50 Y50", "N50 X50.3 Y50"))
    (tmp_path / "R.MPF").write_text(SQUARE)
    assert main(["grade", str(tmp_path / "S.MPF"), "--reference", str(tmp_path / "R.MPF"),
                 "--data-dir", str(tmp_path / "data")]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "S.MPF against R.MPF: score 90/100"
    assert lines[2].startswith("≠ path            largest deviation 0.300 mm")
    assert lines[3].strip().startswith("student N50 passes MCS X50.300 Y50.000 Z74.000, 0.300 mm")


@pytest.mark.parametrize("which", ["student", "reference"])
def test_an_endless_loop_is_reported_not_graded(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                which: str) -> None:
    loop = "N10 G0 X0\nN20 LOOP\nN30 G1 X10 F1000\nN40 X0\nN50 ENDLOOP\nN60 M30\n"
    pair = (loop, SQUARE) if which == "student" else (SQUARE, loop)
    code, report, err = grade(tmp_path, capsys, *pair, "--timeout", "30")
    assert code == 3 and report == {}
    name = "STUDENT.MPF" if which == "student" else "REF.MPF"
    assert f"nck grade: {name} did not end within 30 s of simulated time" in err
    assert "Traceback" not in err


def test_bad_input_gives_a_message_and_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "R.MPF").write_text(SQUARE)
    assert main(["grade", str(tmp_path / "NONE.MPF"), "--reference", str(tmp_path / "R.MPF")]) == 2
    assert "program file" in capsys.readouterr().err
    assert main(["grade", str(tmp_path), "--reference", str(tmp_path / "R.MPF")]) == 2
    assert "is a folder, not a program file" in capsys.readouterr().err
    assert main(["grade", str(tmp_path / "R.MPF")]) == 2  # --reference missing
    assert "--reference" in capsys.readouterr().err
    assert main(["grade", str(tmp_path / "R.MPF"), "--reference", str(tmp_path / "R.MPF"), "--timeout", "0"]) == 2
    assert "--timeout" in capsys.readouterr().err


def polyline(*points: tuple[float, float], label: str = "N1") -> Polyline:
    return Polyline(np.array([[x, y, 0.0] for x, y in points]), tuple(label for _ in points[1:]))


def test_path_deviation_of_polylines_by_hand() -> None:
    # parallel lines 1 mm apart
    assert path_deviation(polyline((0, 0), (10, 0)), polyline((0, 1), (10, 1))).distance_mm == pytest.approx(1.0)
    # a peak of 3 mm in the reference: the student's line misses it by 3 mm (the peak),
    # while the student's farthest point, (5, 0), is 15 / sqrt(34) = 2.572 mm from the flanks
    found = path_deviation(polyline((0, 0), (10, 0), label="N10"),
                           polyline((0, 0), (5, 3), (10, 0), label="N20"))
    assert found.distance_mm == pytest.approx(3.0)
    assert found.missing_in == "student" and found.reference_block == "N20"
    assert path_deviation(polyline((0, 0), (5, 3), (10, 0)), polyline((0, 0), (10, 0))).distance_mm \
        == pytest.approx(3.0)
