"""Program control and overrides, a part of :class:`nck.kernel.Nck`.

Program control: single block SBL1/SBL2, M01, dry run (SD42100 feed with the
SD42101 mode, handed to the motion, which applies it to every segment not yet
started, so a switch during NC STOP or at block end reaches the buffered
blocks), program test (switched only in channel reset; the program runs on a
simulated copy of the axes, ``MachinePlant.test_motion``), rapid override (ROV)
and skip levels (changed only in STOP or RESET). The switches themselves are
:class:`nck.channel_state.ControlSwitches`; this part checks and applies them.
"""

from __future__ import annotations

from typing import Any, cast

from nck import commands as cmd
from nck.channel import ACTIVE, RESET
from nck.channel_state import ChannelState, ControlSwitches, MachinePlant
from nck.commands import Accepted, SubmitResult
from nck.interp.api import Interpreter
from nck.kernel_interpreters import ChannelInterpreters
from nck.kernel_search import BlockSearchControl
from nck.motion.instant import InstantMotion
from nck.ncdata import NcData
from nck.refusals import refuse

DEFAULT_DRY_RUN_MM_MIN = 5000.0  # SD42100 DRY_RUN_FEED
# 002 L56312-56319: path feed and spindle 0 … 200 %, rapid traverse 0 … 100 %
# (the switches of the panel have fewer positions, see the keymap).
OVERRIDE_LIMITS_PERCENT = {"feed": (0.0, 200.0), "rapid": (0.0, 100.0), "spindle": (0.0, 200.0)}


class ControlSettings:
    """The program-control and override switches, checked and handed to motion and interpreters."""

    def __init__(self, plant: MachinePlant, data: NcData, channel: ChannelState, switches: ControlSwitches,
                 interpreters: ChannelInterpreters, search: BlockSearchControl) -> None:
        self.plant = plant  # the machine's motion and the simulated axes of program test
        self.data = data  # the setting data of the dry run (SD42100, SD42101)
        self.channel = channel
        self.switches = switches
        self.interpreters = interpreters  # get the skip levels and the dry-run flag
        self.search = search  # refuses program test and dry run during SERUPRO

    # -------------------------------------------------------------- commands
    def set_program_control(self, command: cmd.SetProgramControl) -> SubmitResult:
        """Switch single block, dry run, M01, rapid override, program test or the skip levels."""
        name, value = command.name, command.value
        refused = self.search.refuse_selection_in_serupro(name)
        if refused is not None:
            return refused
        if name == "single_block":
            text = None if value in (None, False, "") else str(value).upper()
            if text == "SBL3":
                text = "SBL2"
            if text not in (None, "SBL1", "SBL2"):
                return refuse("single_block_values")
            self.switches.program_control[name] = text
        elif name in ("dry_run", "m01", "rapid_override"):
            self.switches.program_control[name] = bool(value)
            self.apply_overrides()
            self.apply_dry_run()
        elif name == "program_test":
            if self.channel.situation.channel != RESET:
                return refuse("program_test_needs_reset")
            self.switches.program_control[name] = bool(value)
            self.plant.test_motion = (
                InstantMotion(self.plant.machine, self.plant.motion.positions_mcs()) if value else None
            )
            self.apply_overrides()
            self.apply_dry_run()
        elif name == "skip_levels":
            try:
                levels = frozenset(int(v) for v in cast(Any, value or ()))
            except (TypeError, ValueError):
                return refuse("skip_level_values")
            if any(level < 0 or level > 9 for level in levels):
                return refuse("skip_level_values")
            if self.channel.situation.channel == ACTIVE:
                return refuse("skip_levels_need_stop")
            self.switches.program_control[name] = levels
            for interp in self.interpreters.all():
                self.apply_skip_levels(interp)
        else:
            return refuse("unknown_program_control", name=repr(name))
        return Accepted()

    def set_override(self, command: cmd.SetOverride) -> SubmitResult:
        """Turn the feed, rapid or spindle override switch (percent)."""
        if command.which not in OVERRIDE_LIMITS_PERCENT:
            return refuse("unknown_override", which=repr(command.which))
        low, high = OVERRIDE_LIMITS_PERCENT[command.which]
        percent = float(command.percent)
        if not low <= percent <= high:
            return refuse("override_range", which=command.which, low=f"{low:g}", high=f"{high:g}")
        self.switches.overrides[command.which] = percent
        self.apply_overrides()
        return Accepted()

    def set_controller_enable(self, command: cmd.SetControllerEnable) -> SubmitResult:
        """Switch the controller enable of a machine axis."""
        set_enable = getattr(self.plant.motion, "set_controller_enable", None)
        if set_enable is None or command.axis not in self.plant.machine.path_axes:
            return refuse("no_machine_axis", axis=command.axis)
        set_enable(command.axis, command.enabled)
        return Accepted()

    def set_spindle_drive_fault(self, command: cmd.SetSpindleDriveFault) -> SubmitResult:
        """Inject (or remove) a spindle drive fault that keeps its actual speed low."""
        spindle = (getattr(self.plant.motion, "spindles", None) or {}).get(command.spindle)
        if spindle is None:
            return refuse("no_spindle", spindle=command.spindle)
        spindle.drive_limit_rpm = None if command.limit_rpm is None else abs(float(command.limit_rpm))
        return Accepted()

    # ------------------------------------------------------------- applying
    def apply_skip_levels(self, interp: Interpreter) -> None:
        """Hand the skip levels to ``interp``."""
        levels = frozenset(cast("frozenset[int]", self.switches.program_control["skip_levels"]))
        setter = getattr(interp, "set_skip_levels", None)
        if setter is not None:
            setter(levels)
        elif hasattr(interp, "skip_levels"):
            interp.skip_levels = levels  # type: ignore[attr-defined]

    def apply_dry_run(self) -> None:
        """Hand the dry run (SD42100 feed, SD42101 mode) or its absence to the motion systems
        and to the interpreters ($P_DRYRUN); called on the switch, at NC START (setting data
        written meanwhile) and for a new program-test motion."""
        on = bool(self.switches.program_control["dry_run"])
        feed = float(self._setting("SD42100", DEFAULT_DRY_RUN_MM_MIN)) if on else None
        mode = int(self._setting("SD42101", 0))
        for motion in (self.plant.motion, self.plant.test_motion):
            if motion is not None:
                motion.set_dry_run(feed, mode)
        for interp in self.interpreters.all():
            flags = getattr(interp, "flags", None)
            if isinstance(flags, dict):
                flags["dry_run"] = on

    def apply_overrides(self) -> None:
        """Hand the override switches to the machine's motion and to the simulated axes."""
        spindle = getattr(self.plant.motion, "set_spindle_override", None)
        if spindle is not None:
            spindle(self.switches.overrides["spindle"])
        feed = self.switches.overrides["feed"]
        # 002 L56369-56370: the feed switch acting as rapid override counts at most 100 %.
        rapid = min(feed, 100.0) if self.switches.program_control["rapid_override"] else self.switches.overrides["rapid"]
        for motion in (self.plant.motion, self.plant.test_motion):
            if motion is not None:
                motion.set_overrides(feed, rapid)

    def _setting(self, name: str, default: object) -> Any:
        value = self.data.setting_data.get(name)
        if value is None:
            return default
        return value


__all__ = ["ControlSettings", "DEFAULT_DRY_RUN_MM_MIN"]
