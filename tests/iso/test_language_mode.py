"""The language mode after power on and RESET comes from the machine data (000 L466-475: MD20150
$MC_GCODE_RESET_VALUES[46] 1 = G290 Siemens mode, 2 = G291 ISO Dialect mode; MD10880
$MN_EXTERN_CNC_SYSTEM 1 = ISO Dialect M, 2 = ISO Dialect T), and G291 in Siemens mode switches
to that external language. Where MD10880 is not set (0) the machine's kind decides (our choice:
a lathe ISO T, a mill ISO M). The kernel, ``nck run`` / ``nck check`` and the editor's check
all start in that mode."""

from __future__ import annotations

import dataclasses

import pytest

from nck import canon
from nck.check import check_text
from nck.cli_tools import read_tool_table
from nck.headless import interpret_only, run_program
from nck.interp.sources import MemorySource
from nck.iso.dialect import language_mode
from nck.machine import MachineConfig, load_machine
from nck.ncdata import NcData, ToolEdge
from nck.resources import data_path

PROGRAM = data_path("examples", "iso", "ISO_T_SHAFT.MPF")
TOOLS_PATH = data_path("examples", "iso", "ISO_T_SHAFT_TOOLS.toml")


def machine_with(name: str, reset_47: int | None = None, extern_system: int | None = None) -> MachineConfig:
    """``name`` with MD20150[46] and MD10880 set (None: as shipped)."""
    machine = load_machine(name)
    md = dict(machine.md)
    if reset_47 is not None:
        md["MD20150"] = [0] * 46 + [reset_47] + [0] * 13
    if extern_system is not None:
        md["MD10880"] = extern_system
    return dataclasses.replace(machine, md=md)


def lathe_tools() -> NcData:
    data = NcData()
    data.tools = {key: ToolEdge(params=dict(p)) for key, p in read_tool_table(TOOLS_PATH).items()}
    return data


@pytest.mark.parametrize(("name", "reset_47", "extern_system", "mode"), [
    ("mill3", 1, 1, "siemens"),   # table 2-1, row 1
    ("lathe2", 1, 2, "siemens"),  # row 2
    ("mill3", 2, 1, "iso-m"),     # row 3
    ("mill3", 2, 2, "iso-t"),     # row 4: MD10880 decides, not the machine's kind
    ("lathe2", 2, 1, "iso-m"),
    ("lathe2", 2, 0, "iso-t"),    # MD10880 not set: the lathe's dialect (our choice)
    ("mill3", 2, 0, "iso-m"),
    ("mill3", None, None, "siemens"), ("lathe2", None, None, "siemens"),  # as shipped
])
def test_the_mode_after_reset(name: str, reset_47: int | None, extern_system: int | None, mode: str) -> None:
    assert language_mode(machine_with(name, reset_47, extern_system)) == mode


def test_an_iso_lathe_runs_the_iso_program_without_being_told_the_dialect() -> None:
    """ISO_T_SHAFT on a lathe whose machine data start in ISO Dialect T: the same commands as
    with the dialect given explicitly, and on the kernel (AUTO) to its end."""
    machine = machine_with("lathe2", reset_47=2, extern_system=2)
    text = PROGRAM.read_text()
    told = interpret_only(load_machine("lathe2"), MemorySource({}), lathe_tools(), PROGRAM.name, text=text,
                          max_blocks=10_000, dialect="iso-t")
    from_md = interpret_only(machine, MemorySource({}), lathe_tools(), PROGRAM.name, text=text, max_blocks=10_000)
    assert told.status == from_md.status == "ended"
    assert [m.end_mcs for m in from_md.segments] == [m.end_mcs for m in told.segments]
    run = run_program(machine, MemorySource({}), lathe_tools(), PROGRAM.name, text=text, timeout_s=600.0)
    assert run.status == "ended" and run.alarms == []


def test_the_editors_check_reads_the_program_in_the_machines_mode() -> None:
    """In Siemens mode every ISO line is a faulty line; on the ISO lathe the program checks clean."""
    text = PROGRAM.read_text()
    assert len(check_text(PROGRAM.name, text, machine=load_machine("lathe2"), data=lathe_tools())) >= 10
    assert check_text(PROGRAM.name, text, machine=machine_with("lathe2", 2, 2), data=lathe_tools()) == []


@pytest.mark.parametrize(("name", "alarms"), [("lathe2", []), ("mill3", [12550])])
def test_g291_switches_to_the_machines_external_language(name: str, alarms: list[int]) -> None:
    """``U`` is ISO Dialect T's incremental X (the lathe switches to ISO T) and no address of
    ISO Dialect M (12550 on the mill)."""
    text = "N10 G291\nN20 G00 X20. Z5.\nN30 U10.\nN40 M30\n"
    result = interpret_only(load_machine(name), MemorySource({}), NcData(), "T.MPF", text=text, max_blocks=100)
    assert [a.number for a in result.alarms] == alarms
    if not alarms:
        assert [m.end_mcs["X"] for m in result.segments if isinstance(m, canon.Motion)][-1] == 30.0


def test_which_language_each_line_is_read_in() -> None:
    """The editor's reading (word help): the machine's mode at the start, G291 / G290 lines
    switch (their own line too); a comment's G291 does not; a PROC program is Siemens."""
    from nck.iso.dialect import program_language

    text = "N10 G0 X1\nN20 G291 ; to ISO\nN30 G00 X2.\nN40 (G290 in a comment)\nN50 G290\nN60 G1 X3\n"
    on_mill = program_language(text, load_machine("mill3"))
    assert [on_mill.dialect_at(i) for i in range(6)] == ["siemens", "iso-m", "iso-m", "iso-m", "siemens", "siemens"]
    iso_lathe = machine_with("lathe2", 2, 2)
    assert program_language("G00 X20.\n", iso_lathe).dialect_at(0) == "iso-t"
    assert program_language("PROC CYC\nG0 X1\nRET\n", iso_lathe).dialect_at(1) == "siemens"
