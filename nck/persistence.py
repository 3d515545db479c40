"""Retained NC data: what a real control keeps in battery-backed memory, kept in files.

Every section lives in its own file ``<data dir>/retained/<section>.json`` so
that a damaged file costs only that section:

=================  ==========================================================
``tools``          cutting edges ``$TC_DP1…25`` by tool and edge
``work_offsets``   settable frames G54 … and the base frame
``r_parameters``   R parameters that are not zero
``user_data``      global user data (GUD)
``setting_data``   setting data (``SD…`` keys as in ``NcData.setting_data``)
``machine_data``   machine data changed against the machine file, per machine
``access``         keyswitch position, active password level, password hashes
``counters``       workpiece counters
``mda``            the MDA buffer
``panel``          positions of the override switches of the machine control panel
``alarm_log``      the alarm log (bounded)
``machine_setup``  what is clamped: blank, reference block, the instructor's hidden switch
``manual_settings`` retraction plane, safety distance, measuring feed of manual mode (JOG Settings)
``display``        the language of the operator texts (Setup > Language, ``hmi --lang``) and the colour theme
=================  ==========================================================

File format (version 1)::

    {"format": "sinumerik-trainer/retained", "section": "tools",
     "format_version": 1, "data": { ... section data ... }}

Files are written atomically with one backup generation (``<file>.bak``). At
start a file that cannot be read (truncated, garbage, wrong section or a
``format_version`` this program does not know) is moved aside as
``<file>.bad-<n>`` and its backup is used, with alarm 4065 naming the file; if
the backup is unusable too the section starts from standard values with alarm
4060. A section is never reset silently.

"Cannot be read" covers hostile files too: an entry that is not a regular file
(a link — never followed —, a FIFO, a device), a file larger than
:data:`SECTION_LIMIT_BYTES`, nesting deeper than :data:`NESTING_LIMIT`, numbers
that are not finite or beyond :data:`INTEGER_LIMIT`, an R parameter count
beyond the largest ``MD28050`` allows, and machine or setting data of the wrong
type or outside the catalogue's limits.

:class:`Session` ties it together for one data directory and one machine:
NC data, MD/SD store, access control, NC file system; ``save()`` writes the
sections that changed, ``power_on()`` restarts from the files.
"""

from __future__ import annotations

import base64
import copy
import dataclasses
import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping

from nck.access import (
    PASSWORD_LEVELS, AccessControl, AccessDenied, AccessState, Action, default_password_hashes,
)
from nck.archive_writes import md_write_level, write_import
from nck.atomic import atomic_write_bytes, atomic_write_text, backup_path, remove_stale_temp_files
from nck.cli_tools import read_tool_table
from nck.errors import NcAlarmError
from nck.machine import MachineConfig, load_machine
from nck.machine_data import DataError, MachineDataStore, catalog, fill_setting_defaults
from nck.ncdata import NcData, ToolEdge, WorkOffset
from nck.regular_files import check_export_target, plain_directory, read_regular_bytes, set_aside
from nck.resources import data_path
from nck.status import AlarmEntry
from nck.storage import NcFileSystem, StorageError, check_program_size
from nck.sample_programs import sample_filter
from nck.manual_settings import settings_from_plain, settings_to_plain
from nck.workpiece import default_machine_setup, default_part_zero_mcs, setup_from_plain, setup_to_plain
from nck.translations import SOURCE_LANGUAGE, check_language
from nck.writes import DataWriter, WriteRefused

FORMAT = "sinumerik-trainer/retained"
FORMAT_VERSION = 1
ARCHIVE_FORMAT = "sinumerik-trainer/archive"
ARCHIVE_VERSION = 1
CLASS_PACK_CONTENT = "class-pack"
"""The ``content`` of an archive that is a class pack (:mod:`nck.class_pack`); NC data have none."""
RETAINED_DIR = "retained"
NC_DIR = "nc"
ALARM_LOG_LIMIT = 500
WALL_CLOCK_STAMPS = ("came_at", "went_at")
"""Keys of a retained alarm-log entry the HMI fills (date and time of day as ISO text)."""
ALARM_FROM_BACKUP = 4065
ALARM_DEFAULTS_LOADED = 4060
SECTION_LIMIT_BYTES = 32 * 1024 * 1024
"""Largest retained file read (the biggest real one, a full tool list, is a few MB)."""
NESTING_LIMIT = 32
"""Deepest nesting of tables and lists in a retained file (the data need 7 at most)."""
INTEGER_LIMIT = 2**63 - 1
"""Largest integer magnitude in a retained file (the control's data are at most 64 bit)."""
ARCHIVE_LIMIT_BYTES = 256 * 1024 * 1024
"""Largest archive imported (all programs and data of a data directory)."""
"""Largest integer magnitude in a retained file (the control's data are at most 64 bit)."""
SAMPLE_TOOLS = "sample_tools.toml"  # the tools of the training programs (data/)
SAMPLE_TOOLS_BY_KIND = {"lathe": "sample_tools_lathe.toml"}  # machines of another kind than the mill
PRIVATE_SECTIONS = frozenset({"access"})  # password hashes: readable by the owner only


