"""Exercises as data (issue 26): every shipped file loads, its set-up lands in a private
data directory, and the checks pass and fail on scripted kernel sessions.

The sessions drive the kernel with the operator's commands, as the panel's keys do
(the panel itself: ``tests/hmi/test_exercises_panel.py``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from nck import commands as cmd
from nck.exercise import Exercise, ExerciseError, exercise_from_table, load_exercises
from nck.exercise_checks import ExerciseProgress, replay, report_text
from nck.exercise_setup import prepare_data_dir, start_commands
from nck.kernel import Nck
from nck.persistence import Session
from nck.queries import ReadData, answer

EXERCISES = {e.exercise_id: e for e in load_exercises()}


class Scripted:
    """A kernel on an exercise's private data directory, followed by an ExerciseProgress."""

    def __init__(self, exercise: Exercise, directory: Path) -> None:
        prepare_data_dir(exercise, directory)
        self.session = Session.open(directory)
        self.nck = Nck(**self.session.kernel_arguments())
        self.progress = ExerciseProgress(exercise.steps, exercise.final_checks)
        for command in start_commands(exercise):  # the set-up's, not the trainee's: not recorded (as on the panel)
            self.nck.submit(command)
        self.observe()

    def observe(self) -> None:
        self.progress.observe_status(self.nck.status(), answer(self.nck, ReadData()).data)

    def do(self, command: Any) -> Any:
        result = self.nck.submit(command)
        self.progress.observe_command(command, isinstance(result, cmd.Accepted))
        self.observe()
        return result

    def run(self, seconds: float, until: Any = None) -> None:
        """Advance in steps of 0.2 s, observing each (the panel polls 20 times a second)."""
        for _ in range(int(seconds * 5)):
            self.nck.tick(0.2)
            self.observe()
            if until is not None and until(self.nck.status()):
                return

    def reference(self) -> None:
        self.do(cmd.SelectMode("JOG"))
        self.do(cmd.SelectMachineFunction("REF"))
        for axis in ("X", "Y", "Z"):
            self.do(cmd.Jog(axis, 1))
            self.run(60, lambda s, a=axis: next(x for x in s.axes if x.name == a).referenced)
            self.do(cmd.Jog(axis, 0))
        self.do(cmd.SelectMachineFunction(None))

    def run_program(self) -> None:
        self.do(cmd.SelectMode("AUTO"))
        self.do(cmd.CycleStart())
        self.run(300, lambda s: s.channel.channel_state != "active")


def test_every_shipped_exercise_loads_and_ten_are_ready() -> None:
    assert len(EXERCISES) >= 12
    ready = [e for e in EXERCISES.values() if not e.waits_for]
    assert len(ready) >= 13
    assert {e.exercise_id for e in EXERCISES.values() if e.waits_for} == set()
    assert EXERCISES["13_exam_setup"].exam and not any(s.hint for s in EXERCISES["13_exam_setup"].steps)


def test_unknown_check_or_fault_is_refused_with_its_name() -> None:
    with pytest.raises(ExerciseError, match="unknown check 'eval'"):
        exercise_from_table("x", {"title": "t", "step": [{"text": "a", "checks": [{"kind": "eval"}]}]})
    with pytest.raises(ExerciseError, match="unknown fault 'fire'"):
        exercise_from_table("x", {"title": "t", "setup": {"faults": [{"kind": "fire"}]},
                                  "step": [{"text": "a", "checks": [{"kind": "mode", "is": "JOG"}]}]})
    with pytest.raises(ExerciseError, match="at least one"):
        exercise_from_table("x", {"title": "t"})


def broken_setup(**setup: Any) -> Exercise:
    """An exercise whose file loads but whose set-up cannot be written (as an instructor may type it)."""
    return exercise_from_table("99_broken", {"title": "t", "setup": setup,
                                             "step": [{"text": "a", "checks": [{"kind": "mode", "is": "JOG"}]}]})


