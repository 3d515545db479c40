"""Setting up a job, a part of :class:`nck.kernel.Nck`: machine set-up, Set WO, PRESET.

* ``WriteMachineSetup`` — what is clamped (:mod:`nck.workpiece`), protection level 2;
* ``WriteManualSettings`` — retraction plane, safety distance, measuring feed (:mod:`nck.manual_settings`);
* ``SetActualValue`` — Set WO / PRESET / scratching: an axis reads a given WCS value, by
  changing the translation of the active settable frame or, under G500, of the system frame
  for PRESET and scratching ``$P_SETFR`` (002 L30600-30612, L30655-30660; MD28082 bit 0);
* ``SetWorkOffsetRotation`` — the angle of a rotated corner into a work offset;
* ``DeleteActiveWorkOffset`` — the active offset's translations (or ``$P_SETFR``'s) to 0.

Every change is active at once in every interpreter (the WCS display follows). At RESET,
MD24007 bit 0 deletes ``$P_SETFR`` (002 L31398-31408); MD24006 bit 0 says whether it stays
active (read by the geometry when the frames are loaded again).

Trainer limits: lengths are taken in mm (metric basic system, G71/G710 displays); a
transverse axis in diameter (DIAMON) is set in radius.
"""

from __future__ import annotations

from typing import Any, Callable

from nck.channel_state import ChannelState, MachinePlant
from nck import commands as cmd
from nck.access import AccessError, Action
from nck.commands import Accepted, Rejected, SubmitResult
from nck.geometry.preset import TARGET_SETFRAME, TARGET_SETTABLE, translation_change, wcs_of_point
from nck.kernel_interpreters import ChannelInterpreters
from nck.ncdata import SETTABLE_FRAME_NAMES, NcData, WorkOffset
from nck.manual_settings import BadSetting, ManualSettings, settings_from_plain, settings_to_plain
from nck.refusals import refuse, rejected_by
from nck.workpiece import MachineSetup

SETFR = "SETFR"
SETFR_MASK_BIT = 1  # MD28082 / MD24006 / MD24007 bit 0: the frame for PRESET and scratching


