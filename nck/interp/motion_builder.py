"""Motion building: the machine words of one block + modal state → canonical commands.

This is the one place that turns axis words and technology words into
:mod:`nck.canon` commands. The interpreter has already

* evaluated every expression of the block,
* validated the G codes (one per group) and applied the *modal* ones to
  ``modal.gcodes`` (so ``modal.gcodes[1]`` is the motion type in force),
* handled program flow and the program-control M functions (M0, M1, M2, M17, M30).

Interface::

    builder = MotionBuilder(machine, data)
    commands = builder.build(words, modal)   # may raise NcAlarmError
    commands = builder.flush(modal)          # before a stop point / program end

``build`` updates ``modal`` (positions, feed, spindle, tool, edge and the
geometry state ``modal.geometry``) in place and returns the commands in output
order (tool, edge, spindle, other aux functions, then motion). The
interpreter snapshots ``modal`` before the block, so an alarm here leaves no
trace. A block with a chamfer or rounding (CHF/CHR/RND/RNDM) holds its motion
back until the next path block is known; :meth:`MotionBuilder.flush` emits it
unchanged when the program stops or ends first.

The path geometry (frames, planes, circles, polar coordinates, tool length,
inch/metric, contour aids) lives in :mod:`nck.geometry.path_builder`; this
module keeps the technology: feed (G93/G94/G95/G96/G97, F, FA), spindle (S,
M3/M4/M5/M19, SPOS, LIMS), tool (T, M6 per MD22550, D) and G4 dwell.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, cast

from nck.alarm_ids import (
    ADDRESS_PROGRAMMED_TWICE, CHAMFER_OR_ROUNDING_NEGATIVE, CHAMFER_OR_ROUNDING_WITHOUT_PATH_MOTION,
    NAME_NOT_DEFINED, POSITION_OUTSIDE_MODULO_RANGE, SYNTAX_ERROR, VALUE_RANGE_EXCEEDED,
)
from nck import canon
from nck.errors import NcAlarmError
from nck.geometry import trc_canon
from nck.geometry.path_builder import ALARM_NOT_AVAILABLE, SD_THREAD_START_ANGLE, PathBuilder
from nck.geometry.path_state import GeometryState
from nck.geometry.rounding_distance import AID
from nck.geometry.tool_length import ALARM_T_NOT_DEFINED
from nck.interp import aux_timing, waiting_outputs
from nck.interp.modal import ModalState
from nck.machine import MachineConfig
from nck.ncdata import NcData

SPINDLE_M = {3: "M3", 4: "M4", 5: "M5", 19: "M19"}
SPINDLE_STATE_M = {state: number for number, state in SPINDLE_M.items()}
ALARM_NO_TRANSVERSE_AXIS = 10870  # G96 without a transverse axis (MD20100)
ALARM_G96_WITHOUT_S = 10900  # first G96 without a cutting speed S
ALARM_LIMS_NEGATIVE = 14820  # negative maximum spindle speed for G96 (LIMS)
ALARM_NO_FEED = 10860
ALARM_G93_WITH_TRC = 10798  # G93 while G41/G42 is active (002 L55402; own number)
ALARM_PATH_VELOCITY = 14800
ALARM_ADDRESS_TOO_OFTEN = 12010  # address type programmed too often
AUX_LIMITS = {"M": 5, "S": 3, "H": 3, "T": 1, "D": 1, "F": 6}  # per block (H2, 828D)
AUX_LIMIT_TOTAL = 10
AUX_WORDS_WITHIN_LIMITS = min(AUX_LIMITS["F"], AUX_LIMIT_TOTAL)
"""A block without M, H and extended words and with at most this many others keeps every limit."""
CIRCLE_WORDS = ("CR", "AR", "TURN")  # radius, opening angle, helix turns: G2/G3 only
CENTRE_WORDS = ("I", "J", "K")  # interpolation parameters: a circle's centre or a thread's lead
LINEAR_KINDS = ("G0", "G1")  # straight lines, where I/J/K mean nothing (001 L3137-3155)
NOT_WAITING_FOR_SPEED = ("G0", "G331", "G332")  # motions that start without the spindle's set speed range
SPINDLE_WORDS = frozenset(("S", "SPOS", "SPOSA", "LIMS"))
"""Words :meth:`MotionBuilder._spindle` reads (with M codes, extended ``S1=`` words, G25/G26 and G96)."""
UNAVAILABLE_WORDS = ("SR", "OVRA")  # retraction on a fast NCK input; override of FA / a spindle


@dataclass
class BlockWords:
    """The evaluated machine words of one block.

    Attributes:
        source: file/line/N of the block.
        gcodes: every G code written in the block, group → code (modal and non-modal).
        axes: axis name → (value, mode) with mode ``"AC"``, ``"IC"`` or None (use G90/G91).
        words: other addresses → value (``F``, ``S``, ``T``, ``D``, ``I``, ``J``, ``K``,
            ``CR``, ``AR``, ``TURN``, ``I1``, ``RP``, ``AP``, ``RPL``, ``CHF``, …);
            axis-indexed ones as ``FA[X]``; extended ones in ``extended``.
        word_modes: ``"AC"``/``"IC"`` written around a non-axis word (``I=AC(10)``, ``AP=IC(30)``).
        extended: (address, extension) → value for ``S1=``, ``T1=``, ``H2=`` words.
        m_codes: the M functions of the block in order, as (extension or None, value).
        h_codes: the H functions, as (extension or None, value).
    """

    source: canon.Source
    gcodes: dict[int, str] = field(default_factory=dict)
    axes: dict[str, tuple[float, str | None]] = field(default_factory=dict)
    words: dict[str, float] = field(default_factory=dict)
    word_modes: dict[str, str] = field(default_factory=dict)
    extended: dict[tuple[str, int], float] = field(default_factory=dict)
    m_codes: list[tuple[int | None, int]] = field(default_factory=list)
    h_codes: list[tuple[int | None, float]] = field(default_factory=list)


class MotionBuilder:
    """Builds the canonical commands of a block (see the module docstring)."""

    def __init__(self, machine: MachineConfig, data: NcData) -> None:
        self.machine = machine
        self.data = data
        self.path_axes = machine.path_axes
        # MD22550 TOOL_CHANGE_MODE from the machine file; the catalogue default is 0 (T changes).
        self.tool_change_with_m6 = bool(machine.md_value("MD22550") or 0)
        default_edge = machine.md_value("MD20270")
        self.default_edge = 1 if default_edge is None else int(default_edge)
        transverse = machine.md_value("MD20100")
        self.transverse_axis = transverse if transverse in self.path_axes else None
        self.spindle_limit_rpm = _first_spindle_value(machine, "MD35100")
        self.path = PathBuilder(machine, data)
        self.aux_timing = aux_timing.AuxOutputTiming(machine)

    # ------------------------------------------------------------------ entry points
    def build(self, words: BlockWords, modal: ModalState) -> list[canon.CanonCommand]:
        """Return the commands of the block and update ``modal``."""
        trc_canon.reset_if_needed(modal)  # radius compensation look-ahead goes with RESET
        geo = self.path.state(modal)
        self._rounding_distances(words, modal, geo)
        pending = geo.pending
        if pending is not None and pending.aid == AID and not self.path.has_path_words(words, modal):
            # G641: a block with outputs but no path motion ends the rounding (implicit stop).
            return _wait_for_spindle_speed(self.release_held(modal) + self._build(words, modal, geo), geo)
        return _wait_for_spindle_speed(self._build(words, modal, geo), geo)

    def simple_path_block(self, words: BlockWords, modal: ModalState) -> list[canon.CanonCommand]:
        """:meth:`build` of a simple motion line (:mod:`nck.interp.simple_step`) in a simple modal
        state (:func:`nck.interp.plain_setup.simple_state`): G codes of groups 1 and 14 only,
        path axes written, no word but I/J/K/CR=/F, nothing held back, waiting or compensated.

        The same stages as :meth:`build` without those that cannot act on such a block (G641
        distances, settable frame, dwell, auxiliary limits, tool, spindle, outputs, contour
        definition, radius compensation's pass-through, measuring); under G96, or without a
        path axis, :meth:`build` itself."""
        geo = modal.geometry
        if not words.axes or modal.gcodes.get(15) == "G96":
            return self.build(words, modal)
        _refuse_words_without_effect(words, modal)
        self.spindle_wait = False
        self._feed_and_type(words, modal, geo)
        own: list[canon.CanonCommand] = list(self.path.motion(words, modal, geo, self._feed_info(modal, geo)))
        if not own and (geo.waiting or self._holding(modal, geo)):
            geo.waiting = geo.waiting + (waiting_outputs.WaitingBlock(words.source, (), True),)
        if geo.spindle_check_due:
            return _wait_for_spindle_speed(own, geo)
        return own

    def _build(self, words: BlockWords, modal: ModalState, geo: GeometryState) -> list[canon.CanonCommand]:
        """The commands of the block once a held-back G641 corner is settled."""
        if 8 in words.gcodes:
            self.path.select_settable(modal, geo)
        if words.gcodes.get(2) == "G4":
            return self._dwell(words, modal)
        _check_aux_limits(words)
        _refuse_words_without_effect(words, modal)
        self.spindle_wait = False
        out = self._build_commands(words, modal, geo)
        if self.spindle_wait:
            out.append(canon.Dwell(words.source, wait_spindle=True, gcodes=dict(modal.gcodes),
                                   feed=modal.feed))
        return out

    def _build_commands(self, words: BlockWords, modal: ModalState, geo: GeometryState) -> list[canon.CanonCommand]:
        """The commands of a block that is not a dwell, outputs placed around the motion."""
        outputs: list[canon.CanonCommand] = []
        src = words.source
        self._feed(words, modal, geo)
        self._thread_start(words)
        self._tool(words, modal, outputs)
        self._spindle(words, modal, geo, outputs)
        for ext, value in words.m_codes:
            if value in SPINDLE_M or value == 6:
                continue
            outputs.append(canon.AuxFunction(src, "M", float(value), ext))
            modal.aux["M"] = str(value)
        for ext, h_value in words.h_codes:
            outputs.append(canon.AuxFunction(src, "H", float(h_value), ext))
            modal.aux["H"] = _fmt(h_value)
        earlier, own = self._geometry(words, modal, geo, src)
        out = self._released(earlier, modal, geo)
        if not own and (geo.waiting or self._holding(modal, geo)):
            # Something before this block is held back: its outputs wait for it.
            moves = self.path.has_path_words(words, modal)
            if moves or outputs:
                waiting = tuple(outputs) if moves else tuple(self._place_outputs(outputs, [], src))
                geo.waiting = geo.waiting + (waiting_outputs.WaitingBlock(src, waiting, moves),)
            return out
        return out + self._place_outputs(outputs, own, src)

    def _holding(self, modal: ModalState, geo: GeometryState) -> bool:
        """True while a programmed motion is held back (chamfer, rounding, contour, compensation)."""
        return geo.pending is not None or geo.contour_first is not None or trc_canon.holding(modal)

    def _released(self, released: list[canon.CanonCommand], modal: ModalState,
                  geo: GeometryState) -> list[canon.CanonCommand]:
        """Motions released now with the outputs waiting for them (:mod:`nck.interp.waiting_outputs`)."""
        if not geo.waiting:
            return released
        out, geo.waiting = waiting_outputs.release(released, geo.waiting, self._place_outputs)
        if geo.waiting and not self._holding(modal, geo):
            out += waiting_outputs.release_all(geo.waiting, self._place_outputs)
            geo.waiting = ()
        return out

    def _geometry(self, words: BlockWords, modal: ModalState, geo: GeometryState,
                  src: canon.Source) -> tuple[list[canon.CanonCommand], list[canon.CanonCommand]]:
        """The path part of a block: (motions of earlier blocks released now, its own motions)."""
        released: list[canon.CanonCommand] = []
        own: list[canon.CanonCommand] = []
        if geo.contour_first is not None:
            words = self._second_of_two_lines(geo.contour_first, words, modal, geo, released, own)
        if words.gcodes.get(3) is not None:
            flushed: list[canon.CanonCommand] = list(self.path.frame_block(words, modal, geo))
            return flushed, []
        if self.path.has_path_words(words, modal):
            earlier, motions = self._path_motion(words, modal, geo)
            return released + earlier, own + motions
        if "ANG" in words.words:  # first block of a two-line contour definition (000 L4133-4155)
            if modal.gcodes.get(1) not in ("G0", "G1"):
                raise NcAlarmError(ALARM_NOT_AVAILABLE, "ANG")
            geo.contour_first = (float(words.words["ANG"]), self.path.plane(modal).code, words)
            return [], []
        if any(k in words.words for k in ("CHF", "CHR", "RND")):
            raise NcAlarmError(CHAMFER_OR_ROUNDING_WITHOUT_PATH_MOTION)
        if "RNDM" in words.words:
            value = float(words.words["RNDM"]) * self.path.units(modal).position_mm
            if value < 0:
                raise NcAlarmError(CHAMFER_OR_ROUNDING_NEGATIVE)
            geo.rndm_mm = value
            return [], []
        released = list(trc_canon.process([], modal, self.path, self.data, self.machine, src))
        return released, []

    def _path_motion(self, words: BlockWords, modal: ModalState, geo: GeometryState
                     ) -> tuple[list[canon.CanonCommand], list[canon.CanonCommand]]:
        """(motions of earlier blocks released now, the block's own motions) of a path block."""
        src = words.source
        feed = self._feed_info(modal, geo)
        motions = self.path.motion(words, modal, geo, feed)
        motions = trc_canon.process(motions, modal, self.path, self.data, self.machine, src)
        earlier, motions = trc_canon.split_released(motions, src)
        measure = "MEAS" if "MEAS" in words.words else "MEAW" if "MEAW" in words.words else None
        if measure is not None:  # the probe measures in this block's motion (nck.kernel_contact)
            motions = [replace(m, measure=measure) if isinstance(m, canon.Motion) else m for m in motions]
        own: list[canon.CanonCommand] = list(motions)
        if modal.gcodes.get(15) == "G96" and motions:
            self._constant_cutting_speed(modal, geo, own, src)
        return list(earlier), own

    def _second_of_two_lines(self, first_block: tuple[float, str, BlockWords], words: BlockWords,
                             modal: ModalState, geo: GeometryState, released: list[canon.CanonCommand],
                             own: list[canon.CanonCommand]) -> BlockWords:
        """The block after ``ANG=`` without a plane axis ends a two-line contour (000 L4133-4155):
        its own ``ANG=`` in the same plane, with both plane axes, one (the other keeps the
        position reached before the contour) or none (000 L4056-4063). The first line runs to
        the corner of the two lines (with its chamfer or rounding; its commands go to
        ``released`` and ``own``); returns this block's words without ``ANG``, a plane axis
        not written taken as that position. Anything else is 12550 (000 L4066, L4075,
        L4079-4080)."""
        angle_deg, plane_code, first = first_block
        geo.contour_first = None
        plane = self.path.plane(modal)
        if ("ANG" not in words.words or plane.code != plane_code
                or modal.gcodes.get(1) not in ("G0", "G1")):
            raise NcAlarmError(ALARM_NOT_AVAILABLE, "ANG")
        reached = {axis: modal.position_wcs.get(axis, 0.0) for axis in (plane.abscissa, plane.ordinate)
                   if axis not in words.axes}
        words = replace(words, axes={**words.axes, **{axis: (v, "AC") for axis, v in reached.items()}})
        corner = self.path.two_line_corner(angle_deg, words, modal, geo)
        first_line = replace(first, axes={**first.axes, **{axis: (v, "AC") for axis, v in corner.items()}},
                             words={k: v for k, v in first.words.items() if k != "ANG"})
        earlier, motions = self._path_motion(first_line, modal, geo)
        released.extend(earlier)
        own.extend(motions)
        return replace(words, words={k: v for k, v in words.words.items() if k != "ANG"})

    def _place_outputs(self, outputs: list[canon.CanonCommand], own: list[canon.CanonCommand],
                       src: canon.Source) -> list[canon.CanonCommand]:
        """Outputs before/during the motion ahead of it, outputs at block end behind it
        (002 L14590-14598). An output before the motion, or any output of a block without
        path motion, first ends the previous block with exact stop (002 L4797-4809); an
        output at block end ends the block's own motion at interpolator end."""
        if not outputs:
            return own
        timings = [self._timing(command) for command in outputs]
        ahead = [c for c, t in zip(outputs, timings) if t != aux_timing.AFTER]
        behind = [c for c, t in zip(outputs, timings) if t == aux_timing.AFTER]
        motions = [i for i, c in enumerate(own) if isinstance(c, canon.Motion)]
        barrier: list[canon.CanonCommand] = []
        if aux_timing.BEFORE in timings or not motions:
            barrier = [canon.ExactStop(src)]
        if behind and motions:
            last = own[motions[-1]]
            assert isinstance(last, canon.Motion)
            if not last.exact_stop:
                own = list(own)
                own[motions[-1]] = replace(last, exact_stop=True, exact_stop_window="G603")
        return ahead + barrier + own + behind

    def _timing(self, command: canon.CanonCommand) -> str:
        """When ``command`` goes out relative to the block's motion (MD22080, MD22035)."""
        timing = self.aux_timing.timing
        if isinstance(command, canon.AuxFunction):
            return timing(command.address, command.extension, command.value)
        if isinstance(command, canon.ToolSelect):
            return timing("T")
        if isinstance(command, canon.EdgeSelect):
            return timing("D")
        if isinstance(command, canon.SpindleCommand):
            state = command.state
            if state in SPINDLE_STATE_M:
                return timing("M", command.spindle, SPINDLE_STATE_M[state])
            if command.speed_rpm is not None:
                return timing("S", command.spindle)
            return aux_timing.DURING  # SPOS: no auxiliary function, the block waits for it
        return aux_timing.DURING

    def release_held(self, modal: ModalState) -> list[canon.CanonCommand]:
        """Emit an element held back for a corner unchanged (radius compensation still applies)."""
        held = list(self.path.flush(modal))
        if held:
            held = trc_canon.process(held, modal, self.path, self.data, self.machine)
        # the path holds back motions only: a list of them is a list of canon commands
        return self._released(cast(list[canon.CanonCommand], held), modal, self.path.state(modal))

    def _rounding_distances(self, words: BlockWords, modal: ModalState, geo: GeometryState) -> None:
        """ADIS= / ADISPOS= (G641 rounding distances, modal; 16500 when negative)."""
        for key, attribute in (("ADIS", "adis_mm"), ("ADISPOS", "adispos_mm")):
            if key in words.words:
                value = float(words.words[key]) * self.path.units(modal).position_mm
                if value < 0:
                    raise NcAlarmError(CHAMFER_OR_ROUNDING_NEGATIVE)
                setattr(geo, attribute, value)

    def flush(self, modal: ModalState) -> list[canon.CanonCommand]:
        """Emit a motion held back for a chamfer/rounding (program stop or end reached).

        A two-line contour still waiting for its second block cannot end here (000 L4075).
        """
        geo = getattr(modal, "geometry", None)
        if geo is not None and geo.contour_first is not None:
            geo.contour_first = None
            raise NcAlarmError(ALARM_NOT_AVAILABLE, "ANG")
        held = list(self.path.flush(modal))
        if held:
            held = trc_canon.process(held, modal, self.path, self.data, self.machine)
        held += trc_canon.flush(modal, self.path, self.data)
        commands = cast(list[canon.CanonCommand], held)
        return self._released(commands, modal, self.path.state(modal)) if geo is not None else commands

    def sync_position(self, modal: ModalState, position_mcs: dict[str, float]) -> None:
        """Take over actual machine positions; the programmed WCS follows via frames and tool."""
        self.path.sync_position(modal, position_mcs)

    def wcs_from_mcs(self, modal: ModalState, position_mcs: dict[str, float]) -> dict[str, float]:
        """WCS (program units) of machine positions under the active frames and tool offset."""
        return self.path.wcs_from_mcs(modal, position_mcs)

    # ------------------------------------------------------------------ dwell
    def _dwell(self, words: BlockWords, modal: ModalState) -> list[canon.CanonCommand]:
        """G4 F… (seconds) or G4 S… (revolutions of the master spindle); F and S stay as they were."""
        held = self.release_held(modal)
        # With radius compensation G4 is a block without plane motion, not a stop of the look-ahead.
        geo = self.path.state(modal)
        own = trc_canon.process([], modal, self.path, self.data, self.machine, words.source)
        out: list[canon.CanonCommand] = held + self._released(cast(list[canon.CanonCommand], own), modal, geo)
        seconds = words.words.get("F")
        revolutions = words.words.get("S")
        if seconds is None and revolutions is None:
            raise NcAlarmError(SYNTAX_ERROR, "G4")
        if (self.path.has_path_words(words, modal) or words.m_codes or words.h_codes
                or "T" in words.words or "D" in words.words):
            # No other functions in a dwell block (001 L6406-6408); they were dropped silently.
            raise NcAlarmError(SYNTAX_ERROR, "G4")
        for value in (seconds, revolutions):
            if value is not None and value < 0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "G4")
        dwell = canon.Dwell(words.source, seconds=seconds, revolutions=revolutions,
                            gcodes=dict(modal.gcodes), feed=modal.feed)
        if geo.waiting or self._holding(modal, geo):  # the dwell comes after the motion held back
            geo.waiting = geo.waiting + (waiting_outputs.WaitingBlock(words.source, (dwell,), False),)
        else:
            out.append(dwell)
        return out

    # ------------------------------------------------------------------ feed
    def _feed(self, words: BlockWords, modal: ModalState, geo: GeometryState) -> None:
        self._feed_and_type(words, modal, geo)
        self._feed_words(words, geo)

    def _feed_and_type(self, words: BlockWords, modal: ModalState, geo: GeometryState) -> None:
        """The feed type (G93/G94/G95 …) in force and a programmed F."""
        feed_type = modal.gcodes.get(15, "G94")
        if feed_type != geo.feed_type:
            # Changing between G93, G94 and G95 deletes the programmed F (V1, 5.1).
            if _feed_family(feed_type) != _feed_family(geo.feed_type):
                modal.feed = 0.0
            geo.feed_type = feed_type
        if "F" in words.words:
            feed = words.words["F"]
            if feed <= 0:
                raise NcAlarmError(ALARM_PATH_VELOCITY)
            modal.feed = feed
            geo.feed_unit_mm = self.path.units(modal).feed_mm

    def _feed_words(self, words: BlockWords, geo: GeometryState) -> None:
        """FA[…], ACC[…] and OVR: the feeds of spindles, acceleration factors, the override."""
        for key, value in words.words.items():
            if key.startswith("FA[S") and key.endswith("]"):
                # 002 L51375-51385: the positioning speed of a spindle in degrees/min; 0 gives
                # the configured MD35300 back.
                if value < 0:
                    raise NcAlarmError(ALARM_PATH_VELOCITY)
                if value:
                    geo.axis_feeds[key[3:-1]] = value
                else:
                    geo.axis_feeds.pop(key[3:-1], None)
            elif key.startswith("FA[") and key.endswith("]"):
                # FA[axis] is the feed of a positioning axis (POS/POSA, 002 L8737, L11159);
                # this control has no positioning axes (POS is 12550), so it would act on nothing.
                raise NcAlarmError(ALARM_NOT_AVAILABLE, "FA")
            elif key.startswith("ACC[") and key.endswith("]"):
                # 002 L7433-7450: 0 < factor ≤ 200 % of the axis' maximum acceleration, modal.
                axis = key[4:-1]
                if axis not in self.machine.path_axes:
                    raise NcAlarmError(NAME_NOT_DEFINED, axis)
                if not 0.0 < value <= 200.0:
                    raise NcAlarmError(VALUE_RANGE_EXCEEDED, "ACC")
                if value == 100.0:
                    geo.accel_pct.pop(axis, None)
                else:
                    geo.accel_pct[axis] = float(value)
            elif key == "ACC":
                raise NcAlarmError(SYNTAX_ERROR, "ACC")  # the axis is required: ACC[X]=…
        if "OVR" in words.words:
            # 002 L56515-56536: 0 … 200 %, multiplied with the override of the panel.
            value = words.words["OVR"]
            if not 0.0 <= value <= 200.0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "OVR")
            geo.feed_override_pct = float(value)

    def _feed_info(self, modal: ModalState, geo: GeometryState) -> dict[str, Any]:
        """The feed of a path block with the programmable override OVR and the ACC factors."""
        info = self._programmed_feed(modal, geo)
        share = geo.feed_override_pct / 100.0
        if share != 1.0 and info["feed"] is not None:
            for key in ("feed_mm_min", "feed_mm_rev"):
                if info.get(key) is not None:
                    info[key] *= share
            info["override"] = share
        if geo.accel_pct:
            info["accel_pct"] = dict(geo.accel_pct)
        return info

    def _programmed_feed(self, modal: ModalState, geo: GeometryState) -> dict[str, Any]:
        kind = modal.gcodes.get(1, "G1")
        if kind == "G0":
            return {"feed": None, "feed_mm_min": None, "inverse_time": False}
        if kind == "G33":
            # Feed = spindle speed x lead; a stopped spindle means the axes wait (no alarm).
            return {"feed": modal.feed or None, "feed_mm_min": 0.0, "inverse_time": False,
                    "per_rev_rpm": _turning_rpm(modal), "feed_mm_rev": None}
        if kind in ("G331", "G332"):
            # Rigid tapping: the spindle is in position control (after SPOS) and turns with the
            # axis at the programmed S, so the path feed is S x lead (002 L19681, tapping without
            # compensating chuck; the lead's sign, right/left hand, is not simulated).
            return {"feed": modal.feed or None, "feed_mm_min": 0.0, "inverse_time": False,
                    "per_rev_rpm": modal.spindle_speed_rpm, "feed_mm_rev": None}
        if modal.feed <= 0:
            raise NcAlarmError(ALARM_NO_FEED)
        feed_type = modal.gcodes.get(15, "G94")
        if feed_type == "G93":
            if modal.gcodes.get(7) in ("G41", "G42"):
                raise NcAlarmError(ALARM_G93_WITH_TRC)  # 002 L55402
            return {"feed": modal.feed, "feed_mm_min": None, "inverse_time": True}
        if feed_type in canon.FEED_PER_REVOLUTION:
            # Revolutional feed follows the master spindle; while it stands the path waits (V1).
            return {"feed": modal.feed, "feed_mm_min": modal.feed * geo.feed_unit_mm * _turning_rpm(modal),
                    "inverse_time": False, "feed_mm_rev": modal.feed * geo.feed_unit_mm}
        return {"feed": modal.feed, "feed_mm_min": modal.feed * geo.feed_unit_mm, "inverse_time": False}

    def _thread_start(self, words: BlockWords) -> None:
        """``SF=``: the start angle of the thread, kept in SD42000 for the threads that follow
        (002 L26538, L55683-55687); the datum holds 0 … 359.999°."""
        if "SF" not in words.words:
            return
        angle = float(words.words["SF"])
        if not 0.0 <= angle < 360.0:
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, "SF")
        self.data.setting_data[SD_THREAD_START_ANGLE] = angle

    # ------------------------------------------------------------------ tool
    def _tool(self, words: BlockWords, modal: ModalState, out: list[canon.CanonCommand]) -> None:
        src = words.source
        change = bool(words.m_codes) and any(v == 6 and ext in (None, 0, 1) for ext, v in words.m_codes)
        if "T" in words.words:
            tool = int(words.words["T"])
            if tool < 0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "T")
            direct = not self.tool_change_with_m6
            if direct:
                self._require_tool_data(tool)  # MD22550 = 0: stop at the T block (002 L58150-58153)
            modal.tool_selected = tool
            out.append(canon.ToolSelect(src, tool, change=direct or change))
            if direct:
                self._change_tool(modal, "D" in words.words, out, src)
        elif change:
            out.append(canon.ToolSelect(src, modal.tool_selected, change=True))
        if change and self.tool_change_with_m6:
            self._require_tool_data(modal.tool_selected)  # MD22550 = 1: stop at M06 (002 L58171-58190)
            self._change_tool(modal, "D" in words.words, out, src)
        if "D" in words.words:
            edge = int(words.words["D"])
            if edge < 0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "D")
            modal.edge = edge
            modal.wear_sign = self.path.wear_sign()
            self.path.tool_vector(modal)  # a D that does not exist for the tool: alarm 17180
            out.append(canon.EdgeSelect(src, edge))

    def _require_tool_data(self, tool: int) -> None:
        """17191 when T<tool> has no data set in the tool offset memory (002 L58219); T0 is no
        tool. Raised before the block changes anything, so NC START runs it again once the data
        set is loaded (compensation block, 002 L58150-58160)."""
        if tool and not any(number == tool for number, _edge in self.data.tools):
            raise NcAlarmError(ALARM_T_NOT_DEFINED, str(tool))

    def _change_tool(self, modal: ModalState, edge_programmed: bool, out: list[canon.CanonCommand],
                     src: canon.Source) -> None:
        """The tool change: new tool, and the default edge of MD20270 unless D is in the block
        (output, so that the channel shows the edge the compensation uses)."""
        modal.tool = modal.tool_selected
        modal.wear_sign = self.path.wear_sign()
        if edge_programmed:
            return
        if not modal.tool:
            modal.edge = 0
        elif self.default_edge >= 0:
            modal.edge = self.default_edge
        out.append(canon.EdgeSelect(src, modal.edge))

    # ------------------------------------------------------------------ spindle
    def _spindle(self, words: BlockWords, modal: ModalState, geo: GeometryState,
                 out: list[canon.CanonCommand]) -> None:
        """S / M3 M4 M5 M19 / SPOS per spindle (``S2=``, ``M2=3`` address spindle 2; plain = master)."""
        if not (words.m_codes or words.extended) and words.gcodes.get(3) not in ("G25", "G26") \
                and modal.gcodes.get(15) != "G96" and words.words.keys().isdisjoint(SPINDLE_WORDS):
            return  # nothing for a spindle in this block
        src = words.source
        speeds: dict[int, float] = {}
        states: dict[int, str] = {}
        positions: dict[int, float] = {}
        modes: dict[int, str] = {}
        if "S" in words.words:
            speeds[1] = words.words["S"]
        for (address, number), value in words.extended.items():
            if address == "S":
                speeds[number or 1] = value
        if words.gcodes.get(3) in ("G25", "G26"):
            self._speed_limits(words.gcodes[3], speeds)
            speeds = {}
        programmed = set(speeds)  # S written (also a cutting speed under G96), not computed
        for ext, value in words.m_codes:
            if value in SPINDLE_M:
                spindle = ext or 1
                if spindle in states:
                    raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, "M")
                states[spindle] = SPINDLE_M[value]
                if value == 19:
                    positions[spindle] = self._spindle_setting("SD43240", spindle) % 360.0
        for key in ("SPOS", "SPOSA"):
            if key in words.words:
                states[1] = "SPOS"
                positions[1] = self._spos_target(float(words.words[key]), words.word_modes.get(key), modal)
                modes[1] = words.word_modes.get(key) or "DC"
        if any(state in ("M19", "SPOS") for state in states.values()) and "SPOSA" not in words.words:
            # SPOS and M19 stay active until the spindle is positioned (002 L51162-51165).
            self.spindle_wait = True
        if "LIMS" in words.words:
            lims = words.words["LIMS"]
            if lims < 0:
                raise NcAlarmError(ALARM_LIMS_NEGATIVE)
            geo.lims_rpm = lims
        feed_type = modal.gcodes.get(15, "G94")
        if feed_type == "G96":
            if self.transverse_axis is None:
                raise NcAlarmError(ALARM_NO_TRANSVERSE_AXIS)
            if 1 in speeds:
                if speeds[1] < 0:
                    raise NcAlarmError(VALUE_RANGE_EXCEEDED, "S")
                geo.cutting_speed_m_min = speeds.pop(1)
            elif geo.cutting_speed_m_min <= 0:
                raise NcAlarmError(ALARM_G96_WITHOUT_S)
            speeds[1] = self._g96_speed(modal, geo)
        for spindle in sorted(set(speeds) | set(states)):
            speed = speeds.get(spindle)
            state = states.get(spindle)
            if speed is not None and speed < 0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "S")
            if spindle == 1:
                if speed is not None:
                    modal.spindle_speed_rpm = speed
                if state is not None:
                    modal.spindle_state = state if state != "SPOS" else "M19"
            speed_deg_min = geo.axis_feeds.get(f"S{spindle}") if spindle in positions else None
            out.append(canon.SpindleCommand(src, spindle, state=state, speed_rpm=speed,
                                            position_deg=positions.get(spindle),
                                            approach=modes.get(spindle),
                                            positioning_rpm=None if speed_deg_min is None else speed_deg_min / 360.0,
                                            speed_change=state in ("M3", "M4") or (
                                                spindle in programmed and modal.spindle_state in ("M3", "M4"))))
            if spindle == 1 and spindle in positions:
                modal.spindle_position_deg = positions[spindle]

    def _spindle_setting(self, key: str, spindle: int) -> float:
        """A spindle's setting datum (kept per spindle name, or one number for all)."""
        value = self.data.setting_data.get(key, 0.0)
        if isinstance(value, dict):
            names = self.machine.spindles
            value = value.get(names[spindle - 1], 0.0) if 1 <= spindle <= len(names) else 0.0
        return float(value or 0.0)

    def _spos_target(self, value: float, mode: str | None, modal: ModalState) -> float:
        """End angle of ``SPOS=…``: AC/DC/ACP/ACN absolute 0 … 359.999°, IC relative to the last
        programmed position (002 L51127-51160)."""
        if mode == "IC":
            return (modal.spindle_position_deg + value) % 360.0
        if not 0.0 <= value < 360.0:
            raise NcAlarmError(POSITION_OUTSIDE_MODULO_RANGE, "SPOS")
        return value
    def _speed_limits(self, code: str, speeds: dict[int, float]) -> None:
        """``G25 S…`` / ``G26 S…``: the minimum / maximum speed of a spindle (002 L54093-54107),
        kept in SD43210 / SD43220 of that spindle, where the spindle reads it."""
        key = "SD43210" if code == "G25" else "SD43220"
        table = self.data.setting_data.get(key)
        table = dict(table) if isinstance(table, dict) else {}
        for number, rpm in speeds.items():
            if rpm < 0:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, "S")
            if not 1 <= number <= len(self.machine.spindles):
                raise NcAlarmError(NAME_NOT_DEFINED, f"S{number}")  # no such spindle
            table[self.machine.spindles[number - 1]] = float(rpm)
        self.data.setting_data[key] = table

    def _g96_speed(self, modal: ModalState, geo: GeometryState) -> float:
        """Spindle speed for the constant cutting speed at the programmed transverse position."""
        assert self.transverse_axis is not None
        radius_mm = abs(geo.wcs_mm.get(self.transverse_axis, 0.0))
        speed_mm_min = geo.cutting_speed_m_min * 1000.0 * self.path.units(modal).feed_mm
        limit = geo.lims_rpm if geo.lims_rpm is not None else self.spindle_limit_rpm
        if radius_mm <= 1e-9:
            return float(limit) if limit else 0.0
        rpm = speed_mm_min / (2.0 * math.pi * radius_mm)
        if limit:
            rpm = min(rpm, float(limit))
        return round(rpm, 6)

    def _constant_cutting_speed(self, modal: ModalState, geo: GeometryState,
                                out: list[canon.CanonCommand], src: canon.Source) -> None:
        if self.transverse_axis is None or geo.cutting_speed_m_min <= 0:
            return
        rpm = self._g96_speed(modal, geo)
        if abs(rpm - modal.spindle_speed_rpm) > 1e-6:
            modal.spindle_speed_rpm = rpm
            out.append(canon.SpindleCommand(src, 1, speed_rpm=rpm))