class BadFile(Exception):
    """A retained-data file that cannot be used; ``str()`` says why."""


class ArchiveError(Exception):
    """An archive could not be read or imported; ``str()`` says why (nothing was changed)."""


class ArchiveRefused(ArchiveError):
    """The archive changes data the importer's protection level may not write (nothing was changed);
    ``refusal`` is the keyed access refusal (a panel says it with ``nck.refusals.rejected_by``)."""

    def __init__(self, path: object, refusal: AccessDenied) -> None:
        self.refusal = refusal
        super().__init__(f"{path}: refused: {refusal}")


@dataclass
class RetainedData:
    """Everything retained, in memory."""

    ncdata: NcData = field(default_factory=NcData)
    md_by_machine: dict[str, dict[str, Any]] = field(default_factory=dict)
    # no hashes until loaded (the factory passwords are hashed only for a fresh state)
    access: AccessState = field(default_factory=lambda: AccessState(password_hashes={}))
    alarm_log: list[dict[str, Any]] = field(default_factory=list)
    language: str = SOURCE_LANGUAGE
    """The language of the operator texts (a code of :data:`nck.translations.LANGUAGES`)."""
    theme: str = ""
    """The panel's colour theme by name (the HMI knows the names); "" for its default."""


# ---------------------------------------------------------------- validators
def _number(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"{value!r} is not a number")
    return float(value)


def _check_document(document: Any) -> None:
    """Raise BadFile for nesting deeper than NESTING_LIMIT, non-finite or oversized numbers.

    Walks iteratively, so a deep document cannot exhaust the stack; every later
    reader (loaders, ``json.dumps`` on save) may then recurse safely.
    """
    pending = [(document, 1)]
    while pending:
        value, depth = pending.pop()
        if isinstance(value, (dict, list)):
            if depth > NESTING_LIMIT:
                raise BadFile(f"nested deeper than {NESTING_LIMIT} levels")
            items = value.values() if isinstance(value, dict) else value
            pending.extend((item, depth + 1) for item in items)
        elif isinstance(value, float) and not math.isfinite(value):
            raise BadFile(f"holds the number {value!r}")
        elif isinstance(value, int) and not isinstance(value, bool) and abs(value) > INTEGER_LIMIT:
            raise BadFile("holds an integer beyond 64 bits")


def _integer(value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"{value!r} is not an integer")
    return value


def _mapping(value: Any) -> Mapping[str, Any]:
    if not isinstance(value, dict):
        raise ValueError("a table was expected")
    return value


def _sequence(value: Any) -> list[Any]:
    if not isinstance(value, list):
        raise ValueError("a list was expected")
    return value


def _text(value: Any) -> str:
    if not isinstance(value, str):
        raise ValueError(f"{value!r} is not text")
    return value


def _plain(value: Any) -> Any:
    """Check that a value is plain JSON data (numbers, strings, bools, lists, tables)."""
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    raise ValueError(f"{value!r} cannot be stored")


# ------------------------------------------------------------------ sections
def _dump_offset(offset: WorkOffset) -> dict[str, Any]:
    return {"trans": dict(offset.trans), "fine": dict(offset.fine), "rot": dict(offset.rot),
            "scale": dict(offset.scale), "mirror": dict(offset.mirror)}


def _load_offset(data: Any) -> WorkOffset:
    table = _mapping(data)
    offset = WorkOffset()
    for part in ("trans", "fine", "rot", "scale"):
        setattr(offset, part, {str(k): _number(v) for k, v in _mapping(table.get(part, {})).items()})
    mirror = _mapping(table.get("mirror", {}))
    if not all(isinstance(v, bool) for v in mirror.values()):
        raise ValueError("mirror flags must be true/false")
    offset.mirror = dict(mirror)
    return offset


def _dump_tools(rd: RetainedData) -> dict[str, Any]:
    return {"edges": [
        {"t": t, "d": d, "params": {str(i): v for i, v in sorted(edge.params.items())}}
        for (t, d), edge in sorted(rd.ncdata.tools.items())
    ]}


def _load_tools(data: Mapping[str, Any], rd: RetainedData) -> None:
    tools: dict[tuple[int, int], ToolEdge] = {}
    for entry in data["edges"]:
        entry = _mapping(entry)
        key = (_integer(entry["t"]), _integer(entry["d"]))
        params = {int(i): _number(v) for i, v in _mapping(entry["params"]).items()}
        tools[key] = ToolEdge(params=params)
    rd.ncdata.tools = tools


