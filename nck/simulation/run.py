"""Simulate a milling program: the AUTO run's motions swept through a Z-map over the blank.

The program runs through the kernel exactly as ``nck run`` runs it (AUTOMATIC, axes
referenced, NC START; :func:`nck.headless.run_program`), so the simulation stops with the same
alarm at the same block as the machine would, and the machining time is the interpolator's
own simulated time (acceleration, look-ahead, dwells). The executed motions — with tool radius
compensation, cycles and frames already applied — are taken as the kernel hands them to the
motion: line and arc segments of the tool tip in the workpiece coordinate system. Arcs are
sampled with the motion's own arc geometry (:func:`nck.motion.path.arc`) into chords whose
sagitta stays below a fraction of a cell.

The material is removed along the setpoints (the interpolated path), not along the drives'
actual positions, as Operate's simulation does; still the run keeps the drive model. Our
choice, measured (2026-11-27, the 200,000-block plate program): the drive model costs about
5 % of the run (its monitors are proven silent per block by bounds), and it is what raises the
axis monitoring alarms an AUTO run raises (contour 25050, speed setpoint 25060, velocity 25030,
positioning 25080, zero speed 25040, clamping 26000); without it the simulation would say "no
errors" for a program whose feeds the axes cannot follow.

Per-tool times: the run's machining time split in proportion to each tool's share of the
motions' nominal times (path length over the programmed feed, rapid moves at the rapid
traverse estimate of ``nck check``). Our choice: the kernel reports one time for the run,
not one per block.

Events found while sweeping, each naming its block: a rapid move (G0) that cuts material,
a feed move that cuts while the spindle stands, and a cut deeper than the tool's length 1 —
the toolholder below the surface (the tool data has no flute length: ``$TC_DP`` ends the
tool at the toolholder reference point, 002 L62525-62558; our choice: the holder is as wide
as the tool).

The mill's path is recorded in the blank's frame: the machine positions (MCS) less the tool
length and the work offset of the first motion, so that programmable frames (TRANS, ROT,
MIRROR, SCALE) cut where the machine cuts (a mirrored G2 turns the other way, 001
L2285-2289). A program that sets such a frame before its first motion places the blank
with it (our choice).
"""

from __future__ import annotations

import math
from array import array
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping
import numpy as np

from nck import canon
from nck.canon import THREAD_AND_TAPPING_KINDS
from nck.errors import NcAlarmError
from nck.headless import DEFAULT_RAPID_MM_MIN, HeadlessRun, run_program
from nck.interp.api import ProgramSource
from nck.interp.sources import program_file_key
from nck.machine import MachineConfig, load_machine
from nck.motion.path import arc as arc_segment
from nck.ncdata import NcData
from nck.phrase import Phrase
from nck.simulation.blank import Blank, blank_around, blank_from_setup, blank_from_text
from nck.simulation.checkpoints import Checkpoints
from nck.simulation.cutter import Cutter
from nck.simulation.pairwise import pairwise_sum
from nck.simulation.turning import Insert, TurnProfile, bar, bar_around, half_section
from nck.simulation.zmap import ZMap
from nck.workpiece import Cylinder, MachineSetup

DEFAULT_RESOLUTION_MM = 0.5
AUTO_CELLS = 400
AUTO_CHORD_RESOLUTION_MM = 0.4
"""Without a resolution, arcs are cut into chords as for this cell size (sagitta 0.05 mm)."""
CUT_EPSILON_MM = 0.01
"""A move cuts when it lowers some cell by more than this (below: rounding, a touch)."""

_PLANE_INDEX = {"G17": (0, 1), "G18": (2, 0), "G19": (1, 2)}
_LINEAR_MASK = (True, True, True)  # a tuple: arc() iterates it per arc (numpy booleans cost more)
Point = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class SimEvent:
    """Something the sweep found: ``kind`` is ``rapid_cut``, ``spindle_stopped`` or
    ``holder_in_material`` (the cut went deeper than the tool's length 1)."""

    kind: str
    line: int | None
    n: int | None
    depth_mm: float

    @property
    def text(self) -> Phrase:
        """The event in the panel's words (English; a panel translates the phrase)."""
        where = f"N{self.n}" if self.n is not None else Phrase("line {line}", line=self.line)
        depth = f"{self.depth_mm:.2f}"
        if self.kind == "rapid_cut":
            return Phrase("{where}: rapid traverse into material ({depth} mm deep)", where=where, depth=depth)
        if self.kind == "holder_in_material":
            return Phrase("{where}: tool holder below the surface (cut {depth} mm deep)", where=where, depth=depth)
        return Phrase("{where}: cutting with the spindle stopped ({depth} mm deep)", where=where, depth=depth)