@pytest.mark.parametrize(("setup", "said"), [
    ({"tools": [{"t": 1, "length1": "long"}]}, "99_broken: setup tools: could not convert string to float: 'long'"),
    ({"tools": [{"length1": 120.0}]}, "99_broken: setup tools: 't' is missing"),
    ({"offsets": [{"X": "minus ten"}]}, "99_broken: setup offsets: could not convert string to float: 'minus ten'"),
    ({"program_texts": {"AB.MPF": "G0 X0\n"},
      "faults": [{"kind": "broken_line", "program": "AB.MPF", "line": 9, "text": "G0 X=="}]},
     "99_broken: setup faults: list assignment index out of range"),
])
def test_a_malformed_set_up_value_is_an_exercise_error_naming_it(tmp_path: Path, setup: dict[str, Any], said: str) -> None:
    with pytest.raises(ExerciseError) as raised:
        prepare_data_dir(broken_setup(**setup), tmp_path / "run")
    assert str(raised.value) == said


def test_an_unknown_machine_is_an_exercise_error(tmp_path: Path) -> None:
    exercise = exercise_from_table("99_broken", {"title": "t", "machine": "nosuch",
                                                 "step": [{"text": "a", "checks": [{"kind": "mode", "is": "JOG"}]}]})
    with pytest.raises(ExerciseError, match="99_broken: machine 'nosuch' not found"):
        prepare_data_dir(exercise, tmp_path / "run")


@pytest.mark.parametrize("exercise_id", sorted(EXERCISES))
def test_set_up_lands_in_a_private_directory(tmp_path: Path, exercise_id: str) -> None:
    exercise = EXERCISES[exercise_id]
    prepare_data_dir(exercise, tmp_path / "run")
    session = Session.open(tmp_path / "run")
    for name in exercise.setup.get("programs", []):
        assert session.files.exists(f"MPF/{name}")
    assert session.ncdata.machine_setup.hidden == bool(exercise.setup.get("blank_hidden", False))


def test_faults_are_in_the_retained_data(tmp_path: Path) -> None:
    prepare_data_dir(EXERCISES["10_wrong_offset"], tmp_path / "a")
    assert Session.open(tmp_path / "a").ncdata.settable_frames["G54"].trans == {"X": -45.0, "Y": -40.0, "Z": -220.0}
    prepare_data_dir(EXERCISES["11_worn_tool"], tmp_path / "b")
    assert Session.open(tmp_path / "b").ncdata.tools[(1, 1)].params[12] == 0.4
    prepare_data_dir(EXERCISES["12_missing_tool"], tmp_path / "c")
    assert not any(t == 2 for t, _ in Session.open(tmp_path / "c").ncdata.tools)
    prepare_data_dir(EXERCISES["05_broken_line"], tmp_path / "d")
    assert "N80 Y==30" in Session.open(tmp_path / "d").files.read("MPF/FIRST_STEPS.MPF").splitlines()
    blank = EXERCISES["08_measure_workpiece"]
    prepare_data_dir(blank, tmp_path / "e")
    setup = Session.open(tmp_path / "e").ncdata.machine_setup
    assert setup.hidden and setup.blank.low_mcs == (-63.0, -27.5, -248.0)


def test_referencing_passes_and_an_unreferenced_axis_fails(tmp_path: Path) -> None:
    exercise = EXERCISES["01_power_on_reference"]
    s = Scripted(exercise, tmp_path / "run")
    s.do(cmd.SelectMode("JOG"))
    assert s.progress.current == 1
    s.do(cmd.SelectMachineFunction("REF"))
    s.do(cmd.Jog("X", 1))
    s.run(60, lambda st: st.axes[0].referenced)
    report = s.progress.report(exercise.title)
    assert report["steps"][0]["done"] and not report["steps"][1]["done"]
    assert report["steps"][1]["why_not"] == ["axes not referenced: Y, Z"]
    assert report["score"] == 67  # 2 of 3: step 1 and the final check (no alarm)
    s.reference()
    report = s.progress.report(exercise.title)
    assert s.progress.finished and report["score"] == 100
    assert "[x] 2. Reference every axis" in report_text(report)


