"""Path motion of one block: end points, circles, polar moves, frames, tool length.

The interpreter's motion builder (:mod:`nck.interp.motion_builder`) handles the
technology words (F, S, T, D, M, H) and calls :class:`PathBuilder` for

* frame and pole instructions (G group 3: TRANS … AMIRROR, G58, G59, G110 …
  G112) — :meth:`PathBuilder.frame_block`;
* path motion (G0, G1, G2, G3, CIP, CT, G33, polar RP/AP, helix TURN,
  chamfers and roundings) — :meth:`PathBuilder.motion`.

Coordinates: programmed values are converted into millimetres of the WCS
(G70/G700 inch, DIAMON diameter), mapped through the frame chain into the BCS
and the tool length vector is added to get the MCS. A geometry axis that is
not programmed in a block keeps its machine position (a new offset is
travelled when the axis is next programmed) unless a rotation couples the
axes. The canonical motion carries the WCS in program units and the MCS in mm.
"""

from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Any, Iterable, Mapping, Sequence

import numpy as np

from nck.alarm_ids import NAME_NOT_DEFINED
from nck import canon
from nck.errors import NcAlarmError
from nck.geometry import circles, path_aids
from nck.geometry.chain import SUPPRESSION_CODES, frame_from_work_offset
from nck.geometry.circles import Arc, CircleTolerance
from nck.geometry.contour_aids import LineElement
from nck.geometry.frames import Frame
from nck.geometry.line_frame import LineFrame, line_frame
from nck.geometry.path_state import GeometryState
from nck.geometry.planes import GEOMETRY_AXES_DEFAULT, Plane, plane
from nck.geometry.rounding_distance import rounding_distance_mm
from nck.geometry.tangents import line_tangent
from nck.geometry.tool_length import active_wear_sign, length_offset, resolve_edge
from nck.geometry.transform import Transform
from nck.geometry.units import UnitSystem
from nck.machine import MachineConfig
from nck.ncdata import NcData, WorkOffset

ALARM_CIRCLE_NOT_DETERMINED = circles.ALARM_CIRCLE_END_POINT
ALARM_THREAD_LEAD_ZERO = 16720  # G33 without (or with zero) thread lead
SD_THREAD_START_ANGLE = "SD42000"  # start angle of a thread (SF=)
ALARM_THREAD_FRAME = 10607  # a frame rotation changes the thread length
ALARM_DC_NOT_POSSIBLE = 16800  # DC programmed for an axis that is not a rotary axis
ALARM_ACP_NOT_POSSIBLE = 16810  # ACP/ACN programmed for an axis that is not a rotary axis
ALARM_MODULO_POSITION = 16830  # ACP/ACN target outside 0 … < 360°
ALARM_NOT_AVAILABLE = 12550  # a language element this NC does not offer (contour definition forms)
ALARM_VALUE_OUTSIDE = 12560  # programmed value outside the permitted limits
ALARM_FRAME_INSTRUCTION = 18311  # G58/G59 without MD24000 FRAME_ADD_COMPONENTS
ALARM_FINE_NOT_CONFIGURED = 18312  # G58/G59 without a fine offset (MD18600 MM_FRAME_FINE_TRANS)
ROTARY_MODES = ("DC", "ACP", "ACN")
ARC_KINDS = ("G2", "G3", "CIP", "CT")
CIRCLE_KINDS = ("G2", "G3")  # circles with an end point and a centre, radius or angle
LEAD_KINDS = ("G33", "G331", "G332")
"""Path motions programmed with a lead (the thread pitch, I/J/K): thread cutting G33 and
rigid tapping G331/G332 (the spindle in position control); the path builder reads the lead."""
LINE_KINDS = ("G0", "G1")
PATH_KINDS = LINE_KINDS + LEAD_KINDS + ARC_KINDS
LINE_AID_WORDS = frozenset(("ANG", "RP", "AP", "CHF", "CHR", "RND", "RNDM"))
"""Words of a line block that need the general geometry: contour definition, polar end point,
chamfer and rounding."""
INTERP_LETTERS = "IJK"
ROUND_DIGITS = 9
_LENGTH_PARAMS = (1, 3, 4, 5, 12, 13, 14, 21, 22, 23)  # $TC_DP of the tool length vector: type, L1-L3 geometry, wear, base
_LENGTH_DEFAULTS = (0.0,) * len(_LENGTH_PARAMS)  # a parameter not written counts as 0
_UNIT_SYSTEMS: dict[tuple[str, bool], UnitSystem] = {}  # (G group 13 code, basic system metric): immutable


def machine_mm(wcs_mm: Any, scale: float, offset: float, tool_mm: float) -> Any:
    """A geometry axis' machine position under a frame that maps the axis on its own
    (:meth:`Transform.axis_affine`): ``(wcs · m_ii + t_i) + tool``, before rounding. The one
    formula of the path builder's lines and of the G1 batch (a float or a numpy array)."""
    return (wcs_mm * scale + offset) + tool_mm


def ends_in_exact_stop(words: Any, gcodes: Mapping[int, str]) -> bool:
    """Whether a block ends in exact stop: G60 modal (group 10) or G9 in the block (group 11)."""
    return gcodes.get(10, "G60") == "G60" or words.gcodes.get(11) == "G9"


assert ROUND_DIGITS == 9, "ROUND_FAST_LIMIT and ROUND_FAST_MARGIN are worked out for a scale of 10^9"
ROUND_SCALE = 10.0 ** ROUND_DIGITS
ROUND_FAST_LIMIT = 2.0 ** 43
"""Below this, ``value · 10^9`` is a double whose rounding error is at most 2^-11 (half an ulp)."""
ROUND_FAST_MARGIN = 0.49
"""How far from the nearest integer ``value · 10^9`` may be for the integer to be the
correctly rounded one: 0.49 plus the product's error stays below 0.5, away from any tie."""
ROUND_TO_INTEGER = 1.5 * 2.0 ** 52
"""Added to and taken from a double below 2^51 in magnitude, it leaves the nearest integer
(ties to even) as a double: the sum's units place is 1, so the addition rounds there."""


def round_position(value: float) -> float:
    """A position as the path builder keeps it: floating noise (sub-nanometre) and negative
    zero rounded away (every machine and WCS end point goes through this).

    ``round(value, 9) + 0.0``, in two steps where that is exact: Python rounds ``value`` to
    the nearest multiple ``k · 10^-9`` (correctly, ties to even, through a decimal string) and
    reads it back as the double nearest to ``k · 10^-9``. When ``value · 10^9`` is below
    :data:`ROUND_FAST_LIMIT` and not within 0.01 of a tie, ``k`` is the nearest integer to the
    computed product, and ``k / 10^9`` — two exact doubles, one correctly rounded division —
    *is* the double nearest to ``k · 10^-9``. ``k`` is found in doubles
    (:data:`ROUND_TO_INTEGER`; exact below 2^51, no int object made). Otherwise (near a tie,
    huge, not finite) Python's ``round`` does it (property-tested equal:
    tests/geometry/test_round_position.py).
    """
    value = float(value)
    scaled = value * ROUND_SCALE
    if -ROUND_FAST_LIMIT < scaled < ROUND_FAST_LIMIT:
        nearest = (scaled + ROUND_TO_INTEGER) - ROUND_TO_INTEGER
        if -ROUND_FAST_MARGIN <= scaled - nearest <= ROUND_FAST_MARGIN:
            return nearest / ROUND_SCALE + 0.0
    return round(value, ROUND_DIGITS) + 0.0


