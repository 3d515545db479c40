"""ISO macros: ``G65`` (call), ``G66`` / ``G67`` (modal call), ``G05 P…`` and the ``$C_…`` arguments.

Translation (:func:`macro_block`, called by :mod:`nck.iso.translate` for blocks
with G65, G66, G67 or G05):

* ``G65 P10 L3 X150. F55`` → ``$C_X=150 $C_X_PROG=1 $C_F=55 … CALL "O0010" P3``:
  every address but P and L is an argument, nothing moves. The values are
  the numbers as written (``$C_TYP_PROG`` tells REAL from INTEGER, one bit
  per letter A = bit 0 … Z = bit 25); ``$C_<a>_PROG`` is 1, or 3 for an
  axis address under G91; ``$C_ALL_PROG`` / ``$C_INC_PROG`` are the bit
  maps. I, J and K may come up to ten times: ``$C_I[n]``, ``$C_I_NUM``,
  ``$C_I_ORDER[n]`` (the I/J/K set each value belongs to).
* ``G66 P10 X5.`` stores the arguments with a modal call (``$C_MCALL``):
  the macro runs after every later block of this level that moves an axis
  (the Siemens MCALL rule), not in the G66 block and not after blocks
  without motion. ``G67`` (or a new G66) cancels it.
* ``G05 P<prog> L<n>`` calls the program ``<prog>`` as written (no padding);
  G05 without P, ``P0``/``P1`` and G05.1 would call CYCLE305, which this
  control does not have: they are skipped without an alarm. The block's
  other words run as usual.
* M-code macros (MD 10814/10815) and G-code macros (MD 10816/10817): the M
  or G word calls its program like G65 (arguments in ``$C_…``, L passes,
  ``$C_G`` = the G number; the block's other G codes run first). While an
  M/G-code macro runs (at any level below it) the words act as plain M and G
  functions; a G that exists only as a macro then raises 12470. Fixed M
  functions (M0–M5, M17, M19, M30, M40–M45, M96–M99) are never replaced.
* Only one call per block: M98, G65, G66, G05 and M/G-code macros together
  raise 12722, and so does G05 while a fixed cycle is modal.

A macro whose first line is ``PROC`` runs in Siemens mode, any other in ISO
mode (decided by :func:`nck.iso.loader.wants_iso`).

Interpreter side: the ``$C_…`` writes of a translated block collect in the
calling level (:class:`MacroState` on the interpreter's frame, field
``iso_macro``); :func:`bind_call` hands them to the called level, where
:func:`read` serves them (system-variable hook in :mod:`nck.interp.sysvars`).
Unprogrammed arguments read 0.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import Any, Sequence

from nck.alarm_ids import (
    ADDRESS_PROGRAMMED_TWICE, DATA_WRITE_PROTECTED, G_FUNCTION_UNKNOWN, ILLEGAL_ARRAY_INDEX_1, NAME_NOT_DEFINED,
    PASS_COUNT_NOT_ALLOWED, SYNTAX_ERROR,
)
from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso.lexing import Word
from nck.iso.words import SIMPLE_G, IsoSettings, TranslateWords, g_name
from nck.lang.dialect import CallLevel, InterpreterContext
from nck.iso.subprograms import call_block
from nck.lang import ast

ALARM_TOO_MANY_CALLS = 12722
MAX_IJK = 10
MAX_PASSES = 9999
AXIS_LETTERS = frozenset("XYZUVWABC")
NOT_ARGUMENTS = frozenset("PLNOG")
EIGHT_DIGIT_PROGRAMS_BIT = 1 << 6  # MD 20734 bit 6
MCALL_NAME = "$C_MCALL"  # internal: sets the G66 modal call (empty string cancels)
MCALL_PASSES = "$C_MCALL_PASSES"  # internal: passes of each G66 call (L)
ISO_MODE_GROUP = 47
SUBST_CALL = "$C_SUBST_CALL"  # internal write: this call is an M/G-code macro
SUBST_ACTIVE = "$C_SUBST_ACTIVE"  # internal read: 1 while an M/G-code macro runs
FIXED_M = frozenset({0, 1, 2, 3, 4, 5, 17, 19, 30, 40, 41, 42, 43, 44, 45, 96, 97, 98, 99})

_READABLE = re.compile(r"^\$C_(?:[A-Z]|[A-Z]_PROG|[IJK]_NUM|[IJK]_ORDER|ALL_PROG|INC_PROG|TYP_PROG)$")
_ARRAYS = re.compile(r"^\$C_(?:[IJK]|[IJK]_ORDER)$")


# ============================================================================ translation
def _names(words: list[Word]) -> list[str]:
    return [g_name(w) for w in words if w.letter == "G"]


def _is_g05(code: str) -> bool:
    return code in ("G05", "G5.1")


def macro_block(words: list[Word], modal: Any, settings: IsoSettings,
                translate_words: TranslateWords) -> list[str] | None:
    """The Siemens blocks of a G65/G66/G67/G05 block, or None for any other block.

    ``translate_words`` translates the block's other words (:mod:`nck.iso.translate`)."""
    gcodes = _names(words)
    calls = [c for c in gcodes if c in ("G65", "G66") or _is_g05(c)]
    substitution = _substitution(words, gcodes, modal, settings)
    if substitution is not None:
        if calls or any(w.letter == "M" and w.value == 98 for w in words):
            raise NcAlarmError(ALARM_TOO_MANY_CALLS)
        return _substituted(words, substitution, modal, settings, translate_words)
    if not calls and "G67" not in gcodes:
        return _m98_with_words(words, modal, settings, translate_words)
    if len(calls) + sum(1 for w in words if w.letter == "M" and w.value == 98) > 1:
        raise NcAlarmError(ALARM_TOO_MANY_CALLS)  # one call, macro or substitution per block
    number = ""
    if words and words[0].letter == "N":
        number = f"N{int(words[0].value)} "
    if "G67" in gcodes and not calls:
        rest = [w for w in words if not (w.letter == "G" and w.value == 67)]
        blocks = [number + f'{MCALL_NAME}=""']
        if any(w.letter != "N" for w in rest):
            blocks += translate_words(rest, modal, settings)
        return blocks
    if "G67" in gcodes:
        raise NcAlarmError(SYNTAX_ERROR, "G67")
    call = calls[0]
    if _is_g05(call):
        if getattr(getattr(modal, "cycle", None), "code", None) is not None:
            raise NcAlarmError(ALARM_TOO_MANY_CALLS)  # G05 while a fixed cycle is modal
        return _g05(words, modal, settings, number, translate_words)
    return _g65_g66(words, call, modal, settings, number)


