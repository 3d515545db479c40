"""One simple motion block without the parser's tree walk and the per-block snapshot: the fast
path of :meth:`Interpreter.step`.

A *simple* motion line (:data:`nck.lang.plain.SIMPLE_LINE`: N, G0–G3, G90/G91, X Y Z, I J K,
``CR=``, F, a comment) is what CAM posts write for almost every block. Its words are read as
the parser reads them (:func:`nck.lang.plain.simple_words`) and turned once into a
:class:`MotionPlan` (its G codes by group, axis values and other words, already converted),
kept per interpreter by line text once the line comes again (:class:`SimpleStep`); each
execution hands the plan's words to the general motion builder — the same G-code table, feed,
path geometry (lines, arcs with I/J/K or ``CR=``, the 14040 end-point check, planes, frames,
tool offsets) and canonical motions as a block of the general path. What the fast step leaves out is only what such a block cannot need: the
evaluation of expressions, control flow, calls, and the full snapshot of the run state.

Instead of the snapshot the step saves the fields of the modal and the geometry state that
the motion builder replaces (every change it makes to them is an assignment of a field) and
the G groups the line writes. When the builder raises an NC alarm, they are put back and the
step returns None: the general path then interprets the same block, with its full snapshot,
and raises the alarm at the same line with the same state. So do lines and states the step
does not take (a modal call, a section repeat, radius compensation, a held-back corner,
chamfer/rounding modal, G641 rounding by distance, an ISO program).
"""

from __future__ import annotations

from typing import NamedTuple

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.api import BLOCK_COST_S, BlockResult
from nck.interp.host import InterpreterHost
from nck.interp.modal import ModalState
from nck.interp.motion_builder import BlockWords
from nck.interp.plain_setup import plain_frame, simple_state
from nck.lang.gcodes import GTable
from nck.lang.lines import remember_bounded
from nck.lang.plain import SIMPLE_LINE, simple_words

PLANS_KEPT = 4096
"""Plans kept per interpreter, by line text (the oldest go first)."""


class MotionPlan(NamedTuple):
    """A simple motion line, precompiled: what its execution hands to the motion builder.

    The dicts are built once and handed to every execution's :class:`BlockWords` as they are
    (the motion builder reads a block's words and never changes them). A named tuple: a CAM
    program's lines are all new, so a plan is made for almost every block."""

    gcodes: tuple[tuple[int, str], ...]  # (G group, code) in the order written; every group modal
    block_gcodes: dict[int, str]  # the same as the block's G codes by group
    axes: dict[str, tuple[float, str | None]]  # path axis -> (value as the block run converts it, None: no AC/IC)
    words: dict[str, float]  # I/J/K/CR/F -> value
    motion: str | None  # the group-1 code the line writes
    number: int | None  # its block number N


def motion_plan(text: str, table: GTable, path_axes: tuple[str, ...]) -> MotionPlan | None:
    """The plan of a simple motion line, or None when the line is not one the fast step takes
    (not simple, no words, an axis the machine lacks, a G code not modal in ``table``)."""
    found = SIMPLE_LINE.fullmatch(text)
    if found is None:
        return None
    codes, written = simple_words(found)
    if not codes and not written:
        return None
    gcodes: list[tuple[int, str]] = []
    motion = None
    for code in codes:
        group = table.group_of.get(code)
        if group is None or not table.groups[group].modal:
            return None
        gcodes.append((group, code))
        if group == 1:
            motion = code
    axes: dict[str, tuple[float, str | None]] = {}
    words: dict[str, float] = {}
    for address, value in written:
        if address in path_axes:
            axes[address] = (float(value), None)
        elif address in ("X", "Y", "Z"):
            return None  # not an axis of this machine: the block run's alarm
        else:
            words[address] = float(value)
    number = found.group(1)
    return MotionPlan(tuple(gcodes), dict(gcodes), axes, words, motion, None if number is None else int(number))