@dataclass
class Toolpath:
    """The executed path as straight chords of the tool tip (WCS), one row per chord."""

    starts: np.ndarray
    ends: np.ndarray
    lines: np.ndarray  # 1-based source line of the block (0: unknown)
    rapid: np.ndarray  # bool
    tools: np.ndarray  # T number active
    cutters: list[Cutter | Insert | None] = field(default_factory=list)  # the cutters chords index into
    cutter_of: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int32))
    spindle_on: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    numbers: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))  # N (-1: none)
    motion_of: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))  # index into states
    states: list[ModalState] = field(default_factory=list)  # per executed motion


@dataclass(frozen=True, slots=True)
class ModalState:
    """The modal state an executed motion ran with: its G groups (group → G code), the feed as
    programmed, the active T and D, and the spindle speed (rpm, None: not programmed)."""

    gcodes: Any
    feed: float | None
    tool: int
    edge: int
    speed_rpm: float | None

    def text(self) -> str:
        """The state in the panel's words: the shown groups' G codes, T, D, F, S."""
        gcodes = dict(self.gcodes or {})
        words = [str(gcodes[g]) for g in SHOWN_GROUPS if gcodes.get(g)]
        words += [f"T{self.tool}", f"D{self.edge}"]
        if self.feed is not None:
            words.append(f"F{self.feed:g}")
        if self.speed_rpm is not None:
            words.append(f"S{self.speed_rpm:g}")
        return " ".join(words)


SHOWN_GROUPS = (1, 6, 7, 8, 14, 15)
"""G groups the step view names (002: 1 motion, 6 plane, 7 tool radius compensation, 8 settable
work offset, 14 absolute/incremental, 15 feed type) — the groups of the Machine area's G line."""
SHOWN_TABLES_KEPT = 16
"""G code tables whose shown groups the recorder remembers (more than the path builder shares)."""


@dataclass(frozen=True)
class AlarmPlace:
    """The main program's line an alarm belongs to: its own line, or for an alarm that came in a
    cycle or subprogram the line that called it, with the called program and its line."""

    line: int | None
    called_file: str | None = None
    called_line: int | None = None


@dataclass
class Simulation:
    """The outcome of :func:`simulate`."""

    blank: Blank
    zmap: ZMap | TurnProfile  # the lathe's profile: radius per Z cell
    path: Toolpath
    events: list[SimEvent]
    alarms: list[NcAlarmError]
    status: str  # ended, alarm, timeout
    machine_time_s: float
    tool_times_s: dict[int, float]
    blocks: int
    checkpoints: Checkpoints | None = None  # heights along the way, kept by the sweep (for scrubbing)
    alarm_places: list[AlarmPlace] = field(default_factory=list)
    """Per alarm, the main program's line it belongs to (as the path's lines)."""
    _half_section: tuple[np.ndarray, np.ndarray] | None = field(default=None, init=False, repr=False,
                                                                 compare=False)  # drawn_path() of a lathe, made once

    def blocks_in_order(self) -> list[tuple[int, int]]:
        """The executed blocks as (source line, number of chords up to and including it), in order."""
        lines = self.path.lines
        if len(lines) == 0:
            return []
        change = np.flatnonzero(lines[1:] != lines[:-1]) + 1
        ends = np.concatenate((change, [len(lines)]))
        return list(zip(lines[ends - 1].tolist(), ends.tolist()))

    @property
    def turning(self) -> bool:
        """True for a lathe's simulation (a rotational profile, not a Z-map)."""
        return isinstance(self.zmap, TurnProfile)

    def modal_at(self, chords: int) -> str:
        """The modal state (G groups, T, D, F, S) of the block shown after ``chords`` chords."""
        path = self.path
        if chords <= 0 or not path.states:
            return ""
        return path.states[int(path.motion_of[chords - 1])].text()

    def drawn_path(self) -> tuple[np.ndarray, np.ndarray]:
        """The chords' starts and ends as a view draws them: the workpiece coordinates, on a
        lathe the half section (Z, 0, radius), made once: the same arrays at every call, so that
        a view keeping its overlay per path arrays finds them again at each scrub step."""
        if not self.turning:
            return self.path.starts, self.path.ends
        if self._half_section is None:
            self._half_section = (half_section(self.path.starts), half_section(self.path.ends))
        return self._half_section

    def tool_at(self, chords: int) -> tuple[tuple[float, float, float] | None, float]:
        """Where a view draws the tool after ``chords`` chords, and its radius: the tip (a
        lathe: the nose centre in the half section) and the cutting (nose) radius."""
        if chords <= 0:
            return None, 0.0
        cutter = self.path.cutters[int(self.path.cutter_of[chords - 1])] if len(self.path.cutters) else None
        radius = cutter.radius_mm if cutter is not None else 0.0
        if not self.turning:
            return tuple(float(v) for v in self.path.ends[chords - 1]), radius  # type: ignore[return-value]
        z, _y, r = half_section(self.path.ends[chords - 1])[0]
        dz, dr = cutter.nose_centre_from_tip() if isinstance(cutter, Insert) else (0.0, 0.0)
        return (float(z + dz), 0.0, float(r + dr)), radius

    def cut_until(self, chords: int) -> ZMap | TurnProfile:
        """The uncut blank cut by the first ``chords`` chords (stepping through the program)."""
        zmap = self.zmap.fresh()
        sweep_path(zmap, self.path, upto=chords)
        return zmap


