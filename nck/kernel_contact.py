"""Contact of the tool with the blank or the reference block during motion (a part of ``Nck``).

Every kernel step, when something is clamped (``NcData.machine_setup``) and the axes move,
the straight segment the tool tip travelled in that step is intersected with each solid
(:func:`nck.contact.first_contact`). Steps are kept short enough near a solid: a step of
``n`` IPO cycles may run only while the tip cannot reach any solid within them (the gap
function is a lower bound of the distance), so every step that can touch is a single IPO
cycle — one straight segment between two interpolation setpoints, at any feed, override, in
JOG, INC, MDA and AUTO. The tip travels at most the path distance, so ``n`` cycles at the
path velocity bound ``v`` travel at most ``n · v · T`` (times a margin). The bound ``v``:

* a program's path motion: the motion's velocity ceiling (the velocity now and the limit of
  every buffered segment with the overrides, :meth:`PlannedMotion.path_speed_ceiling_mm_s`).
  A block buffered inside the step can be faster: at every block event inside the step (the
  program was just fed) the rest of the gap is divided by the ceiling again, and the step ends
  there when no further cycle fits (:meth:`ContactWatch.cycles_left`);
* JOG, a reference point approach, a motion without that ceiling: every path axis at its
  MD32000 velocity at once.

What a contact is (issue 22; the manuals do not describe a simulated workpiece):

* a 3D probe (tool type 710) **switches**: its trigger position (the machine positions at
  the exact point of contact) is recorded; JOG motion stops. Driven on more than
  :data:`PROBE_OVERTRAVEL_MM` into the surface it is a crash (alarm 90003);
* a cutter touching while the spindle turns (M3/M4, speed > 0) and the axes do not move at
  rapid traverse is **scratching**: recorded, no alarm, the motion goes on;
* anything else — a cutter with the spindle at rest (90001), a rapid move into a solid
  (90002) — is a **crash**: an alarm of the trainer's own number range 90000 … 90099 (not a
  SINUMERIK number; data/alarms/contact.toml), in the alarm log; the motion stops.

A tool already in contact moving deeper is judged the same way (a turning cutter goes on
cutting). What a cutter removes cutting with the spindle turning (not at rapid traverse) is
gone for the moves that follow: on a lathe the bar is turned (:mod:`nck.turned_bar`), on a
mill the blank is milled (:mod:`nck.milled_blank`, the simulation's Z-map). A rapid move back
into a drilled hole or through a milled slot is therefore no crash, a rapid move into material
still there is; clamping a blank again (a new set-up) brings the whole blank back, as does a
restart (what was cut is not retained data).

In a program, ``MEAS=1``/``MEAW=1`` make a block a measuring block for the probe (002 L32646-32663
names their results): when the probe switches in it, the trigger position is ``$AA_MM[axis]``
(MCS) and ``$AA_MW[axis]`` (WCS of that block), the probe status ``$AC_MEA[1]`` is 1;
``MEAS`` deletes the distance to go (the axes brake inside the overtravel, the next block —
interpreted only after the axes stand — starts from there), ``MEAW`` runs the block to its
end. A measuring block that reaches its end without a switch leaves ``$AC_MEA[1]`` at 0 and
the last results unchanged, without an alarm (our choice: the manuals at hand do not say more).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

from nck.alarms import AlarmServer
from nck.canon import THREAD_AND_TAPPING_KINDS
from nck.channel_state import ChannelState, ControlSwitches, MachineOutputs, MachinePlant
from nck.contact import BALL, CUTTER, ToolBody, clearance, first_contact
from nck.errors import NcAlarmError
from nck.milled_blank import MilledBlank
from nck.ncdata import NcData
from nck.turned_bar import Z_GRID_MM, TurnedBar
from nck.workpiece import Cylinder, Point

PROBE_TOOL_TYPE = 710  # 3D probe (milling)
PROBE_OVERTRAVEL_MM = 2.0  # trainer choice: how far a probe's stylus may be deflected
ALARM_CRASH_SPINDLE_STOPPED = 90001
ALARM_CRASH_RAPID = 90002
ALARM_CRASH_PROBE_OVERTRAVEL = 90003
EVENT_LIMIT = 100
STEP_MARGIN = 1.25  # the servo setpoints may exceed the path velocity a little
DEEPER_MM = 1e-9


SURFACE_SLACK_MM = 1e-6
"""A tip at most this deep counts as on the surface, not in the solid (the sums of increments)."""


def _leaving(body: ToolBody, solid: Any, start: Point, end: Point) -> bool:
    """True when the tip starts on the surface of ``solid`` and the step takes it off (never in)."""
    before = clearance(body, solid, start)
    return before >= -SURFACE_SLACK_MM and clearance(body, solid, end) > before


def _cycles_within(budget: StepBudget) -> int:
    """How many more cycles of ``budget.cycle_mm`` fit into the gap not yet spent."""
    if budget.cycle_mm <= 0.0:
        return 1 << 30  # nothing moves at the ceiling: asked again when a block is buffered
    return max(int((budget.gap_mm - budget.spent_mm) / budget.cycle_mm), 0)


def _point(before: dict[str, float], after: dict[str, float], t: float) -> dict[str, float]:
    """The machine positions at parameter ``t`` of the step from ``before`` to ``after``."""
    return {a: before.get(a, after[a]) + (after[a] - before.get(a, after[a])) * t for a in after}


@dataclass(frozen=True, slots=True)
class ContactEvent:
    """A contact of the tool with a solid: ``kind`` ``"probe"`` (switched), ``"scratch"`` or
    ``"crash"``; ``solid`` ``"blank"``/``"reference"``; ``position_mcs`` the machine
    positions of the path axes at the exact point of contact; ``tool``/``edge`` T and D;
    ``seq`` counts events since power on; ``time_s`` the control time."""

    seq: int
    kind: str
    solid: str
    position_mcs: dict[str, float]
    tool: int
    edge: int
    time_s: float


@dataclass
class StepBudget:
    """A kernel step bounded by the path velocity ceiling: the gap at its start, the distance
    the cycles run so far may have travelled, and the distance one more cycle may travel."""

    gap_mm: float
    spent_mm: float
    cycles: int  # cycles counted into spent_mm
    cycle_mm: float


@dataclass
class ContactState:
    """The kernel's contact bookkeeping: the events (bounded) and the solids touched now."""

    events: list[ContactEvent] = field(default_factory=list)
    touching: set[str] = field(default_factory=set)
    seq: int = 0
    jog_rapid: bool = False
    rapid: bool = False  # the step being judged started at rapid traverse
    threading: bool = False  # ... in a tapping or thread-cutting block (G33, G331, G63 …)
    measuring: Any = None  # the MEAS/MEAW segment executing at the start of the step, else None
    measured_block: int | None = None  # id of the measuring block the results below belong to
    switched: bool = False  # $AC_MEA[1]: the probe switched in that block
    measured_mcs: dict[str, float] = field(default_factory=dict)  # $AA_MM
    measured_wcs: dict[str, float] = field(default_factory=dict)  # $AA_MW
    free: tuple[float, ToolBody, Point] | None = None  # at the step's start: gap to every solid, tool body, tip offset
    budget: StepBudget | None = None  # the step's gap spent at the motion's velocity ceiling
    material: TurnedBar | MilledBlank | None = None  # what is left of the blank object ``material_from``
    material_from: Any = None