def takes_motion(interp: InterpreterHost, motion: str) -> bool:
    """True when the modal state lets a simple motion block under group-1 code ``motion`` go
    straight to the motion builder: nothing held back or waiting, no chamfer/rounding or
    G641 rounding that would hold the element back, radius compensation off, the settable
    frame current, a Siemens program."""
    return motion in ("G0", "G1", "G2", "G3") and simple_state(interp)


class SimpleStep:
    """The fast step of one interpreter, with its plans by line text (a subprogram's or a
    loop's lines are planned once) for its G-code table and path axes."""

    def __init__(self) -> None:
        self._plans: dict[str, MotionPlan | None] = {}
        self._seen: dict[str, None] = {}  # lines planned once and not kept (yet)
        self._table: GTable | None = None
        self._path_axes: tuple[str, ...] = ()

    def plan(self, interp: InterpreterHost, text: str) -> MotionPlan | None:
        """The plan of the line ``text`` (None: not one the fast step takes).

        A plan is kept from the second time its line comes (a loop's or a subprogram's line):
        the lines of a CAM program come once each, and keeping their plans (a few containers
        each, alive for thousands of blocks) only fed the garbage collector. The text alone is
        remembered after the first time (a string: nothing for the collector to walk)."""
        table, path_axes = interp.table, interp.builder.path.path_axes
        if table is not self._table or path_axes != self._path_axes:
            self._plans, self._seen, self._table, self._path_axes = {}, {}, table, path_axes
        plans = self._plans
        if text in plans:
            return plans[text]
        found = motion_plan(text, table, path_axes)
        if text in self._seen:
            remember_bounded(plans, text, found, PLANS_KEPT)
        else:
            remember_bounded(self._seen, text, None, PLANS_KEPT)
        return found

    def step(self, interp: InterpreterHost) -> BlockResult | None:
        """Interpret the next block if it is a simple motion line the state lets through (else
        None, nothing changed: the general path interprets it).

        Gives exactly the general path's :class:`BlockResult` and state (property-tested).
        """
        found = plain_frame(interp)
        if found is None:
            return None
        frame, lines = found
        program = frame.program
        index = frame.pc
        if index >= len(lines) or index in program.structure_errors:
            return None
        text = lines.raw(index)
        plan = self.plan(interp, text)
        if plan is None:
            return None
        modal = interp.modal
        if not takes_motion(interp, plan.motion or modal.gcodes.get(1, "G1")):
            return None
        source = canon.Source(program.name, index + 1, plan.number)
        words = BlockWords(source=source, gcodes=plan.block_gcodes, axes=plan.axes, words=plan.words)
        geo = modal.geometry
        saved_modal, saved_geo = dict(modal.__dict__), dict(geo.__dict__)
        gcodes = modal.gcodes
        saved_groups = [(group, gcodes.get(group)) for group, _ in plan.gcodes]
        for group, code in plan.gcodes:
            gcodes[group] = code
        try:
            commands = interp.builder.simple_path_block(words, modal)
        except NcAlarmError:
            _restore(modal, saved_modal, saved_groups)
            geo.__dict__.clear()
            geo.__dict__.update(saved_geo)
            return None
        frame.def_open = False
        frame.pc = index + 1
        interp.skip_run = None
        return BlockResult(
            source=source, text=text, commands=tuple(commands), action_block=bool(commands), finished=False,
            cost_s=BLOCK_COST_S,
            extras={"level": len(interp.run_state.frames), "preprocessing_stop": False,
                    "single_block_off": frame.single_block_off, "display_off": frame.display_off},
        )


def _restore(modal: ModalState, fields: dict, groups: list[tuple[int, str | None]]) -> None:
    """Put back the modal state's fields and the G groups the line wrote (in place: the
    G-code dict is shared with the saved fields)."""
    gcodes = fields["gcodes"]
    for group, code in reversed(groups):
        if code is None:
            gcodes.pop(group, None)
        else:
            gcodes[group] = code
    modal.__dict__.clear()
    modal.__dict__.update(fields)
