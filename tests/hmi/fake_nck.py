"""A small stand-in kernel for HMI tests: same facade as ``nck.kernel.Nck``, fixed behaviour.

It exists so the rendering (snapshots) and the shell do not change when the real
kernel evolves. It knows modes, machine functions, JOG, referencing, a toy MDA
(``G0/G1 X.. Y.. Z..``), AUTO over a list of blocks with single block, NC STOP/START,
RESET, overrides, keyswitch and alarms. Motion is instantaneous per block.
"""

from __future__ import annotations

import re
from dataclasses import replace

from nck import commands as c
from nck.machine import load_machine
from nck.ncdata import NcData
from nck.status import AlarmEntry, AxisStatus, BlockView, ChannelStatus, ModalView, NckStatus

SAMPLE_PROGRAM = [
    "N10 G90 G54 G17 G71 G94",
    "N20 T1 D1",
    "N30 M3 S1200",
    "N40 G0 X10 Y20 Z5",
    "N50 G1 Z-2 F300",
    "N60 X40",
    "N70 Y50",
    "N80 G0 Z50",
    "N90 M30",
]

DEFAULT_GCODES = {1: "G0", 6: "G17", 7: "G40", 8: "G500", 10: "G60", 13: "G71", 14: "G90", 15: "G94"}


