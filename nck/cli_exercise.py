"""``nck exercise``: the shipped exercises, and a recorded session replayed for the instructor.

::

    nck exercise list [--data-dir D]
    nck exercise replay SESSION.json [--events] [--data-dir D]

The exercises are the shipped ones and those a class pack brought into the data
directory (``nck class-pack import``).

``replay`` feeds the recording of a session (the JSON file the panel writes when an
exercise ends) through the exercise's checks again, as fast as it goes, and prints what
happened step by step — keys, commands, alarms, steps done — with the control time of
each, then the report. Exit codes: 0 done, 2 a file or exercise that cannot be used.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any, TextIO

from nck.cli_parser import CliParser
from nck.exercise import ExerciseError, available_exercises
from nck.exercise_checks import replay, report_text
from nck.exercise_files import load_recording
from nck.paths import default_data_dir


def _parser() -> CliParser:
    parser = CliParser(prog="nck exercise", description="Guided exercises: list them, replay a recorded session")
    sub = parser.add_subparsers(dest="action")
    listing = sub.add_parser("list", help="the shipped and imported exercises")
    again = sub.add_parser("replay", help="replay a recorded session (the .json report of the panel)")
    again.add_argument("session")
    again.add_argument("--events", action="store_true", help="also every state change")
    for command in (listing, again):
        command.add_argument("--data-dir", help="NC data directory with imported class packs "
                                                "(default: the user data directory)")
    return parser


def event_line(event: dict[str, Any], with_states: bool) -> str | None:
    """One line of the replay's timeline (None: not shown)."""
    kind = event["kind"]
    what = {
        "key": lambda: f"key {event['key']}",
        "command": lambda: " ".join([event["name"], *(f"{k}={v}" for k, v in event.get("fields", {}).items()),
                                     *([] if event["accepted"] else ["(refused)"])]),
        "alarm_came": lambda: f"alarm {event['number']} came",
        "alarm_went": lambda: f"alarm {event['number']} went ({event.get('by') or '-'})",
        "program_started": lambda: f"{event['program']} started",
        "program_ended": lambda: f"{event['program']} ended" + (f", alarms {event['alarms']}" if event["alarms"] else ""),
        "stop": lambda: f"stop: {event['reason']}",
        "step_done": lambda: f"=== step {event['step']} done",
        "ended": lambda: "=== session ended",
        "state": lambda: f"state: {event['state']['mode']} {event['state']['channel']}" if with_states else None,
    }.get(kind)
    text = what() if what is not None else None
    return None if text is None else f"{event['t_s']:9.2f} s  {text}"


def run(argv: list[str], out: TextIO, err: TextIO) -> int:
    """Run ``nck exercise`` with ``argv`` (without ``exercise``); return the exit code."""
    options = _parser().parse_command(argv, err)
    if isinstance(options, int):
        return options
    try:
        chosen = getattr(options, "data_dir", None)
        data_dir = Path(chosen).expanduser() if chosen else default_data_dir()
        exercises = {e.exercise_id: e for e in available_exercises(data_dir)}
    except ExerciseError as exc:
        print(f"nck exercise: {exc}", file=err)
        return 2
    if options.action == "list":
        for exercise in exercises.values():
            waits = f"  (waits for {exercise.waits_for})" if exercise.waits_for else ""
            print(f"{exercise.exercise_id:<28} {exercise.title}{waits}", file=out)
        return 0
    if options.action != "replay":
        print("usage: nck exercise {list,replay} ...", file=err)
        return 2
    try:
        exercise_id, events = load_recording(Path(options.session))
    except (OSError, ValueError) as exc:
        print(f"nck exercise: cannot replay '{options.session}': {exc}", file=err)
        return 2
    if exercise_id not in exercises:
        print(f"nck exercise: the session is of exercise '{exercise_id}', which is neither shipped nor imported", file=err)
        return 2
    exercise = exercises[exercise_id]
    try:
        progress = replay(exercise.steps, exercise.final_checks, events)
    except (KeyError, TypeError) as exc:
        print(f"nck exercise: '{options.session}' is not a recording of this version: {exc}", file=err)
        return 2
    for event in progress.events:
        line = event_line(event, options.events)
        if line is not None:
            print(line, file=out)
    print(file=out)
    print(report_text(progress.report(exercise.title)), end="", file=out)
    return 0


def main(argv: list[str]) -> int:
    """Entry point from ``nck exercise``."""
    return run(argv, sys.stdout, sys.stderr)
