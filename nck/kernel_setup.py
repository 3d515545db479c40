"""Setting up a job on :class:`nck.kernel.Nck` (a mixin): machine set-up, Set WO, PRESET.

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

from typing import Any

from nck.channel_state import ChannelState
from nck import commands as cmd
from nck.access import AccessError, Action
from nck.commands import Accepted, Rejected, SubmitResult
from nck.geometry.preset import TARGET_SETFRAME, TARGET_SETTABLE, translation_change, wcs_of_point
from nck.interp.modal import kept_groups
from nck.ncdata import SETTABLE_FRAME_NAMES, WorkOffset
from nck.manual_settings import ManualSettings, settings_from_plain, settings_to_plain
from nck.workpiece import MachineSetup

SETFR = "SETFR"
SETFR_MASK_BIT = 1  # MD28082 / MD24006 / MD24007 bit 0: the frame for PRESET and scratching


class JobSetup:
    """Machine set-up, Set WO, PRESET; mixed into ``Nck`` (uses its state)."""
    channel: ChannelState

    data: Any
    machine: Any
    _interpreters: dict[str, Any]

    # ------------------------------------------------------------ machine set-up
    def _write_machine_setup(self, command: cmd.WriteMachineSetup) -> SubmitResult:
        try:
            self._require(Action.WRITE_MACHINE_SETUP)  # type: ignore[attr-defined]
        except AccessError as error:
            return Rejected(str(error))
        if not isinstance(command.setup, MachineSetup):
            return Rejected("not a machine set-up")
        if self.channel.situation.channel == "active":  # type: ignore[attr-defined]
            return Rejected("The machine set-up can be changed only while the channel is not active")
        self.data.machine_setup = command.setup
        return Accepted()

    def _write_manual_settings(self, command: cmd.WriteManualSettings) -> SubmitResult:
        if not isinstance(command.settings, ManualSettings):
            return Rejected("not settings for manual mode")
        try:  # the same checks as the retained file's
            settings = settings_from_plain(settings_to_plain(command.settings))
        except ValueError as error:
            return Rejected(str(error))
        self.data.manual_settings = settings
        return Accepted()

    # ------------------------------------------------------------ Set WO / PRESET
    def _set_actual_value(self, command: cmd.SetActualValue) -> SubmitResult:
        interp = self._frame_interpreter()
        path, modal = interp.builder.path, interp.modal
        axis = command.axis.strip().upper()
        if axis not in self.machine.path_axes:
            return Rejected(f"no axis {command.axis}")
        target = self._preset_target(command.target, modal)
        if isinstance(target, Rejected):
            return target
        positions = self._path_positions(self.motion)  # type: ignore[attr-defined]
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
        self._activate_stored_frames()
        return Accepted()

    def _set_work_offset_rotation(self, command: cmd.SetWorkOffsetRotation) -> SubmitResult:
        interp = self._frame_interpreter()
        target = self._preset_target(command.target, interp.modal)
        if isinstance(target, Rejected):
            return target
        if target == SETFR:
            return Rejected("The PRESET frame holds no rotation: select a work offset (G54 …)")
        self._target_offset(target).rot[command.axis.strip().upper()] = float(command.angle_deg)
        self._activate_stored_frames()
        return Accepted()

    def _delete_active_work_offset(self, command: cmd.DeleteActiveWorkOffset) -> SubmitResult:
        interp = self._frame_interpreter()
        target = self._preset_target(None, interp.modal)
        if isinstance(target, Rejected):
            return target
        self._target_offset(target).trans.clear()
        self._activate_stored_frames()
        return Accepted()

    def _preset_target(self, wanted: str | None, modal: Any) -> str | Rejected:
        """The frame a Set WO writes (``"G54"`` …, or :data:`SETFR`), checked; else the refusal."""
        if self.channel.situation.channel == "active":  # type: ignore[attr-defined]
            return Rejected("Set WO is possible only while the channel is not active")
        target = (wanted or modal.gcodes.get(8, "G500")).strip().upper()
        if target in ("G500", "$P_SETFR"):
            target = SETFR
        if target == SETFR:
            if not int(self.machine.md_value("MD28082", None, 33) or 0) & SETFR_MASK_BIT:
                return Rejected("No system frame for PRESET and scratching (MD28082 bit 0)")
            action = Action.PRESET
        elif target in SETTABLE_FRAME_NAMES:
            action = Action.WRITE_WORK_OFFSET
        else:
            return Rejected(f"{wanted} is not a work offset")
        try:
            self._require(action)  # type: ignore[attr-defined]
        except AccessError as error:
            return Rejected(str(error))
        return target

    def _target_offset(self, target: str) -> WorkOffset:
        return self.data.setframe if target == SETFR else self.data.settable_frame(target)

    def _frame_interpreter(self) -> Any:
        """The interpreter whose frames the WCS display shows (the MDA one when none ran yet)."""
        run = self.channel.active_run()
        if run is not None:
            return run.interp
        last = getattr(self, "_last_interp", None)  # the one that ran last holds the channel's state
        if last is not None:
            return last
        return self._interpreters.get("AUTO") or self._interpreters.get("MDA") or self._interpreter("MDA")  # type: ignore[attr-defined]

    def _activate_stored_frames(self) -> None:
        """An operator frame action (Set WO, PRESET, an offset in effect at once): every
        interpreter takes the stored frames; from now on the frame interpreter holds the
        channel's state (before, the snapshot read the power-on frames from the data)."""
        positions = self._path_positions(self.motion)  # type: ignore[attr-defined]
        for interp in self._interpreters.values():
            path = getattr(getattr(interp, "builder", None), "path", None)
            if path is not None:
                path.activate_stored_frames(interp.modal, positions)
        self._last_interp = self._frame_interpreter()

    # ------------------------------------------------------------ the channel after a program
    def _share_kept_gcodes(self, ended: Any) -> None:
        """A program ended or was reset in interpreter ``ended``: it holds the channel's state
        now (the WCS display and Set WO read it: its tool, its frames); the G groups of
        MD20152 = 1 (e.g. the work offset chosen in T,S,M) go to the other interpreters (MDA,
        AUTO) too; one whose G codes change loads its frames at once."""
        modal = getattr(ended, "modal", None)  # an interpreter without G codes keeps none
        if modal is None:
            return
        keeps = kept_groups(self.machine)
        codes = {group: code for group, code in modal.gcodes.items() if group in keeps}
        self._kept_gcodes = codes
        self._last_interp = ended
        positions = self._path_positions(self.motion)  # type: ignore[attr-defined]
        for interp in self._interpreters.values():
            other = getattr(interp, "modal", None)
            if interp is ended or other is None or all(other.gcodes.get(g) == c for g, c in codes.items()):
                continue  # no G code changes there: its frames stay as they are (MD24006 …)
            self._take_kept_gcodes(interp)
            path = getattr(getattr(interp, "builder", None), "path", None)
            if path is not None:
                path.activate_stored_frames(interp.modal, positions)

    def _take_kept_gcodes(self, interp: Any) -> None:
        """Give ``interp`` the channel's kept G codes (none before a program has ended)."""
        sync = getattr(interp, "sync_gcodes", None)
        if sync is not None:
            sync(getattr(self, "_kept_gcodes", {}))

    def _reset_system_frames(self) -> None:
        """RESET: MD24007 bit 0 deletes ``$P_SETFR`` in the data (002 L31398-31408)."""
        if int(self.machine.md_value("MD24007", None, 0) or 0) & SETFR_MASK_BIT:
            self.data.setframe = WorkOffset()
