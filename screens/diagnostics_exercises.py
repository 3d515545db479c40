"""The Exercises view of the Diagnostics area (issue 26): the list of guided exercises.

Each line: number, title, level, and what an exercise waits for when a feature it needs
is not built yet (such an exercise cannot be started). The selected line carries ``▶``;
under the list, the summary of the selected exercise and, while one runs, which.
"""

from __future__ import annotations

from typing import Any

from rich.text import Text

from hmi.i18n import _, exercise_text


def exercises_text(exercises: list[Any], selected: int, running: str | None, exam_note: bool = True) -> Text:
    """The list with the selected exercise marked and its summary under it."""
    text = Text()
    if running:
        text.append(" " + _("Running: {title}  (End exercise: ⇧F2)").format(title=running) + "\n\n", style="bold")
    if not exercises:
        text.append(" " + _("No exercises found.") + "\n")
        return text
    for index, exercise in enumerate(exercises):
        mark = "▶" if index == selected else " "
        level = f"[{exercise_text(exercise, 'level')}]" if exercise.level else ""
        line = f" {mark} {index + 1:2d}  {exercise_text(exercise, 'title'):<50} {level}"
        if exercise.waits_for:
            line += "  " + _("(waits)")
        text.append(line + "\n", style="reverse" if index == selected else "")
    chosen = exercises[selected]
    text.append("\n")
    text.append(f" {exercise_text(chosen, 'summary')}\n")
    if chosen.exam and exam_note:
        text.append(" " + _("Exam: no hints are shown.") + "\n")
    if chosen.waits_for:
        text.append(" " + _("Waits for {what}.").format(what=exercise_text(chosen, "waits_for")) + "\n", style="italic")
    return text
