"""Manual traversing, a part of :class:`nck.kernel.Nck`: JOG, INC, REF, REPOS.

JOG continuous while a direction key is held, INC increments (1 … 10000 in
0.001 mm, or VAR from SD41010), REF starts the reference point approach with
the key of ``MD34010`` (0 = plus), REPOS moves an axis back towards the
interruption point of the interrupted program. NC STOP stops an increment,
NC START continues it (Table 9-3 situations 8 and 15).
"""

from __future__ import annotations

from typing import Callable

from nck.channel_state import ChannelState, MachinePlant
from nck import commands as cmd
from nck.channel import ABORTED, ACTIVE, INCREMENTS, INTERRUPTED, MACHINE_FUNCTIONS
from nck.commands import Accepted, Rejected, SubmitResult
from nck.kernel_contact import ContactState
from nck.ncdata import NcData
from nck.refusals import refuse

DEFAULT_JOG_MM_MIN = 2000.0  # MD32020 JOG_VELO
DEFAULT_JOG_RAPID_MM_MIN = 10000.0  # MD32010 JOG_VELO_RAPID


class ManualControl:
    """JOG, INC, REF and REPOS handling on the parts it is given."""

    def __init__(self, plant: MachinePlant, data: NcData, channel: ChannelState, contact: ContactState,
                 park: Callable[[], None]) -> None:
        self.plant = plant  # the machine and its motion system
        self.data = data  # SD41010 (VAR increment), SD41110 (JOG feed)
        self.channel = channel  # the channel's state (nck.channel_state)
        self.contact = contact  # contacts with the blank (nck.kernel_contact): a rapid JOG into it is a crash
        self.park = park  # keeps the interrupted program's rest before the axes move by hand

    def select_machine_function(self, command: cmd.SelectMachineFunction) -> SubmitResult:
        """REF, REPOS, INC or none (JOG continuous), in JOG and MDA while the channel is not active."""
        function = command.function.upper() if command.function else None
        if function is not None and function not in MACHINE_FUNCTIONS:
            return refuse("unknown_machine_function", function=repr(command.function))
        if self.channel.situation.mode == "AUTO" and function is not None:
            return refuse("machine_function_mode")
        if function == "INC" and self.channel.situation.mode != "JOG":
            return refuse("inc_jog_only")
        if self.channel.situation.channel == ACTIVE:
            return refuse("channel_active_stop_first")
        self.channel.machine_function = function
        return Accepted()

    def select_increment(self, command: cmd.SelectIncrement) -> SubmitResult:
        """INC 1 … 10000 (0.001 mm) or VAR (None), in JOG only."""
        value = command.increment
        if value is not None and value not in INCREMENTS:
            return refuse("increment_values")
        if self.channel.situation.mode != "JOG":
            return refuse("inc_jog_only")
        self.channel.increment = value
        if self.channel.machine_function not in ("REF", "REPOS"):
            self.channel.machine_function = "INC"
        return Accepted()

    def jog(self, command: cmd.Jog) -> SubmitResult:
        """A direction key of an axis or spindle pressed (+1/-1) or released (0)."""
        axis = command.axis.upper()
        if axis in self.plant.machine.spindles:
            return self._jog_spindle(axis, command.direction)
        if axis not in self.plant.machine.path_axes:
            return refuse("no_axis", axis=command.axis)
        function = self.channel.machine_function
        if command.direction == 0:
            if self.channel.jogging and function is None:
                self.plant.motion.jog_continuous(axis, 0, 0.0)
            return Accepted()
        if self.channel.estop_active:
            return refuse("emergency_stop_active")
        if self.channel.situation.mode == "AUTO" or (self.channel.situation.mode == "MDA" and function not in ("REF", "REPOS")):
            return refuse("traverse_jog_only")
        if self.channel.situation.channel == ACTIVE and not self.channel.jogging:
            return refuse("channel_active")
        direction = 1 if command.direction > 0 else -1
        self.park()
        position = self.plant.motion.positions_mcs()[axis]
        if function == "REF":
            plus = int(self.plant.machine.md_value("MD34010", axis, 0) or 0) == 0
            if (direction > 0) != plus:
                return Accepted()  # wrong direction key: nothing happens
            self.plant.motion.start_reference(axis)
        elif function == "REPOS":
            if self.channel.repos_point is None or axis not in self.channel.repos_point:
                return refuse("no_repos_point")
            distance = self.channel.repos_point[axis] - position
            if abs(distance) < 1e-9 or (distance > 0) != (direction > 0):
                return Accepted()
            self.plant.motion.jog_increment(axis, distance, self.jog_velocity(axis, command.rapid))
        elif function == "INC":
            # A press while an increment still runs adds its increment to that target:
            # every press is one increment (keymap), none cut short by the next.
            target = self.channel.jog_targets.get(axis, position) + direction * self._increment_mm()
            self.plant.motion.jog_increment(axis, target - position, self.jog_velocity(axis, command.rapid))
            self.channel.jog_targets[axis] = target
        else:
            self.plant.motion.jog_continuous(axis, direction, self.jog_velocity(axis, command.rapid))
        self.channel.jog_rest.clear()
        self.contact.jog_rapid = command.rapid  # a rapid move into the blank is a crash (nck.kernel_contact)
        if not self.channel.jogging:
            self.channel.jogging = True
            self.channel.transition("jog_start")
        return Accepted()

    def _jog_spindle(self, spindle: str, direction: int) -> SubmitResult:
        """Spindle JOG: turns at its JOG speed while the key is held (JOG mode only)."""
        if direction != 0:
            if self.channel.estop_active:
                return refuse("emergency_stop_active")
            if self.channel.situation.mode != "JOG" or self.channel.situation.channel == ACTIVE:
                return refuse("spindle_jog_only")
        self.plant.motion.jog_continuous(spindle, 0 if direction == 0 else (1 if direction > 0 else -1),
                                   self.jog_velocity(spindle, False))
        return Accepted()

    def stop_jog(self, keep_rest: bool) -> None:
        """NC STOP of a manual motion; ``keep_rest``: NC START continues the increments."""
        positions = self.plant.motion.positions_mcs()
        rest = {axis: target - positions[axis] for axis, target in self.channel.jog_targets.items()}
        for axis in self.plant.machine.path_axes:
            self.plant.motion.jog_continuous(axis, 0, 0.0)
        self.channel.jogging = False
        self.channel.jog_targets.clear()
        self.channel.jog_rest = {a: d for a, d in rest.items() if abs(d) > 1e-9} if keep_rest else {}

    def continue_jog(self) -> SubmitResult:
        """NC START in JOG: continue the increments NC STOP interrupted."""
        if self.channel.situation.channel != INTERRUPTED or self.channel.situation.program != ABORTED or not self.channel.jog_rest:
            return refuse("jog_start_continues_increment")
        positions = self.plant.motion.positions_mcs()
        for axis, distance in self.channel.jog_rest.items():
            self.plant.motion.jog_increment(axis, distance, self.jog_velocity(axis, False))
            self.channel.jog_targets[axis] = positions[axis] + distance
        self.channel.jog_rest.clear()
        self.channel.jogging = True
        self.channel.transition("jog_start")
        return Accepted()

    def jog_velocity(self, axis: str, rapid: bool) -> float:
        """The JOG velocity of ``axis`` (rapid: MD32010; else SD41110 for linear axes, MD32020)."""
        if rapid:
            return float(self.plant.machine.md_value("MD32010", axis, DEFAULT_JOG_RAPID_MM_MIN) or DEFAULT_JOG_RAPID_MM_MIN)
        set_velo = float(self.data.setting_data.get("SD41110") or 0.0)
        if set_velo > 0.0 and self.plant.machine.axis(axis).kind == "linear":
            return set_velo  # SD41110 JOG_SET_VELO: the JOG feed of linear axes; 0 = MD32020
        return float(self.plant.machine.md_value("MD32020", axis, DEFAULT_JOG_MM_MIN) or DEFAULT_JOG_MM_MIN)

    def _increment_mm(self) -> float:
        if self.channel.increment is None:
            variable = self.data.setting_data.get("SD41010")  # VAR: SD41010 JOG_VAR_INCR_SIZE
            return 0.001 if variable is None else float(variable)
        return self.channel.increment * 0.001
