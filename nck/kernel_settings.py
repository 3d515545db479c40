"""Switches and data for :class:`nck.kernel.Nck`: program control, overrides,
written data, access (a mixin).

Program control: single block SBL1/SBL2, M01, dry run (SD42100 feed with the
SD42101 mode, handed to the motion, which applies it to every segment not yet
started, so a switch during NC STOP or at block end reaches the buffered
blocks), program test (switched only in channel reset; the program runs on a
simulated copy of the axes), rapid override (ROV) and skip levels (changed
only in STOP or RESET).
"""

from __future__ import annotations

from typing import Any, Callable, cast

from nck.channel_state import ChannelState, ControlSwitches, MachineOutputs
from nck import commands as cmd
from nck.access import (ALARM_PASSWORD_REFUSED, AccessControl, AccessError, AccessLocked, AccessState, Action,
                        action_for_write)
from nck.alarms import AlarmServer
from nck.canon import Motion
from nck.channel import ACTIVE, RESET
from nck.commands import Accepted, Rejected, SubmitResult
from nck.counters import PartCounters
from nck.interp.api import Interpreter
from nck.kernel_data import DataWrites
from nck.kernel_interpreters import ChannelInterpreters
from nck.kernel_search import BlockSearchControl
from nck.kernel_setup import JobSetup
from nck.machine import MachineConfig
from nck.ncdata import NcData
from nck.value_text import InvalidValue, number_from_text
from nck.motion.instant import InstantMotion
from nck.status import LogbookEntry

DEFAULT_DRY_RUN_MM_MIN = 5000.0  # SD42100 DRY_RUN_FEED