def test_emergency_stop_must_be_cleared_with_reset(tmp_path: Path) -> None:
    exercise = EXERCISES["02_emergency_stop"]
    s = Scripted(exercise, tmp_path / "run")
    assert s.nck.status().emergency_stop
    s.do(cmd.EmergencyStop(False))
    assert s.progress.current == 1
    s.do(cmd.Reset())
    assert s.progress.current == 2
    assert s.progress.report()["steps"][1]["done"]


def test_alarm_cleared_with_the_wrong_key_does_not_count(tmp_path: Path) -> None:
    # alarm 10860 (no feedrate) is cleared by RESET; CANCEL leaves it standing, and
    # an alarm gone by a program's NC START would name CycleStart
    exercise = EXERCISES["04_fix_from_alarm"]
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    s.run_program()
    assert 10860 in [a.number for a in s.nck.status().alarms]
    assert s.progress.current == 2
    s.do(cmd.CancelAlarms())
    assert s.progress.current == 2
    report = s.progress.report()
    assert report["steps"][2]["why_not"] == ["alarm 10860 was not cleared"]
    s.do(cmd.Reset())
    assert s.progress.current == 3
    # the program is not fixed yet: it stops again, step 4 stays open
    s.run_program()
    assert not s.progress.finished
    assert s.progress.report()["steps"][3]["why_not"] == ["ALARM_DEMO has not run to its end without alarm"]
    text = s.session.files.read("MPF/ALARM_DEMO.MPF").replace("N30 G1 Z-1", "N30 G1 Z-1 F200")
    s.session.files.save("MPF/ALARM_DEMO.MPF", text)
    s.do(cmd.Reset())
    s.run_program()
    assert s.progress.finished


def test_single_block_run_counts_its_stops(tmp_path: Path) -> None:
    exercise = EXERCISES["03_single_block_flange"]
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    s.do(cmd.SelectProgram("DRILL_FLANGE.MPF"))
    s.do(cmd.SelectMode("AUTO"))
    assert s.progress.current == 2  # step 3 waits for single block
    s.do(cmd.SetProgramControl("single_block", "SBL1"))
    assert s.progress.current == 3
    s.do(cmd.CycleStart())
    for _ in range(400):
        s.run(30, lambda st: st.channel.channel_state != "active")
        if s.nck.status().channel.channel_state == "reset":
            break
        s.do(cmd.CycleStart())
    assert s.progress.finished
    ends = [e for e in s.progress.events if e["kind"] == "program_ended"]
    assert ends[-1]["single_block_stops"] >= 10


def test_a_run_without_single_block_does_not_count() -> None:
    step = EXERCISES["03_single_block_flange"].steps[3]
    progress = ExerciseProgress([step])
    progress.replay_event({"kind": "state", "t_s": 0.0, "state": {}})
    progress.replay_event({"kind": "program_ended", "t_s": 9.0, "program": "DRILL_FLANGE.MPF",
                           "alarms": [], "single_block_stops": 0})
    assert not progress.finished
    assert progress.report()["steps"][0]["why_not"] == [
        "DRILL_FLANGE has not run to its end without alarm with at least 10 single-block stops"]
    progress.replay_event({"kind": "program_ended", "t_s": 30.0, "program": "DRILL_FLANGE.MPF",
                           "alarms": [], "single_block_stops": 24})
    assert progress.finished


