"""Turn a headless run into a readable, stable text trace (for the golden files)."""

from __future__ import annotations

import tomllib
from pathlib import Path

from nck import canon
from nck.cli_tools import read_tool_table
from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.lang.gcodes import gtable
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge


def num(value: float | None) -> str:
    """Numbers with at most 6 decimals, no trailing zeros."""
    if value is None:
        return "-"
    text = f"{float(value):.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def command_line(command: canon.CanonCommand) -> str:
    """One trace line per canonical command."""
    src = command.source
    where = f"L{src.line} N{src.n if src.n is not None else '-'}"
    if isinstance(command, canon.Motion):
        axes = " ".join(f"{a}={num(v)}" for a, v in command.end_wcs.items())
        return f"{where} {command.kind} {axes} F={num(command.feed)}"
    if isinstance(command, canon.ToolSelect):
        return f"{where} T{command.tool}{' change' if command.change else ''}"
    if isinstance(command, canon.EdgeSelect):
        return f"{where} D{command.edge}"
    if isinstance(command, canon.SpindleCommand):
        return f"{where} SPINDLE{command.spindle} {command.state or '-'} S={num(command.speed_rpm)}"
    if isinstance(command, canon.AuxFunction):
        ext = f"{command.extension}=" if command.extension is not None else ""
        return f"{where} {command.address}{ext}{num(command.value)}"
    if isinstance(command, canon.Message):
        return f'{where} MSG "{command.text}"'
    if isinstance(command, canon.StopPoint):
        return f"{where} STOP {command.kind}"
    if isinstance(command, canon.ProgramEnd):
        return f"{where} END {command.kind}"
    if isinstance(command, canon.UserAlarm):
        return f"{where} SETAL {command.number} {' '.join(command.params)}".rstrip()
    if isinstance(command, canon.ExactStop):
        return f"{where} EXACT STOP"
    if isinstance(command, canon.Dwell):
        return f"{where} DWELL {num(command.seconds)}"
    return f"{where} {type(command).__name__}"


def final_lines(result: HeadlessRun, data: NcData) -> list[str]:
    """The final state: status, alarms, changed G groups, position, tool, spindle, R."""
    interp = result.interpreter
    assert interp is not None
    modal = interp.modal
    lines = [f"status {result.status} blocks {result.blocks}"]
    for alarm in result.alarms:
        lines.append(f"alarm {alarm.number} {alarm.file}:{alarm.line} N{alarm.n if alarm.n is not None else '-'}")
    reset = gtable().reset_state()
    changed = [f"{g}={c}" for g, c in sorted(modal.gcodes.items()) if reset.get(g) != c]
    if changed:
        lines.append("gcodes " + " ".join(changed))
    lines.append("position " + " ".join(f"{a}={num(v)}" for a, v in modal.position_wcs.items()))
    lines.append(f"tool T{modal.tool} D{modal.edge} spindle {modal.spindle_state} S={num(modal.spindle_speed_rpm)}")
    r_values = [f"R{i}={num(v)}" for i, v in enumerate(data.r) if v != 0]
    if r_values:
        lines.append("r " + " ".join(r_values))
    for key in sorted(data.tools):
        params = data.tools[key].params
        lines.append(f"tool_edge T{key[0]} D{key[1]} " + " ".join(f"P{p}={num(v)}" for p, v in sorted(params.items())))
    return lines


def case_data(folder: Path, options: dict) -> NcData:
    """The NC data a case starts with: its tool table (``tools = "file"`` in options.toml)."""
    data = NcData()
    if "tools" in options:
        table = read_tool_table(folder / options["tools"])
        data.tools = {key: ToolEdge(params=dict(params)) for key, params in table.items()}
    return data


def run_case(folder: Path) -> str:
    """Run ``main.mpf`` of a case folder (other files are subprograms) → trace text."""
    options = {}
    if (folder / "options.toml").is_file():
        options = tomllib.loads((folder / "options.toml").read_text())
    programs = {p.name: p.read_text() for p in folder.iterdir() if p.suffix.lower() in (".spf", ".mpf")}
    data = case_data(folder, options)
    for index, value in options.get("r", {}).items():
        data.r[int(index)] = float(value)
    # The language is tested on its own: the interpreter-only loop (no kernel, no motion
    # simulation), with a generous block budget so that a runaway program still ends.
    result = interpret_only(load_machine(options.get("machine")), MemorySource(programs), data,
                            "main.mpf", text=programs["main.mpf"], max_blocks=100_000,
                            skip_levels=frozenset(options.get("skip_levels", [])))
    lines = [command_line(c) for c in result.commands]
    lines.append("--")
    lines.extend(final_lines(result, data))
    return "\n".join(lines) + "\n"