class PathRecorder:
    """Collects the executed motions with the tool, edge and spindle state in force."""

    def __init__(self, data: NcData, chord_tol_mm: float, turning: bool = False, main: str = "") -> None:
        self.data = data
        self.main = program_file_key(main)
        self._main_line = 0
        self._main_line_of: dict[int, int] = {}  # id(motion) → the main program's line it runs for
        self.turning = turning
        self.tol = chord_tol_mm
        self.tool = 0
        self.selected = 0
        self.edge = 1
        self.spindle_on = False
        self.speed_rpm: float | None = None
        self.feed: float | None = None  # the last programmed F (modal, shown with G0 too)
        self.states: list[ModalState] = []  # per motion; equal states are one object
        self._state_of: dict[tuple[Any, ...], ModalState] = {}
        # The shown groups of the G code tables seen lately, by identity (the path builder shares a
        # few read-only tables among its motions); the table is kept so that its id is not reused.
        self._shown_of: dict[int, tuple[Any, tuple[str | None, ...]]] = {}
        self._file: str | None = None  # the file of the last block, and whether it is the main program
        self._in_main = False
        self.tool_times: dict[int, float] = {}
        self.position: Point | None = None  # the tool tip after the last motion
        self.mcs_minus_wcs: tuple[float, float, float] | None = None  # the work offset, tool length taken out
        # Flat buffers, not an array or a tuple per motion (a 200,000-block program kept 100 MB
        # of small objects): chord starts and ends (X Y Z per chord), per motion its chord count
        # and line, rapid, tool, cutter, spindle, N.
        self._starts = array("d")
        self._ends = array("d")
        self._meta = array("q")
        self.counts = array("q")
        self.cutters: list[Cutter | Insert | None] = []
        self._cutter_index: dict[tuple[int, int], int] = {}

    def block(self, block: Any) -> None:
        """An interpreted block: its motions belong to its line if it is a block of the main
        program, else (a subprogram or cycle) to the main program's block that called it."""
        source = getattr(block, "source", None)
        if source is not None:
            if source.file != self._file:
                self._file, self._in_main = source.file, program_file_key(source.file) == self.main
            if self._in_main:
                self._main_line = source.line
        for command in getattr(block, "commands", ()):
            if isinstance(command, canon.Motion):
                self._main_line_of[id(command)] = self._main_line

    def place_of(self, alarm: NcAlarmError) -> AlarmPlace:
        """The main program's line ``alarm`` belongs to: its own line in the main program, else
        the line of the main program's block interpreted last (the call of the cycle or
        subprogram it came in: the run stops there)."""
        if alarm.file is None or program_file_key(alarm.file) == self.main or not self._main_line:
            return AlarmPlace(alarm.line)
        return AlarmPlace(self._main_line, alarm.file, alarm.line)

    def _cutter(self) -> int:
        key = (self.tool, self.edge)
        if key not in self._cutter_index:
            number = self.edge if self.edge > 0 else 1
            edge = self.data.edge(self.tool, number) if self.tool else None
            self._cutter_index[key] = len(self.cutters)
            if edge is None:
                self.cutters.append(None)
            elif self.turning:
                self.cutters.append(Insert.from_edge(self.data, self.tool, number))
            else:
                self.cutters.append(Cutter.from_edge(self.tool, dict(edge.params)))
        return self._cutter_index[key]

    def _no_cutter(self) -> int:
        if (-1, -1) not in self._cutter_index:
            self._cutter_index[(-1, -1)] = len(self.cutters)
            self.cutters.append(None)
        return self._cutter_index[(-1, -1)]

    def __call__(self, command: canon.CanonCommand) -> None:
        if isinstance(command, canon.Motion):  # first: most commands are motions
            self._motion(command)
        elif isinstance(command, canon.ToolSelect):
            self.selected = command.tool
            if command.change:
                self.tool = command.tool
        elif isinstance(command, canon.AuxFunction) and command.address == "M" and int(command.value) == 6:
            self.tool = self.selected
        elif isinstance(command, canon.EdgeSelect):
            self.edge = command.edge
        elif isinstance(command, canon.SpindleCommand):
            if command.speed_rpm is not None:
                self.speed_rpm = command.speed_rpm
            if command.state in ("M3", "M4"):
                self.spindle_on = command.speed_rpm is None or command.speed_rpm > 0.0
            elif command.state is not None:
                self.spindle_on = False
            elif command.speed_rpm is not None and command.speed_rpm <= 0.0:
                self.spindle_on = False

    def _motion(self, motion: canon.Motion) -> None:
        end_wcs = motion.end_wcs
        end_mcs = motion.end_mcs
        first = not self.counts
        if self.mcs_minus_wcs is None and self.turning and all(a in end_wcs and a in end_mcs for a in "XZ"):
            # Lathe: MCS X in radius, WCS X a diameter (DIAMON); length 1 along X, 2 along Z (G18).
            edge = self.data.edge(self.tool, self.edge) if self.tool and self.edge > 0 else None
            along_x = edge.get(3) + edge.get(12) if edge is not None else 0.0
            along_z = edge.get(4) + edge.get(13) if edge is not None else 0.0
            self.mcs_minus_wcs = (float(end_mcs["X"]) - float(end_wcs["X"]) / 2.0 - along_x, 0.0,
                                  float(end_mcs["Z"]) - float(end_wcs["Z"]) - along_z)
        if self.mcs_minus_wcs is None and not self.turning and all(a in end_wcs and a in end_mcs for a in "XYZ"):
            length = self._length()
            self.mcs_minus_wcs = (float(end_mcs["X"]) - float(end_wcs["X"]), float(end_mcs["Y"]) - float(end_wcs["Y"]),
                                  float(end_mcs["Z"]) - float(end_wcs["Z"]) - length)
        in_blank = not self.turning and self.mcs_minus_wcs is not None
        shift = self._shift() if in_blank else (0.0, 0.0, 0.0)  # the edge is the same all through the motion
        if self.position is None:
            if in_blank:
                self.position = self._blank_point(motion.start_mcs or end_mcs, None, shift)
            else:
                start_mcs = motion.start_mcs

                def start_of(a: str) -> float:
                    if a in end_wcs and a in end_mcs:
                        return (float(start_mcs.get(a, end_mcs.get(a, 0.0))) + float(end_wcs.get(a, 0.0))
                                - float(end_mcs.get(a, 0.0)))
                    return float(end_wcs.get(a, 0.0))

                self.position = (start_of("X"), start_of("Y"), start_of("Z"))
        start = self.position
        if in_blank:
            end = self._blank_point(end_mcs, start, shift)
        else:
            end = (float(end_wcs["X"]) if "X" in end_wcs else start[0],
                   float(end_wcs["Y"]) if "Y" in end_wcs else start[1],
                   float(end_wcs["Z"]) if "Z" in end_wcs else start[2])
        kind = motion.kind
        if kind == "G2" or kind == "G3":
            points = self._points_in_blank(motion, start, end, shift) if in_blank else self._points(motion, start, end)
        else:
            points = None
        # Each chord starts where the one before ends; its length as numpy's norm of one row
        # ((dx² + dy²) + dz²), the lengths summed in numpy's pairwise order (one chord: itself).
        if points is None:  # a straight move is one chord
            dx, dy, dz = end[0] - start[0], end[1] - start[1], end[2] - start[2]
            length = math.sqrt(dx * dx + dy * dy + dz * dz)
            self._starts.extend(start)
            self._ends.extend(end)
            self.counts.append(1)
        else:
            starts = [*start, *points[:-3]]
            lengths = []
            for i in range(0, len(points), 3):
                dx, dy, dz = points[i] - starts[i], points[i + 1] - starts[i + 1], points[i + 2] - starts[i + 2]
                lengths.append(math.sqrt(dx * dx + dy * dy + dz * dz))
            length = pairwise_sum(lengths)
            self._starts.extend(starts)
            self._ends.extend(points)
            self.counts.append(len(lengths))
        feed = DEFAULT_RAPID_MM_MIN if kind == "G0" or not motion.feed_mm_min else motion.feed_mm_min
        self.tool_times[self.tool] = self.tool_times.get(self.tool, 0.0) + length / feed
        # The first motion comes from wherever the machine stands (the reference point, beyond
        # the blank): it is drawn but cuts nothing (our choice; a real set-up starts clear).
        cutter = self._cutter() if not first else self._no_cutter()
        n = motion.source.n if motion.source.n is not None else -1
        line = self._main_line_of.pop(id(motion), None) or motion.source.line or 0
        # Tapping and thread cutting (G331 after SPOS, G33, G63) turn the spindle with the axes
        # (002 L19681): not a cut with the spindle stopped, as the machine's contact watch says.
        turning_spindle = self.spindle_on or kind in THREAD_AND_TAPPING_KINDS
        self._meta.extend((line, kind == "G0", self.tool, cutter, turning_spindle, n))
        if motion.feed is not None:
            self.feed = motion.feed
        self.states.append(self._state(motion.gcodes))
        self.position = end

    def _state(self, gcodes: Any) -> ModalState:
        """The modal state in force, shared with every motion that has the same (the motions'
        own G code tables are not kept: one per motion was most of a long program's memory)."""
        gcodes = gcodes or {}
        seen = self._shown_of.get(id(gcodes))
        if seen is not None and seen[0] is gcodes:
            shown = seen[1]
        else:
            shown = tuple(gcodes.get(g) for g in SHOWN_GROUPS)
            if len(self._shown_of) >= SHOWN_TABLES_KEPT:
                self._shown_of.clear()
            self._shown_of[id(gcodes)] = (gcodes, shown)
        key = (shown, self.feed, self.tool, self.edge, self.speed_rpm)
        state = self._state_of.get(key)
        if state is None:
            groups = {g: code for g, code in zip(SHOWN_GROUPS, shown) if code}
            state = self._state_of[key] = ModalState(groups, self.feed, self.tool, self.edge, self.speed_rpm)
        return state

    def _length(self) -> float:
        """Length 1 with its wear of the active edge (along Z on the mill)."""
        edge = self.data.edge(self.tool, self.edge) if self.tool and self.edge > 0 else None
        return edge.get(3) + edge.get(12) if edge is not None else 0.0

    def _shift(self) -> Point:
        """What a toolholder reference point in the MCS less gives the tool tip in the blank's
        frame: the work offset of the first motion (:attr:`mcs_minus_wcs`) and the length 1 of
        the active edge along Z."""
        offset = self.mcs_minus_wcs or (0.0, 0.0, 0.0)
        return (offset[0], offset[1], offset[2] + self._length())

    @staticmethod
    def _blank_point(mcs: Mapping[str, float], keep: Point | None, shift: Point) -> Point:
        """A point of the toolholder reference in the MCS as the tool tip in the blank's frame
        (less ``shift``, :meth:`_shift`); axes missing: ``keep``'s."""
        return (float(mcs["X"]) - shift[0] if "X" in mcs else (keep[0] if keep is not None else 0.0),
                float(mcs["Y"]) - shift[1] if "Y" in mcs else (keep[1] if keep is not None else 0.0),
                float(mcs["Z"]) - shift[2] if "Z" in mcs else (keep[2] if keep is not None else 0.0))

    def _points_in_blank(self, motion: canon.Motion, start: Point, end: Point, shift: Point) -> list[float] | None:
        """The chords' end points (x, y, z after x, y, z) of a mill's arc in the blank's frame,
        from its MCS geometry (None: one chord): a frame that mirrors or rotates in the plane moves the cut where the
        machine cuts. An arc whose axis is not the plane's normal in the MCS (a frame tilting
        the plane) is one chord (our choice)."""
        if not motion.center_mcs:
            return None
        plane = _PLANE_INDEX.get(motion.plane, (0, 1))
        normal_axis = "XYZ"[3 - plane[0] - plane[1]]
        clockwise = motion.kind == "G2"
        if motion.arc_normal_mcs:
            component = float(motion.arc_normal_mcs.get(normal_axis, 0.0))
            if abs(component) < 0.999:
                return None
            clockwise = component < 0.0
        centre = self._blank_point(motion.center_mcs, start, shift)
        return self._arc_chords(start, end, (float(centre[plane[0]]), float(centre[plane[1]])), plane, clockwise,
                                motion.turns)

    def _points(self, motion: canon.Motion, start: Point, end: Point) -> list[float] | None:
        """The chords' end points (x, y, z after x, y, z) of an arc in the WCS (None: one chord)."""
        if not motion.center_wcs:
            return None
        plane = _PLANE_INDEX.get(motion.plane, (0, 1))
        centre = motion.center_wcs
        names = "XYZ"
        c = (float(centre.get(names[plane[0]], start[plane[0]])), float(centre.get(names[plane[1]], start[plane[1]])))
        return self._arc_chords(start, end, c, plane, motion.kind == "G2", motion.turns)

    def _arc_chords(self, start: Point, end: Point, centre: tuple[float, float], plane: tuple[int, int],
                    clockwise: bool, turns: int) -> list[float] | None:
        segment = arc_segment(np.array(start), np.array(end), centre, plane, clockwise, turns, _LINEAR_MASK)
        if segment.arc is None:
            return None
        radius = max(segment.arc[4], segment.arc[5])
        sweep = abs(segment.arc[7])
        step = 2.0 * math.acos(max(1.0 - self.tol / max(radius, 1e-9), -1.0)) if radius > self.tol else math.pi
        count = max(1, int(math.ceil(sweep / max(step, 1e-6))))
        # The chords' ends at equal path steps, as numpy's linspace(0, length, count + 1)[1:]
        # (i × step, the last exactly the length): the arc's length exceeds MIN_LENGTH_MM.
        # Python floats (Segment.points): an arc is mostly a few chords, where numpy's fixed
        # cost per call was most of the recorder's time for it.
        step_mm = segment.length / count
        points = segment.points([i * step_mm for i in range(1, count)] + [segment.length])
        points[-3:] = end
        return points

    def toolpath(self) -> Toolpath:
        if not self.counts:
            empty = np.zeros((0, 3))
            return Toolpath(empty, empty, np.zeros(0, np.int32), np.zeros(0, bool), np.zeros(0, np.int32),
                            self.cutters)
        # copies: the buffers grow on while a live recording goes on
        counts = np.array(self.counts, dtype=np.int64)
        meta = np.array(self._meta, dtype=np.int64).reshape(-1, 6)
        return Toolpath(
            starts=np.array(self._starts, dtype=np.float64).reshape(-1, 3),
            ends=np.array(self._ends, dtype=np.float64).reshape(-1, 3),
            lines=np.repeat(meta[:, 0], counts).astype(np.int32),
            rapid=np.repeat(meta[:, 1].astype(bool), counts),
            tools=np.repeat(meta[:, 2], counts).astype(np.int32),
            cutters=self.cutters,
            cutter_of=np.repeat(meta[:, 3], counts).astype(np.int32),
            spindle_on=np.repeat(meta[:, 4].astype(bool), counts),
            numbers=np.repeat(meta[:, 5], counts).astype(np.int64),
            motion_of=np.repeat(np.arange(len(counts)), counts),
            states=self.states,
        )


