"""Chamfers and roundings in the block stream: holding an element back until the next one.

A block with ``CHF=``/``CHR=``/``RND=`` (or with a modal ``RNDM=``) cannot be
emitted before the next path element is known. Its element is kept in the
geometry state (:class:`~nck.geometry.path_state.PendingCorner`); the next
in-plane element trims it, the chamfer or rounding is inserted (carrying the
block that caused it) and the new element goes on. ``flush`` emits a held-back
element unchanged when the program stops or ends first.
"""

from __future__ import annotations

import math
from typing import Any, Mapping

from nck.alarm_ids import CHAMFER_OR_ROUNDING_NEGATIVE, CHAMFER_OR_ROUNDING_WITHOUT_PATH_MOTION
from nck import canon
from nck.errors import NcAlarmError
from nck.geometry.circles import Arc
from nck.geometry.contour_aids import Corner, LineElement, chamfer, rounding
from nck.geometry.path_state import GeometryState, PendingCorner
from nck.geometry.rounding_distance import AID, criterion_mm, limit_feed, round_by_distance, transition_mm
from nck.geometry.planes import Plane
from nck.geometry.units import UnitSystem



def aid_of(words: Any, geo: GeometryState, units: UnitSystem) -> tuple[str, float] | None:
    """The chamfer/rounding of the block (CHF, CHR, RND, or the modal RNDM), in mm."""
    w = words.words
    if "RNDM" in w:
        value = float(w["RNDM"]) * units.position_mm
        if value < 0:
            raise NcAlarmError(CHAMFER_OR_ROUNDING_NEGATIVE)
        geo.rndm_mm = value
    for key in ("CHF", "CHR", "RND"):
        if key in w:
            value = float(w[key]) * units.position_mm
            if value < 0:
                raise NcAlarmError(CHAMFER_OR_ROUNDING_NEGATIVE)
            return (key, value)
    if geo.rndm_mm > 0:
        return ("RND", geo.rndm_mm)
    return None


def with_contour_aids(builder: Any, words: Any, geo: GeometryState, pl: Plane,
                      element: LineElement | Arc, context: dict[str, Any],
                      start_mcs: dict[str, float], units: UnitSystem,
                      shown_end: Mapping[str, float] | None = None) -> list[canon.Motion]:
    """Emit ``element``, finishing a held-back corner first; hold ``element`` if it has an aid.

    ``shown_end``: the element's end in the WCS display (:meth:`PathBuilder.emit`), used when
    no corner trims the element."""
    out: list[canon.Motion] = []
    in_plane = moves_in_plane(element, pl)
    pending = geo.pending
    geo.pending = None
    if pending is not None:
        if in_plane and pending.context["plane"] == pl.code:
            cut = corner(pl, pending, element, context, geo)
            first = builder.emit(cut.first, pending.context, pending.context["start_mcs"])
            out.append(first)
            last_mcs = first.end_mcs
            if cut.inserted is not None:
                inserted_context = dict(pending.context)
                inserted_context["feed"] = context["feed"]
                inserted_context["programmed"] = set(pending.context["programmed"]) | {pl.abscissa, pl.ordinate}
                kind = "G1" if isinstance(cut.inserted, LineElement) else None
                motion = builder.emit(cut.inserted, inserted_context, last_mcs, kind=kind, inserted=True)
                if pending.aid == AID:
                    motion = limit_feed(motion, transition_mm(pending, context, geo), builder.machine)
                out.append(motion)
                last_mcs = motion.end_mcs
            element = cut.second
            start_mcs = dict(last_mcs)
            if isinstance(element, LineElement) or cut.inserted is not None:
                context["programmed"] = set(context["programmed"]) | {pl.abscissa, pl.ordinate}
        else:
            out.append(builder.emit(pending.element, pending.context, pending.context["start_mcs"]))
            start_mcs = dict(out[-1].end_mcs)
    aid = aid_of(words, geo, units)
    if aid is None and in_plane:
        distance = criterion_mm(context, geo)
        if distance > 0.0:
            aid = (AID, distance)  # G641: every corner is rounded by distance
    if aid is not None and in_plane and context["kind"] != "G33":
        context["start_mcs"] = start_mcs
        geo.pending = PendingCorner(element, aid[0], aid[1], context)
        return out
    if aid is not None and not in_plane and ("CHF" in words.words or "CHR" in words.words
                                             or "RND" in words.words):
        raise NcAlarmError(CHAMFER_OR_ROUNDING_WITHOUT_PATH_MOTION)
    out.append(builder.emit(element, context, start_mcs, shown_end=shown_end if pending is None else None))
    return out


def corner(pl: Plane, pending: PendingCorner, element: LineElement | Arc,
           context: dict[str, Any], geo: GeometryState) -> Corner:
    """The corner between the held-back element and the next one (``context``: the next block's)."""
    if pending.aid == AID:
        return round_by_distance(pl, pending.element, element, transition_mm(pending, context, geo))
    if pending.aid == "RND":
        return rounding(pl, pending.element, element, pending.size_mm)
    return chamfer(pl, pending.element, element, pending.size_mm, pending.aid)


def flush(builder: Any, modal: Any) -> list[canon.Motion]:
    """Emit an element held back for a chamfer/rounding unchanged (no next element came)."""
    geo = getattr(modal, "geometry", None)
    if geo is None or geo.pending is None:
        return []
    pending, geo.pending = geo.pending, None
    return [builder.emit(pending.element, pending.context, pending.context["start_mcs"])]


def moves_in_plane(element: LineElement | Arc, pl: Plane) -> bool:
    """True when the element moves in the plane (only those get chamfers and roundings)."""
    if isinstance(element, Arc):
        return True
    s, e = pl.to_plane(element.start), pl.to_plane(element.end)
    return math.hypot(e[0] - s[0], e[1] - s[1]) > 1e-9
