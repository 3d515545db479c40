"""The status snapshot of :class:`nck.kernel.Nck`: :func:`build_status`, pure over the parts
it is handed (channel, switches, outputs, motion systems, interpreters, alarms, counters).

Positions come from the displayed motion system (the simulated one under
program test); the block display follows the block the main run executes
(``current_source`` of the motion system), not the interpreter's look-ahead;
service values of the drives come from ``axis_states()`` when the motion
system offers it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from nck.canon import Dwell, Motion
from nck.channel import INTERRUPTED
from nck.geometry.cutting_edge import effective_radius
from nck.geometry.tool_length import effective_lengths
from nck.interp.modal import ModalState
from nck.alarms import AlarmServer
from nck.channel_state import ChannelState, ControlSwitches, MachineOutputs
from nck.counters import PartCounters, RuntimeTimer
from nck.machine import MachineConfig
from nck.ncdata import NcData
from nck.status import AxisStatus, ChannelStatus, ModalView, NckStatus

BASIC_BLOCKS_BEFORE = 8
BASIC_BLOCKS_AFTER = 16
"""Display blocks of the basic block display before and after the executing one (on the control
MD28402 $MC_MM_ABSBLOCK_BUFFER_CONF[0] and [1], 002 L23596-23599)."""
SERVICE_FIELDS = (
    "position_actual_mm", "control_deviation_mm", "contour_deviation_mm",
    "velocity_setpoint_mm_min", "kv_calculated", "speed_setpoint_pct", "speed_actual_pct",
    "motor_speed_setpoint_rpm", "motor_speed_actual_rpm", "torque_nm", "current_pct",
    "motor_temperature_c", "controller_mode", "exact_stop_coarse", "exact_stop_fine", "clamped",
    "servo_parameter_set",
)
TEMPERATURE_DECIMALS = 1
"""The snapshot carries a motor temperature (r0035) as the service screen shows it, to a tenth of a
degree: the thermal model warms a drive that holds an axis against gravity a little in every
IPO cycle, and a snapshot that changed with it would make the panel redraw at every refresh of
an idle machine."""


def shown_temperature_c(temperature_c: float) -> float:
    """``temperature_c`` rounded to :data:`TEMPERATURE_DECIMALS`."""
    return round(temperature_c, TEMPERATURE_DECIMALS)


def _service_values(state: Any) -> dict[str, float]:
    """The service-screen values of a motion system's axis state (numbers only)."""
    values: dict[str, float] = {}
    for name in SERVICE_FIELDS:
        value = getattr(state, name, None)
        if isinstance(value, (bool, int, float)):
            values[name] = float(value)
    if "motor_temperature_c" in values:
        values["motor_temperature_c"] = shown_temperature_c(values["motor_temperature_c"])
    for name, value in dict(getattr(state, "extra", {}) or {}).items():
        if isinstance(value, (int, float)):
            values[name] = float(value)
    return values


@dataclass(frozen=True)
class StatusSources:
    """Everything the snapshot is read from, handed over by the kernel each time it is built.

    ``shown_motion`` is the motion system whose positions are displayed (the simulated one
    under program test), ``path_motion`` the one programs run on, ``motion`` the machine's
    own (drives, spindles, reference state). ``modal_interpreter`` supplies the displayed G
    codes, ``frame_interpreter`` the frames that turn positions into WCS while nothing
    executes (the run's interpreter, else the one that ran last; None: nothing has run
    since power on, the stored frames apply); either may be None.
    """

    machine: MachineConfig
    data: NcData
    channel: ChannelState
    switches: ControlSwitches
    outputs: MachineOutputs
    motion: Any
    shown_motion: Any
    path_motion: Any
    modal_interpreter: Any
    frame_interpreter: Any
    alarms: AlarmServer
    runtime: RuntimeTimer
    counters: PartCounters
    access_level: int
    keyswitch_position: int | None  # None: a kernel without access control
    internal_errors: int


