"""Motion of the ISO T turning cycles as Siemens blocks (pure geometry, no program flow).

Every function gets numbers (already converted from the ISO words) and the
start point ``A`` of the cycle as ``(z, x)`` with X a *diameter*, and returns
Siemens-mode blocks with absolute targets (``X=AC(…)`` as a diameter under
DIAMON, ``Z=AC(…)``). Cycle formats follow the Fanuc convention; the manual
(ISO Dialects, §3.4) leaves the parameter figures out, so these are documented
choices:

* G71/G72 rough stock removal along Z / along X: passes of depth ``Δd``
  (radius for G71) from the start point toward the contour shifted by the
  finishing allowance (``U`` diameter, ``W``); each pass rapids to its depth,
  cuts (G1) to the shifted contour, lifts by ``e`` at 45° (G0) and rapids back;
  a pass that does not meet the contour cuts nothing and is left out. Then one
  pass along the shifted contour, then rapid back to A (X first, then Z, for
  G72 Z first).
* G73 pattern repeat: ``d`` passes along the contour shifted by a share of the
  total relief ``Δi``/``Δk`` (radius / Z) plus the allowance; back to A after
  each pass.
* G74/G75 peck drilling / grooving along Z / along X with retract ``e`` after
  every peck, columns stepped by ``Δi`` (X, radius) / ``Δk`` (Z).
* G76 multi-pass threading: cut depths ``Δd·√n`` (at least ``Δdmin`` more each
  pass) down to ``k − d``, then the finishing depth ``k`` ``m`` times; with a
  tool angle the infeed follows one flank (start and end Z move back by
  ``depth·tan(angle/2)``). Each pass: rapid to depth, G33 to the end (with a
  run-out ``rr`` the last ``rr/10`` leads at 45°), rapid out to the start X,
  rapid back to the start Z.
* G77/G78/G79 single cycles (system A: G90/G92/G94): rapid in, cut (G1, G33
  for G78), feed (G78: rapid) out, rapid back; ``R`` is the taper (radius
  difference for G77/G78, Z difference for G79).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso.turning_contour import EPS, Element, crossing, fmt_elements

ALARM_PITCH = 61001  # thread lead (pitch) wrong
ALARM_NO_INFEED = 61610  # no infeed depth programmed
ALARM_BAD_VALUE = 61812  # value(s) incorrectly specified in the external cycle call
ALARM_START_POINT = 61607  # starting point not outside the machining area
MAX_PASSES = 10_000


def _feed(feed: float | None) -> str:
    return f" F{trimmed(feed)}" if feed else ""


def _x(diameter: float) -> str:
    return f"X=AC({trimmed(diameter)})"


def _z(z: float) -> str:
    return f"Z=AC({trimmed(z)})"


def _point(facing: bool, a: float, b: float) -> tuple[float, float]:
    """(z, r) of a point given in cycle coordinates (a cut axis, b infeed axis)."""
    return (b, a) if facing else (a, b)


def _words(facing: bool, a: float | None = None, b: float | None = None) -> str:
    """Target words for cycle coordinates: G71 a = Z, b = radius; G72 a = radius, b = Z."""
    parts = []
    z, r = (b, a) if facing else (a, b)
    if r is not None:
        parts.append(_x(2 * r))
    if z is not None:
        parts.append(_z(z))
    return " ".join(parts)


@dataclass(frozen=True)
class RoughingPass:
    """One roughing pass: infeed level ``b`` and where the cut ends along ``a``."""

    level: float
    cut_end: float


def roughing_passes(profile: Sequence[Element], start: tuple[float, float], depth: float,
                    first: tuple[float, float]) -> list[RoughingPass]:
    """Passes in cycle coordinates (``(a, b)`` points, elements already in (a, b)).

    ``start`` is A, ``first`` the shifted contour start A''; passes step by
    ``depth`` from A toward A'' and stop before reaching it.
    """
    if depth <= 0:
        raise NcAlarmError(ALARM_NO_INFEED, "U")
    a0, b0 = start
    sign = 1.0 if first[1] > b0 else -1.0
    along = profile[-1].end[0] - profile[0].start[0]  # the contour's direction along a
    passes: list[RoughingPass] = []
    for k in range(1, MAX_PASSES):
        level = b0 + sign * k * depth
        if (first[1] - level) * sign <= EPS:
            break
        end = crossing(profile, level)
        if end is None:  # beyond the contour on the start side: cut to the contour's end
            end = profile[-1].end[0]
        if (end - a0) * along > EPS or (abs(along) <= EPS and abs(end - a0) > EPS):
            passes.append(RoughingPass(level, end))  # (a cut backward from A cuts nothing)
    return passes


def stock_removal(profile: Sequence[Element], start_zx: tuple[float, float], depth: float,
                  retract: float, du: float, dw: float, feed: float | None,
                  facing: bool) -> list[str]:
    """G71 (``facing`` False) / G72 (True) roughing blocks, ending back at A.

    ``profile`` holds the contour elements in (z, r) after the approach block;
    ``start_zx`` is A as (z, X diameter).
    """
    if not profile:
        raise NcAlarmError(ALARM_BAD_VALUE, "P")
    moved = [e.moved(dw, du / 2.0) for e in profile]
    cycle = [e.swapped() for e in moved] if facing else moved
    _check_monotonic(cycle)
    za, xa = start_zx
    a0, b0 = _point(facing, za, xa / 2.0)  # (z, r) -> cycle coords is the same swap
    first = cycle[0].start
    infeed_sign = 1.0 if first[1] > b0 else -1.0
    levels = [p[1] for e in ([x.swapped() for x in profile] if facing else profile)
              for p in (e.start, e.end)]
    if (b0 - max(levels) if infeed_sign < 0 else min(levels) - b0) < -EPS:
        raise NcAlarmError(ALARM_START_POINT, "A")  # the start point lies inside the contour
    blocks: list[str] = []
    for step in roughing_passes(cycle, (a0, b0), depth, first):
        cut_sign = 1.0 if step.cut_end > a0 else -1.0
        blocks.append(f"G0 {_words(facing, b=step.level)}")
        blocks.append(f"G1 {_words(facing, a=step.cut_end)}{_feed(feed)}")
        blocks.append(f"G0 {_words(facing, step.cut_end - cut_sign * retract, step.level - infeed_sign * retract)}")
        blocks.append(f"G0 {_words(facing, a=a0)}")
    blocks.append(f"G0 {_words(facing, first[0], first[1])}")
    blocks.extend(fmt_elements(moved, _feed(feed)))
    blocks.extend(_back_to(start_zx, facing))
    return blocks


def _check_monotonic(cycle: Sequence[Element]) -> None:
    """G71/G72 (type I) need a contour that never turns back along the cut axis (61812)."""
    points = [cycle[0].start[0]] + [e.end[0] for e in cycle]
    steps = [b - a for a, b in zip(points, points[1:]) if abs(b - a) > EPS]
    if steps and not (all(s > 0 for s in steps) or all(s < 0 for s in steps)):
        raise NcAlarmError(ALARM_BAD_VALUE, "Q")


def _back_to(start_zx: tuple[float, float], facing: bool) -> list[str]:
    za, xa = start_zx
    if facing:
        return [f"G0 {_z(za)}", f"G0 {_x(xa)}"]
    return [f"G0 {_x(xa)}", f"G0 {_z(za)}"]


def pattern_repeat(approach_end: tuple[float, float], profile: Sequence[Element],
                   start_zx: tuple[float, float], relief_r: float, relief_z: float,
                   divisions: int, du: float, dw: float, feed: float | None) -> list[str]:
    """G73 blocks: ``divisions`` passes along the shifted contour, back to A after each."""
    if divisions < 1:
        raise NcAlarmError(ALARM_BAD_VALUE, "R")
    blocks: list[str] = []
    for j in range(1, divisions + 1):
        share = 0.0 if divisions == 1 else (divisions - j) / (divisions - 1)
        dz = relief_z * share + dw
        dr = relief_r * share + du / 2.0
        z, r = approach_end
        blocks.append(f"G0 {_x(2 * (r + dr))} {_z(z + dz)}")
        blocks.extend(fmt_elements([e.moved(dz, dr) for e in profile], _feed(feed)))
        blocks.extend(_back_to(start_zx, False))
    return blocks


def peck_levels(start: float, end: float, step: float) -> list[float]:
    """Levels from ``start`` toward ``end`` in steps of ``step``; the last is ``end``."""
    if step <= 0:
        return [end]
    sign = 1.0 if end > start else -1.0
    levels: list[float] = []
    level = start
    while (end - level) * sign > step + EPS and len(levels) < MAX_PASSES:
        level += sign * step
        levels.append(level)
    levels.append(end)
    return levels


def peck_cycle(start_zx: tuple[float, float], end_zx: tuple[float, float], peck: float,
               shift: float, retract: float, feed: float | None, along_x: bool) -> list[str]:
    """G74 (pecks along Z, ``along_x`` False) / G75 (pecks along X) blocks.

    ``peck`` is the peck depth (Z for G74, radius for G75), ``shift`` the column
    step of the other axis (radius for G74, Z for G75); back to A at the end.
    """
    za, xa = start_zx
    ze, xe = end_zx
    facing = along_x
    # cycle coordinates: a = peck axis, b = column axis
    a0, b0 = (xa / 2.0, za) if facing else (za, xa / 2.0)
    a_end, b_end = (xe / 2.0, ze) if facing else (ze, xe / 2.0)
    blocks: list[str] = []
    columns = [b0] + (peck_levels(b0, b_end, shift) if abs(b_end - b0) > EPS else [])
    if abs(b_end - b0) > EPS and shift <= 0:
        raise NcAlarmError(ALARM_NO_INFEED, "P" if not along_x else "Q")
    sign = 1.0 if a_end > a0 else -1.0
    for column in columns:
        if abs(column - b0) > EPS:
            blocks.append(f"G0 {_words(facing, b=column)}")
        levels = peck_levels(a0, a_end, peck)
        for index, level in enumerate(levels):
            blocks.append(f"G1 {_words(facing, a=level)}{_feed(feed)}")
            if index < len(levels) - 1:
                blocks.append(f"G0 {_words(facing, a=level - sign * retract)}")
        blocks.append(f"G0 {_words(facing, a=a0)}")
    if abs(columns[-1] - b0) > EPS:
        blocks.append(f"G0 {_words(facing, b=b0)}")
    return blocks


def thread_depths(height: float, first: float, minimum: float, allowance: float) -> list[float]:
    """Cumulative radial depths of the roughing passes of G76 (Fanuc rule, see module doc)."""
    if first <= 0 or height <= 0:
        raise NcAlarmError(ALARM_NO_INFEED, "Q")
    target = height - allowance
    depths: list[float] = []
    n = 1
    while len(depths) < MAX_PASSES:
        depth = first * math.sqrt(n)
        if depths and depth - depths[-1] < minimum:
            depth = depths[-1] + minimum
        if depth >= target - EPS or target - depth < minimum:  # no pass thinner than Δdmin
            depths.append(target)
            break
        depths.append(depth)
        n += 1
    return depths


def multi_thread(start_zx: tuple[float, float], end_zx: tuple[float, float], taper_r: float,
                 height: float, first: float, minimum: float, allowance: float,
                 finish_passes: int, angle_deg: float, lead: float,
                 chamfer_tenths: float = 0.0) -> list[str]:
    """G76 blocks (external thread if the start X is above the end X, else internal).

    ``chamfer_tenths`` (P digits rr) is the thread run-out in 0.1 leads: the last
    ``rr/10 · lead`` of every pass leaves the thread at 45° (a second G33 block).
    """
    if lead <= 0:
        raise NcAlarmError(ALARM_PITCH, "F")
    za, xa = start_zx
    ze, xe = end_zx
    outward = 1.0 if xa >= xe else -1.0
    root_r = xe / 2.0
    depths = thread_depths(height, first, minimum, allowance)
    depths += [height] * max(finish_passes, 1)
    travel = 1.0 if ze > za else -1.0
    flank = math.tan(math.radians(angle_deg) / 2.0)
    run_out = chamfer_tenths / 10.0 * lead
    blocks: list[str] = []
    for depth in depths:
        shift = -travel * depth * flank
        cut_r = root_r + outward * (height - depth)
        blocks.append(f"G0 {_x(2 * (cut_r + taper_r))} {_z(za + shift)}")
        if run_out > EPS:
            blocks.append(f"G33 {_x(2 * cut_r)} {_z(ze + shift - travel * run_out)} K{trimmed(lead)}")
            blocks.append(f"G33 {_x(2 * (cut_r + outward * run_out))} {_z(ze + shift)} "
                          f"K{trimmed(lead)}")
        else:
            blocks.append(f"G33 {_x(2 * cut_r)} {_z(ze + shift)} K{trimmed(lead)}")
        blocks.append(f"G0 {_x(xa)}")
        blocks.append(f"G0 {_z(za)}")
    return blocks


def single_cycle(code: int, start_zx: tuple[float, float], end_zx: tuple[float, float],
                 taper: float, feed: float | None) -> list[str]:
    """G77 (longitudinal), G78 (thread, ``feed`` = lead), G79 (facing) from A and back."""
    za, xa = start_zx
    ze, xe = end_zx
    if code == 77:
        return [f"G0 {_x(xe + 2 * taper)}", f"G1 {_x(xe)} {_z(ze)}{_feed(feed)}",
                f"G1 {_x(xa)}", f"G0 {_z(za)}"]
    if code == 78:
        if not feed or feed <= 0:
            raise NcAlarmError(ALARM_PITCH, "F")
        return [f"G0 {_x(xe + 2 * taper)}", f"G33 {_x(xe)} {_z(ze)} K{trimmed(feed)}",
                f"G0 {_x(xa)}", f"G0 {_z(za)}"]
    return [f"G0 {_z(ze + taper)}", f"G1 {_x(xe)} {_z(ze)}{_feed(feed)}",
            f"G1 {_z(za)}", f"G0 {_x(xa)}"]
