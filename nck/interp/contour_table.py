"""The contour of a turning cycle read from its subprogram into a table (``CONTOURTAB``).

CYCLE95 machines a contour that the program describes in a subprogram of its own
(the finished part from its start point on). On the control the cycle reads the
subprogram with its contour preparation instead of running it; here the cycle
calls the predefined procedure ``CONTOURTAB(NAME, TAB, NN)`` (the trainer's own
name, written down in data/cycles/README.md): the blocks of the program NAME are
read in order without moving anything and every contour element becomes one row
of the REAL array TAB[n, 7]; NN gets the number of rows.

Row layout (Z along the turning axis, R the radius of the transverse axis X):

    [i,0] 1 straight line, 2 clockwise arc (G2), 3 counterclockwise arc (G3)
    [i,1] [i,2]  start Z, R
    [i,3] [i,4]  end Z, R
    [i,5] [i,6]  arc centre Z, R (0 for a line)

The first block with a coordinate gives the start point (it is no element). X is a
diameter under DIAMON / DIAM90 at the call (absolute and incremental), Z is Z;
G90 / G91 and ``=AC()`` / ``=IC()`` work as in a motion block. Arcs take ``CR=``
(negative: more than a half circle) or the centre ``I``/``K`` (incremental, a
radius). G0 and G1 are both straight elements; F, S, M, G40/G41/G42 and the
other G codes are accepted and ignored. Anything else a contour of the cycle
cannot hold (RND, CHF, CHR, variables assigned, jumps, control structures,
calls) is alarm 10931 (error in the stock removal contour); an arc whose end is
not on its circle is 10931 too. The reading ends at M17, M2, M30 or RET.
"""

from __future__ import annotations

import math
from typing import Callable

from nck.alarm_ids import STOCK_REMOVAL_CONTOUR_ERROR as ALARM_CONTOUR
from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.parser import parse_block

ROW_WIDTH = 7
ARC_TOLERANCE_MM = 0.01  # end point off its circle by more than this: not an arc
_IGNORED_ADDRESSES = frozenset(("F", "S", "T", "D", "H"))
_END_M = (2, 17, 30)

Row = tuple[float, float, float, float, float, float, float]


def contour_rows(text: str, name: str, evaluate: Callable[[ast.Expr], float], diameter: bool) -> list[Row]:
    """The contour elements of the program ``text`` (see the module docstring).

    ``evaluate`` gives the value of an expression in the caller's context,
    ``diameter`` says X is programmed as a diameter.
    """
    rows: list[Row] = []
    start: tuple[float, float] | None = None
    motion, absolute = 1, True
    for number, line in enumerate(text.splitlines(), start=1):
        block = parse_block(line, number)
        words: dict[str, tuple[float, str | None]] = {}
        for statement in block.statements:
            if isinstance(statement, ast.GWord):
                code = statement.code
                if code in ("G0", "G1", "G2", "G3"):
                    motion = int(code[1])
                elif code in ("G90", "G91"):
                    absolute = code == "G90"
                continue
            if isinstance(statement, (ast.Proc, ast.Def)):
                continue
            if isinstance(statement, ast.Builtin) and statement.name == "RET":
                return rows
            if not isinstance(statement, ast.AddressWord):
                raise NcAlarmError(ALARM_CONTOUR, name)
            address = statement.address
            if address == "M":
                if evaluate(statement.value) in _END_M:
                    return rows
                continue
            if address in _IGNORED_ADDRESSES:
                continue
            if address not in ("X", "Z", "CR", "I", "K"):
                raise NcAlarmError(ALARM_CONTOUR, name)
            value, mode = statement.value, None
            if isinstance(value, ast.Func) and value.name in ("AC", "IC") and len(value.args) == 1:
                mode = value.name
                inner = value.args[0]
                if inner is None:
                    raise NcAlarmError(ALARM_CONTOUR, name)
                value = inner
            words[address] = (float(evaluate(value)), mode)
        if "X" not in words and "Z" not in words:
            continue
        z0, r0 = start if start is not None else (0.0, 0.0)
        z1 = _coordinate(words.get("Z"), z0, absolute, 1.0)
        r1 = _coordinate(words.get("X"), r0, absolute, 2.0 if diameter else 1.0)
        if start is None:
            start = (z1, r1)
            continue
        start = (z1, r1)
        if motion in (0, 1):
            if math.dist((z0, r0), (z1, r1)) > 1e-9:
                rows.append((1.0, z0, r0, z1, r1, 0.0, 0.0))
            continue
        centre = _centre(words, (z0, r0), (z1, r1), motion == 2, name)
        rows.append((float(motion), z0, r0, z1, r1, centre[0], centre[1]))
    return rows


def _coordinate(word: tuple[float, str | None] | None, previous: float, absolute: bool, scale: float) -> float:
    if word is None:
        return previous
    value, mode = word
    if mode == "IC" or (mode is None and not absolute):
        return previous + value / scale
    return value / scale


def _centre(words: dict[str, tuple[float, str | None]], start: tuple[float, float], end: tuple[float, float],
            clockwise: bool, name: str) -> tuple[float, float]:
    """Centre (Z, R) of an arc from CR= or from I/K (incremental, radius) in the ZX plane."""
    if "CR" in words:
        radius = words["CR"][0]
        chord = math.dist(start, end)
        if chord < 1e-9 or abs(radius) * 2 < chord - 1e-6:
            raise NcAlarmError(ALARM_CONTOUR, name)
        half = chord / 2.0
        height = math.sqrt(max(radius * radius - half * half, 0.0))
        mz, mr = (start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0
        uz, ur = (end[0] - start[0]) / chord, (end[1] - start[1]) / chord
        # G18 with Z as abscissa and X as ordinate: a clockwise minor arc has its centre
        # to the right of the chord
        side = 1.0 if clockwise else -1.0
        if radius < 0:
            side = -side
        return (mz + side * height * ur, mr - side * height * uz)
    if "I" not in words and "K" not in words:
        raise NcAlarmError(ALARM_CONTOUR, name)
    centre = (start[0] + words.get("K", (0.0, None))[0], start[1] + words.get("I", (0.0, None))[0])
    if abs(math.dist(centre, start) - math.dist(centre, end)) > ARC_TOLERANCE_MM:
        raise NcAlarmError(ALARM_CONTOUR, name)
    return centre
