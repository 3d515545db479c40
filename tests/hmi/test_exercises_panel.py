"""Guided exercises on the panel (issue 26): Diagnostics, More, Exercises.

The trainee's own data directory stays as it was; the exercise runs on a private
one; the side window shows the step and its hint; the end writes the scored report
(text and JSON with the recording, which replays to the same report). Keys are
sent one at a time and in bursts, as a terminal delivers them.
"""

from __future__ import annotations

import hashlib
import json
import os
import shlex
from pathlib import Path

import pytest
from textual.widgets import Static

from hmi.app import HmiApp, make_app
from hmi.exercise_run import reports_dir_of
from hmi.serve import panel_command
from nck import commands as cmd
from nck.class_pack import export_pack
from nck.exercise import exercise_from_table, load_exercises
from nck.exercise_checks import replay
from nck.paths import default_data_dir
from tests.burst import burst
from tests.exercises.test_class_pack import EXERCISE as PACKED_EXERCISE, SQUARE
from tests.hmi.conftest import SIZE

REFERENCE_KEYS = ("alt+m", "alt+j", "alt+r", "alt+x", "ctrl+right", "alt+y", "ctrl+right", "alt+z", "ctrl+right")
OPEN_LIST = ("alt+a", "f8", "f4")  # Diagnostics, More, Exercises
START, END, NEXT, PREVIOUS, IMPORT = "shift+f1", "shift+f2", "shift+f3", "shift+f4", "shift+f5"