SHARED_GCODE_TABLES = 4
"""G-code tables the path builder keeps for its motions to share (:meth:`PathBuilder.shared_gcodes`)."""


class PathBuilder:
    """Computes the path geometry of blocks for one machine (see module docstring)."""

    separable_lines = True
    """Lines and G2/G3 circles on a separable frame take :meth:`_separable_line` and
    :meth:`_separable_arc` (the tests switch it off to compare with the general element path)."""

    def __init__(self, machine: MachineConfig, data: NcData) -> None:
        self.machine = machine
        self.data = data
        self.geo_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
        self.path_axes = machine.path_axes
        self.kinds = {a.name: a.kind for a in machine.axes}
        self.diameter_axes = frozenset(a.name for a in machine.axes if a.diameter)
        self.tolerance = CircleTolerance(
            float(machine.md_value("MD21000", default=circles.CIRCLE_ERROR_CONST_MM)),
            float(machine.md_value("MD21010", default=circles.CIRCLE_ERROR_FACTOR)),
        )
        self.mirror_toggle = bool(machine.md_value("MD10612", default=1))
        self.frame_add_components = bool(machine.md_value("MD24000", default=0))
        self.frame_fine_configured = bool(machine.md_value("MD18600", default=1))
        self.basic_metric = bool(machine.md_value("MD10240", default=1))
        self._no_tool: Mapping[str, float] = {axis: 0.0 for axis in self.geo_axes}  # read only
        self._display_axes: dict[str | None, tuple[tuple[str, bool, bool], ...]] = {}  # by G group 29 code
        self._gcodes_copies: list[Mapping[int, str]] = []  # the motions' shared G-code tables (shared_gcodes)
        self._line_frame_kept: tuple[Any, Any, LineFrame | None] = (None, None, None)
        self._tool_vectors: dict[tuple, Mapping[str, float]] = {}  # _tool_lengths by its inputs
        self._tool_vector_last: tuple[tuple | None, Mapping[str, float]] = (None, {})  # the last of them

    # ================================================================ state
    def state(self, modal: Any) -> GeometryState:
        """The geometry state inside ``modal`` (created and loaded on first use / after RESET)."""
        geo = getattr(modal, "geometry", None)
        if geo is None:
            geo = GeometryState()
            geo.wcs_mm = {axis: float(modal.position_wcs.get(axis, 0.0)) for axis in self.path_axes}
            modal.geometry = geo
        code = modal.gcodes.get(8, "G500")
        if not geo.loaded:
            geo.setframe_active = bool(int(self.machine.md_value("MD24006", None, 1) or 0) & 1)
            geo.frames = geo.frames.with_base(self._base_frame(modal, geo.setframe_active))
            geo.frames = geo.frames.with_settable(code, self._settable_frame(code, modal))
            geo.feed_type = modal.gcodes.get(15, "G94")
            geo.loaded = True
            # After RESET the WCS position follows from the machine position and the new frames.
            self._resync(modal, geo, dict(modal.position_mcs))
        elif geo.frames.settable_code != code:
            geo.frames = geo.frames.with_settable(code, self._settable_frame(code, modal))
        return geo

    def select_settable(self, modal: Any, geo: GeometryState) -> None:
        """G500/G54… written in the block: (re)activate the settable frame from the NC data."""
        code = modal.gcodes.get(8, "G500")
        geo.setframe_active = True  # G500/G54… activate the system frames of the data (002 L30660-30664)
        geo.frames = geo.frames.with_base(self._base_frame(modal, True))
        geo.frames = geo.frames.with_settable(code, self._settable_frame(code, modal))

    def activate_stored_frames(self, modal: Any, position_mcs: Mapping[str, float]) -> None:
        """A work offset or ``$P_SETFR`` changed by an operator action (Set WO, PRESET, measuring
        in JOG): take the stored frames into the active chain at once; the WCS follows from the MCS."""
        geo = self.state(modal)
        self.select_settable(modal, geo)
        self._resync(modal, geo, position_mcs)

    def _settable_frame(self, code: str, modal: Any) -> Frame:
        offset = self.data.settable_frames.get(code)
        if offset is None:
            return Frame(geometry_axes=self.geo_axes)
        return frame_from_work_offset(offset, self.geo_axes, self.units(modal).basic_mm)

    def _base_frame(self, modal: Any, with_setframe: bool) -> Frame:
        """The basic frame, with the PRESET/scratching system frame ``$P_SETFR`` outside it when
        active: both sit between the BCS and the settable frame and G153/SUPA suppress both
        (002 L28330-28345). ``$P_SETFR`` holds translations only, so it adds to the basic
        frame's translation (applied after its rotation)."""
        offset: WorkOffset = self.data.base_frame
        setframe = getattr(self.data, "setframe", None)
        if with_setframe and setframe is not None and any(setframe.trans.values()):
            trans = dict(offset.trans)
            for axis, value in setframe.trans.items():
                trans[axis] = trans.get(axis, 0.0) + float(value)
            offset = WorkOffset(trans=trans, fine=dict(offset.fine), rot=dict(offset.rot),
                                scale=dict(offset.scale), mirror=dict(offset.mirror))
        return frame_from_work_offset(offset, self.geo_axes, self.units(modal).basic_mm)

    def units(self, modal: Any) -> UnitSystem:
        """The active inch/metric code (G group 13) against the basic system."""
        key = (modal.gcodes.get(13, "G71"), self.basic_metric)
        found = _UNIT_SYSTEMS.get(key)
        if found is None:
            found = _UNIT_SYSTEMS[key] = UnitSystem(key[0], basic_metric=key[1])
        return found

    def plane(self, modal: Any) -> Plane:
        """The active working plane (G group 6)."""
        return plane(modal.gcodes.get(6, "G17"), self.geo_axes)

    # ================================================================ unit helpers
    def _is_length(self, axis: str) -> bool:
        return self.kinds.get(axis, "linear") == "linear"

    def _diameter(self, axis: str, modal: Any) -> bool:
        """The transverse axis is displayed in diameter (DIAMON, DIAM90: 002 L32637-32648)."""
        return axis in self.diameter_axes and modal.gcodes.get(29) in ("DIAMON", "DIAM90")

    def to_mm(self, axis: str, value: float, modal: Any, units: UnitSystem, incremental: bool = False) -> float:
        """A programmed axis value in internal units (mm radius, or degrees).

        The transverse axis takes diameters under DIAMON, and under DIAM90 for absolute
        values only (incremental ones are radii) (002 L32558-32565).
        """
        if not self._is_length(axis):
            return float(value)
        out = float(value) * units.position_mm
        code = modal.gcodes.get(29)
        diameter = axis in self.diameter_axes and (code == "DIAMON" or (code == "DIAM90" and not incremental))
        return out / 2.0 if diameter else out

    def _frame_mm(self, axis: str, value: float, units: UnitSystem) -> float:
        """A frame component in mm: always a radius on the transverse axis (002 L32672-32684)."""
        return float(value) * units.position_mm if self._is_length(axis) else float(value)

    def from_mm(self, axis: str, value: float, modal: Any, units: UnitSystem) -> float:
        """An internal value back in programmed units (WCS display)."""
        if not self._is_length(axis):
            return round_position(value)
        out = float(value) / units.position_mm
        return round_position(out * 2.0 if self._diameter(axis, modal) else out)

    def wcs_view(self, geo: GeometryState, modal: Any) -> dict[str, float]:
        """The programmed WCS position in program units, per path axis."""
        return self._display(geo.wcs_mm, modal.gcodes, self.units(modal))

    def shared_gcodes(self, gcodes: Mapping[int, str]) -> Mapping[int, str]:
        """The G-code table for a motion: a copy of ``gcodes``, or one of the last
        :data:`SHARED_GCODE_TABLES` copies equal to it, so motions share tables (a motion's table
        is read only; a copy per motion cost ~2 KB, 200 MB for 100,000 motions). Several are
        kept because CAM code alternates G1, G2 and G3, which changes group 1 from block to block."""
        copies = self._gcodes_copies
        for table in copies:
            if table == gcodes:
                return table
        table = dict(gcodes)
        copies.insert(0, table)
        del copies[SHARED_GCODE_TABLES:]
        return table

    def cartesian_xyz(self) -> bool:
        """True when X, Y and Z are the geometry axes, all of them linear path axes."""
        return self.geo_axes == ("X", "Y", "Z") and all(
            a in self.path_axes and self._is_length(a) for a in self.geo_axes)

    def _display(self, values_mm: Mapping[str, float], gcodes: Mapping[int, str],
                 units: UnitSystem) -> dict[str, float]:
        """:meth:`from_mm` of every path axis (0 where ``values_mm`` has none), the same operations."""
        code = gcodes.get(29)
        table = self._display_axes
        axes = table.get(code)
        if axes is None:  # (axis, is a length, shown as a diameter) per path axis
            diameter = code in ("DIAMON", "DIAM90")
            axes = table[code] = tuple((a, self._is_length(a), diameter and a in self.diameter_axes)
                                       for a in self.path_axes)
        position_mm = units.position_mm
        out: dict[str, float] = {}
        for axis, length, doubled in axes:
            value = values_mm.get(axis, 0.0)
            if not length:
                out[axis] = round_position(value)
                continue
            value = float(value) / position_mm
            out[axis] = round_position(value * 2.0 if doubled else value)
        return out

    # ================================================================ tool
    def tool_vector(self, modal: Any) -> dict[str, float]:
        """Tool length vector (mm) of the active T/D in the active plane.

        A D of a tool that has cutting-edge data but not this edge is alarm
        17180; a tool without any data counts as a tool without offsets.
        The vector is kept per input (the edge's type and lengths, plane, setting data,
        units): every motion block asks for it.
        """
        return dict(self._tool_lengths(modal))

    def _tool_lengths(self, modal: Any) -> Mapping[str, float]:
        """:meth:`tool_vector` as kept (shared: read it, never change it)."""
        tool, edge = int(modal.tool), int(modal.edge)
        if tool == 0 or edge == 0:
            return self._no_tool
        found = self.data.edge(tool, edge)
        if found is None:
            if not any(t == tool for t, _ in self.data.tools):
                return self._no_tool
            found = resolve_edge(self.data, tool, edge)  # alarm 17180: the tool has no such edge
            assert found is not None
        sd = self.data.setting_data
        plane_code = modal.gcodes.get(6, "G17")
        length_const = int(sd.get("SD42940", 0) or 0)
        length_type = int(sd.get("SD42950", 0) or 0)
        wear_sign = active_wear_sign(modal, sd)
        data_mm = self.units(modal).data_mm
        params = found.params
        key = (plane_code, length_const, length_type, wear_sign, data_mm, self.geo_axes,
               tuple(map(params.get, _LENGTH_PARAMS, _LENGTH_DEFAULTS)))
        last_key, last_vector = self._tool_vector_last
        if key == last_key:  # every motion block asks: an equal tuple, compared without hashing
            return last_vector
        cache = self._tool_vectors
        vector = cache.get(key)
        if vector is None:
            if len(cache) > 256:
                cache.clear()
            vector = cache[key] = length_offset(found, plane_code, self.geo_axes, length_const=length_const,
                                                length_type=length_type, wear_sign=wear_sign, data_mm=data_mm)
        self._tool_vector_last = (key, vector)
        return vector

    def wear_sign(self) -> int:
        """SD42930 now (taken over by the next edge selection)."""
        return active_wear_sign(None, self.data.setting_data)

    # ================================================================ frames / pole
    def frame_block(self, words: Any, modal: Any, geo: GeometryState) -> list[canon.Motion]:
        """Execute a G group 3 instruction; returns motions flushed ahead of it."""
        code = words.gcodes.get(3)
        if code in ("G58", "G59"):  # 002 L28600-28606
            if not self.frame_add_components:
                raise NcAlarmError(ALARM_FRAME_INSTRUCTION, code)
            if not self.frame_fine_configured:
                raise NcAlarmError(ALARM_FINE_NOT_CONFIGURED, code)
        flushed = self.flush(modal)
        units = self.units(modal)
        values = {a: self._frame_mm(a, v, units) for a, (v, _mode) in words.axes.items()}
        angles = {a: float(v) for a, (v, _mode) in words.axes.items()}
        frames = geo.frames
        prog = frames.programmable
        geo_axes = self.geo_axes
        if code == "TRANS":
            prog = Frame.ctrans(values, geo_axes)
        elif code == "ATRANS":
            prog = prog.atrans(values)
        elif code in ("ROT", "AROT"):
            base = Frame(geometry_axes=geo_axes) if code == "ROT" else prog
            if "RPL" in words.words:
                prog = base.arot_plane(self.plane(modal), float(words.words["RPL"]))
            else:
                prog = base.arot(angles)
        elif code == "SCALE":
            prog = Frame.cscale(angles, geo_axes)
        elif code == "ASCALE":
            prog = prog.ascale(angles)
        elif code == "MIRROR":
            prog = Frame.cmirror(angles.keys(), geo_axes)
        elif code == "AMIRROR":
            prog = prog.amirror(angles, toggle=self.mirror_toggle)
        elif code == "G58":
            prog = prog.g58(values)
        elif code == "G59":
            prog = prog.g59(values)
        elif code in ("G110", "G111", "G112"):
            self._pole(code, words, modal, geo, units)
            return flushed
        elif code in ("G25", "G26"):
            self._working_area(code, values)
            return flushed
        else:
            return flushed
        geo.frames = frames.with_programmable(prog)
        return flushed

    def _working_area(self, code: str, values: Mapping[str, float]) -> None:
        """``G25``/``G26``: lower/upper working-area limit per axis (machine coordinates).

        Written to SD43430 WORKAREA_LIMIT_MINUS / SD43420 WORKAREA_LIMIT_PLUS; they act
        where SD43410/SD43400 enable them (WALIMON).
        """
        key = "SD43430" if code == "G25" else "SD43420"
        table = self.data.setting_data.get(key)
        table = dict(table) if isinstance(table, Mapping) else {}
        table.update({axis: float(v) for axis, v in values.items()})
        self.data.setting_data[key] = table

    def _pole(self, code: str, words: Any, modal: Any, geo: GeometryState, units: UnitSystem) -> None:
        pl = self.plane(modal)
        a, o = pl.abscissa, pl.ordinate
        last = (geo.wcs_mm.get(a, 0.0), geo.wcs_mm.get(o, 0.0))
        if "RP" in words.words or "AP" in words.words:
            rp = float(words.words.get("RP", 0.0)) * units.position_mm
            ap = float(words.words.get("AP", 0.0))
            geo.polar = geo.polar.define_pole(code, last, polar=(rp, ap))
        else:
            axes = {ax: self.to_mm(ax, v, modal, units) for ax, (v, _m) in words.axes.items()}
            geo.polar = geo.polar.define_pole(code, last, axes=(axes.get(a, 0.0), axes.get(o, 0.0)))

    # ================================================================ motion
    def has_path_words(self, words: Any, modal: Any) -> bool:
        """True when the block commands a path motion (axes, polar values, or circle data)."""
        w = words.words
        if words.axes or "RP" in w or "AP" in w:
            return True
        kind = modal.gcodes.get(1, "G1")
        if kind in ("G2", "G3"):
            return any(k in w for k in ("I", "J", "K", "CR", "AR", "TURN"))
        if kind == "CIP":
            return any(k in w for k in ("I1", "J1", "K1"))
        return False

    def motion(self, words: Any, modal: Any, geo: GeometryState, feed: dict[str, Any]) -> list[canon.Motion]:
        """Path motion of the block (possibly several segments, possibly held back).

        ``feed`` holds ``feed`` (programmed F or None), ``feed_mm_min`` (or None)
        and ``inverse_time`` (G93: F is 1/min, the mm/min value follows from the length).
        """
        kind = modal.gcodes.get(1, "G1")
        if kind not in PATH_KINDS:
            raise NcAlarmError(NAME_NOT_DEFINED, kind)
        units = self.units(modal)
        suppress = words.gcodes.get(9)
        if suppress in SUPPRESSION_CODES:
            return self.flush(modal) + [self._suppressed_move(kind, words, modal, geo, units, suppress, feed)]
        if kind in LINE_KINDS and self.separable_lines:
            line = self._separable_line(kind, words, modal, geo, feed, units, modal.gcodes.get(6, "G17"))
            if line is not None:
                return [line]
        elif kind in CIRCLE_KINDS and self.separable_lines:
            arc = self._separable_arc(kind, words, modal, geo, feed, units)
            if arc is not None:
                return [arc]
        pl = self.plane(modal)
        start = dict(geo.wcs_mm)
        end, programmed = self._targets(words, modal, geo, units)
        if "ANG" in words.words:
            programmed |= self._angle_end(kind, float(words.words["ANG"]), words, pl, start, end)
        if kind in ARC_KINDS:
            element: LineElement | Arc = self._arc(kind, words, modal, geo, units, pl, start, end)
            programmed |= {pl.abscissa, pl.ordinate}
            element_end = element.end
            for i, axis in enumerate(self.geo_axes):
                end[axis] = element_end[i]
        else:
            element = LineElement(self._vec(start), self._vec(end))
        lead = None
        if kind in LEAD_KINDS:
            lead = self._thread_lead(words, geo, units)
            self._check_thread_frame(words, geo.frames.transform(), start, end)
        context = {
            "kind": kind, "source": words.source, "plane": pl.code, "programmed": programmed,
            "transform": geo.frames.transform(), "tool": self._tool_lengths(modal),
            "feed": feed, "lead": lead, "gcodes": self.shared_gcodes(modal.gcodes),
            "thread_start": self._thread_start_deg() if kind == "G33" else None,
            "exact": ends_in_exact_stop(words, modal.gcodes),
            "window": modal.gcodes.get(12, "G601"), "units": units,
            "end_other": {a: end[a] for a in end if a not in self.geo_axes},
        }
        start_mcs = dict(modal.position_mcs)
        geo.wcs_mm = end
        held_before = geo.pending is not None
        position_wcs = self.wcs_view(geo, modal)  # the element's end as shown: emit's too when it goes out as is
        out = path_aids.with_contour_aids(self, words, geo, pl, element, context, start_mcs, units, position_wcs)
        geo.tangent_at_end_of(element)
        modal.position_wcs = position_wcs
        if not held_before and geo.pending is None and len(out) == 1:
            modal.position_mcs = dict(out[0].end_mcs)  # the element itself went out: its end, computed once
        else:
            modal.position_mcs = self._mcs_of(self._vec(end), context, start_mcs, self._kept_axes(context))
        return out

    # ---------------------------------------------------------------- lines on a separable frame
    def _separable_start(self, kind: str, words: Any, modal: Any, geo: GeometryState) -> tuple[bool, Transform] | None:
        """What a separable line or circle starts from: whether it ends in an exact stop, and the
        frame's transform; None when the block needs the general path (a pending element,
        rounding, contour aids, a changed geometry axis set, a G641 corner, a frame coupling axes)."""
        if geo.pending is not None or geo.rndm_mm or self.geo_axes != GEOMETRY_AXES_DEFAULT \
                or not LINE_AID_WORDS.isdisjoint(words.words):
            return None
        exact = ends_in_exact_stop(words, modal.gcodes)
        if rounding_distance_mm(kind, exact, modal.gcodes, geo) > 0.0:
            return None  # G641 holds the block back for its corner
        transform = geo.frames.transform()
        if transform.axis_affine() is None:
            return None
        return exact, transform

    def _separable_line(self, kind: str, words: Any, modal: Any, geo: GeometryState, feed: dict[str, Any],
                        units: UnitSystem, plane_code: str) -> canon.Motion | None:
        """The motion of a G0/G1 line when nothing but the line itself can happen: no contour
        aid (chamfer, rounding, G641 corner, ``ANG=``), no polar words, only geometry axes
        programmed, and a frame that maps every geometry axis on its own
        (:meth:`Transform.axis_affine`). Then :meth:`motion` would build a line element, map
        its end through the frame and emit it; here the same operations in the same order run
        on 3-tuples (:func:`machine_mm`, :meth:`_display`, :func:`line_tangent`), and
        the modal state is updated as :meth:`motion` updates it. None when the block is not
        such a line (nothing changed: :meth:`motion` builds it).
        """
        separable = self._separable_start(kind, words, modal, geo)
        if separable is None:
            return None
        gcodes = modal.gcodes
        exact, transform = separable
        geo_axes = self.geo_axes
        programmed = words.axes
        for axis, (_value, mode) in programmed.items():
            if axis not in geo_axes or mode in ROTARY_MODES:
                return None
        end, _programmed = self._targets(words, modal, geo, units)
        start, stop = self._vec(geo.wcs_mm), self._vec(end)
        if not math.isfinite(stop[0] + stop[1] + stop[2]):
            return None  # the frame maps it with numpy's matrix product
        tool = self._tool_lengths(modal)
        frame = self._line_frame(transform, tool)
        assert frame is not None  # the frame maps every geometry axis on its own (checked above)
        start_mcs = modal.position_mcs
        end_mcs: dict[str, float] = {}
        kept: list[str] = []
        for axis, i, scale, offset, tool_mm in frame.axes:
            if i >= 0:
                if axis in programmed or axis not in start_mcs:
                    end_mcs[axis] = round_position(machine_mm(stop[i], scale, offset, tool_mm))
                else:
                    end_mcs[axis] = round_position(start_mcs[axis])
            elif axis in start_mcs:
                end_mcs[axis] = round_position(start_mcs[axis])
            else:
                bcs = scale * float(end[axis]) + offset if axis in end else 0.0
                end_mcs[axis] = round_position(bcs + tool_mm)
            if axis not in programmed:
                kept.append(axis)
        position_wcs = self._display(end, gcodes, units)
        end_wcs = dict(position_wcs)
        if kept:
            self._report_actual(end_wcs, end_mcs, kept, (frame.scales, frame.offsets), transform, tool, modal,
                                units)
        rapid = kind == "G0"
        motion = canon.Motion(
            kind=kind, source=words.source, plane=plane_code, end_wcs=end_wcs, end_mcs=end_mcs,
            start_mcs=dict(start_mcs),
            feed=None if rapid else feed.get("feed"),
            feed_mm_min=None if rapid else self._feed_value(feed, math.dist(start, stop)),
            feed_mm_rev=None if rapid else feed.get("feed_mm_rev"),
            accel_pct=feed.get("accel_pct"), exact_stop=exact, exact_stop_window=gcodes.get(12, "G601"),
            gcodes=self.shared_gcodes(gcodes),
        )
        geo.wcs_mm = end
        geo.tangent = line_tangent(start, stop)
        modal.position_wcs = position_wcs
        modal.position_mcs = dict(end_mcs)
        return motion

    def _separable_arc(self, kind: str, words: Any, modal: Any, geo: GeometryState, feed: dict[str, Any],
                       units: UnitSystem) -> canon.Motion | None:
        """The motion of a G2/G3 circle when nothing but the circle itself can happen (the
        conditions of :meth:`_separable_line`, and both the end and the centre finite). Then
        :meth:`motion` would emit the arc unchanged through :func:`path_aids.with_contour_aids`
        and :meth:`emit`; here the same operations in the same order without the block's
        context: the end and the centre mapped by :func:`_mcs_on_frame`, the axes neither
        programmed nor in the plane kept (the frame couples no axes). The modal state is
        updated as :meth:`motion` updates it. None when the block is not such a circle (nothing
        changed: :meth:`motion` builds it); an alarm of the circle as :meth:`motion` raises it.
        """
        separable = self._separable_start(kind, words, modal, geo)
        if separable is None or separable[1].geometry_axes != GEOMETRY_AXES_DEFAULT:
            return None
        gcodes = modal.gcodes
        exact, transform = separable
        pl = self.plane(modal)
        end, programmed = self._targets(words, modal, geo, units)
        element = self._arc(kind, words, modal, geo, units, pl, geo.wcs_mm, end)  # _arc reads the start
        assert isinstance(element, Arc)  # G2/G3 without a pole
        point, centre = element.end, element.center
        if not (math.isfinite(point[0] + point[1] + point[2]) and math.isfinite(centre[0] + centre[1] + centre[2])):
            return None  # numpy's matrix product maps it (:meth:`_mcs_of`)
        programmed |= {pl.abscissa, pl.ordinate}
        for i, axis in enumerate(self.geo_axes):
            end[axis] = point[i]
        tool = self._tool_lengths(modal)
        shared = self.shared_gcodes(gcodes)
        other = {a: end[a] for a in end if a not in self.geo_axes}
        start_mcs = modal.position_mcs
        position_wcs = self._display(end, gcodes, units)
        kept = tuple(a for a in self.path_axes if a not in programmed)
        frame = self._line_frame(transform, tool)
        assert frame is not None  # the frame maps every geometry axis on its own (checked above)
        end_mcs = _mcs_on_frame(point, frame, other, start_mcs, kept)
        centre_full = {"X": centre[0], "Y": centre[1], "Z": centre[2]}
        centre_full.update(other)
        center_wcs = self._display(centre_full, gcodes, units)
        center_mcs = _mcs_on_frame(centre, frame, other, start_mcs, ())
        applicate = pl.applicate
        if applicate in self.path_axes and applicate not in programmed:
            center_mcs[applicate] = start_mcs.get(applicate, center_mcs[applicate])
        normal = _map_normal(transform, element.axis)
        end_wcs = dict(position_wcs)
        if kept:
            self._report_actual(end_wcs, end_mcs, kept, (frame.scales, frame.offsets), transform, tool, modal,
                                units)
        motion = canon.Motion(
            kind=kind, source=words.source, plane=pl.code, end_wcs=end_wcs, end_mcs=end_mcs,
            start_mcs=dict(start_mcs), center_wcs=center_wcs, center_mcs=center_mcs, turns=element.turns,
            feed=feed.get("feed"), feed_mm_min=self._feed_value(feed, element.length()),
            feed_mm_rev=feed.get("feed_mm_rev"), accel_pct=feed.get("accel_pct"), exact_stop=exact,
            exact_stop_window=gcodes.get(12, "G601"), gcodes=shared, arc_normal_mcs=normal,
        )
        geo.wcs_mm = end
        geo.tangent_at_end_of(element)
        modal.position_wcs = position_wcs
        modal.position_mcs = dict(end_mcs)
        return motion

    def _line_frame(self, transform: Transform, tool: Mapping[str, float]) -> LineFrame | None:
        """:func:`line_frame` of ``transform`` and ``tool``, kept for the last pair (both are
        immutable and stay the same objects while the frames and the tool stay)."""
        kept_transform, kept_tool, frame = self._line_frame_kept
        if kept_transform is not transform or kept_tool is not tool:
            frame = line_frame(transform, tool, self.path_axes, self.geo_axes)
            self._line_frame_kept = (transform, tool, frame)
        return frame

    # ---------------------------------------------------------------- targets
    def _vec(self, point: Mapping[str, float]) -> tuple[float, float, float]:
        return (float(point.get("X", 0.0)), float(point.get("Y", 0.0)), float(point.get("Z", 0.0)))

    def _targets(self, words: Any, modal: Any, geo: GeometryState, units: UnitSystem):
        absolute = modal.gcodes.get(14, "G90") == "G90"
        end = dict(geo.wcs_mm)
        for axis in self.geo_axes:
            end.setdefault(axis, 0.0)
        programmed: set[str] = set()
        for axis, (value, mode) in words.axes.items():
            incremental = mode == "IC" or (mode is None and not absolute)
            v = self.to_mm(axis, value, modal, units, incremental=incremental and mode not in ROTARY_MODES)
            if mode in ROTARY_MODES:
                end[axis] = self._rotary_target(axis, end.get(axis, 0.0), v, mode)
            else:
                end[axis] = end.get(axis, 0.0) + v if incremental else v
            programmed.add(axis)
        w = words.words
        if ("RP" in w or "AP" in w) and modal.gcodes.get(1) != "CIP":
            modes = getattr(words, "word_modes", {})
            polar = geo.polar
            rp, ap = polar.radius_mm, polar.angle_deg
            if "RP" in w:
                v = float(w["RP"]) * units.position_mm
                inc = modes.get("RP") == "IC" or (modes.get("RP") is None and not absolute)
                rp = rp + v if inc else v
            if "AP" in w:
                v = float(w["AP"])
                inc = modes.get("AP") == "IC" or (modes.get("AP") is None and not absolute)
                ap = ap + v if inc else v
            geo.polar = polar.with_values(radius_mm=rp, angle_deg=ap)
            target = geo.polar.target()
            pl = self.plane(modal)
            end[pl.abscissa], end[pl.ordinate] = target
            programmed |= {pl.abscissa, pl.ordinate}
        return end, programmed

    def _angle_end(self, kind: str, angle_deg: float, words: Any, pl: Plane,
                   start: Mapping[str, float], end: dict[str, float]) -> set[str]:
        """Contour definition "straight line with angle" (000 L4105-4160; Siemens ``ANG=``):
        one plane coordinate and the angle to the abscissa fix the end point; the other
        coordinate is computed into ``end``. Returns the plane axes now programmed.

        The two- and three-line forms (``ANG`` without a plane coordinate, then a block with
        both and its own ``ANG``) are joined by the motion builder (:meth:`two_line_corner`);
        here both coordinates with ``ANG`` are 12550. A coordinate the angle cannot reach
        (parallel, or behind the start) is 12560.
        """
        a, o = pl.abscissa, pl.ordinate
        given = [axis for axis in (a, o) if axis in words.axes]
        if kind not in ("G0", "G1") or len(given) != 1:
            raise NcAlarmError(ALARM_NOT_AVAILABLE, "ANG")
        direction = (math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)))
        index = 0 if given[0] == a else 1
        other = o if index == 0 else a
        along = direction[index]
        delta = end[given[0]] - start.get(given[0], 0.0)
        if abs(along) < 1e-12 or delta / along < -1e-9:
            raise NcAlarmError(ALARM_VALUE_OUTSIDE, "ANG")
        length = delta / along
        end[other] = start.get(other, 0.0) + length * direction[1 - index]
        return {a, o}

    def two_line_corner(self, first_angle_deg: float, words: Any, modal: Any, geo: GeometryState) -> dict[str, float]:
        """The corner of a two-line contour definition (000 L4133-4155): the line from the
        current point at ``first_angle_deg`` meets the line that ends at this block's plane
        point at its ``ANG=``. Returns the corner in program units (absolute WCS).

        Raises:
            NcAlarmError: 12560 when the lines are parallel or meet behind the start or
                beyond the end (no valid intermediate point, 000 L4073).
        """
        units = self.units(modal)
        pl = self.plane(modal)
        a, o = pl.abscissa, pl.ordinate
        start = dict(geo.wcs_mm)
        end, _ = self._targets(words, modal, geo, units)
        first = (math.cos(math.radians(first_angle_deg)), math.sin(math.radians(first_angle_deg)))
        second_deg = float(words.words["ANG"])
        second = (math.cos(math.radians(second_deg)), math.sin(math.radians(second_deg)))
        span = (end[a] - start.get(a, 0.0), end[o] - start.get(o, 0.0))
        det = first[0] * second[1] - second[0] * first[1]
        if abs(det) < 1e-12:
            raise NcAlarmError(ALARM_VALUE_OUTSIDE, "ANG")
        along_first = (span[0] * second[1] - second[0] * span[1]) / det
        along_second = (first[0] * span[1] - first[1] * span[0]) / det
        if along_first < -1e-9 or along_second < -1e-9:
            raise NcAlarmError(ALARM_VALUE_OUTSIDE, "ANG")
        corner_mm = {a: start.get(a, 0.0) + along_first * first[0], o: start.get(o, 0.0) + along_first * first[1]}
        return {axis: self.from_mm(axis, value, modal, units) for axis, value in corner_mm.items()}

    def _rotary_target(self, axis: str, current: float, value: float, mode: str) -> float:
        """``DC`` (shortest way), ``ACP`` (positive), ``ACN`` (negative) to an absolute angle.

        Only rotary axes; the angle is taken within one revolution (0 … < 360°).
        """
        if self._is_length(axis):
            raise NcAlarmError(ALARM_DC_NOT_POSSIBLE if mode == "DC" else ALARM_ACP_NOT_POSSIBLE, axis)
        if mode != "DC" and not 0.0 <= value < 360.0:
            raise NcAlarmError(ALARM_MODULO_POSITION, axis)
        delta = (value % 360.0 - current % 360.0) % 360.0
        if mode == "DC" and delta > 180.0:
            delta -= 360.0
        elif mode == "ACN" and delta > 0.0:
            delta -= 360.0
        return current + delta

    # ---------------------------------------------------------------- circles
    def _arc(self, kind: str, words: Any, modal: Any, geo: GeometryState, units: UnitSystem,
             pl: Plane, start: dict[str, float], end: dict[str, float]) -> Arc | LineElement:
        w = words.words
        modes = getattr(words, "word_modes", {})
        s, e = self._vec(start), self._vec(end)
        turns_value = w.get("TURN", 0.0)
        if turns_value != int(turns_value):
            raise NcAlarmError(circles.ALARM_CIRCLE_TURNS)
        turns = int(turns_value)
        if kind == "CIP":
            absolute = modal.gcodes.get(14, "G90") == "G90"
            mid = list(s)
            for i, letter in enumerate(INTERP_LETTERS):
                key = f"{letter}1"
                if key in w:
                    v = float(w[key]) * units.position_mm
                    inc = modes.get(key) == "IC" or (modes.get(key) is None and not absolute)
                    mid[i] = s[i] + v if inc else v
            arc = circles.arc_through_point(s, (mid[0], mid[1], mid[2]), e, turns)
            return LineElement(s, e) if arc is None else arc
        if kind == "CT":
            if geo.tangent is None:
                raise NcAlarmError(circles.ALARM_TANGENTIAL_CIRCLE)
            return circles.arc_tangential(pl, s, e, geo.tangent, turns)
        clockwise = kind == "G2"
        if "RP" in w or "AP" in w:  # circle about the pole
            pole = geo.polar.effective_pole
            return circles.arc_from_center(pl, s, e, pole, clockwise, turns, self.tolerance)
        if "CR" in w:
            return circles.arc_from_radius(pl, s, e, float(w["CR"]) * units.position_mm, clockwise,
                                           turns, self.tolerance)
        centre_given = any(letter in w for letter in INTERP_LETTERS)
        centre = self._centre(pl, s, w, modes, units, modal)
        if "AR" in w:
            if centre_given:
                end_app = pl.to_plane(e)[2]
                return circles.arc_from_center_and_angle(pl, s, centre, float(w["AR"]), clockwise,
                                                         end_app, turns)
            return circles.arc_from_end_and_angle(pl, s, e, float(w["AR"]), clockwise, turns)
        if not centre_given:
            raise NcAlarmError(ALARM_CIRCLE_NOT_DETERMINED)
        return circles.arc_from_center(pl, s, e, centre, clockwise, turns, self.tolerance)

    def _centre(self, pl: Plane, s: tuple[float, float, float], w: Mapping[str, float],
                modes: Mapping[str, str], units: UnitSystem, modal: Any) -> tuple[float, float]:
        out = []
        for index in pl.indices[:2]:
            letter = INTERP_LETTERS[index]
            if letter in w:
                v = float(w[letter]) * units.position_mm
                if modes.get(letter) == "AC" and self._diameter(self.geo_axes[index], modal):
                    v /= 2.0  # an absolute centre is a diameter on the transverse axis (002 L32643-32646)
                out.append(v if modes.get(letter) == "AC" else s[index] + v)
            else:
                out.append(s[index])
        return (out[0], out[1])

    def _thread_lead(self, words: Any, geo: GeometryState, units: UnitSystem) -> float:
        leads = [float(words.words[k]) for k in INTERP_LETTERS if k in words.words]
        if leads:
            geo.thread_lead_mm = abs(leads[-1]) * units.position_mm
        if not geo.thread_lead_mm:
            raise NcAlarmError(ALARM_THREAD_LEAD_ZERO)
        return geo.thread_lead_mm

    def _thread_start_deg(self) -> float:
        """The start angle of a thread: SD42000, written by ``SF=`` (002 L26538, L55683-55687)."""
        return float(self.data.setting_data.get(SD_THREAD_START_ANGLE, 0.0) or 0.0)

    def _check_thread_frame(self, words: Any, transform: Transform, start: Mapping[str, float],
                            end: Mapping[str, float]) -> None:
        """10607 when a frame rotation tilts the thread axis (002 L55706-55711): the axis of the
        lead letter (I/J/K; else the longest move) must keep its direction; MD11410 bit 12
        suppresses the alarm."""
        if int(self.machine.md_value("MD11410", None, 0) or 0) & (1 << 12):
            return
        letters = [i for i, k in enumerate(INTERP_LETTERS) if k in words.words]
        if letters:
            index = letters[-1]
        else:
            moves = [abs(end.get(a, 0.0) - start.get(a, 0.0)) for a in self.geo_axes]
            index = moves.index(max(moves))
        column = np.asarray(transform.matrix)[:3, index]
        length = float(np.linalg.norm(column))
        if length > 0.0 and math.hypot(*(column[i] for i in range(3) if i != index)) > 1e-9 * length:
            raise NcAlarmError(ALARM_THREAD_FRAME)

    # ---------------------------------------------------------------- suppression
    def _suppressed_move(self, kind: str, words: Any, modal: Any, geo: GeometryState,
                         units: UnitSystem, suppress: str, feed: dict[str, Any]) -> canon.Motion:
        if kind not in ("G0", "G1"):
            kind = "G1"
        tool = self.tool_vector(modal)
        full = geo.frames.transform()
        reduced = geo.frames.transform(suppress)
        start_mcs = dict(modal.position_mcs)
        bcs = {a: start_mcs.get(a, 0.0) - tool.get(a, 0.0) for a in self.path_axes}
        for axis in self.geo_axes:
            bcs.setdefault(axis, 0.0)
        point = reduced.inverse().apply(bcs)
        absolute = modal.gcodes.get(14, "G90") == "G90"
        for axis, (value, mode) in words.axes.items():
            incremental = mode == "IC" or (mode is None and not absolute)
            v = self.to_mm(axis, value, modal, units, incremental=incremental)
            point[axis] = point.get(axis, 0.0) + v if incremental else v
        end_bcs = reduced.apply(point)
        end_mcs = dict(start_mcs)
        for axis in words.axes:
            if axis in end_mcs:
                end_mcs[axis] = round_position(end_bcs[axis] + tool.get(axis, 0.0))
        wcs = full.inverse().apply(end_bcs)
        for axis in words.axes:
            geo.wcs_mm[axis] = wcs.get(axis, 0.0)
        modal.position_wcs = self.wcs_view(geo, modal)
        modal.position_mcs = end_mcs
        geo.tangent = None
        length = math.dist([start_mcs.get(a, 0.0) for a in self.path_axes],
                           [end_mcs.get(a, 0.0) for a in self.path_axes])
        return canon.Motion(
            kind=kind, source=words.source, plane=modal.gcodes.get(6, "G17"),
            end_wcs=dict(modal.position_wcs), end_mcs=end_mcs, start_mcs=start_mcs,
            feed=feed.get("feed") if kind != "G0" else None,
            feed_mm_min=self._feed_value(feed, length) if kind != "G0" else None,
            feed_mm_rev=feed.get("feed_mm_rev") if kind != "G0" else None,
            accel_pct=feed.get("accel_pct"),
            exact_stop=True, exact_stop_window=modal.gcodes.get(12, "G601"),
            gcodes=self.shared_gcodes(modal.gcodes),
        )

    # ---------------------------------------------------------------- MCS mapping
    def _mcs_of(self, point: tuple[float, float, float], context: Mapping[str, Any],
                start_mcs: Mapping[str, float], kept: tuple[str, ...]) -> dict[str, float]:
        """MCS of a WCS geometry point; the ``kept`` axes (:meth:`_kept_axes`) stay where they are.

        On a frame that maps every geometry axis on its own (:meth:`Transform.axis_affine`, the
        frame of almost every block) through the factors of :meth:`_line_frame`, as a line on
        such a frame: :func:`machine_mm` is what :meth:`Transform.apply` and the tool's
        addition compute there, without a point dict per call."""
        transform: Transform = context["transform"]
        tool: Mapping[str, float] = context["tool"]
        if self.geo_axes == GEOMETRY_AXES_DEFAULT and transform.geometry_axes == GEOMETRY_AXES_DEFAULT \
                and math.isfinite(point[0] + point[1] + point[2]):
            frame = self._line_frame(transform, tool)
            if frame is not None:
                return _mcs_on_frame(point, frame, context["end_other"], start_mcs, kept)
        full = {"X": point[0], "Y": point[1], "Z": point[2]}
        full.update(context["end_other"])
        bcs = transform.apply(full)
        out = {}
        for axis in self.path_axes:
            value = bcs.get(axis, 0.0) + tool.get(axis, 0.0)
            if axis in kept:
                value = start_mcs.get(axis, value)
            out[axis] = round_position(value)
        return out

    def _kept_axes(self, context: Mapping[str, Any]) -> tuple[str, ...]:
        """Path axes a block leaves where they stand: not programmed, not coupled by a rotation."""
        coupled = couples_axes(context["transform"])
        return tuple(a for a in self.path_axes
                     if a not in context["programmed"] and (a not in self.geo_axes or not coupled))

    def _report_actual(self, end_wcs: dict[str, float], end_mcs: Mapping[str, float], kept: Iterable[str],
                       geo_scales_offsets: tuple[Sequence[float] | np.ndarray, Sequence[float] | np.ndarray],
                       transform: Transform, tool: Mapping[str, float], modal: Any, units: UnitSystem) -> None:
        """Kept axes report where they stand in the active system, not their old programmed value.

        After a zero-offset change an axis the block does not program stays in the machine, so
        its WCS position is the machine position seen through the new frame (what the actual
        value display shows); its programmed position (for incremental moves, SD 42440) is kept.
        Differences below 1e-6 are floating noise of the round trip and leave the value alone.
        A geometry axis is seen through its scale and offset of ``geo_scales_offsets``, any
        other axis through the frame's axial part.
        """
        scales, offsets = geo_scales_offsets
        for axis in kept:
            bcs = float(end_mcs.get(axis, 0.0)) - tool.get(axis, 0.0)
            if axis in self.geo_axes:
                i = self.geo_axes.index(axis)
                wcs_mm = (bcs - offsets[i]) / scales[i]
            else:
                factor, offset = transform.axial.get(axis, (1.0, 0.0))
                wcs_mm = (bcs - offset) / factor
            actual = self.from_mm(axis, wcs_mm, modal, units)  # rounded (round_position is idempotent)
            if abs(actual - end_wcs.get(axis, actual)) > 1e-6:
                end_wcs[axis] = actual

    def _wcs_out(self, point: tuple[float, float, float], context: Mapping[str, Any]) -> dict[str, float]:
        full = {"X": point[0], "Y": point[1], "Z": point[2]}
        full.update(context["end_other"])
        return self._display(full, context["gcodes"], context["units"])

    def _feed_value(self, feed: Mapping[str, Any], length_mm: float) -> float | None:
        if feed.get("inverse_time"):
            f = feed.get("feed") or 0.0
            return max(length_mm, 1e-9) * float(f) * feed.get("override", 1.0)
        return feed.get("feed_mm_min")

    def emit(self, element: LineElement | Arc, context: Mapping[str, Any], start_mcs: Mapping[str, float],
             kind: str | None = None, inserted: bool = False, keep: bool = True,
             shown_end: Mapping[str, float] | None = None) -> canon.Motion:
        """Turn a WCS element into a canonical motion.

        ``shown_end``: the element's end as :meth:`wcs_view` shows it, when the caller has it
        (the block's own element, not trimmed by a corner): the same values ``_wcs_out`` of the
        end computes (the end point's geometry axes and ``end_other`` are the block's end)."""
        kind = kind or context["kind"]
        kept = self._kept_axes(context) if keep and not inserted else ()
        end_mcs = self._mcs_of(element.end, context, start_mcs, kept)
        center_wcs = center_mcs = None
        normal = None
        turns = 0
        if isinstance(element, Arc):
            center_wcs = self._wcs_out(element.center, context)
            centre_point = self._mcs_of(element.center, context, start_mcs, ())
            transform: Transform = context["transform"]
            applicate = plane(context["plane"], self.geo_axes).applicate
            if applicate in self.path_axes and applicate not in context["programmed"] \
                    and not couples_axes(transform):
                centre_point[applicate] = start_mcs.get(applicate, centre_point[applicate])
            center_mcs = centre_point
            normal = _map_normal(transform, element.axis)
            turns = element.turns
            if kind not in ARC_KINDS:
                kind = "G2" if element.clockwise_in(plane(context["plane"], self.geo_axes)) else "G3"
        end_wcs = dict(shown_end) if shown_end is not None else self._wcs_out(element.end, context)
        if kept:
            transform = context["transform"]
            scales_offsets = transform.axis_affine() or (transform.matrix.diagonal(), transform.matrix[:, 3])
            self._report_actual(end_wcs, end_mcs, kept, scales_offsets, transform,
                                context["tool"], SimpleNamespace(gcodes=context["gcodes"]), context["units"])
        length = element.length() if isinstance(element, Arc) else math.dist(element.start, element.end)
        feed = context["feed"]
        rapid = kind == "G0"
        feed_mm_min = None if rapid else self._feed_value(feed, length)
        feed_mm_rev = None if rapid else feed.get("feed_mm_rev")
        if context["lead"] is not None:
            feed_mm_rev = context["lead"]
            if feed.get("per_rev_rpm"):
                feed_mm_min = context["lead"] * float(feed["per_rev_rpm"])
        return canon.Motion(
            kind=kind,
            source=context["source"],
            plane=context["plane"],
            end_wcs=end_wcs,
            end_mcs=end_mcs,
            start_mcs=dict(start_mcs),
            center_wcs=center_wcs,
            center_mcs=center_mcs,
            turns=turns,
            feed=None if rapid else feed.get("feed"),
            feed_mm_min=feed_mm_min,
            feed_mm_rev=feed_mm_rev,
            accel_pct=feed.get("accel_pct"),
            exact_stop=context["exact"],
            exact_stop_window=context["window"],
            lead_mm=context["lead"],
            thread_start_deg=context["thread_start"],
            gcodes=context["gcodes"],
            inserted=inserted,
            arc_normal_mcs=normal,
        )

    # ---------------------------------------------------------------- chamfers and roundings
    def flush(self, modal: Any) -> list[canon.Motion]:
        """Emit an element held back for a chamfer/rounding unchanged (no next element came)."""
        return path_aids.flush(self, modal)

    # ---------------------------------------------------------------- positions
    def wcs_from_mcs(self, modal: Any, position_mcs: Mapping[str, float]) -> dict[str, float]:
        """WCS (program units) of machine positions under the active frames and tool offset."""
        geo = self.state(modal)
        tool = self.tool_vector(modal)
        bcs = {a: float(position_mcs.get(a, 0.0)) - tool.get(a, 0.0) for a in self.path_axes}
        for axis in self.geo_axes:
            bcs.setdefault(axis, 0.0)
        wcs = geo.frames.transform().inverse().apply(bcs)
        units = self.units(modal)
        return {a: self.from_mm(a, wcs.get(a, 0.0), modal, units) for a in self.path_axes}

    def sync_position(self, modal: Any, position_mcs: Mapping[str, float]) -> None:
        """Take over machine positions (after JOG): programmed WCS follows from the MCS."""
        self._resync(modal, self.state(modal), position_mcs)

    def _resync(self, modal: Any, geo: GeometryState, position_mcs: Mapping[str, float]) -> None:
        try:
            tool = self.tool_vector(modal)
        except NcAlarmError:  # a missing edge is reported when it is used, not here
            tool = {}
        bcs = {a: float(position_mcs.get(a, modal.position_mcs.get(a, 0.0))) - tool.get(a, 0.0)
               for a in self.path_axes}
        for axis in self.geo_axes:
            bcs.setdefault(axis, 0.0)
        wcs = geo.frames.transform().inverse().apply(bcs)
        for axis in self.path_axes:
            if axis in position_mcs:
                modal.position_mcs[axis] = float(position_mcs[axis])
                geo.wcs_mm[axis] = wcs.get(axis, 0.0)
        modal.position_wcs = self.wcs_view(geo, modal)


