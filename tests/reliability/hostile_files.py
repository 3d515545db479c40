"""A corpus of hostile retained-data files and the doors they are tried on.

Each :class:`Hostile` replaces the main file of one retained section of a data
directory whose backup generation is valid: by depth (nesting far past any
real data), size (integers with thousands of digits, oversized files), type
(text where numbers belong), value (out of the catalogue's limits, not finite,
a count of 10^10 R parameters) and kind of entry (links out of the directory,
to ``/dev/zero``, dangling; FIFOs; directories). Every door that opens a data
directory (``nck md``, ``nck check``, ``nck run``, the HMI's start) must answer
with alarm 4065 naming the file, keep the bad file aside, use the backup and
never show a traceback; so must the archive import (``nck archive import``,
whose session opens the directory first) and the panel built by ``make_app``.
:data:`FOLDER_CORPUS` does the same for the folders (``retained``, ``nc``,
``nc/MPF`` … replaced by a link, FIFO or file): alarm 4060 naming the folder,
the odd entry kept aside, nothing outside touched. The expected alarm follows from the manual's
description of 4065 ("data restored from backup") — not from our own output.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from nck.atomic import backup_path
from nck.ncdata import ToolEdge
from nck.persistence import Session

VICTIM_TEXT = "an outside file that must stay as it is\n"


def make_template() -> Path:
    """A data directory with two saved generations of every section (the backup is the first)."""
    root = Path(tempfile.mkdtemp(prefix="nck-hostile-template-"))
    session = Session.open(root, install_samples=False)
    for generation in (1, 2):
        data = session.ncdata
        data.tools[(generation, 1)] = ToolEdge({1: 100.0 + generation, 3: 70.0})
        data.r[3] = 3.0 + generation
        data.settable_frames["G54"].trans["X"] = -250.0 - generation
        data.gud["COUNT"] = generation
        data.part_counters = {"TOTAL_PARTS": 10 * generation}
        data.mda_program = f"G0 X{generation}\n"
        data.override_switches = {"feed": 10.0 * generation}
        data.setting_data["SD42100"] = 100.0 * generation
        session.retained.access.keyswitch_position = generation
        session.md.write("MD32000[X]", 5000.0 + generation, level=1)
        session.record_alarms([{"seq": generation, "number": 14000 + generation, "text": "x",
                                "category": "", "clear": "reset", "came_s": 1.0 * generation}])
        session.save()
    return root


# --------------------------------------------------------------------- corpus
@dataclass(frozen=True)
class Hostile:
    """One hostile main file: ``plant(path, valid_document, victim)`` puts it in place."""

    name: str
    section: str
    plant: Callable[[Path, dict[str, Any], Path], None]


def _write(document: Any) -> Callable[[Path, dict[str, Any], Path], None]:
    return lambda path, _doc, _victim: path.write_text(json.dumps(document))


def _edit(change: Callable[[dict[str, Any]], None]) -> Callable[[Path, dict[str, Any], Path], None]:
    def plant(path: Path, document: dict[str, Any], _victim: Path) -> None:
        change(document["data"])
        path.write_text(json.dumps(document))
    return plant


def _raw(text: str) -> Callable[[Path, dict[str, Any], Path], None]:
    return lambda path, _doc, _victim: path.write_text(text)


def _deep(depth: int) -> str:
    return "[" * depth + "]" * depth


def _wrapped(section: str, data_text: str) -> str:
    return ('{"format": "sinumerik-trainer/retained", "format_version": 1, '
            f'"section": "{section}", "data": {data_text}}}')


def _link_to_victim(path: Path, _document: dict[str, Any], victim: Path) -> None:
    path.unlink()
    path.symlink_to(victim)


def _link_to(target: str) -> Callable[[Path, dict[str, Any], Path], None]:
    def plant(path: Path, _document: dict[str, Any], _victim: Path) -> None:
        path.unlink()
        path.symlink_to(target)
    return plant


def _fifo(path: Path, _document: dict[str, Any], _victim: Path) -> None:
    path.unlink()
    os.mkfifo(path)


def _link_to_directory(path: Path, _document: dict[str, Any], victim: Path) -> None:
    path.unlink()
    path.symlink_to(victim.parent, target_is_directory=True)


def _socket(path: Path, _document: dict[str, Any], _victim: Path) -> None:
    import socket

    path.unlink()
    with socket.socket(socket.AF_UNIX) as listener:
        listener.bind(str(path))  # the socket file stays after close


def _directory(path: Path, _document: dict[str, Any], _victim: Path) -> None:
    path.unlink()
    path.mkdir()
    (path / "inner.json").write_text("{}")


def _oversized(path: Path, _document: dict[str, Any], _victim: Path) -> None:
    with open(path, "wb") as handle:  # sparse: 40 MB without writing them
        handle.truncate(40 * 1024 * 1024)


def _set_md(value: Any) -> Callable[[dict[str, Any]], None]:
    def change(data: dict[str, Any]) -> None:
        for values in data["machines"].values():
            values["MD32000"] = {"X": value}
    return change


def _set_alarm_field(field: str, value: Any) -> Callable[[dict[str, Any]], None]:
    return lambda data: data["entries"][0].__setitem__(field, value)


HUGE_DIGITS = "9" * 5000
LONG_DIGITS = "9" * 4000  # within the parser's digit limit, beyond any float

CORPUS: tuple[Hostile, ...] = (
    # depth
    Hostile("gud nested 100000 deep", "user_data", _raw(_wrapped("user_data", '{"gud": {"A": ' + _deep(100_000) + "}}"))),
    Hostile("whole file nested 100000 deep", "tools", _raw(_deep(100_000))),
    Hostile("gud nested 500 deep", "user_data", _raw(_wrapped("user_data", '{"gud": {"A": ' + _deep(500) + "}}"))),
    Hostile("table nested 900 deep", "setting_data",
            _raw(_wrapped("setting_data", '{"values": ' + '{"a": ' * 900 + "1" + "}" * 900 + "}"))),
    # size
    Hostile("5000-digit R count", "r_parameters", _raw(_wrapped("r_parameters", '{"count": ' + HUGE_DIGITS + ', "values": {}}'))),
    Hostile("4000-digit R value", "r_parameters", _raw(_wrapped("r_parameters", '{"count": 100, "values": {"3": ' + LONG_DIGITS + "}}"))),
    Hostile("4000-digit tool number", "tools",
            _raw(_wrapped("tools", '{"edges": [{"t": ' + LONG_DIGITS + ', "d": 1, "params": {}}]}'))),
    Hostile("5000-digit edge parameter index", "tools",
            _raw(_wrapped("tools", '{"edges": [{"t": 1, "d": 1, "params": {"' + HUGE_DIGITS + '": 1.0}}]}'))),
    Hostile("4000-digit part counter", "counters",
            _raw(_wrapped("counters", '{"part_counters": {"TOTAL_PARTS": ' + LONG_DIGITS + "}}"))),
    Hostile("40 MB file", "mda", _oversized),
    # type
    Hostile("machine datum as text", "machine_data", _edit(_set_md("fast"))),
    Hostile("machine datum as a list of tables", "machine_data", _edit(_set_md([{"a": 1}]))),
    Hostile("setting datum as text", "setting_data", _edit(lambda d: d["values"].__setitem__("SD42100", "fast"))),
    Hostile("tool parameter as a list", "tools", _edit(lambda d: d["edges"][0]["params"].__setitem__("1", [1]))),
    Hostile("R values as a list", "r_parameters", _edit(lambda d: d.__setitem__("values", [1, 2]))),
    Hostile("alarm parameters as a number", "alarm_log", _edit(_set_alarm_field("params", 5))),
    Hostile("alarm line as text", "alarm_log", _edit(_set_alarm_field("line", "ten"))),
    Hostile("alarm time as text", "alarm_log", _edit(_set_alarm_field("came_s", "noon"))),
    Hostile("counter as text", "counters", _edit(lambda d: d["part_counters"].__setitem__("TOTAL_PARTS", "x"))),
    Hostile("MDA text as a number", "mda", _edit(lambda d: d.__setitem__("text", 5))),
    Hostile("override switch as text", "panel", _edit(lambda d: d["override_switches"].__setitem__("feed", "50"))),
    Hostile("override switch of no such name", "panel",
            _edit(lambda d: d["override_switches"].__setitem__("coolant", 50.0))),
    Hostile("feed override switch beyond 200 %", "panel",
            _edit(lambda d: d["override_switches"].__setitem__("feed", 250.0))),
    Hostile("rapid override switch beyond 100 %", "panel",
            _edit(lambda d: d["override_switches"].__setitem__("rapid", 150.0))),
    Hostile("mirror flag as text", "work_offsets", _edit(lambda d: d["base"].__setitem__("mirror", {"X": "yes"}))),
    Hostile("keyswitch as text", "access", _edit(lambda d: d.__setitem__("keyswitch_position", "3"))),
    Hostile("data as a list", "counters", _edit(lambda d: d.clear())),
    Hostile("document as a string", "mda", _write("hello")),
    Hostile("R value as true", "r_parameters", _edit(lambda d: d["values"].__setitem__("3", True))),
    Hostile("tool edge without parameters", "tools", _edit(lambda d: d["edges"][0].pop("params"))),
    Hostile("GUD access level as text", "user_data", _edit(lambda d: d.__setitem__("access", {"A": {"r": "x"}}))),
    Hostile("password table as a number", "access", _edit(lambda d: d.__setitem__("passwords", 5))),
    Hostile("password table empty", "access", _edit(lambda d: d.__setitem__("passwords", {}))),
    Hostile("password iterations 10**9", "access", _edit(lambda d: d["passwords"]["1"].__setitem__("iterations", 10**9))),
    Hostile("empty file", "work_offsets", _raw("")),
    Hostile("NUL bytes", "counters", _raw("\x00" * 64)),
    Hostile("UTF-16 text", "mda", lambda path, doc, _v: path.write_bytes(json.dumps(doc).encode("utf-16"))),
    Hostile("section of another name", "tools", _raw(_wrapped("mda", '{"text": ""}'))),
    Hostile("format version 99", "setting_data",
            _raw('{"format": "sinumerik-trainer/retained", "format_version": 99, "section": "setting_data", '
                 '"data": {}}')),
    # value
    Hostile("machine datum below its limit", "machine_data", _edit(_set_md(-1.0))),
    Hostile("machine datum above its limit", "machine_data", _edit(_set_md(1e300))),
    Hostile("R count 1e10", "r_parameters", _edit(lambda d: d.__setitem__("count", 10**10))),
    Hostile("R count 1e10 as a real", "r_parameters", _edit(lambda d: d.__setitem__("count", 1e10))),
    Hostile("R count past MD28050", "r_parameters", _edit(lambda d: d.__setitem__("count", 40_000))),
    Hostile("R index 1e10", "r_parameters", _edit(lambda d: d["values"].__setitem__("10000000000", 1.0))),
    Hostile("R value NaN", "r_parameters", _raw(_wrapped("r_parameters", '{"count": 100, "values": {"3": NaN}}'))),
    Hostile("offset Infinity", "work_offsets",
            _raw(_wrapped("work_offsets", '{"settable": {}, "base": {"trans": {"X": Infinity}}}'))),
    Hostile("counter beyond 64 bits", "counters", _edit(lambda d: d["part_counters"].__setitem__("TOTAL_PARTS", 2**70))),
    Hostile("negative R count", "r_parameters", _edit(lambda d: d.__setitem__("count", -1))),
    # links, FIFOs, directories
    Hostile("link to an outside file", "r_parameters", _link_to_victim),
    Hostile("link to /dev/zero", "tools", _link_to("/dev/zero")),
    Hostile("dangling link", "setting_data", _link_to("/nonexistent/nowhere.json")),
    Hostile("link to its own backup", "counters", _link_to("counters.json.bak")),
    Hostile("FIFO", "machine_data", _fifo),
    Hostile("link to a directory", "user_data", _link_to_directory),
    Hostile("socket", "work_offsets", _socket),
    Hostile("directory", "alarm_log", _directory),
)

FAST_SAMPLE = ("gud nested 100000 deep", "5000-digit R count", "machine datum as text",
               "R count 1e10", "link to an outside file", "FIFO")
"""The cases run in ``make test`` (the whole corpus runs under ``make fuzz``)."""


# ---------------------------------------------------------------------- doors
def door_session(data_dir: Path, program: Path) -> tuple[list[int], str]:
    """``nck.persistence.Session.open``: the alarm numbers and no text."""
    session = Session.open(data_dir, install_samples=False)
    return [a.number for a in session.startup_alarms], ""


def door_md(data_dir: Path, program: Path) -> tuple[list[int], str]:
    """``nck md MD28050``."""
    from nck.cli_md import run

    out, err = io.StringIO(), io.StringIO()
    code = run(["--data-dir", str(data_dir), "MD28050"], out, err)
    assert code == 0, err.getvalue()
    return _alarm_numbers(err.getvalue()), err.getvalue()


def _nck(command: str) -> Callable[[Path, Path], tuple[list[int], str]]:
    def door(data_dir: Path, program: Path) -> tuple[list[int], str]:
        import contextlib

        from nck.cli import main

        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            code = main([command, "--data-dir", str(data_dir), str(program)])
        assert code == 0, err.getvalue()
        return _alarm_numbers(err.getvalue()), err.getvalue()
    door.__name__ = f"door_nck_{command}"
    return door


def door_hmi(data_dir: Path, program: Path) -> tuple[list[int], str]:
    """The HMI's start (``hmi --data-dir``): the alarms the kernel shows."""
    from hmi.startup import build_session

    holder = build_session(data_dir=str(data_dir))
    try:
        numbers = [a.number for a in holder.nck.status().alarms]
    finally:
        holder.quit()
    return numbers, ""


