"""Building the kernel the HMI runs on: machine, NC data directory, retained data, samples.

:class:`NcDataSession` ties the HMI to the retained data of the NC data
directory (:class:`nck.persistence.Session`): the kernel is built on the
session's NC data, machine-data store and access control, so tools, offsets,
R parameters, GUD, setting and machine data, passwords and the keyswitch that
the operator changes survive a restart. ``save()`` writes what changed (the
app calls it after data commands, on a timer and on quit); ``power_on()`` is
"Reset (po)": save, reload from the files (every stored MD becomes active)
and build a new kernel.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from nck import AccessDenied, Action, build_session_kernel, open_data_session
from nck import commands as cmd
from nck.commands import Rejected

from hmi.alarm_times import AlarmTimes


class NcDataSession:
    """The retained NC data of one data directory and the kernel built on it."""

    def __init__(self, session: Any, copy: Any = None) -> None:
        self.session = session
        self._copy = copy
        self.alarm_times = AlarmTimes()
        """Date and time of the alarm log's entries (the bridge stamps them; retained with the log)."""
        self.nck = self._build_kernel()

    def _build_kernel(self) -> Any:
        built = build_session_kernel(self.session)
        if built.alarm_stamps is not None:
            self.alarm_times.restart(built.alarm_stamps)
        return built.nck

    def _collect(self) -> None:
        """Copy what the kernel keeps itself (part counters, MDA buffer, override switches) into the NC data."""
        channel = self.nck.status().channel
        data = self.session.ncdata
        data.part_counters = {
            "TOTAL_PARTS": int(channel.parts_total), "REQUIRED_PARTS": int(channel.parts_required),
            "ACTUAL_PARTS": int(channel.part_count), "SPECIAL_PARTS": int(channel.parts_special),
        }
        data.mda_program = channel.mda_text
        data.override_switches = {switch: float(percent) for switch, percent in channel.overrides.items()}

    @property
    def language(self) -> str:
        """The language of the operator texts kept in the data directory (``en``, ``de``)."""
        return str(self.session.language)

    @language.setter
    def language(self, code: str) -> None:
        self.session.language = code

    @property
    def theme(self) -> str:
        """The colour theme kept in the data directory ("" for the default)."""
        return str(self.session.theme)

    @theme.setter
    def theme(self, name: str) -> None:
        self.session.theme = name

    def save(self) -> list[str]:
        """Write the retained sections that changed (alarm log included); return their names."""
        if self._copy is not None and getattr(self._copy, "discarded", False):
            return []
        self._collect()
        store = getattr(self.session, "store_alarm_log", None)
        if callable(store):
            store(self.nck, self.alarm_times.retained())
        return self.session.save()

    def power_on(self) -> Any:
        """Reset (po): save, start again from the files, return the new kernel."""
        self.save()
        self.session = self.session.power_on()
        self.nck = self._build_kernel()
        return self.nck

    def quit(self) -> None:
        """Save, then remove an ephemeral copy."""
        try:
            self.save()
        finally:
            if self._copy is not None:
                self._copy.cleanup()
            self.release_lock()

    def release_lock(self) -> None:
        """Give the NC data directory free for another HMI (see :mod:`nck.datalock`)."""
        lock = getattr(self, "data_lock", None)
        if lock is not None:
            lock.release()


def build_session(machine: str | None = None, data_dir: str | None = None, ephemeral: bool = False,
                  program: str | None = None, confirm: Callable[[str], bool] | None = None) -> NcDataSession:
    """Open the NC data directory and build the kernel on its retained data.

    The NC file system (``nck.storage``) lives in ``<data dir>/nc``; the training
    programs of ``data/programs`` are installed into a fresh directory. With
    ``ephemeral`` the kernel works on a temporary copy that is deleted on quit.
    ``program`` (a local file, imported into MPF, or a program name) is selected
    at start; the HMI still starts in JOG (axes must be referenced first). A local
    file that would replace a different program of the same name needs the level
    of program editing and ``confirm(question)`` (None: refused); the old program
    is kept as ``<name>_OLD<n>``.
    """
    opened = open_data_session(machine, data_dir, ephemeral)
    try:
        holder = NcDataSession(opened.session, opened.copy)
        holder.data_lock = opened.lock
        _select_at_start(holder, program, confirm)
    except BaseException:  # a failed start leaves neither a lock nor a temporary copy
        if opened.lock is not None:
            opened.lock.release()
        if opened.copy is not None:
            opened.copy.cleanup()
        raise
    return holder


def _select_at_start(holder: NcDataSession, program: str | None,
                     confirm: Callable[[str], bool] | None = None) -> None:
    """Select ``program`` (a local file is imported first) for the start in AUTOMATIC."""
    if program:
        name = program
        local = Path(program)
        if local.is_file():
            name = _import_at_start(holder, local, confirm)
        result = holder.nck.submit(cmd.SelectProgram(name))
        if isinstance(result, Rejected):
            raise ValueError(f"program {program}: {result.reason}")


def _import_at_start(holder: NcDataSession, local: Path, confirm: Callable[[str], bool] | None) -> str:
    """Import a local file for ``--program``; never replace another program unasked or unkept."""
    files = holder.session.files
    target = files.import_target(local)
    if files.exists(target):
        if files.read_bytes(target) == local.read_bytes():
            return target.rpartition("/")[2]  # the same program: nothing to write
        access = holder.session.access
        if not access.may(Action.EDIT_PROGRAM):
            raise ValueError(f"program {local}: {target} already exists in the NC memory with another "
                             f"text; {AccessDenied('program_replace', access.required(Action.EDIT_PROGRAM), access.level)}")
        if confirm is None or not confirm(f"{target} already exists in the NC memory with another text. "
                                          "Replace it (the old one is kept as a copy)?"):
            raise ValueError(f"program {local}: {target} already exists in the NC memory; not replaced")
        files.keep_backup(target)
    return files.import_file(local, overwrite=True).name


def start_session(machine: str | None = None, data_dir: str | None = None, ephemeral: bool = False,
                  program: str | None = None, confirm: Callable[[str], bool] | None = None,
                  ) -> tuple[NcDataSession, Any]:
    """Open the NC data directory (:func:`build_session`); return the session and its kernel for the bridge."""
    session = build_session(machine, data_dir, ephemeral, program, confirm)
    return session, session.nck
