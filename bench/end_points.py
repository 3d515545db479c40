"""Block end points of a corpus program, from ``nck`` (in process) and from ``rs274 -g``.

Both lists are (X, Y, Z) in mm in the work coordinate system, X as a radius on the lathe,
with consecutive repeats dropped (a drilling cycle or a tool change may move to where the
axes already stand in one interpreter and not in the other).
"""

from __future__ import annotations

import os
import re
import subprocess
import tempfile
from pathlib import Path

from bench.corpus import RS274_TOOL_TABLE, CorpusProgram
from nck import canon
from nck.headless import interpret_only
from nck.machine import load_machine
from nck.cli_tools import read_tool_table
from nck.interp.sources import DirectorySource
from nck.ncdata import NcData, ToolEdge

Point = tuple[float, float, float]

_CALL = re.compile(r"\b(STRAIGHT_FEED|STRAIGHT_TRAVERSE|ARC_FEED|SELECT_PLANE)\((.*)\)")


def _dedupe(points: list[Point], digits: int = 3) -> list[Point]:
    out: list[Point] = []
    for point in points:
        rounded = tuple(round(v, digits) + 0.0 for v in point)
        if not out or rounded != out[-1]:
            out.append(rounded)  # type: ignore[arg-type]
    return out


def nck_end_points(program: CorpusProgram, max_blocks: int = 1_000_000) -> list[Point]:
    """End points of every motion ``nck`` interprets in the SINUMERIK spelling (alarms raise)."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for name, text in program.subprograms.items():
            (folder / name).write_text(text)
        tools_file = folder / "tools.toml"
        tools_file.write_text(program.tools_toml)
        data = NcData()
        for key, params in read_tool_table(tools_file).items():
            data.tools[key] = ToolEdge(dict(params))
        motions: list[canon.Motion] = []

        def keep_motion(command: canon.CanonCommand) -> None:
            if isinstance(command, canon.Motion):
                motions.append(command)

        result = interpret_only(load_machine(program.machine), DirectorySource(folder), data,
                                f"{program.name}.MPF", text=program.siemens, max_blocks=max_blocks,
                                on_command=keep_motion, keep_commands=False)
    if result.alarms or result.status != "ended":
        raise AssertionError(f"nck: {program.name} alarms {result.alarms}, status {result.status}")
    lathe = program.machine == "lathe2"
    points = []
    for motion in motions:
        end = motion.end_wcs
        x = end.get("X", 0.0)
        points.append((x / 2.0 if lathe else x, end.get("Y", 0.0), end.get("Z", 0.0)))
    return _dedupe(points)


def rs274_end_points(program: CorpusProgram, rs274: str = "rs274") -> list[Point]:
    """End points of every motion ``rs274 -g`` prints for the LinuxCNC spelling."""
    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / f"{program.name}.ngc"
        source.write_text(program.linuxcnc)
        output = Path(tmp) / "canon.txt"
        table = Path(tmp) / "rs274.tbl"
        table.write_text(RS274_TOOL_TABLE)
        # rs274 keeps its tool table in $HOME/.tool.mmap, truncated by every start: a private
        # HOME keeps runs at the same time (tests, benchmarks) from reading each other's table.
        done = subprocess.run([rs274, "-t", str(table), "-g", str(source), str(output)], cwd=tmp,
                              env=dict(os.environ, HOME=tmp), stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=300)
        text = output.read_text() if output.exists() else ""
    if done.returncode != 0:
        raise AssertionError(f"rs274 exited {done.returncode}: {done.stdout[-300:]} {done.stderr[-300:]} "
                             f"{text[-300:]}")
    plane = "XY"
    points: list[Point] = []
    for name, arguments in _CALL.findall(text):
        words = [w.strip() for w in arguments.split(",")]
        if name == "SELECT_PLANE":
            plane = words[0].rsplit("_", 1)[-1]
            continue
        if name != "ARC_FEED":
            points.append((float(words[0]), float(words[1]), float(words[2])))
            continue
        first, second, axis = float(words[0]), float(words[1]), float(words[5])
        if plane == "XY":
            points.append((first, second, axis))
        elif plane == "XZ":  # first axis Z, second X, axis Y
            points.append((second, axis, first))
        else:  # YZ: first Y, second Z, axis X
            points.append((axis, first, second))
    return _dedupe(points)
