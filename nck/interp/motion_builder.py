"""Motion building: the machine words of one block + modal state → canonical commands.

This is the one place that turns axis words and technology words into
:mod:`nck.canon` commands. The interpreter has already

* evaluated every expression of the block,
* validated the G codes (one per group) and applied the *modal* ones to
  ``modal.gcodes`` (so ``modal.gcodes[1]`` is the motion type in force),
* handled program flow and the program-control M functions (M0, M1, M2, M17, M30).

Interface::

    builder = MotionBuilder(machine, data)
    commands = builder.build(words, modal)   # may raise NcAlarmError

``build`` updates ``modal`` (positions, feed, spindle, tool, edge) in place
and returns the commands in output order (tool, edge, spindle, other aux
functions, then motion). The interpreter snapshots ``modal`` before the block,
so an alarm here leaves no trace.

Current scope: G0/G1 with linear/rotary axes in G90/G91 with AC()/IC(),
WCS = MCS (no frames, no tool offsets yet); F with G94 (mm/min) and G95
(mm/rev × S); S, M3/M4/M5/M19; T with M6 (mill, MD22550 = 1) or direct change
(MD22550 = 0); D.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.modal import ModalState
from nck.machine import MachineConfig
from nck.ncdata import NcData

SPINDLE_M = {3: "M3", 4: "M4", 5: "M5", 19: "M19"}


@dataclass
class BlockWords:
    """The evaluated machine words of one block.

    Attributes:
        source: file/line/N of the block.
        gcodes: every G code written in the block, group → code (modal and non-modal).
        axes: axis name → (value, mode) with mode ``"AC"``, ``"IC"`` or None (use G90/G91).
        words: other addresses → value (``F``, ``S``, ``T``, ``D``, ``I``, ``J``, ``K``,
            ``CR``, ``AR``, ``TURN``, ``I1``, …); extended ones as ``S1``/``M2`` style keys
            in ``extended``.
        extended: (address, extension) → value for ``S1=``, ``T1=``, ``H2=`` words.
        m_codes: the M functions of the block in order, as (extension or None, value).
        h_codes: the H functions, as (extension or None, value).
    """

    source: canon.Source
    gcodes: dict[int, str] = field(default_factory=dict)
    axes: dict[str, tuple[float, str | None]] = field(default_factory=dict)
    words: dict[str, float] = field(default_factory=dict)
    extended: dict[tuple[str, int], float] = field(default_factory=dict)
    m_codes: list[tuple[int | None, int]] = field(default_factory=list)
    h_codes: list[tuple[int | None, float]] = field(default_factory=list)


class MotionBuilder:
    """Builds the canonical commands of a block (see the module docstring)."""

    def __init__(self, machine: MachineConfig, data: NcData) -> None:
        self.machine = machine
        self.data = data
        self.path_axes = machine.path_axes
        mode = machine.md_value("MD22550")
        self.tool_change_with_m6 = (machine.kind != "lathe") if mode is None else bool(mode)

    # ------------------------------------------------------------------ entry point
    def build(self, words: BlockWords, modal: ModalState) -> list[canon.CanonCommand]:
        """Return the commands of the block and update ``modal``."""
        out: list[canon.CanonCommand] = []
        src = words.source
        self._feed(words, modal)
        self._tool(words, modal, out)
        self._spindle(words, modal, out)
        for ext, value in words.m_codes:
            if value in SPINDLE_M or value == 6:
                continue
            out.append(canon.AuxFunction(src, "M", float(value), ext))
            modal.aux["M"] = str(value)
        for ext, value in words.h_codes:
            out.append(canon.AuxFunction(src, "H", float(value), ext))
            modal.aux["H"] = _fmt(value)
        motion = self._motion(words, modal)
        if motion is not None:
            out.append(motion)
        return out

    # ------------------------------------------------------------------ technology
    def _feed(self, words: BlockWords, modal: ModalState) -> None:
        if "F" in words.words:
            feed = words.words["F"]
            if feed <= 0:
                raise NcAlarmError(14800)
            modal.feed = feed

    def _tool(self, words: BlockWords, modal: ModalState, out: list[canon.CanonCommand]) -> None:
        src = words.source
        change = any(v == 6 for _, v in words.m_codes)
        if "T" in words.words:
            tool = int(words.words["T"])
            if tool < 0:
                raise NcAlarmError(12160, "T")
            modal.tool_selected = tool
            direct = not self.tool_change_with_m6
            out.append(canon.ToolSelect(src, tool, change=direct or change))
            if direct:
                self._change_tool(modal)
        elif change:
            out.append(canon.ToolSelect(src, modal.tool_selected, change=True))
        if change and self.tool_change_with_m6:
            self._change_tool(modal)
        if "D" in words.words:
            edge = int(words.words["D"])
            if edge < 0:
                raise NcAlarmError(12160, "D")
            modal.edge = edge
            out.append(canon.EdgeSelect(src, edge))

    def _change_tool(self, modal: ModalState) -> None:
        modal.tool = modal.tool_selected
        modal.edge = 1 if modal.tool else 0

    def _spindle(self, words: BlockWords, modal: ModalState, out: list[canon.CanonCommand]) -> None:
        """S / M3 M4 M5 M19 per spindle (``S2=``, ``M2=3`` address spindle 2; plain = master)."""
        src = words.source
        speeds: dict[int, float] = {}
        states: dict[int, str] = {}
        if "S" in words.words:
            speeds[1] = words.words["S"]
        for (address, ext), value in words.extended.items():
            if address == "S":
                speeds[ext or 1] = value
        for ext, value in words.m_codes:
            if value in SPINDLE_M:
                spindle = ext or 1
                if spindle in states:
                    raise NcAlarmError(12000, "M")
                states[spindle] = SPINDLE_M[value]
        for spindle in sorted(set(speeds) | set(states)):
            speed = speeds.get(spindle)
            state = states.get(spindle)
            if speed is not None and speed < 0:
                raise NcAlarmError(12160, "S")
            if spindle == 1:
                if speed is not None:
                    modal.spindle_speed_rpm = speed
                if state is not None:
                    modal.spindle_state = state
            out.append(canon.SpindleCommand(src, spindle, state=state, speed_rpm=speed))

    # ------------------------------------------------------------------ motion
    def _motion(self, words: BlockWords, modal: ModalState) -> canon.Motion | None:
        if not words.axes:
            return None
        kind = modal.gcodes.get(1, "G1")
        if kind not in ("G0", "G1"):
            raise NcAlarmError(12550, kind)
        absolute = modal.gcodes.get(14, "G90") == "G90"
        start_mcs = dict(modal.position_mcs)
        end_wcs = dict(modal.position_wcs)
        for axis, (value, mode) in words.axes.items():
            if axis not in end_wcs:
                raise NcAlarmError(12550, axis)
            incremental = mode == "IC" or (mode is None and not absolute)
            end_wcs[axis] = end_wcs[axis] + value if incremental else value
        feed = None
        feed_mm_min = None
        if kind != "G0":
            if modal.feed <= 0:
                raise NcAlarmError(10860)
            feed = modal.feed
            feed_mm_min = self._feed_mm_min(modal)
        end_mcs = dict(end_wcs)  # WCS = MCS until frames and tool offsets arrive
        modal.position_wcs = end_wcs
        modal.position_mcs = end_mcs
        exact = modal.gcodes.get(10, "G60") == "G60" or words.gcodes.get(11) == "G9"
        return canon.Motion(
            kind=kind,
            source=words.source,
            plane=modal.gcodes.get(6, "G17"),
            end_wcs=end_wcs,
            end_mcs=end_mcs,
            start_mcs=start_mcs,
            feed=feed,
            feed_mm_min=feed_mm_min,
            exact_stop=exact,
            exact_stop_window=modal.gcodes.get(12, "G601"),
            gcodes=dict(modal.gcodes),
        )

    def _feed_mm_min(self, modal: ModalState) -> float:
        feed_type = modal.gcodes.get(15, "G94")
        if feed_type == "G95":
            if modal.spindle_speed_rpm <= 0:
                raise NcAlarmError(14800)
            return modal.feed * modal.spindle_speed_rpm
        return modal.feed


def _fmt(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else str(value)
