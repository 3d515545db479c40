"""The headless command line ``nck`` (its contract is the specification's ``cli.md``).

``nck check PROGRAM…``, ``nck run PROGRAM [options]``, ``nck grade STUDENT --reference REF``
(:mod:`nck.grade`), ``nck version``; ``nck md``, ``nck setup``, ``nck archive`` and ``nck class-pack`` are
dispatched to their own modules. Exit codes: 0 ok, 1 alarm or
problems found, 2 command line / file problem, 3 timeout (``nck run``: one hour of
simulated time unless ``--timeout`` says otherwise; ``nck check``: a program not ended
after ``--max-blocks``, default 200,000 blocks), 141 the reader of the standard output
went away (``nck run --segments - P | head``): the command ends quietly, as a Unix tool
ended by SIGPIPE.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from contextlib import ExitStack
from pathlib import Path
from typing import Any, TextIO

from nck import __version__, canon
from nck.cli_parser import CliError, CliParser
from nck.errors import NcAlarmError
from nck.headless import CHECK_BLOCK_BUDGET, alarm_message, check_outcome, format_alarm, run_program
from nck.motion.tracefile import start_trace, write_trace_csv
from nck.interp.sources import DirectorySource, read_text_file
from nck.machine import MachineConfig, MachineFileError, load_machine
from nck.ncdata import NcData
from nck.regular_files import export_text_stream
from nck.termination import INTERRUPTED_EXIT, exit_on_termination
from nck.translations import LANGUAGES, SOURCE_LANGUAGE


wait_s = time.sleep
"""How the command line waits after a wrong --password (tests replace it)."""
DEFAULT_RUN_TIMEOUT_S = 3600.0  # one hour of machine time: a bound for endless loops, not for parts
STDOUT_CLOSED_EXIT = 141
"""Exit code when the reader of stdout went away: 128 + SIGPIPE, what a shell reports for such tools."""


DISPATCHED_COMMANDS = {
    "exercise": "guided exercises: list them, replay a recorded session (nck exercise --help)",
    "class-pack": "exercises with their programs and set-ups as one archive (nck class-pack --help)",
    "md": "read and write machine and setting data (nck md --help)",
    "setup": "read and change the machine set-up: blank, reference block (nck setup --help)",
    "archive": "export or import all NC data as one file (nck archive --help)",
}
"""The commands with their own modules and parsers, as ``nck --help`` lists them."""


def _build_parser() -> CliParser:
    parser = CliParser(prog="nck", description="Headless SINUMERIK NCK simulator")
    sub = parser.add_subparsers(dest="command")
    check = sub.add_parser("check", help="check programs without moving anything")
    check.add_argument("programs", nargs="+")
    _common_options(check)
    check.add_argument("--max-blocks", type=int, default=CHECK_BLOCK_BUDGET, metavar="N",
                       help=f"interpret at most N blocks per program (default {CHECK_BLOCK_BUDGET}); "
                            "a program not ended by then is reported (exit 3), e.g. an endless loop")
    run = sub.add_parser("run", help="run a program headless")
    run.add_argument("program")
    _common_options(run)
    run.add_argument("--json", action="store_true", help="print the final state as JSON")
    run.add_argument("--segments", help="write motion segments as JSON lines (- = stdout)")
    run.add_argument("--trace", help="write the MCS setpoints of every IPO cycle as CSV (t_s, axes; - = stdout)")
    run.add_argument("--timeout", type=float, default=DEFAULT_RUN_TIMEOUT_S, metavar="S",
                     help=f"stop after S seconds of simulated time, exit 3 (default {DEFAULT_RUN_TIMEOUT_S:g}; "
                          "0 = no limit); every block costs time, so an endless loop ends too")
    run.add_argument("--realtime", action="store_true", help="(accepted; runs as fast as possible)")
    grade = sub.add_parser("grade", help="run a trainee's program and a reference and compare them")
    grade.add_argument("program", metavar="STUDENT")
    grade.add_argument("--reference", required=True, metavar="REF", help="the reference program")
    _common_options(grade)
    grade.add_argument("--json", action="store_true", help="print the comparison as JSON")
    grade.add_argument("--tolerance", type=float, default=0.01, metavar="MM",
                       help="path deviation that still counts as the same path (default 0.01 mm)")
    grade.add_argument("--timeout", type=float, default=DEFAULT_RUN_TIMEOUT_S, metavar="S",
                       help=f"budget of simulated time per program (default {DEFAULT_RUN_TIMEOUT_S:g}); "
                            "a program not ended by then is reported (exit 3), e.g. an endless loop")
    sub.add_parser("version", help="print the version")
    for name, summary in DISPATCHED_COMMANDS.items():
        sub.add_parser(name, help=summary, add_help=False)  # listed only: _main hands them on first
    return parser


def _common_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--machine", help="machine name or TOML file")
    parser.add_argument("--dialect", choices=["siemens", "iso-m", "iso-t"],
                        help="language mode at program start (default: the machine data's, MD20150[46] "
                             "with MD10880; Siemens mode on the shipped machines)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="before start: write an R parameter (R1=5), a tool edge ($TC_DP6[1,1]=4), "
                             "a work offset ($P_UIFR[1,X,TR]=100), machine or setting data "
                             "(SD42100=2000); protection levels and limits apply as on the panel")
    parser.add_argument("--tools", help="tool table (TOML, see nck/cli_tools.py); written like --set")
    parser.add_argument("--password", help="password for this call's --set/--tools writes (levels 1..3)")
    parser.add_argument("--data-dir", help="NC data directory (retained data, NC file system)")
    parser.add_argument("--ephemeral", action="store_true",
                        help="work on a temporary copy of the data directory")
    parser.add_argument("--lang", default=SOURCE_LANGUAGE, choices=sorted(LANGUAGES),
                        help="language of the alarm texts on stderr (default en; --json stays English)")


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``nck`` console script; returns the exit code.

    SIGTERM and SIGHUP end a command like a normal exit (:mod:`nck.termination`),
    so a temporary copy of the data directory is removed and the lock given free;
    Ctrl+C too, with exit code 130 and no traceback.
    """
    with exit_on_termination():
        try:
            return _main(sys.argv[1:] if argv is None else list(argv))
        except BrokenPipeError:
            return _stdout_closed()
        except KeyboardInterrupt:  # the clean-up ran on the way out
            return INTERRUPTED_EXIT