class ContactWatch:
    """Contact detection in the kernel cycle, on the parts it is given; it owns the contact
    bookkeeping (:attr:`state`)."""

    def __init__(self, plant: MachinePlant, data: NcData, channel: ChannelState, switches: ControlSwitches,
                 outputs: MachineOutputs, alarms: AlarmServer, ipo_s: float, *,
                 path_motion: Callable[[], Any], clock: Callable[[], float],
                 motion_alarm: Callable[[NcAlarmError], None]) -> None:
        self.state = ContactState()
        self.plant = plant  # the machine and its motion system
        self.data = data  # the machine set-up (what is clamped) and the tool edges
        self.channel = channel
        self.switches = switches  # no contact under program test
        self.outputs = outputs  # the active tool and edge, the spindle
        self.alarms = alarms  # a crash alarm already pending is not raised again
        self.ipo_s = ipo_s
        self.path_motion = path_motion  # the motion system programs run on (the kernel's choice)
        self.clock = clock  # the control time of an event
        self.motion_alarm = motion_alarm  # raises a crash with the reactions of a motion alarm

    # ---------------------------------------------------------------- reading
    def events(self, since_seq: int = 0) -> tuple[ContactEvent, ...]:
        """The contact events after ``since_seq`` (oldest first, bounded)."""
        return tuple(event for event in self.state.events if event.seq > since_seq)

    def probe_deflected(self) -> bool:
        """True while the active tool is a 3D probe in contact with a solid."""
        return bool(self.state.touching) and self.tool_body()[0].shape == BALL

    # ---------------------------------------------------------------- the tool
    def tool_body(self) -> tuple[ToolBody, Point]:
        """The active tool's body and its tip offset (machine position − tip) in X, Y, Z."""
        edge = self.data.edge(self.outputs.tool, self.outputs.edge) if self.outputs.edge else None
        if edge is None:
            return ToolBody(CUTTER, 0.0, 0.0), (0.0, 0.0, 0.0)
        radius = max(edge.get(6) + edge.get(15), 0.0)
        length1, length2 = edge.get(3) + edge.get(12), edge.get(4) + edge.get(13)
        if self.plant.machine.kind == "lathe":  # L1 along X, L2 along Z; the cutting edge a ball
            return ToolBody(BALL, radius), (length1, 0.0, length2)
        shape = BALL if edge.tool_type == PROBE_TOOL_TYPE else CUTTER
        true_length = self.data.machine_setup.true_length(self.outputs.tool)  # a tool whose data are wrong
        length1 = true_length if true_length is not None else length1
        return ToolBody(shape, radius, max(length1, 0.0)), (0.0, 0.0, length1)  # G17: the tool along Z

    def _tip(self, positions: dict[str, float], offset: Point) -> Point:
        return (positions.get("X", 0.0) - offset[0], positions.get("Y", 0.0) - offset[1],
                positions.get("Z", 0.0) - offset[2])

    def _watched(self) -> bool:
        return bool(self.data.machine_setup.solids()) and not self.switches.program_control["program_test"]

    # ---------------------------------------------------------------- the cycle
    def cycle_limit(self, cycles: int) -> int:
        """At most as many IPO cycles as the tool surely cannot reach a solid in."""
        self.state.free = None
        self.state.budget = None
        if cycles <= 1 or not self._watched():
            return cycles
        if (self.channel.run is None and self.channel.overlay is None and not self.channel.jogging
                and self.plant.motion.is_idle()):
            return cycles  # nothing can start moving inside this step
        body, offset = self.tool_body()
        tip = self._tip(self.plant.positions(), offset)
        # A milled blank: the solid's gap is a lower bound of the gap to what is left (its
        # height map is built only when the tool comes near: ``watch``).
        bar = self._material() if self.plant.machine.kind == "lathe" else None
        if not isinstance(bar, TurnedBar):
            bar = None
        gap = min(bar.clearance(body, tip) if bar and name == "blank" else clearance(body, solid, tip)
                  for name, solid in self.data.machine_setup.solids())
        self.state.free = (gap, body, offset)
        if gap <= 0.0:
            return 1
        ceiling = self._ceiling()
        if ceiling is None:
            return max(1, min(cycles, int(gap / (self._max_path_mm_s() * self.ipo_s * STEP_MARGIN))))
        budget = StepBudget(gap, 0.0, 0, ceiling * self.ipo_s * STEP_MARGIN)
        self.state.budget = budget
        return max(1, min(cycles, _cycles_within(budget)))

    def cycles_left(self, cycles_done: int) -> int | None:
        """Inside a step, at a block event after ``cycles_done`` cycles (the program was just
        fed): how many more cycles the tip surely cannot reach a solid in (0: end the step
        here); ``None`` when the step is not bounded by the motion's velocity ceiling."""
        budget = self.state.budget
        if budget is None:
            return None
        budget.spent_mm += (cycles_done - budget.cycles) * budget.cycle_mm
        budget.cycles = cycles_done
        ceiling = self.plant.motion.buffered_speed_ceiling_mm_s()  # blocks buffered inside the step
        budget.cycle_mm = max(budget.cycle_mm, ceiling * self.ipo_s * STEP_MARGIN)
        return _cycles_within(budget)

    def _ceiling(self) -> float | None:
        """The path velocity ceiling of a program's motion (mm/s), ``None`` while JOG moves
        (or for a motion without one)."""
        motion = self.plant.motion
        if self.channel.jogging or motion.jog_active():
            return None
        return motion.path_speed_ceiling_mm_s()

    def _max_path_mm_s(self) -> float:
        speeds = [float(self.plant.machine.md_value("MD32000", axis, 10000.0) or 10000.0)
                  for axis in self.plant.machine.path_axes]
        return math.sqrt(sum(v * v for v in speeds)) / 60.0

    def positions_before(self) -> dict[str, float] | None:
        """Before a step: the machine positions (``None`` when nothing is watched); notes
        whether the motion of the step starts at rapid traverse."""
        if not self._watched():
            return None
        self.state.rapid = self._moving_at_rapid()
        self.state.threading = not self.channel.jogging and self._segment_kind() in THREAD_AND_TAPPING_KINDS
        self._note_measuring_block()
        return self.plant.positions()

    def watch(self, before: dict[str, float] | None) -> None:
        """After a step: judge the tip's segment from ``before`` to now against every solid."""
        free, self.state.free = self.state.free, None
        self.state.budget = None
        if before is None:
            return
        after = self.plant.positions()
        if all(abs(after[a] - before.get(a, after[a])) <= 0.0 for a in after):
            return
        body, offset = self.tool_body()
        start, end = self._tip(before, offset), self._tip(after, offset)
        if (free is not None and not self.state.touching and free[1:] == (body, offset)
                and math.dist(start, end) < free[0]):
            return  # the tool moved less than its gap to every solid: nothing can be touched
        material = self._material()
        for name, solid in self.data.machine_setup.solids():
            if (isinstance(material, MilledBlank) and name == "blank" and name in self.state.touching
                    and body.shape != BALL and self._crash_number() is None):
                material.cut(body, start, end)  # goes on cutting (no new event) until it is clear of the blank
                if clearance(body, solid, end) > 0.0:
                    self.state.touching.discard(name)
                continue
            if material is not None and name == "blank" and (
                    isinstance(material, TurnedBar) or material.touches_cut(body, start, end)):
                self._watch_material(material, body, before, after, start, end)
                continue
            touching_before = name in self.state.touching
            t = first_contact(body, solid, start, end)
            if t is None:
                self.state.touching.discard(name)
                continue
            if t == 0.0 and not touching_before and _leaving(body, solid, start, end):
                continue  # on the surface (not seen arriving: the solid or the tool changed) and moving off
            if t > 0.0 or not touching_before:
                self.state.touching.add(name)
                self._on_contact(name, body, before, after, t)
            elif clearance(body, solid, end) < clearance(body, solid, start) - DEEPER_MM:
                self._on_deeper(name, body, solid, before, after, start, end)
            if isinstance(material, MilledBlank) and name == "blank" and self._crash_number() is None:
                material.cut(body, start, end)  # a rotating cutter at feed in the blank cuts it
            if clearance(body, solid, end) > 0.0:
                self.state.touching.discard(name)

    def _watch_material(self, material: TurnedBar | MilledBlank, body: ToolBody, before: dict[str, float],
                        after: dict[str, float], start: Point, end: Point) -> None:
        """The blank where material has been removed (a lathe's bar always, a mill's blank near
        a cut): a first touch is a contact event; while the tool stays on the surface it cuts
        without new events (a crash still stops it, a probe driven on past its overtravel is
        one); a rotating cutter at feed removes what it passes."""
        touching = self.state.touching
        crash = self._crash_number()
        cutting = crash is None and body.shape != BALL
        if "blank" in touching and cutting:
            material.cut(body, start, end)  # goes on cutting: no new event
            return
        t = material.first_contact(body, start, end)
        if t == 0.0 and "blank" not in touching:
            before_gap = material.clearance(body, start)
            if before_gap >= -SURFACE_SLACK_MM and material.clearance(body, end) > before_gap:
                return  # on the surface (not seen arriving) and moving off
        if t is None:
            leave_mm = Z_GRID_MM if isinstance(material, TurnedBar) else 0.0  # a turned step's slack
            if "blank" in touching and material.clearance(body, end) > leave_mm:
                touching.discard("blank")
            return
        probe = body.shape == BALL and self.plant.machine.kind != "lathe"
        if "blank" not in touching:
            touching.add("blank")
            self._on_contact("blank", body, before, after, t)
        elif probe and isinstance(material, MilledBlank):
            deep = material.first_contact(body, start, end, PROBE_OVERTRAVEL_MM)
            if deep is not None:
                self._crash(ALARM_CRASH_PROBE_OVERTRAVEL, "blank", _point(before, after, deep))
        elif crash is not None:
            self._crash(crash, "blank", dict(after))
        if not probe and self._crash_number() is None:
            material.cut(body, start, end)

    def _material(self) -> TurnedBar | MilledBlank | None:
        """What is left of the clamped blank: on a lathe the bar as turned, on a mill the block
        or round blank as milled (whole again for a newly clamped blank; not retained data)."""
        blank = self.data.machine_setup.blank
        lathe = self.plant.machine.kind == "lathe"
        if blank is None or (lathe and not isinstance(blank, Cylinder)):
            return None
        state = self.state
        if state.material is None or state.material_from is not blank:
            state.material = TurnedBar.of(blank) if lathe and isinstance(blank, Cylinder) else MilledBlank.of(blank)
            state.material_from = blank
        return state.material

    def _on_contact(self, name: str, body: ToolBody, before: dict[str, float], after: dict[str, float],
                    t: float) -> None:
        at = _point(before, after, t)
        if body.shape == BALL and self.plant.machine.kind != "lathe":
            self._record("probe", name, at)
            self._halt_jog()
            self._measured(at)
            return
        crash = self._crash_number()
        if crash is None:
            self._record("scratch", name, at)
        else:
            self._crash(crash, name, at)

    def _on_deeper(self, name: str, body: ToolBody, solid: Any, before: dict[str, float],
                   after: dict[str, float], start: Point, end: Point) -> None:
        if body.shape == BALL and self.plant.machine.kind != "lathe":
            t = first_contact(body, solid, start, end, PROBE_OVERTRAVEL_MM)
            if t is not None:
                self._crash(ALARM_CRASH_PROBE_OVERTRAVEL, name, _point(before, after, t))
            return
        crash = self._crash_number()
        if crash is not None:
            self._crash(crash, name, dict(after))

    def _crash_number(self) -> int | None:
        """The crash alarm for a cutter touching now, ``None`` when it is scratching (cutting)."""
        if self.state.rapid:
            return ALARM_CRASH_RAPID
        if self.state.threading:
            return None  # tapping, thread cutting: the spindle turns with the axes (002 L19681)
        turning = self.outputs.spindle_state in ("M3", "M4") and self.outputs.spindle_rpm > 0.0
        return None if turning else ALARM_CRASH_SPINDLE_STOPPED

    def _segment_kind(self) -> str | None:
        """The motion kind (G0, G1, G331 …) of the program block moving now (``None`` in JOG)."""
        run, source = self._executing()
        segment = run.segments.get(id(source)) if run is not None and source is not None else None
        return getattr(segment, "kind", None)

    def _moving_at_rapid(self) -> bool:
        if self.channel.jogging:
            return self.state.jog_rapid
        return self._segment_kind() == "G0"

    # ---------------------------------------------------------------- MEAS / MEAW
    def _note_measuring_block(self) -> None:
        """A measuring block (``MEAS=``/``MEAW=``) starts: its probe status begins at 0."""
        run, source = self._executing()
        segment = run.segments.get(id(source)) if run is not None and source is not None else None
        measuring = segment if getattr(segment, "measure", None) else None
        state = self.state
        state.measuring = measuring
        if measuring is not None and id(measuring) != state.measured_block:
            state.measured_block = id(measuring)
            state.switched = False

    def _measured(self, at: dict[str, float]) -> None:
        """The probe switched: in a measuring block its trigger position is the result
        (``$AA_MM`` MCS, ``$AA_MW`` WCS of that block), ``$AC_MEA[1]`` = 1; ``MEAS`` deletes
        the distance to go (the axes brake; the next block starts where they stop)."""
        state = self.state
        segment = state.measuring
        if segment is None or state.switched:
            return
        state.switched = True
        state.measured_mcs = dict(at)
        offsets = {a: float(segment.end_mcs[a]) - float(segment.end_wcs[a])
                   for a in segment.end_mcs if a in segment.end_wcs}
        state.measured_wcs = {a: value - offsets.get(a, 0.0) for a, value in at.items()}
        if segment.measure == "MEAS":
            self.path_motion().abort(keep_spindles=self.plant.machine.spindles)

    def measurement(self, name: str, axis: str) -> float:
        """The interpreter's ``$AA_MM[axis]``, ``$AA_MW[axis]``, ``$AC_MEA[1]``."""
        state = self.state
        if name == "$AC_MEA":
            return 1.0 if state.switched else 0.0
        values = state.measured_mcs if name == "$AA_MM" else state.measured_wcs
        return float(values.get(axis, 0.0))

    def _executing(self) -> tuple[Any, Any]:
        """The program run whose block executes now and that block's source (``None``s in JOG)."""
        run = self.channel.active_run()
        return run, (self.path_motion().current_source() if run is not None else None)

    def _record(self, kind: str, name: str, at: dict[str, float]) -> None:
        state = self.state
        state.seq += 1
        state.events.append(ContactEvent(state.seq, kind, name, at, self.outputs.tool, self.outputs.edge,
                                         self.clock()))
        del state.events[:-EVENT_LIMIT]

    def _crash(self, number: int, name: str, at: dict[str, float]) -> None:
        if any(entry.number == number for entry in self.alarms.active):
            self._halt_jog()  # still crashed (braking, or driven on): one event, one alarm
            return
        self._record("crash", name, at)
        what = "blank" if name == "blank" else "reference block"
        _, source = self._executing()
        where = {"file": source.file, "line": source.line, "n": source.n} if source is not None else {}
        self.motion_alarm(NcAlarmError(number, f"T{self.outputs.tool}", what, **where))
        self._halt_jog()

    def _halt_jog(self) -> None:
        """Brake every JOG motion (an increment is not continued); the channel ends JOG when
        the axes stand, as after a released key."""
        if not self.channel.jogging:
            return
        for axis in self.plant.machine.path_axes:
            self.plant.motion.jog_continuous(axis, 0, 0.0)
        self.channel.jog_targets.clear()
        self.channel.jog_rest.clear()