def _whole(word: Word, what: str) -> int:
    """P, L, O, N take integers only."""
    if word.has_point or word.value != int(word.value) or word.value < 0:
        raise NcAlarmError(SYNTAX_ERROR, f"{what}{word.text}")
    return int(word.value)


def _program_name(word: Word | None, settings: IsoSettings, code: str) -> str:
    if word is None:
        raise NcAlarmError(SYNTAX_ERROR, code)
    number = _whole(word, "P")
    digits = len(word.text.lstrip("+"))
    limit = 8 if settings.function_mask & EIGHT_DIGIT_PROGRAMS_BIT else 4
    if digits > limit:
        raise NcAlarmError(SYNTAX_ERROR, f"P{word.text}")
    return f"O{number:04d}"


def _passes(words: list[Word]) -> int:
    found = [w for w in words if w.letter == "L"]
    if not found:
        return 1
    passes = _whole(found[-1], "L")
    if not 1 <= passes <= MAX_PASSES:
        raise NcAlarmError(PASS_COUNT_NOT_ALLOWED)
    return passes


def argument_writes(words: list[Word], incremental: bool) -> list[str]:
    """``$C_…`` assignments for every argument word of a call block."""

    writes: list[str] = []
    seen: set[str] = set()
    all_bits = inc_bits = typ_bits = 0
    ijk: dict[str, list[tuple[float, int]]] = {"I": [], "J": [], "K": []}
    set_number, last = 1, -1
    for word in words:
        letter = word.letter
        if letter in NOT_ARGUMENTS or len(letter) != 1:
            continue
        bit = 1 << (ord(letter) - ord("A"))
        all_bits |= bit
        if letter in ijk:
            position = "IJK".index(letter)
            if position <= last:
                set_number += 1
            last = position
            ijk[letter].append((word.value, set_number))
            if len(ijk[letter]) > MAX_IJK:
                raise NcAlarmError(SYNTAX_ERROR, letter)
            continue
        if letter in seen:
            raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, letter)
        seen.add(letter)
        prog = 1
        if incremental and letter in AXIS_LETTERS:
            inc_bits |= bit
            prog = 3
        if word.has_point:
            typ_bits |= bit
        writes.append(f"$C_{letter}={trimmed(word.value)} $C_{letter}_PROG={prog}")
    for letter, entries in ijk.items():
        if not entries:
            continue
        writes.append(f"$C_{letter}_NUM={len(entries)} $C_{letter}_PROG=1")
        for index, (value, set_no) in enumerate(entries):
            writes.append(f"$C_{letter}[{index}]={trimmed(value)} $C_{letter}_ORDER[{index}]={set_no}")
    writes.append(f"$C_ALL_PROG={all_bits} $C_INC_PROG={inc_bits} $C_TYP_PROG={typ_bits}")
    return writes


