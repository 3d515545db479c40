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

from nck import commands as cmd
from nck.commands import Rejected

from hmi.alarm_times import AlarmTimes


PART_COUNTERS = ("TOTAL_PARTS", "REQUIRED_PARTS", "ACTUAL_PARTS", "SPECIAL_PARTS")
"""Workpiece counters ``$AC_…`` that are retained (REQUIRED first: it bounds nothing but is set before ACTUAL)."""


class NcDataSession:
    """The retained NC data of one data directory and the kernel built on it."""

    def __init__(self, session: Any, copy: Any = None) -> None:
        self.session = session
        self._copy = copy
        self.alarm_times = AlarmTimes()
        """Date and time of the alarm log's entries (the bridge stamps them; retained with the log)."""
        self.nck = self._build_kernel()

    def _build_kernel(self) -> Any:
        from nck.kernel import Nck

        nck = Nck(**self.session.kernel_arguments())
        nck.md_store = self.session.md
        files = self.session.files
        files.in_use_check = lambda: programs_in_execution(nck.status())
        for alarm in self.session.startup_alarms:
            nck.raise_alarm(alarm)
        restore = getattr(self.session, "restore_alarm_log", None)
        if callable(restore):
            self.alarm_times.restart(restore(nck))
        data = self.session.ncdata
        for key in PART_COUNTERS:  # the kernel keeps them itself: hand it the retained values
            if key in data.part_counters:
                nck.submit(cmd.WriteData(f"$AC_{key}", int(data.part_counters[key])))
        if data.mda_program:
            nck.submit(cmd.SetMdaProgram(data.mda_program))
        for switch, percent in data.override_switches.items():  # a switch stays where it was turned
            nck.submit(cmd.SetOverride(switch, percent))
        return nck

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
    from nck.machine import load_machine
    from nck.datalock import lock_data_dir
    from nck.paths import open_data_dir
    from nck.persistence import Session

    config = load_machine(machine)
    root, copy = open_data_dir(data_dir, ephemeral)
    lock = None
    try:
        # One process per data directory: a second HMI gets a clear message (DataDirInUse), not torn data.
        lock = lock_data_dir(root) if copy is None else None
        holder = NcDataSession(Session.open(root, config), copy)
        holder.data_lock = lock
        _select_at_start(holder, program, confirm)
    except BaseException:  # a failed start leaves neither a lock nor a temporary copy
        if lock is not None:
            lock.release()
        if copy is not None:
            copy.cleanup()
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
    from nck.access import AccessDenied, Action

    files = holder.session.files
    target = files.import_target(local)
    if files.exists(target):
        if files.read_bytes(target) == local.read_bytes():
            return target.rpartition("/")[2]  # the same program: nothing to write
        access = holder.session.access
        if not access.may(Action.EDIT_PROGRAM):
            raise ValueError(f"program {local}: {target} already exists in the NC memory with another "
                             f"text; {AccessDenied('replacing it', access.required(Action.EDIT_PROGRAM), access.level)}")
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


def programs_in_execution(status: Any) -> list[str]:
    """The programs that may not be edited, renamed or deleted: the one being executed.

    A program that is only selected (channel in reset, program aborted) stays editable, as on
    the control; once started it is in use until RESET or program end.
    """
    channel = status.channel
    if channel.selected_program and channel.program_state != "aborted":
        return [channel.selected_program]
    return []