def _wait_for_spindle_speed(commands: list[canon.CanonCommand], geo: GeometryState) -> list[canon.CanonCommand]:
    """``commands`` with the wait for the set speed range before the first machining motion
    after a programmed speed change of the master spindle (M3, M4, S), in this block or an
    earlier one (MD35500 = 1, 002 L51282-51285, L54530-54536, L54560-54562: checked only at
    the start of a traversing block after a speed change). G0 does not wait, nor does
    tapping with G331/G332 (the spindle is position-controlled, where "spindle in setpoint
    range" means nothing, 002 L72955). The motion system leaves the wait out when the
    spindle's MD35500 is 0 or MD35150 is 0 (:meth:`Spindle.settle_s`).

    Our choice where the manual is silent: the path stops at the start of that block (as
    with MD35500 = 2) even when the spindle is already up to speed then."""
    due = geo.spindle_check_due
    if not due and not any(isinstance(command, canon.SpindleCommand) for command in commands):
        return commands  # no speed change before or in this block: nothing waits
    out: list[canon.CanonCommand] = []
    for command in commands:
        if isinstance(command, canon.SpindleCommand) and command.spindle == 1 and command.speed_change:
            due = True
        elif due and isinstance(command, canon.Motion) and command.kind not in NOT_WAITING_FOR_SPEED:
            out.append(canon.Dwell(command.source, wait_spindle=True, feed_enable=True,
                                   gcodes=command.gcodes, feed=command.feed))
            due = False
        out.append(command)
    geo.spindle_check_due = due
    return out