class FakeNck:
    """Deterministic fake of the kernel facade (submit / tick / step / status)."""

    ipo_cycle_s = 0.002

    def __init__(self, referenced: bool = False, axes: tuple[str, ...] = ("X", "Y", "Z")) -> None:
        self.axes = list(axes)
        self.pos = {a: 0.0 for a in axes}
        self.referenced = {a: referenced for a in axes}
        self.time_s = 0.0
        self.seq = 1
        self.mode = "JOG"
        self.function: str | None = None
        self.increment: int | None = 1
        self.channel_state = "reset"
        self.program_state = "aborted"
        self.selected: str | None = None
        self.programs: dict[str, list[str]] = {"PART1.MPF": list(SAMPLE_PROGRAM)}
        self.blocks: list[str] = []
        self.pc = 0
        self.mda_text = ""
        self.control: dict[str, object] = {"single_block": None, "dry_run": False, "m01": False,
                                           "program_test": False, "rapid_override": False,
                                           "skip_levels": frozenset()}
        self.overrides = {"feed": 100.0, "rapid": 100.0, "spindle": 100.0}
        self.keyswitch = 0
        self.alarms: list[AlarmEntry] = []
        self.gcodes = dict(DEFAULT_GCODES)
        self.tool = 0
        self.edge = 0
        self.feed = 0.0
        self.spindle_rpm = 0.0
        self.spindle_state = "M5"
        self.runtime_s = 0.0
        self.parts = 0
        self.message = ""
        self.repos_offsets: dict[str, float] = {}
        self.submitted: list[object] = []
        self.data = NcData()  # the real Nck exposes its NC data (the Parameter area reads it)
        self.machine = load_machine()

    # -- facade -------------------------------------------------------------------------
    def status(self) -> NckStatus:
        """Return the snapshot."""
        axes = tuple(
            AxisStatus(name=a, kind="linear", position_mcs=self.pos[a], position_wcs=self.pos[a],
                       referenced=self.referenced[a])
            for a in self.axes
        ) + (AxisStatus(name="SP", kind="spindle", position_mcs=0.0, position_wcs=0.0,
                        referenced=True, speed_rpm=self.spindle_rpm),)
        current = None
        if self.blocks:
            index = min(self.pc, len(self.blocks) - 1)
            current = BlockView(self.selected or "MDA", index + 1, self.blocks[index])
        views = tuple(BlockView(self.selected or "MDA", i + 1, t) for i, t in enumerate(self.blocks))
        channel = ChannelStatus(
            mode=self.mode, machine_function=self.function, increment=self.increment,
            channel_state=self.channel_state, program_state=self.program_state,
            selected_program=self.selected, current_block=current, blocks=views,
            modal=ModalView(gcodes=dict(self.gcodes), tool=self.tool, edge=self.edge,
                            feed=self.feed, spindle_speed_rpm=self.spindle_rpm,
                            spindle_state=self.spindle_state),
            program_control=dict(self.control), overrides=dict(self.overrides),
            program_runtime_s=self.runtime_s, part_count=self.parts, message=self.message,
            repos_offsets=dict(self.repos_offsets),
        )
        return NckStatus(seq=self.seq, time_s=self.time_s, channel=channel, axes=axes,
                         alarms=tuple(self.alarms), access_level=7 - self.keyswitch,
                         machine_name="fake")

    def tick(self, dt_s: float) -> None:
        """Advance time; a running program executes one block per 0.1 s."""
        self.time_s += dt_s
        if self.program_state == "running":
            self.runtime_s += dt_s
            self._accum = getattr(self, "_accum", 0.0) + dt_s
            while self._accum >= 0.1 and self.program_state == "running":
                self._accum -= 0.1
                self._execute_block()
        self.seq += 1 if self.program_state == "running" else 0

    def step(self, n: int) -> None:
        """Advance ``n`` IPO cycles."""
        self.tick(n * self.ipo_cycle_s)

    def list_programs(self) -> list[str]:
        """Names of the part programs."""
        return sorted(self.programs)

    def raise_alarm(self, number: int, text: str, category: str = "channel",
                    clear: str = "reset") -> None:
        """Test helper: put an alarm on the list."""
        self.alarms.append(AlarmEntry(seq=len(self.alarms) + 1, number=number, text=text,
                                      category=category, clear=clear, came_s=self.time_s))
        self._changed()

    def submit(self, command: object) -> c.SubmitResult:
        """Take or refuse a command."""
        self.submitted.append(command)
        result = self._submit(command)
        if isinstance(result, c.Accepted):
            self._changed()
        return result

    # -- behaviour --------------------------------------------------------------------------
    def _changed(self) -> None:
        self.seq += 1

    def _submit(self, command: object) -> c.SubmitResult:
        if isinstance(command, c.SelectMode):
            if self.channel_state == "active":
                return c.Rejected("Mode change not possible: channel active")
            self.mode, self.function = command.mode, None
            if command.mode == "MDA":
                self.blocks = [b for b in self.mda_text.splitlines() if b.strip()]
                self.pc = 0
            elif command.mode == "AUTO":
                self.blocks = list(self.programs.get(self.selected or "", []))
                self.pc = 0
            return c.Accepted()
        if isinstance(command, c.SelectMachineFunction):
            if self.mode != "JOG":
                return c.Rejected("Machine functions only in JOG")
            self.function = command.function
            return c.Accepted()
        if isinstance(command, c.SelectIncrement):
            self.increment = command.increment
            return c.Accepted()
        if isinstance(command, c.Jog):
            if self.mode != "JOG":
                return c.Rejected("JOG keys only in mode JOG")
            if command.direction == 0:
                return c.Accepted()
            if self.function == "REF":
                self.referenced[command.axis] = True
            elif command.axis in self.pos:
                step = (self.increment or 1) * 0.001 if self.function == "INC" else 1.0
                self.pos[command.axis] += command.direction * step
            return c.Accepted()
        if isinstance(command, c.SetMdaProgram):
            self.mda_text = command.text
            if self.mode == "MDA" and self.channel_state == "reset":
                self.blocks = [b for b in command.text.splitlines() if b.strip()]
                self.pc = 0
            return c.Accepted()
        if isinstance(command, c.SelectProgram):
            if self.channel_state != "reset":
                return c.Rejected("Program selection only in channel reset")
            if command.name not in self.programs:
                return c.Rejected(f"Program {command.name} not found")
            self.selected = command.name
            if self.mode == "AUTO":
                self.blocks, self.pc = list(self.programs[command.name]), 0
            return c.Accepted()
        if isinstance(command, c.CycleStart):
            if self.mode == "JOG":
                return c.Rejected("NC START not possible in JOG")
            if not all(self.referenced.values()):
                return c.Rejected("Axes not referenced", alarm=10203)
            if not self.blocks:
                return c.Rejected("No program selected")
            self.channel_state, self.program_state = "active", "running"
            if self.control["single_block"]:
                self._execute_block()
            return c.Accepted()
        if isinstance(command, c.CycleStop):
            if self.channel_state == "active":
                self.channel_state, self.program_state = "interrupted", "stopped"
            return c.Accepted()
        if isinstance(command, c.Reset):
            self.channel_state, self.program_state = "reset", "aborted"
            self.pc = 0
            self.alarms = [a for a in self.alarms if a.clear not in ("reset", "cancel")]
            self.gcodes = dict(DEFAULT_GCODES)
            return c.Accepted()
        if isinstance(command, c.CancelAlarms):
            self.alarms = [a for a in self.alarms if a.clear != "cancel"]
            return c.Accepted()
        if isinstance(command, c.SetProgramControl):
            self.control[command.name] = command.value
            return c.Accepted()
        if isinstance(command, c.SetOverride):
            self.overrides[command.which] = command.percent
            return c.Accepted()
        if isinstance(command, c.SetKeyswitch):
            self.keyswitch = command.position
            return c.Accepted()
        return c.Rejected(f"{type(command).__name__} not supported by the fake kernel")

    def _execute_block(self) -> None:
        if self.pc >= len(self.blocks):
            self._end()
            return
        text = self.blocks[self.pc]
        words = dict(re.findall(r"([A-Z])\s*(-?\d+(?:\.\d+)?)", text.upper()))
        for g in re.findall(r"\bG(\d+)\b", text.upper()):
            group = {0: 1, 1: 1, 2: 1, 3: 1, 17: 6, 18: 6, 19: 6, 90: 14, 91: 14, 54: 8,
                     500: 8, 71: 13, 70: 13, 94: 15, 95: 15, 40: 7, 41: 7, 42: 7}.get(int(g))
            if group:
                self.gcodes[group] = f"G{int(g)}"
        for axis in self.axes:
            if axis in words:
                self.pos[axis] = float(words[axis])
        if "F" in words:
            self.feed = float(words["F"])
        if "T" in words:
            self.tool = int(float(words["T"]))
        if "D" in words:
            self.edge = int(float(words["D"]))
        if "S" in words:
            self.spindle_rpm = float(words["S"])
        for m in re.findall(r"\bM(\d+)\b", text.upper()):
            if m in ("3", "4", "5"):
                self.spindle_state = f"M{m}"
                if m == "5":
                    self.spindle_rpm = 0.0
        self.pc += 1
        self._changed()
        if re.search(r"\bM(30|2|17)\b", text.upper()) or self.pc >= len(self.blocks):
            self._end()
        elif self.control["single_block"]:
            self.channel_state, self.program_state = "interrupted", "stopped"

    def _end(self) -> None:
        self.channel_state, self.program_state = "reset", "aborted"
        if self.mode == "AUTO":
            self.parts += 1
        self.pc = 0
        self._changed()


def fake_with(**changes: object) -> FakeNck:
    """Return a FakeNck with attributes replaced (for compact test setup)."""
    fake = FakeNck()
    for key, value in changes.items():
        setattr(fake, key, value)
    return fake


__all__ = ["FakeNck", "SAMPLE_PROGRAM", "fake_with", "replace"]
