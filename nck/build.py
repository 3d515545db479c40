"""Building a kernel: the one composition root of the HMI, the command line and headless runs.

:func:`build_nck` wires a kernel from a machine, its NC data, a program source and an access
control, with the interpreters of one language dialect; every client builds its kernel there
(the HMI through :func:`build_session_kernel`, ``nck run`` / ``nck grade`` and the simulation
through :func:`nck.headless.run_on_kernel`, the benchmarks directly). ``Nck(...)`` alone
is a bare kernel for unit tests (Siemens dialect, no protection).

:func:`open_data_session` opens an NC data directory (or a temporary copy of it), takes its
lock and loads the retained data (:class:`nck.persistence.Session`); :func:`build_session_kernel`
wires a kernel on that data: the session's machine with its active machine data, NC data,
file system and access control, the machine-data store, the "program in use" rule of the
file system, the power-on alarms, the retained alarm log and what the kernel keeps itself
(part counters, MDA buffer, override switches). The HMI builds every kernel it runs on,
also after "Reset (po)", here.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from nck import commands as cmd
from nck.access import AccessControl
from nck.datalock import lock_data_dir
from nck.interp.api import ProgramSource
from nck.interp.interpreter import Interpreter
from nck.iso.dialect import dialect_for
from nck.kernel import Nck
from nck.machine import MachineConfig, load_machine
from nck.ncdata import NcData
from nck.paths import open_data_dir

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


def build_nck(
    machine: MachineConfig,
    data: NcData,
    programs: ProgramSource,
    *,
    access: AccessControl | None = None,
    dialect: str | None = None,
    referenced: bool = False,
    motion_factory: Callable[[MachineConfig], Any] | None = None,
    on_interpreter: Callable[[Interpreter], None] | None = None,
) -> Nck:
    """The kernel on ``machine`` with the NC data ``data``, the programs of ``programs`` and
    the protection of ``access`` (None: unprotected), interpreting the language ``dialect``
    (``siemens``, ``iso-m``, ``iso-t``; None: the machine data's mode after power on and RESET).

    ``referenced``: every axis is referenced at power on (headless runs); otherwise only
    those with an adjusted absolute encoder (MD34210). ``motion_factory``: the motion system
    (default: the planned one). ``on_interpreter`` sees every interpreter the kernel creates.
    """

    def interpreter_factory(config: MachineConfig, source: ProgramSource, nc_data: NcData) -> Interpreter:
        interp = Interpreter(config, source, nc_data, dialect=dialect_for(dialect, config))
        if on_interpreter is not None:
            on_interpreter(interp)
        return interp

    return Nck(machine, data, programs, motion_factory=motion_factory, referenced=referenced,
               interpreter_factory=interpreter_factory, access=access)


def open_data_session(machine: str | None = None, data_dir: str | None = None,
                      ephemeral: bool = False) -> OpenedData:
    """Open the NC data directory ``data_dir`` (a temporary copy with ``ephemeral``) for
    the machine ``machine`` (name or file, ``None``: the default) and load its retained data.

    One process per data directory: a directory locked by another HMI or ``nck`` command
    raises ``nck.datalock.DataDirInUse``. A failed start leaves neither a lock nor a copy.
    """
    from nck.persistence import Session  # here: `nck run` without a data directory never loads one

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
    nck = build_nck(**session.kernel_arguments())
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
