"""``nck md``: read and write machine and setting data of an NC data directory.

::

    nck md [--machine M] [--data-dir D] [--ephemeral] [--password PW] [NAME[=VALUE]...]

Names by number (``MD32000[X]``, ``SD42100``, ``MD32200[1,X]``) or identifier
(``$MA_MAX_AX_VELO[X]``, ``$SC_DRY_RUN_FEED``). Without names every datum is
listed. Reading prints ``<number name> <identifier> = <value> <unit>``; axis
data without an axis print one line per axis. Writing checks the protection
level (the keyswitch level stored in the data directory, or the level of
``--password`` for this call only) and the datum's limits; a refused write
changes nothing. Several writes are all checked before any is made.

Exit codes: 0 done, 1 refused (level, limits, wrong password), 2 command line,
unknown name, machine or data directory unusable.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any, Callable, TextIO

from nck.access import AccessDenied, level_name
from nck.cli_data_dir import run_on_data_dir
from nck.cli_parser import CliParser
from nck.cli_password import level_of_password
from nck.machine import MachineFileError, load_machine
from nck.machine_data import (
    ACTIVATION_TEXT,
    DataError,
    DataRef,
    DataValueError,
    MachineDataStore,
    UnknownDataError,
    format_value,
)
from nck.persistence import Session
from nck.resources import alarm_text


def _parser() -> CliParser:
    parser = CliParser(prog="nck md", description="Read and write machine and setting data")
    parser.add_argument("--machine", help="machine name or TOML file (default: the 3-axis mill)")
    parser.add_argument("--data-dir", help="NC data directory (default: the user data directory)")
    parser.add_argument("--ephemeral", action="store_true",
                        help="work on a temporary copy of the data directory")
    parser.add_argument("--password", help="password for this call (levels 1..3)")
    parser.add_argument("names", nargs="*", metavar="NAME[=VALUE]")
    return parser


def _line(store: MachineDataStore, ref: DataRef, value: Any) -> str:
    d = ref.definition
    unit = f" {store.unit(ref)}" if d.unit else ""
    pending = ""
    if d.kind == "md" and store.is_pending(ref):
        pending = f"  (not active yet: active {format_value(d, store.active_value(ref))}, " \
                  f"takes effect {_when(d.activation)})"
    return f"{ref.text} {ref.identifier_text} = {format_value(d, value)}{unit}{pending}"


def _when(activation: str) -> str:
    return ACTIVATION_TEXT[activation]


def _read_lines(store: MachineDataStore, ref: DataRef) -> list[str]:
    if ref.definition.per_axis and ref.axis is None:
        return [_line(store, axis_ref, store.value(axis_ref))
                for axis_ref in (DataRef(ref.definition, axis, ref.index) for axis in store.axes)]
    return [_line(store, ref, store.value(ref))]


def run(argv: list[str], out: TextIO, err: TextIO, wait_s: Callable[[float], None] | None = None) -> int:
    """Run ``nck md`` with ``argv`` (without ``md``); return the exit code.

    ``wait_s`` is how the command waits after a wrong ``--password`` (None: not at all).
    """
    options = _parser().parse_command(argv, err)
    if isinstance(options, int):
        return options
    try:
        machine = load_machine(options.machine)
    except MachineFileError as exc:
        print(f"nck md: {exc}", file=err)
        return 2
    return run_on_data_dir("nck md", options.data_dir, options.ephemeral, err,
                           lambda data_dir: _run(options, machine, data_dir, out, err, wait_s))


def _run(options: argparse.Namespace, machine, data_dir, out: TextIO, err: TextIO,
         wait_s: Callable[[float], None] | None) -> int:
    session = Session.open(data_dir, machine)
    for alarm in session.startup_alarms:
        print(f"ALARM {alarm.number} - - {alarm_text(alarm.number, alarm.params)}", file=err)
    store = session.md
    level = session.access.level
    how = level_name(level)
    if options.password is not None:
        granted = level_of_password(session.access, options.password, session, wait_s)
        if granted is None:
            session.save()  # the failed attempt counts at the next try too
            print("nck md: password not accepted (level unchanged)", file=err)
            return 1
        level, how = granted, f"level {granted} (password)"

    reads: list[DataRef] = []
    writes: list[tuple[DataRef, Any]] = []
    try:
        for item in options.names:
            name, eq, value = item.partition("=")
            ref = store.resolve(name)
            if eq:
                writes.append((ref, value))
            else:
                reads.append(ref)
    except UnknownDataError as exc:
        print(f"nck md: {exc}", file=err)
        return 2
    if not options.names:
        reads = [DataRef(d) for d in store.catalog]

    refused = False
    for ref in reads:
        try:
            store.check_read(ref, level)
        except AccessDenied as exc:
            if not options.names:
                continue  # listing everything: show what this level may read
            print(f"nck md: {ref.text}: refused: {exc.what} needs protection level "
                  f"{exc.needed_level}; the current level is {how}", file=err)
            refused = True
            continue
        for line in _read_lines(store, ref):
            print(line, file=out)

    checked: list[tuple[DataRef, Any]] = []
    for ref, value in writes:
        try:
            checked.append((ref, store.check_write(ref, value, level)))
        except AccessDenied as exc:
            print(f"nck md: {ref.text}: refused: {exc.what} needs protection level "
                  f"{exc.needed_level}; the current level is {how}", file=err)
            refused = True
        except UnknownDataError as exc:
            print(f"nck md: {exc}", file=err)
            return 2
        except DataValueError as exc:
            print(f"nck md: {ref.text}: refused: {exc}", file=err)
            refused = True
    if refused:
        if writes:
            print("nck md: nothing was written", file=err)
        return 1
    for ref, value in checked:
        try:
            result = store.write(ref, value, level=level)
        except DataError as exc:  # pragma: no cover - checked above
            print(f"nck md: {ref.text}: {exc}", file=err)
            return 1
        d = ref.definition
        unit = f" {store.unit(ref)}" if d.unit else ""
        print(f"{ref.text} {ref.identifier_text} = {format_value(d, result.new)}{unit} "
              f"(was {format_value(d, result.old)}) - takes effect {result.takes_effect}", file=out)
    if checked:
        session.save()
    return 0


def main(argv: list[str] | None = None, wait_s: Callable[[float], None] | None = None) -> int:
    """Entry point used by ``nck.cli`` for ``nck md …``; returns the exit code."""
    return run(sys.argv[1:] if argv is None else list(argv), sys.stdout, sys.stderr, wait_s)