class ControlSettings(DataWrites):
    """Program control, overrides, data writes, keyswitch and passwords; mixed into ``Nck``:
    what it uses of the kernel is declared here."""

    machine: MachineConfig
    motion: Any
    data: NcData
    channel: ChannelState  # the channel's state (nck.channel_state)
    switches: ControlSwitches  # the program-control and override switches it sets
    outputs: MachineOutputs
    counters: PartCounters  # $AC_…_PARTS written through WriteData
    logbook: list[LogbookEntry]  # refused password entries
    alarms: AlarmServer
    interpreters: ChannelInterpreters  # the channel's interpreters (nck.kernel_interpreters)
    setup: JobSetup  # Set WO and the stored frames (nck.kernel_setup)
    _test_motion: InstantMotion | None  # the simulated axes under program test
    _access: AccessControl | None  # None: no protection (a bare kernel), created by a password entry
    _keyswitch: int  # keyswitch position 0 … 3 while there is no access control
    _time_s: float
    _raise_number: Callable[..., None]  # raises an alarm by number with its parameters
    search: BlockSearchControl  # refuses program test and dry run during SERUPRO (nck.kernel_search)

    def _set_program_control(self, command: cmd.SetProgramControl) -> SubmitResult:
        name, value = command.name, command.value
        refused = self.search.refuse_selection_in_serupro(name)
        if refused is not None:
            return refused
        if name == "single_block":
            text = None if value in (None, False, "") else str(value).upper()
            if text == "SBL3":
                text = "SBL2"
            if text not in (None, "SBL1", "SBL2"):
                return Rejected("single block is None, SBL1 or SBL2")
            self.switches.program_control[name] = text
        elif name in ("dry_run", "m01", "rapid_override"):
            self.switches.program_control[name] = bool(value)
            self._apply_overrides()
            self._apply_dry_run()
        elif name == "program_test":
            if self.channel.situation.channel != RESET:
                return Rejected("Program test can be switched only in channel reset")
            self.switches.program_control[name] = bool(value)
            self._test_motion = (
                InstantMotion(self.machine, self.motion.positions_mcs()) if value else None
            )
            self._apply_overrides()
            self._apply_dry_run()
        elif name == "skip_levels":
            try:
                levels = frozenset(int(v) for v in cast(Any, value or ()))
            except (TypeError, ValueError):
                return Rejected("skip levels are numbers 0 … 9")
            if any(level < 0 or level > 9 for level in levels):
                return Rejected("skip levels are numbers 0 … 9")
            if self.channel.situation.channel == ACTIVE:
                return Rejected("Skip levels can be changed only in STOP or RESET")
            self.switches.program_control[name] = levels
            for interp in self.interpreters.all():
                self._apply_skip_levels(interp)
        else:
            return Rejected(f"unknown program control {name!r}")
        return Accepted()

    def _set_override(self, command: cmd.SetOverride) -> SubmitResult:
        # 002 L56312-56319: path feed and spindle 0 … 200 %, rapid traverse 0 … 100 %
        # (the switches of the panel have fewer positions, see the keymap).
        limits = {"feed": (0.0, 200.0), "rapid": (0.0, 100.0), "spindle": (0.0, 200.0)}
        if command.which not in limits:
            return Rejected(f"unknown override {command.which!r}")
        low, high = limits[command.which]
        percent = float(command.percent)
        if not low <= percent <= high:
            return Rejected(f"{command.which} override must be {low:g} … {high:g} %")
        self.switches.overrides[command.which] = percent
        self._apply_overrides()
        return Accepted()

    def _cancel_alarms(self, command: cmd.CancelAlarms) -> SubmitResult:
        self.alarms.clear("cancel", self._time_s)
        return Accepted()

    def _write_data(self, command: cmd.WriteData) -> SubmitResult:
        handled = self._write_nc_datum(command)  # protection, MD/SD, tools, frames, GUD
        if handled is not None:
            if isinstance(handled, Accepted) and (action_for_write(command.name) == Action.WRITE_WORK_OFFSET
                                                  or command.name.strip().upper().startswith("$P_UBFR")):
                self._work_offset_edited()
            return handled
        name = command.name.strip().upper()
        try:
            parts = {"$AC_TOTAL_PARTS": "total", "$AC_ACTUAL_PARTS": "actual",
                     "$AC_SPECIAL_PARTS": "special", "$AC_REQUIRED_PARTS": "required"}
            if name in parts:
                value = int(number_from_text(command.value, name, whole=True))
                if not 0 <= value <= 999_999_999:
                    return Rejected("part counters range over 0 … 999999999")
                setattr(self.counters, parts[name], value)
                return Accepted()
        except InvalidValue as refusal:
            return Rejected(str(refusal))
        return Rejected(f"{command.name} cannot be written here")

    @property
    def access(self) -> AccessControl:
        """Keyswitch and passwords (protection levels 0 … 7)."""
        if self._access is None:
            self._access = AccessControl(AccessState(keyswitch_position=self._keyswitch))
        return self._access

    def _set_controller_enable(self, command: cmd.SetControllerEnable) -> SubmitResult:
        set_enable = getattr(self.motion, "set_controller_enable", None)
        if set_enable is None or command.axis not in self.machine.path_axes:
            return Rejected(f"no machine axis {command.axis}")
        set_enable(command.axis, command.enabled)
        return Accepted()

    def _set_keyswitch(self, command: cmd.SetKeyswitch) -> SubmitResult:
        if command.position not in (0, 1, 2, 3):
            return Rejected("keyswitch positions are 0 … 3")
        try:
            self.access.set_keyswitch(command.position)
        except AccessLocked as error:
            return Rejected(str(error))
        self._keyswitch = command.position
        return Accepted()

    def _enter_password(self, command: cmd.EnterPassword) -> SubmitResult:
        failed_before = self.access.state.failed_attempts
        try:
            self.access.enter_password(command.password)
        except AccessError as error:
            failed = self.access.state.failed_attempts
            if failed > failed_before:  # a wrong password (not a malformed one): logbook and alarm log
                delay = f"{self.access.retry_delay_s:g}"
                self.logbook.append(LogbookEntry(self._time_s, "access",
                                                 f"password not accepted (failed attempt {failed})"))
                self._raise_number(ALARM_PASSWORD_REFUSED, failed, delay)
            return Rejected(str(error) or "Password not accepted", alarm=ALARM_PASSWORD_REFUSED
                            if failed > failed_before else None)
        # the refusal and its waiting time are over: the alarm goes (the log keeps it)
        self.alarms.clear_number(ALARM_PASSWORD_REFUSED, self._time_s)
        return Accepted()

    def _delete_password(self, command: cmd.DeletePassword) -> SubmitResult:
        if self._access is not None:
            try:
                self._access.delete_password()
            except AccessLocked as error:
                return Rejected(str(error))
        return Accepted()

    def _apply_skip_levels(self, interp: Interpreter) -> None:
        levels = frozenset(cast("frozenset[int]", self.switches.program_control["skip_levels"]))
        setter = getattr(interp, "set_skip_levels", None)
        if setter is not None:
            setter(levels)
        elif hasattr(interp, "skip_levels"):
            interp.skip_levels = levels  # type: ignore[attr-defined]

    def _adjust_motion(self, motion: Motion) -> Motion:
        """The WCS offset bookkeeping of every segment handed to the motion."""
        for axis, mcs in motion.end_mcs.items():
            if axis in motion.end_wcs:
                self.outputs.wcs_offset[axis] = float(mcs) - float(motion.end_wcs[axis])
        return motion

    def _work_offset_edited(self) -> None:
        """An edited work offset stays inactive until the program selects it again, RESET or
        program start; with MD9440 = 1 it is active at once in RESET and from the next NC
        START when entered while the program is stopped (002 L28128-28137, L31541-31546)."""
        if not int(self.machine_data.active_value("MD9440") or 0):
            return
        if self.channel.situation.channel == RESET:
            self.setup.activate_stored_frames()
        else:
            self.channel.offsets_edited = True

    def _apply_offset_edits(self) -> None:
        """NC START: offsets edited while stopped under MD9440 = 1 become active."""
        if self.channel.offsets_edited:
            self.channel.offsets_edited = False
            self.setup.activate_stored_frames()

    def _apply_dry_run(self) -> None:
        """Hand the dry run (SD42100 feed, SD42101 mode) or its absence to the motion systems
        and to the interpreters ($P_DRYRUN); called on the switch, at NC START (setting data
        written meanwhile) and for a new program-test motion."""
        on = bool(self.switches.program_control["dry_run"])
        feed = float(self._setting("SD42100", DEFAULT_DRY_RUN_MM_MIN)) if on else None
        mode = int(self._setting("SD42101", 0))
        for motion in (self.motion, self._test_motion):
            if motion is not None:
                motion.set_dry_run(feed, mode)
        for interp in self.interpreters.all():
            flags = getattr(interp, "flags", None)
            if isinstance(flags, dict):
                flags["dry_run"] = on

    def _setting(self, name: str, default: object) -> Any:
        value = self.data.setting_data.get(name)
        if value is None:
            return default
        return value

    def _apply_overrides(self) -> None:
        spindle = getattr(self.motion, "set_spindle_override", None)
        if spindle is not None:
            spindle(self.switches.overrides["spindle"])
        feed = self.switches.overrides["feed"]
        # 002 L56369-56370: the feed switch acting as rapid override counts at most 100 %.
        rapid = min(feed, 100.0) if self.switches.program_control["rapid_override"] else self.switches.overrides["rapid"]
        for motion in (self.motion, self._test_motion):
            if motion is not None:
                motion.set_overrides(feed, rapid)
