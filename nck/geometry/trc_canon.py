"""Tool radius compensation on canonical motions: the glue to the motion builder.

:class:`TrcStage` sits after the path builder. It takes the
:class:`nck.canon.Motion` segments of each block (the programmed contour of
the tool reference point, MCS in mm), compensates them in the MCS coordinates
of the active plane with :class:`nck.geometry.radius_comp.RadiusCompensator`,
and returns the tool-centre segments (for a turning tool: the tool reference
point P = nose centre S + the cutting-edge offset). While G40 is in force and
nothing is buffered the motions pass through untouched.

Per block it reads from the motion's ``gcodes``: G40/G41/G42, G450/G451,
NORM/KONT and CDON/CDOF; from the modal state: the active T/D
(``$TC_DP6`` + ``$TC_DP15``, type, cutting edge position) and the frame (a
mirror in the plane swaps the side, see ``mirrored``). Output segments carry
the block they belong to (``source``); NC-inserted ones have ``inserted``.
The WCS of each output comes from the builder's ``wcs_from_mcs``.

The stage lives in the geometry state of the modal state (attribute
``trc_stage``), so the interpreter's snapshot/rollback covers it. Use::

    reset_if_needed(modal)                  # before the builder reloads after RESET
    motions = process(motions, modal, path, data, machine)
    motions = flush(modal, path, data)      # stop point / program end

Known simplifications: a stop point (M0/M1/M2/M30, STOPRE) ends the
look-ahead like a preprocessing stop (the tool ends at the offset point of the
block and the next block starts with a linking line); G4 does not. KONTT and
KONTC approach like KONT; DISC, CUTCONON, G460/G461 and smooth approach
(G147 …) are not simulated; the retraction uses G462.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from typing import Any, Mapping

from nck import canon
from nck.errors import NcAlarmError
from nck.geometry.cutting_edge import effective_radius, reference_offset
from nck.geometry.radius_comp import CompensatedElement, ContourElement, RadiusCompensator, TrcSettings
from nck.geometry.tool_length import active_wear_sign, resolve_edge
from nck.geometry.trc_geometry import plane_axes, same_point

STAGE_ATTRIBUTE = "trc_stage"
ALARM_PLANE_CHANGE = 10757  # G17/G18/G19 changed while G41/G42 is active
SIDES = ("G40", "G41", "G42")
CORNER_MODES = ("G450", "G451")
APPROACH_MODES = ("NORM", "KONT", "KONTT", "KONTC")
COMPENSATED_KINDS = ("G0", "G1", "G2", "G3", "CIP", "CT")
ARC_KINDS = ("G2", "G3", "CIP", "CT")


@dataclass(frozen=True, slots=True)
class TrcKey:
    """Identifies a fed block (serial number) and where it came from (for alarms)."""

    serial: int
    file: str | None = None
    line: int | None = None
    n: int | None = None


def _member(gcodes: Mapping[int, str], members: tuple[str, ...], default: str) -> str:
    for code in gcodes.values():
        if code in members:
            return code
    return default


class TrcStage:
    """Compensator plus the motions it still has to turn into output."""

    def __init__(self, settings: TrcSettings) -> None:
        self.compensator = RadiusCompensator(settings)
        self.templates: dict[int, canon.Motion | None] = {}
        self.serial = 0
        self.last_end_mcs: dict[str, float] | None = None
        self.plane: str | None = None
        self.tips: dict[int, tuple[float, float]] = {}

    # ------------------------------------------------------------------ input
    def _element(self, motion: canon.Motion | None, modal: Any, data: Any, key: TrcKey,
                 mirrored: bool, last: canon.Motion | None) -> ContourElement:
        template = motion if motion is not None else last
        gcodes = template.gcodes if template is not None else modal.gcodes
        plane = template.plane if template is not None else modal.gcodes.get(6, "G17")
        a, b, c = plane_axes(plane)
        side = _member(gcodes, SIDES, "G40")
        edge = resolve_edge(data, modal.tool, modal.edge) if side != "G40" else None
        radius = effective_radius(edge, active_wear_sign(modal, data.setting_data))
        if edge is not None:
            self.tips[key.serial] = reference_offset(edge.tool_type, int(edge.get(2)), radius)
        state: dict[str, Any] = dict(
            side=side,
            radius_mm=radius,
            edge=int(modal.edge),
            corner_mode=_member(gcodes, CORNER_MODES, "G450"),
            approach="KONT" if _member(gcodes, APPROACH_MODES, "NORM") != "NORM" else "NORM",
            collision_detection=_member(gcodes, ("CDON", "CDOF", "CDOF2"), "CDOF") == "CDON",
            mirrored=mirrored,
        )
        if motion is None:
            point = (0.0, 0.0)
            if self.last_end_mcs is not None:
                point = (self.last_end_mcs.get(a, 0.0), self.last_end_mcs.get(b, 0.0))
            return ContourElement("G1", point, point, source=key, plane_motion=False, **state)
        start = (motion.start_mcs.get(a, 0.0), motion.start_mcs.get(b, 0.0))
        end = (motion.end_mcs.get(a, 0.0), motion.end_mcs.get(b, 0.0))
        kind = motion.kind
        center = None
        if kind in ARC_KINDS and motion.center_mcs is not None:
            center = (motion.center_mcs.get(a, 0.0), motion.center_mcs.get(b, 0.0))
            normal = getattr(motion, "arc_normal_mcs", None)
            if normal:
                kind = "G3" if float(normal.get(c, 0.0)) > 0 else "G2"
            elif kind not in ("G2", "G3"):
                kind = "G3"
        geometry_axis = any(
            abs(motion.end_mcs.get(axis, 0.0) - motion.start_mcs.get(axis, 0.0)) > 1e-9
            for axis in (a, b, c)
        )
        return ContourElement(kind, start, end, source=key, center=center,
                              geometry_axis=geometry_axis, **state)

    # ------------------------------------------------------------------ output
    def _motion(self, out: CompensatedElement, modal: Any, path: Any, data: Any) -> canon.Motion | None:
        key = out.source
        template = self.templates.get(key.serial) if isinstance(key, TrcKey) else None
        if template is None:
            return None
        if out.role == "uncompensated":
            self.last_end_mcs = dict(template.end_mcs)
            return template
        a, b, _c = plane_axes(template.plane)
        tip = (0.0, 0.0)
        if out.programmed is not None and isinstance(out.programmed.source, TrcKey):
            tip = self.tips.get(out.programmed.source.serial, tip)

        def placed(point: tuple[float, float], base: Mapping[str, float]) -> dict[str, float]:
            values = dict(base)
            values[a] = round(point[0] + tip[0], 9) + 0.0
            values[b] = round(point[1] + tip[1], 9) + 0.0
            return values

        previous = self.last_end_mcs if self.last_end_mcs is not None else template.start_mcs
        programmed = out.programmed
        # The approach starts and the retraction ends at programmed points, where the
        # reference point itself stands (no compensation there).
        if out.role == "approach" and programmed is not None and same_point(out.start, programmed.start):
            start_mcs = dict(previous)
        else:
            start_mcs = placed(out.start, previous)
        other_source = start_mcs if out.inserted else template.end_mcs
        if out.role == "retract" and programmed is not None and same_point(out.end, programmed.end):
            end_mcs = dict(template.end_mcs)
        else:
            end_mcs = placed(out.end, other_source)
        wcs = path.wcs_from_mcs(modal, end_mcs)
        end_wcs = dict(template.end_wcs)
        end_wcs[a], end_wcs[b] = wcs.get(a, end_wcs.get(a, 0.0)), wcs.get(b, end_wcs.get(b, 0.0))
        kind = template.kind if out.kind == "dummy" else out.kind
        center_mcs = center_wcs = None
        normal = None
        if out.kind in ("G2", "G3") and out.center is not None:
            center_mcs = placed(out.center, start_mcs)
            centre_wcs = path.wcs_from_mcs(modal, center_mcs)
            center_wcs = dict(template.center_wcs or template.end_wcs)
            center_wcs[a], center_wcs[b] = centre_wcs.get(a, 0.0), centre_wcs.get(b, 0.0)
            normal = {axis: 0.0 for axis in plane_axes(template.plane)}
            normal[plane_axes(template.plane)[2]] = 1.0 if out.kind == "G3" else -1.0
            if out.programmed is not None and out.programmed.mirrored:
                kind = "G2" if out.kind == "G3" else "G3"
        elif kind in ARC_KINDS:
            kind = "G1"
        self.last_end_mcs = dict(end_mcs)
        changes: dict[str, Any] = dict(
            kind=kind, start_mcs=start_mcs, end_mcs=end_mcs, end_wcs=end_wcs,
            center_mcs=center_mcs, center_wcs=center_wcs,
            inserted=template.inserted or out.inserted,
        )
        if hasattr(template, "arc_normal_mcs"):
            changes["arc_normal_mcs"] = normal
        if hasattr(template, "contour_end_wcs") and not out.inserted and out.role != "approach":
            # The programmed contour stays visible next to the compensated path.
            changes["contour_end_wcs"] = dict(template.end_wcs)
            changes["contour_center_wcs"] = (
                dict(template.center_wcs) if template.center_wcs is not None else None
            )
        if out.kind in ("G2", "G3") and (out.inserted or out.role != "contour"):
            changes["turns"] = 0
        return replace(template, **changes)

    def _emit(self, outputs: list[CompensatedElement], modal: Any, path: Any, data: Any) -> list[canon.Motion]:
        result: list[canon.Motion] = []
        for out in outputs:
            motion = self._motion(out, modal, path, data)
            if motion is not None:
                result.append(motion)
            if isinstance(out.source, TrcKey):
                for serial in [s for s in self.templates if s < out.source.serial]:
                    del self.templates[serial]
                    self.tips.pop(serial, None)
        return result

    # ------------------------------------------------------------------ API
    def idle_for(self, motions: list[canon.Motion]) -> bool:
        """True if these motions pass through untouched (G40 and nothing buffered)."""
        return not self.compensator.active and not any(
            _member(m.gcodes, SIDES, "G40") != "G40" and m.kind in COMPENSATED_KINDS for m in motions
        )

    def process(self, motions: list[canon.Motion], modal: Any, path: Any, data: Any,
                source: canon.Source | None = None) -> list[canon.Motion]:
        """Compensate the motions of one block (untouched while G40 is in force and idle)."""
        comp = self.compensator
        if self.idle_for(motions):
            return motions
        plane = motions[0].plane if motions else modal.gcodes.get(6, "G17")
        if comp.active and self.plane is not None and plane != self.plane:
            error = NcAlarmError(ALARM_PLANE_CHANGE)
            if source is not None:
                error.located(source.file, source.line, source.n)
            raise error
        mirrored = _plane_mirrored(modal, plane)
        if not comp.active:
            # The selection block starts where the block itself says (positions may
            # have changed outside this stage: frames, JOG, REPOS).
            self.last_end_mcs = None
        try:
            return self._process(motions, modal, path, data, source, mirrored)
        finally:
            self.plane = plane if comp.active else None

    def _process(self, motions: list[canon.Motion], modal: Any, path: Any, data: Any,
                 source: canon.Source | None, mirrored: bool) -> list[canon.Motion]:
        comp = self.compensator
        result: list[canon.Motion] = []
        if not motions:
            # A block without path motion counts as a block without plane motion.
            self.serial += 1
            where = source or canon.Source("", 0, None)
            key = TrcKey(self.serial, where.file, where.line, where.n)
            self.templates[self.serial] = None
            element = self._element(None, modal, data, key, mirrored, None)
            return self._emit(comp.feed(element), modal, path, data)
        for motion in motions:
            if motion.kind not in COMPENSATED_KINDS:
                # G33 and the like: end the compensation look-ahead first.
                result += self._emit(comp.flush(), modal, path, data)
                result.append(motion)
                self.last_end_mcs = dict(motion.end_mcs)
                continue
            self.serial += 1
            key = TrcKey(self.serial, motion.source.file, motion.source.line, motion.source.n)
            self.templates[self.serial] = motion
            element = self._element(motion, modal, data, key, mirrored, motion)
            result += self._emit(comp.feed(element), modal, path, data)
        return result

    def flush(self, modal: Any, path: Any, data: Any) -> list[canon.Motion]:
        """Release the look-ahead (stop point, program end)."""
        return self._emit(self.compensator.flush(), modal, path, data)


def _plane_mirrored(modal: Any, plane: str) -> bool:
    """True if the frame mirrors the plane (determinant of its plane part < 0)."""
    geo = getattr(modal, "geometry", None)
    if geo is None:
        return False
    try:
        matrix = geo.frames.transform().matrix
        names = geo.frames.transform().geometry_axes
    except AttributeError:
        return False
    a, b, _c = plane_axes(plane)
    if a not in names or b not in names:
        return False
    i, j = names.index(a), names.index(b)
    det = float(matrix[i][i] * matrix[j][j] - matrix[i][j] * matrix[j][i])
    return det < 0


def stage(modal: Any, machine: Any) -> TrcStage | None:
    """The stage of this channel (created on first use), or None without a geometry state."""
    geo = getattr(modal, "geometry", None)
    if geo is None:
        return None
    found = getattr(geo, STAGE_ATTRIBUTE, None)
    if found is None:
        found = TrcStage(TrcSettings.from_machine(machine))
        setattr(geo, STAGE_ATTRIBUTE, found)
    return found


def reset_if_needed(modal: Any) -> None:
    """Drop the stage after a RESET (the geometry state is marked not loaded)."""
    geo = getattr(modal, "geometry", None)
    if geo is not None and not getattr(geo, "loaded", True) and getattr(geo, STAGE_ATTRIBUTE, None):
        setattr(geo, STAGE_ATTRIBUTE, None)


def process(motions: list[canon.Motion], modal: Any, path: Any, data: Any, machine: Any,
            source: canon.Source | None = None) -> list[canon.Motion]:
    """Compensate one block's motions (see :class:`TrcStage`)."""
    found = stage(modal, machine)
    if found is None or found.idle_for(motions):
        return motions
    return _writable(modal, found).process(motions, modal, path, data, source)


