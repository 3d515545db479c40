"""ISO dialect T (turning): the words and cycles that differ from ISO M.

Hooked into :mod:`nck.iso.translate` for ``iso-t``: :func:`attach` gives the
translator's modal state a :class:`LatheState` (the program's lines, for the
``P``/``Q`` contour references), :func:`translate_words` translates one block
(falling back to the common ISO translation) and :func:`after_line` closes
the contour skip of G71–G73.

What is handled here:

* code system (MD 10881): B (default) as in the manual's T table; A renames
  its codes to B first (G90/G92/G94 → G77/G78/G79, G50 → G92, G98/G99 →
  G94/G95); ``U``/``W`` are incremental X/Z in every system;
* X is a diameter (DIAMON at program start), ``U`` an incremental diameter;
* ``G96 S`` constant cutting speed (Siemens G96/G961), ``G97``; ``G92 S``
  (system A ``G50 S``) the spindle speed limit (LIMS), ``G92 X Z`` (A: ``G50``)
  sets the coordinate system so the tool position reads X/Z;
* ``G32``/``G33 X Z F`` threads: F is the lead (Siemens ``G33 … K``), ``Q``
  the start angle in 0.001° (SF);
* ``G10 P<n> X Z R Q`` (U/W incremental): tool offset n of the active tool,
  geometry for P < 100, wear of n for P = 100 + n (MD 20734 bit 1 = 0);
* G70–G76 and the modal single cycles G77–G79 (system A G90/G92/G94), expanded
  into NC-inserted blocks (:mod:`nck.iso.turning_cycles`) that carry the cycle
  block's line and number. G71–G73 continue after the ``Q`` block (the blocks
  between the call and the contour end are jumped over); G70 runs the contour
  and continues after its own block. Settings blocks (``G71 U R``, ``G72 W R``,
  ``G73 U W R``, ``G74 R``, ``G76 P Q R``) move nothing and keep their values
  for later calls of the same cycle. In G74–G76, P and Q written without a
  decimal point count µm whatever MD 10884 says (the Fanuc formats); G76
  ``P<mm><rr><aa>`` holds finishing passes, run-out (0.1 leads) and tool angle.

The cycle start point A is the position the translator tracks from the
program text (programmed X/Z since the last preset or absolute move); when it
is not known (after G28, a subprogram call, Siemens blocks) a cycle that needs
it raises 61607.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any, Callable

from nck.alarm_ids import (
    ADDRESS_PROGRAMMED_TWICE, G_FUNCTION_UNKNOWN, JUMP_TARGET_NOT_FOUND, NAME_NOT_DEFINED, SYNTAX_ERROR,
)
from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso import turning_cycles as tc
from nck.iso.lexing import Word, split_words
from nck.iso.turning_contour import read_contour
from nck.iso.words import TranslateWords, g_name, word_value

ALARM_START_POINT = 61607  # starting point incorrectly specified / not known
ALARM_ABS_AND_INC = 61805  # value programmed both absolute and incremental
ALARM_BAD_VALUE = 61812

START_BLOCK = "G0 G291 G18 G95 DIAMON"
"""Reset motion, plane G18, feed per revolution and diameter programming of an ISO T main program."""

_SYSTEM_A = {"G90": "G77", "G92": "G78", "G94": "G79", "G50": "G92", "G98": "G94", "G99": "G95",
             "G50.3": "G92.1"}
_NOT_IN_SYSTEM_B = {"G50", "G51"}  # ISO M scaling; in ISO T only system A knows G50 (preset)
_RESTORED = ("iso", "absolute", "per_rev", "motion", "cycle")
"""Translator state put back at the end of a contour that G71–G73 jumped over."""
_GROUP_1 = {"G00", "G01", "G02", "G03", "G0", "G1", "G2", "G3"}
_THREAD = {"G32", "G33"}
_CYCLES = {f"G{n}" for n in range(70, 77)}
_SINGLE = {"G77": 77, "G78": 78, "G79": 79}
_GEOMETRY_PARAMS = {"X": 3, "Z": 4, "R": 6, "Q": 2}  # $TC_DP of geometry (L1, L2, radius, SL)
_WEAR_PARAMS = {"X": 12, "Z": 13, "R": 15}
# settings of each cycle when never programmed (the shell cycles' GUD are initialised so)
_DEFAULTS: dict[int, dict[str, float]] = {
    71: {"depth": 1.0, "retract": 0.5}, 72: {"depth": 1.0, "retract": 0.5},
    73: {"relief_r": 0.0, "relief_z": 0.0, "divisions": 1.0},
    74: {"retract": 0.5}, 75: {"retract": 0.5},
    76: {"finish": 1.0, "chamfer": 0.0, "angle": 60.0, "minimum": 0.0, "allowance": 0.0},
}


@dataclass
class LatheState:
    """ISO T translation state kept across blocks."""

    lines: list[str]
    system_a: bool = False
    position: tuple[float, float] | None = None  # (z, X diameter), programmed
    settings: dict[int, dict[str, float]] = field(default_factory=lambda: copy.deepcopy(_DEFAULTS))
    single: int | None = None  # active G77/G78/G79
    single_params: dict[str, float] = field(default_factory=dict)
    single_start: tuple[float, float] | None = None
    thread: bool = False  # G32/G33 modal
    css: bool = False  # G96 active
    line_index: int = 0
    pending: dict[int, tuple[str, Any]] = field(default_factory=dict)  # Q line → (label, modal)
    labels: int = 0
    _words: dict[int, list[Word] | None] = field(default_factory=dict)

    def words_of(self, index: int) -> list[Word] | None:
        """Lexed words of program line ``index`` (0-based), None if it does not lex."""
        if index not in self._words:
            try:
                _, words = split_words(self.lines[index])
            except NcAlarmError:
                words = None
            self._words[index] = words
        return self._words[index]

    def find_block(self, number: int, start: int) -> int:
        """Line index of block ``N<number>``: searched forward from ``start``, then backward."""
        order = list(range(start, len(self.lines))) + list(range(start - 1, -1, -1))
        for index in order:
            words = self.words_of(index)
            if words and words[0].letter == "O":
                words = words[1:]
            if words and words[0].letter == "N" and int(words[0].value) == number:
                return index
        raise NcAlarmError(JUMP_TARGET_NOT_FOUND, f"N{number}")


def attach(modal: Any, lines: list[str], settings: Any) -> None:
    """Give the translator's modal state ``modal`` the ISO T state for program ``lines``."""
    modal.lathe = LatheState(list(lines), system_a=getattr(settings, "gcode_system", 0) == 1)
    modal.per_rev = True  # ISO T resets to G95 (feed per revolution)