def door_hmi_app(data_dir: Path, program: Path) -> tuple[list[int], str]:
    """The panel as the ``hmi`` console script builds it (``make_app``), then its quit."""
    from hmi.app import make_app

    app = make_app(data_dir=str(data_dir), realtime=False)
    try:
        numbers = [a.number for a in app.nc_session.nck.status().alarms]
    finally:
        app.nc_session.quit()
    return numbers, ""


def door_archive_import(data_dir: Path, program: Path) -> tuple[list[int], str]:
    """``nck archive import`` of an archive that changes nothing (the session opens first)."""
    from nck.cli_archive import run

    archive = program.with_name("empty-archive.json")
    archive.write_text(json.dumps({"format": "sinumerik-trainer/archive", "format_version": 1,
                                   "sections": {}, "workpieces": [], "programs": []}))
    out, err = io.StringIO(), io.StringIO()
    code = run(["import", str(archive), "--data-dir", str(data_dir)], out, err)
    assert code == 0, err.getvalue()
    return _alarm_numbers(err.getvalue()), err.getvalue()


def _alarm_numbers(text: str) -> list[int]:
    return [int(line.split()[1]) for line in text.splitlines() if line.startswith("ALARM ")]


DOORS: dict[str, Callable[[Path, Path], tuple[list[int], str]]] = {
    "session": door_session, "nck md": door_md, "nck check": _nck("check"), "nck run": _nck("run"),
    "hmi": door_hmi, "hmi make_app": door_hmi_app, "nck archive import": door_archive_import,
}