def split_released(motions: list[canon.Motion], source: canon.Source) -> tuple[list[canon.Motion], list[canon.Motion]]:
    """Split into (motions of earlier blocks, motions of the block ``source``).

    The look-ahead releases earlier blocks' motions while a later block is built;
    they belong before that block's own auxiliary functions.
    """
    if all(m.source is source for m in motions):
        return [], motions  # the usual case: the block's own motions only
    earlier = [m for m in motions if m.source != source]
    own = [m for m in motions if m.source == source]
    return earlier, own


def flush(modal: Any, path: Any, data: Any) -> list[canon.Motion]:
    """Release the compensation look-ahead at a stop point / program end."""
    geo = getattr(modal, "geometry", None)
    found = getattr(geo, STAGE_ATTRIBUTE, None) if geo is not None else None
    if found is None or not found.compensator.active:
        return []
    return _writable(modal, found).flush(modal, path, data)


def compensating(geo: Any) -> bool | None:
    """True while radius compensation is active in the geometry state ``geo``, False when it
    is off, None while the stage has not been created (no block has asked for it yet)."""
    found = getattr(geo, STAGE_ATTRIBUTE, None)
    return None if found is None else found.compensator.active


def holding(modal: Any) -> bool:
    """True while the compensation look-ahead holds a programmed block back."""
    geo = getattr(modal, "geometry", None)
    found = getattr(geo, STAGE_ATTRIBUTE, None) if geo is not None else None
    return found is not None and found.compensator.holding


def _writable(modal: Any, found: TrcStage) -> TrcStage:
    """Copy on write: the interpreter's snapshot of the geometry state shares its
    attributes, so the stage is replaced by a copy before it changes (an alarm then
    rolls back to the untouched original)."""
    fresh = copy.deepcopy(found)
    setattr(modal.geometry, STAGE_ATTRIBUTE, fresh)
    return fresh


__all__ = ["TrcStage", "TrcKey", "process", "flush", "reset_if_needed", "split_released", "stage"]
