"""Plain motion blocks: one compiled pattern instead of the parser.

A *plain* block is the bread and butter of CAM output::

    [N<digits>] [G0|G1|G00|G01] [G90|G91] [X<v>] [Y<v>] [Z<v>] [F<v>] [; comment]

with upper-case letters, the words in this order (the two G words in either
order), whitespace between words optional, plain numbers (sign only on
axis values, at most 9 digits before and after the point) and nothing else.
Such a line is always valid for the block parser and means exactly: the G
words, the axis words X/Y/Z with constant values, the feed word F. Everything
else (lower case, ``X=…``, expressions, exponents, other addresses, a different
word order) is simply *not plain* and goes through the lexer and parser, which
decide and raise the alarms; so a plain match never changes what a line means.

The values follow the parser's rules exactly: an unsigned mantissa without a
point is an integer, a sign is applied as ``-1 * value`` (so ``X-0`` is +0.0
while ``X-0.0`` is -0.0), and the axis value is then converted to float.
"""

from __future__ import annotations

import re

from nck.lang import ast

_NUM = r"(?:[0-9]{1,9}(?:\.[0-9]{0,9})?|\.[0-9]{1,9})"
_WS = r"[ \t]*"
_MOTION = r"(G0?[01])"
_DISTANCE = r"(G9[01])"

PLAIN_PATTERN = (
    rf"{_WS}(?:N([0-9]{{1,9}}){_WS})?"
    rf"(?:{_MOTION}{_WS}(?:{_DISTANCE}{_WS})?|{_DISTANCE}{_WS}(?:{_MOTION}{_WS})?)?"
    rf"(?:X([+-]?{_NUM}){_WS})?"
    rf"(?:Y([+-]?{_NUM}){_WS})?"
    rf"(?:Z([+-]?{_NUM}){_WS})?"
    rf"(?:F({_NUM}){_WS})?"
    r"(?:;.*)?"
)
"""One plain line; groups: 1 N, 2 motion G, 3 distance G, 4 distance G, 5 motion G
(one G of each group at most, in either order), 6 X, 7 Y, 8 Z, 9 F."""

PLAIN_LINE = re.compile(PLAIN_PATTERN)
"""Full-match this against one line."""

PLAIN_LINES = re.compile(rf"^{PLAIN_PATTERN}$", re.MULTILINE)
"""The same for every line of a text chunk (``findall`` → one tuple per plain line, '' for absent)."""

_BARE = re.sub(r"\((?!\?)", "(?:", PLAIN_PATTERN)

NOT_PLAIN_LINE = re.compile(rf"(?:{_BARE}(?:\n|\Z))*+([^\n]*)")
"""``finditer`` over a whole text (from its start) → per match, group 1 is the next line that
is *not* plain ('' at the end of the text). Every match starts at a line start (or at the line
end of the previous non-plain line) and skips the plain lines before it in one go, so a scan
allocates nothing for plain lines."""

PLAIN_WORDS = re.compile(
    r"^[ \t]*(?:N[0-9]+[ \t]*)?([^XYZF;\n]*)(?:X([^ \tYZF;\n]+))?[ \t]*(?:Y([^ \tZF;\n]+))?"
    r"[ \t]*(?:Z([^ \tF;\n]+))?[ \t]*(?:F([^ \t;\n]+))?.*$",
    re.MULTILINE,
)
"""Words of lines *known* to be plain (three times faster than :data:`PLAIN_LINES`):
``findall`` → per line (G words, X, Y, Z, F), '' for absent."""

SIMPLE_ADDRESSES = ("X", "Y", "Z", "I", "J", "K", "CR", "F")
"""The address words of a simple motion line, in the order they must be written."""

