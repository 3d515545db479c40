"""The contract between the channel (kernel) and the motion system.

The channel pushes canonical motion into a bounded queue; the motion system
plans and interpolates it when the kernel advances time. All quantities are
in the MCS, millimetres (degrees for rotary axes), seconds.
"""

from __future__ import annotations

from typing import Callable, Collection, Mapping, Protocol

from nck.canon import Dwell, Motion, Source
from nck.errors import NcAlarmError


class MotionSystem(Protocol):
    """Planner + interpolator + axes, as the channel sees them."""

    def can_accept(self) -> bool:
        """True while the block buffer has room for another segment."""

    def buffer_fill(self) -> tuple[int, int]:
        """(segments and dwells in the block buffer, its capacity), for the diagnosis."""

    def path_speed_ceiling_mm_s(self) -> float | None:
        """An upper bound of the path velocity (mm/s) until every segment buffered now has run
        (JOG not included), for the contact watch's step bound; None when the motion has no
        planned profile to bound it (the watch then assumes every axis at rapid)."""

    def buffered_speed_ceiling_mm_s(self) -> float:
        """The highest velocity limit (mm/s) of the segments buffered since the last
        :meth:`path_speed_ceiling_mm_s` (0 when there is none)."""

    def push(self, item: Motion | Dwell) -> None:
        """Append a segment or dwell to the buffer (planned with look-ahead)."""

    def advance(self, dt_s: float) -> None:
        """Advance simulated time by ``dt_s`` (a whole number of IPO cycles)."""

    def is_idle(self) -> bool:
        """True when the buffer is empty and every axis stands still."""

    def hold(self) -> None:
        """NC STOP: brake along the path on the ramp and stay interrupted."""

    def resume(self) -> None:
        """NC START after hold: continue the interrupted segment."""

    def abort(self, keep_spindles: Collection[str] = ()) -> None:
        """RESET: brake, then discard everything buffered; the spindles stop except those
        named in ``keep_spindles``."""

    def positions_mcs(self) -> Mapping[str, float]:
        """Actual positions of every axis (MCS)."""

    def set_overrides(self, feed_percent: float, rapid_percent: float) -> None:
        """Set the effective path feed override and rapid traverse override (0 … 200 %, 0 … 100 %).

        Applies on the fly to buffered and running segments; the feed override
        also scales JOG velocities. The kernel has already folded ROV into
        ``rapid_percent``.
        """

    def reposition(self, feed_mm_min: float | None) -> None:
        """REPOS: after ``hold()``, when the axes may have been moved in JOG since.

        On the next ``resume()`` the axes first travel linearly from their actual
        positions back to the point where they were held (RMI), at ``feed_mm_min``
        (``None`` = rapid traverse), then the interrupted remainder continues.
        A zero-length approach must be harmless. (The kernel does not rely on
        this: when a program is left for JOG/MDA it keeps the unexecuted segments,
        calls ``abort()``, and on NC START pushes the approach and the remainder.)
        """

    def current_source(self) -> Source | None:
        """The block whose segment or dwell is executing now (None when idle).

        The channel shows it as the current block, so the display lags the
        interpreter's look-ahead as on the real control.
        """

    def drain_alarms(self) -> list[NcAlarmError]:
        """Return and forget the alarms raised by monitoring since the last call."""

    def set_dry_run(self, feed_mm_min: float | None, mode: int = 0) -> None:
        """Dry run on with SD42100 ``feed_mm_min`` and SD42101 ``mode``, or off (None).

        Acts on every buffered segment that has not started, and on the interrupted one
        while the path is held (002 L18181-18182); a segment in execution keeps its feed.
        """

    def path_velocity_mm_min(self) -> float:
        """The velocity the interpolator traverses at now (the actual feed of the display).

        Along the path of the executing segment (G0 at its rapid velocity, both with their
        override, also while braking), else of the JOG motion; 0 while the axes stand
        (NC STOP, dwell, exact-stop wait, idle).
        """


class JogControl(Protocol):
    """JOG and referencing, as the channel sees them (same object as the MotionSystem)."""

    def jog_continuous(self, axis: str, direction: int, velocity_mm_min: float) -> None:
        """Start (direction ±1) or stop (0) continuous JOG of one axis."""

    def jog_increment(self, axis: str, distance_mm: float, velocity_mm_min: float) -> None:
        """Traverse one axis by a signed increment."""

    def start_reference(self, axis: str) -> None:
        """Start the reference point approach of one axis (JOG-REF)."""

    def is_referenced(self, axis: str) -> bool:
        """True once the axis has been referenced."""

    def jog_active(self) -> bool:
        """True while any axis moves in JOG (braking included) or a reference approach runs."""

    def set_referenced(self, axis: str, referenced: bool) -> None:
        """Mark an axis referenced (or not) without motion: absolute encoders, headless runs.

        Notes for implementers (kernel use): ``is_idle()`` is False while a JOG
        motion or reference point approach is under way; ``jog_continuous(axis, 0)``
        stops any JOG motion of that axis, an increment too (the kernel continues
        an interrupted increment with a new ``jog_increment``); ``hold()`` and
        ``resume()`` act on the path only, and JOG must work while a path is held.
        """


class MotionExtensions(Protocol):
    """Optional extras of the planned motion (:class:`nck.motion.system.PlannedMotion`).

    Callers use them through ``getattr`` so that the stand-in keeps working.
    """

    @property
    def ipo_cycle_s(self) -> float:
        """The interpolation cycle (MD10050 × MD10070) in seconds."""

    def axis_states(self) -> Mapping[str, object]:
        """Service-screen values per path axis (``nck.motion.servo.AxisState``)."""

    def drain_cleared_alarms(self) -> list[int]:
        """Numbers of self-clearing alarms (10621, 10631) whose cause went since the last call."""

    def attach_setting_data(self, setting_data: Mapping[str, object]) -> None:
        """Read the working-area setting data (SD43400 … SD43430) live from this mapping."""

    def cycles_until_block_change(self) -> int:
        """IPO cycles the current segment or dwell surely still runs; advancing that many at
        once gives the same motion as cycle by cycle (numpy per block)."""

    def advance_cycles(self, n_cycles: int, on_block_event: Callable[[int], int] | None = None) -> int:
        """Advance at most ``n_cycles`` IPO cycles, ending the step with the cycle of the next
        block event; at an event ``on_block_event(cycles_done)`` may do the caller's per-cycle
        work and answer how many more cycles may run (0 = stop). Returns the cycles run; the
        result is the same as one cycle per call (the kernel's batched steps)."""

    def enable_trace(self) -> None:
        """Record every IPO-cycle setpoint from now on (``nck run --trace``)."""
