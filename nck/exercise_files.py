"""The files of an exercise session: the report (text and JSON) and its recording.

The JSON file holds the report and the recording (every event of the session: keys,
commands, states, alarms), so an instructor can replay the session
(:func:`nck.exercise_checks.replay`) or read it with any tool. Both files are
written atomically.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Mapping

from nck.atomic import atomic_write_text
from nck.exercise_checks import report_text


def save_report(folder: Path, name: str, report: Mapping[str, Any], events: list[dict[str, Any]],
                exercise_id: str) -> tuple[Path, Path]:
    """Write ``<name>.txt`` (the readable report) and ``<name>.json`` (report and recording)."""
    folder.mkdir(parents=True, exist_ok=True)
    text_path, json_path = folder / f"{name}.txt", folder / f"{name}.json"
    atomic_write_text(text_path, report_text(report))
    atomic_write_text(json_path, json.dumps({"exercise": exercise_id, "report": report, "events": events},
                                            indent=1) + "\n")
    return text_path, json_path


def load_recording(path: Path) -> tuple[str, list[dict[str, Any]]]:
    """The exercise id and the events of a saved session (``ValueError`` when it is not one)."""
    data = json.loads(path.read_text(encoding="utf-8"))
    if not isinstance(data, dict) or not isinstance(data.get("events"), list):
        raise ValueError(f"{path.name} is not a recorded exercise session")
    return str(data.get("exercise", "")), data["events"]