SIMPLE_PATTERN = (
    rf"{_WS}(?:N([0-9]{{1,9}}){_WS})?"
    rf"(?:(G0?[0-3]){_WS}(?:(G9[01]){_WS})?|(G9[01]){_WS}(?:(G0?[0-3]){_WS})?)?"
    + "".join(rf"(?:{address}{'=' if len(address) > 1 else ''}([+-]?{_NUM}){_WS})?"
              for address in SIMPLE_ADDRESSES[:-1])
    + rf"(?:F({_NUM}){_WS})?"
    r"(?:;(.*))?"
)
"""A *simple* motion line: a plain line (every plain line is simple) that may also be a circle
(G2/G3, ``G02``/``G03``) with centre words I, J, K or a radius ``CR=``, the words in the order
N, G, X, Y, Z, I, J, K, CR, F.
Like a plain line it is always valid for the block parser (property-tested), so the load scan
and the editor's check do not parse it, and :func:`simple_block` gives its syntax tree without
the lexer; what it means is decided by the interpreter. Groups: 1 N, 2-5 the G words (2, 3 or
4, 5 in source order), 6-13 the words of :data:`SIMPLE_ADDRESSES`, 14 the comment."""

SIMPLE_LINE = re.compile(SIMPLE_PATTERN)
"""Full-match this against one line."""

NOT_SIMPLE_LINE = re.compile(rf"(?:{re.sub(r'[(](?![?])', '(?:', SIMPLE_PATTERN)}(?:\n|\Z))*+([^\n]*)")
"""As :data:`NOT_PLAIN_LINE` for simple lines: ``finditer`` over a text (from a line start, up to
a line start or the text's end) → per match, group 1 is the next line that is *not* simple ('' at
the end); the simple lines before it are skipped in one go."""


def simple_words(found: re.Match[str]) -> tuple[list[str], list[tuple[str, int | float]]]:
    """The words of a :data:`SIMPLE_LINE` match as the parser reads them: the normalised G
    codes in source order (``G02`` is ``G2``) and ``(address, constant)`` in line order."""
    groups = found.groups()
    gcodes = [code if len(code) == 3 and code[1] == "9" else "G" + code[-1]
              for code in groups[1:5] if code is not None]
    return gcodes, [(address, _literal(text)) for address, text in zip(SIMPLE_ADDRESSES, groups[5:13])
                    if text is not None]


def simple_block(line: str, number: int) -> ast.Block | None:
    """The syntax tree of a simple motion line — exactly the block parser's, property-tested —
    or None when ``line`` is not simple (then the parser reads it). ``number``: its 1-based
    line."""
    found = SIMPLE_LINE.fullmatch(line)
    if found is None:
        return None
    gcodes, words = simple_words(found)
    statements: list[ast.Statement] = [ast.GWord(code) for code in gcodes]
    statements += [ast.AddressWord(address, ast.Num(value)) for address, value in words]
    block_number = found.group(1)
    return ast.Block(line=number, text=line, number=None if block_number is None else int(block_number),
                     statements=tuple(statements), comment=found.group(14))


def _literal(text: str) -> int | float:
    """A signed constant as the parser folds it: an int without a point, a float with one, a
    minus applied as ``-1 * value`` (``-0`` is the int 0, ``-0.0`` the float -0.0)."""
    mantissa = text[1:] if text[:1] in "+-" else text
    value: int | float = float(mantissa) if "." in mantissa else int(mantissa)
    return -1 * value if text[:1] == "-" else value


def parses_without_alarm(line: str) -> bool:
    """True if ``line`` is known to be valid for the block parser without parsing it (a plain or
    a simple motion line); False says nothing (the parser decides)."""
    return SIMPLE_LINE.fullmatch(line) is not None


G_CODES = {"G0": "G0", "G00": "G0", "G1": "G1", "G01": "G1", "G90": "G90", "G91": "G91"}
"""Normalised G codes of a plain line."""


def match_plain(line: str) -> re.Match[str] | None:
    """The match of a plain line, or None."""
    return PLAIN_LINE.fullmatch(line)


def is_plain(line: str) -> bool:
    """True if ``line`` is a plain block (valid without the parser)."""
    return PLAIN_LINE.fullmatch(line) is not None


def has_statements(found: re.Match[str]) -> bool:
    """True if the plain line has any word besides its block number."""
    return any(found.group(i) is not None for i in range(2, 10))
