"""Run program text through the interpreter and collect what the geometry produced."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import pytest

from nck import canon
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge, WorkOffset


@dataclass
class Run:
    """The commands of a run, the interpreter (for its modal state) and the motions by block."""

    interp: Interpreter
    commands: list[canon.CanonCommand] = field(default_factory=list)

    @property
    def motions(self) -> list[canon.Motion]:
        return [c for c in self.commands if isinstance(c, canon.Motion)]

    def block(self, n: int) -> list[canon.Motion]:
        """The motions caused by block N<n> (inserted segments included)."""
        return [m for m in self.motions if m.source.n == n]

    def end_mcs(self, n: int) -> dict[str, float]:
        return dict(self.block(n)[-1].end_mcs)

    def end_wcs(self, n: int) -> dict[str, float]:
        return dict(self.block(n)[-1].end_wcs)


def run(text: str, data: NcData | None = None, machine: str = "mill3",
        md: dict[str, object] | None = None) -> Run:
    """Interpret ``text`` to the end (alarms propagate); ``md`` overrides machine data."""
    config = load_machine(machine)
    if md:
        config = dataclasses.replace(config, md={**config.md, **md})
    interp = Interpreter(config, MemorySource({}), data or NcData())
    interp.start_text("TEST.MPF", text)
    result = Run(interp)
    while not interp.finished:
        result.commands.extend(interp.step().commands)
    return result


def lines(*blocks: str) -> str:
    return "\n".join(blocks) + "\n"


def approx(values: dict[str, float], tol: float = 1e-6) -> object:
    return pytest.approx(values, abs=tol)


def mill_data(g54: dict[str, float] | None = None, length_mm: float = 100.0) -> NcData:
    """NC data with G54 translations and tool T1 D1: end mill (type 120), L1 = ``length_mm``."""
    data = NcData()
    data.settable_frames["G54"] = WorkOffset(trans=dict(g54 or {}))
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: length_mm, 6: 5.0})
    return data
