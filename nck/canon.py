"""Canonical commands: what the interpreter emits and the channel/planner consume.

The interpreter never moves anything; it turns each block into a list of these
immutable records. Positions are dictionaries keyed by axis name. ``*_wcs``
values are in program units in the workpiece coordinate system of the
programmed tool tip; ``*_mcs`` values are machine coordinates in millimetres
(tool length compensation applied).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping


FEED_PER_REVOLUTION = frozenset({"G95", "G96", "G97", "G952", "G962", "G972"})
THREAD_AND_TAPPING_KINDS = frozenset({"G33", "G34", "G35", "G331", "G332", "G63"})
"""Motion kinds of thread cutting (G33, G34, G35) and tapping (G331, G332 without, G63 with
compensating chuck): the spindle turns with the axes (002 L19681), so they cut without M3/M4;
dry run modes 10-12 leave their feed as programmed (002 L18151-18182)."""
"""Feed types (G group 15) whose F is a feed per revolution of the master spindle: G95, and
G96/G97 "as with G95" (001 L2584: with G97 the feedrate is a revolutional feedrate; 002 L5773).
G961/G971 keep a linear feed."""

@dataclass(frozen=True, slots=True)
class Source:
    """Where a command came from: program file, 1-based line, block number."""

    file: str
    line: int
    n: int | None = None


@dataclass(slots=True)
class Motion:
    """One path segment (G0, G1, G2, G3, G33, …).

    Immutable by contract like every command here, but not a frozen dataclass: a frozen one
    sets each of its 23 fields through ``object.__setattr__`` (~2.8 against ~0.9 us per motion,
    one motion per block); change one with :func:`dataclasses.replace`, never in place.

    Attributes:
        kind: the motion G code as displayed: ``G0``, ``G1``, ``G2``, ``G3``, ``G33``.
        source: the block that caused it (NC-inserted segments carry their cause).
        plane: active plane ``G17`` / ``G18`` / ``G19``.
        end_wcs: end point in the WCS, program units.
        end_mcs: end point in the MCS, mm.
        start_mcs: start point in the MCS, mm (lets the planner work per segment).
        center_wcs: arc centre in the WCS (arcs only).
        center_mcs: arc centre in the MCS, mm (arcs only).
        turns: extra full turns of a helix (``TURN=``).
        feed: the programmed F value in force, in its own units (for display/segments).
        feed_mm_min: path feed converted to mm/min (``None`` for rapid traverse).
        feed_mm_rev: revolutional feed (G95/G96/G97) or thread lead (G33) in mm per
            revolution of the master spindle: the motion takes the path feed from the
            spindle's speed when the block runs (002 L55411-55420); ``feed_mm_min`` is
            then the value at the programmed speed (estimates). None otherwise.
        accel_pct: ``ACC[axis]`` factors (percent of MD32300) of axes not at 100 %, or None.
        exact_stop: True if this block ends with exact stop (G60 modal or G9).
        exact_stop_window: ``G601`` fine or ``G602`` coarse.
        lead_mm: thread lead for G33 (mm per spindle revolution).
        thread_start_deg: G33 only: the spindle angle after the zero mark at which the thread
            starts (``SF=``, SD42000); None for other motions.
        gcodes: the active member of every G group (group number -> G code) at this block.
        inserted: True for segments inserted by the NC (chamfers, roundings, cycle moves).
        arc_normal_mcs: arcs only: unit vector in the MCS about which the arc turns
            counter-clockwise (right-hand rule). ``kind`` stays the programmed G2/G3;
            a mirroring or rotating frame can make the machine turn the other way or in
            another plane: G3 in G17 without frames gives ``{"X": 0, "Y": 0, "Z": 1}``,
            G2 gives Z = -1; with ``MIRROR X0`` a G2 gives Z = +1.
        contour_end_wcs: with tool radius compensation active, the programmed contour end
            point of the block (``end_wcs`` is then the compensated tool path); None
            otherwise and for NC-inserted segments.
        contour_center_wcs: likewise the programmed arc centre (arcs only).
        measure: ``"MEAS"`` (measuring with delete distance to go) or ``"MEAW"`` (without)
            when the block programmed ``MEAS=``/``MEAW=`` for the probe; None otherwise.
    """

    kind: str
    source: Source
    plane: str
    end_wcs: Mapping[str, float]
    end_mcs: Mapping[str, float]
    start_mcs: Mapping[str, float] = field(default_factory=dict)
    center_wcs: Mapping[str, float] | None = None
    center_mcs: Mapping[str, float] | None = None
    turns: int = 0
    feed: float | None = None
    feed_mm_min: float | None = None
    feed_mm_rev: float | None = None
    accel_pct: Mapping[str, float] | None = None
    exact_stop: bool = False
    exact_stop_window: str = "G601"
    lead_mm: float | None = None
    thread_start_deg: float | None = None
    gcodes: Mapping[int, str] = field(default_factory=dict)
    inserted: bool = False
    arc_normal_mcs: Mapping[str, float] | None = None
    contour_end_wcs: Mapping[str, float] | None = None
    contour_center_wcs: Mapping[str, float] | None = None
    measure: str | None = None


@dataclass(frozen=True, slots=True)
class Dwell:
    """G4: wait ``seconds`` of time or ``revolutions`` of the spindle; with ``wait_spindle``
    (SPOS, M19, WAITS) wait until the master spindle is positioned, stands or turns in
    its set speed range (002 L51302-51335); with ``feed_enable`` too, the machining block
    after a programmed speed change waits so (MD35500, 002 L54545-54562). ``gcodes`` (the
    active member of every G group) and ``feed`` (the programmed F in force, in its own
    units) are the block's modal state, shown while the dwell runs."""

    source: Source
    seconds: float | None = None
    revolutions: float | None = None
    wait_spindle: bool = False
    gcodes: Mapping[int, str] = field(default_factory=dict)
    feed: float | None = None
    feed_enable: bool = False  # with wait_spindle: a machining block waits for the set speed range (MD35500)