# ---------------------------------------------------------------------- check
def _scene(template: Path, work: Path) -> tuple[Path, Path, Path]:
    """A copy of ``template`` as the data directory, a file outside it and a program to run."""
    data_dir = work / "data"
    shutil.copytree(template, data_dir, symlinks=True)
    victim = work / "victim.txt"
    victim.write_text(VICTIM_TEXT)
    program = work / "P.MPF"
    program.write_text("G0 X1\nM30\n")
    return data_dir, victim, program


def try_door(template: Path, hostile: Hostile, door: str, work: Path) -> None:
    """Plant ``hostile`` in a copy of ``template``, open it through ``door``, check the answer."""
    data_dir, victim, program = _scene(template, work)
    retained = data_dir / "retained"
    main = retained / f"{hostile.section}.json"
    backup = backup_path(main)
    expected = backup.read_bytes()
    hostile.plant(main, json.loads(main.read_text()), victim)

    numbers, text = DOORS[door](data_dir, program)

    assert "Traceback" not in text and "Internal error" not in text, text
    assert numbers.count(4065) == 1 and 4060 not in numbers, (numbers, text)
    if text:  # the command line's alarm line names the file (data/alarms/data.toml 4065)
        assert f"Retained data {hostile.section}.json unreadable" in text, text
    kept = retained / f"{hostile.section}.json.bad-1"
    assert os.path.lexists(kept), "the bad file was not kept aside"
    assert victim.read_text() == VICTIM_TEXT
    assert backup.read_bytes() == expected, "the backup was lost"
    # the backup's data (generation 1) are in use and whole: a new start finds nothing wrong
    again = Session.open(data_dir, install_samples=False)
    assert again.startup_alarms == []
    assert GENERATION[hostile.section](again) == 1