class JobSetup:
    """Machine set-up, Set WO, PRESET on the parts it is given."""

    def __init__(self, plant: MachinePlant, data: NcData, channel: ChannelState,
                 interpreters: ChannelInterpreters, require: Callable[[Action], None]) -> None:
        self.plant = plant  # the machine (MD24007, MD28082) and its axes' positions
        self.data = data  # the machine set-up, manual settings and the stored frames
        self.channel = channel
        self.interpreters = interpreters  # Set WO works on the frames of the one holding the channel's state
        self.require = require  # raises AccessError when the access level does not allow the action

    # ------------------------------------------------------------ machine set-up
    def write_machine_setup(self, command: cmd.WriteMachineSetup) -> SubmitResult:
        """What is clamped (protection level 2; not while the channel is active)."""
        try:
            self.require(Action.WRITE_MACHINE_SETUP)
        except AccessError as error:
            return rejected_by(error)
        if not isinstance(command.setup, MachineSetup):
            return refuse("not_a_machine_setup")
        if self.channel.situation.channel == "active":
            return refuse("setup_needs_inactive")
        self.data.machine_setup = command.setup
        return Accepted()

    def write_manual_settings(self, command: cmd.WriteManualSettings) -> SubmitResult:
        """Retraction plane, safety distance and measuring feed, checked as the retained file's."""
        if not isinstance(command.settings, ManualSettings):
            return refuse("not_manual_settings")
        try:  # the same checks as the retained file's
            settings = settings_from_plain(settings_to_plain(command.settings))
        except BadSetting as error:
            return rejected_by(error)
        self.data.manual_settings = settings
        return Accepted()

    # ------------------------------------------------------------ Set WO / PRESET
    def set_actual_value(self, command: cmd.SetActualValue) -> SubmitResult:
        """Set WO / PRESET / scratching: the axis reads the given WCS value (see the module docstring)."""
        interp = self.frame_interpreter()
        path, modal = interp.builder.path, interp.modal
        axis = command.axis.strip().upper()
        if axis not in self.plant.machine.path_axes:
            return refuse("no_axis", axis=command.axis)
        target = self._preset_target(command.target, modal)
        if isinstance(target, Rejected):
            return target
        positions = self.plant.positions()
        chain = path.state(modal).frames
        if command.point_mcs is None:
            now = path.wcs_from_mcs(modal, positions)[axis]
        else:
            now = wcs_of_point(chain, command.point_mcs)[axis]
        kind = TARGET_SETFRAME if target == SETFR else TARGET_SETTABLE
        change = translation_change(chain, kind, {axis: now - float(command.value_mm)})
        offset = self._target_offset(target)
        for name, delta in change.items():
            offset.trans[name] = offset.trans.get(name, 0.0) + delta
        self.activate_stored_frames()
        return Accepted()

    def set_work_offset_rotation(self, command: cmd.SetWorkOffsetRotation) -> SubmitResult:
        """The angle of a rotated corner into the active (or given) work offset."""
        interp = self.frame_interpreter()
        target = self._preset_target(command.target, interp.modal)
        if isinstance(target, Rejected):
            return target
        if target == SETFR:
            return refuse("preset_no_rotation")
        self._target_offset(target).rot[command.axis.strip().upper()] = float(command.angle_deg)
        self.activate_stored_frames()
        return Accepted()

    def delete_active_work_offset(self, command: cmd.DeleteActiveWorkOffset) -> SubmitResult:
        """The active offset's translations (or ``$P_SETFR``'s) to 0."""
        interp = self.frame_interpreter()
        target = self._preset_target(None, interp.modal)
        if isinstance(target, Rejected):
            return target
        self._target_offset(target).trans.clear()
        self.activate_stored_frames()
        return Accepted()

    def _preset_target(self, wanted: str | None, modal: Any) -> str | Rejected:
        """The frame a Set WO writes (``"G54"`` …, or :data:`SETFR`), checked; else the refusal."""
        if self.channel.situation.channel == "active":
            return refuse("set_wo_needs_inactive")
        target = (wanted or modal.gcodes.get(8, "G500")).strip().upper()
        if target in ("G500", "$P_SETFR"):
            target = SETFR
        if target == SETFR:
            if not int(self.plant.machine.md_value("MD28082", None, 33) or 0) & SETFR_MASK_BIT:
                return refuse("no_preset_frame")
            action = Action.PRESET
        elif target in SETTABLE_FRAME_NAMES:
            action = Action.WRITE_WORK_OFFSET
        else:
            return refuse("not_a_work_offset", name=wanted)
        try:
            self.require(action)
        except AccessError as error:
            return rejected_by(error)
        return target

    def _target_offset(self, target: str) -> WorkOffset:
        return self.data.setframe if target == SETFR else self.data.settable_frame(target)

    def frame_interpreter(self) -> Any:
        """The interpreter whose frames Set WO changes: the run's, else the one holding the channel's
        state, else AUTOMATIC's (created at power on)."""
        run = self.channel.active_run()
        if run is not None:
            return run.interp
        interpreters = self.interpreters
        return interpreters.holder or interpreters.existing("AUTO") or interpreters.get("MDA")

    def activate_stored_frames(self) -> None:
        """An operator frame action (Set WO, PRESET, an offset in effect at once): every
        interpreter takes the stored frames; from now on the frame interpreter holds the
        channel's state (before, the snapshot read the power-on frames from the data)."""
        positions = self.plant.positions()
        for interp in self.interpreters.all():
            path = getattr(getattr(interp, "builder", None), "path", None)
            modal = getattr(interp, "modal", None)
            if path is not None and modal is not None:
                path.activate_stored_frames(modal, positions)
        self.interpreters.holder = self.frame_interpreter()

    def reset_system_frames(self) -> None:
        """RESET: MD24007 bit 0 deletes ``$P_SETFR`` in the data (002 L31398-31408)."""
        if int(self.plant.machine.md_value("MD24007", None, 0) or 0) & SETFR_MASK_BIT:
            self.data.setframe = WorkOffset()
