"""Fixtures of the diagnostics tests: a real kernel with the real motion system.

X has its software limit switch at +5 mm (MD36110) so that JOG and AUTO reach it
quickly; ``LIMIT.MPF`` drives X past it, ``FEED.MPF`` moves X at F1000.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from nck.kernel import Nck
from nck.machine import MachineConfig, load_machine
from nck.motion.system import planned_motion_factory
from nck.persistence import Session

from hmi.app import HmiApp

SIZE = (160, 48)
PROGRAMS = {
    "LIMIT.MPF": "N10 G90 G1 X20 F1000\nN20 M30\n",
    "FEED.MPF": "N10 G90 G0 X-100\nN20 G1 X-20 F1000\nN30 M30\n",
    "MSG.MPF": 'N10 MSG("Clamp the part, then NC START")\nN20 M0\nN30 MSG()\nN40 SETAL(61000)\nN50 M30\n',
    "TRACE.MPF": "N10 G90 G0 X-50 Y-20\nN20 G1 X-10 Y-5 F2000\nN30 G1 X-30 F800\nN40 M30\n",
}


def with_md(base: MachineConfig, **overrides: dict[str, Any]) -> MachineConfig:
    """``base`` with per-axis machine data merged in (``MD36110={"X": 5.0}``)."""
    md = dict(base.md)
    for key, value in overrides.items():
        md[key] = {**dict(md.get(key, {})), **value}
    return replace(base, md=md)


def limit_machine(base: MachineConfig | None = None) -> MachineConfig:
    """The mill with X's plus software limit at 5 mm."""
    return with_md(base or load_machine(), MD36110={"X": 5.0})


def kv1_machine() -> MachineConfig:
    """The mill with Kv = 1 (m/min)/mm and no feedforward on X and Y."""
    return with_md(load_machine(), MD32200={"X": 1.0, "Y": 1.0}, MD32620={"X": 0, "Y": 0})


class Programs:
    """An in-memory program source."""

    def read_program(self, name: str) -> tuple[str, str] | None:
        text = PROGRAMS.get(name)
        return (name, text) if text is not None else None


def kernel(machine: MachineConfig | None = None) -> Nck:
    """A referenced kernel with the real motion system."""
    return Nck(machine=machine or limit_machine(), programs=Programs(), referenced=True,
               motion_factory=planned_motion_factory)


def app_on(nck: Nck) -> HmiApp:
    """The HMI on ``nck`` without the wall-clock timer."""
    return HmiApp(nck, realtime=False)


def power_on(data_dir: Path) -> tuple[Session, Nck]:
    """Start the control on ``data_dir``: retained data, alarm log restored."""
    session = Session.open(data_dir)
    args = session.kernel_arguments()
    args["machine"] = limit_machine(args["machine"])
    args["programs"] = Programs()
    nck = Nck(**args, referenced=True, motion_factory=planned_motion_factory)
    session.restore_alarm_log(nck)
    return session, nck


def power_off(session: Session, nck: Nck) -> None:
    """Quit: the alarm log and the retained data written to the data directory."""
    session.store_alarm_log(nck)
    session.save()
