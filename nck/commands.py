"""Operator commands: the only way the HMI and the headless CLI act on the kernel.

Each command is an immutable record named as an imperative. ``Nck.submit``
answers :class:`Accepted` or :class:`Rejected` (with a reason an operator can
read) at once.
"""

from __future__ import annotations

from dataclasses import dataclass

# Re-exported: screens build a WriteMachineSetup with them.
from nck.workpiece import Box as Box, Cylinder as Cylinder, MachineSetup as MachineSetup
from nck.manual_settings import ManualSettings as ManualSettings


@dataclass(frozen=True, slots=True)
class Accepted:
    """The command was taken."""


@dataclass(frozen=True, slots=True)
class Rejected:
    """The command was refused; nothing changed. ``alarm`` is set when an alarm was raised.

    ``reason`` is the English text. A refusal of the kernel's own (``nck.refusals.refuse``)
    also carries its ``key`` in ``data/refusals.toml`` and the values of its placeholders
    (``fields``); one that raised an alarm carries the alarm's parameters (``alarm_params``).
    With them a panel says the refusal in its own language.
    """

    reason: str
    alarm: int | None = None
    key: str = ""
    fields: tuple[tuple[str, str], ...] = ()
    alarm_params: tuple[str, ...] = ()


SubmitResult = Accepted | Rejected


@dataclass(frozen=True, slots=True)
class SelectMode:
    """Select the mode ``JOG``, ``MDA`` or ``AUTO``."""

    mode: str


@dataclass(frozen=True, slots=True)
class SelectMachineFunction:
    """Select a machine function in JOG: ``REF``, ``REPOS``, ``INC`` or ``None`` (off)."""

    function: str | None


@dataclass(frozen=True, slots=True)
class SelectIncrement:
    """Set the JOG increment in 0.001 mm units (1 … 10000), or ``None`` for VAR."""

    increment: int | None


@dataclass(frozen=True, slots=True)
class CycleStart:
    """NC START."""


@dataclass(frozen=True, slots=True)
class CycleStop:
    """NC STOP."""


@dataclass(frozen=True, slots=True)
class Reset:
    """RESET of the channel / mode group."""


@dataclass(frozen=True, slots=True)
class EmergencyStop:
    """Press (``pressed=True``) or release the emergency stop button."""

    pressed: bool


@dataclass(frozen=True, slots=True)
class SelectProgram:
    """Select a part program for AUTOMATIC (only in channel reset)."""

    name: str


@dataclass(frozen=True, slots=True)
class SetMdaProgram:
    """Replace the MDA buffer with ``text``."""

    text: str


@dataclass(frozen=True, slots=True)
class SetProgramControl:
    """Set one program-control switch.

    ``name`` is one of ``single_block`` (value ``None``/``"SBL1"``/``"SBL2"``),
    ``dry_run``, ``m01``, ``program_test``, ``rapid_override`` (bool values) or
    ``skip_levels`` (a frozenset of levels 0…9).
    """

    name: str
    value: object


@dataclass(frozen=True, slots=True)
class SetOverride:
    """Set an override: ``feed`` or ``spindle`` (0…200 %), ``rapid`` (0…100 %)."""

    which: str
    percent: float


@dataclass(frozen=True, slots=True)
class CancelAlarms:
    """ALARM CANCEL: clear every alarm whose criterion is CANCEL."""


@dataclass(frozen=True, slots=True)
class Jog:
    """Traverse ``axis`` in JOG: ``direction`` +1/−1 while pressed, 0 = key released.

    ``rapid`` is the rapid traverse overlay.
    """

    axis: str
    direction: int
    rapid: bool = False


@dataclass(frozen=True, slots=True)
class SetControllerEnable:
    """The controller enable of a machine axis (the PLC signal DB31.DBX2.1; the trainer has
    no PLC, so the operator's simulation sets it): removed while the axis moves, it stops
    with alarm 21612 (002 L756-768)."""

    axis: str
    enabled: bool


@dataclass(frozen=True, slots=True)
class SetSpindleDriveFault:
    """A simulated drive fault of a spindle (an exercise's injected fault; the trainer has no
    drive): its actual speed stays within ``limit_rpm`` whatever the set speed (None: the
    drive is sound). A machining block then waits for the set speed range (MD35500)."""

    spindle: str
    limit_rpm: float | None


@dataclass(frozen=True, slots=True)
class StartBlockSearch:
    """Block search to block number ``target`` (``N260``) or to the first block containing
    the text ``target``; ``search_type`` names the type (:mod:`nck.block_search`):
    ``contour`` (with calculation, approach to the start of the target block),
    ``end_point`` (with calculation, to the block end point), ``without_calculation``,
    ``serupro`` (search run by program test)."""

    target: str
    search_type: str = "contour"


