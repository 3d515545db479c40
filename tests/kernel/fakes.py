"""A tiny stand-in interpreter so kernel tests do not depend on the language.

Understands one block per line: ``N``, ``G0``/``G1``, ``G90``/``G91``,
``X``/``Y``/``Z``, ``F``, ``G4 F<s>`` (dwell), ``M0 M1 M2 M30 M3 M4 M5`` and
other M codes, ``S``, ``T``, ``D``, ``R<n>=<v>`` (a pure calculation block),
``MSG("text")``, ``SETAL(n)``, ``STOPRE``, skip markers ``/`` and ``/n``, and
``ERR`` (raises alarm 12080). WCS = MCS + ``wcs_shift`` (to test the display).
"""

from __future__ import annotations

import re

from nck.canon import (
    AuxFunction, Dwell, EdgeSelect, Message, Motion, ProgramEnd, Source, SpindleCommand,
    StopPoint, ToolSelect, UserAlarm,
)
from nck.errors import NcAlarmError
from nck.interp.api import BlockResult
from nck.status import ModalView

TOKEN = re.compile(r'MSG\("([^"]*)"\)|SETAL\((\d+)\)|STOPRE|ERR|R(\d+)=(-?[\d.]+)|([A-Z])(-?[\d.]+)')


class MemoryPrograms:
    """A ProgramSource over a dict name -> text."""

    def __init__(self, programs: dict[str, str] | None = None) -> None:
        self.programs = dict(programs or {})

    def read_program(self, name: str) -> tuple[str, str] | None:
        text = self.programs.get(name)
        return None if text is None else (name, text)


class FakeInterpreter:
    """Interpreter protocol over the mini-language of the module docstring."""

    def __init__(self, machine, programs, data) -> None:
        self.machine = machine
        self.programs = programs
        self.data = data
        self.skip_levels: frozenset[int] = frozenset()
        self.steps = 0
        self._lines: list[str] = []
        self._file = ""
        self._index = 0
        self._done = True
        self._reset_modal()
        self.pos = {a: 0.0 for a in machine.path_axes}

    def _reset_modal(self) -> None:
        self.motion = "G0"
        self.absolute = True
        self.feed = 0.0
        self.wcs_shift = 0.0

    # -- protocol ----------------------------------------------------------
    def start(self, program_name: str) -> None:
        found = self.programs.read_program(program_name)
        if found is None:
            raise NcAlarmError(14011, program_name)
        self.start_text(found[0], found[1])

    def start_text(self, name: str, text: str) -> None:
        self._file = name
        self._lines = text.splitlines()
        self._index = 0
        self._done = False

    def reset(self) -> None:
        self._done = True
        self._lines = []
        self._reset_modal()

    def skip_to(self, number: int | None, text: str) -> bool:
        for index, line in enumerate(self._lines):
            if re.match(rf"N{number}(?!\d)", line.strip()) if number is not None else text in line:
                self._index = index
                return True
        return False

    def set_skip_levels(self, levels: frozenset[int]) -> None:
        self.skip_levels = frozenset(levels)

    @property
    def finished(self) -> bool:
        return self._done or self._index >= len(self._lines)

    def modal_view(self) -> ModalView:
        return ModalView(gcodes={1: self.motion, 14: "G90" if self.absolute else "G91"}, feed=self.feed)

    def step(self) -> BlockResult:
        self.steps += 1
        line_no = self._index + 1
        text = self._lines[self._index].strip()
        source_n = None
        match = re.match(r"/(\d?)\s*", text)
        body = text
        if match:
            level = int(match.group(1) or 0)
            body = text[match.end():]
            if level in self.skip_levels:
                self._index += 1
                numbered = re.match(r"N(\d+)", body)
                return BlockResult(source=Source(self._file, line_no, int(numbered.group(1)) if numbered else None), text=text)
        commands = []
        moved: dict[str, float] = {}
        kind = None
        dwell = False
        end = None
        calc_only = True
        for token in TOKEN.finditer(body):
            msg, setal, r_index, r_value, address, value = token.groups()
            whole = token.group(0)
            if whole == "ERR":
                raise NcAlarmError(12080, "ERR", file=self._file, line=line_no, n=source_n)
            if msg is not None:
                commands.append(("msg", msg))
            elif setal is not None:
                commands.append(("setal", int(setal)))
            elif whole == "STOPRE":
                commands.append(("stop", "STOPRE"))
            elif r_index is not None:
                self.data.r[int(r_index)] = float(r_value)
            elif address == "N":
                source_n = int(float(value))
            elif address == "G":
                g = int(float(value))
                if g in (0, 1):
                    kind = f"G{g}"
                elif g == 90:
                    self.absolute = True
                elif g == 91:
                    self.absolute = False
                elif g == 4:
                    dwell = True
            elif address in ("X", "Y", "Z"):
                moved[address] = float(value)
            elif address == "F":
                if dwell:
                    commands.append(("dwell", float(value)))
                else:
                    self.feed = float(value)
            elif address == "M":
                m = int(float(value))
                if m in (0, 1):
                    commands.append(("stop", f"M{m}"))
                elif m in (2, 30):
                    end = f"M{m}"
                elif m in (3, 4, 5):
                    commands.append(("spindle", f"M{m}"))
                else:
                    commands.append(("aux", ("M", m)))
            elif address == "S":
                commands.append(("speed", float(value)))
            elif address == "T":
                commands.append(("tool", int(float(value))))
            elif address == "D":
                commands.append(("edge", int(float(value))))
        source = Source(self._file, line_no, source_n)
        out = []
        if kind is not None:
            self.motion = kind
        if moved:
            start = dict(self.pos)
            for axis, value in moved.items():
                self.pos[axis] = value if self.absolute else self.pos[axis] + value
            out.append(Motion(
                kind=self.motion, source=source, plane="G17",
                end_wcs={a: v - self.wcs_shift for a, v in self.pos.items()},
                end_mcs=dict(self.pos), start_mcs=start, feed=self.feed,
                feed_mm_min=None if self.motion == "G0" else self.feed,
                gcodes={1: self.motion},
            ))
        spindle_state = None
        speed = None
        for what, value in commands:
            if what == "msg":
                out.append(Message(source, value))
            elif what == "setal":
                out.append(UserAlarm(source, value))
            elif what == "stop":
                out.append(StopPoint(source, value))
            elif what == "dwell":
                out.append(Dwell(source, seconds=value))
            elif what == "spindle":
                spindle_state = value
            elif what == "speed":
                speed = value
            elif what == "aux":
                out.append(AuxFunction(source, value[0], value[1]))
            elif what == "tool":
                out.append(ToolSelect(source, value, change=True))
            elif what == "edge":
                out.append(EdgeSelect(source, value))
        if spindle_state or speed is not None:
            out.append(SpindleCommand(source, 1, state=spindle_state, speed_rpm=speed))
        if end is not None:
            out.append(ProgramEnd(source, end))
        calc_only = not out
        self._index += 1
        if end is not None:
            self._done = True
        return BlockResult(
            source=source, text=text, commands=tuple(out), action_block=not calc_only,
            finished=end is not None, cost_s=0.001,
        )


def fake_factory(machine, programs, data) -> FakeInterpreter:
    """interpreter_factory for Nck."""
    return FakeInterpreter(machine, programs, data)
