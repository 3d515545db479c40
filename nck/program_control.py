"""One program run in the channel: interpreter → motion buffer, stops, block search.

A :class:`ProgramRun` is created when NC START begins a program (AUTO) or the
MDA buffer, and lives until the program ends or RESET. Every IPO cycle the
kernel calls :meth:`ProgramRun.feed`: it asks the interpreter for blocks
while the motion buffer accepts, pushes their motion, and reports what the
kernel must act on as :class:`RunEvent` records (alarms, messages, auxiliary
functions, stop reached, program end). It applies single block (SBL1 after
each action block, SBL2 after every block), M0, M1 (only with "programmed
stop" on), STOPRE and M2/M30.

Block search with calculation (:meth:`ProgramRun.search`) interprets up to the
target block without moving anything, collecting the last position and the
auxiliary functions (the action blocks), and keeps the target block pending;
NC START outputs the actions, alarm 10208 follows, the next NC START
approaches the start of the target block (type 2) or runs the target block from
where the axes stand (type 4) and continues. Block search without calculation
(type 1) places the program at the target block; its NC STARTs output no action
and approach nothing. The types: :mod:`nck.block_search`.
"""

from __future__ import annotations

import re
from collections import OrderedDict, deque
from dataclasses import dataclass, field, replace
from typing import Callable, Mapping

from nck.basic_blocks import BasicBlockLog
from nck.block_search import CONTOUR, END_POINT, WITHOUT_CALCULATION, EndPointStart
from nck.canon import (
    AuxFunction, Dwell, EdgeSelect, ExactStop, Message, Motion, ProgramEnd, SpindleCommand, StopPoint,
    Source, ToolSelect, UserAlarm,
)
from nck.errors import NcAlarmError
from nck.geometry.circles import CircleTolerance
from nck.inflight import InFlight
from nck.interp.api import BlockResult, Interpreter
from nck.motion.api import MotionSystem
from nck.status import BlockView

PUSHED_HISTORY = 256  # motion items remembered for REPOS (more than any look-ahead buffer)
MAX_BLOCKS_PER_CYCLE = 50  # interpretation blocks per IPO cycle when blocks cost no time
SEARCH_BLOCK_LIMIT = 200_000
DISPLAY_HISTORY = 8
# Blocks remembered with the block the display shows for them: more than the interpreter reads
# ahead of the main run (a cycle computes many blocks between two moves).
BLOCKS_REMEMBERED = 8192
NOT_OUTPUT_IN_SEARCH_M = {0, 1, 2, 17, 30}

# Run phases.
FEEDING = "feeding"  # interpreting and pushing blocks
WAIT_IDLE = "wait_idle"  # STOPRE: wait until the motion is done, then go on
WAIT_STOP = "wait_stop"  # stop at block end: wait until the motion is done
WAIT_END = "wait_end"  # program end: wait until the motion is done
STOPPED = "stopped"  # stopped at a block boundary; NC START continues
ENDED = "ended"
REFUSED = "refused"  # the motion refused a block (10720 …): no block after it is prepared
SEARCH_FOUND = "search_found"  # target found; NC START outputs the action blocks
SEARCH_ACTIONS_DONE = "search_actions_done"  # 10208 pending; NC START approaches and continues
SEARCH_TARGET_FOUND = "search target found"  # the stop reason at a found search target


@dataclass(frozen=True, slots=True)
class RunEvent:
    """Something the kernel must act on.

    ``kind``: ``alarm`` (``alarm`` set), ``user_alarm`` (``command``), ``message``
    (``text``), ``output`` (an auxiliary/tool/spindle command in ``command``),
    ``stop`` (stopped at a block boundary, reason in ``text``), ``end`` (program
    end; ``text`` is ``M2``/``M30``/``M17`` or ``""`` when the text simply ran out).
    """

    kind: str
    text: str = ""
    alarm: NcAlarmError | None = None
    command: object = None


@dataclass
class RunOptions:
    """Program-control settings the run reads while it feeds."""

    single_block: str | None = None  # None, "SBL1", "SBL2"
    m01: bool = False