def fingerprint(directory: Path) -> dict[str, str]:
    """Every file below ``directory`` (but the report folder and the lock) with its content hash."""
    return {str(p.relative_to(directory)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(directory.rglob("*")) if p.is_file()
            and "exercise_reports" not in p.parts and p.name != ".lock"}


def trainee_app(tmp_path: Path) -> HmiApp:
    app = make_app(data_dir=str(tmp_path / "trainee"), realtime=False)
    app.nc_session.save()
    return app


def referenced(status) -> bool:
    return all(a.referenced for a in status.axes if a.kind != "spindle")


def side(app: HmiApp) -> str:
    return str(app.screen.query_one("#exercise-side", Static).render())


async def test_reference_exercise_with_keys_report_and_own_data_untouched(tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    before = fingerprint(tmp_path / "trainee")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press(*OPEN_LIST)
        assert "Power on: reference the axes" in str(app.screen.query_one("#diag-exercises", Static).render())
        await pilot.press(START)
        assert app.hint == "Exercise started: Power on: reference the axes"
        assert "Step 2 of 2" in side(app) and "Hint: REF POINT" in side(app)
        private = app.nc_session.session.data_dir
        assert private != tmp_path / "trainee" and private.is_dir()
        for key in REFERENCE_KEYS:  # one key at a time
            await pilot.press(key)
        app.bridge.run_until(referenced, max_s=60)
        await pilot.pause()
        assert "All steps done." in side(app)
        # shown beside the Machine area too, which was built before the exercise started
        assert app.screen.AREA_ID == "machine" and app.screen.query_one("#exercise-side").region.width == 34
        await pilot.press("alt+a", END)
        assert app.hint.startswith("Exercise ended, score 100/100: report in ")
        assert not private.exists()  # the private data directory is gone
        assert not referenced(app.bridge.status)  # the trainee's own kernel is back as it was
        assert not app.has_class("-exercise")
    assert fingerprint(tmp_path / "trainee") == before
    reports = tmp_path / "trainee" / "exercise_reports"
    text = next(reports.glob("*.txt")).read_text()
    assert "Score: 100/100" in text and "[x] 2. Reference every axis with REF POINT." in text
    saved = json.loads(next(reports.glob("*.json")).read_text())
    assert saved["exercise"] == "01_power_on_reference" and saved["report"]["score"] == 100
    keys = [e["key"] for e in saved["events"] if e["kind"] == "key"]
    assert keys == [*REFERENCE_KEYS, "alt+a", END]  # from the start to the end of the exercise
    exercise = {e.exercise_id: e for e in load_exercises()}["01_power_on_reference"]
    assert replay(exercise.steps, exercise.final_checks, saved["events"]).report(exercise.title) == saved["report"]


async def test_ended_early_the_report_says_what_is_missing(tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST, START)
        assert "Step 2 of 2" in side(app)
        await burst(pilot, "alt+m", "alt+j", "alt+r", "alt+x", "ctrl+right")  # X only, in one burst
        app.bridge.run_until(lambda s: s.axes[0].referenced, max_s=60)
        await pilot.pause()
        assert "- axes not referenced: Y, Z" in side(app)
        await burst(pilot, "alt+a", END)
        assert app.hint.startswith("Exercise ended, score 67/100")
    text = next((tmp_path / "trainee" / "exercise_reports").glob("*.txt")).read_text()
    assert "[ ] 2. Reference every axis with REF POINT.\n      not done: axes not referenced: Y, Z" in text


async def test_the_report_time_runs_to_the_end_even_after_idle_minutes(tmp_path: Path) -> None:
    # The panel follows the exercise on the snapshots that changed; an idle machine's does not
    # (tests/kernel/test_snapshot_once.py). The terminal is lost after two idle minutes, no key
    # pressed: the report still times the session to its end, and the saved recording replays
    # to the same report.
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST, START)
        started_s = app.bridge.status.time_s
        await burst(pilot, *REFERENCE_KEYS)
        app.bridge.run_until(referenced, max_s=60)
        await pilot.pause()
        referenced_s = app.bridge.status.time_s
        for _ in range(120):  # two minutes with nothing to do, at the panel's refresh period
            app.bridge.advance(1.0)
        await pilot.pause()
        end_s = app.bridge.status.time_s
        assert end_s - referenced_s >= 119.0
        app.quit_unattended(129)
        await pilot.pause()
    saved = json.loads(next((tmp_path / "trainee" / "exercise_reports").glob("*.json")).read_text())
    assert saved["report"]["time_s"] == round(end_s - started_s, 1)
    exercise = {e.exercise_id: e for e in load_exercises()}["01_power_on_reference"]
    assert replay(exercise.steps, exercise.final_checks, saved["events"]).report(exercise.title) == saved["report"]


@pytest.mark.parametrize("in_a_burst", [False, True], ids=["one-at-a-time", "burst"])
async def test_the_arrow_keys_select_in_the_exercise_list(tmp_path: Path, in_a_burst: bool) -> None:
    """▼ and ▲ move the selection as Next ▼ and Previous ▲ do (a trainee who pressed Down seven
    times started the first exercise: the arrows did nothing in this list)."""
    app = trainee_app(tmp_path)
    keys = (*OPEN_LIST, *["down"] * 8, "up", START)  # the eighth exercise
    async with app.run_test(size=SIZE) as pilot:
        if in_a_burst:
            await burst(pilot, *keys)
        else:
            await pilot.press(*keys)
        assert app.hint == "Exercise started: Set up a job: find the blank by measuring"
        await pilot.press("alt+a", END)


async def test_emergency_stop_cleared_with_the_wrong_key_then_the_right_one(tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST, NEXT, START)  # the second exercise
        assert app.bridge.status.emergency_stop
        assert "Step 1 of 3" in side(app)
        await burst(pilot, "alt+l")  # release the button
        assert "Step 2 of 3" in side(app)
        await burst(pilot, "f12")  # CANCEL does not clear alarm 3000
        assert "Step 2 of 3" in side(app) and "alarm 3000 was not cleared" in side(app)
        await burst(pilot, "alt+q")  # RESET does
        assert "Step 3 of 3" in side(app)
        await burst(pilot, *REFERENCE_KEYS)
        app.bridge.run_until(referenced, max_s=60)
        await pilot.pause()
        assert "All steps done." in side(app)
        await burst(pilot, "alt+a", END)
        assert "score 100/100" in app.hint
        assert not app.bridge.status.emergency_stop  # the trainee's machine never was in E-stop


async def test_exam_shows_no_hint_and_the_spindle_exercise_starts(tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press(*OPEN_LIST, *[NEXT] * 13, START)  # 14: the spindle drive fault
        assert app.hint == "Exercise started: The spindle does not reach its speed"
        assert "Step 1 of 3" in side(app) and "Hint" in side(app)
        await pilot.press(END)
        await pilot.press(*OPEN_LIST, PREVIOUS, START)  # 13: the exam (the list kept its place)
        assert "Step 1 of 3" in side(app) and "Hint" not in side(app)
        await pilot.press(END)
        assert "score 25/100" in app.hint  # 1 of 4: only the final check (no alarm) holds


def test_a_broken_exercise_is_said_and_a_bug_is_not_hidden(tmp_path: Path, monkeypatch) -> None:
    app = trainee_app(tmp_path)
    broken = exercise_from_table("99_broken", {"title": "Broken", "setup": {"tools": [{"t": 1, "length1": "long"}]},
                                               "step": [{"text": "a", "checks": [{"kind": "mode", "is": "JOG"}]}]})
    said = app.start_exercise(broken)
    assert said == "Exercise could not be started: 99_broken: setup tools: could not convert string to float: 'long'"
    assert app.exercise_run is None
    exercise = {e.exercise_id: e for e in load_exercises()}["01_power_on_reference"]

    def failing(*args, **kwargs):
        raise ZeroDivisionError("a bug, not a broken exercise file")
    monkeypatch.setattr("hmi.exercise_run.start_session", failing)
    with pytest.raises(ZeroDivisionError):  # a bug is not a message on the dialog line
        app.start_exercise(exercise)
    assert app.exercise_run is None


async def test_class_pack_imported_on_the_panel(tmp_path: Path) -> None:
    folder = tmp_path / "course"
    (folder / "programs").mkdir(parents=True)
    (folder / "20_square.toml").write_text(PACKED_EXERCISE)
    (folder / "programs" / "SQUARE.MPF").write_text(SQUARE)
    pack = tmp_path / "c.pack"
    export_pack(pack, [folder / "20_square.toml"])
    broken = tmp_path / "b.pack"
    broken.write_bytes(pack.read_bytes()[:100])
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST, IMPORT)
        assert app.hint == "Import class pack: needs access level 2"
        app.submit(cmd.EnterPassword("EVENING"))  # the instructor's service password
        await pilot.pause()
        await burst(pilot, IMPORT, *str(broken), "enter")  # typing replaces the proposed folder
        assert app.hint.startswith(f"Class pack not imported: {broken}: not a readable class pack (truncated")
        await burst(pilot, IMPORT, *str(pack), "enter")
        assert app.hint == "Class pack imported: 1 exercise, 1 program (2 files new or changed)"
        listed = str(app.screen.query_one("#diag-exercises", Static).render())
        assert "15  Run the instructor's square" in listed
        await burst(pilot, IMPORT, *str(pack), "enter")  # again: nothing changes
        assert app.hint == "Class pack imported: 1 exercise, 1 program (0 files new or changed)"
        await burst(pilot, *[NEXT] * 14, START)  # the imported exercise on its set-up
        assert app.hint == "Exercise started: Run the instructor's square"
        assert "Step 1 of 1" in side(app) and "SQUARE" in app.bridge.status.channel.selected_program
        assert app.nc_session.session.files.read("MPF/SQUARE.MPF") == SQUARE
        await burst(pilot, END)
    assert (tmp_path / "trainee" / "exercises" / "programs" / "SQUARE.MPF").read_text() == SQUARE


async def test_reports_of_a_panel_on_a_private_copy_outlive_the_copy(tmp_path: Path) -> None:
    """A browser tab's panel runs on a temporary copy (--ephemeral, hmi --serve): its reports go to
    exercise_reports of the directory copied, or to --reports-dir, never into the copy."""
    trainee_app(tmp_path).nc_session.quit()
    for reports_dir, expected in ((None, tmp_path / "trainee" / "exercise_reports"),
                                  (str(tmp_path / "class"), tmp_path / "class")):
        app = make_app(data_dir=str(tmp_path / "trainee"), ephemeral=True, realtime=False, reports_dir=reports_dir)
        copy = app.nc_session.session.data_dir
        assert copy != tmp_path / "trainee"
        try:
            async with app.run_test(size=SIZE) as pilot:
                await burst(pilot, *OPEN_LIST, START, END, START, END)  # twice, maybe in one second
                assert app.hint.startswith(f"Exercise ended, score 67/100: report in {expected}{os.sep}01_power_on")
        finally:
            app.nc_session.quit()
        assert len(list(expected.glob("01_power_on_reference-*.txt"))) == 2
        assert len(list(expected.glob("01_power_on_reference-*.json"))) == 2
        assert not copy.exists()


def test_browser_panels_write_reports_outside_their_copies(tmp_path: Path) -> None:
    assert reports_dir_of(None, str(tmp_path)) == tmp_path / "exercise_reports"
    assert reports_dir_of(str(tmp_path / "r"), str(tmp_path)) == tmp_path / "r"
    assert reports_dir_of(None, None) == default_data_dir().absolute() / "exercise_reports"
    words = shlex.split(panel_command("mill3", str(tmp_path), str(tmp_path / "r")))
    assert words[words.index("--reports-dir") + 1] == str(tmp_path / "r")


async def test_a_class_pack_imported_in_a_browser_tab_goes_to_the_served_directory(tmp_path: Path) -> None:
    """hmi --serve: each tab runs on a copy of the served directory (--ephemeral) and names the
    served one with --class-dir. A pack imported in one tab is written there (not into the
    tab's copy), and another tab, started before the import, lists it when it opens its list."""
    served = tmp_path / "trainee"
    trainee_app(tmp_path).nc_session.quit()
    pack = tmp_path / "c.pack"
    folder = tmp_path / "course"
    (folder / "programs").mkdir(parents=True)
    (folder / "20_square.toml").write_text(PACKED_EXERCISE)
    (folder / "programs" / "SQUARE.MPF").write_text(SQUARE)
    export_pack(pack, [folder / "20_square.toml"])
    tabs = [make_app(data_dir=str(served), ephemeral=True, realtime=False, class_dir=str(served)) for _ in range(2)]
    try:
        async with tabs[0].run_test(size=SIZE) as pilot:
            await burst(pilot, *OPEN_LIST, IMPORT, *str(pack), "enter")
            assert tabs[0].hint == "Import class pack: needs access level 2"  # checked in the tab
            tabs[0].submit(cmd.EnterPassword("EVENING"))
            await pilot.pause()
            await burst(pilot, IMPORT, *str(pack), "enter")
            assert tabs[0].hint == "Class pack imported: 1 exercise, 1 program (2 files new or changed)"
        assert (served / "exercises" / "programs" / "SQUARE.MPF").read_text() == SQUARE
        assert not (tabs[0].nc_session.session.data_dir / "exercises").exists()
        async with tabs[1].run_test(size=SIZE) as pilot:
            await burst(pilot, *OPEN_LIST, *[NEXT] * 14, START)
            assert tabs[1].hint == "Exercise started: Run the instructor's square"
            assert tabs[1].nc_session.session.files.read("MPF/SQUARE.MPF") == SQUARE
            await burst(pilot, END)
    finally:
        for tab in tabs:
            tab.nc_session.quit()
    words = shlex.split(panel_command("mill3", str(served), class_dir=str(served)))
    assert words[words.index("--class-dir") + 1] == str(served)
