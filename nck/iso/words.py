"""The words of ISO mode every translator part shares: the ISO settings, the G codes with a
Siemens twin, a G word's canonical name and a word's value in mm.

The parts that translate generated blocks again (:mod:`nck.iso.macros`,
:mod:`nck.iso.turning`) are handed the block translator of :mod:`nck.iso.translate`
(:data:`TranslateWords`) instead of importing it, so the translator's modules form no circle.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from nck.iso.lexing import Word

LENGTH_LETTERS = frozenset("XYZUVWABCIJKQR")


@dataclass(frozen=True)
class IsoSettings:
    """Decimal point rules: MD 10884 (pocket calculator) and MD 10886 (IS-C)."""

    pocket_calculator: bool = True
    increment_system_c: bool = False
    function_mask: int = 0  # MD 20734 EXTERN_FUNCTION_MASK (bit 2: G04 in revolutions under G95)
    fixed_feedrates: bool = False  # MD 22920 EXTERN_FIXED_FEEDRATE_F1_ON: F0…F9 from SD 42160
    gcode_system: int = 0  # ISO T code system, MD 10881: 0 B, 1 A
    tool_digits: int = 2  # ISO T digits of the tool number in T, MD 10888
    start_unit: str = ""  # G700/G710 from MD 20154[5] (ISO group 6 reset), "" = table reset
    m_macros: tuple[tuple[int, str], ...] = ()  # MD 10814/10815: M number → macro program
    g_macros: tuple[tuple[str, str], ...] = ()  # MD 10816/10817: G code → macro program

    @property
    def increment_mm(self) -> float:
        """Value of one increment for a number written without a point."""
        return 0.0001 if self.increment_system_c else 0.001


TranslateWords = Callable[[list[Word], Any, IsoSettings], list[str]]
"""``translate(words, modal, settings)``: the Siemens blocks of one ISO block's words."""

SIMPLE_G = {  # ISO G code -> the Siemens G code with the same meaning
    "G0": "G0", "G00": "G0", "G1": "G1", "G01": "G1", "G2": "G2", "G02": "G2",
    "G3": "G3", "G03": "G3", "G17": "G17", "G18": "G18", "G19": "G19",
    "G40": "G40", "G41": "G41", "G42": "G42", "G54": "G54", "G55": "G55",
    "G56": "G56", "G57": "G57", "G58": "G505", "G59": "G506", "G61": "G60",
    "G64": "G64", "G9": "G9", "G09": "G9", "G90": "G90", "G91": "G91",
    "G93": "G93", "G94": "G94", "G95": "G95", "G20": "G700", "G21": "G710", "G70": "G700",
    "G71": "G710", "G53": "G53",
}


def g_name(word: Word) -> str:
    """The canonical name of a G word: ``G1`` -> ``G01``, ``G54.10`` -> ``G54.1``."""
    text = word.text
    if "." in text:
        whole, _, sub = text.partition(".")
        whole = str(int(whole)) if whole else "0"
        if sub.strip("0") == "":
            return f"G{int(whole):02d}" if int(whole) < 10 else f"G{whole}"
        return f"G{int(whole)}.{sub.rstrip('0')}"
    number = int(text)
    return f"G{number:02d}" if number < 10 else f"G{number}"


def word_value(word: Word, settings: IsoSettings, modal: Any) -> float:
    """The value of ``word`` in mm, mm/min or mm/rev: undotted lengths and feeds scaled by the ISO input increment."""
    if word.has_point or settings.pocket_calculator:
        return word.value
    if word.letter == "F":
        return word.value * (0.01 if modal.per_rev else 1.0)
    if word.letter in LENGTH_LETTERS or word.letter in (",R", ",C"):
        return word.value * settings.increment_mm
    return word.value