@dataclass
class SearchFindings:
    """What a block search found and collected: whether it reached the target, the position
    to approach, the actions to output first, the blocks searched (``search_type``: a name
    of :mod:`nck.block_search`)."""

    found: bool
    search_type: str = CONTOUR
    position_mcs: dict[str, float] = field(default_factory=dict)
    position_wcs: dict[str, float] = field(default_factory=dict)
    actions: list[object] = field(default_factory=list)
    blocks_searched: int = 0


def block_view(result: BlockResult) -> BlockView:
    """The display form of an interpreted block."""
    source = result.source
    return BlockView(source.file, source.line, result.text)


def parse_search_target(target: str) -> tuple[int | None, str]:
    """``"N260"``/``"260"`` → block number 260; anything else is searched as text."""
    text = target.strip()
    match = re.fullmatch(r"[Nn]?\s*(\d+)", text)
    if match:
        return int(match.group(1)), text
    return None, text


class ProgramRun:
    """Drives one interpreter into one motion system; see the module docstring."""

    def __init__(
        self,
        kind: str,
        name: str,
        interpreter: Interpreter,
        transform: Callable[[Motion], Motion] | None = None,
    ) -> None:
        self.kind = kind  # "AUTO" or "MDA"
        self.name = name
        self.interp = interpreter
        self.phase = FEEDING
        self.stop_reason = ""
        self.current: BlockResult | None = None
        self.history: deque[BlockView] = deque(maxlen=DISPLAY_HISTORY)
        # see _take; ordered so that the oldest entry goes in O(1) (popping the first key of a
        # plain dict walks the slots earlier pops left empty: ~5 us a block at 8,192 entries)
        self._shown_as: OrderedDict[int, tuple[Source, BlockView | None]] = OrderedDict()
        self.basic_blocks = BasicBlockLog()
        """The basic block display: the blocks as they are executed, cycles' blocks included."""
        self.blocks_executed = 0
        self.last_motion: Motion | None = None
        # Recent segments by the identity of their block's Source: a line run several
        # times (loops, subprogram passes) has one Source per run, and the look-ahead
        # buffer may hold several runs of it at once.
        # A dwell is kept under its block unless a segment of that block is (a spindle wait).
        self.segments: OrderedDict[int, Motion | Dwell] = OrderedDict()  # oldest first, as _shown_as
        self.pushed: deque[Motion | Dwell] = deque(maxlen=PUSHED_HISTORY)
        self._requeued: deque[Motion | Dwell] = deque()
        # Main-run bookkeeping: outputs (aux functions, MSG) of a block go out when
        # the motion pushed before them has been executed, not at interpretation.
        self._inflight = InFlight()  # the blocks of the items pushed, not known to be done
        self._pushed_total = 0
        self._deferred: deque[tuple[int, RunEvent]] = deque()
        self._approach: Motion | None = None
        self._transform = transform or (lambda motion: motion)
        self.listener: Callable[[BlockResult], None] | None = None  # sees every interpreted block
        self._pending: BlockResult | None = None
        self._index = 0
        self._stop_after: str | None = None
        self._end_kind: str | None = None
        self._search: SearchFindings | None = None
        self._end_point: EndPointStart | None = None  # type 4: how the target block's motion starts
        self._stop_before: tuple[int | None, str] | None = None  # SERUPRO: stop before this target

    # -- feeding ------------------------------------------------------------
    def feed(self, motion: MotionSystem, options: RunOptions, budget_s: float) -> list[RunEvent]:
        """Advance the run by one IPO cycle's worth of interpretation."""
        events: list[RunEvent] = []
        self._release(motion, events)
        if self._approach is not None:
            if not motion.can_accept():
                return events
            motion.push(self._approach)  # not counted: no output waits for it
            self._approach = None
        while self._requeued:
            if not motion.can_accept():
                return events
            self._push(motion, self._requeued.popleft())
        if self.phase in (WAIT_IDLE, WAIT_STOP, WAIT_END):
            if not motion.is_idle():
                return events
            self._release(motion, events, everything=True)
            if self.phase == WAIT_STOP:
                self.phase = STOPPED
                events.append(RunEvent("stop", self.stop_reason))
                return events
            if self.phase == WAIT_END:
                self.phase = ENDED
                events.append(RunEvent("end", self._end_kind or ""))
                return events
            self.phase = FEEDING
        if self.phase != FEEDING:
            return events
        blocks = 0
        while self.phase == FEEDING:
            if self._pending is None:
                if self.interp.finished:
                    self._finish_at_idle("")
                    break
                if budget_s <= 0.0 or blocks >= MAX_BLOCKS_PER_CYCLE:
                    break
                if self._must_wait_for_main_run(motion):
                    break  # implicit STOPRE: the block reads main-run data ($AA_IM …)
                if self.last_motion is not None and self.last_motion.measure == "MEAS":
                    self._after_measuring(motion)
                try:
                    result = self.interp.step()
                except NcAlarmError as error:
                    events.append(RunEvent("alarm", alarm=error))
                    self._stop_at_idle("alarm")
                    break
                budget_s -= max(0.0, result.cost_s)
                blocks += 1
                if self._stop_before is not None and self._is_target(result, *self._stop_before):
                    self._stop_before = None  # SERUPRO: stop at the beginning of the target block
                    self._take(result)
                    self.blocks_executed -= 1
                    self._stop_at_idle(SEARCH_TARGET_FOUND)
                    break
                self._take(result)
            if not self._emit(motion, options, events):
                break  # motion buffer full: continue next cycle
            self._block_done(options)
        self._release(motion, events)
        return events

    def _push(self, motion: MotionSystem, item: Motion | Dwell) -> None:
        self.pushed.append(item)
        self._inflight.append(item.source)
        self._pushed_total += 1
        motion.push(item)

    def _release(self, motion: MotionSystem, events: list[RunEvent], everything: bool = False) -> None:
        """Forget the pushed items the main run has executed; hand out deferred outputs whose
        preceding motion is among them.

        Executed items are dropped also while no output waits: a block that runs again (a loop,
        a subprogram's next pass) must be found at its current run, not at an earlier run's entry
        left behind — an output is tied to its own block's motion (002 L14590-14598), and an
        output of a subprogram's third pass would otherwise wait for the end of the program.
        This also keeps the queue as short as the motion's look-ahead."""
        current = motion.current_source()
        if everything or (current is None and motion.is_idle()):
            self._inflight.clear()
        elif current is not None:
            executing = self._inflight.find(current)
            if executing is not None:
                self._inflight.drop(executing)
        if not self._deferred:
            return
        done = self._pushed_total - len(self._inflight)
        while self._deferred and self._deferred[0][0] <= done:
            events.append(self._deferred.popleft()[1])

    def wants_every_cycle(self, motion: MotionSystem) -> bool:
        """True while the run must be fed cycle by cycle (it can push more motion now)."""
        if self._approach is not None or self._requeued:
            return True
        if self.phase != FEEDING or not motion.can_accept():
            return False
        return not self._must_wait_for_main_run(motion)

    def _must_wait_for_main_run(self, motion: MotionSystem) -> bool:
        """True while the next block needs the main run to catch up first.

        After a ``MEAS`` block too: the probe may delete its distance to go, so the next block
        starts from where the axes stopped (our model of MEAS; the interpreter takes over
        the actual position before it, :meth:`_after_measuring`)."""
        measuring = self.last_motion is not None and self.last_motion.measure == "MEAS"
        needs = getattr(self.interp, "needs_preprocessing_stop", None)
        if not measuring and (needs is None or not needs()):
            return False
        return bool(self._deferred) or not motion.is_idle()

    def _after_measuring(self, motion: MotionSystem) -> None:
        """Before the block after a ``MEAS`` block: the interpreter continues from the actual position."""
        assert self.last_motion is not None
        sync = getattr(self.interp, "sync_position", None)
        if sync is not None:
            sync(motion.positions_mcs())
        self.last_motion = replace(self.last_motion, measure=None)

    def _take(self, result: BlockResult) -> None:
        if self.listener is not None:
            self.listener(result)
        self._pending = result
        self._index = 0
        self.basic_blocks.taken(result)
        history = self.history
        if not result.extras.get("display_off"):
            self.current = result
            history.append(block_view(result))
        # What the block display shows while the main run executes this block: the block itself,
        # or for a block of a DISPLOF subprogram the block that called it. By identity of the
        # source: the main run may be far behind the interpreter (more than the history holds).
        source, shown_as = result.source, self._shown_as
        shown_as[id(source)] = (source, history[-1] if history else None)
        if len(shown_as) > BLOCKS_REMEMBERED:
            shown_as.popitem(last=False)
        self.blocks_executed += 1

    def _emit(self, motion: MotionSystem, options: RunOptions, events: list[RunEvent]) -> bool:
        """Output the pending block's commands; False if the buffer filled up."""
        assert self._pending is not None
        commands = self._pending.commands
        while self._index < len(commands):
            command = commands[self._index]
            if isinstance(command, ExactStop):
                command = Dwell(command.source, seconds=0.0)  # the motion stops, then goes on
            if isinstance(command, (Motion, Dwell)):
                if not motion.can_accept():
                    return False
                if isinstance(command, Motion) and self._end_point is not None:
                    try:
                        started = self._start_at_end_point(command)
                    except NcAlarmError as error:
                        events.append(RunEvent("alarm", alarm=error))
                        self._pending = None
                        self._stop_at_idle("alarm")
                        return False
                    if started is None:
                        self._index += 1
                        continue
                    command = started
                segments = self.segments
                if isinstance(command, Motion):
                    command = self._transform(command)
                    self.last_motion = command
                    self.basic_blocks.moved(command)
                    segments[id(command.source)] = command
                else:
                    segments.setdefault(id(command.source), command)
                if len(segments) > PUSHED_HISTORY:
                    segments.popitem(last=False)
                self._push(motion, command)
                if getattr(motion, "refused_source", None) is command.source:
                    # Block preparation checks the end point (10720, 10730 …) and goes no further;
                    # the alarm comes when the main run reaches the block.
                    self._pending = None
                    self.phase = REFUSED
                    return False
            elif isinstance(command, StopPoint):
                kind = command.kind.upper()
                if kind in ("M0", "M00"):
                    self._stop_after = "M0"
                elif kind in ("M1", "M01"):
                    if options.m01:
                        self._stop_after = "M1"
                elif self._stop_after is None:
                    self._stop_after = "STOPRE"  # STOPRE and any other sync point: wait for the main run
            elif isinstance(command, ProgramEnd):
                self._end_kind = command.kind
            elif isinstance(command, Message):
                self._deferred.append((self._pushed_total, RunEvent("message", text=command.text, command=command)))
            elif isinstance(command, UserAlarm):
                events.append(RunEvent("user_alarm", command=command))
                if self._stop_after is None:
                    self._stop_after = "alarm"
            else:
                self._deferred.append((self._pushed_total, RunEvent("output", command=command)))
            self._index += 1
            if options.single_block == "SBL1" and self._single_segment_stop(commands):
                self._stop_at_idle("single block")
                return False
        return True

    def _start_at_end_point(self, motion: Motion) -> Motion | None:
        """After a search to the block end point: the target block's motion starts where the
        axes stand; motion of a searched block that radius compensation held back until
        the target (same program, earlier line) is not run (None), nor a corner the NC
        inserts before the target's own motion: the approach uses the target block's
        interpolation (002 L18296-18297)."""
        start = self._end_point
        assert start is not None
        source, target = motion.source, start.target
        if (source.file == target.file and source.line < target.line) or (source == target and motion.inserted):
            return None
        self._end_point = None
        return start.apply(motion) if source == target else motion

    def _single_segment_stop(self, commands: tuple) -> bool:
        """SBL1 stops after every segment, also one the NC inserted or one an earlier block
        released late (radius compensation, RND), and after the outputs of a block without
        path motion that waited for such a motion (M8, G4 between two rounded blocks), when
        more motion follows (002 L18071-18094): the stops keep in step with the motion. Asked
        only under SBL1."""
        if self._pending is None or self._pending.extras.get("single_block_off"):
            return False
        done, rest = commands[self._index - 1], commands[self._index:]
        if not any(isinstance(c, (Motion, Dwell, ExactStop)) for c in rest):
            return False  # the block's own end: the stop after the block
        after = rest[0]
        if isinstance(done, Motion):
            return isinstance(after, (Motion, Dwell, ExactStop)) or after.source != done.source
        return done.source != after.source and done.source != self._pending.source

    def _block_done(self, options: RunOptions) -> None:
        assert self._pending is not None
        block = self._pending
        self._pending = None
        if block.finished or self._end_kind is not None:
            self._finish_at_idle(self._end_kind or "M30")
            return
        reason = self._stop_after
        self._stop_after = None
        if reason == "STOPRE":
            self.phase = WAIT_IDLE
            reason = None
        if reason is None and not block.extras.get("single_block_off"):
            if options.single_block == "SBL2" or (
                options.single_block == "SBL1" and block.action_block
            ):
                reason = "single block"
        if reason is not None:
            self._stop_at_idle(reason)

    def _stop_at_idle(self, reason: str) -> None:
        self.stop_reason = reason
        self.phase = WAIT_STOP

    def _finish_at_idle(self, kind: str) -> None:
        self._end_kind = kind
        self.phase = WAIT_END

    # -- operator actions ----------------------------------------------------
    def continue_after_stop(self) -> None:
        """NC START after a block-boundary stop (single block, M0/M1, alarm)."""
        if self.phase == STOPPED:
            self.phase = FEEDING
            self.stop_reason = ""

    def interpreter_stop(self, reason: str = "alarm") -> None:
        """Stop interpreting; the channel stops once the buffered motion is done."""
        if self.phase in (FEEDING, WAIT_IDLE):
            self._pending = None
            self._stop_at_idle(reason)

    def park(self, current: Source | None, position_mcs: Mapping[str, float]) -> list[Motion | Dwell]:
        """The motion items not yet executed, from the one at ``current`` on.

        Called before the kernel discards the motion buffer of an interrupted
        program (mode change, JOG); the first item is cut to start at
        ``position_mcs``. ``current`` None (nothing was executing) gives [].
        """
        # The executed part of the in-flight list is dropped; the rest is pushed again
        # on resume, so the deferred outputs keep waiting for the same items.
        if current is None:
            self._inflight.clear()
        else:
            executing = self._inflight.find(current)
            self._inflight.drop(len(self._inflight) if executing is None else executing)
        self._pushed_total -= len(self._inflight)
        self._inflight.clear()
        self._approach = None
        items = list(self._requeued)
        if current is not None:
            history = list(self.pushed)
            key = (current.file, current.line)
            for index in range(len(history) - 1, -1, -1):
                if (history[index].source.file, history[index].source.line) == key:
                    rest = history[index:]
                    if isinstance(rest[0], Motion):
                        rest[0] = replace(rest[0], start_mcs=dict(position_mcs))
                    items = rest + items
                    break
        self._requeued.clear()
        return items

    def requeue(self, items: list[Motion | Dwell], approach: Motion | None = None) -> None:
        """Push the parked remainder ``items`` before new blocks, led by the REPOS ``approach``."""
        if approach is not None:
            self._approach = approach
        self._requeued.extend(items)

    def last_executed_source(self) -> Source | None:
        """The block to show while the motion stands: the one whose motion ran last, when the
        latest interpreted block handed on motion (possibly of an earlier block: radius
        compensation and RND release segments late); None: show the latest block."""
        block = self.current
        if block is None or not self.pushed:
            return None
        if block is self._pending and self.stop_reason == SEARCH_TARGET_FOUND:
            return None  # SERUPRO stands before its target block: show it
        if not any(isinstance(c, (Motion, Dwell)) for c in block.commands):
            return None
        return self.pushed[-1].source

    @property
    def at_stop(self) -> bool:
        """True while stopped at a block boundary."""
        return self.phase == STOPPED

    def display_blocks(self) -> tuple[BlockView, ...]:
        """The recently interpreted blocks, oldest first."""
        return tuple(self.history)

    def shown_for(self, source: Source) -> BlockView | None:
        """The block the display shows while the main run executes ``source``: that block, or
        for a block of a DISPLOF subprogram the block that called it (002 L21867-21868,
        L23164); None if ``source`` is not remembered."""
        entry = self._shown_as.get(id(source))
        return entry[1] if entry is not None and entry[0] is source else None

    # -- block search --------------------------------------------------------
    def search(self, target: str, start_positions: Mapping[str, float],
               search_type: str = CONTOUR) -> SearchFindings:
        """Block search of ``search_type`` to block number or text ``target``.

        The interpreter must be positioned at the program start. Raises
        :class:`NcAlarmError` when a block before the target fails (with calculation)
        or the target block itself fails.
        """
        number, text = parse_search_target(target)
        result = SearchFindings(found=False, search_type=search_type, position_mcs=dict(start_positions))
        flags = getattr(self.interp, "flags", None)
        if isinstance(flags, dict):
            flags["search"] = True
        try:
            if search_type == WITHOUT_CALCULATION:
                self._search_without_calculation(number, text, result)
            else:
                self._search_blocks(number, text, result)
        finally:
            if isinstance(flags, dict):
                flags["search"] = False
        self.basic_blocks.forget_shown_modals()
        return result

    def _search_without_calculation(self, number: int | None, text: str, result: SearchFindings) -> None:
        """Type 1: place the program at the target and interpret only the target block."""
        if not self.interp.skip_to(number, text):
            return
        block = self.interp.step()
        result.blocks_searched = 1
        result.position_mcs = {}  # nothing to approach
        self._found(block, result)

    def _search_blocks(self, number: int | None, text: str, result: SearchFindings) -> None:
        spindles: dict[int, SpindleCommand] = {}
        aux: dict[tuple[str, int | None], AuxFunction] = {}
        tool: ToolSelect | None = None
        edge: EdgeSelect | None = None
        for _ in range(SEARCH_BLOCK_LIMIT):
            if self.interp.finished:
                break
            block = self.interp.step()
            result.blocks_searched += 1
            if self._is_target(block, number, text):
                self._found(block, result)
                break
            ended = False
            for command in block.commands:
                if isinstance(command, Motion):
                    result.position_mcs.update(command.end_mcs)
                    result.position_wcs.update(command.end_wcs)
                    self.last_motion = command
                elif isinstance(command, SpindleCommand):
                    spindles[command.spindle] = command
                elif isinstance(command, ToolSelect):
                    tool = command
                elif isinstance(command, EdgeSelect):
                    edge = command
                elif isinstance(command, AuxFunction):
                    if command.address.upper() == "M" and int(command.value) in NOT_OUTPUT_IN_SEARCH_M:
                        continue
                    aux[(command.address.upper(), command.extension)] = command
                elif isinstance(command, ProgramEnd):
                    ended = True
            if ended or block.finished:
                break
        if result.found:
            actions: list[object] = list(aux.values())
            actions += [c for c in (tool, edge) if c is not None]
            actions += list(spindles.values())
            result.actions = actions

    def _found(self, block: BlockResult, result: SearchFindings) -> None:
        """The target block is pending; the channel shows "search target found"."""
        result.found = True
        self._take(block)
        self.blocks_executed -= 1
        self._search = result
        self.phase = SEARCH_FOUND
        self.stop_reason = SEARCH_TARGET_FOUND

    def stop_before(self, target: str) -> None:
        """SERUPRO: run, and stop (reason "search target found") before the block ``target``."""
        self._stop_before = parse_search_target(target)

    @staticmethod
    def _is_target(block: BlockResult, number: int | None, text: str) -> bool:
        if number is not None:
            if block.source.n == number:
                return True
            stripped = block.text.lstrip().upper()
            return bool(re.match(rf"N{number}(?!\d)", stripped))
        return text.upper() in block.text.upper()

    def output_search_actions(self) -> list[RunEvent]:
        """First NC START after the search: the action blocks; then 10208 is due."""
        assert self._search is not None
        events = [RunEvent("output", command=c) for c in self._search.actions]
        self.phase = SEARCH_ACTIONS_DONE
        self.stop_reason = "10208"
        return events

    def search_approach(self, actual_mcs: Mapping[str, float], tolerance: CircleTolerance) -> Motion | None:
        """Second NC START: the approach to the start of the target block (type 2), or None:
        type 4 starts the target block itself from ``actual_mcs`` (a circle there may fail
        with 14040 when it is output), type 1 approaches nothing."""
        search = self._search
        self._search = None
        self.phase = FEEDING
        self.stop_reason = ""
        block = self._pending
        if search is not None and search.search_type == END_POINT and block is not None:
            self._end_point = EndPointStart(block.source, block.text, dict(actual_mcs), tolerance)
            return None
        if search is None or not search.position_mcs:
            return None
        source = self._pending.source if self._pending is not None else None
        if source is None:
            return None
        return Motion(
            kind="G0", source=source, plane="G17",
            end_wcs=dict(search.position_wcs), end_mcs=dict(search.position_mcs),
            exact_stop=True, inserted=True,
        )
