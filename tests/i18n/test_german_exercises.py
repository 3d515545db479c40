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
