"""``nck exercise list`` / ``nck exercise replay SESSION.json``: the instructor's replay (issue 26)."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as cmd
from nck.cli import main
from nck.exercise_files import save_report
from tests.exercises.test_exercise_checks import EXERCISES, Scripted


def test_list_names_every_exercise_and_none_waits(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["exercise", "list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == len(EXERCISES)
    assert any(line.startswith("14_spindle_speed") for line in lines)
    assert not any("(waits for" in line for line in lines)


def test_replay_of_a_saved_session(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    exercise = EXERCISES["02_emergency_stop"]
    s = Scripted(exercise, tmp_path / "run")
    s.progress.observe_key("alt+l")
    s.do(cmd.EmergencyStop(False))
    s.progress.observe_key("f12")
    s.do(cmd.CancelAlarms())
    s.progress.observe_key("alt+q")
    s.do(cmd.Reset())
    s.progress.observe_end(s.nck.status().time_s)
    _, recording = save_report(tmp_path / "reports", "session", s.progress.report(exercise.title),
                               s.progress.events, exercise.exercise_id)
    assert main(["exercise", "replay", str(recording)]) == 0
    out = capsys.readouterr().out
    timeline = [line.split(" s  ", 1)[1] for line in out.split("\n\n")[0].splitlines()]
    assert timeline == ["alarm 3000 came", "key alt+l", "EmergencyStop pressed=False", "=== step 1 done",
                        "key f12", "CancelAlarms", "key alt+q", "Reset", "alarm 3000 went (Reset)",
                        "=== step 2 done", "=== session ended"]
    assert "Score: 67/100" in out and "[ ] 3. Reference the axes in JOG." in out


def test_replay_of_a_bad_file_says_so(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "x.json").write_text("[1, 2]")
    assert main(["exercise", "replay", str(tmp_path / "x.json")]) == 2
    assert "is not a recorded exercise session" in capsys.readouterr().err
    assert main(["exercise", "replay", str(tmp_path / "none.json")]) == 2
    assert "cannot replay" in capsys.readouterr().err


def test_reports_of_the_same_name_do_not_overwrite_each_other(tmp_path: Path) -> None:
    report = {"title": "t", "score": 1, "time_s": 0.0, "keys": 0, "steps": [], "final_checks": []}
    first = save_report(tmp_path, "01-20261127-101500", report, [], "01")
    second = save_report(tmp_path, "01-20261127-101500", {**report, "score": 2}, [], "01")
    assert first[0].name == "01-20261127-101500.txt" and second == (
        tmp_path / "01-20261127-101500-2.txt", tmp_path / "01-20261127-101500-2.json")
    assert '"score": 1' in first[1].read_text() and '"score": 2' in second[1].read_text()