@dataclass(frozen=True, slots=True)
class WriteData:
    """Write one NC datum by name (``R10``, ``$TC_DP6[1,1]``, ``MD32000[X]``, ``SD42100`` …)."""

    name: str
    value: object


@dataclass(frozen=True, slots=True)
class EnterPassword:
    """Enter a password (raises the access level while it is set)."""

    password: str


@dataclass(frozen=True, slots=True)
class DeletePassword:
    """Delete the active password (back to the keyswitch level)."""


@dataclass(frozen=True, slots=True)
class SetKeyswitch:
    """Turn the keyswitch to position 0…3."""

    position: int


@dataclass(frozen=True, slots=True)
class ChangePassword:
    """Give access level ``level`` (1 … 3) the new password ``password``."""

    level: int
    password: str


@dataclass(frozen=True, slots=True)
class DeleteToolEdge:
    """Delete cutting edge ``edge`` of tool ``tool`` (``edge=None``: the whole tool)."""

    tool: int
    edge: int | None = None


@dataclass(frozen=True, slots=True)
class ClearRParameters:
    """Set every R parameter to 0."""


@dataclass(frozen=True, slots=True)
class ActivateMachineData:
    """NEW CONFIG ("Set MD active"): stored machine data of activation cf (and re) take effect."""


@dataclass(frozen=True, slots=True)
class WriteManualSettings:
    """Replace the settings for manual mode (:class:`ManualSettings`: retraction plane,
    safety distance, measuring feed) that measuring in JOG uses. No protection level (like
    the JOG feed). Read them back with ``nck.queries.ManualSettingsData``. Retained."""

    settings: ManualSettings


@dataclass(frozen=True, slots=True)
class WriteMachineSetup:
    """Replace what is clamped on the machine: ``setup`` is a :class:`MachineSetup` (a blank
    :class:`Box` or :class:`Cylinder` or none, a reference :class:`Box` or none, the
    instructor's ``hidden`` switch), all positions in the MCS in mm.

    Needs protection level 2 (``write_machine_setup`` in data/access.toml); refused while
    the channel is active. Read it back with ``nck.queries.MachineSetupData``. Retained.
    """

    setup: MachineSetup


@dataclass(frozen=True, slots=True)
class SetActualValue:
    """Set WO / PRESET / scratching: from now on ``axis`` reads ``value_mm`` in the WCS.

    ``point_mcs`` ``None``: the actual position of the tool (its WCS value through frames
    and tool length, as displayed) is set — "Set WO" in JOG. Given (a dict of MCS positions
    of the geometry axes, e.g. a measured edge, corner or centre from ``nck.measuring``):
    that workpiece point gets ``value_mm`` on ``axis`` (no tool offset) — the "Set WO" of the
    measuring screens.

    ``target``: ``None`` = as the control does it: the active settable frame (G54 … G599),
    under G500 the system frame for PRESET and scratching ``$P_SETFR`` (needs MD28082 bit 0);
    or ``"G54"`` … ``"G599"`` / ``"SETFR"`` explicitly. The translation of that frame changes
    by what removes the difference (with rotated frames along the rotated axes); the change
    is active at once. Refused while the channel is active; needs the level of "write work
    offset" (MD9210) for a settable frame, of PRESET (MD9220) for ``$P_SETFR``.
    """

    axis: str
    value_mm: float
    target: str | None = None
    point_mcs: dict[str, float] | None = None


@dataclass(frozen=True, slots=True)
class SetWorkOffsetRotation:
    """Write the rotation of a work offset (degrees about ``axis``, "Z" in G17), e.g. the angle
    of a rotated corner from ``nck.measuring.rotated_corner``; ``target`` as in
    :class:`SetActualValue` (``$P_SETFR`` holds no rotation: a G500 target is refused).
    Write the rotation first, then set the corner with :class:`SetActualValue`."""

    angle_deg: float
    axis: str = "Z"
    target: str | None = None


@dataclass(frozen=True, slots=True)
class DeleteActiveWorkOffset:
    """"Delete active WO": the translations of the active settable frame (G54 …) become 0;
    under G500 those of ``$P_SETFR``. Active at once; same levels as :class:`SetActualValue`."""


Command = (
    SelectMode | SelectMachineFunction | SelectIncrement | CycleStart | CycleStop | Reset
    | EmergencyStop | SelectProgram | SetMdaProgram | SetProgramControl | SetOverride
    | CancelAlarms | Jog | SetControllerEnable | SetSpindleDriveFault | StartBlockSearch | WriteData | EnterPassword | DeletePassword
    | SetKeyswitch | ChangePassword | DeleteToolEdge | ClearRParameters | ActivateMachineData
    | WriteMachineSetup | WriteManualSettings | SetActualValue | SetWorkOffsetRotation | DeleteActiveWorkOffset
)
