"""Service screens of the Diagnostics area: overview, axis/spindle, drive, utilisation.

Rows are built from :class:`nck.status.AxisStatus` (service values in
``extra``, filled from the motion system's axis model) as
``(name, value, unit)`` triples; a row the motion system does not model shows
``—``.
"""

from __future__ import annotations


from rich.text import Text

from nck import fixed
from nck.status import AxisStatus, NckStatus

from hmi.i18n import N_, _
from hmi.utilisation import UtilisationMeter

CONTROLLER_MODES = {0: N_("0 position control"), 1: N_("1 speed control"), 2: N_("2 hold"),
                    3: N_("3 parking"), 4: N_("4 follow-up"), 5: N_("5 braking")}
DC_LINK_NOMINAL_V = 600.0
"""The drive model has no DC link: the service drive screen shows the nominal voltage."""
MOTOR_TEMP_WARN_C = 120.0
"""Motor temperature warning threshold (SINAMICS p0604, as the 611D MD1602 standard value)."""
Row = tuple[str, str, str]
MISSING = "—"


def _num(value: float | None, digits: int = 3) -> str:
    return MISSING if value is None else fixed(value, digits)


def _extra(axis: AxisStatus, name: str) -> float | None:
    value = axis.extra.get(name)
    return None if value is None else float(value)


def _yes(flag: bool | None) -> str:
    return MISSING if flag is None else (N_("yes") if flag else N_("no"))


def enables(status: NckStatus, axis: AxisStatus) -> dict[str, bool]:
    """The enable/state signals of the overview: column name -> on."""
    ready = status.mode_group_ready and not status.emergency_stop
    mode = _extra(axis, "controller_mode")
    follow_up = mode is not None and int(mode) == 4
    return {
        N_("Ctrl enable"): ready and not follow_up,
        N_("Pulse enable"): ready,
        N_("Referenced"): axis.referenced,
        N_("Pos. control"): ready and not follow_up,
        N_("Exact stop C"): bool(_extra(axis, "exact_stop_coarse") if _extra(axis, "exact_stop_coarse") is not None
                             else abs(axis.following_error) < 0.04),
        N_("Exact stop F"): bool(_extra(axis, "exact_stop_fine") if _extra(axis, "exact_stop_fine") is not None
                             else abs(axis.following_error) < 0.01),
        N_("Not clamped"): not bool(_extra(axis, "clamped") or 0.0),
    }


def overview_text(status: NckStatus) -> Text:
    """Axes as rows, enable signals as columns (✓ / ✗)."""
    axes = [a for a in status.axes]
    columns = list(enables(status, axes[0]).keys()) if axes else []
    text = Text(no_wrap=True, end="")
    text.append(f" {_('Axis'):<8}" + "".join(f"{_(c):>14}" for c in columns) + f"{_('Foll. error mm'):>18}\n",
                style="bold")
    for axis in axes:
        text.append(f" {axis.name:<8}")
        if axis.kind == "spindle":
            flags = {c: status.mode_group_ready for c in columns}
        else:
            flags = enables(status, axis)
        for name in columns:
            on = flags[name]
            text.append(" " * 13)
            text.append("✓" if on else "✗", style="green" if on else "bold red")
        fe = MISSING if axis.kind == "spindle" else fixed(axis.following_error, 3)
        text.append(f"{fe:>18}\n")
    return text


def axis_rows(status: NckStatus, axis: AxisStatus) -> list[Row]:
    """The rows of the service screen Axis/spindle (digest part 1 §8.3) for ``axis``."""
    overrides = status.channel.overrides
    if axis.kind == "spindle":
        unit = "deg"
        return [
            (N_("Position actual value MS1 (MCS)"), _num(axis.position_mcs), unit),
            (N_("Spindle speed setpoint programmed"), _num(status.channel.modal.spindle_speed_rpm, 1), "rpm"),
            (N_("Spindle speed setpoint current"), _num(_extra(axis, "setpoint_rpm"), 1), "rpm"),
            (N_("Speed actual value"), _num(axis.speed_rpm, 1), "rpm"),
            (N_("Override"), _num(_extra(axis, "override_pct") or overrides.get("spindle"), 0), "%"),
            (N_("Torque"), _num(_extra(axis, "torque_nm"), 2), "Nm"),
            (N_("Active measuring system"), "1", ""),
            (N_("Current gear stage"), "1", ""),
            (N_("Referenced status"), "1" if axis.referenced else "0", "bits"),
        ]
    unit = "deg" if axis.kind == "rotary" else "mm"
    rapid = status.channel.modal.gcodes.get(1, "") == "G0" if status.channel.modal.gcodes else False
    override = overrides.get("rapid" if rapid else "feed", 100.0)
    mode = _extra(axis, "controller_mode")
    referenced_bits = (1 if axis.referenced else 0) | (0 if axis.referenced else 2)
    return [
        (N_("Following error"), _num(axis.following_error), unit),
        (N_("System deviation (control error)"), _num(_extra(axis, "control_deviation_mm")), unit),
        (N_("Contour deviation"), _num(_extra(axis, "contour_deviation_mm")), unit),
        (N_("Servo gain factor (calculated)"), _num(_extra(axis, "kv_calculated")), "(m/min)/mm"),
        (N_("Active measuring system"), "1", ""),
        (N_("Position actual value MS1 (MCS)"), _num(_extra(axis, "position_actual_mm")
                                                 if "position_actual_mm" in axis.extra else axis.position_mcs), unit),
        (N_("Position setpoint"), _num(axis.setpoint_mcs), unit),
        (N_("Velocity actual value"), _num(axis.velocity, 1), f"{unit}/min"),
        (N_("Speed setpoint"), _num(_extra(axis, "speed_setpoint_pct"), 2), "%"),
        (N_("Speed actual value"), _num(_extra(axis, "speed_actual_pct"), 2), "%"),
        (N_("Override"), _num(override, 0), "%"),
        (N_("Active servo parameter set"), _num(_extra(axis, "servo_parameter_set"), 0), ""),
        (N_("Controller mode"), CONTROLLER_MODES.get(int(mode), str(mode)) if mode is not None else MISSING, ""),
        (N_("Referenced status"), f"{referenced_bits}", "bits"),
        (N_("Exact stop coarse / fine"), f"{_yes(bool(_extra(axis, 'exact_stop_coarse') or 0))} / "
                                     f"{_yes(bool(_extra(axis, 'exact_stop_fine') or 0))}", ""),
        (N_("Clamping active"), _yes(bool(_extra(axis, "clamped") or 0)), ""),
    ]


