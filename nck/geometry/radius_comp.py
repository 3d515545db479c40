"""Tool radius compensation 2D (TRC): G40 / G41 / G42 in the active plane.

The compensator turns the programmed contour of the active plane into the
path of the tool centre, block by block, with a look-ahead buffer. It is pure
geometry: no tool table, no frames, no feed. The caller (the motion builder)
gives it the programmed elements in plane coordinates (see
:mod:`nck.geometry.trc_geometry` for the axis order of G17/G18/G19) with the
compensation state of each block, and receives the tool-centre elements.

Adapter API (what the motion builder calls)::

    comp = RadiusCompensator(TrcSettings.from_machine(machine))
    for each block with motion (or without motion in the plane):
        for out in comp.feed(ContourElement(...)):   # may return nothing yet
            emit a Motion for ``out`` (its ``source`` is the block it belongs to)
    at a preprocessing stop (STOPRE) or program end:
        for out in comp.flush(): ...
    on RESET:
        comp.reset()

``feed`` returns the finished elements in path order. While compensation is
active the output lags the input by up to MD20240 blocks (the look-ahead
needed to find intersections); ``flush`` empties the buffer, ending at the
offset point of the last block. Every fed element comes out at least once:
a block without motion in the plane (``kind == "dummy"`` output, start ==
end) says where in the plane its other-axis motion happens; a block skipped
by bottleneck detection comes out as a dummy with ``warning = 10763``.
Elements inserted by the NC (transition circles at outside corners, linking
lines) have ``inserted = True`` and carry the block they belong to: the
following block (the transition circle counts as part of the next block).

Rules implemented (Function Manual W1 §18.5; Programming Guide 840C ch. 11):

* Selection on the first block with plane motion under G41/G42 with D≠0; it
  must be linear (G0/G1), otherwise alarm 10753. D0 selects nothing. If the
  next plane block has G40, nothing is selected.
* NORM: straight to the normal position at the start of the first contour
  element (and from the normal position at the end on retraction). KONT: the
  same unless the start (end) point lies behind the contour; then the tool
  goes round the contour point (G450 circle / G451 intersection).
* Deselection G40 only in a linear block (alarm 10754). A G40 block that
  moves only other geometry axes still deselects. D0 while active: alarm
  10750, compensation stays active.
* Outside corners: G450 circle of radius r round the corner point, G451
  intersection of the offset elements; G451 falls back to G450 above
  MD20210 (very sharp corners), G450 uses the intersection below MD20230
  (very flat corners).
* Inside corners: intersection of the offset elements; if none, up to
  MD20240 blocks ahead are searched (the blocks in between are skipped,
  warning 10763); none found: alarm 10751. With CDON non-adjacent blocks are
  always checked and the last intersection wins.
* Retraction (G462, the initial setting): if the last block's offset has no
  intersection with the one before, it is extended by its end tangent; where
  that meets the previous offset the tool stops and retracts.
* Arcs are offset to radius R ∓ r; an inside arc whose radius is smaller than
  the compensation: alarm 10758.
* Up to MD20250 consecutive blocks without plane motion; one more: alarm 10762.
* A change of D (radius) while active: each block is offset with its own
  radius; the corner is the intersection of the two offsets (or a linking
  line). A change of side (G41↔G42) links the end normal point of the old
  block to the start normal point of the new one. ``mirrored`` swaps G41/G42.

After an alarm raised by :meth:`RadiusCompensator.feed` for 10750, 10753,
10754, 10758 or 10762 the state is unchanged; after 10751 the channel must
reset the compensator (the program is aborted anyway).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Iterable

from nck.errors import NcAlarmError
from nck.geometry.trc_geometry import (
    EPS_MM,
    EPS_PARALLEL,
    Curve,
    Vec,
    add,
    arc,
    contains,
    cross,
    dist,
    dot,
    intersections,
    left_normal,
    line,
    offset,
    offset_radius,
    length,
    param,
    param_tolerance,
    path_length_mm,
    same_point,
    scale,
    sub,
    tangent_end,
    tangent_start,
    unit,
)
from nck.geometry.trc_elements import (
    ALARM_COLLISION,
    ALARM_CURVATURE_TOO_SMALL,
    ALARM_D0_WHILE_ACTIVE,
    ALARM_DESELECT_NOT_LINEAR,
    ALARM_SELECT_NOT_LINEAR,
    ALARM_TOO_MANY_DUMMY_BLOCKS,
    LINEAR_KINDS,
    WARNING_BLOCK_SKIPPED,
    CompensatedElement,
    ContourElement,
    TrcSettings,
)

__all__ = [
    "ALARM_COLLISION", "ALARM_CURVATURE_TOO_SMALL", "ALARM_D0_WHILE_ACTIVE",
    "ALARM_DESELECT_NOT_LINEAR", "ALARM_SELECT_NOT_LINEAR", "ALARM_TOO_MANY_DUMMY_BLOCKS",
    "WARNING_BLOCK_SKIPPED", "CompensatedElement", "ContourElement", "RadiusCompensator",
    "TrcSettings", "compensate", "with_state",
]


@dataclass
class _Piece:
    """A buffered piece of the raw offset path."""

    curve: Curve
    owner: ContourElement
    role: str
    inside_before: bool = False
    trailing: list[ContourElement] = field(default_factory=list)


def _alarm(number: int, element: ContourElement | None, *params: object) -> NcAlarmError:
    error = NcAlarmError(number, *params)
    source = element.source if element is not None else None
    if source is not None:
        error.located(
            getattr(source, "file", None), getattr(source, "line", None), getattr(source, "n", None)
        )
    error.trc_source = source  # type: ignore[attr-defined]
    return error


def _arc_kind(ccw: bool) -> str:
    return "G3" if ccw else "G2"


class RadiusCompensator:
    """Streaming 2D tool radius compensation with look-ahead (see the module docstring)."""

    def __init__(self, settings: TrcSettings | None = None) -> None:
        self.settings = settings or TrcSettings()
        self.reset()

    def reset(self) -> None:
        """Forget everything: compensation off, buffers empty (RESET / program start)."""
        self._state = "off"
        self._selection: ContourElement | None = None
        self._selection_dummies: list[ContourElement] = []
        self._pieces: list[_Piece] = []
        self._dummy_run = 0
        self._resume: tuple[Vec, ContourElement] | None = None

    @property
    def active(self) -> bool:
        """True while compensation is selected (including a pending selection)."""
        return self._state != "off"

    @property
    def holding(self) -> bool:
        """True while a programmed block waits in the look-ahead (selection or buffered pieces)."""
        return self._state == "selecting" or bool(self._pieces)

    # ----------------------------------------------------------------- feeding

    def feed(self, element: ContourElement) -> list[CompensatedElement]:
        """Take the next programmed block; return the tool-centre elements now finished."""
        if self._state == "off":
            return self._feed_off(element)
        if not element.moves_in_plane:
            return self._feed_dummy(element)
        if element.edge == 0 and element.side != "G40":
            raise _alarm(ALARM_D0_WHILE_ACTIVE, element)
        self._dummy_run = 0
        if self._state == "selecting":
            return self._feed_after_selection(element)
        if element.side == "G40":
            if element.kind not in LINEAR_KINDS:
                raise _alarm(ALARM_DESELECT_NOT_LINEAR, element)
            return self._retract(element)
        self._check_curvature(element)
        self._append(element)
        return self._drain(self.settings.max_check_blocks)

    def flush(self) -> list[CompensatedElement]:
        """Empty the look-ahead (preprocessing stop or program end).

        The last compensated block ends at its offset point; the next plane block
        starts from there with a linking line to its own start offset point.
        """
        if self._state == "selecting":
            assert self._selection is not None
            out = [self._uncompensated(self._selection)]
            out += [self._uncompensated(d) for d in self._selection_dummies]
            self._selection = None
            self._selection_dummies = []
            self._state = "off"
            return out
        if self._state != "on" or not self._pieces:
            return []
        out = self._drain(0)
        last = self._pieces[0]
        out += self._emit(last, last.curve)
        self._resume = (last.curve.end, last.owner)
        self._pieces = []
        return out

    # ------------------------------------------------------------ state: off

    def _feed_off(self, element: ContourElement) -> list[CompensatedElement]:
        wants = element.side in ("G41", "G42") and element.edge != 0
        if wants and element.moves_in_plane:
            if element.kind not in LINEAR_KINDS:
                raise _alarm(ALARM_SELECT_NOT_LINEAR, element)
            self._state = "selecting"
            self._selection = element
            self._selection_dummies = []
            self._dummy_run = 0
            return []
        return [self._uncompensated(element)]

    def _uncompensated(self, element: ContourElement) -> CompensatedElement:
        return CompensatedElement(
            kind=element.kind,
            start=element.start,
            end=element.end,
            source=element.source,
            center=element.center,
            role="uncompensated",
            programmed=element,
        )

    # ---------------------------------------------------- blocks without plane motion

    def _feed_dummy(self, element: ContourElement) -> list[CompensatedElement]:
        if element.side == "G40" and element.geometry_axis:
            # A geometry axis in the G40 block deselects even outside the plane.
            if self._state == "selecting":
                out = self.flush()
                return out + [self._uncompensated(element)]
            self._dummy_run = 0
            return self._retract(element)
        if element.edge == 0 and element.side != "G40":
            raise _alarm(ALARM_D0_WHILE_ACTIVE, element)
        if self._dummy_run + 1 > self.settings.max_dummy_blocks:
            raise _alarm(ALARM_TOO_MANY_DUMMY_BLOCKS, element)
        self._dummy_run += 1
        if self._state == "selecting" or not self._pieces:
            if self._state == "on" and self._resume is not None:
                point = self._resume[0]
                return [self._dummy_output(element, point)]
            self._selection_dummies.append(element)
        else:
            self._pieces[-1].trailing.append(element)
        return []

    def _dummy_output(
        self, element: ContourElement, point: Vec, role: str = "dummy", warning: int | None = None
    ) -> CompensatedElement:
        return CompensatedElement(
            kind="dummy",
            start=point,
            end=point,
            source=element.source,
            role=role,
            warning=warning,
            programmed=element,
        )

    # ------------------------------------------------------------- selection

    def _check_curvature(self, element: ContourElement) -> None:
        if element.is_arc and offset_radius(element.curve(), element.offset_mm) < -EPS_MM:
            raise _alarm(ALARM_CURVATURE_TOO_SMALL, element)

    def _feed_after_selection(self, element: ContourElement) -> list[CompensatedElement]:
        selection = self._selection
        assert selection is not None
        if element.side == "G40":
            # G40 in the block after the selection: nothing is selected.
            out = self.flush()
            return out + [self._uncompensated(element)]
        self._check_curvature(element)
        out = self._approach(selection, element)
        self._selection = None
        self._selection_dummies = []
        self._state = "on"
        return out

    def _corner_mode(self, requested: str, turn_rad: float) -> str:
        turn_deg = math.degrees(turn_rad)
        if requested == "G451" and turn_deg > self.settings.corner_limit_deg:
            return "G450"
        if requested == "G450" and turn_deg < self.settings.curve_insert_limit_deg:
            return "G451"
        return requested

    @staticmethod
    def _nearest(points: Iterable[Vec], target: Vec, limit: float) -> Vec | None:
        best: Vec | None = None
        for point in points:
            if dist(point, target) <= limit and (best is None or dist(point, target) < dist(best, target)):
                best = point
        return best

    def _approach(self, selection: ContourElement, first: ContourElement) -> list[CompensatedElement]:
        d = first.offset_mm
        first_curve = first.curve()
        first_offset = offset(first_curve, d)
        p0, p1 = selection.start, selection.end
        a = unit(sub(p1, p0))
        t1 = tangent_start(first_curve)
        turn = math.atan2(abs(cross(a, t1)), dot(a, t1))
        outside = cross(a, t1) * d < 0 or (abs(cross(a, t1)) < EPS_PARALLEL and dot(a, t1) < 0)
        behind = selection.approach == "KONT" and d != 0 and outside and dot(a, t1) < 0
        out: list[CompensatedElement] = []
        start_point = first_offset.start
        if not behind:
            out.append(self._make(selection, line(p0, start_point), "approach"))
        else:
            normal_point = add(p1, scale(left_normal(a), d))
            mode = self._corner_mode(selection.corner_mode, turn)
            crossing = None
            if mode == "G451":
                approach_offset = line(normal_point, add(normal_point, a))
                crossing = self._nearest(
                    intersections(approach_offset, first_offset), p1, 3.0 * abs(d)
                )
            if crossing is not None:
                out.append(self._make(selection, line(p0, crossing), "approach"))
                first_offset = first_offset.with_start(crossing)
                start_point = crossing
            else:
                out.append(self._make(selection, line(p0, normal_point), "approach"))
                round_arc = arc(normal_point, start_point, p1, ccw=d < 0)
                out.append(self._make(selection, round_arc, "approach", inserted=True))
        for dummy in self._selection_dummies:
            out.append(self._dummy_output(dummy, start_point))
        self._pieces = [_Piece(curve=first_offset, owner=first, role="contour")]
        self._resume = None
        return out

    # ----------------------------------------------------- contour elements

    def _append(self, element: ContourElement) -> None:
        """Add the raw offset of ``element`` (and any corner piece) to the buffer."""
        new_curve = offset(element.curve(), element.offset_mm)
        if not self._pieces:
            # Restart after a flush: link from where the tool stands.
            assert self._resume is not None
            point = self._resume[0]
            self._resume = None
            pieces = []
            if not same_point(point, new_curve.start):
                pieces.append(_Piece(line(point, new_curve.start), element, "link"))
            pieces.append(_Piece(new_curve, element, "contour"))
            self._pieces = pieces
            return
        prev = self._pieces[-1]
        prev_el = prev.owner
        d_prev, d_new = prev_el.offset_mm, element.offset_mm
        t_prev = tangent_end(prev_el.curve())
        t_new = tangent_start(element.curve())
        corner = element.start
        end_prev = prev.curve.end
        start_new = new_curve.start
        turn_cross = cross(t_prev, t_new)
        turn = math.atan2(abs(turn_cross), dot(t_prev, t_new))
        extra: list[_Piece] = []
        inside = False
        if same_point(end_prev, start_new):
            pass
        elif d_prev * d_new < 0 or (abs(turn_cross) < EPS_PARALLEL and dot(t_prev, t_new) > 0):
            # Change of side, or a tangent transition with a change of radius.
            extra.append(_Piece(line(end_prev, start_new), element, "link"))
        else:
            reversal = abs(turn_cross) < EPS_PARALLEL
            outside = reversal or turn_cross * (d_prev if d_prev != 0 else d_new) < 0
            if not outside:
                inside = True
            else:
                mode = self._corner_mode(element.corner_mode, turn)
                same_radius = abs(abs(d_prev) - abs(d_new)) <= EPS_MM
                if not same_radius:
                    mode = "G451"
                crossing = None
                if mode == "G451":
                    reach = 3.0 * max(abs(d_prev), abs(d_new))
                    crossing = self._nearest(intersections(prev.curve, new_curve), corner, reach)
                if crossing is not None:
                    prev.curve = prev.curve.with_end(crossing)
                    new_curve = new_curve.with_start(crossing)
                elif same_radius:
                    extra.append(
                        _Piece(arc(end_prev, start_new, corner, ccw=d_prev < 0), element, "corner")
                    )
                else:
                    extra.append(_Piece(line(end_prev, start_new), element, "link"))
        self._pieces.extend(extra)
        self._pieces.append(_Piece(new_curve, element, "contour", inside_before=inside))

    def _blocks_ahead(self) -> int:
        """Number of buffered blocks after the block of the head piece."""
        head_owner = self._pieces[0].owner
        return sum(
            1 for piece in self._pieces[1:] if piece.role == "contour" and piece.owner is not head_owner
        )

    def _drain(self, keep: int) -> list[CompensatedElement]:
        """Resolve head pieces while at least ``keep`` further blocks are buffered."""
        out: list[CompensatedElement] = []
        while len(self._pieces) > 1 and self._blocks_ahead() >= max(keep, 1):
            out += self._resolve_head()
        if keep == 0:
            while len(self._pieces) > 1:
                out += self._resolve_head()
        return out

    def _valid_crossing(self, head: Curve, other: Curve, exclude: Vec | None) -> Vec | None:
        """The intersection of two bounded pieces nearest the start of ``other``."""
        best: Vec | None = None
        best_param = math.inf
        for point in intersections(head, other):
            if exclude is not None and same_point(point, exclude, EPS_MM * 100):
                continue
            if not (contains(head, point) and contains(other, point)):
                continue
            p = param(other, point)
            if other.center is not None and p > math.pi * 2 - 1e-6:
                p = 0.0
            if p < best_param:
                best, best_param = point, p
        return best

    def _resolve_head(self) -> list[CompensatedElement]:
        head = self._pieces[0]
        rest = self._pieces[1:]
        inside = rest[0].inside_before
        detect = head.owner.collision_detection
        chosen: tuple[int, Vec] | None = None
        # Where the head would end with its neighbour alone.
        if inside:
            adjacent = self._valid_crossing(head.curve, rest[0].curve, None)
            if adjacent is not None:
                chosen = (0, adjacent)
                limit = param(head.curve, adjacent)
            else:
                limit = math.inf
        else:
            limit = length(head.curve)
        if chosen is None and inside or detect:
            # Search later blocks. A crossing counts only before the neighbour's
            # crossing on the head (the offset path would form a loop there); of
            # several, the first along the head wins, for equal points the later block.
            tolerance = param_tolerance(head.curve)
            best = limit - tolerance
            window = 0
            for index, piece in enumerate(rest):
                if piece.role == "contour" and piece.owner is not head.owner:
                    window += 1
                if window > self.settings.max_check_blocks:
                    break
                if index == 0:
                    continue
                exclude = head.curve.end if not inside else None
                crossing = self._valid_crossing(head.curve, piece.curve, exclude)
                if crossing is None:
                    continue
                at = param(head.curve, crossing)
                if at < best + tolerance:
                    chosen = (index, crossing)
                    best = min(best, at)
        if chosen is None:
            if inside:
                raise _alarm(ALARM_COLLISION, rest[0].owner)
            out = self._emit(head, head.curve)
            self._pieces = rest
            return out
        index, crossing = chosen
        out = self._emit(head, head.curve.with_end(crossing))
        emitted_owners = {id(head.owner)}
        for skipped in rest[:index]:
            if skipped.role == "contour" and id(skipped.owner) not in emitted_owners:
                out.append(
                    self._dummy_output(skipped.owner, crossing, "skipped", WARNING_BLOCK_SKIPPED)
                )
                emitted_owners.add(id(skipped.owner))
            for dummy in skipped.trailing:
                out.append(self._dummy_output(dummy, crossing))
        target = rest[index]
        target.curve = target.curve.with_start(crossing)
        target.inside_before = False
        self._pieces = rest[index:]
        return out

    # ------------------------------------------------------------- retraction

    def _retract_extended(self, element: ContourElement) -> list[CompensatedElement] | None:
        """G462: the last block has no intersection with the one before; extend it.

        Its offset is prolonged by its end tangent; where that meets the previous
        offset the tool stops and retracts (the rest of the corner stays unmachined).
        Returns None when this does not apply (the caller raises 10751).
        """
        if len(self._pieces) != 2 or self._pieces[1].role != "contour":
            return None
        head, last = self._pieces
        end = last.curve.end
        ray = line(end, add(end, tangent_end(last.curve)))
        found = [
            point for point in intersections(head.curve, ray)
            if contains(head.curve, point) and param(ray, point) >= -EPS_MM
        ]
        if not found:
            return None
        crossing = min(found, key=lambda point: param(head.curve, point))
        out = self._emit(head, head.curve.with_end(crossing))
        out.append(self._dummy_output(last.owner, crossing, "contour"))
        for dummy in last.trailing:
            out.append(self._dummy_output(dummy, crossing))
        out.append(self._make(element, line(crossing, element.end), "retract"))
        self._pieces = []
        self._state = "off"
        self._resume = None
        return out

    def _retract(self, element: ContourElement) -> list[CompensatedElement]:
        out: list[CompensatedElement] = []
        while len(self._pieces) > 1:
            try:
                out += self._resolve_head()
            except NcAlarmError as error:
                if error.number != ALARM_COLLISION:
                    raise
                extended = self._retract_extended(element)
                if extended is None:
                    raise
                return out + extended
        if not self._pieces:
            # Deselection right after a flush: go from the offset point to the end point.
            point = self._resume[0] if self._resume is not None else element.start
            out.append(self._make(element, line(point, element.end), "retract"))
            self._state = "off"
            self._resume = None
            return out
        last = self._pieces[0]
        d = last.owner.offset_mm
        pn, pe = element.start, element.end
        t_n = tangent_end(last.owner.curve())
        moves = not same_point(pn, pe)
        r_dir = unit(sub(pe, pn)) if moves else t_n
        turn_cross = cross(t_n, r_dir)
        outside = turn_cross * d < 0 or (abs(turn_cross) < EPS_PARALLEL and dot(t_n, r_dir) < 0)
        behind = element.approach == "KONT" and moves and d != 0 and outside and dot(t_n, r_dir) < 0
        if not behind:
            out += self._emit(last, last.curve)
            out.append(self._make(element, line(last.curve.end, pe), "retract"))
        else:
            turn = math.atan2(abs(turn_cross), dot(t_n, r_dir))
            normal_point = add(pn, scale(left_normal(r_dir), d))
            mode = self._corner_mode(element.corner_mode, turn)
            crossing = None
            if mode == "G451":
                retract_offset = line(normal_point, add(normal_point, r_dir))
                crossing = self._nearest(
                    intersections(last.curve, retract_offset), pn, 3.0 * abs(d)
                )
            if crossing is not None:
                out += self._emit(last, last.curve.with_end(crossing))
                out.append(self._make(element, line(crossing, pe), "retract"))
            else:
                out += self._emit(last, last.curve)
                round_arc = arc(last.curve.end, normal_point, pn, ccw=d < 0)
                out.append(self._make(element, round_arc, "retract", inserted=True))
                out.append(self._make(element, line(normal_point, pe), "retract"))
        self._pieces = []
        self._state = "off"
        self._resume = None
        return out

    # ---------------------------------------------------------------- output

    def _make(
        self, owner: ContourElement, curve: Curve, role: str, inserted: bool = False
    ) -> CompensatedElement:
        if curve.is_arc:
            kind = _arc_kind(curve.ccw)
        elif owner.kind in LINEAR_KINDS:
            kind = owner.kind
        else:
            kind = "G1"
        return CompensatedElement(
            kind=kind,
            start=curve.start,
            end=curve.end,
            source=owner.source,
            center=curve.center,
            role=role,
            inserted=inserted,
            programmed=owner,
        )

    def _emit(self, piece: _Piece, curve: Curve) -> list[CompensatedElement]:
        """Output one resolved piece (and the dummy blocks that follow it)."""
        out: list[CompensatedElement] = []
        if path_length_mm(curve) > EPS_MM:
            inserted = piece.role in ("corner", "link")
            out.append(self._make(piece.owner, curve, piece.role, inserted=inserted))
        elif piece.role == "contour":
            out.append(self._dummy_output(piece.owner, curve.end, "contour"))
        for dummy in piece.trailing:
            out.append(self._dummy_output(dummy, curve.end))
        return out


def compensate(
    elements: Iterable[ContourElement], settings: TrcSettings | None = None
) -> list[CompensatedElement]:
    """Compensate a whole element list at once (feed everything, then flush)."""
    comp = RadiusCompensator(settings)
    out: list[CompensatedElement] = []
    for element in elements:
        out += comp.feed(element)
    out += comp.flush()
    return out


def with_state(element: ContourElement, **changes: Any) -> ContourElement:
    """A copy of ``element`` with other fields (convenience for callers and tests)."""
    return replace(element, **changes)
