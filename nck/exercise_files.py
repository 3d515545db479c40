"""The files of an exercise session: the report (text and JSON) and its recording.

The JSON file holds the report and the recording (every event of the session: keys,
commands, states, alarms), so an instructor can replay the session
(:func:`nck.exercise_checks.replay`) or read it with any tool. Both files are
written atomically.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Mapping

from nck.atomic import atomic_write_text
from nck.exercise_checks import report_text


def save_report(folder: Path, name: str, report: Mapping[str, Any], events: list[dict[str, Any]],
                exercise_id: str, text: str | None = None) -> tuple[Path, Path]:
    """Write ``<name>.txt`` (the readable report: ``text``, a panel's wording of it, else
    :func:`report_text` in English) and ``<name>.json`` (report and recording, in English).

    Several panels may write into one folder (browser sessions of a class): a name already
    taken gets ``-2``, ``-3`` … (the text file is claimed first, so two panels ending the same
    exercise in the same second never write over each other's report).
    """
    folder.mkdir(parents=True, exist_ok=True)
    text_path = _claimed(folder, name)
    json_path = text_path.with_suffix(".json")
    atomic_write_text(text_path, report_text(report) if text is None else text)
    atomic_write_text(json_path, json.dumps({"exercise": exercise_id, "report": report, "events": events},
                                            indent=1) + "\n")
    return text_path, json_path


def _claimed(folder: Path, name: str) -> Path:
    """A new, empty ``<name>[-n].txt`` in ``folder``, created here (so no other writer takes it)."""
    for number in range(1, 1000):
        path = folder / (f"{name}.txt" if number == 1 else f"{name}-{number}.txt")
        try:
            os.close(os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644))
        except FileExistsError:
            continue
        return path
    raise FileExistsError(f"{folder}: too many reports named {name}")


def load_recording(path: Path) -> tuple[str, list[dict[str, Any]]]:
    """The exercise id and the events of a saved session (``ValueError`` when it is not one)."""
    data = json.loads(path.read_text(encoding="utf-8"))
    if not isinstance(data, dict) or not isinstance(data.get("events"), list):
        raise ValueError(f"{path.name} is not a recorded exercise session")
    return str(data.get("exercise", "")), data["events"]