def before_line(modal: Any, index: int) -> None:
    """Tell the state which program line (0-based) is translated next."""
    modal.lathe.line_index = index


def after_line(modal: Any, line: Any) -> None:
    """End of a line: at the end of a skipped contour put the jump label, restore the state."""
    lathe: LatheState = modal.lathe
    pending = lathe.pending.pop(lathe.line_index, None)
    if pending is None:
        return
    label, saved = pending
    line.blocks = list(line.blocks) + [f"{label}:"]
    for name in _RESTORED:
        setattr(modal, name, saved[name])
    lathe.position, lathe.single, lathe.thread, lathe.css = saved["lathe"]


def _g(word: Word) -> str:
    return g_name(word)


def _micro(word: Word) -> float:
    """P/Q of G74–G76 (Fanuc): an integer counts µm, a value with a point is in mm."""
    return word.value if word.has_point else word.value * 0.001


def _raw_number(word: Word, settings: Any, factor: float) -> float:
    """Value of a word whose unpointed form counts ``factor`` units (P, F as a lead)."""
    if word.has_point or getattr(settings, "pocket_calculator", True):
        return word.value
    return word.value * factor


def translate_words(words: list[Word], modal: Any, settings: Any,
                    common: TranslateWords) -> list[str]:
    """Siemens blocks of one ISO T block; ``common`` is the shared ISO translation."""
    lathe: LatheState = modal.lathe
    if lathe.system_a:
        words = [Word("G", _SYSTEM_A[_g(w)][1:], float(_SYSTEM_A[_g(w)][1:]), "." in _SYSTEM_A[_g(w)])
                 if w.letter == "G" and _g(w) in _SYSTEM_A else w for w in words]
    else:
        for word in words:
            if word.letter == "G" and _g(word) in _NOT_IN_SYSTEM_B:
                raise NcAlarmError(G_FUNCTION_UNKNOWN, _g(word))
    body = [w for w in words if w.letter != "N"]
    codes = [_g(w) for w in body if w.letter == "G"]
    address = {w.letter: w for w in body if w.letter not in ("G", "M")}
    if len(address) != len([w for w in body if w.letter not in ("G", "M")]):
        raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, "address")
    tool = address.get("T")
    if tool is not None and (tool.has_point or tool.value < 0):
        raise NcAlarmError(SYNTAX_ERROR, f"T{tool.text}")  # T<tool><offset> is a plain integer
    def value(word: Word) -> float:
        return word_value(word, settings, modal)

    for code in codes:
        if code == "G90":
            modal.absolute = True
        elif code == "G91":
            modal.absolute = False
    cycle = next((c for c in codes if c in _CYCLES), None)
    if cycle is not None:
        return _run_cycle(int(cycle[1:]), address, modal, settings, value, common)
    if "G10" in codes and "L" not in address:
        return _tool_offset(address, modal, value)
    if "G92" in codes:
        return _preset(address, modal, value)
    single = next((c for c in codes if c in _SINGLE), None)
    if single is not None:
        lathe.single = _SINGLE[single]
        lathe.single_params = {}
        lathe.single_start = lathe.position
        lathe.thread = False
    elif any(c in _GROUP_1 or c in _THREAD for c in codes):
        lathe.single = None
    if lathe.single is not None and any(a in address for a in "XZUW"):
        return _run_single(address, modal, settings, value, codes)
    prefix: list[str] = []
    if any(c in _THREAD for c in codes):
        lathe.thread = True
    elif any(c in _GROUP_1 for c in codes):
        lathe.thread = False
    speed_codes = {"G96", "G97"} & set(codes)
    if "G96" in speed_codes and "P" in address:
        raise NcAlarmError(SYNTAX_ERROR, "G96 P")  # only the transverse axis of MD 20100 (P0)
    if speed_codes or (lathe.css and {"G94", "G95"} & set(codes)):
        # Siemens group 15 holds both: G96/G961 (constant cutting speed), G97/G971
        lathe.css = "G96" in speed_codes or (lathe.css and "G97" not in speed_codes)
        per_rev = modal.per_rev if not {"G94", "G95"} & set(codes) else "G95" in codes
        if lathe.css:
            prefix.append("G96" if per_rev else "G961")
        else:
            prefix.append("G97" if per_rev else "G971")
        modal.per_rev = per_rev
        dropped = {"G94", "G95", "G96", "G97", "G32", "G33", "G77", "G78", "G79"}
    else:
        dropped = {"G96", "G97", "G32", "G33", "G77", "G78", "G79"}
    keep = [w for w in body if not (w.letter == "G" and _g(w) in dropped)]
    suffix = ""
    if lathe.thread:
        prefix.append("G33")
        modal.motion = "G33"
        start_angle = next((w for w in keep if w.letter == "Q"), None)
        if start_angle is not None:  # Q: start angle in 0.001 degrees (an integer)
            suffix = f" SF={trimmed(start_angle.value / 1000.0)}"
        keep = _thread_words(keep, lathe, settings)
    dwell = bool({"G04", "G4"} & set(codes))  # G04 U is a time, not an axis
    relative = (not dwell and modal.absolute and lathe.position is None
                and any(w.letter in "UW" for w in keep))
    if not dwell:
        keep = _incremental_words(keep, modal, value)
    if relative:  # U/W with an unknown position: the block in G91, then G90 again
        modal.absolute = False
        blocks = ["G91"] + (common(keep, modal, settings) if keep else []) + ["G90"]
        modal.absolute = True
    else:
        blocks = common(keep, modal, settings) if keep else []
    if prefix or suffix:
        head = " ".join(prefix)
        blocks = [f"{head} {blocks[0]}{suffix}".strip()] + blocks[1:] if blocks else [head + suffix]
    _track(body, codes, modal, value)
    return blocks


