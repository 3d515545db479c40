"""``nck archive``: export and import all NC data of a data directory as one file.

::

    nck archive export FILE [--machine M] [--data-dir D]
    nck archive import FILE [--with-access] [--password PW] [--machine M] [--data-dir D]

An import is a write like any other (:meth:`nck.persistence.Session.import_archive`):
every datum it changes needs its protection level — the keyswitch level stored in
the data directory, or the level of ``--password`` for this call —, every value
is checked against its datum's type and limits, programs need the level of
program editing, the passwords (``--with-access``) level 1. A refused or
malformed archive changes nothing.

Exit codes: 0 done, 1 refused (level, wrong password), 2 command line, archive
or data directory unusable.
"""

from __future__ import annotations

import argparse
import sys
from typing import Callable, TextIO

from nck.access import level_name
from nck.cli_parser import CliParser
from nck.cli_password import level_of_password
from nck.datalock import DataDirLockError, lock_data_dir
from nck.machine import MachineFileError, load_machine
from nck.paths import resolve_data_dir
from nck.persistence import ArchiveError, ArchiveRefused, Session
from nck.resources import alarm_text


def _parser() -> CliParser:
    parser = CliParser(prog="nck archive", description="Export or import all NC data as one file")
    parser.add_argument("action", choices=["export", "import"])
    parser.add_argument("file")
    parser.add_argument("--machine", help="machine name or TOML file (default: the 3-axis mill)")
    parser.add_argument("--data-dir", help="NC data directory (default: the user data directory)")
    parser.add_argument("--password", help="password for this call's import (levels 1..3)")
    parser.add_argument("--with-access", action="store_true",
                        help="import the keyswitch position and the passwords too (needs level 1)")
    return parser


def run(argv: list[str], out: TextIO, err: TextIO, wait_s: Callable[[float], None] | None = None) -> int:
    """Run ``nck archive`` with ``argv`` (without ``archive``); return the exit code."""
    options = _parser().parse_command(argv, err)
    if isinstance(options, int):
        return options
    try:
        machine = load_machine(options.machine)
    except MachineFileError as exc:
        print(f"nck archive: {exc}", file=err)
        return 2
    lock = None
    try:
        data_dir = resolve_data_dir(options.data_dir)
        lock = lock_data_dir(data_dir)
        session = Session.open(data_dir, machine)
        for alarm in session.startup_alarms:
            print(f"ALARM {alarm.number} - - {alarm_text(alarm.number, alarm.params)}", file=err)
        if options.action == "export":
            print(f"NC data written to {session.export_archive(options.file)}", file=out)
            return 0
        return _import(options, session, out, err, wait_s)
    except ArchiveRefused as exc:
        print(f"nck archive: {exc}", file=err)
        return 1
    except (ArchiveError, DataDirLockError) as exc:
        print(f"nck archive: {exc}", file=err)
        return 2
    except OSError as exc:
        print(f"nck archive: {exc.filename or options.data_dir}: {exc.strerror or exc}", file=err)
        return 2
    finally:
        if lock is not None:
            lock.release()


def _import(options: argparse.Namespace, session: Session, out: TextIO, err: TextIO,
            wait_s: Callable[[float], None] | None) -> int:
    level = session.access.level
    how = level_name(level)
    if options.password is not None:
        granted = level_of_password(session.access, options.password, session, wait_s)
        if granted is None:
            session.save()  # the failed attempt counts at the next try too
            print("nck archive: password not accepted (nothing was imported)", file=err)
            return 1
        level, how = granted, f"level {granted} (password)"
    session.import_archive(options.file, include_access=options.with_access, level=level)
    print(f"NC data imported from {options.file} at {how}", file=out)
    return 0


def main(argv: list[str] | None = None, wait_s: Callable[[float], None] | None = None) -> int:
    """Entry point used by ``nck.cli`` for ``nck archive …``; returns the exit code."""
    return run(sys.argv[1:] if argv is None else list(argv), sys.stdout, sys.stderr, wait_s)