def _g65_g66(words: list[Word], call: str, modal: Any, settings: IsoSettings, number: str) -> list[str]:

    prefix: list[str] = []
    for code in _names(words):
        if code == call:
            continue
        if code not in SIMPLE_G:
            raise NcAlarmError(SYNTAX_ERROR, code)
        prefix.append(SIMPLE_G[code])
        if code == "G90":
            modal.absolute = True
        elif code == "G91":
            modal.absolute = False
    p_words = [w for w in words if w.letter == "P"]
    name = _program_name(p_words[-1] if p_words else None, settings, call)
    passes = _passes(words)
    writes = " ".join(argument_writes(words, not modal.absolute))
    blocks = [number + " ".join(prefix)] if prefix else []
    if call == "G65":
        tail = f' CALL "{name}"' + (f" P{passes}" if passes > 1 else "")
        return blocks + [f"{number}{writes}{tail}"]
    return blocks + [f'{number}{writes} {MCALL_PASSES}={passes} {MCALL_NAME}="{name}"']


def substitution_tables(md_value: Any) -> dict[str, tuple]:
    """IsoSettings fields from MD 10814/10815 (M-code macros) and MD 10816/10817 (G-code
    macros). Entries without a name, and fixed M functions (M0–M5, M17, M19, M30,
    M40–M45, M96–M99), are left out."""
    def listed(key: str) -> list:
        value = md_value(key, None, None) if md_value else None
        if value is None:
            return []
        return list(value) if isinstance(value, (list, tuple)) else [value]

    m_macros = tuple((int(n), str(name).strip().upper())
                     for n, name in zip(listed("MD10814"), listed("MD10815"))
                     if str(name).strip() and int(n) >= 0 and int(n) not in FIXED_M)
    g_macros = tuple((_g_text(n), str(name).strip().upper())
                     for n, name in zip(listed("MD10816"), listed("MD10817"))
                     if str(name).strip() and float(n) > 0)
    return {"m_macros": m_macros, "g_macros": g_macros}


def _g_text(number: Any) -> str:
    """The G name as the translator spells it: 21 → G21, 5 → G05, 12.3 → G12.3."""
    value = float(number)
    if value == int(value):
        whole = int(value)
        return f"G{whole:02d}" if whole < 10 else f"G{whole}"
    whole_text, _, sub = f"{value:.4f}".rstrip("0").partition(".")
    return f"G{int(whole_text)}.{sub}"


def _substitution(words: list[Word], gcodes: list[str], modal: Any,
                  settings: IsoSettings) -> tuple[str, Word, str] | None:
    """(kind "M"/"G", the word, macro program) of an M/G-code macro in the block, or None."""
    if getattr(modal, "no_substitution", False):
        return None
    m_table = dict(getattr(settings, "m_macros", ()) or ())
    g_table = dict(getattr(settings, "g_macros", ()) or ())
    if not m_table and not g_table:
        return None
    found: list[tuple[str, Word, str]] = []
    for word in words:
        if word.letter == "M" and word.value == int(word.value) and int(word.value) in m_table:
            found.append(("M", word, m_table[int(word.value)]))
        elif word.letter == "G":
            name = _names([word])[0]
            if name in g_table:
                found.append(("G", word, g_table[name]))
    if len(found) > 1:
        raise NcAlarmError(ALARM_TOO_MANY_CALLS)
    return found[0] if found else None