def _stdout_closed() -> int:
    """End quietly after the reader of stdout went away (``| head``); return the exit code.

    The rest of the output goes nowhere: stdout is pointed at the null device, so
    the interpreter's final flush cannot fail again with a message.
    """
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(null, sys.stdout.fileno())
    finally:
        os.close(null)
    return STDOUT_CLOSED_EXIT


def _main(args: list[str]) -> int:
    if args[:1] == ["archive"]:
        from nck import cli_archive

        return cli_archive.main(args[1:], wait_s=wait_s)
    if args[:1] == ["class-pack"]:
        from nck import cli_class_pack

        return cli_class_pack.main(args[1:], wait_s=wait_s)
    if args[:1] == ["setup"]:
        from nck import cli_setup

        return cli_setup.main(args[1:], wait_s=wait_s)
    if args[:1] == ["exercise"]:
        from nck import cli_exercise

        return cli_exercise.main(args[1:])
    if args[:1] == ["md"]:
        try:
            from nck import cli_md  # type: ignore[attr-defined]
        except ImportError:
            print("nck md: not available in this build", file=sys.stderr)
            return 2
        return int(cli_md.main(args[1:], wait_s=wait_s))
    options = _build_parser().parse_command(args, sys.stderr)
    if isinstance(options, int):
        return options
    try:
        if options.command == "version":
            print(f"nck {__version__}")
            return 0
        if options.command == "check":
            return _check(options)
        if options.command == "run":
            return _run(options)
        if options.command == "grade":
            return _grade(options)
        _build_parser().print_usage(sys.stderr)
        return 2
    except CliError as exc:
        print(f"nck: {exc}", file=sys.stderr)
        return 2
    except MachineFileError as exc:
        print(f"nck: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        raise  # the reader went away: not a bug (see main)
    except Exception as exc:  # noqa: BLE001 - a bug must still not show a traceback to the user
        print(f"ALARM 1 - - Internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return 1


# ----------------------------------------------------------------------------- helpers
def _machine(options: argparse.Namespace) -> MachineConfig:
    from nck.resources import data_path

    if options.dialect and not data_path("gcode", f"{options.dialect.replace('-', '_')}.toml").is_file():
        raise CliError(f"language mode '{options.dialect}' is not available yet")
    return load_machine(options.machine)


def _read_program(path_text: str) -> tuple[Path, str]:
    path = Path(path_text)
    if path.is_dir():
        raise CliError(f"'{path_text}' is a folder, not a program file")
    if not path.is_file():
        raise CliError(f"program file '{path_text}' not found")
    try:
        return path, read_text_file(path)
    except OSError as exc:
        raise CliError(f"cannot read '{path_text}': {exc.strerror}") from None


def _source(path: Path, options: argparse.Namespace, env: "_Environment | None" = None) -> Any:
    """Subprograms: the program's own directory first, then the NC file system."""
    from nck.interp.sources import ChainSource

    here = DirectorySource(path.parent if str(path.parent) else Path("."))
    return ChainSource(here, env.session.files if env is not None and env.session else None)


class _Environment:
    """Machine, NC data and (with ``--data-dir``) the retained-data session of one command.

    With ``--data-dir`` the data directory is loaded (a temporary copy with
    ``--ephemeral``) and, unless ephemeral, saved again after the run. Without it the
    user's NC data directory (the HMI's) is read if it exists — offsets, tools, machine
    data and programs set up there apply — but a headless command never writes it back:
    it works on a temporary copy, so checking a program cannot change the trainee's
    set-up. With no user data directory every command starts from fresh NC data.
    """

    def __init__(self, options: argparse.Namespace) -> None:
        self.machine = _machine(options)
        self.session: Any = None
        self._ephemeral: Any = None
        self._lock: Any = None  # nck.datalock: no HMI may work on the same directory meanwhile
        self.data = NcData()
        data_dir, ephemeral = options.data_dir, options.ephemeral
        if not data_dir:
            from nck.paths import default_data_dir

            default = default_data_dir()
            if default.is_dir():
                data_dir, ephemeral = str(default), True
        if data_dir:
            from nck.datalock import DataDirLockError, lock_data_dir
            from nck.paths import EphemeralDataDir, resolve_data_dir
            from nck.persistence import Session

            try:
                if ephemeral:
                    self._ephemeral = EphemeralDataDir(data_dir)
                    directory = self._ephemeral.path
                else:
                    directory = resolve_data_dir(data_dir)
                    self._lock = lock_data_dir(directory)
                self.session = Session.open(directory, self.machine)
            except OSError as exc:
                self._release()
                raise CliError(f"NC data directory '{data_dir}': {exc}") from None
            except DataDirLockError as exc:  # another HMI or nck command works there (or .lock is a link)
                self._release()
                raise CliError(str(exc)) from None
            for alarm in self.session.startup_alarms:
                print(format_alarm(alarm, options.lang), file=sys.stderr)
            self.machine = self.session.active_machine()
            self.data = self.session.ncdata
        try:
            _apply_writes(options, self)
        except CliError:
            self.finish(save=False)
            raise

    def finish(self, save: bool = True) -> None:
        """Write the retained data back (not for ephemeral copies); clean up."""
        try:
            if self.session is not None and save and self._ephemeral is None:
                self.session.save()
        finally:
            self._release()

    def keep_failed_attempt(self) -> None:
        """Save the count of failed password attempts (and its alarm-log entry) and nothing else."""
        if self.session is not None and self._ephemeral is None:
            self.session.save()

    def _release(self) -> None:
        """Give the data directory free and remove a temporary copy (also when the start failed)."""
        if self._lock is not None:
            self._lock.release()
            self._lock = None
        if self._ephemeral is not None:
            self._ephemeral.cleanup()


def _requested_writes(options: argparse.Namespace) -> list[tuple[str, str, object]]:
    """``(door, name, value)`` of every ``--tools`` and ``--set`` write, in order."""
    writes: list[tuple[str, str, object]] = []
    if getattr(options, "tools", None):
        from nck.cli_tools import ToolFileError, read_tool_table

        try:
            edges = read_tool_table(options.tools)
        except ToolFileError as exc:
            raise CliError(str(exc)) from None
        writes += [("--tools", f"$TC_DP{param}[{tool},{edge}]", value)
                   for (tool, edge), params in edges.items() for param, value in sorted(params.items())]
    for setting in options.set:
        if "=" not in setting:
            raise CliError(f"--set needs NAME=VALUE, got '{setting}'")
        name, value = (part.strip() for part in setting.split("=", 1))
        writes.append(("--set", name, value))
    return writes


def _apply_writes(options: argparse.Namespace, env: "_Environment") -> None:
    """Write ``--tools`` and ``--set`` through the one write path (level and limit checks).

    The level is the one stored in the data directory (fresh NC data: keyswitch
    position 0, level 7) or that of ``--password`` for this call, as for ``nck md``.
    The first refused write stops the command before anything is saved.
    """
    from nck.access import AccessControl, AccessDenied, AccessState, level_name
    from nck.machine_data import DataError, MachineDataStore
    from nck.writes import DataWriter, WriteRefused

    writes = _requested_writes(options)
    if not writes:
        return
    if env.session is not None:
        store, access = env.session.md, env.session.access
    else:
        store = MachineDataStore(env.machine, {}, env.data.setting_data)
        access = AccessControl(AccessState(), user_class=store.user_class)
    level, how = access.level, level_name(access.level)
    if options.password is not None:
        from nck.cli_password import level_of_password

        granted = level_of_password(access, options.password, env.session, wait_s)
        if granted is None:
            env.keep_failed_attempt()
            raise CliError("password not accepted (nothing was written)")
        level, how = granted, f"level {granted} (password)"
    writer = DataWriter(env.data, store, access, level=level)
    for door, name, value in writes:
        try:
            writer.write(name, value)
        except AccessDenied as exc:
            raise CliError(f"{door} {name}: refused: {exc.what} needs protection level "
                           f"{exc.needed_level}; the current level is {how} (--password raises it)") from None
        except (WriteRefused, DataError) as exc:
            raise CliError(f"{door} {name}={value}: refused: {exc}") from None
    store.activate("power_on")  # the run starts after the writes: every written MD is in effect
    env.machine = store.active_machine()


# ----------------------------------------------------------------------------- check
def _check(options: argparse.Namespace) -> int:
    if options.max_blocks < 1:
        raise CliError("--max-blocks needs a number of blocks of 1 or more")
    files = [_read_program(p) for p in options.programs]
    problems = unended = 0
    for path, text in files:
        env = _Environment(options)
        try:
            found = check_outcome(env.machine, _source(path, options, env), path.name, text,
                                  env.data, max_blocks=options.max_blocks, dialect=options.dialect)
        finally:
            env.finish(save=False)
        for alarm in found.alarms:
            print(format_alarm(alarm, options.lang), file=sys.stderr)
        problems += len(found.alarms)
        if not found.alarms and not found.ended:
            unended += 1
            print(f"{path.name}: not ended after {found.blocks} blocks (an endless loop? "
                  f"--max-blocks N checks longer programs)")
        else:
            print(f"{path.name}: {'ok' if not found.alarms else f'{len(found.alarms)} problem(s)'}")
    return 1 if problems else 3 if unended else 0


# ----------------------------------------------------------------------------- run
def _run(options: argparse.Namespace) -> int:
    if options.timeout < 0:
        raise CliError("--timeout needs 0 (no limit) or a number of seconds")
    timeout_s = options.timeout or None
    path, text = _read_program(options.program)
    try:
        with ExitStack() as outputs:
            segment_out = _output(outputs, options.segments, "--segments")
            trace_out = _output(outputs, options.trace, "--trace")
            env = _Environment(options)
            machine, data = env.machine, env.data

            def on_command(command: canon.CanonCommand) -> None:
                if segment_out is not None and isinstance(command, canon.Motion):
                    segment_out.write(json.dumps(segment_json(command)) + "\n")

            traced: list[Any] = []

            def on_motion(motion: Any) -> None:
                start_trace(motion)
                traced.append(motion)

            try:
                result = run_program(machine, _source(path, options, env), data, path.name, text=text,
                                     timeout_s=timeout_s, on_command=on_command,
                                     dialect=options.dialect, on_motion=on_motion if trace_out else None,
                                     keep_commands=False)
            finally:
                env.finish()
            if trace_out is not None and traced:
                write_trace_csv(traced[-1], trace_out)
    except BrokenPipeError:
        raise  # the reader of stdout went away (see main)
    except OSError as exc:  # an output file could not be completed (disk full ...): the old one stays
        raise CliError(f"cannot write '{exc.filename or 'an output file'}': {exc.strerror}") from None
    for alarm in result.alarms:
        print(format_alarm(alarm, options.lang), file=sys.stderr)
    if result.status == "timeout":
        print(f"nck: the program did not end within {options.timeout:g} s of simulated time "
              "(an endless loop? --timeout S allows longer runs, 0 = no limit)", file=sys.stderr)
    if options.json:
        print(json.dumps(final_state_json(result, machine, data)))
    return result.exit_code


# ----------------------------------------------------------------------------- grade
def _grade(options: argparse.Namespace) -> int:
    """``nck grade``: exit 0 same in every respect, 1 differences, 2 input, 3 a program did not end."""
    from nck.grade import grade, grade_json, grade_text, summarize

    if options.timeout <= 0:
        raise CliError("--timeout needs a number of seconds above 0 (a grade needs a budget)")
    if options.tolerance < 0:
        raise CliError("--tolerance needs a distance of 0 mm or more")
    student, reference = _read_program(options.program), _read_program(options.reference)
    summaries = []
    for path, text in (student, reference):
        env = _Environment(options)
        try:
            result = run_program(env.machine, _source(path, options, env), env.data, path.name, text=text,
                                 timeout_s=options.timeout, dialect=options.dialect)
        finally:
            env.finish(save=False)  # grading changes nothing in the data directory
        if result.status == "timeout":
            print(f"nck grade: {path.name} did not end within {options.timeout:g} s of simulated time "
                  "(an endless loop? --timeout S allows longer runs); nothing was graded", file=sys.stderr)
            return 3
        summaries.append(summarize(result, path.name))
    graded = grade(student[0].name, summaries[0], reference[0].name, summaries[1], options.tolerance)
    print(json.dumps(grade_json(graded)) if options.json else grade_text(graded))
    return 0 if graded.all_same else 1


def _output(outputs: ExitStack, name: str | None, option: str) -> TextIO | None:
    """The stream of an output file option (``-`` = stdout), opened before the run.

    A file is written like every export (:func:`nck.regular_files.export_text_stream`):
    complete when the run is over, never through a link, FIFO or device; an
    existing regular file is replaced, as a shell's ``>`` would.
    """
    if not name:
        return None
    if name == "-":
        return sys.stdout
    try:
        return outputs.enter_context(export_text_stream(name, replace=True))
    except OSError as exc:
        raise CliError(f"cannot write '{name}' ({option}): {exc.strerror}") from None


def segment_json(motion: canon.Motion) -> dict[str, Any]:
    """One ``--segments`` line."""
    return {
        "file": motion.source.file,
        "line": motion.source.line,
        "n": motion.source.n,
        "motion": motion.kind,
        "plane": motion.plane,
        "end": {k: _num(v) for k, v in motion.end_wcs.items()},
        "end_mcs": {k: _num(v) for k, v in motion.end_mcs.items()},
        "center": {k: _num(v) for k, v in motion.center_wcs.items()} if motion.center_wcs else None,
        "feed": motion.feed,
    }


def _num(value: float) -> float:
    return round(float(value), 6) + 0.0


def final_state_json(result: Any, machine: MachineConfig, data: NcData) -> dict[str, Any]:
    """The ``--json`` final state."""
    interp = result.interpreter
    modal = interp.modal
    if result.status == "ended":
        channel, program = "reset", "aborted"
    elif result.status == "alarm":
        channel, program = "interrupted", "interrupted"
    else:
        channel, program = "active", "running"
    return {
        "alarms": [
            {"number": a.number, "line": a.line, "n": a.n, "file": a.file, "text": alarm_message(a)}
            for a in result.alarms
        ],
        "position": {  # where the axes stand (a refused block did not move them, 002 L2397-2416)
            "wcs": {k: _num(v) for k, v in (result.position_wcs or modal.position_wcs).items()},
            "mcs": {k: _num(v) for k, v in (result.position_mcs or modal.position_mcs).items()},
        },
        "gcodes": {str(k): v for k, v in sorted(modal.gcodes.items())},
        "tool": {"T": modal.tool, "D": modal.edge},
        "spindle": {"S": _num(modal.spindle_speed_rpm), "state": modal.spindle_state},
        "r": {str(i): v for i, v in enumerate(data.r) if v != 0},
        "blocks": result.blocks,
        "machine_time_s": round(result.machine_time_s, 6),
        "channel": channel,
        "program": program,
    }