def test_a_corrected_work_offset_passes(tmp_path: Path) -> None:
    exercise = EXERCISES["10_wrong_offset"]
    s = Scripted(exercise, tmp_path / "run")
    report = s.progress.report()
    # The reason gives the value entered, not how far off it is (that would give the answer).
    assert report["steps"][0]["why_not"] == ["G54 X is -45.000 mm: not within 0.001 mm of where it belongs"]
    s.do(cmd.WriteData("$P_UIFR[1,X,TR]", -50.0))
    assert s.progress.finished


def test_recording_replays_to_the_same_report(tmp_path: Path) -> None:
    exercise = EXERCISES["02_emergency_stop"]
    s = Scripted(exercise, tmp_path / "run")
    s.progress.observe_key("alt+l")
    s.do(cmd.EmergencyStop(False))
    s.do(cmd.Reset())
    s.reference()
    again = replay(exercise.steps, exercise.final_checks, s.progress.events)
    assert again.report(exercise.title) == s.progress.report(exercise.title)
    assert again.report()["keys"] == 1 and again.finished


def test_the_report_time_runs_to_the_end_of_the_session(tmp_path: Path) -> None:
    # Referenced, then 40 s of control time with nothing to do: an idle machine's snapshot does
    # not change (tests/kernel/test_snapshot_once.py), yet the session lasted until it ended.
    # The end is recorded, so the replay says the same time.
    exercise = EXERCISES["01_power_on_reference"]
    s = Scripted(exercise, tmp_path / "run")
    started_s = s.nck.status().time_s
    s.reference()
    s.run(40)
    end_s = s.nck.status().time_s
    s.progress.observe_end(end_s)
    report = s.progress.report(exercise.title)
    assert report["time_s"] == round(end_s - started_s, 1)
    assert replay(exercise.steps, exercise.final_checks, s.progress.events).report(exercise.title) == report


def finish_run(s: Scripted, starts: int = 5) -> None:
    """NC START until the channel is in reset (action blocks, REPOS, stops)."""
    for _ in range(starts):
        s.run(300, lambda st: st.channel.channel_state != "active")
        if s.nck.status().channel.channel_state == "reset":
            return
        s.do(cmd.CycleStart())


def test_block_search_to_n80_then_the_rest(tmp_path: Path) -> None:
    exercise = EXERCISES["07_block_search"]
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    s.do(cmd.SelectMode("AUTO"))
    s.do(cmd.StartBlockSearch("N70"))  # the wrong block: the step asks for N80
    assert s.progress.current == 1
    s.do(cmd.Reset())
    s.do(cmd.StartBlockSearch("N80"))
    assert s.progress.current == 2
    s.run(30, lambda st: st.channel.stop_reason == "search target found")
    s.do(cmd.CycleStart())
    finish_run(s)
    assert s.progress.finished, s.progress.report()


def test_repos_after_nc_stop(tmp_path: Path) -> None:
    exercise = EXERCISES["06_repos"]
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    s.do(cmd.SelectMode("AUTO"))
    s.do(cmd.CycleStart())
    s.run(3)
    s.do(cmd.CycleStop())
    assert s.progress.current == 2
    s.do(cmd.SelectMode("JOG"))
    s.do(cmd.Jog("Z", 1))
    s.run(1)
    s.do(cmd.Jog("Z", 0))
    assert s.progress.current == 3
    s.run(2)  # the axis brakes; the mode changes once it stands
    s.do(cmd.SelectMode("AUTO"))
    s.do(cmd.CycleStart())
    finish_run(s)
    assert s.progress.finished, s.progress.report()


def test_missing_tool_created_then_the_program_runs(tmp_path: Path) -> None:
    exercise = EXERCISES["12_missing_tool"]
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    s.run_program()
    assert s.progress.current == 1
    for name, value in (("$TC_DP1[2,1]", 200), ("$TC_DP3[2,1]", 90.0), ("$TC_DP6[2,1]", 4.0)):
        assert isinstance(s.do(cmd.WriteData(name, value)), cmd.Accepted)
    s.do(cmd.Reset())
    s.run_program()
    assert s.progress.finished, s.progress.report()