def build_status(src: StatusSources) -> NckStatus:
    """The snapshot of ``src`` with ``seq`` and ``time_s`` 0 (the kernel stamps them)."""
    channel_state = src.channel
    shown = src.shown_motion
    positions = shown.positions_mcs()
    run = channel_state.active_run()
    current_source = src.path_motion.current_source() if run is not None else None
    # A program parked by a mode change (NC STOP, JOG) is still at the block it was
    # interrupted in: its first unexecuted item, not the interpreter's look-ahead.
    parked_items = channel_state.parked
    parked = parked_items[0] if parked_items and run is not None and run is not channel_state.overlay else None
    if current_source is None and parked is not None:
        current_source = parked.source
    executing_source = current_source  # None: the motion stands, everything taken has run
    if current_source is None and run is not None:
        current_source = run.last_executed_source()
    current = None
    executing: Motion | None = None
    executing_state: Motion | Dwell | None = None  # the segment or dwell in execution
    blocks: tuple = ()
    basic_blocks: tuple = ()
    basic_index = -1
    dtg: dict[str, float] = {}
    if run is not None:
        blocks = run.display_blocks()
        if current_source is not None:
            current = run.shown_for(current_source)
            for view in reversed(blocks if current is None else ()):
                if view.file == current_source.file and view.line == current_source.line:
                    current = view
                    break
            segment = parked if parked is not None and current_source is parked.source \
                else run.segments.get(id(current_source))
            if segment is not None and segment.source is current_source:
                executing_state = segment
                if isinstance(segment, Motion):
                    dtg = {a: float(v) - positions.get(a, 0.0) for a, v in segment.end_mcs.items()}
                    executing = segment
        if current is None and blocks:
            current = blocks[-1]
    if channel_state.basic_blocks is not None:
        basic_blocks, basic_index = channel_state.basic_blocks.around(
            executing_source, BASIC_BLOCKS_BEFORE, BASIC_BLOCKS_AFTER)
        if run is None:
            basic_index = -1  # the run ended (or RESET): its blocks stay, none is in execution
    offsets = dict(src.outputs.wcs_offset)
    scales: dict[str, float] = {}
    if executing is not None:
        # The WCS of the block being executed (the interpreter may already be ahead);
        # the transverse axis in diameter under DIAMON/DIAM90 (002 L32637-32660).
        diameter = (executing.gcodes or {}).get(29) in ("DIAMON", "DIAM90")
        for name, mcs_end in executing.end_mcs.items():
            if name in executing.end_wcs:
                scale = 2.0 if diameter and name in _diameter_axes(src.machine) else 1.0
                scales[name] = scale
                offsets[name] = float(mcs_end) - float(executing.end_wcs[name]) / scale
    wcs_now = _interpreter_wcs(src, positions) if executing is None else None
    axes = []
    getter = getattr(src.motion, "axis_states", None)
    drive = getter() if getter is not None else {}
    for axis in src.machine.axes:
        if axis.kind == "spindle":
            axes.append(_spindle_status(src, axis.name, positions))
            continue
        mcs = float(positions.get(axis.name, 0.0))
        state = drive.get(axis.name)
        axes.append(AxisStatus(
            name=axis.name, kind=axis.kind, position_mcs=mcs,
            position_wcs=(wcs_now[axis.name] if wcs_now and axis.name in wcs_now
                          else (mcs - offsets.get(axis.name, 0.0)) * scales.get(axis.name, 1.0)),
            distance_to_go=dtg.get(axis.name, 0.0),
            referenced=bool(src.motion.is_referenced(axis.name)),
            setpoint_mcs=float(state.position_setpoint_mm) if state is not None else mcs,
            velocity=float(state.velocity_actual_mm_min) if state is not None else 0.0,
            following_error=float(state.following_error_mm) if state is not None else 0.0,
            extra=_service_values(state) if state is not None else {},
        ))
    modal = _modal_view(src)
    if executing_state is not None and executing_state.gcodes:
        # The main run lags the interpreter: show the G codes and F of the executing block.
        feed = executing_state.feed if executing_state.feed is not None else modal.feed
        modal = replace(modal, gcodes={**dict(modal.gcodes), **dict(executing_state.gcodes)}, feed=feed)
    repos = {}
    if channel_state.repos_point is not None and channel_state.owner is not None:
        now = src.motion.positions_mcs()
        repos = {a: p - float(now[a]) for a, p in channel_state.repos_point.items()
                 if a in now and a in src.machine.path_axes}
    situation = channel_state.situation
    runtime, counters = src.runtime, src.counters
    program_state = situation.program
    if program_state == "running" and getattr(src.path_motion, "waiting_for_spindle", False):
        # A machining block waits for the spindle's set speed range (MD35500): the channel
        # stays active, the program waits (002 L21016-21040, L21104-21108).
        program_state = "waiting"
    channel = ChannelStatus(
        mode=situation.mode, machine_function=channel_state.machine_function,
        increment=channel_state.increment, channel_state=situation.channel,
        program_state=program_state, selected_program=channel_state.selected,
        current_block=current, blocks=blocks, basic_blocks=basic_blocks, basic_block_index=basic_index,
        modal=modal,
        program_control=dict(src.switches.program_control), overrides=dict(src.switches.overrides),
        path_feed_mm_min=shown.path_velocity_mm_min(), program_runtime_s=runtime.act_s,
        part_count=counters.actual, message=src.alarms.message,
        stop_reason=run.stop_reason if run is not None and situation.channel == INTERRUPTED else "",
        interrupted_program=channel_state.owner, mda_text=channel_state.mda_text,
        program_runtime_last_s=runtime.old_s, program_runtime_count=runtime.old_count,
        parts_total=counters.total, parts_required=counters.required,
        parts_special=counters.special, repos_offsets=repos,
    )
    return NckStatus(
        seq=0, time_s=0.0, channel=channel, axes=tuple(axes), alarms=src.alarms.active,
        access_level=src.access_level, keyswitch_position=src.keyswitch_position, machine_name=src.machine.name,
        emergency_stop=channel_state.estop_active, mode_group_ready=not channel_state.estop_active,
        alarm_log_seq=src.alarms.last_seq, internal_errors=src.internal_errors,
    )


