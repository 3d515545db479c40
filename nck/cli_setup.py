"""``nck setup``: read and change what is clamped on the machine (the instructor's switch).

::

    nck setup [--machine M] [--data-dir D] [--ephemeral] [--password PW] [FIELD[=VALUE]...]

Fields as in :mod:`nck.setup_fields` (``blank.x=-120`` moves the blank, ``hidden=yes`` hides
its position from the trainee). Without fields every field is listed. Writing needs the
level of ``write_machine_setup`` in data/access.toml (the stored level of the data
directory, or ``--password`` for this call); while the blank is hidden, its position and
size are printed as ``(hidden)`` below that level. Several writes are applied in the order
given and all checked before the set-up is saved; a refused one changes nothing.

Exit codes: 0 done, 1 refused (level, wrong password), 2 command line, unknown field, bad
value, machine or data directory unusable.
"""

from __future__ import annotations

import argparse
import sys
from typing import Callable, TextIO

from nck.access import Action, level_name
from nck.cli_data_dir import run_on_data_dir
from nck.cli_parser import CliParser
from nck.cli_password import level_of_password
from nck.machine import MachineConfig, MachineFileError, load_machine
from nck.persistence import Session
from nck.resources import alarm_text
from nck.setup_fields import SetupFieldError, setup_fields, with_field

HIDDEN_TEXT = "(hidden)"


def _parser() -> CliParser:
    parser = CliParser(prog="nck setup", description="Read and change the machine set-up (blank, reference block)")
    parser.add_argument("--machine", help="machine name or TOML file (default: the 3-axis mill)")
    parser.add_argument("--data-dir", help="NC data directory (default: the user data directory)")
    parser.add_argument("--ephemeral", action="store_true", help="work on a temporary copy of the data directory")
    parser.add_argument("--password", help="password for this call (levels 1..3)")
    parser.add_argument("fields", nargs="*", metavar="FIELD[=VALUE]")
    return parser


def run(argv: list[str], out: TextIO, err: TextIO, wait_s: Callable[[float], None] | None = None) -> int:
    """Run ``nck setup`` with ``argv`` (without ``setup``); return the exit code."""
    options = _parser().parse_command(argv, err)
    if isinstance(options, int):
        return options
    try:
        machine = load_machine(options.machine)
    except MachineFileError as exc:
        print(f"nck setup: {exc}", file=err)
        return 2
    return run_on_data_dir(
        "nck setup", options.data_dir, options.ephemeral, err,
        lambda data_dir: _run(options, machine, Session.open(data_dir, machine), out, err, wait_s))


def _run(options: argparse.Namespace, machine: MachineConfig, session: Session, out: TextIO, err: TextIO,
         wait_s: Callable[[float], None] | None) -> int:
    for alarm in session.startup_alarms:
        print(f"ALARM {alarm.number} - - {alarm_text(alarm.number, alarm.params)}", file=err)
    level, how = session.access.level, level_name(session.access.level)
    if options.password is not None:
        granted = level_of_password(session.access, options.password, session, wait_s)
        if granted is None:
            session.save()  # the failed attempt counts at the next try too
            print("nck setup: password not accepted (level unchanged)", file=err)
            return 1
        level, how = granted, f"level {granted} (password)"
    needed = session.access.required(Action.WRITE_MACHINE_SETUP)
    setup = session.ncdata.machine_setup
    reads = [item for item in options.fields if "=" not in item]
    writes = [item.partition("=")[::2] for item in options.fields if "=" in item]
    if writes and level > needed:
        print(f"nck setup: refused: changing the machine set-up needs protection level {needed}; "
              f"the current level is {how}", file=err)
        return 1
    try:
        for name, value in writes:
            setup = with_field(setup, name, value, machine.kind)
        known = {field.name: field for field in setup_fields(setup)}
        for name in reads:
            if name.strip().lower() not in known:
                raise SetupFieldError("setup_unknown_field", name=name, fields=", ".join(known))
    except SetupFieldError as exc:
        print(f"nck setup: {exc}; nothing was written" if writes else f"nck setup: {exc}", file=err)
        return 2
    shown = [known[name.strip().lower()] for name in reads] if reads else (
        [] if writes else list(known.values()))
    shown += [known[name.strip().lower()] for name, _ in writes if name.strip().lower() in known]
    for field in shown:
        text = HIDDEN_TEXT if field.position and setup.hidden and level > needed else field.text
        unit = f" {field.unit}" if field.unit and text != HIDDEN_TEXT else ""
        print(f"{field.name} = {text}{unit}", file=out)
    if writes:
        session.ncdata.machine_setup = setup
        session.save()
    return 0


def main(argv: list[str] | None = None, wait_s: Callable[[float], None] | None = None) -> int:
    """Entry point used by ``nck.cli`` for ``nck setup …``; returns the exit code."""
    return run(sys.argv[1:] if argv is None else list(argv), sys.stdout, sys.stderr, wait_s)
