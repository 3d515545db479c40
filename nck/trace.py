"""Servo trace: record up to four signals every IPO cycle from the axis model.

A :class:`TraceRecorder` is attached to a kernel (``Nck.cycle_listeners``) and
samples its signals at the end of every IPO cycle, so its time base is the
simulated control's, never a wall clock. Signals are named ``<axis>.<quantity>``:

=====================  ============================================  =======
signal                 what                                          unit
=====================  ============================================  =======
``X.position``         position (MCS) as displayed and in ``--trace``  mm/deg
``X.actual``           actual position of the measuring system (MCS)  mm/deg
``X.velocity``         actual velocity                               mm/min
``X.following_error``  setpoint − actual position                    mm
``S1.speed``           actual spindle speed                          rpm
``feed_override``      feed override of the channel                  %
``spindle_override``   spindle override of the channel               %
=====================  ============================================  =======

Trigger ``now`` records from the next cycle on; ``nc_start`` waits until the
channel becomes active in AUTOMATIC or MDA. Recording ends after
``duration_s`` of simulated time. :func:`trace_csv` writes the samples as CSV:
``t_s`` then one column per signal; an axis position column is headed with the
bare axis name, as in ``nck run --trace``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Mapping, Sequence

from nck.number_text import fixed
from nck.refused import Refused

MAX_SIGNALS = 4
TRIGGERS = ("now", "nc_start")
AXIS_QUANTITIES: dict[str, str] = {
    "position": "mm",
    "actual": "mm",
    "velocity": "mm/min",
    "following_error": "mm",
}
CHANNEL_SIGNALS: dict[str, str] = {"feed_override": "%", "spindle_override": "%"}


class TraceError(Refused, ValueError):
    """A trace setting that cannot be used (unknown signal, too many, bad duration): a keyed
    refusal (``trace_*`` in ``data/refusals.toml``) that a panel says in its language."""


@dataclass(frozen=True, slots=True)
class TraceSettings:
    """What to record: signal names (≤ 4), the trigger and the duration in seconds."""

    signals: tuple[str, ...]
    trigger: str = "now"
    duration_s: float = 5.0


def available_signals(machine: Any) -> list[str]:
    """Every signal the machine offers, in display order."""
    names: list[str] = []
    for axis in machine.axes:
        if axis.kind == "spindle":
            names.append(f"{axis.name}.speed")
        else:
            names.extend(f"{axis.name}.{quantity}" for quantity in AXIS_QUANTITIES)
    names.extend(CHANNEL_SIGNALS)
    return names


def signal_unit(signal: str) -> str:
    """The unit of ``signal`` (``mm``, ``mm/min``, ``rpm``, ``%``)."""
    if signal in CHANNEL_SIGNALS:
        return CHANNEL_SIGNALS[signal]
    quantity = signal.partition(".")[2]
    if quantity == "speed":
        return "rpm"
    return AXIS_QUANTITIES.get(quantity, "")


def csv_column(signal: str) -> str:
    """CSV column heading: the bare axis name for a position, else ``<signal>_<unit>``."""
    axis, _, quantity = signal.partition(".")
    if quantity == "position":
        return axis
    unit = signal_unit(signal).replace("/", "_").replace("%", "pct")
    return f"{signal.replace('.', '_')}_{unit}"


def validate(settings: TraceSettings, machine: Any) -> None:
    """Raise :class:`TraceError` when ``settings`` cannot be recorded on ``machine``."""
    if not settings.signals:
        raise TraceError("trace_no_signal")
    if len(settings.signals) > MAX_SIGNALS:
        raise TraceError("trace_too_many_signals", max=MAX_SIGNALS)
    known = set(available_signals(machine))
    for signal in settings.signals:
        if signal not in known:
            raise TraceError("trace_unknown_signal", signal=signal)
    if settings.trigger not in TRIGGERS:
        raise TraceError("trace_unknown_trigger", trigger=settings.trigger)
    if not settings.duration_s > 0:
        raise TraceError("trace_duration")


def _reader(signal: str) -> Callable[[Any, dict[str, Any]], float]:
    """A function (kernel, per-cycle cache) -> value of ``signal``."""
    if signal == "feed_override":
        return lambda nck, cache: float(nck.switches.overrides.get("feed", 100.0))
    if signal == "spindle_override":
        return lambda nck, cache: float(nck.switches.overrides.get("spindle", 100.0))
    axis, _, quantity = signal.partition(".")

    def positions(nck: Any, cache: dict[str, Any]) -> Any:
        if "positions" not in cache:
            cache["positions"] = nck.positions_mcs()
        return cache["positions"]

    def states(nck: Any, cache: dict[str, Any]) -> dict[str, Any]:
        if "states" not in cache:
            cache["states"] = nck.axis_states()
        return cache["states"]

    if quantity == "position":
        return lambda nck, cache: float(positions(nck, cache).get(axis, 0.0))
    if quantity == "speed":
        def spindle_speed(nck: Any, cache: dict[str, Any]) -> float:
            spindle = (getattr(nck.motion, "spindles", None) or {}).get(axis)
            state = getattr(spindle, "state", None)
            if state is not None and hasattr(state, "actual_rpm"):
                return float(state.actual_rpm)
            return float(nck.outputs.spindle_rpm) if nck.outputs.spindle_state in ("M3", "M4") else 0.0
        return spindle_speed
    field_name = {"actual": "position_actual_mm", "velocity": "velocity_actual_mm_min",
                  "following_error": "following_error_mm"}[quantity]

    def from_state(nck: Any, cache: dict[str, Any]) -> float:
        state = states(nck, cache).get(axis)
        if state is None:  # a motion system without a servo model: actual = displayed, no lag
            return float(positions(nck, cache).get(axis, 0.0)) if quantity == "actual" else 0.0
        return float(getattr(state, field_name))

    return from_state


class TraceRecorder:
    """Samples ``settings.signals`` every IPO cycle of the kernel it is attached to.

    ``state`` is ``idle`` (not attached), ``armed`` (waiting for NC START),
    ``recording`` or ``done``. ``times_s`` and ``columns`` hold the samples.
    """

    def __init__(self, settings: TraceSettings, machine: Any) -> None:
        validate(settings, machine)
        self.settings = settings
        self.state = "idle"
        self.times_s: list[float] = []
        self.columns: dict[str, list[float]] = {name: [] for name in settings.signals}
        self._readers = [(name, _reader(name)) for name in settings.signals]
        self._start_s = 0.0
        self._was_active = (False, False)
        self._nck: Any = None

    # -- attaching -------------------------------------------------------------------
    def attach(self, nck: Any) -> None:
        """Start: arm the trigger and sample at the end of every IPO cycle of ``nck``."""
        self.detach()
        self._nck = nck
        self.times_s.clear()
        for column in self.columns.values():
            column.clear()
        self._was_active = self._active(nck)
        if self.settings.trigger == "now":
            self._begin(nck)
        else:
            self.state = "armed"
        nck.cycle_listeners.append(self._on_cycle)

    def detach(self) -> None:
        """Stop sampling (the samples taken so far stay)."""
        if self._nck is not None and self._on_cycle in self._nck.cycle_listeners:
            self._nck.cycle_listeners.remove(self._on_cycle)
        self._nck = None
        if self.state in ("armed", "recording"):
            self.state = "done"

    # -- sampling ----------------------------------------------------------------------
    @staticmethod
    def _active(nck: Any) -> tuple[bool, bool]:
        """(channel active, program not aborted) in AUTOMATIC or MDA."""
        situation = nck.situation
        program_mode = situation.mode in ("AUTO", "MDA")
        return (program_mode and situation.channel == "active",
                program_mode and situation.program != "aborted")

    def _begin(self, nck: Any) -> None:
        self.state = "recording"
        self._start_s = float(nck.time_s)

    def _on_cycle(self, nck: Any) -> None:
        if self.state == "armed":
            # NC START: the channel became active, or a program left "aborted" (an
            # alarm may stop it again within its very first cycle).
            active = self._active(nck)
            was_active = self._was_active
            if (active[0] and not was_active[0]) or (active[1] and not was_active[1]):
                self._begin(nck)
                self._start_s -= float(nck.ipo_cycle_s)  # the starting cycle is the first sample
            self._was_active = active
        if self.state != "recording":
            return
        cache: dict[str, Any] = {}
        self.times_s.append(float(nck.time_s))
        for name, read in self._readers:
            self.columns[name].append(read(nck, cache))
        if float(nck.time_s) - self._start_s >= self.settings.duration_s - 1e-9:
            self.detach()

    # -- results -------------------------------------------------------------------------
    @property
    def sample_count(self) -> int:
        """Number of samples taken."""
        return len(self.times_s)

    def value_at(self, index: int) -> dict[str, float]:
        """The values of every signal at sample ``index`` (cursor read-out)."""
        return {name: column[index] for name, column in self.columns.items()}

    def to_csv(self) -> str:
        """The samples as CSV text (see :func:`trace_csv`)."""
        return trace_csv(self.times_s, {csv_column(n): c for n, c in self.columns.items()})


def trace_csv(times_s: Sequence[float], columns: Mapping[str, Sequence[float]]) -> str:
    """CSV: a header ``t_s,<columns…>``, then one row per sample (time in ms steps, values 6 decimals)."""
    lines = [",".join(["t_s", *columns])]
    values = list(columns.values())
    for index, t in enumerate(times_s):
        row = [fixed(t, 3)] + [fixed(column[index], 6) for column in values]
        lines.append(",".join(row))
    return "\n".join(lines) + "\n"


class AxisTrace:
    """Positions of any number of axes every IPO cycle (no four-signal limit): ``--trace``."""

    def __init__(self, axes: Sequence[str], duration_s: float = 1e12) -> None:
        self.axes = list(axes)
        self.duration_s = duration_s
        self.times_s: list[float] = []
        self.columns: dict[str, list[float]] = {name: [] for name in self.axes}

    def attach(self, nck: Any) -> None:
        """Sample ``nck`` at the end of every IPO cycle from now on."""
        nck.cycle_listeners.append(self._on_cycle)

    def _on_cycle(self, nck: Any) -> None:
        if self.times_s and nck.time_s - self.times_s[0] >= self.duration_s:
            return
        positions = nck.positions_mcs()
        self.times_s.append(float(nck.time_s))
        for name in self.axes:
            self.columns[name].append(float(positions.get(name, 0.0)))

    def to_csv(self) -> str:
        """``t_s`` then one column per axis (MCS), every IPO cycle."""
        return trace_csv(self.times_s, self.columns)
