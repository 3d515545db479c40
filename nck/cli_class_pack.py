"""``nck class-pack``: exercises with their programs and set-ups as one archive (issue 26).

::

    nck class-pack export PACK EXERCISE...
    nck class-pack import PACK [--data-dir D] [--ephemeral] [--password PW]

``export`` packs exercise files (``EXERCISE`` is a ``.toml`` file, a folder of them, or the
name of a shipped exercise such as ``03_single_block_flange``) with every program they name
(:mod:`nck.class_pack`). ``import`` checks the whole pack, then writes its exercises into
the data directory, where the panel's Exercises list and ``nck exercise`` find them;
importing needs the level of ``import_class_pack`` in data/access.toml (the stored level of
the data directory, or ``--password`` for this call).

Exit codes: 0 done, 1 refused (level, wrong password), 2 command line, pack, exercise or
data directory unusable (nothing was written).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Callable, TextIO

from nck.access import Action, level_name
from nck.class_pack import ClassPack, PackError, export_pack, install_pack, read_pack
from nck.cli_data_dir import run_on_data_dir
from nck.cli_parser import CliParser
from nck.cli_password import level_of_password
from nck.exercise import ExerciseError, exercise_dir
from nck.persistence import Session
from nck.translations import counted_text

PROG = "nck class-pack"


def _parser() -> CliParser:
    parser = CliParser(prog=PROG, description="Exercises with their programs and set-ups as one archive")
    sub = parser.add_subparsers(dest="action")
    out = sub.add_parser("export", help="write exercises and their programs into a pack")
    out.add_argument("pack")
    out.add_argument("exercises", nargs="+", metavar="EXERCISE",
                     help="an exercise file (.toml), a folder of them, or a shipped exercise's name")
    into = sub.add_parser("import", help="import a pack's exercises into the data directory")
    into.add_argument("pack")
    into.add_argument("--data-dir", help="NC data directory (default: the user data directory)")
    into.add_argument("--ephemeral", action="store_true", help="work on a temporary copy of the data directory")
    into.add_argument("--password", help="password for this call (levels 1..3)")
    return parser


def exercise_files(names: list[str]) -> list[Path]:
    """The exercise files ``names`` stand for (files, folders, shipped names); ExerciseError if none."""
    files: list[Path] = []
    for name in names:
        path = Path(name)
        if path.is_dir():
            found = sorted(path.glob("*.toml"))
            if not found:
                raise ExerciseError(f"{name}: no exercise files (.toml) in this folder")
            files += found
        elif path.is_file():
            files.append(path)
        elif (exercise_dir() / f"{name}.toml").is_file():
            files.append(exercise_dir() / f"{name}.toml")
        else:
            raise ExerciseError(f"{name}: neither an exercise file nor a shipped exercise")
    return files


def run(argv: list[str], out: TextIO, err: TextIO, wait_s: Callable[[float], None] | None = None) -> int:
    """Run ``nck class-pack`` with ``argv`` (without ``class-pack``); return the exit code."""
    options = _parser().parse_command(argv, err)
    if isinstance(options, int):
        return options
    if options.action == "export":
        try:
            pack = export_pack(options.pack, exercise_files(options.exercises))
        except (ExerciseError, PackError) as exc:
            print(f"{PROG}: {exc}; nothing was written", file=err)
            return 2
        print(f"Class pack written to {options.pack}: {pack.summary()}", file=out)
        return 0
    if options.action != "import":
        print(f"usage: {PROG} {{export,import}} ...", file=err)
        return 2
    try:
        pack = read_pack(options.pack)
    except PackError as exc:
        print(f"{PROG}: {exc}; nothing was imported", file=err)
        return 2
    return run_on_data_dir(PROG, options.data_dir, options.ephemeral, err,
                           lambda data_dir: _import(options, pack, data_dir, out, err, wait_s))


def _import(options: argparse.Namespace, pack: ClassPack, data_dir: Path, out: TextIO, err: TextIO,
            wait_s: Callable[[float], None] | None) -> int:
    session = Session.open(data_dir)
    level, how = session.access.level, level_name(session.access.level)
    if options.password is not None:
        granted = level_of_password(session.access, options.password, session, wait_s)
        if granted is None:
            session.save()  # the failed attempt counts at the next try too
            print(f"{PROG}: password not accepted (nothing was imported)", file=err)
            return 1
        level, how = granted, f"level {granted} (password)"
    needed = session.access.required(Action.IMPORT_CLASS_PACK)
    if level > needed:
        print(f"{PROG}: refused: importing a class pack needs protection level {needed}; "
              f"the current level is {how}", file=err)
        return 1
    written = install_pack(pack, data_dir)
    files = counted_text(len(written), "({count} file new or changed)", "({count} files new or changed)")
    print(f"Class pack {options.pack} imported: {pack.summary()} {files}", file=out)
    return 0


def main(argv: list[str] | None = None, wait_s: Callable[[float], None] | None = None) -> int:
    """Entry point used by ``nck.cli`` for ``nck class-pack …``; returns the exit code."""
    return run(sys.argv[1:] if argv is None else list(argv), sys.stdout, sys.stderr, wait_s)