def _thread_words(words: list[Word], lathe: LatheState, settings: Any) -> list[Word]:
    """F → lead: K along Z, I for a thread mostly along X (face); Q (start angle) taken out."""
    out = [w for w in words if w.letter not in ("F", "Q")]
    feed = next((w for w in words if w.letter == "F"), None)
    if feed is not None:
        lead = _raw_number(feed, settings, 0.0001)
        got = {w.letter: w.value for w in words}
        along_x = not ("Z" in got or "W" in got) and ("X" in got or "U" in got)
        if lathe.position is not None and ("Z" in got or "W" in got) and ("X" in got or "U" in got):
            z, x = lathe.position
            dz = got["W"] if "W" in got else got["Z"] - z
            dr = (got["U"] if "U" in got else got["X"] - x) / 2.0
            along_x = abs(dr) > abs(dz)
        out.append(Word("I" if along_x else "K", trimmed(lead), lead, True))
    return out


def _incremental_words(words: list[Word], modal: Any,
                       value: Callable[[Word], float]) -> list[Word]:
    """U/W (incremental X/Z) as X/Z: absolute when the position is known, else a G91 block."""
    if not any(w.letter in "UW" for w in words):
        return words
    lathe: LatheState = modal.lathe
    pairs = {"U": "X", "W": "Z"}
    if any(w.letter == pairs[u.letter] for u in words if u.letter in "UW" for w in words):
        raise NcAlarmError(ALARM_ABS_AND_INC, "U/W")
    if not modal.absolute:
        return [Word(pairs[w.letter], w.text, w.value, w.has_point) if w.letter in "UW" else w
                for w in words]
    if lathe.position is None:
        if any(w.letter in "XZ" for w in words):
            raise NcAlarmError(ALARM_ABS_AND_INC, "U/W")
        return [Word(pairs[w.letter], w.text, w.value, w.has_point) if w.letter in "UW" else w
                for w in words]
    z, x = lathe.position
    out = []
    for w in words:
        if w.letter == "U":
            target = x + value(w)
            out.append(Word("X", trimmed(target), target, True))
        elif w.letter == "W":
            target = z + value(w)
            out.append(Word("Z", trimmed(target), target, True))
        else:
            out.append(w)
    return out