@dataclass
class Recording:
    """What :func:`record` collected from the AUTO run."""

    run: HeadlessRun
    path: Toolpath
    tool_times_s: dict[int, float]
    mcs_minus_wcs_mm: tuple[float, float, float] | None  # the work offset seen (no rotation)
    alarm_places: list[AlarmPlace]  # per alarm of the run, its main program's line


def record(
    name: str,
    text: str,
    *,
    machine: MachineConfig | None = None,
    programs: ProgramSource | None = None,
    data: NcData | None = None,
    resolution_mm: float = DEFAULT_RESOLUTION_MM,
    timeout_s: float | None = None,
    give_up: Callable[[int], bool] | None = None,
) -> Recording:
    """Run ``text`` as AUTO runs it; return the run, its executed toolpath (arcs as chords of at
    most an eighth of ``resolution_mm`` sagitta), the machining time per tool and the work
    offset (MCS − WCS of the tool tip without the tool length, from the first motion).
    ``give_up``: see :func:`nck.headless.run_on_kernel`."""
    machine = machine or load_machine()
    data = data if data is not None else NcData()
    source = programs if programs is not None else _NoPrograms()
    recorder = PathRecorder(data, chord_tol_mm=resolution_mm / 8.0, turning=machine.kind == "lathe", main=name)
    run = run_program(machine, source, data, name, text=text, timeout_s=timeout_s,
                      on_command=recorder, keep_commands=False, on_block=recorder.block, give_up=give_up)
    nominal = sum(recorder.tool_times.values())
    share = run.machine_time_s / nominal if nominal > 0.0 else 0.0
    tool_times = {t: s * share for t, s in recorder.tool_times.items() if s > 0.0}
    return Recording(run, recorder.toolpath(), tool_times, recorder.mcs_minus_wcs,
                     [recorder.place_of(alarm) for alarm in run.alarms])


