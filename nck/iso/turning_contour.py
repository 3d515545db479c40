"""Contours of the ISO T turning cycles (G70–G73): reading, shifting, cutting-line crossings.

A contour is the chain of blocks ``P<ns>`` … ``Q<nf>`` of the program, read
statically from the lexed ISO words. Internally every point is ``(z, r)``:
Z and the *radius* of the transverse axis X (ISO T programs X as a diameter,
U as an incremental diameter). Elements are straight lines or circular arcs
(``G02``/``G03`` with ``R`` or ``I``/``K``, arcs in the ZX plane G18 with Z as
abscissa and X as ordinate, the Siemens convention for G18).

The roughing cycles only need two questions answered: where does a line
parallel to Z (G71) or parallel to X (G72) first meet the contour
(:func:`crossing`), and what does the contour look like shifted by the
finishing allowance (:func:`shifted`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable, Sequence

from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso.lexing import Word

ALARM_BAD_CYCLE_VALUE = 61812  # value(s) incorrectly specified in the external cycle call
EPS = 1e-9

Point = tuple[float, float]  # (z, r)


@dataclass(frozen=True)
class Element:
    """One contour element from ``start`` to ``end`` (both ``(z, r)``).

    ``center`` is None for a line; for an arc ``clockwise`` is G02 and
    ``radius`` its (positive) radius.
    """

    start: Point
    end: Point
    center: Point | None = None
    clockwise: bool = False

    @property
    def radius(self) -> float:
        """Arc radius (0 for a line)."""
        if self.center is None:
            return 0.0
        return math.dist(self.start, self.center)

    def moved(self, dz: float, dr: float) -> "Element":
        """The element translated by ``dz`` along Z and ``dr`` in radius."""
        def move(p: Point) -> Point:
            return (p[0] + dz, p[1] + dr)
        return replace(self, start=move(self.start), end=move(self.end),
                       center=None if self.center is None else move(self.center))

    def swapped(self) -> "Element":
        """The element with its two coordinates exchanged (mirror: arcs change sense)."""
        def swap(p: Point) -> Point:
            return (p[1], p[0])
        return Element(swap(self.start), swap(self.end),
                       None if self.center is None else swap(self.center), not self.clockwise)


def shifted(contour: Sequence[Element], du_diameter: float, dw: float) -> list[Element]:
    """The contour moved by the finishing allowance (U as a diameter, W along Z)."""
    return [e.moved(dw, du_diameter / 2.0) for e in contour]


def arc_center(start: Point, end: Point, radius: float, clockwise: bool) -> Point:
    """Centre of an arc given by its radius (negative: more than 180°), ZX plane."""
    (z0, r0), (z1, r1) = start, end
    chord = math.dist(start, end)
    if chord < EPS or abs(radius) * 2 < chord - 1e-6:
        raise NcAlarmError(ALARM_BAD_CYCLE_VALUE, "R")
    half = chord / 2.0
    height = math.sqrt(max(radius * radius - half * half, 0.0))
    mz, mr = (z0 + z1) / 2.0, (r0 + r1) / 2.0
    dz, dr = (z1 - z0) / chord, (r1 - r0) / chord
    # right of the chord for a clockwise minor arc (abscissa Z right, ordinate X up)
    side = 1.0 if clockwise else -1.0
    if radius < 0:
        side = -side
    return (mz + side * height * dr, mr - side * height * dz)


def _angle(center: Point, p: Point) -> float:
    return math.atan2(p[1] - center[1], p[0] - center[0])


def _on_arc(element: Element, p: Point) -> bool:
    """True if ``p`` (on the circle) lies within the element's sweep."""
    assert element.center is not None
    a0 = _angle(element.center, element.start)
    a1 = _angle(element.center, element.end)
    a = _angle(element.center, p)
    if element.clockwise:
        sweep, along = (a0 - a1) % (2 * math.pi), (a0 - a) % (2 * math.pi)
    else:
        sweep, along = (a1 - a0) % (2 * math.pi), (a - a0) % (2 * math.pi)
    if sweep < EPS:
        sweep = 2 * math.pi
    return along <= sweep + 1e-9 or along >= 2 * math.pi - 1e-9


