"""Loading an exercise's starting set-up into a private NC data directory.

The trainee's own data directory is never touched: the set-up is written into a new
directory (the caller's, e.g. a temporary one) as retained data of the same kind the
panel keeps — tools, work offsets, the clamped blank and its instructor switch
``hidden`` (:mod:`nck.workpiece`), the keyswitch, programs — so the kernel built on it
starts exactly as the exercise says. Faults that need a running kernel (E-stop, a spindle
drive fault) are
returned as commands for the caller to send after the start (:func:`start_commands`).
"""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

from nck import commands as cmd
from nck.exercise import Exercise, ExerciseError, exercise_program
from nck.machine import MachineFileError, load_machine
from nck.ncdata import ToolEdge
from nck.persistence import Session
from nck.workpiece import MachineSetup, solid_from_plain

TRUE_LENGTH_FIELD = "true_length1"
"""A tool's field for its true length when its ``length1`` is wrong (:attr:`MachineSetup.tool_lengths`)."""
TOOL_FIELDS = {"type": 1, "position": 2, "length1": 3, "length2": 4, "length3": 5, "radius": 6,
               "wear_length1": 12, "wear_radius": 15}
"""Names of an exercise's tool fields and their ``$TC_DP`` numbers (as ``nck run --tools``)."""


def prepare_data_dir(exercise: Exercise, directory: Path) -> None:
    """Write the exercise's starting set-up as the retained data of ``directory`` (new).

    Raises :class:`ExerciseError` for an unknown machine or a malformed set-up value (named),
    ``StorageError``/``OSError`` when a file cannot be read or written.
    """
    setup = exercise.setup
    try:
        machine = load_machine(exercise.machine)
    except MachineFileError as exc:
        raise ExerciseError(f"{exercise.exercise_id}: {exc}") from None
    session = Session.open(directory, machine)
    data = session.ncdata
    with _setup_values(exercise, "tools"):
        for entry in setup.get("tools", []):
            params = {number: float(entry[name]) for name, number in TOOL_FIELDS.items() if name in entry}
            data.tools[(int(entry["t"]), int(entry.get("d", 1)))] = ToolEdge(params=params)
    with _setup_values(exercise, "offsets"):
        for entry in setup.get("offsets", []):
            frame = data.settable_frame(entry.get("frame", "G54"))
            frame.trans.update({a: float(v) for a, v in entry.items() if a in ("X", "Y", "Z")})
    blank = setup.get("blank")
    current = data.machine_setup
    if blank is not None:
        shape = "box" if "low_mcs" in blank else "cylinder"
        try:
            solid = solid_from_plain({"shape": shape, **blank})
        except (ValueError, KeyError) as exc:
            raise ExerciseError(f"{exercise.exercise_id}: blank: {exc}") from None
        current = MachineSetup(solid, current.reference, current.hidden)
    with _setup_values(exercise, "tools"):
        true_lengths = tuple((int(entry["t"]), float(entry[TRUE_LENGTH_FIELD]))
                             for entry in setup.get("tools", []) if TRUE_LENGTH_FIELD in entry)
    data.machine_setup = MachineSetup(current.blank, current.reference, bool(setup.get("blank_hidden", False)),
                                      true_lengths)
    session.retained.access.keyswitch_position = int(setup.get("keyswitch", 0))
    session.retained.access.locked = exercise.exam  # an exam: the trainee cannot change the level
    for name in setup.get("programs", []):
        session.files.save(f"MPF/{name}", exercise_program(exercise, name).read_text(encoding="utf-8"))
    for name, text in setup.get("program_texts", {}).items():
        session.files.save(f"MPF/{name}", text)
    with _setup_values(exercise, "faults"):
        for fault in setup.get("faults", []):
            _inject(fault, session)
    session.save()


@contextmanager
def _setup_values(exercise: Exercise, section: str) -> Iterator[None]:
    """Turn a malformed value of the set-up's ``section`` (a text where a number belongs, a
    missing field, a line beyond the program) into an :class:`ExerciseError` that names it."""
    try:
        yield
    except KeyError as exc:
        raise ExerciseError(f"{exercise.exercise_id}: setup {section}: {exc} is missing") from None
    except (ValueError, TypeError, IndexError) as exc:
        raise ExerciseError(f"{exercise.exercise_id}: setup {section}: {exc}") from None


def _inject(fault: dict[str, Any], session: Any) -> None:
    """Apply one fault that lives in the retained data (the others: :func:`start_commands`)."""
    data = session.ncdata
    kind = fault["kind"]
    if kind == "wrong_offset":
        frame = data.settable_frame(fault["frame"])
        frame.trans[fault["axis"]] = frame.trans.get(fault["axis"], 0.0) + float(fault["by_mm"])
    elif kind == "worn_tool":
        edge = data.tools[(int(fault["t"]), int(fault["d"]))]
        edge.params[12] = edge.params.get(12, 0.0) + float(fault["wear_mm"])
    elif kind == "missing_tool":
        for key in [k for k in data.tools if k[0] == int(fault["t"])]:
            del data.tools[key]
    elif kind == "broken_line":
        path = f"MPF/{fault['program']}"
        lines = session.files.read(path).splitlines()
        lines[int(fault["line"]) - 1] = fault["text"]
        session.files.save(path, "\n".join(lines) + "\n")


def start_commands(exercise: Exercise) -> list[Any]:
    """Commands to send to the new kernel at the start: program selection, E-stop, a spindle
    drive fault (faults that live in the running kernel, not in the retained data)."""
    commands: list[Any] = []
    if exercise.setup.get("select"):
        commands.append(cmd.SelectProgram(exercise.setup["select"]))
    faults = exercise.setup.get("faults", [])
    if any(f["kind"] == "emergency_stop" for f in faults):
        commands.append(cmd.EmergencyStop(True))
    spindles = load_machine(exercise.machine).spindles
    for fault in faults:
        if fault["kind"] == "spindle_drive" and spindles:
            commands.append(cmd.SetSpindleDriveFault(spindles[0], float(fault["limit_rpm"])))
    return commands