def simulate(
    name: str,
    text: str,
    *,
    machine: MachineConfig | None = None,
    programs: ProgramSource | None = None,
    data: NcData | None = None,
    resolution_mm: float | None = DEFAULT_RESOLUTION_MM,
    blank: Blank | None = None,
    timeout_s: float | None = None,
    give_up: Callable[[int], bool] | None = None,
) -> Simulation:
    """Run ``text`` as main program ``name`` as AUTO runs it and cut the blank with it.

    ``blank`` overrides the program's ``WORKPIECE``; without either the blank is the machine
    set-up's clamped blank (unless the instructor hid it), else a box around the cutting moves.
    On a lathe (``machine.kind``) the blank is a bar and the model a rotational profile
    (:mod:`nck.simulation.turning`). ``data`` (tools, offsets) is used as the run's NC data:
    pass a copy.
    ``resolution_mm`` None: chosen from the blank's size (:func:`auto_resolution`).
    ``give_up`` is asked with the blocks run so far, every few simulated seconds; True ends the
    run there, as a timeout (see :func:`nck.headless.run_on_kernel`).
    """
    data = data if data is not None else NcData()
    machine = machine or load_machine()
    turning = machine.kind == "lathe"
    recording = record(name, text, machine=machine, programs=programs, data=data,
                       resolution_mm=resolution_mm or AUTO_CHORD_RESOLUTION_MM, timeout_s=timeout_s,
                       give_up=give_up)
    run, path, tool_times = recording.run, recording.path, recording.tool_times_s
    if blank is None:
        blank = choose_blank(text, data.machine_setup, recording.mcs_minus_wcs_mm, path, turning)
    model = material_model(blank, resolution_mm, turning)
    kept = Checkpoints(model.heights)
    events = sweep_path(model, path, done=lambda chords: kept.keep(chords, model.heights))
    return Simulation(blank, model, path, events, list(run.alarms), run.status, run.machine_time_s,
                      tool_times, run.blocks, kept, recording.alarm_places)