def _diameter_axes(machine: MachineConfig) -> frozenset[str]:
    """The transverse axes (MD20100), shown in diameter under DIAMON/DIAM90."""
    return frozenset(a.name for a in machine.axes if a.diameter)


def _interpreter_wcs(src: StatusSources, positions: Any) -> dict[str, float] | None:
    """WCS of ``positions`` under the frames the interpreter holds now (when nothing executes).

    Uses the real interpreter's motion builder when it offers ``wcs_from_mcs``
    (display only; any failure falls back to the last executed segment's offset). With no
    ``frame_interpreter`` (nothing has run since power on) the frames are those of the
    power-on state: the stored frames chosen by the shown G codes, read afresh each time
    (into a new modal state; the interpreter's own is not touched).
    """
    interp = src.frame_interpreter
    modal = getattr(interp, "modal", None)
    if interp is None:
        interp = src.modal_interpreter
        modal = _power_on_modal(interp)
    convert = getattr(getattr(interp, "builder", None), "wcs_from_mcs", None)
    if convert is None or modal is None:
        return None
    try:
        wcs = convert(modal, {a: float(positions[a]) for a in src.machine.path_axes if a in positions})
    except Exception:  # noqa: BLE001 - display only
        return None
    return {a: float(v) for a, v in dict(wcs).items()}


def _power_on_modal(interp: Any) -> ModalState | None:
    """A fresh modal state with the G codes ``interp`` shows (None: not a real interpreter)."""
    table = getattr(interp, "table", None)
    shown = getattr(interp, "modal", None)
    if table is None or shown is None:
        return None
    modal = ModalState.initial(interp.machine, table)
    modal.gcodes = dict(shown.gcodes)
    return modal


def _spindle_status(src: StatusSources, name: str, positions: Any) -> AxisStatus:
    """A spindle: speed from the motion system when it models spindles, else programmed."""
    spindle = (getattr(src.motion, "spindles", None) or {}).get(name)
    state = getattr(spindle, "state", None)
    if state is not None and hasattr(state, "actual_rpm"):
        angle = float(getattr(state, "angle_deg", 0.0))
        return AxisStatus(
            name=name, kind="spindle", position_mcs=angle, position_wcs=angle, referenced=True,
            setpoint_mcs=angle, velocity=float(state.actual_rpm), speed_rpm=float(state.actual_rpm),
            extra={"setpoint_rpm": float(getattr(state, "setpoint_rpm", 0.0)),
                   # DB31 DBX83.1 / 83.2 as flags 1.0 / 0.0: the setpoint was clamped / raised
                   "setpoint_limited": float(bool(getattr(state, "setpoint_limited", False))),
                   "setpoint_increased": float(bool(getattr(state, "setpoint_increased", False))),
                   "override_pct": float(getattr(state, "override_pct", 100.0)),
                   "torque_nm": float(getattr(state, "torque_nm", 0.0)),
                   "motor_temperature_c": shown_temperature_c(float(getattr(state, "temperature_c", 0.0)))},
        )
    outputs = src.outputs
    rpm = outputs.spindle_rpm if outputs.spindle_state in ("M3", "M4") else 0.0
    if outputs.spindle_state == "M4":
        rpm = -rpm
    position = float(positions.get(name, 0.0)) if hasattr(positions, "get") else 0.0
    return AxisStatus(name=name, kind="spindle", position_mcs=position, position_wcs=position,
                      referenced=True, speed_rpm=rpm)


def _modal_view(src: StatusSources) -> ModalView:
    base = ModalView()
    getter = getattr(src.modal_interpreter, "modal_view", None)
    if getter is not None:
        try:
            base = getter()
        except Exception:  # noqa: BLE001 - display only
            base = ModalView()
    # Tool, edge, spindle and auxiliary functions as the main run output them:
    # the interpreter's own modal state is ahead of the machine (look-ahead).
    outputs = src.outputs
    length_mm, radius_mm = _edge_values(src)
    return replace(
        base, tool=outputs.tool, edge=outputs.edge, spindle_speed_rpm=outputs.spindle_rpm,
        spindle_state=outputs.spindle_state, aux=dict(outputs.aux),
        tool_length_mm=length_mm, tool_radius_mm=radius_mm,
    )


def _edge_values(src: StatusSources) -> tuple[float, float]:
    """Length 1 and radius of the active edge, geometry + wear (+ base for the length),
    with the wear sign of SD42930; 0, 0 without an active edge (T0 or D0)."""
    outputs = src.outputs
    edge = src.data.edge(outputs.tool, outputs.edge) if outputs.edge else None
    if edge is None:
        return 0.0, 0.0
    wear_sign = int(src.data.setting_data.get("SD42930") or 0)
    return effective_lengths(edge, wear_sign)[0], effective_radius(edge, wear_sign)
