"""The guided exercises in a German panel (issue 27): the list's title and summary, the side
window's fixed lines, step text and hint, and the dialog line come in German
(data/lang/de/exercises.toml, data/lang/de/hmi.po). Keys sent in a burst, as a terminal does."""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Static

from hmi.app import make_app
from tests.burst import burst
from tests.hmi.conftest import SIZE

OPEN_LIST = ("alt+a", "f8", "f4")  # Diagnostics, More (Weitere), Exercises (Übungen)
START, END = "shift+f1", "shift+f2"


async def test_exercise_list_and_side_window_in_german(tmp_path: Path) -> None:
    app = make_app(data_dir=str(tmp_path / "trainee"), realtime=False, lang="de")
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST)
        listed = str(app.screen.query_one("#diag-exercises", Static).render())
        assert "Einschalten: Achsen referenzieren" in listed
        assert "Nach dem Einschalten wissen die Messsysteme nicht" in listed
        assert "[Grundlagen]" in listed and "Power on" not in listed and "[basic]" not in listed
        await burst(pilot, START)
        assert app.hint == "Übung gestartet: Einschalten: Achsen referenzieren"
        side = str(app.screen.query_one("#exercise-side", Static).render())
        # step 1 (mode JOG) holds at once: the side window is at step 2
        assert side.startswith("ÜBUNG: Einschalten: Achsen referenzieren")
        assert "Schritt 2 von 2\nJede Achse mit REF POINT referenzieren." in side
        assert "Hinweis: REF POINT (Alt+R); X wählen (Alt+X)" in side
        assert "Noch offen:\n- Achsen nicht referenziert: X, Y, Z" in side  # the check's reason
        assert "Step" not in side and "Hint" not in side and "Reference every axis" not in side
        await burst(pilot, END)
        assert app.exercise_run is None
        assert app.hint.startswith("Übung beendet, Bewertung ")


async def test_the_report_of_a_german_panel_is_german(tmp_path: Path) -> None:
    """End exercise on a German panel: the report file says title, steps, score line and the
    reasons in German; the JSON beside it keeps the English (replays and the command line)."""
    app = make_app(data_dir=str(tmp_path / "trainee"), realtime=False, lang="de")
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *OPEN_LIST)
        await burst(pilot, START)
        await burst(pilot, END)
        reports = sorted((tmp_path / "trainee" / "exercise_reports").glob("*.txt"))
    assert len(reports) == 1
    lines = reports[0].read_text(encoding="utf-8").splitlines()
    assert lines[0] == "Übung: Einschalten: Achsen referenzieren"
    assert lines[1].startswith("Bewertung: 67/100   Zeit: ") and "   Tasten: " in lines[1]
    assert lines[3].startswith("[x] 1. ") and "(erledigt nach " in lines[3]
    assert lines[4] == "[ ] 2. Jede Achse mit REF POINT referenzieren."
    assert lines[5] == "      nicht erledigt: Achsen nicht referenziert: X, Y, Z"
    assert lines[6] == "[x] am Ende: no_alarm_came"  # steps 1 and the final check of 3: 67 points
    recorded = reports[0].with_suffix(".json").read_text(encoding="utf-8")
    assert '"title": "Power on: reference the axes"' in recorded and "axes not referenced: X, Y, Z" in recorded


def test_an_exercise_that_waits_says_so_in_german(german: None) -> None:
    """An exercise that needs a feature not built yet (``waits_for``): the list marks it and
    says what it waits for in German; the command line keeps the English (nck exercise list)."""
    from dataclasses import replace

    from nck.exercise import load_exercises
    from screens.diagnostics_exercises import exercises_text

    waiting = replace(load_exercises()[0], waits_for="the tool magazine")
    shown = exercises_text([waiting], 0, None).plain
    assert "(wartet)" in shown and "Wartet auf the tool magazine." in shown
    assert "waits" not in shown.lower()
