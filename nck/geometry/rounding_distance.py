"""G641: rounding by a path distance (``ADIS=`` for feed blocks, ``ADISPOS=`` for G0).

Under G641 with a distance above zero the corner between two path blocks is
rounded: the transition starts at most the distance before the corner and
ends at most the distance after it. The manual leaves the shape of the
transition to the control; here it is the circle tangent to both elements
(the RND machinery of :mod:`nck.geometry.contour_aids`), sized so that its
tangent points lie exactly the distance from the corner along lines (radius
``d / tan(φ / 2)`` for a turn by ``φ``) and within it along arcs.

Further rules of the manual:

* a block shorter than four times the distance keeps about 60 % of its length:
  the distance shrinks to 40 % of that block (of what is left of it after the
  rounding at its start, when it has one);
* at a transition between G0 and a feed block the smaller of ADIS and ADISPOS
  applies; two G0 blocks meeting are not rounded here (the canonical motion has
  no rapid circles: the corner is passed as under G64);
* tangential transitions, G60/G9 exact stops, threads (G33), elements outside
  the working plane and blocks with outputs in between are not rounded;
* the path velocity in the transition is limited to ``distance / IPO cycle``
  (IPO cycle = MD10050 · MD10070): the inserted circle carries that feed limit
  (``feed_mm_min`` capped; the programmed ``feed`` shown stays as it was).

The inserted circle is its own canonical ``Motion`` (``inserted=True``, G2/G3 even
between a G0 and a feed block: there are no rapid circles) and carries the
``Source`` of the block that ends at the corner, like an RND rounding. It moves
with the feed of the block after the corner.

The rounding only exists in the working plane (like RND); the remaining axes
move linearly in the trimmed blocks.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any, Mapping

from nck import canon

from nck.geometry.contour_aids import TANGENT_EPS, Corner, Element, FlatElement, corner_turn, rounding
from nck.geometry.planes import Plane

SHORT_BLOCK_FACTOR = 4.0  # blocks shorter than this many distances keep 60 %
KEPT_SHARE = 0.4  # … and the distance shrinks to this share of the block
SEARCH_STEPS = 50
AID = "ADIS"  # the aid name of a corner held back under G641
DEFAULT_IPO_CYCLE_S = 0.004


def ipo_cycle_s(machine: Any) -> float:
    """The IPO cycle of ``machine`` in seconds (MD10050 basic clock × MD10070 ratio)."""
    sysclock = machine.md_value("MD10050", None, None)
    ratio = machine.md_value("MD10070", None, None)
    if isinstance(sysclock, (int, float)) and isinstance(ratio, (int, float)) and sysclock * ratio > 0:
        return float(sysclock) * float(ratio)
    return DEFAULT_IPO_CYCLE_S


def limit_feed(motion: canon.Motion, distance_mm: float, machine: Any) -> canon.Motion:
    """The inserted transition with its feed limited to ``distance / IPO cycle`` (manual, G641)."""
    if distance_mm <= 0.0 or motion.feed_mm_min is None:
        return motion
    limit_mm_min = distance_mm / ipo_cycle_s(machine) * 60.0
    if motion.feed_mm_min <= limit_mm_min:
        return motion
    per_rev = motion.feed_mm_rev
    if per_rev is not None:
        per_rev *= limit_mm_min / motion.feed_mm_min  # the same share of the spindle's speed
    return dataclasses.replace(motion, feed_mm_min=limit_mm_min, feed_mm_rev=per_rev)


def criterion_mm(context: dict[str, Any], geo: Any) -> float:
    """The rounding distance of a block held back under G641 (0: the block is not rounded)."""
    return rounding_distance_mm(context["kind"], context["exact"], context["gcodes"], geo)


def rounding_distance_mm(kind: str, exact: bool, gcodes: Mapping[int, str], geo: Any) -> float:
    """The G641 rounding distance of a block of motion ``kind`` (ADISPOS for G0, else ADIS);
    0 when it ends in exact stop, is a thread (G33) or G641 is not active."""
    if exact or kind == "G33" or gcodes.get(10) != "G641":
        return 0.0
    return geo.adispos_mm if kind == "G0" else geo.adis_mm


def transition_mm(pending: Any, context: dict[str, Any], geo: Any) -> float:
    """The distance for the corner between a held-back block and the next one (0: none)."""
    first_rapid = pending.context["kind"] == "G0"
    second_rapid = context["kind"] == "G0"
    if context["kind"] == "G33" or (first_rapid and second_rapid):
        return 0.0
    if first_rapid != second_rapid:
        return min(geo.adis_mm, geo.adispos_mm)
    return pending.size_mm


def round_by_distance(plane: Plane, first: Element, second: Element, distance_mm: float) -> Corner:
    """The corner with a tangent circle reaching at most ``distance_mm`` into each element."""
    f, s = FlatElement(plane, first), FlatElement(plane, second)
    cross, dot = corner_turn(f, s)
    if distance_mm <= 0.0 or abs(cross) < TANGENT_EPS:
        return Corner(first, None, second)  # no distance, tangent, or a reversal
    reach = min(_limited(distance_mm, f.length), _limited(distance_mm, s.length))
    if reach <= 1e-9:
        return Corner(first, None, second)
    half_turn = math.atan2(abs(cross), dot) / 2.0
    radius = reach / math.tan(half_turn)
    cut = rounding(plane, first, second, radius)
    if f.center is None and s.center is None:
        return cut  # two lines: the tangent points are exactly ``reach`` from the corner
    if _fits(plane, f, s, cut, reach):
        return cut
    low, high = 0.0, radius
    best = Corner(first, None, second)
    for _ in range(SEARCH_STEPS):
        middle = (low + high) / 2.0
        trial = rounding(plane, first, second, middle)
        if _fits(plane, f, s, trial, reach):
            low, best = middle, trial
        else:
            high = middle
    return best


def _limited(distance_mm: float, length_mm: float) -> float:
    """The short-block rule: a block below four distances keeps 60 % of its length."""
    return distance_mm if length_mm >= SHORT_BLOCK_FACTOR * distance_mm else KEPT_SHARE * length_mm


def _fits(plane: Plane, f: FlatElement, s: FlatElement, cut: Corner, reach: float) -> bool:
    """True when the rounding exists and takes at most ``reach`` of path from each element."""
    if cut.inserted is None:
        return False
    taken_first = f.length - FlatElement(plane, cut.first).length
    taken_second = s.length - FlatElement(plane, cut.second).length
    return taken_first <= reach + 1e-9 and taken_second <= reach + 1e-9