def crossing(contour: Sequence[Element], level: float) -> float | None:
    """First point (in contour order) where the contour meets ``r == level``: its z.

    None if the contour never reaches that radius.
    """
    for element in contour:
        (z0, r0), (z1, r1) = element.start, element.end
        if element.center is None:
            low, high = min(r0, r1), max(r0, r1)
            if level < low - EPS or level > high + EPS:
                continue
            if abs(r1 - r0) < EPS:
                return z0
            return z0 + (z1 - z0) * (level - r0) / (r1 - r0)
        cz, cr = element.center
        radius = element.radius
        offset = level - cr
        if abs(offset) > radius + EPS:
            continue
        dz = math.sqrt(max(radius * radius - offset * offset, 0.0))
        hits = [p for p in ((cz + dz, level), (cz - dz, level)) if _on_arc(element, p)]
        if hits:  # the one nearer the element's start along the path
            hits.sort(key=lambda p: (_sweep_to(element, p)))
            return hits[0][0]
    return None


def _sweep_to(element: Element, p: Point) -> float:
    assert element.center is not None
    a0, a = _angle(element.center, element.start), _angle(element.center, p)
    return (a0 - a) % (2 * math.pi) if element.clockwise else (a - a0) % (2 * math.pi)


def read_contour(blocks: Sequence[list[Word]], start: Point, absolute: bool,
                 value: Callable[[Word], float]) -> list[Element]:
    """Contour elements of the lexed blocks ``blocks`` starting at ``start`` (``(z, r)``).

    ``absolute`` is the G90/G91 state at the cycle call (a G90/G91 inside the
    contour changes it); ``value`` converts a word to its number (decimal-point
    rules). X/Z are absolute (or incremental under G91), U/W always incremental.
    Blocks without X/Z/U/W add nothing. A G02/G03 needs R or I/K (else 61812).
    """
    elements: list[Element] = []
    z, r = start
    motion = 1
    for words in blocks:
        got: dict[str, Word] = {}
        for word in words:
            if word.letter == "G":
                code = int(word.value) if float(word.value).is_integer() else -1
                if code in (0, 1, 2, 3):
                    motion = code
                elif code == 90:
                    absolute = True
                elif code == 91:
                    absolute = False
            elif word.letter in "XZUWRIK":
                got[word.letter] = word
        if not any(letter in got for letter in "XZUW"):
            continue
        new_z, new_r = z, r
        if "Z" in got:
            new_z = value(got["Z"]) if absolute else z + value(got["Z"])
        if "W" in got:
            new_z = z + value(got["W"])
        if "X" in got:
            new_r = value(got["X"]) / 2.0 if absolute else r + value(got["X"]) / 2.0
        if "U" in got:
            new_r = r + value(got["U"]) / 2.0
        if motion in (2, 3):
            clockwise = motion == 2
            if "R" in got:
                center = arc_center((z, r), (new_z, new_r), value(got["R"]), clockwise)
            elif "I" in got or "K" in got:
                center = (z + (value(got["K"]) if "K" in got else 0.0),
                          r + (value(got["I"]) if "I" in got else 0.0))
            else:
                raise NcAlarmError(ALARM_BAD_CYCLE_VALUE, "R")
            elements.append(Element((z, r), (new_z, new_r), center, clockwise))
        elif abs(new_z - z) > EPS or abs(new_r - r) > EPS:
            elements.append(Element((z, r), (new_z, new_r)))
        z, r = new_z, new_r
    return elements


def fmt_elements(elements: Sequence[Element], feed: str) -> list[str]:
    """Siemens blocks that follow ``elements`` (absolute X as a diameter, arcs with CR)."""

    blocks: list[str] = []
    for element in elements:
        z, r = element.end
        target = f"X=AC({trimmed(2 * r)}) Z=AC({trimmed(z)})"
        if element.center is None:
            blocks.append(f"G1 {target}{feed}")
            continue
        radius = element.radius
        if _sweep_to(element, element.end) > math.pi + 1e-9:
            radius = -radius
        blocks.append(f"{'G2' if element.clockwise else 'G3'} {target} CR={trimmed(radius)}{feed}")
    return blocks