def _refuse_words_without_effect(words: BlockWords, modal: ModalState) -> None:
    """12550 for a word that would change nothing in this block (issue 20: never parse and drop).

    ``CR=``/``AR=``/``TURN=`` only describe a G2/G3 circle, ``I``/``J``/``K`` a circle's centre
    or a thread's lead, so they mean nothing under G0/G1 (the manuals name no alarm: our
    choice, the number of the other words without effect); ``RPL=`` is the plane angle of a
    ``ROT``/``AROT`` in the same block. ``SR=`` needs the fast NCK inputs of "multiple feedrates
    in one block" (002 L56700-56712) and ``OVRA[]`` positioning axes or a programmable spindle
    override (002 L56523-56527, L54153); this control has neither. The number is the one the
    control uses for ``ANG=`` in a circle block: the function is not available there.
    """
    present = words.words
    if not present:
        return
    if modal.gcodes.get(1) not in ("G2", "G3"):
        for key in CIRCLE_WORDS:
            if key in present:
                raise NcAlarmError(ALARM_NOT_AVAILABLE, key)
    if modal.gcodes.get(1, "G1") in LINEAR_KINDS:
        for key in CENTRE_WORDS:
            if key in present:
                raise NcAlarmError(ALARM_NOT_AVAILABLE, key)
    if "RPL" in present and words.gcodes.get(3) not in ("ROT", "AROT"):
        raise NcAlarmError(ALARM_NOT_AVAILABLE, "RPL")
    for key in UNAVAILABLE_WORDS:
        if key in present:
            raise NcAlarmError(ALARM_NOT_AVAILABLE, key)