def _dump_offsets(rd: RetainedData) -> dict[str, Any]:
    return {"settable": {name: _dump_offset(o) for name, o in rd.ncdata.settable_frames.items()},
            "base": _dump_offset(rd.ncdata.base_frame), "setframe": _dump_offset(rd.ncdata.setframe)}


def _load_offsets(data: Mapping[str, Any], rd: RetainedData) -> None:
    settable = {str(name): _load_offset(o) for name, o in _mapping(data["settable"]).items()}
    base = _load_offset(data["base"])
    setframe = _load_offset(data.get("setframe", {}))  # files written before $P_SETFR existed lack it
    rd.ncdata.settable_frames = settable
    rd.ncdata.base_frame = base
    rd.ncdata.setframe = setframe


def _dump_r(rd: RetainedData) -> dict[str, Any]:
    r = rd.ncdata.r
    return {"count": len(r), "values": {str(i): v for i, v in enumerate(r) if v != 0.0}}


def _load_r(data: Mapping[str, Any], rd: RetainedData) -> None:
    count = _integer(data["count"])
    values = {int(i): _number(v) for i, v in _mapping(data["values"]).items()}
    if count < 0 or any(i < 0 for i in values):
        raise ValueError("negative R parameter index")
    limit = catalog().get_md(28050).max
    assert limit is not None, "MD28050 MM_NUM_R_PARAM has an upper limit in the catalogue"
    if count > limit or any(i >= limit for i in values):
        raise ValueError(f"more than {limit:g} R parameters (the most MD28050 allows)")
    r = [0.0] * max(count, max(values, default=-1) + 1)
    for index, value in values.items():
        r[index] = value
    rd.ncdata.r = r


def _dump_gud(rd: RetainedData) -> dict[str, Any]:
    return {"gud": _plain(rd.ncdata.gud), "access": _plain(rd.ncdata.gud_access)}