def _track(body: list[Word], codes: list[str], modal: Any,
           value: Callable[[Word], float]) -> None:
    """Programmed position after a plain block (unknown after G28, M98, G53, G290)."""
    lathe: LatheState = modal.lathe
    ms = {int(w.value) for w in body if w.letter == "M"}
    if {"G28", "G30", "G53", "G290"} & set(codes) or 98 in ms or "G10" in codes or "G04" in codes \
            or "G4" in codes or "G52" in codes or "G92.1" in codes:
        if not ({"G10", "G04", "G4"} & set(codes)):
            lathe.position = None
        return
    got = {w.letter: w for w in body}
    if not any(a in got for a in "XZUW"):
        return
    if lathe.position is None:
        if modal.absolute and "X" in got and "Z" in got:
            lathe.position = (value(got["Z"]), value(got["X"]))
        return
    z, x = lathe.position
    if "X" in got:
        x = value(got["X"]) if modal.absolute else x + value(got["X"])
    if "U" in got:
        x += value(got["U"])
    if "Z" in got:
        z = value(got["Z"]) if modal.absolute else z + value(got["Z"])
    if "W" in got:
        z += value(got["W"])
    lathe.position = (z, x)


def _target(address: dict[str, Word], modal: Any, value: Callable[[Word], float],
            start: tuple[float, float]) -> tuple[float, float]:
    """End point (z, X diameter) of a cycle block: X/Z per G90/G91, U/W incremental."""
    z, x = start
    if "X" in address:
        x = value(address["X"]) if modal.absolute else x + value(address["X"])
    if "U" in address:
        x = start[1] + value(address["U"])
    if "Z" in address:
        z = value(address["Z"]) if modal.absolute else z + value(address["Z"])
    if "W" in address:
        z = start[0] + value(address["W"])
    return (z, x)