def try_door_without_backup(template: Path, hostile: Hostile, door: str, work: Path) -> None:
    """The main file damaged and ``hostile`` planted as its backup: 4060 (standard values) on
    ``door``, both kept aside, nothing outside touched, the next start clean."""
    data_dir, victim, program = _scene(template, work)
    retained = data_dir / "retained"
    main = retained / f"{hostile.section}.json"
    document = json.loads(main.read_text())
    main.write_text("damaged")
    hostile.plant(backup_path(main), document, victim)

    numbers, text = DOORS[door](data_dir, program)

    assert "Traceback" not in text and "Internal error" not in text, text
    assert numbers.count(4060) == 1 and 4065 not in numbers, (numbers, text)
    if text:
        assert f"Retained data {hostile.section}.json unreadable" in text, text
    assert (retained / f"{hostile.section}.json.bad-1").read_text() == "damaged"
    assert os.path.lexists(retained / f"{hostile.section}.json.bak.bad-1"), "the bad backup was not kept aside"
    assert victim.read_text() == VICTIM_TEXT
    assert Session.open(data_dir, install_samples=False).startup_alarms == []


GENERATION: dict[str, Callable[[Session], Any]] = {
    "tools": lambda s: sorted(t for t, _d in s.ncdata.tools) == [1] and 1,
    "work_offsets": lambda s: -250.0 - s.ncdata.settable_frames["G54"].trans["X"],
    "r_parameters": lambda s: s.ncdata.r[3] - 3.0,
    "user_data": lambda s: s.ncdata.gud["COUNT"],
    "setting_data": lambda s: s.ncdata.setting_data["SD42100"] / 100.0,
    "machine_data": lambda s: s.md.value("MD32000[X]") - 5000.0,
    "access": lambda s: s.retained.access.keyswitch_position,
    "counters": lambda s: s.ncdata.part_counters["TOTAL_PARTS"] / 10,
    "mda": lambda s: int(s.ncdata.mda_program.split("X")[1]),
    "panel": lambda s: s.ncdata.override_switches["feed"] / 10.0,
    "alarm_log": lambda s: {e["number"] for e in s.alarm_log} & {14001, 14002} == {14001} and 1,
}
"""Which saved generation a section of a session holds (the backup holds 1, the main file 2)."""