def _check_aux_limits(words: BlockWords) -> None:
    """Auxiliary functions per block (H2): M ≤ 5, S ≤ 3, H ≤ 3, T ≤ 1, D ≤ 1, F/FA ≤ 6, all ≤ 10.

    Raises:
        NcAlarmError: 12010 (address type programmed too often) naming the address.
    """
    if not (words.m_codes or words.h_codes or words.extended) and len(words.words) <= AUX_WORDS_WITHIN_LIMITS:
        return  # S, T, D at most once each (every limit ≥ 1), F/FA and the total at most len(words)
    counts = {
        "M": len(words.m_codes),
        "S": len({ext or 1 for (a, ext) in words.extended if a == "S"} | ({1} if "S" in words.words else set())),
        "H": len(words.h_codes),
        "T": len({ext for (a, ext) in words.extended if a == "T"} | ({0} if "T" in words.words else set())),
        "D": len({ext for (a, ext) in words.extended if a == "D"} | ({0} if "D" in words.words else set())),
        "F": sum(1 for k in words.words if k == "F" or k.startswith("FA[")),
    }
    for address, count in counts.items():
        if count > AUX_LIMITS[address]:
            raise NcAlarmError(ALARM_ADDRESS_TOO_OFTEN, address)
    if sum(counts.values()) > AUX_LIMIT_TOTAL:
        raise NcAlarmError(ALARM_ADDRESS_TOO_OFTEN, "M/S/H/T/D/F")


def _turning_rpm(modal: ModalState) -> float:
    """Speed of the master spindle for revolutional feed: S while M3/M4, else 0."""
    return modal.spindle_speed_rpm if modal.spindle_state in ("M3", "M4") else 0.0


def _feed_family(feed_type: str) -> str:
    """``time`` (G93), ``rev`` (per revolution) or ``lin`` (per minute) feed."""
    if feed_type == "G93":
        return "time"
    if feed_type in canon.FEED_PER_REVOLUTION:
        return "rev"
    return "lin"


def _first_spindle_value(machine: MachineConfig, ident: str) -> float | None:
    value = machine.md.get(ident)
    if isinstance(value, dict):
        for spindle in machine.spindles:
            if spindle in value:
                return float(value[spindle])
        return None
    return float(value) if value is not None else None


def _fmt(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else str(value)