def _start(modal: Any) -> tuple[float, float]:
    position = modal.lathe.position
    if position is None:
        raise NcAlarmError(ALARM_START_POINT, "A")
    return position


def _restore_motion(modal: Any) -> list[str]:
    """Group 1 as it was before the cycle (the cycle's own moves leave G0 active)."""
    return [modal.motion]


def _run_cycle(code: int, address: dict[str, Word], modal: Any, settings: Any,
               value: Callable[[Word], float], common: TranslateWords) -> list[str]:
    """A G70–G76 block: a settings block stores values, a run block expands the cycle."""
    lathe: LatheState = modal.lathe
    stored = lathe.settings.setdefault(code, {})
    feed = value(address["F"]) if "F" in address else None
    runs = ("P" in address and "Q" in address) if code <= 73 else any(a in address for a in "XZUW")
    if code == 70:
        return _finishing(address, modal, settings, common)
    if not runs:  # settings block: store for later calls, no motion
        _store_settings(code, address, stored, value)
        return []
    extra = [f"S{trimmed(value(address['S']))}"] if "S" in address else []
    if "T" in address:
        extra.append(f"T{int(address['T'].value)}")
    start = _start(modal)
    if code in (71, 72, 73):
        blocks = _contour_cycle(code, address, modal, settings, value, stored, start, feed)
    elif code in (74, 75):
        end = _target(address, modal, value, start)
        step_i = _micro(address["P"]) if "P" in address else 0.0
        step_k = _micro(address["Q"]) if "Q" in address else 0.0
        if code == 74:
            blocks = tc.peck_cycle(start, end, step_k, step_i, stored["retract"], feed, False)
        else:
            blocks = tc.peck_cycle(start, end, step_i, step_k, stored["retract"], feed, True)
    else:
        end = _target(address, modal, value, start)
        height = _micro(address["P"]) if "P" in address else 0.0
        first = _micro(address["Q"]) if "Q" in address else 0.0
        taper = value(address["R"]) if "R" in address else 0.0
        lead = _raw_number(address["F"], settings, 0.0001) if "F" in address else 0.0
        blocks = tc.multi_thread(start, end, taper, height, first, stored["minimum"],
                                 stored["allowance"], int(stored["finish"]), stored["angle"], lead,
                                 stored["chamfer"])
    if extra and blocks:
        blocks.insert(0, " ".join(extra))
    lathe.position = start
    jump = [blocks.pop()] if blocks and blocks[-1].startswith("GOTOF ") else []
    return blocks + _restore_motion(modal) + jump