def _substituted(words: list[Word], substitution: tuple[str, Word, str], modal: Any,
                 settings: IsoSettings, translate_words: TranslateWords) -> list[str]:
    """An M/G-code macro call; inside a running M/G-code macro the word acts as a plain
    M or G function instead (a G that exists only as a macro then raises 12470)."""
    kind, word, program = substitution
    number = f"N{int(words[0].value)} " if words[0].letter == "N" else ""
    other_g = [w for w in words if w.letter == "G" and w is not word]
    head = translate_words(other_g, modal, settings) if other_g else []
    arguments = [w for w in words if w.letter not in ("N", "G") and w is not word]
    writes = " ".join(argument_writes(arguments, not modal.absolute))
    if kind == "G":
        writes += f" $C_G={_names([word])[0][1:]}"
    passes = _passes(words)
    call = f'{number}{writes} {SUBST_CALL}=1 CALL "{program}"' + (f" P{passes}" if passes > 1 else "")
    modal.no_substitution = True
    try:
        plain = translate_words(words, modal, settings)
    except NcAlarmError as alarm:  # a G code that exists only as a macro: 12470 at run time
        if alarm.number != G_FUNCTION_UNKNOWN or kind != "G":
            raise
        plain = [number + _names([word])[0]]
    finally:
        modal.no_substitution = False
    return ([f"{number}IF {SUBST_ACTIVE}==0"] + head + [call] + [f"{number}ELSE"] + plain
            + [f"{number}ENDIF"])


def _m98_with_words(words: list[Word], modal: Any, settings: IsoSettings,
                    translate_words: TranslateWords) -> list[str] | None:
    """``M98 P… X10. A1.``: the other words run first, then the call; they also reach
    the subprogram as ``$C_…`` (None: a plain M98 block or no M98 at all)."""
    m98 = [w for w in words if w.letter == "M" and w.value == 98]
    if not m98:
        return None
    rest = [w for w in words if w.letter not in ("P", "L") and w is not m98[0]]
    if not any(w.letter != "N" for w in rest):
        return None
    number = f"N{int(words[0].value)} " if words[0].letter == "N" else ""
    blocks = translate_words(rest, modal, settings)
    arguments = [w for w in rest if w.letter not in ("N", "M", "G")]
    writes = " ".join(argument_writes(arguments, not modal.absolute)) + " " if arguments else ""
    call = call_block({w.letter: w.value for w in words if w.letter in ("P", "L")})
    return blocks + [f"{number}{writes}{call}"]


def _g05(words: list[Word], modal: Any, settings: IsoSettings, number: str,
         translate_words: TranslateWords) -> list[str]:
    """G05 P<prog> L<n> calls ``<prog>`` (not padded); the other forms (no P, P0/P1,
    G05.1) would call CYCLE305, which this control does not have: skipped without an
    alarm. Every other word of the block runs first, as in any block."""
    p_words = [w for w in words if w.letter == "P"]
    codes = _names(words)
    program = None
    if "G05" in codes and p_words and _whole(p_words[-1], "P") > 1:
        program = p_words[-1].text.lstrip("+")
    rest = [w for w in words if w.letter not in ("P", "L")
            and not (w.letter == "G" and _is_g05(_names([w])[0]))]
    blocks = translate_words(rest, modal, settings) if any(w.letter != "N" for w in rest) else []
    if program is None:
        return blocks or ([number.strip()] if number else [])
    if len(program) > 10:
        raise NcAlarmError(SYNTAX_ERROR, f"P{program}")
    passes = _passes(words)
    return blocks + [f'{number}CALL "{program}"' + (f" P{passes}" if passes > 1 else "")]


# ============================================================================ interpreter
@dataclass(frozen=True)
class MacroState:
    """The ``$C_…`` data of one program level (immutable: replaced on change).

    ``args``: what this level reads (given by its caller); ``pending``: written
    by the current block for the call it makes; ``modal_args`` / ``modal_call``
    / ``modal_passes``: the G66 modal call of this level.
    """

    args: dict[tuple[str, tuple], Any] = field(default_factory=dict)
    pending: dict[tuple[str, tuple], Any] | None = None
    modal_args: dict[tuple[str, tuple], Any] | None = None
    modal_call: Any = None
    modal_passes: int = 1
    back_to_iso: bool = False  # a PROC program called from ISO mode: G291 again on return
    substitution: bool = False  # this level runs an M/G-code macro (no substitution inside)


