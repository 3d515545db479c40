"""ISO block lexing: nested ``( … )`` comments, ``;`` comments, ``/n`` skip, address words.

:func:`split_words` turns one ISO line into its block-skip level (or None) and
a list of :class:`Word` (letter, sub-code text, numeric value, whether the
value was written with a decimal point). Anything that is not an ISO address
word (Siemens keywords, ``=``, names) raises alarm 12080.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from nck.alarm_ids import SKIP_LEVEL_NOT_ALLOWED, SYNTAX_ERROR
from nck.errors import NcAlarmError


@dataclass(frozen=True)
class Word:
    """One address word: ``letter`` + ``text`` (as written); ``value`` parsed."""

    letter: str
    text: str
    value: float
    has_point: bool


_WORD = re.compile(r"\s*([A-Z])\s*([+-]?(?:\d+\.?\d*|\.\d+))")
_COMMA_WORD = re.compile(r"\s*,\s*([RCA])\s*([+-]?(?:\d+\.?\d*|\.\d+))")  # ,R ,C ,A (000 L4034-4041)


def strip_comments(text: str) -> str:
    """Remove nested ``( … )`` comments and everything after ``;``.

    An unclosed ``(`` comments out the rest of the line.
    """
    out: list[str] = []
    depth = 0
    for char in text:
        if char == "(":
            depth += 1
            continue
        if char == ")" and depth:
            depth -= 1
            continue
        if depth:
            continue
        if char == ";":
            break
        out.append(char)
    return "".join(out)


def split_words(line: str, active_skip_levels: frozenset[int] | None = None
                ) -> tuple[int | None, list[Word]]:
    """Lex one ISO line into ``(skip level at block start or None, words)``.

    A ``/n`` at the start of the block is returned as its level (0 for a bare
    ``/``) for the interpreter's normal block skip. A ``/n`` later in the block
    discards the rest of the block when ``n`` is in ``active_skip_levels``;
    otherwise the slash is ignored. Levels outside 1..9 raise 14060.
    """
    text = strip_comments(line).upper()
    position = 0
    skip: int | None = None
    words: list[Word] = []
    active = active_skip_levels or frozenset()
    while position < len(text):
        char = text[position]
        if char in " \t":
            position += 1
            continue
        if char == "/":
            match = re.match(r"/\s*(\d*)", text[position:])
            digits = match.group(1) if match else ""
            level = int(digits) if digits else 0
            if digits and not 1 <= level <= 9:
                raise NcAlarmError(SKIP_LEVEL_NOT_ALLOWED, level)
            position += match.end() if match else 1
            if not words and skip is None:
                skip = level
                continue
            if level in active:
                break
            continue
        match = _COMMA_WORD.match(text, position) if char == "," else None
        if match:
            words.append(Word("," + match.group(1), match.group(2), float(match.group(2)),
                              "." in match.group(2)))
            position = match.end()
            continue
        match = _WORD.match(text, position)
        if not match:
            raise NcAlarmError(SYNTAX_ERROR, text[position:].strip()[:20])
        letter, number = match.group(1), match.group(2)
        end = match.end()
        # a following letter glued to a name (WAIT, G500X) is a Siemens keyword
        if letter != "G" and position + 1 < len(text) and text[position + 1].isalpha():
            raise NcAlarmError(SYNTAX_ERROR, text[position:].strip()[:20])
        words.append(Word(letter, number, float(number), "." in number))
        position = end
    return skip, words
