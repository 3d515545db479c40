"""Run a short program through the interpreter and read off what the standard cycles did."""

from __future__ import annotations

from dataclasses import dataclass

from nck import canon
from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge

PROLOGUE = "G17 G90 G0 X0 Y0 Z50 F100 S1000 M3\n"  # feed 100 mm/min, 1000 rpm right


@dataclass
class Cycled:
    """The outcome of a program: status, alarms and the canonical commands in order."""

    result: HeadlessRun

    @property
    def alarms(self) -> list[int]:
        return [a.number for a in self.result.alarms]

    def ended(self) -> "Cycled":
        assert self.result.status == "ended", self.result.alarms
        return self

    def steps(self) -> list[tuple]:
        """Each command after the prologue line as a short tuple: ("G0", x, y, z),
        ("G1", x, y, z, feed), ("G331", x, y, z, lead), ("DWELL", s), ("SPOS", deg),
        ("M3"/"M4"/"M5",), ("S", rpm), ("M0",)."""
        out: list[tuple] = []
        for command in self.result.commands:
            if command.source.file == "main.mpf" and command.source.line == 1:
                continue
            if isinstance(command, canon.Motion):
                end = command.end_wcs
                x, y, z = (round(end[a], 4) for a in "XYZ")
                if command.kind == "G0":
                    out.append(("G0", x, y, z))
                elif command.lead_mm is not None:
                    out.append((command.kind, x, y, z, round(command.lead_mm, 4)))
                else:
                    out.append((command.kind, x, y, z, round(command.feed_mm_min or 0.0, 4)))
            elif isinstance(command, canon.Dwell) and command.seconds:
                out.append(("DWELL", command.seconds))
            elif isinstance(command, canon.SpindleCommand):
                if command.state == "SPOS":
                    out.append(("SPOS", command.position_deg))
                elif command.state is not None:
                    out.append((command.state,))
                elif command.speed_rpm is not None:
                    out.append(("S", command.speed_rpm))
            elif isinstance(command, canon.StopPoint) and command.kind in ("M0", "M1"):
                out.append((command.kind,))
        return out


def run(body: str, prologue: str = PROLOGUE) -> Cycled:
    """Run ``prologue + body + M30`` (the cycles come from data/cycles)."""
    text = prologue + body.strip() + "\nM30\n"
    result = interpret_only(load_machine(None), MemorySource({"main.mpf": text}), NcData(), "main.mpf",
                            text=text, max_blocks=20_000)
    return Cycled(result)


TOOL = "T1 M6 D1\n"  # end mill T1 D1 of radius 5 mm ($TC_DP6), see run_with_tool


def run_with_tool(body: str, tool: str = TOOL) -> Cycled:
    """Run ``prologue + tool + body + M30`` with the tool T1 D1: length 50 mm, radius 5 mm."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 50.0, 6: 5.0})
    text = PROLOGUE + tool + body + "\nM30\n"
    return Cycled(interpret_only(load_machine(None), MemorySource({"main.mpf": text}), data, "main.mpf",
                                 text=text, max_blocks=20_000))


def tool_path(case: Cycled) -> list[tuple]:
    """The motions after the prologue's G0: (kind, x, y, z) and, for arcs, the centre (x, y)
    as a fifth item; rounded to 0.001 mm."""
    out = []
    for m in case.result.segments[1:]:
        end = tuple(round(m.end_wcs[a], 3) for a in "XYZ")
        centre = tuple(round(m.center_wcs[a], 3) for a in "XY") if m.center_wcs else None
        out.append((m.kind, *end, centre) if centre else (m.kind, *end))
    return out
