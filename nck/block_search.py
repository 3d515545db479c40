"""Block search types and the approach of a search to the block end point.

The operator chooses the type on the block search screen (002 L18283-18315):

* ``without_calculation`` (type 1): the program is placed at the target block; nothing
  before it is interpreted, so the control keeps the state it had before the search.
* ``contour`` (type 2): every block up to the target is interpreted without motion; NC
  START approaches the start of the target block, which then runs true to contour.
* ``end_point`` (type 4): interpreted like type 2, but there is no approach block: the
  target block itself takes the axes it programs from where they stand to its end point,
  with its own interpolation (not true to contour); a circle whose radius from the new
  start differs from its end radius fails with 14040 (002 L18296-18302, L18474-18477,
  L18836-18840).
* ``serupro`` (type 5): search run by program test: the program runs in program test up to
  the target block with the machine standing; NC START repositions to the start of the
  target block (002 L18304-18309, L18994-19027).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Mapping

from nck.canon import Motion, Source
from nck.errors import NcAlarmError
from nck.geometry import circles
from nck.geometry.circles import ALARM_CIRCLE_END_POINT, CircleTolerance
from nck.lang import ast
from nck.lang.parser import parse_block
from nck.machine import MachineConfig

WITHOUT_CALCULATION = "without_calculation"
CONTOUR = "contour"
END_POINT = "end_point"
SERUPRO = "serupro"
SEARCH_TYPES = {WITHOUT_CALCULATION: 1, CONTOUR: 2, END_POINT: 4, SERUPRO: 5}
"""Search type name → the manual's type number."""


def circle_tolerance(machine: MachineConfig) -> CircleTolerance:
    """The circle end-point tolerance of ``machine`` (MD21000, MD21010)."""
    return CircleTolerance(
        float(machine.md_value("MD21000", default=circles.CIRCLE_ERROR_CONST_MM)),
        float(machine.md_value("MD21010", default=circles.CIRCLE_ERROR_FACTOR)),
    )


def programmed_axes(text: str, axes: frozenset[str]) -> frozenset[str] | None:
    """The axes among ``axes`` that the block ``text`` programs (``X10``, ``X=AC(5)``);
    None when the text is not a Siemens block (an ISO block: then every axis counts)."""
    try:
        block = parse_block(text)
    except NcAlarmError:
        return None
    found: set[str] = set()
    for statement in block.statements:
        if isinstance(statement, ast.AddressWord) and statement.address in axes:
            found.add(statement.address)
        elif (isinstance(statement, ast.Assign) and isinstance(statement.target, ast.Name)
              and statement.target.name in axes):
            found.add(statement.target.name)
    return frozenset(found)


@dataclass(frozen=True, slots=True)
class EndPointStart:
    """The start of the target block after a search to the block end point (type 4).

    The first motion of the target block (``target``, whose text is ``text``) starts at
    ``actual_mcs``, where the axes stand at NC START; axes the block does not program stay
    there (002 L18296-18302). With radius compensation the block's motion may come out
    with a later block, so the kernel applies this to the first motion of ``target``.
    """

    target: Source
    text: str
    actual_mcs: Mapping[str, float]
    tolerance: CircleTolerance

    def apply(self, motion: Motion) -> Motion:
        """``motion`` started from the actual position; 14040 (at the target block) for a
        circle whose radius from there differs from its end radius beyond the tolerance
        (002 L18474-18477, L18836-18840)."""
        actual = self.actual_mcs
        programmed = programmed_axes(self.text, frozenset(motion.end_mcs))
        end_mcs = dict(motion.end_mcs)
        end_wcs = dict(motion.end_wcs)
        for axis in end_mcs:
            if programmed is not None and axis not in programmed and axis in actual:
                if axis in end_wcs:  # (no rotating frame assumed for the axes left standing)
                    end_wcs[axis] += actual[axis] - end_mcs[axis]
                end_mcs[axis] = actual[axis]
        start_mcs = {axis: float(actual.get(axis, value))
                     for axis, value in (motion.start_mcs or actual).items()}
        moved = replace(motion, start_mcs=start_mcs, end_mcs=end_mcs, end_wcs=end_wcs)
        if moved.center_mcs is not None:
            _check_circle(moved, self.tolerance)
        return moved


def _check_circle(motion: Motion, tolerance: CircleTolerance) -> None:
    """14040 when start and end radius about the centre differ beyond the tolerance."""
    center = motion.center_mcs or {}
    normal = motion.arc_normal_mcs or {}

    def radius(point: Mapping[str, float]) -> float:
        offset = {a: float(point.get(a, 0.0)) - float(c) for a, c in center.items()}
        along = sum(offset[a] * float(normal.get(a, 0.0)) for a in offset)
        return math.sqrt(sum((offset[a] - along * float(normal.get(a, 0.0))) ** 2 for a in offset))

    r_start, r_end = radius(motion.start_mcs), radius(motion.end_mcs)
    if r_start < 1e-9 or abs(r_start - r_end) > tolerance.allowed(r_start):
        source = motion.source
        raise NcAlarmError(ALARM_CIRCLE_END_POINT, file=source.file, line=source.line, n=source.n)