def drive_rows(status: NckStatus, axis: AxisStatus) -> list[Row]:
    """The rows of the service screen Drive (digest part 1 §8.4) for ``axis``."""
    ready = status.mode_group_ready and not status.emergency_stop
    temperature = _extra(axis, "motor_temperature_c")
    current = _extra(axis, "current_pct")
    if axis.kind == "spindle":
        setpoint = _extra(axis, "setpoint_rpm")
        actual = axis.speed_rpm
    else:
        setpoint = _extra(axis, "motor_speed_setpoint_rpm")
        actual = _extra(axis, "motor_speed_actual_rpm")
    # An 828D / 840D sl drives SINAMICS: the enables are the drive's sequence-control
    # words (r0898 control word, r0899 status word) and the PLC's axis interface
    # signals, not the SIMODRIVE 611D terminals (64/63/48/112) of the older manuals.
    # The shared manuals describe only the 611D screen; these names are our choice.
    return [
        (N_("ON / OFF1 (r0898.0)"), _yes(ready), ""),
        (N_("No coast down, OFF2 (r0898.1)"), N_("yes"), ""),
        (N_("No fast stop, OFF3 (r0898.2)"), _yes(ready), ""),
        (N_("Enable operation (r0898.3)"), _yes(ready), ""),
        (N_("Infeed ready, DC link charged (p0864)"), N_("yes"), ""),
        (N_("Ready for switching on (r0899.0)"), N_("yes"), ""),
        (N_("Operation enabled (r0899.2)"), _yes(ready), ""),
        (N_("Pulses enabled (r0899.11)"), _yes(ready), ""),
        (N_("PLC pulse disable (DBX21.7)"), N_("no"), ""),
        (N_("Pulses enabled to the PLC (DBX93.7)"), _yes(ready), ""),
        (N_("Drive ready (DBX93.5)"), _yes(ready), ""),
        (N_("DC link voltage, nominal (r0070)"), _num(DC_LINK_NOMINAL_V, 0), "V"),
        (N_("Speed setpoint (r0060)"), _num(setpoint, 1), "rpm"),
        (N_("Speed actual value (r0063)"), _num(actual, 1), "rpm"),
        (N_("Smoothed actual current"), _num(current, 1), "%"),
        (N_("Motor temperature (r0035)"), _num(temperature, 1), "°C"),
        (N_("Warning: motor temperature"), _yes(temperature is not None and temperature > MOTOR_TEMP_WARN_C), ""),
        (N_("Warning: power unit at I²t limit"), _yes(current is not None and current > 100.0), ""),
        (N_("Drive data set, selected / active (r0051)"), "1 / 1", ""),
        (N_("Operating mode"), N_("main spindle drive") if axis.kind == "spindle" else N_("feed drive"), ""),
    ]


def rows_text(title: str, rows: list[Row]) -> Text:
    """A ``Name | Value | Unit`` table; names and word values (yes, no …) in the panel's language."""
    text = Text(no_wrap=True, end="")
    text.append(f" {title}\n", style="bold")
    text.append(f" {_('Name'):<48}{_('Value'):>22}  {_('Unit')}\n", style="bold")
    for name, english_value, unit in rows:
        value = " / ".join(_(part) for part in english_value.split(" / "))
        text.append(f" {_(name):<48}")
        text.append(" " * max(22 - len(value), 0))
        text.append(value, style="bold" if value != MISSING else "dim")
        text.append(f"  {_(unit)}\n")
    return text


# -- system utilisation ----------------------------------------------------------------------
def utilisation_rows(meter: UtilisationMeter, ipo_cycle_s: float, buffer: tuple[int, int],
                     cycles_total: int, blocks_total: int) -> list[Row]:
    """The rows of the system utilisation screen (real measured figures)."""
    figures = meter.figures(ipo_cycle_s)
    fill, size = buffer
    return [
        (N_("IPO cycle"), _num(ipo_cycle_s * 1000.0, 1), "ms"),
        (N_("Compute time per IPO cycle (mean)"), _num(figures["cycle_compute_us"], 1), "µs"),
        (N_("Compute time per IPO cycle (worst tick)"), _num(figures["cycle_compute_max_us"], 1), "µs"),
        (N_("IPO cycle load"), _num(figures["ipo_load_pct"], 2), "%"),
        (N_("Interpreter blocks per second (wall clock)"), _num(figures["blocks_per_s"], 1), "1/s"),
        (N_("Interpreter blocks per second (control time)"), _num(figures["blocks_per_sim_s"], 1), "1/s"),
        (N_("Block buffer fill"), f"{fill} / {size}", N_("blocks")),
        (N_("IPO cycles measured"), _num(figures["cycles_measured"], 0), ""),
        (N_("IPO cycles since power on"), str(cycles_total), ""),
        (N_("Blocks interpreted since power on"), str(blocks_total), ""),
    ]
