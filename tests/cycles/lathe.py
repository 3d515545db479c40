"""Run a short Siemens-mode program on the lathe (lathe2: X a diameter under DIAMON, Z) and
read off the motion of the turning cycles."""

from __future__ import annotations

from nck import canon
from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from tests.cycles.helpers import Cycled

# 1000 rpm at a constant speed, feeds per revolution: F0.3 is 300 mm/min
PROLOGUE = "G18 G90 DIAMON G95 S1000 M4 F0.2\nG0 X70 Z5\n"


class Turned(Cycled):
    """Steps as ("G0", x_diameter, z), ("G1", x, z, feed_mm_min), ("G2"/"G3", x, z, feed),
    ("DWELL", s), ("G33", x, z, lead, start angle); the prologue is left out."""

    def steps(self) -> list[tuple]:  # type: ignore[override]
        out: list[tuple] = []
        for command in self.result.commands:
            if command.source.file == "main.mpf" and command.source.line <= 2:
                continue
            if isinstance(command, canon.Motion):
                x, z = round(command.end_wcs["X"], 4), round(command.end_wcs["Z"], 4)
                if command.kind == "G0":
                    out.append(("G0", x, z))
                elif command.lead_mm is not None:
                    out.append((command.kind, x, z, round(command.lead_mm, 4), command.thread_start_deg))
                else:
                    out.append((command.kind, x, z, round(command.feed_mm_min or 0.0, 4)))
            elif isinstance(command, canon.Dwell) and command.seconds:
                out.append(("DWELL", command.seconds))
        return out


def run_lathe(body: str, files: dict[str, str] | None = None, prologue: str = PROLOGUE,
              tools: dict[tuple[int, int], dict[int, float]] | None = None) -> Turned:
    """Run ``prologue + body + M30`` on the lathe with the subprograms ``files`` and the tool
    edges ``tools`` ({(t, d): {$TC_DP number: value}})."""
    text = prologue + body.strip() + "\nM30\n"
    programs = {"main.mpf": text, **(files or {})}
    data = NcData()
    data.tools = {key: ToolEdge(params=dict(params)) for key, params in (tools or {}).items()}
    result = interpret_only(load_machine("lathe2"), MemorySource(programs), data, "main.mpf",
                            text=text, max_blocks=50_000)
    return Turned(result)