def _store_settings(code: int, address: dict[str, Word], stored: dict[str, float],
                    value: Callable[[Word], float]) -> None:
    """Values of a settings-only block (Fanuc first block of the two-block formats)."""
    if code == 71 and "U" in address:
        stored["depth"] = value(address["U"])
    if code == 72 and "W" in address:
        stored["depth"] = value(address["W"])
    if code in (71, 72, 74, 75) and "R" in address:
        stored["retract"] = value(address["R"])
    if code == 73:
        for letter, name in (("U", "relief_r"), ("W", "relief_z"), ("R", "divisions")):
            if letter in address:
                stored[name] = address[letter].value if letter == "R" else value(address[letter])
    if code == 76:
        if "P" in address:
            digits = address["P"].text.lstrip("+").split(".")[0].rjust(6, "0")
            stored["finish"], stored["chamfer"], stored["angle"] = (
                float(digits[-6:-4]), float(digits[-4:-2]), float(digits[-2:]))
        if "Q" in address:
            stored["minimum"] = _micro(address["Q"])
        if "R" in address:
            stored["allowance"] = value(address["R"])


def _contour_lines(address: dict[str, Word], lathe: LatheState) -> tuple[int, int]:
    first = lathe.find_block(int(address["P"].value), lathe.line_index)
    last = lathe.find_block(int(address["Q"].value), first)
    if last < first:
        raise NcAlarmError(ALARM_BAD_VALUE, "Q")
    return first, last


def _contour_words(lathe: LatheState, first: int, last: int) -> list[list[Word]]:
    blocks = []
    for index in range(first, last + 1):
        words = lathe.words_of(index)
        if words is None:
            raise NcAlarmError(ALARM_BAD_VALUE, f"line {index + 1}")
        blocks.append([w for w in words if w.letter not in ("N", "O")])
    return blocks


def _contour_cycle(code: int, address: dict[str, Word], modal: Any, settings: Any,
                   value: Callable[[Word], float], stored: dict[str, float],
                   start: tuple[float, float], feed: float | None) -> list[str]:
    lathe: LatheState = modal.lathe
    first, last = _contour_lines(address, lathe)
    blocks_words = _contour_words(lathe, first, last)
    za, xa = start
    elements = read_contour(blocks_words, (za, xa / 2.0), modal.absolute, value)
    approach = 1 if elements and any(w.letter in "XZUW" for w in blocks_words[0]) else 0
    profile = elements[approach:]
    approach_end = elements[approach - 1].end if approach else (za, xa / 2.0)
    du = value(address["U"]) if "U" in address else 0.0
    dw = value(address["W"]) if "W" in address else 0.0
    if code == 73:
        blocks = tc.pattern_repeat(approach_end, profile, start, stored["relief_r"],
                                   stored["relief_z"], int(stored["divisions"]), du, dw, feed)
    else:
        blocks = tc.stock_removal(profile, start, stored["depth"], stored["retract"], du, dw,
                                  feed, facing=code == 72)
    if last > lathe.line_index:  # continue after the Q block: jump over the blocks between
        lathe.labels += 1
        label = f"ISO_CONTOUR_END_{lathe.labels}"
        blocks.append(f"GOTOF {label}")
        saved = {name: copy.deepcopy(getattr(modal, name)) for name in _RESTORED}
        saved["lathe"] = (start, lathe.single, lathe.thread, lathe.css)
        lathe.pending[last] = (label, saved)
    return blocks


def _finishing(address: dict[str, Word], modal: Any, settings: Any, common: TranslateWords) -> list[str]:
    """G70 P Q: the contour blocks with their own F/S/T, then back to the start point."""
    lathe: LatheState = modal.lathe
    if "P" not in address or "Q" not in address:
        raise NcAlarmError(ALARM_BAD_VALUE, "P")
    start = lathe.position
    first, last = _contour_lines(address, lathe)
    blocks: list[str] = []
    index_before = lathe.line_index
    for index, words in zip(range(first, last + 1), _contour_words(lathe, first, last)):
        lathe.line_index = index
        if words:
            blocks.extend(translate_words(words, modal, settings, common))
    lathe.line_index = index_before
    if start is not None:
        blocks.extend([f"G0 X=AC({trimmed(start[1])})", f"G0 Z=AC({trimmed(start[0])})",
                       modal.motion])
        lathe.position = start
    return blocks


