"""Shared set-up for kernel tests: an Nck on the default mill with the fake interpreter."""

from __future__ import annotations

from nck import commands as c
from nck.kernel import Nck
from nck.machine import MachineConfig, load_machine
from nck.motion.instant import instant_motion_factory
from tests.kernel.fakes import MemoryPrograms, fake_factory


def make_nck(programs: dict[str, str] | None = None, referenced: bool = True,
             machine: MachineConfig | None = None, **kwargs) -> Nck:
    """An Nck with the fake interpreter, the instant motion stand-in (exact times and
    positions) and an in-memory program store."""
    kwargs.setdefault("motion_factory", instant_motion_factory)
    kwargs.setdefault("batch_cycles", 1)  # exact cycle-by-cycle timing
    return Nck(machine=machine or load_machine(), programs=MemoryPrograms(programs),
               referenced=referenced, interpreter_factory=fake_factory, **kwargs)


def states(nck: Nck) -> tuple[str, str, str]:
    """(mode, channel status, program status)."""
    s = nck.situation
    return s.mode, s.channel, s.program


def auto_start(nck: Nck, program: str) -> None:
    """AUTO, select ``program``, NC START; each must be accepted."""
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram(program)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()


def x(nck: Nck) -> float:
    """Displayed X (MCS)."""
    return nck.positions_mcs()["X"]


def alarm_numbers(nck: Nck) -> list[int]:
    """Numbers of the pending alarms."""
    return [a.number for a in nck.status().alarms]


def until_state(nck: Nck, channel: str, program: str, max_s: float = 60.0) -> bool:
    """Tick until the channel/program status is reached."""
    return nck.run_until(lambda k: (k.situation.channel, k.situation.program) == (channel, program), max_s)
