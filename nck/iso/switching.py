"""ISO mode and Siemens language: what passes, what is refused, and the start-up unit.

ISO dialects manual §2.3.2 and §4.1.4 (digest §1, ranked item 3):

* In ISO mode only ISO code is legal; a Siemens keyword or a Siemens-only G
  function raises **12080** (``N10 WAIT``, ``N15 G91 G500``). A G number that
  neither language knows raises 12470.
* Exceptions run as Siemens blocks in ISO mode: control structures (IF/ELSE/
  ENDIF, WHILE, FOR, LOOP, REPEAT/UNTIL, CASE), program branches (GOTO, GOTOF,
  GOTOB, GOTOC and their jump labels) and subprogram calls with CALL, MCALL or
  PCALL (not a call with L: in ISO mode L is an address).
* With MD 20734 ``EXTERN_FUNCTION_MASK`` bit 3 = 1 a block the ISO translator
  rejects with 12080 is handed to the Siemens translator instead; the mode
  stays ISO.
* The inch/metric unit an ISO main program starts with is MD 20154[5]
  (``EXTERN_GCODE_RESET_VALUES`` of ISO group 6): 1 = G20, 2 = G21; 0 keeps
  the table's reset value (G21).
"""

from __future__ import annotations

import functools
import re

from nck.alarm_ids import G_FUNCTION_UNKNOWN, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.lang.gcodes import gtable
from nck.resources import load_toml

PASS_UNKNOWN_BIT = 1 << 3  # MD 20734 bit 3

SIEMENS_STATEMENTS = frozenset({
    "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "ENDFOR", "LOOP", "ENDLOOP", "REPEAT",
    "REPEATB", "UNTIL", "CASE", "GOTO", "GOTOF", "GOTOB", "GOTOC", "CALL", "MCALL", "PCALL",
})
_HEAD = re.compile(r"^\s*(?:/\d?\s*)?(?:N\d+\s*)?([A-Z_][A-Z0-9_]*)(\s*:)?", re.IGNORECASE)


def siemens_statement(raw: str) -> bool:
    """True if the ISO-mode line ``raw`` is a Siemens control structure, branch, jump label
    or CALL/MCALL/PCALL that runs unchanged."""
    head = raw.lstrip(" \t/0123456789")
    if head[:1] in ("N", "n"):
        head = head[1:].lstrip(" \t0123456789")
    if not (head[:2].isalpha() or head[:1] == "_"):
        return False  # ISO address words: one letter, then a number
    match = _HEAD.match(raw)
    if not match:
        return False
    word = match.group(1).upper()
    if match.group(2):  # "LABEL:" — a jump target (ISO words never end in a colon)
        return len(word) > 1
    return word in SIEMENS_STATEMENTS


@functools.cache
def _siemens_only_codes() -> frozenset[str]:

    iso: set[str] = set()
    for name in ("iso_m.toml", "iso_t.toml"):
        for group in load_toml("gcode", name)["group"]:
            iso.update(str(code) for code in group.get("members", ()) if code)
    return frozenset(code for code in gtable("siemens").group_of if code not in iso)


def unknown_g(code: str) -> NcAlarmError:
    """The alarm for a G function the ISO translator does not take: 12080 for a Siemens-only
    G function (``G500``), else 12470."""
    if code in _siemens_only_codes():
        return NcAlarmError(SYNTAX_ERROR, f"{code} unknown")
    return NcAlarmError(G_FUNCTION_UNKNOWN, code)


def pass_to_siemens(alarm: NcAlarmError, function_mask: int) -> bool:
    """MD 20734 bit 3: a block the ISO translator rejects with 12080 goes to the Siemens one."""
    return bool(function_mask & PASS_UNKNOWN_BIT) and alarm.number == SYNTAX_ERROR


def start_unit(reset_values: object) -> str:
    """The Siemens unit code an ISO main program starts with (MD 20154[5]), or ""."""
    if isinstance(reset_values, (list, tuple)) and len(reset_values) > 5:
        value = reset_values[5]
    elif isinstance(reset_values, dict):
        value = reset_values.get(5, reset_values.get("5", 0))
    else:
        return ""
    try:
        number = int(value)
    except (TypeError, ValueError):
        return ""
    return {1: "G700", 2: "G710"}.get(number, "")
