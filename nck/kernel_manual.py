"""Manual traversing for :class:`nck.kernel.Nck`: JOG, INC, REF, REPOS (a mixin).

JOG continuous while a direction key is held, INC increments (1 … 10000 in
0.001 mm, or VAR from SD41010), REF starts the reference point approach with
the key of ``MD34010`` (0 = plus), REPOS moves an axis back towards the
interruption point of the interrupted program. NC STOP stops an increment,
NC START continues it (Table 9-3 situations 8 and 15).
"""

from __future__ import annotations

from typing import Any

from nck import commands as cmd
from nck.channel import ABORTED, ACTIVE, INTERRUPTED, MACHINE_FUNCTIONS
from nck.commands import Accepted, Rejected, SubmitResult

DEFAULT_JOG_MM_MIN = 2000.0  # MD32020 JOG_VELO
DEFAULT_JOG_RAPID_MM_MIN = 10000.0  # MD32010 JOG_VELO_RAPID


class ManualControl:
    """JOG, INC, REF and REPOS handling; mixed into ``Nck`` (uses its state)."""

    machine: Any
    motion: Any
    _jog_targets: dict[str, float]  # axis -> MCS end of the increments pressed so far
    _contact: Any  # nck.kernel_contact.ContactState

    def _select_machine_function(self, command: cmd.SelectMachineFunction) -> SubmitResult:
        function = command.function.upper() if command.function else None
        if function is not None and function not in MACHINE_FUNCTIONS:
            return Rejected(f"unknown machine function {command.function!r}")
        if self._sit.mode == "AUTO" and function is not None:
            return Rejected("Machine functions are available in JOG and MDA only")
        if function == "INC" and self._sit.mode != "JOG":
            return Rejected("INC is available in JOG only")
        if self._sit.channel == ACTIVE:
            return Rejected("Channel active: stop the motion first")
        self._machine_function = function
        return Accepted()

    def _select_increment(self, command: cmd.SelectIncrement) -> SubmitResult:
        value = command.increment
        if value is not None and value not in (1, 10, 100, 1000, 10000):
            return Rejected("Increment must be 1, 10, 100, 1000, 10000 or VAR")
        if self._sit.mode != "JOG":
            return Rejected("INC is available in JOG only")
        self._increment = value
        if self._machine_function not in ("REF", "REPOS"):
            self._machine_function = "INC"
        return Accepted()

    def _jog(self, command: cmd.Jog) -> SubmitResult:
        axis = command.axis.upper()
        if axis in self.machine.spindles:
            return self._jog_spindle(axis, command.direction)
        if axis not in self.machine.path_axes:
            return Rejected(f"no axis {command.axis}")
        function = self._machine_function
        if command.direction == 0:
            if self._jogging and function is None:
                self.motion.jog_continuous(axis, 0, 0.0)
            return Accepted()
        if self._estop_active:
            return Rejected("Emergency stop active")
        if self._sit.mode == "AUTO" or (self._sit.mode == "MDA" and function not in ("REF", "REPOS")):
            return Rejected("Axes can be traversed by hand only in JOG")
        if self._sit.channel == ACTIVE and not self._jogging:
            return Rejected("Channel active")
        direction = 1 if command.direction > 0 else -1
        self._park()
        position = self.motion.positions_mcs()[axis]
        if function == "REF":
            plus = int(self.machine.md_value("MD34010", axis, 0) or 0) == 0
            if (direction > 0) != plus:
                return Accepted()  # wrong direction key: nothing happens
            self.motion.start_reference(axis)
        elif function == "REPOS":
            if self._repos_point is None or axis not in self._repos_point:
                return Rejected("No REPOS point")
            distance = self._repos_point[axis] - position
            if abs(distance) < 1e-9 or (distance > 0) != (direction > 0):
                return Accepted()
            self.motion.jog_increment(axis, distance, self._jog_velocity(axis, command.rapid))
        elif function == "INC":
            # A press while an increment still runs adds its increment to that target:
            # every press is one increment (keymap), none cut short by the next.
            target = self._jog_targets.get(axis, position) + direction * self._increment_mm()
            self.motion.jog_increment(axis, target - position, self._jog_velocity(axis, command.rapid))
            self._jog_targets[axis] = target
        else:
            self.motion.jog_continuous(axis, direction, self._jog_velocity(axis, command.rapid))
        self._jog_rest.clear()
        self._contact.jog_rapid = command.rapid  # a rapid move into the blank is a crash (nck.kernel_contact)
        if not self._jogging:
            self._jogging = True
            self._transition("jog_start")
        return Accepted()

    def _jog_spindle(self, spindle: str, direction: int) -> SubmitResult:
        """Spindle JOG: turns at its JOG speed while the key is held (JOG mode only)."""
        if direction != 0:
            if self._estop_active:
                return Rejected("Emergency stop active")
            if self._sit.mode != "JOG" or self._sit.channel == ACTIVE:
                return Rejected("The spindle can be jogged only in JOG")
        self.motion.jog_continuous(spindle, 0 if direction == 0 else (1 if direction > 0 else -1),
                                   self._jog_velocity(spindle, False))
        return Accepted()

    def _stop_jog(self, keep_rest: bool) -> None:
        positions = self.motion.positions_mcs()
        rest = {axis: target - positions[axis] for axis, target in self._jog_targets.items()}
        for axis in self.machine.path_axes:
            self.motion.jog_continuous(axis, 0, 0.0)
        self._jogging = False
        self._jog_targets.clear()
        self._jog_rest = {a: d for a, d in rest.items() if abs(d) > 1e-9} if keep_rest else {}

    def _continue_jog(self) -> SubmitResult:
        if self._sit.channel != INTERRUPTED or self._sit.program != ABORTED or not self._jog_rest:
            return Rejected("NC START in JOG only continues a stopped increment")
        positions = self.motion.positions_mcs()
        for axis, distance in self._jog_rest.items():
            self.motion.jog_increment(axis, distance, self._jog_velocity(axis, False))
            self._jog_targets[axis] = positions[axis] + distance
        self._jog_rest.clear()
        self._jogging = True
        self._transition("jog_start")
        return Accepted()

    def _jog_velocity(self, axis: str, rapid: bool) -> float:
        if rapid:
            return float(self.machine.md_value("MD32010", axis, DEFAULT_JOG_RAPID_MM_MIN) or DEFAULT_JOG_RAPID_MM_MIN)
        set_velo = float(self._setting("SD41110", 0.0) or 0.0)  # type: ignore[attr-defined]
        if set_velo > 0.0 and self.machine.axis(axis).kind == "linear":
            return set_velo  # SD41110 JOG_SET_VELO: the JOG feed of linear axes; 0 = MD32020
        return float(self.machine.md_value("MD32020", axis, DEFAULT_JOG_MM_MIN) or DEFAULT_JOG_MM_MIN)

    def _increment_mm(self) -> float:
        if self._increment is None:
            return float(self._setting("SD41010", 0.001))
        return self._increment * 0.001