def _run_single(address: dict[str, Word], modal: Any, settings: Any,
                value: Callable[[Word], float], codes: list[str]) -> list[str]:
    """One pass of the modal single cycle G77/G78/G79 from its start point."""
    lathe: LatheState = modal.lathe
    if lathe.single_start is None:
        lathe.single_start = _start(modal)
    start = lathe.single_start
    params = lathe.single_params
    end_prev = (params.get("z", start[0]), params.get("x", start[1]))
    end = _target(address, modal, value, end_prev if ("X" not in address and "U" not in address)
                  or ("Z" not in address and "W" not in address) else start)
    if "U" in address:
        end = (end[0], start[1] + value(address["U"]))
    if "W" in address:
        end = (start[0] + value(address["W"]), end[1])
    params["z"], params["x"] = end
    if "R" in address:
        params["taper"] = value(address["R"])
    if "F" in address:
        params["feed"] = (_raw_number(address["F"], settings, 0.0001) if lathe.single == 78
                          else value(address["F"]))
    blocks = tc.single_cycle(lathe.single or 77, start, end, params.get("taper", 0.0),
                             params.get("feed"))
    lathe.position = start
    head = [c for c in codes if c in ("G90", "G91")]
    return ([" ".join(head)] if head else []) + blocks + [modal.motion]


def _preset(address: dict[str, Word], modal: Any, value: Callable[[Word], float]) -> list[str]:
    """G92 (system A: G50): S = spindle speed limit, X/Z = coordinate system setting."""
    blocks: list[str] = []
    if "S" in address:
        blocks.append(f"LIMS={trimmed(value(address['S']))}")
    axes = [(a, address[a]) for a in ("X", "Z") if a in address]
    if axes:
        # Frames are radii on the transverse axis (002 L32672-32684): X (a diameter) halved.
        parts = " ".join(f"{a}=($P_EP[{a}]-({trimmed(value(w))}))/2" if a == "X" else
                         f"{a}=$P_EP[{a}]-({trimmed(value(w))})" for a, w in axes)
        blocks.append("ATRANS " + parts)
        lathe: LatheState = modal.lathe
        if len(axes) == 2:
            lathe.position = (value(address["Z"]), value(address["X"]))
        elif lathe.position is not None:
            z, x = lathe.position
            lathe.position = (value(address["Z"]) if "Z" in address else z,
                              value(address["X"]) if "X" in address else x)
    return blocks


def _tool_offset(address: dict[str, Word], modal: Any, value: Callable[[Word], float]) -> list[str]:
    """``G10 P<n>``: geometry (n < 100) or wear (100 + n) of offset n of the active tool."""
    if "P" not in address:
        raise NcAlarmError(SYNTAX_ERROR, "G10")
    slot = int(address["P"].value)
    wear = slot >= 100
    edge = slot - 100 if wear else slot
    if edge < 1:
        raise NcAlarmError(NAME_NOT_DEFINED, f"G10 P{slot}")
    params = _WEAR_PARAMS if wear else _GEOMETRY_PARAMS
    blocks = []
    for letter, inc in (("X", "U"), ("Z", "W"), ("R", ""), ("Q", "")):
        param = params.get(letter)
        if param is None:
            continue
        name = f"$TC_DP{param}[$P_TOOLNO,{edge}]"
        if letter in address:
            written = address[letter].value if letter == "Q" else value(address[letter])
            if modal.absolute or letter in ("R", "Q"):
                blocks.append(f"{name}={trimmed(written)}")
            else:
                blocks.append(f"{name}={name}+({trimmed(written)})")
        if inc and inc in address:
            blocks.append(f"{name}={name}+({trimmed(value(address[inc]))})")
    return blocks
