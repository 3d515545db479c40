"""Guided exercises as data (``data/exercises/*.toml``, issue 26).

An exercise is a title, a starting set-up, the task in steps and the checks of every
step, all read from a TOML file; nothing in it is executed as Python. The checks are
tables ``{kind = "...", ...}`` of the small vocabulary of :mod:`nck.exercise_checks`,
the set-up is applied to a private data directory by :mod:`nck.exercise_setup`.

File format::

    title = "Power on: reference the axes"
    level = "basic"                     # free text shown in the list
    machine = "mill3"                   # optional (default machine)
    exam = false                        # true: an exam: no hints, access level locked, help limited to F11
    [setup]
    keyswitch = 0                       # 0..3 (level 7..4)
    programs = ["DRILL_FLANGE.MPF"]     # copied from programs/ beside the file, else data/programs
    program_texts = { "FIX.MPF" = "N10 ..." }   # programs written for the exercise
    select = "DRILL_FLANGE.MPF"         # selected at the start (AUTOMATIC program)
    blank = { low_mcs = [..], high_mcs = [..] }  # a box; or base_mcs/diameter_mm/length_mm
    blank_hidden = true                 # the trainee must find the blank by measuring
    tools = [{ t = 3, d = 1, type = 200, length1 = 95.0, radius = 4.25 }]  # true_length1 = 93.2:
                                        # the tool is really that long (its data are wrong)
    offsets = [{ frame = "G54", X = 0.0, Y = 0.0, Z = 0.0 }]
    faults = [{ kind = "emergency_stop" }]   # see FAULT_KINDS
    [[step]]
    text = "Reference every axis."
    hint = "JOG, REF POINT, then the axis keys."
    checks = [{ kind = "axes_referenced" }]
    [[final]]                           # checked once at the end, over the whole session
    kind = "no_alarm_came"
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from nck.exercise_checks import CHECK_KINDS
from nck.resources import data_path

FAULT_KINDS = {
    "wrong_offset": ("frame", "axis", "by_mm"),  # a work offset shifted from its true value
    "worn_tool": ("t", "d", "wear_mm"),  # length wear ($TC_DP12) written
    "missing_tool": ("t",),  # every edge of the tool deleted
    "broken_line": ("program", "line", "text"),  # one line of a program replaced
    "emergency_stop": (),  # E-stop pressed at the start
    "unreferenced": (),  # axes not referenced after power on (the normal state; stated for the list)
    "spindle_drive": ("limit_rpm",),  # the master spindle's drive reaches only this speed
}
"""Injected faults and their fields."""


IMPORTED_EXERCISES_DIR = "exercises"
"""Folder of a data directory with the exercises of imported class packs (:mod:`nck.class_pack`)."""
IMPORTED_PROGRAMS_DIR = "programs"
"""Folder beside exercise files with the programs they name (``[setup] programs``)."""


class ExerciseError(ValueError):
    """An exercise file that cannot be used (named in the message)."""


@dataclass(frozen=True)
class Step:
    """One step of the task: what to do, a hint, the checks that say it is done."""

    text: str
    hint: str
    checks: tuple[Mapping[str, Any], ...]


@dataclass(frozen=True)
class Exercise:
    """One guided exercise as read from its file."""

    exercise_id: str
    title: str
    level: str
    machine: str | None
    exam: bool
    setup: Mapping[str, Any]
    steps: tuple[Step, ...]
    final_checks: tuple[Mapping[str, Any], ...] = ()
    summary: str = ""
    waits_for: str = ""  # a feature the exercise needs that is not built yet ("" = ready)
    source: Path | None = field(default=None, compare=False)


def exercise_dir() -> Path:
    """The folder of the shipped exercises."""
    return data_path("exercises")


def load_exercises(folder: Path | None = None) -> list[Exercise]:
    """Every exercise of ``folder`` (default: the shipped ones), sorted by file name."""
    folder = folder or exercise_dir()
    return [load_exercise(path) for path in sorted(folder.glob("*.toml"))]


def available_exercises(data_dir: Path | None) -> list[Exercise]:
    """The shipped exercises and those imported into ``data_dir`` (class packs), by file name;
    an imported exercise replaces a shipped one of the same name."""
    by_id = {e.exercise_id: e for e in load_exercises()}
    imported = data_dir / IMPORTED_EXERCISES_DIR if data_dir is not None else None
    if imported is not None and imported.is_dir():
        by_id.update({e.exercise_id: e for e in load_exercises(imported)})
    return [by_id[key] for key in sorted(by_id)]


def exercise_program(exercise: Exercise, name: str, folder: Path | None = None) -> Path:
    """The file of the program ``name`` an exercise copies: in ``programs/`` beside the exercise
    (``folder``, else the exercise file's folder) when it is there, else the shipped one."""
    folder = folder if folder is not None else (exercise.source.parent if exercise.source else None)
    own = folder / IMPORTED_PROGRAMS_DIR / name if folder is not None else None
    return own if own is not None and own.is_file() else data_path("programs", name)


def load_exercise(path: Path) -> Exercise:
    """Read one exercise file; :class:`ExerciseError` names what is wrong."""
    try:
        with path.open("rb") as handle:
            table = tomllib.load(handle)
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise ExerciseError(f"{path.name}: {exc}") from None
    return exercise_from_table(path.stem, table, path)


def exercise_from_table(exercise_id: str, table: Mapping[str, Any], source: Path | None = None) -> Exercise:
    """The :class:`Exercise` of a parsed TOML table (checked against the vocabulary)."""
    where = f"{exercise_id}"

    def text(key: str, owner: Mapping[str, Any], default: str | None = None) -> str:
        value = owner.get(key, default)
        if not isinstance(value, str):
            raise ExerciseError(f"{where}: '{key}' must be a text")
        return value

    steps = []
    for index, step in enumerate(table.get("step", []), start=1):
        checks = tuple(_checked(c, f"{where} step {index}") for c in step.get("checks", []))
        if not checks:
            raise ExerciseError(f"{where} step {index}: a step needs at least one check")
        steps.append(Step(text("text", step), text("hint", step, ""), checks))
    if not steps:
        raise ExerciseError(f"{where}: an exercise needs at least one [[step]]")
    setup = table.get("setup", {})
    for fault in setup.get("faults", []):
        kind = fault.get("kind")
        if kind not in FAULT_KINDS:
            raise ExerciseError(f"{where}: unknown fault '{kind}' (known: {', '.join(sorted(FAULT_KINDS))})")
        missing = [f for f in FAULT_KINDS[kind] if f not in fault]
        if missing:
            raise ExerciseError(f"{where}: fault '{kind}' needs {', '.join(missing)}")
    finals = tuple(_checked(c, f"{where} final") for c in table.get("final", []))
    return Exercise(exercise_id, text("title", table), text("level", table, ""),
                    table.get("machine"), bool(table.get("exam", False)), setup, tuple(steps), finals,
                    text("summary", table, ""), text("waits_for", table, ""), source)


def _checked(check: Any, where: str) -> Mapping[str, Any]:
    if not isinstance(check, Mapping) or check.get("kind") not in CHECK_KINDS:
        kind = check.get("kind") if isinstance(check, Mapping) else check
        raise ExerciseError(f"{where}: unknown check '{kind}' (known: {', '.join(sorted(CHECK_KINDS))})")
    return check
