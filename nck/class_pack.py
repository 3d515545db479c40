"""The class pack: exercises with their programs and set-ups as one archive (issue 26).

An instructor writes a pack once (:func:`export_pack`) and imports it on every seat
(:func:`read_pack`, then :func:`install_pack`). The pack is an NC data archive
(:data:`nck.persistence.ARCHIVE_FORMAT`, same version) whose ``content`` says
``class-pack``; it carries no NC data sections, its ``programs`` are the programs the
exercises copy into their private data directory (``MPF/NAME``, text or base64 as in every
archive), and ``exercises`` holds each exercise file as written (its ``[setup]`` is the
set-up)::

    {"format": "sinumerik-trainer/archive", "format_version": 1, "content": "class-pack",
     "sections": {}, "workpieces": [],
     "programs": [{"path": "MPF/FLANGE.MPF", "text": "..."}],
     "exercises": [{"file": "20_flange.toml", "text": "title = ..."}]}

On a seat the exercises land in ``exercises/`` of the NC data directory and their programs
in ``exercises/programs/`` (:func:`nck.exercise.exercise_program`), next to the shipped
ones: the list shows both, an imported exercise replaces a shipped one of the same file name.
A pack is read and checked whole before anything is written (every exercise against the
check vocabulary, every program it names present, names and sizes); then each file is
written atomically, and a file already there with the same content is left alone, so
importing the same pack again changes nothing.
"""

from __future__ import annotations

import base64
import binascii
import json
import re
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping

from nck.atomic import atomic_write_bytes, atomic_write_text
from nck.exercise import (
    IMPORTED_EXERCISES_DIR, IMPORTED_PROGRAMS_DIR, Exercise, ExerciseError, exercise_from_table,
    exercise_program,
)
from nck.machine import MachineFileError, load_machine
from nck.persistence import (
    ARCHIVE_FORMAT, ARCHIVE_VERSION, CLASS_PACK_CONTENT, read_archive_document,
)
from nck.regular_files import check_export_target
from nck.storage import StorageError, check_program_size
from nck.translations import counted_text

EXERCISE_FILE = re.compile(r"[A-Za-z0-9][A-Za-z0-9_-]{0,63}\.toml")
PROGRAM_FILE = re.compile(r"[A-Za-z0-9][A-Za-z0-9_]{0,23}\.(MPF|SPF|mpf|spf)")


class PackError(Exception):
    """A class pack that cannot be written or read; ``str()`` says why (nothing was changed)."""


@dataclass(frozen=True)
class ClassPack:
    """A checked pack: exercise files and program files by file name."""

    exercises: Mapping[str, str]
    programs: Mapping[str, bytes]

    def summary(self, translate: Callable[[str], str] = str) -> str:
        """What the pack holds, in words ("2 exercises, 1 program"); ``translate`` gives each
        count's text in the language shown (the panel's gettext; the command line's English)."""
        return ", ".join((counted_text(len(self.exercises), "{count} exercise", "{count} exercises", translate),
                          counted_text(len(self.programs), "{count} program", "{count} programs", translate)))


def _program_names(exercise: Exercise) -> list[str]:
    names = exercise.setup.get("programs", [])
    if not isinstance(names, list) or not all(isinstance(n, str) and PROGRAM_FILE.fullmatch(n) for n in names):
        raise ExerciseError(f"{exercise.exercise_id}: 'programs' must list program file names (NAME.MPF)")
    return names


def _checked_exercise(file_name: str, text: str) -> Exercise:
    """The exercise of one file of a pack (its machine known, its programs named properly)."""
    if not EXERCISE_FILE.fullmatch(file_name):
        raise PackError(f"'{file_name}' is not an exercise file name (letters, digits, _ and -, .toml)")
    try:
        exercise = exercise_from_table(file_name[:-5], tomllib.loads(text))
        _program_names(exercise)
        load_machine(exercise.machine)
    except tomllib.TOMLDecodeError as exc:
        raise PackError(f"{file_name}: {exc}") from None
    except (ExerciseError, MachineFileError) as exc:
        raise PackError(f"{file_name}: {exc}") from None
    return exercise


