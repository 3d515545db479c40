"""Building a kernel on the retained data of an NC data directory: the HMI's composition root.

:func:`open_data_session` opens the directory (or a temporary copy of it), takes its lock
and loads the retained data (:class:`nck.persistence.Session`); :func:`build_session_kernel`
wires a kernel on that data: the session's machine with its active machine data, NC data,
file system and access control, the machine-data store, the "program in use" rule of the
file system, the power-on alarms, the retained alarm log and what the kernel keeps itself
(part counters, MDA buffer, override switches). The HMI builds every kernel it runs on,
also after "Reset (po)", here; the kernel's own parts are wired in ``Nck.__init__``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from nck import commands as cmd
from nck.datalock import lock_data_dir
from nck.kernel import Nck
from nck.machine import load_machine
from nck.paths import open_data_dir
from nck.persistence import Session

PART_COUNTERS = ("TOTAL_PARTS", "REQUIRED_PARTS", "ACTUAL_PARTS", "SPECIAL_PARTS")
"""Workpiece counters ``$AC_…`` that are retained (REQUIRED first: it bounds nothing but is set before ACTUAL)."""


@dataclass(frozen=True)
class OpenedData:
    """An opened NC data directory: its retained data, the temporary copy to remove on quit
    (``--ephemeral``, else ``None``) and the directory's lock (``None`` for a copy)."""

    session: Any
    copy: Any
    lock: Any


@dataclass(frozen=True)
class SessionKernel:
    """A kernel built on a session and the wall-clock stamps the HMI kept with its retained
    alarm log, by entry sequence number (see ``Session.restore_alarm_log``)."""

    nck: Nck
    alarm_stamps: dict[int, dict[str, Any]] | None


def open_data_session(machine: str | None = None, data_dir: str | None = None,
                      ephemeral: bool = False) -> OpenedData:
    """Open the NC data directory ``data_dir`` (a temporary copy with ``ephemeral``) for
    the machine ``machine`` (name or file, ``None``: the default) and load its retained data.

    One process per data directory: a directory locked by another HMI or ``nck`` command
    raises ``nck.datalock.DataDirInUse``. A failed start leaves neither a lock nor a copy.
    """
    config = load_machine(machine)
    root, copy = open_data_dir(data_dir, ephemeral)
    lock = None
    try:
        lock = lock_data_dir(root) if copy is None else None
        return OpenedData(Session.open(root, config), copy, lock)
    except BaseException:
        if lock is not None:
            lock.release()
        if copy is not None:
            copy.cleanup()
        raise


def build_session_kernel(session: Any) -> SessionKernel:
    """The kernel on ``session``'s retained data (see the module docstring)."""
    nck = Nck(**session.kernel_arguments())
    nck.md_store = session.md
    session.files.in_use_check = lambda: programs_in_execution(nck.status())
    for alarm in session.startup_alarms:
        nck.raise_alarm(alarm)
    restore = getattr(session, "restore_alarm_log", None)
    stamps = restore(nck) if callable(restore) else None
    data = session.ncdata
    for key in PART_COUNTERS:  # the kernel keeps them itself: hand it the retained values
        if key in data.part_counters:
            nck.submit(cmd.WriteData(f"$AC_{key}", int(data.part_counters[key])))
    if data.mda_program:
        nck.submit(cmd.SetMdaProgram(data.mda_program))
    for switch, percent in data.override_switches.items():  # a switch stays where it was turned
        nck.submit(cmd.SetOverride(switch, percent))
    return SessionKernel(nck, stamps)


def programs_in_execution(status: Any) -> list[str]:
    """The programs that may not be edited, renamed or deleted: the one being executed.

    A program that is only selected (channel in reset, program aborted) stays editable, as on
    the control; once started it is in use until RESET or program end.
    """
    channel = status.channel
    if channel.selected_program and channel.program_state != "aborted":
        return [channel.selected_program]
    return []