def _load_gud(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.ncdata.gud = dict(_plain(_mapping(data["gud"])))
    access = _mapping(data.get("access", {}))  # protection levels of APRP/APWP (older files: none)
    rd.ncdata.gud_access = {str(name): {str(k): int(v) for k, v in _mapping(levels).items()}
                            for name, levels in access.items()}


def _dump_sd(rd: RetainedData) -> dict[str, Any]:
    return {"values": _plain(rd.ncdata.setting_data)}


def _load_sd(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.ncdata.setting_data = _checked_catalog_values(data["values"])


def _dump_md(rd: RetainedData) -> dict[str, Any]:
    return {"machines": _plain(rd.md_by_machine)}


def _checked_catalog_values(values: Any) -> dict[str, Any]:
    """Machine or setting data by key, each element of the catalogue's type and within its limits.

    Raises DataValueError (a DataError) for a value the catalogue refuses.
    """
    cat = catalog()
    checked: dict[str, Any] = {}
    for key, value in _mapping(values).items():
        definition = cat.get(key)
        if definition is not None:  # unknown keys (an older catalogue) are kept as they are
            items = value.values() if isinstance(value, dict) else [value]
            for item in items:
                for element in item if isinstance(item, list) else [item]:
                    definition.coerce(element)
        checked[key] = _plain(value)
    return checked


def _load_md(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.md_by_machine = {str(machine): _checked_catalog_values(values)
                        for machine, values in _mapping(data["machines"]).items()}


def _dump_access(rd: RetainedData) -> dict[str, Any]:
    return rd.access.to_json()


def _load_access(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.access = AccessState.from_json(data)


def _dump_counters(rd: RetainedData) -> dict[str, Any]:
    return {"part_counters": dict(rd.ncdata.part_counters)}


def _load_counters(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.ncdata.part_counters = {str(k): _integer(v) for k, v in _mapping(data["part_counters"]).items()}


def _dump_mda(rd: RetainedData) -> dict[str, Any]:
    return {"text": rd.ncdata.mda_program}


def _load_mda(data: Mapping[str, Any], rd: RetainedData) -> None:
    if not isinstance(data["text"], str):
        raise ValueError("the MDA buffer must be text")
    rd.ncdata.mda_program = data["text"]


OVERRIDE_SWITCH_RANGES = {"feed": (0.0, 200.0), "rapid": (0.0, 100.0), "spindle": (0.0, 200.0)}
"""Positions an override switch can stand at, in % (002 L56312-56319)."""


def _dump_panel(rd: RetainedData) -> dict[str, Any]:
    return {"override_switches": dict(rd.ncdata.override_switches)}


def _load_panel(data: Mapping[str, Any], rd: RetainedData) -> None:
    switches = {}
    for name, value in _mapping(data["override_switches"]).items():
        if name not in OVERRIDE_SWITCH_RANGES:
            raise ValueError(f"no override switch {name!r}")
        low, high = OVERRIDE_SWITCH_RANGES[name]
        percent = _number(value)
        if not low <= percent <= high:
            raise ValueError(f"the {name} override switch cannot stand at {percent:g} %")
        switches[name] = percent
    rd.ncdata.override_switches = switches


def _dump_alarm_log(rd: RetainedData) -> dict[str, Any]:
    return {"entries": _plain(rd.alarm_log[-ALARM_LOG_LIMIT:])}


def _load_alarm_log(data: Mapping[str, Any], rd: RetainedData) -> None:
    entries = []
    for entry in data["entries"]:
        entry = dict(_plain(_mapping(entry)))
        alarm_entry_from_dict(entry)  # every field of the right type
        if any(not isinstance(entry.get(name, ""), str) for name in WALL_CLOCK_STAMPS):
            raise ValueError("an alarm's date and time must be text")
        entries.append(entry)
    rd.alarm_log = entries[-ALARM_LOG_LIMIT:]


def _dump_manual_settings(rd: RetainedData) -> dict[str, Any]:
    return settings_to_plain(rd.ncdata.manual_settings)


def _load_manual_settings(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.ncdata.manual_settings = settings_from_plain(data)


def _dump_machine_setup(rd: RetainedData) -> dict[str, Any]:
    return setup_to_plain(rd.ncdata.machine_setup)


def _load_machine_setup(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.ncdata.machine_setup = setup_from_plain(data)


def _dump_display(rd: RetainedData) -> dict[str, Any]:
    return {"language": rd.language, "theme": rd.theme}


THEME_NAME = re.compile(r"[a-z0-9-]{0,40}")
"""What a theme name may look like (the HMI's names: ``sinumerik``, ``operate-light`` …)."""


def check_theme(name: str) -> str:
    """``name`` if it can be a theme's name (ValueError otherwise)."""
    if not THEME_NAME.fullmatch(name):
        raise ValueError(f"{name!r} is not a theme name")
    return name


def _load_display(data: Mapping[str, Any], rd: RetainedData) -> None:
    rd.language = check_language(_text(data["language"]))
    rd.theme = check_theme(_text(data.get("theme", "")))  # files written before the theme was kept


SECTIONS: dict[str, tuple[Callable[[RetainedData], dict], Callable[[Mapping, RetainedData], None]]] = {
    "tools": (_dump_tools, _load_tools),
    "work_offsets": (_dump_offsets, _load_offsets),
    "r_parameters": (_dump_r, _load_r),
    "user_data": (_dump_gud, _load_gud),
    "setting_data": (_dump_sd, _load_sd),
    "machine_data": (_dump_md, _load_md),
    "access": (_dump_access, _load_access),
    "counters": (_dump_counters, _load_counters),
    "mda": (_dump_mda, _load_mda),
    "panel": (_dump_panel, _load_panel),
    "alarm_log": (_dump_alarm_log, _load_alarm_log),
    "machine_setup": (_dump_machine_setup, _load_machine_setup),
    "manual_settings": (_dump_manual_settings, _load_manual_settings),
    "display": (_dump_display, _load_display),
}


def section_text(name: str, rd: RetainedData) -> str:
    """The file content of one section (stable: sorted keys, one item per line)."""
    document = {"format": FORMAT, "section": name, "format_version": FORMAT_VERSION,
                "data": SECTIONS[name][0](rd)}
    return json.dumps(document, indent=1, sort_keys=True, ensure_ascii=False) + "\n"


def read_archive_document(path: Path | str, error: Callable[[str], Exception], noun: str,
                          not_ours: str) -> dict[str, Any]:
    """The archive document in the file ``path`` (an NC data archive or a class pack), its format
    and version checked; otherwise ``error(message)`` is raised, the message naming the file as
    a ``noun`` ("archive", "class pack") or saying ``not_ours`` for a file of another kind."""
    try:
        document = decode_document(read_regular_bytes(path, ARCHIVE_LIMIT_BYTES, follow_links=True))
    except OSError as exc:
        raise error(f"{path}: not a readable {noun} ({exc.strerror or exc})") from exc
    except BadFile as exc:
        raise error(f"{path}: not a readable {noun} ({exc})") from exc
    if not isinstance(document, dict) or document.get("format") != ARCHIVE_FORMAT:
        raise error(f"{path}: {not_ours}")
    if document.get("format_version") != ARCHIVE_VERSION:
        raise error(f"{path}: archive version {document.get('format_version')!r} not supported")
    return document


def decode_document(raw: bytes) -> Any:
    """The JSON document in ``raw``, bounded in depth and numbers; BadFile says why not."""
    try:
        document = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise BadFile("not UTF-8 text") from exc
    except json.JSONDecodeError as exc:
        if not raw.strip():
            raise BadFile("empty file") from exc
        raise BadFile(f"truncated or garbled at byte {exc.pos}") from exc
    except ValueError as exc:  # the parser's own limit on the digits of an integer
        raise BadFile("holds a number with too many digits") from exc
    except RecursionError as exc:
        raise BadFile(f"nested deeper than {NESTING_LIMIT} levels") from exc
    _check_document(document)
    return document


def parse_section(name: str, raw: bytes, rd: RetainedData) -> None:
    """Read one section file's content into ``rd``; raise BadFile when it is unusable."""
    document = decode_document(raw)
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise BadFile("not a retained-data file")
    if document.get("section") != name:
        raise BadFile(f"holds section {document.get('section')!r}, not {name!r}")
    version = document.get("format_version")
    if version != FORMAT_VERSION:
        raise BadFile(f"format version {version!r} is not supported (this program reads {FORMAT_VERSION})")
    # loaders assign new objects (never mutate), so a shallow copy keeps rd untouched on error
    scratch = RetainedData(copy.copy(rd.ncdata), rd.md_by_machine, rd.access, rd.alarm_log, rd.language,
                           rd.theme)
    try:
        SECTIONS[name][1](_mapping(document["data"]), scratch)
    except (KeyError, TypeError, ValueError, AttributeError, DataError) as exc:
        raise BadFile(f"unexpected content ({exc})") from exc
    # apply only after the whole section was read without error
    rd.ncdata = scratch.ncdata
    rd.md_by_machine = scratch.md_by_machine
    rd.access = scratch.access
    rd.alarm_log = scratch.alarm_log
    rd.language = scratch.language
    rd.theme = scratch.theme


def _read_section_file(path: Path) -> bytes:
    """The content of a retained file; BadFile for a link, FIFO, device or an oversized file."""
    try:
        return read_regular_bytes(path, SECTION_LIMIT_BYTES)
    except OSError as exc:
        if isinstance(exc, FileNotFoundError):
            raise
        raise BadFile(exc.strerror or str(exc)) from exc


def load_section(directory: Path, name: str, rd: RetainedData) -> list[NcAlarmError]:
    """Load one section with recovery from its backup; return the alarms to raise."""
    main = directory / f"{name}.json"
    backup = backup_path(main)
    if not os.path.lexists(main) and not os.path.lexists(backup):
        return []
    reason = "file missing"
    if os.path.lexists(main):
        try:
            parse_section(name, _read_section_file(main), rd)
            return []
        except BadFile as exc:
            reason = str(exc)
        kept = set_aside(main).name
    else:
        kept = "-"
    if os.path.lexists(backup):
        try:
            raw = _read_section_file(backup)
            parse_section(name, raw, rd)
            atomic_write_bytes(main, raw, private=name in PRIVATE_SECTIONS)  # the backup becomes the file again
            return [NcAlarmError(ALARM_FROM_BACKUP, main.name, reason, kept)]
        except BadFile:
            set_aside(backup)
    return [NcAlarmError(ALARM_DEFAULTS_LOADED, main.name, reason, kept)]


def alarm_entry_from_dict(data: Mapping[str, Any]) -> AlarmEntry:
    """An alarm-log entry from its retained form (tolerates missing optional keys)."""
    went = data.get("went_s")
    params = data.get("params", ()) or ()
    if not isinstance(params, (list, tuple)):
        raise ValueError("alarm parameters must be a list")
    file, line, n = data.get("file"), data.get("line"), data.get("n")
    if file is not None and not isinstance(file, str):
        raise ValueError("the alarm's file must be text")
    return AlarmEntry(
        seq=_integer(data.get("seq", 0)), number=_integer(data["number"]), text=str(data.get("text", "")),
        category=str(data.get("category", "")), clear=str(data.get("clear", "reset")),
        came_s=_number(data.get("came_s", 0.0)), went_s=None if went is None else _number(went),
        params=tuple(str(p) for p in params), file=file,
        line=None if line is None else _integer(line), n=None if n is None else _integer(n),
    )


# ------------------------------------------------------------------- session
class Session:
    """The retained state of one NC data directory for one machine.

    Use :meth:`open`. Attributes: ``data_dir``, ``machine`` (as in its file),
    ``retained`` (:class:`RetainedData`), ``ncdata`` (shared with the kernel),
    ``md`` (:class:`MachineDataStore`), ``access`` (:class:`AccessControl`),
    ``files`` (:class:`NcFileSystem`), ``startup_alarms`` (alarms to raise after
    start, e.g. 4065 for a file restored from its backup).
    """

    def __init__(self, data_dir: Path, machine: MachineConfig, retained: RetainedData,
                 files: NcFileSystem, startup_alarms: list[NcAlarmError]) -> None:
        self.data_dir = data_dir
        self.machine = machine
        self.retained = retained
        self.files = files
        self.startup_alarms = startup_alarms
        self.md = MachineDataStore(machine, retained.md_by_machine.get(machine.name, {}),
                                   retained.ncdata.setting_data)
        fill_setting_defaults(retained.ncdata.setting_data, machine)
        r_count = int(self.md.active_value("MD28050"))
        r = retained.ncdata.r
        retained.ncdata.r = (r + [0.0] * r_count)[:r_count]
        self.access = AccessControl(retained.access, user_class=self.md.user_class)
        self._written: dict[str, str] = {}

    @property
    def retained_dir(self) -> Path:
        """``<data dir>/retained``."""
        return self.data_dir / RETAINED_DIR

    @property
    def ncdata(self) -> NcData:
        """The NC data (give this object to the kernel; :meth:`save` persists it)."""
        return self.retained.ncdata

    @property
    def language(self) -> str:
        """The language of the operator texts kept in the data directory (``en``, ``de``)."""
        return self.retained.language

    @language.setter
    def language(self, code: str) -> None:
        self.retained.language = check_language(code)

    @property
    def theme(self) -> str:
        """The panel's colour theme kept in the data directory ("" for the default)."""
        return self.retained.theme

    @theme.setter
    def theme(self, name: str) -> None:
        self.retained.theme = check_theme(name)

    @property
    def alarm_log(self) -> list[dict[str, Any]]:
        """The retained alarm log entries (oldest first)."""
        return self.retained.alarm_log

    @classmethod
    def open(cls, data_dir: Path | str, machine: MachineConfig | None = None, *,
             install_samples: bool = True, samples: Path | None = None) -> "Session":
        """Start from the data directory (created when new): load, recover, install samples."""
        data_dir = Path(data_dir)
        data_dir.mkdir(parents=True, exist_ok=True)
        retained_dir = data_dir / RETAINED_DIR
        alarms: list[NcAlarmError] = []
        odd_folders = [(retained_dir, plain_directory(retained_dir))]
        remove_stale_temp_files(retained_dir)
        files = NcFileSystem(data_dir / NC_DIR)
        odd_folders += files.folders_set_aside
        for folder, kept in odd_folders:
            if kept is not None:  # a link, pipe or file in place of a folder: a new empty one is used
                alarms.append(NcAlarmError(
                    ALARM_DEFAULTS_LOADED, folder.relative_to(data_dir).as_posix(),
                    "a link, not a folder" if kept.is_symlink() else "not a folder",
                    kept.relative_to(data_dir).as_posix()))
        fresh_tools = not (retained_dir / "tools.json").exists()
        setup_file = retained_dir / "machine_setup.json"
        fresh_setup = not os.path.lexists(setup_file) and not os.path.lexists(backup_path(setup_file))
        machine = machine or load_machine()
        samples_installed = bool(install_samples and files.install_samples(
            samples if samples is not None else data_path("programs"), wanted=sample_filter(machine.kind)))
        rd = RetainedData()
        damaged: list[str] = []
        for name in SECTIONS:
            found = load_section(retained_dir, name, rd)
            alarms += found
            if any(a.number == ALARM_DEFAULTS_LOADED for a in found):
                damaged.append(name)
        if samples_installed and fresh_tools:  # the training programs come with their tools
            table = data_path(SAMPLE_TOOLS_BY_KIND.get(machine.kind, SAMPLE_TOOLS))
            rd.ncdata.tools = {key: ToolEdge(params=dict(params)) for key, params in read_tool_table(table).items()}
        if fresh_setup:  # a new data directory: the default blank of the machine kind is clamped
            rd.ncdata.machine_setup = default_machine_setup(machine.kind)
            part_zero = default_part_zero_mcs(machine.kind, rd.ncdata.machine_setup)
            if part_zero and rd.ncdata.settable_frame("G54") == WorkOffset():  # a lathe: G54 on the bar's face
                rd.ncdata.settable_frames["G54"] = WorkOffset(trans=part_zero)
        if not rd.access.password_hashes:  # fresh, or the access file was lost
            rd.access.password_hashes = default_password_hashes()
        session = cls(data_dir, machine, rd, files, alarms)
        for name in SECTIONS:
            path = retained_dir / f"{name}.json"
            if name not in damaged and path.exists() and not (
                    name in PRIVATE_SECTIONS and path.stat().st_mode & 0o077):  # else rewritten 0600
                session._written[name] = path.read_text(encoding="utf-8")
        session.save()
        return session

    def save(self) -> list[str]:
        """Write every section whose content changed (atomically, with backup); return them."""
        self.retained.md_by_machine[self.machine.name] = self.md.retained_changes()
        if not self.retained.md_by_machine[self.machine.name]:
            del self.retained.md_by_machine[self.machine.name]
        written = []
        for name in SECTIONS:
            text = section_text(name, self.retained)
            if self._written.get(name) != text:
                atomic_write_text(self.retained_dir / f"{name}.json", text, backup=True,
                                  private=name in PRIVATE_SECTIONS)
                self._written[name] = text
                written.append(name)
        return written

    def record_alarms(self, entries: Iterable[Any]) -> None:
        """Append alarm-log entries (``nck.status.AlarmEntry`` objects or dicts), bounded."""
        for entry in entries:
            if dataclasses.is_dataclass(entry) and not isinstance(entry, type):
                data = dataclasses.asdict(entry)
            else:
                data = dict(entry)
            self.retained.alarm_log.append(_plain({k: v for k, v in data.items()}))
        del self.retained.alarm_log[:-ALARM_LOG_LIMIT]

    def restore_alarm_log(self, nck: Any) -> dict[int, dict[str, Any]]:
        """Give the kernel the retained alarm log (after power on), as entries before its own.

        Retained entries get negative sequence numbers (oldest lowest), so they
        never mix with the ones the kernel numbers from 1 after this power on;
        the diagnosis marks them as coming from before the last power on.
        Returns the wall-clock stamps the HMI kept with them (``came_at``,
        ``went_at``; see :meth:`store_alarm_log`) by the sequence number given.
        """
        self._alarm_base = list(self.retained.alarm_log)
        entries = [alarm_entry_from_dict(data) for data in self._alarm_base]
        count = len(entries)
        nck.load_alarm_history([dataclasses.replace(e, seq=index - count) for index, e in enumerate(entries)])
        return {index - count: {name: data[name] for name in WALL_CLOCK_STAMPS if name in data}
                for index, data in enumerate(self._alarm_base)}

    def store_alarm_log(self, nck: Any, stamps: Mapping[int, Mapping[str, str]] | None = None) -> None:
        """Replace the retained alarm log by the retained part plus this power on's entries (bounded).

        Call before :meth:`save` (on quit; calling it again later is fine). Alarms
        still pending keep ``went_s`` None. ``stamps`` are wall-clock times the caller
        keeps for this power on's entries (the kernel has no clock), by entry ``seq``:
        stored with them as text.
        """
        base = getattr(self, "_alarm_base", None)
        if base is None:
            base = self._alarm_base = list(self.retained.alarm_log)
        self.retained.alarm_log = list(base)
        stamps = stamps or {}
        self.record_alarms({**dataclasses.asdict(e), **stamps.get(e.seq, {})}
                           for e in nck.alarm_history() if e.seq > 0)

    def active_machine(self) -> MachineConfig:
        """The machine with the active MD values (build the kernel from this)."""
        return self.md.active_machine()

    def kernel_arguments(self) -> dict[str, Any]:
        """Keyword arguments for ``nck.build.build_nck`` on this data directory::

            nck = build_nck(**session.kernel_arguments())
            for alarm in session.startup_alarms:
                nck.raise_alarm(alarm)
            ...
            session.save()          # after changes (and on quit)
            session = session.power_on()   # "Reset (po)": build a new kernel from it
        """
        return {"machine": self.active_machine(), "data": self.ncdata,
                "programs": self.files, "access": self.access}

    def power_on(self) -> "Session":
        """Save, then start again from the files: every stored MD becomes active."""
        self.save()
        return Session.open(self.data_dir, self.machine, install_samples=False)

    # ------------------------------------------------------------- archives
    def _archive_workpiece(self, name: str) -> str:
        canonical = self.files.canonical(name)
        if not canonical.startswith("WKS/") or canonical.count("/") != 1:
            raise ArchiveError(f"{name} is not a workpiece")
        return canonical

    def _checked_sections(self, sections: Mapping[str, Any], include_access: bool,
                          level: int) -> dict[str, str]:
        """The file text of every archive section to import, checked as writes at ``level``."""
        scratch = RetainedData(access=self.retained.access, language=self.retained.language,
                               theme=self.retained.theme)
        for name, data in sections.items():
            if name not in SECTIONS:
                raise ArchiveError(f"unknown section {name!r}")
            if name == "access" and not include_access:
                continue
            SECTIONS[name][1](_mapping(data), scratch)
        names = [n for n in SECTIONS if n in sections and (n != "access" or include_access)]
        machine = self.machine.name
        current_md = self.md.retained_changes()
        imported_md = scratch.md_by_machine.get(machine, {}) if "machine_data" in names else current_md
        written, md_changes = write_import(
            self.ncdata, current_md, scratch.ncdata, imported_md, names, self.machine,
            lambda data, store: DataWriter(data, store, self.access, level=level))
        result = RetainedData(written, {**scratch.md_by_machine, machine: md_changes}, scratch.access,
                              scratch.alarm_log, scratch.language, scratch.theme)
        others = set(scratch.md_by_machine) | set(self.retained.md_by_machine) if "machine_data" in names else set()
        for other in others - {machine}:  # the data of other machines: the same levels by datum
            values = scratch.md_by_machine.get(other, {})
            before = self.retained.md_by_machine.get(other, {})
            for key in set(values) | set(before):
                if values.get(key) != before.get(key) and level > md_write_level(key):
                    raise AccessDenied("import_machine_datum", md_write_level(key), level, datum=key, machine=other)
        if ("access" in names and scratch.access.to_json() != self.retained.access.to_json()
                and level > min(PASSWORD_LEVELS)):
            raise AccessDenied("import_passwords", min(PASSWORD_LEVELS), level)
        for name in ("counters", "mda", "panel"):  # kept by the kernel, not protected data
            if name in names:
                SECTIONS[name][1](SECTIONS[name][0](scratch), result)
        if not result.md_by_machine[machine]:
            del result.md_by_machine[machine]
        return {name: section_text(name, result) for name in names}

    def export_archive(self, path: Path | str) -> Path:
        """Write all NC data (retained sections and every program) into one file."""
        self.save()
        programs = []
        for entry in self.files.all_programs():
            raw = self.files.read_bytes(entry.path)
            try:
                programs.append({"path": entry.path, "text": raw.decode("utf-8")})
            except UnicodeDecodeError:
                programs.append({"path": entry.path, "base64": base64.b64encode(raw).decode()})
        archive = {
            "format": ARCHIVE_FORMAT,
            "format_version": ARCHIVE_VERSION,
            "sections": {name: SECTIONS[name][0](self.retained) for name in SECTIONS},
            "workpieces": [e.path for e in self.files.list_directory("WKS")],
            "programs": programs,
        }
        target = Path(path)
        check_export_target(target, replace=True)  # never through a link, FIFO or device
        # the archive holds the password hashes too: readable by its owner only, like access.json
        atomic_write_text(target, json.dumps(archive, indent=1, sort_keys=True) + "\n", private=True)
        return target

    def import_archive(self, path: Path | str, include_access: bool = False,
                       level: int | None = None) -> "Session":
        """Load an archive written by :meth:`export_archive` and restart from it.

        Every section in the archive replaces the retained one (the access
        section — keyswitch and passwords — only with ``include_access``);
        programs are added or overwritten, other programs stay. The import is a
        write like any other (:mod:`nck.archive_writes`): each datum it changes
        needs its protection level — ``level``, else the access control's
        current one —, programs need the level of program editing, the
        passwords level 1; every value is checked like a write. The whole archive
        is checked first: on any problem ArchiveError (ArchiveRefused for a level
        too low) is raised and nothing changes.
        """
        level = self.access.level if level is None else level
        archive = read_archive_document(path, ArchiveError, "archive", "not an NC data archive")
        if archive.get("content") == CLASS_PACK_CONTENT:
            raise ArchiveError(f"{path}: a class pack, not NC data (import it with 'nck class-pack import')")
        try:
            texts = self._checked_sections(_mapping(archive.get("sections", {})), include_access, level)
            workpieces = [w for w in (self._archive_workpiece(_text(w))
                                      for w in _sequence(archive.get("workpieces", [])))
                          if not self.files.exists(w)]
            programs: list[tuple[str, bytes]] = []
            for item in _sequence(archive.get("programs", [])):
                item = _mapping(item)
                canonical = self.files.canonical(_text(item["path"]))
                if "/" not in canonical or canonical.endswith(".WPD"):
                    raise ArchiveError(f"{path}: {canonical} is not a program")
                raw = (_text(item["text"]).encode("utf-8") if "text" in item
                       else base64.b64decode(_text(item["base64"]), validate=True))
                check_program_size(canonical, raw)
                if self.files.exists(canonical):
                    if self.files.read_bytes(canonical) == raw:
                        continue  # the same program: nothing to write
                    if self.files.is_in_use(canonical):
                        raise ArchiveError(f"{canonical} is in use and cannot be replaced")
                programs.append((canonical, raw))
            if programs or workpieces:
                needed = self.access.required(Action.EDIT_PROGRAM)
                if level > needed:
                    raise AccessDenied("import_programs", needed, level)
        except ArchiveError:
            raise
        except AccessDenied as exc:
            raise ArchiveRefused(path, exc) from None
        except (StorageError, KeyError, TypeError, ValueError, DataError, WriteRefused) as exc:
            raise ArchiveError(f"{path}: bad content ({exc})") from exc
        try:
            for name, text in texts.items():
                atomic_write_text(self.retained_dir / f"{name}.json", text, backup=True,
                                  private=name in PRIVATE_SECTIONS)
            for workpiece in workpieces:
                self.files.create_workpiece(workpiece.split("/")[1], with_program=False)
            for canonical, raw in programs:
                parent = canonical.rpartition("/")[0]
                if parent.startswith("WKS/") and not self.files.exists(parent):
                    self.files.create_workpiece(parent.split("/")[1], with_program=False)
                self.files.save_bytes(canonical, raw)
        except (OSError, StorageError) as exc:
            raise ArchiveError(f"{path}: could not be written completely ({exc})") from exc
        return Session.open(self.data_dir, self.machine, install_samples=False)