def choose_blank(text: str, setup: MachineSetup, offset: tuple[float, float, float] | None, path: Toolpath,
                 turning: bool) -> Blank:
    """The program's ``WORKPIECE``, else the set-up's clamped blank (unless hidden; needs the
    work ``offset`` MCS − WCS), else a box (lathe: a bar) around the cutting moves of ``path``."""
    blank = blank_from_text(text)
    if blank is None and setup.blank is not None and not setup.hidden and offset is not None:
        if turning and isinstance(setup.blank, Cylinder):
            back = setup.blank.base_mcs[2] - offset[2]
            blank = bar(setup.blank.diameter_mm, back, back + setup.blank.length_mm)
        elif not turning:
            blank = blank_from_setup(setup.blank, offset)
    return blank if blank is not None else blank_for(path, turning)


def material_model(blank: Blank, resolution_mm: float | None, turning: bool) -> ZMap | TurnProfile:
    """The uncut ``blank``: a Z-map, on a lathe a rotational profile (resolution None: chosen
    from the blank's size)."""
    if turning:
        return TurnProfile(blank, resolution_mm or auto_resolution(blank, turning=True))
    return ZMap(blank, resolution_mm or auto_resolution(blank))


def auto_resolution(blank: Blank, turning: bool = False) -> float:
    """A cell size for showing ``blank``: about 400 cells along its longer side (a bar: along Z,
    at least 0.05 mm), 0.1 … 2 mm."""
    if turning:
        return min(max((blank.z_mm[1] - blank.z_mm[0]) / AUTO_CELLS, 0.05), 2.0)
    longest = max(blank.x_mm[1] - blank.x_mm[0], blank.y_mm[1] - blank.y_mm[0])
    return min(max(longest / AUTO_CELLS, 0.1), 2.0)


