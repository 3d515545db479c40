"""Immutable status snapshots: what the kernel shows the outside world.

``Nck.status()`` builds one :class:`NckStatus` per tick; ``seq`` increases
whenever anything in it changed, so a display can skip unchanged frames.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

from nck.canon import FEED_PER_REVOLUTION


@dataclass(frozen=True, slots=True)
class AxisStatus:
    """One machine axis or spindle as the position and service screens show it."""

    name: str
    kind: str  # "linear", "rotary" or "spindle"
    position_mcs: float
    position_wcs: float
    distance_to_go: float = 0.0
    referenced: bool = False
    setpoint_mcs: float = 0.0
    velocity: float = 0.0  # mm/min (linear), deg/min (rotary), rpm (spindle)
    following_error: float = 0.0
    speed_rpm: float = 0.0
    extra: Mapping[str, float] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class AlarmEntry:
    """An active alarm or an entry of the alarm log.

    ``seq`` orders the log; ``came_s``/``went_s`` are simulated-control times.
    """

    seq: int
    number: int
    text: str
    category: str
    clear: str
    came_s: float
    went_s: float | None = None
    params: tuple[str, ...] = ()
    file: str | None = None
    line: int | None = None
    n: int | None = None


@dataclass(frozen=True, slots=True)
class ModalView:
    """The modal state a display needs: G groups, tool, feed, spindle."""

    gcodes: Mapping[int, str] = field(default_factory=dict)
    tool: int = 0
    edge: int = 0
    feed: float = 0.0
    spindle_speed_rpm: float = 0.0
    spindle_state: str = "M5"
    aux: Mapping[str, str] = field(default_factory=dict)
    tool_name: str = ""  # name of the active tool when it has one (T="CUTTER_10")
    tool_length_mm: float = 0.0  # length 1 of the active edge (geometry + wear), for the T,F,S window
    tool_radius_mm: float = 0.0  # radius of the active edge (geometry + wear)
    iso_gcodes: Mapping[int, str] = field(default_factory=dict)  # ISO group → code; empty in Siemens mode

    @property
    def feed_per_revolution(self) -> bool:
        """Whether F is a feed per revolution (G95, G96, G97 …) rather than per minute."""
        return self.gcodes.get(15) in FEED_PER_REVOLUTION


@dataclass(frozen=True, slots=True)
class BlockView:
    """A displayed program block."""

    file: str
    line: int
    text: str


@dataclass(frozen=True, slots=True)
class ChannelStatus:
    """Channel 1: states, program, program control, block display."""

    mode: str = "JOG"
    machine_function: str | None = None
    increment: int | None = 1
    channel_state: str = "reset"  # reset / active / interrupted
    program_state: str = "aborted"  # aborted / running / stopped / interrupted / waiting
    selected_program: str | None = None
    current_block: BlockView | None = None
    blocks: tuple[BlockView, ...] = ()
    basic_blocks: tuple[BlockView, ...] = ()  # the basic block display (nck.basic_blocks) around the executing block
    basic_block_index: int = -1  # the executing block's place in basic_blocks; -1: none of them
    modal: ModalView = field(default_factory=ModalView)
    program_control: Mapping[str, object] = field(default_factory=dict)
    overrides: Mapping[str, float] = field(default_factory=dict)
    path_feed_mm_min: float = 0.0
    program_runtime_s: float = 0.0
    part_count: int = 0
    message: str = ""
    stop_reason: str = ""  # why the channel stands: "NC STOP", "M0", "M1", "single block", "alarm", "search target found", "10208"
    interrupted_program: str | None = None  # "AUTO" or "MDA" while that program is interrupted/stopped
    mda_text: str = ""  # the MDA buffer
    program_runtime_last_s: float = 0.0  # $AC_OLD_PROG_NET_TIME
    program_runtime_count: int = 0  # $AC_OLD_PROG_NET_TIME_COUNT
    parts_total: int = 0  # $AC_TOTAL_PARTS (part_count is $AC_ACTUAL_PARTS)
    parts_required: int = 0  # $AC_REQUIRED_PARTS
    parts_special: int = 0  # $AC_SPECIAL_PARTS
    repos_offsets: Mapping[str, float] = field(default_factory=dict)  # axis -> way back to the interruption point


@dataclass(frozen=True, slots=True)
class NckStatus:
    """The whole kernel as seen from outside at one instant of simulated time."""

    seq: int
    time_s: float
    channel: ChannelStatus
    axes: tuple[AxisStatus, ...]
    alarms: tuple[AlarmEntry, ...] = ()
    access_level: int = 7
    machine_name: str = ""
    emergency_stop: bool = False  # E-stop active (pressed, or released but not yet reset)
    mode_group_ready: bool = True
    alarm_log_seq: int = 0  # newest entry of the alarm/message log (Nck.alarm_log_since)
    internal_errors: int = 0  # count of internal errors (alarm 1) since power on
    keyswitch_position: int | None = None  # 0…3; None for a kernel without access control (the HMI's Alt+T cycles it)


@dataclass(frozen=True, slots=True)
class AlarmEvent:
    """One entry of the kernel's append-only alarm/message log (``Nck.alarm_log_since``).

    ``kind`` is ``"came"`` or ``"went"`` for alarms, ``"message"`` for an NC
    message (MSG) being shown or cleared (empty text). ``entry`` is the alarm
    as it was at that moment (for ``went``, with ``went_s`` set); ``entry.seq``
    identifies the alarm occurrence, ``seq`` orders the log.
    """

    seq: int
    kind: str
    time_s: float
    entry: AlarmEntry


@dataclass(frozen=True, slots=True)
class LogbookEntry:
    """One line of the diagnosis logbook (``Nck.logbook``): an access-level or MD/SD change.

    ``kind`` is ``"access"`` or ``"data"``; ``time_s`` is simulated-control time.
    """

    time_s: float
    kind: str
    text: str