def _state(frame: CallLevel) -> MacroState:
    return getattr(frame, "iso_macro", None) or MacroState()


def _key(name: str, indices: tuple[Any, ...]) -> tuple[str, tuple]:
    if _ARRAYS.match(name):
        if len(indices) > 1:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        index = int(indices[0]) if indices else 0
        if index != (indices[0] if indices else 0) or not 0 <= index < MAX_IJK:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        return name, (index,)
    if indices:
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    return name, ()


def read(ctx: InterpreterContext, name: str, indices: tuple[Any, ...]) -> Any:
    """Value of ``$C_…`` at the current program level (0 when not programmed)."""
    frames = ctx.call_stack
    if name == SUBST_ACTIVE:
        return int(any(getattr(f, "iso_macro", None) is not None and f.iso_macro.substitution
                       for f in frames))
    if not (_READABLE.match(name) or _ARRAYS.match(name)):
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    key = _key(name, indices)
    if not frames:
        return 0
    return _state(frames[-1]).args.get(key, 0)


def write(ctx: InterpreterContext, name: str, indices: tuple[Any, ...], value: Any) -> None:
    """Collect a ``$C_…`` argument for the next call (translated ISO blocks only)."""
    frames = ctx.call_stack
    if not frames or ctx.modal.gcodes.get(ISO_MODE_GROUP) != "G291":
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)  # read-only in Siemens mode
    frame = frames[-1]
    state = _state(frame)
    pending = dict(state.pending or {})
    if name == MCALL_NAME:
        target = str(value).strip().upper()
        passes = int(pending.pop((MCALL_PASSES, ()), 1))
        call = ast.Call(target, ()) if target else None
        frame.modal_call = call
        frame.iso_macro = replace(state, pending=None, modal_call=call, modal_passes=passes,
                                  modal_args=pending if call is not None else None)
        return
    internal = name in (MCALL_PASSES, SUBST_CALL)
    if not internal and not (_READABLE.match(name) or _ARRAYS.match(name)):
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    key = (name, ()) if internal else _key(name, indices)
    pending[key] = value
    frame.iso_macro = replace(state, pending=pending)


def bind_call(caller: CallLevel, callee: CallLevel, call: Any, modal: Any = None) -> None:
    """Give the called level its ``$C_…`` arguments (G65 pending ones or the G66 modal set).

    A program whose first line is ``PROC`` called from ISO mode runs in
    Siemens mode: G290 until it returns (:func:`after_return`).
    """
    if modal is not None and callee.program.proc is not None \
            and modal.gcodes.get(ISO_MODE_GROUP) == "G291":
        modal.gcodes[ISO_MODE_GROUP] = "G290"
        callee.iso_macro = MacroState(back_to_iso=True)
    state = getattr(caller, "iso_macro", None)
    if state is None:
        return
    back = bool(callee.iso_macro and callee.iso_macro.back_to_iso)
    if call is not None and call is state.modal_call:
        callee.iso_macro = MacroState(args=dict(state.modal_args or {}), back_to_iso=back)
        callee.passes_left = state.modal_passes - 1
        return
    if state.pending is not None:
        args = dict(state.pending)
        substitution = bool(args.pop((SUBST_CALL, ()), 0))
        callee.iso_macro = MacroState(args=args, back_to_iso=back, substitution=substitution)
        caller.iso_macro = replace(state, pending=None)


def after_return(modal: Any, frame: CallLevel) -> None:
    """Back to ISO mode after a Siemens-mode (PROC) program called from ISO mode."""
    state = getattr(frame, "iso_macro", None)
    if state is not None and state.back_to_iso:
        modal.gcodes[ISO_MODE_GROUP] = "G291"


def display_codes(frames: Sequence[CallLevel], modal: Any, turning: bool) -> dict[int, str]:
    """ISO groups the Siemens G groups cannot show: 12 (G66 while a modal macro call of
    any level is active, else G67) and, in ISO M, 8 (G43 while a tool edge, and with it
    the length compensation, is active, else G49; G44 is shown as G43)."""
    modal_macro = any(
        getattr(f, "iso_macro", None) is not None and f.iso_macro.modal_call is not None
        and f.iso_macro.modal_call is f.modal_call for f in frames)
    codes = {12: "G66" if modal_macro else "G67"}
    if not turning:
        codes[8] = "G43" if getattr(modal, "edge", 0) else "G49"
    return codes