def export_pack(target: Path | str, sources: Iterable[Path]) -> ClassPack:
    """Write the exercise files ``sources`` and every program they name into the pack ``target``.

    A program is taken from ``programs/`` beside its exercise, else from the shipped ones.
    Raises PackError (an exercise that does not load, a program not found) before writing.
    """
    exercises: dict[str, str] = {}
    programs: dict[str, bytes] = {}
    for source in sources:
        try:
            text = source.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise PackError(f"{source}: cannot be read ({getattr(exc, 'strerror', None) or exc})") from None
        exercise = _checked_exercise(source.name, text)
        if source.name in exercises and exercises[source.name] != text:
            raise PackError(f"two different exercises are called {source.name}")
        exercises[source.name] = text
        for name in _program_names(exercise):
            path = exercise_program(exercise, name, source.parent)
            try:
                programs[name] = path.read_bytes()
            except OSError:
                raise PackError(f"{source.name}: program {name} not found "
                                f"(neither in {source.parent / IMPORTED_PROGRAMS_DIR} nor shipped)") from None
    if not exercises:
        raise PackError("no exercise to pack")
    pack = ClassPack(exercises, programs)
    document = {
        "format": ARCHIVE_FORMAT, "format_version": ARCHIVE_VERSION, "content": CLASS_PACK_CONTENT,
        "sections": {}, "workpieces": [],
        "programs": [_program_entry(name, raw) for name, raw in sorted(programs.items())],
        "exercises": [{"file": name, "text": text} for name, text in sorted(exercises.items())],
    }
    try:
        check_export_target(Path(target), replace=True)  # never through a link, FIFO or device
        atomic_write_text(target, json.dumps(document, indent=1, sort_keys=True) + "\n")
    except OSError as exc:
        raise PackError(f"{target}: cannot be written ({exc.strerror or exc})") from None
    return pack


def _program_entry(name: str, raw: bytes) -> dict[str, str]:
    try:
        return {"path": f"MPF/{name}", "text": raw.decode("utf-8")}
    except UnicodeDecodeError:
        return {"path": f"MPF/{name}", "base64": base64.b64encode(raw).decode()}


def read_pack(path: Path | str) -> ClassPack:
    """The checked content of the pack ``path``; PackError says why it cannot be used."""
    document = read_archive_document(path, PackError, "class pack",
                                     "not a class pack (not an archive of this trainer)")
    if document.get("content") != CLASS_PACK_CONTENT:
        raise PackError(f"{path}: an NC data archive, not a class pack (import it with 'nck archive import')")
    try:
        return _pack_content(document)
    except PackError as exc:
        raise PackError(f"{path}: {exc}") from None
    except (KeyError, TypeError, ValueError, binascii.Error, StorageError) as exc:
        raise PackError(f"{path}: bad content ({exc})") from None


def _pack_content(document: Mapping[str, Any]) -> ClassPack:
    programs: dict[str, bytes] = {}
    for item in _listed(document, "programs"):
        folder, _, name = str(item["path"]).partition("/")
        if folder.upper() not in ("MPF", "SPF") or not PROGRAM_FILE.fullmatch(name):
            raise PackError(f"{item['path']} is not a program of an exercise")
        raw = (_text(item["text"]).encode("utf-8") if "text" in item
               else base64.b64decode(_text(item["base64"]), validate=True))
        check_program_size(name, raw)
        programs[name] = raw
    exercises: dict[str, str] = {}
    for item in _listed(document, "exercises"):
        file_name, text = _text(item["file"]), _text(item["text"])
        exercise = _checked_exercise(file_name, text)
        exercises[file_name] = text
        for name in _program_names(exercise):
            if name not in programs and not exercise_program(exercise, name).is_file():
                raise PackError(f"{file_name}: program {name} is neither in the pack nor shipped")
    if not exercises:
        raise PackError("the pack holds no exercise")
    return ClassPack(exercises, programs)


def _listed(document: Mapping[str, Any], key: str) -> list[Mapping[str, Any]]:
    items = document.get(key, [])
    if not isinstance(items, list) or not all(isinstance(item, dict) for item in items):
        raise ValueError(f"'{key}' must be a list of tables")
    return items


def _text(value: Any) -> str:
    if not isinstance(value, str):
        raise ValueError(f"{value!r} is not text")
    return value


def install_pack(pack: ClassPack, data_dir: Path) -> list[str]:
    """Write ``pack`` into the data directory ``data_dir``; return the files written (new or changed).

    Each file is written atomically; one that holds the same content already stays.
    """
    folder = data_dir / IMPORTED_EXERCISES_DIR
    files = [(folder / name, text.encode("utf-8")) for name, text in pack.exercises.items()]
    files += [(folder / IMPORTED_PROGRAMS_DIR / name, raw) for name, raw in pack.programs.items()]
    written = []
    for path, raw in sorted(files):
        if path.is_file() and path.read_bytes() == raw:
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_bytes(path, raw)
        written.append(str(path.relative_to(data_dir)))
    return written
