"""ISO dwell ``G04 X… / U… / P…`` → Siemens ``G4 F<seconds>`` or ``G4 S<revolutions>``.

X and U follow the decimal-point rules of MD 10884 (a value without a point
counts in 0.001 units in standard notation); P is always in 0.001 units, in
both notations. With MD 20734 bit 2 set and G95 active the dwell counts
spindle revolutions instead of seconds (``G95 G04 X1000``: 1 revolution in
standard notation, 1000 in pocket-calculator notation).
"""

from __future__ import annotations

from nck.alarm_ids import SYNTAX_ERROR, VALUE_RANGE_EXCEEDED
from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso.lexing import Word
from nck.iso.words import IsoSettings


REVOLUTIONS_BIT = 1 << 2  # MD 20734 bit 2
INTERNAL_UNIT = 0.001


def amount(addresses: dict[str, Word], settings: IsoSettings) -> float:
    """The dwell in seconds (or revolutions) from P, X or U."""
    if "P" in addresses:
        return addresses["P"].value * INTERNAL_UNIT
    word = addresses.get("X") or addresses.get("U")
    if word is None:
        raise NcAlarmError(SYNTAX_ERROR, "G04")
    if word.has_point or settings.pocket_calculator:
        return word.value
    return word.value * INTERNAL_UNIT


def block(addresses: dict[str, Word], settings: IsoSettings, per_rev: bool) -> str:
    """The Siemens dwell block of a G04 line (``per_rev``: G95 is active)."""
    value = amount(addresses, settings)
    if value < 0:
        raise NcAlarmError(VALUE_RANGE_EXCEEDED, "G04")
    address = "S" if per_rev and settings.function_mask & REVOLUTIONS_BIT else "F"
    return f"G4 {address}{trimmed(value)}"