def _mcs_on_frame(point: tuple[float, float, float], frame: LineFrame, other: Mapping[str, float],
                  start_mcs: Mapping[str, float], kept: Iterable[str]) -> dict[str, float]:
    """:meth:`PathBuilder._mcs_of` on a frame that maps every geometry axis on its own: the
    geometry axes from ``point``, the other path axes from ``other`` (their WCS values), the
    ``kept`` axes where they stand."""
    out: dict[str, float] = {}
    for axis, i, scale, offset, tool_mm in frame.axes:
        if i >= 0:
            value = machine_mm(float(point[i]), scale, offset, tool_mm)
        elif axis in other:
            value = (scale * float(other[axis]) + offset) + tool_mm
        else:
            value = 0.0 + tool_mm
        if axis in kept:
            value = start_mcs.get(axis, value)
        out[axis] = round_position(value)
    return out


def couples_axes(transform: Transform) -> bool:
    """True when the linear part of ``transform`` mixes axes (a rotation, not only scaling/mirroring).

    Cached on the transform (immutable: a frame change makes a new one), as every motion asks.
    """
    cached = transform.__dict__.get("_couples_axes")
    if cached is None:
        m = transform.matrix[:3, :3]
        cached = transform.__dict__["_couples_axes"] = bool(np.any(np.abs(m - np.diag(np.diag(m))) > 1e-12))
    return cached


def _map_normal(transform: Transform, axis: tuple[float, float, float]) -> dict[str, float]:
    """Map an arc's turning axis through a linear map (cofactor rule keeps the turning sense).

    Cached per transform and axis: an arc program turns about the same few axes.
    """
    normals = transform.__dict__.setdefault("_arc_normals", {})
    key = (float(axis[0]), float(axis[1]), float(axis[2]))
    found = normals.get(key)
    if found is None:
        a = transform.matrix[:3, :3]
        cof = np.linalg.det(a) * np.linalg.inv(a).T
        n = cof @ np.asarray(axis, dtype=float)
        n = n / float(np.linalg.norm(n))
        names = transform.geometry_axes
        found = normals[key] = {names[i]: round_position(n[i]) for i in range(3)}
    return dict(found)