@dataclass(frozen=True, slots=True)
class ExactStop:
    """An implicit exact stop: the block before ends with its exact-stop criterion before this
    block goes on (an auxiliary function output before the motion, or a block with outputs
    but no path motion, 002 L4797-4809). The channel pushes it as a zero-time wait."""

    source: Source


@dataclass(frozen=True, slots=True)
class AuxFunction:
    """An auxiliary function output to the PLC: M, S, T, D, H or F with extension."""

    source: Source
    address: str
    value: float
    extension: int | None = None


@dataclass(frozen=True, slots=True)
class ToolSelect:
    """T (select) and, if the tool change happens in this block, the change itself."""

    source: Source
    tool: int
    change: bool


@dataclass(frozen=True, slots=True)
class EdgeSelect:
    """D: the active cutting edge (0 deselects tool offsets)."""

    source: Source
    edge: int


@dataclass(frozen=True, slots=True)
class SpindleCommand:
    """Spindle speed / direction / positioning for spindle number ``spindle``.

    ``state`` is ``M3``, ``M4``, ``M5`` or ``M19``/``SPOS`` for positioning to
    ``position_deg`` along ``approach`` at ``positioning_rpm`` (None: the configured speed).
    """

    source: Source
    spindle: int
    state: str | None = None
    speed_rpm: float | None = None
    position_deg: float | None = None
    approach: str | None = None  # SPOS approach: DC (shortest), AC, ACP (+), ACN (-), IC
    positioning_rpm: float | None = None  # FA[S<n>] for SPOS/M19; None: MD35300 (002 L51375-51385)
    speed_change: bool = False  # M3/M4 or S programmed: the next machining block checks the speed (MD35500)


@dataclass(frozen=True, slots=True)
class Message:
    """``MSG("…")``: show a message; empty text clears it."""

    source: Source
    text: str


@dataclass(frozen=True, slots=True)
class StopPoint:
    """A point where the channel must act: ``M0``, ``M1``, ``STOPRE``."""

    source: Source
    kind: str


@dataclass(frozen=True, slots=True)
class ProgramEnd:
    """End of the main program: ``M2``, ``M30`` (or ``M17`` at main level)."""

    source: Source
    kind: str


# The program ends by an end command: after them MD35040 = 0 brakes the spindle and deletes S
# and direction (002 L51017-51035 name M2 and M30; M17 ends a main program the same way), and
# no tool stays preselected. Our choice: an MDA buffer or a main program that simply runs out
# (kind "EOF") is no such end, so `S1000 M3` or `T1` in MDA leave the spindle turning and the
# tool preselected for the next MDA block (`M6`), as an operator setting up expects.
END_COMMANDS = frozenset({"M2", "M30", "M17"})


@dataclass(frozen=True, slots=True)
class UserAlarm:
    """``SETAL(n)``: a cycle/user alarm raised by the program."""

    source: Source
    number: int
    params: tuple[str, ...] = ()


CanonCommand = (
    Motion | Dwell | ExactStop | AuxFunction | ToolSelect | EdgeSelect | SpindleCommand | Message
    | StopPoint | ProgramEnd | UserAlarm
)