# ------------------------------------------------------------ hostile folders
FOLDERS = ("retained", "nc", "nc/MPF", "nc/SPF", "nc/WKS")


def _plant_folder(entry: Path, kind: str, outside: Path) -> None:
    if os.path.lexists(entry):
        shutil.move(str(entry), str(outside.parent / f"moved-{entry.name}"))
    if kind == "link":
        entry.symlink_to(outside, target_is_directory=True)
    elif kind == "dangling link":
        entry.symlink_to(outside / "missing")
    elif kind == "FIFO":
        os.mkfifo(entry)
    else:
        entry.write_text("a file where a folder belongs\n")


FOLDER_CORPUS: tuple[tuple[str, str], ...] = tuple(
    (folder, kind) for folder in FOLDERS for kind in ("link", "dangling link", "FIFO", "file"))
"""A folder of the data directory replaced by an entry of another kind."""


def try_folder_door(template: Path, folder: str, kind: str, door: str, work: Path) -> None:
    """Replace ``folder`` in a copy of ``template`` by ``kind``; open it through ``door``: 4060 names it."""
    data_dir = work / "data"
    shutil.copytree(template, data_dir, symlinks=True)
    (data_dir / "nc").mkdir(exist_ok=True)
    outside = work / "outside"
    outside.mkdir()
    (outside / "KEEP.MPF").write_text(VICTIM_TEXT)
    _plant_folder(data_dir / folder, kind, outside)
    program = work / "P.MPF"
    program.write_text("G0 X1\nM30\n")

    numbers, text = DOORS[door](data_dir, program)

    assert "Traceback" not in text and "Internal error" not in text, text
    assert numbers.count(4060) == 1, (numbers, text)
    if text:
        assert f"Retained data {folder} unreadable" in text, text
    assert os.path.lexists(data_dir / f"{folder}.bad-1"), "the odd entry was not kept aside"
    assert {p.name: p.read_text() for p in outside.iterdir()} == {"KEEP.MPF": VICTIM_TEXT}
    again = Session.open(data_dir, install_samples=False)
    assert again.startup_alarms == []
