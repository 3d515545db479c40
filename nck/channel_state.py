"""The kernel's mutable state, each field declared once with its one owner.

:class:`ChannelState` is the channel: its mode/channel/program situation (the transition table
of :mod:`nck.channel`), the program run, the MDA overlay, the interrupted program and its
REPOS point, manual traversing and the emergency stop. :class:`ControlSwitches` holds the
operator's program-control switches and override positions; :class:`MachineOutputs` holds
what the main run has output to the machine (active tool and edge, spindle, auxiliary
functions, the work offset of the last segment); :class:`MachinePlant` the machine, the
motion system moving its axes and the simulated axes of program test. ``Nck`` creates one of
each and hands them to its parts (the status snapshot, block search, manual traversing,
contact watch, program control, data writes).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from nck.basic_blocks import BasicBlockLog
from nck.canon import Dwell, Motion, SpindleCommand
from nck.channel import ChannelSituation, next_state
from nck.machine import MachineConfig
from nck.motion.instant import InstantMotion
from nck.program_control import ProgramRun

OVERRIDE_NAMES = ("feed", "rapid", "spindle")


def _default_program_control() -> dict[str, object]:
    return {"single_block": None, "dry_run": False, "m01": False, "program_test": False,
            "rapid_override": False, "skip_levels": frozenset()}


@dataclass
class ChannelState:
    """Mode, channel and program state of the one channel (see the module docstring)."""

    situation: ChannelSituation = field(default_factory=ChannelSituation)
    machine_function: str | None = None  # REF, REPOS, INC or None (JOG continuous)
    increment: int | None = 1  # INC 1 … 10000 (0.001 mm); None = VAR (SD41010)
    inc_waiting_for_jog: bool = False  # INC was active when JOG was left for MDA
    selected: str | None = None  # the program selected for AUTOMATIC
    mda_text: str = ""  # the MDA buffer
    run: ProgramRun | None = None  # the program running (or stopped) in the channel
    overlay: ProgramRun | None = None  # MDA blocks over an interrupted AUTO program
    owner: str | None = None  # mode whose program is stopped/interrupted
    parked: list[Motion | Dwell] | None = None  # unexecuted motion of the parked program
    repos_point: dict[str, float] | None = None  # interruption point (REPOS), MCS
    offsets_edited: bool = False  # a work offset was edited while stopped with MD9440 = 1
    serupro: bool = False  # a search run by program test is under way
    serupro_spindle: SpindleCommand | None = None  # switched on by the NC START after SERUPRO
    estop_pressed: bool = False  # the emergency stop button is pressed
    estop_active: bool = False  # emergency stop in effect (until RESET after release)
    jogging: bool = False  # a manual motion (JOG, INC, REF, REPOS) is under way
    jog_targets: dict[str, float] = field(default_factory=dict)  # axis -> MCS end of the increments pressed
    jog_rest: dict[str, float] = field(default_factory=dict)  # axis -> increment left by NC STOP
    basic_blocks: BasicBlockLog | None = None  # the basic block display of the newest run, kept after its end

    def transition(self, event: str) -> None:
        """Follow ``event`` in the transition table of :mod:`nck.channel` (no change where it has none)."""
        new = next_state(self.situation, event)
        if new is not None:
            self.situation = new

    def begin_run(self, run: ProgramRun) -> None:
        """A program starts from reset: it is the run, nothing is interrupted or parked."""
        self.run = run
        self.owner = None
        self.repos_point = None
        self.parked = None

    def adopt_searched_run(self, run: ProgramRun) -> None:
        """Block search found its target: ``run`` stands there, as an interrupted AUTO program."""
        self.run = run
        self.overlay = None
        self.owner = "AUTO"
        self.repos_point = None
        self.parked = None

    def stop_manual_motion(self) -> None:
        """No manual motion any more, nothing to continue with NC START."""
        self.jogging = False
        self.jog_targets.clear()
        self.jog_rest.clear()

    def clear_programs(self) -> None:
        """RESET (or an internal error): no run, no overlay, no interruption, no manual motion."""
        self.run = None
        self.overlay = None
        self.owner = None
        self.stop_manual_motion()
        self.repos_point = None
        self.parked = None

    def active_run(self) -> ProgramRun | None:
        """The run the channel feeds now: the MDA overlay over an interrupted program, else the run."""
        return self.overlay or self.run


@dataclass
class ControlSwitches:
    """The operator's program-control switches and override switch positions."""

    program_control: dict[str, object] = field(default_factory=_default_program_control)
    overrides: dict[str, float] = field(default_factory=lambda: dict.fromkeys(OVERRIDE_NAMES, 100.0))

    @property
    def program_test(self) -> bool:
        """Program test (PRT) is selected: programs run on a simulated copy of the axes."""
        return bool(self.program_control["program_test"])


@dataclass
class MachineOutputs:
    """What the main run has output to the machine (the interpreter is ahead of it)."""

    tool: int = 0  # the active tool (after the change)
    edge: int = 0  # the active cutting edge (D)
    spindle_state: str = "M5"  # M3, M4 or M5 of the master spindle as programmed
    spindle_rpm: float = 0.0  # its programmed speed
    aux: dict[str, str] = field(default_factory=dict)  # address (+ extension) -> value, e.g. "T", "M"
    wcs_offset: dict[str, float] = field(default_factory=dict)  # axis -> MCS - WCS of the last segment


@dataclass
class MachinePlant:
    """The active machine and the motion system that moves its axes; both are replaced when
    stored machine data come into effect, so parts hold the plant, not the two objects.
    Under program test the program runs on ``test_motion``, a simulated copy of the axes."""

    machine: MachineConfig
    motion: Any
    test_motion: InstantMotion | None = None  # the simulated axes under program test (None: none)

    def positions(self, motion: Any = None) -> dict[str, float]:
        """Actual MCS positions of the path axes (no spindles) of ``motion`` (default: the machine's)."""
        positions = (self.motion if motion is None else motion).positions_mcs()
        return {axis: float(positions[axis]) for axis in self.machine.path_axes if axis in positions}