def sweep_path(zmap: ZMap | TurnProfile, path: Toolpath, upto: int | None = None, first: int = 0,
               done: Callable[[int], None] | None = None) -> list[SimEvent]:
    """Sweep the chords ``first`` … ``upto`` of ``path`` (to the end: None) through ``zmap``;
    return the events.

    Rapid moves and moves with the spindle stopped are swept on their own (so that their cut
    is theirs alone); runs of cutting chords with the same cutter go in one batch.
    ``done(k)`` is called whenever the model holds the state after the first ``k`` chords (after
    every batch; a Z-map also within one).
    """
    total = len(path.starts) if upto is None else min(upto, len(path.starts))
    events: list[SimEvent] = []
    if total <= first:
        return events
    cutter_of = path.cutter_of[first:total]
    alone = path.rapid[first:total] | ~path.spindle_on[first:total]
    # A new batch starts where the cutter changes or at every chord that must go alone.
    breaks = np.flatnonzero((np.diff(cutter_of) != 0) | alone[1:] | alone[:-1]) + 1 + first
    bounds = np.concatenate(([first], breaks, [total]))
    for begin, end in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
        cutter = path.cutters[int(path.cutter_of[begin])] if len(path.cutters) else None
        if cutter is None:
            continue
        if isinstance(zmap, ZMap):
            within = None if done is None else (lambda moves, begin=begin: done(begin + moves))
            depth = zmap.sweep(path.starts[begin:end], path.ends[begin:end], cutter, done=within)  # type: ignore[arg-type]
        else:
            depth = zmap.sweep(path.starts[begin:end], path.ends[begin:end], cutter)  # type: ignore[arg-type]
        if done is not None:
            done(end)
        if alone[begin - first] and depth.size and float(depth.max()) > CUT_EPSILON_MM:
            kind = "rapid_cut" if path.rapid[begin] else "spindle_stopped"
            _add_event(events, path, kind, begin, float(depth.max()))
        length = getattr(cutter, "length_mm", 0.0)
        if length > 0.0 and depth.size:
            for chord in (np.flatnonzero(depth > length + CUT_EPSILON_MM) + begin).tolist():
                _add_event(events, path, "holder_in_material", chord, float(depth[chord - begin]))
    return events


def _add_event(events: list[SimEvent], path: Toolpath, kind: str, chord: int, depth_mm: float) -> None:
    """Add an event at ``chord``; one per block and kind in a row (the deepest)."""
    line = int(path.lines[chord]) or None
    number = int(path.numbers[chord]) if len(path.numbers) and path.numbers[chord] >= 0 else None
    if events and events[-1].line == line and events[-1].kind == kind:
        events[-1] = SimEvent(kind, line, number, max(events[-1].depth_mm, depth_mm))
    else:
        events.append(SimEvent(kind, line, number, depth_mm))


def blank_for(path: Toolpath, turning: bool = False) -> Blank:
    """A box (lathe: a bar) around the cutting moves of ``path`` (:func:`blank_around`,
    :func:`nck.simulation.turning.bar_around`)."""
    cutting = ~path.rapid
    points = path.ends[cutting] if np.any(cutting) else path.ends
    reach = max((c.reach_mm for c in path.cutters if c is not None), default=0.0)
    return bar_around(points, reach) if turning else blank_around(points, reach)


class _NoPrograms:
    """A program source without programs (subprogram calls are 14011)."""

    def read_program(self, name: str) -> tuple[str, str] | None:
        return None
