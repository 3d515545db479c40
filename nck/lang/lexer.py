"""Lexer for one Siemens-mode NC block (one source line).

The block is upper-cased outside string literals (the language is case
insensitive) and cut into :class:`Token` objects. The one Siemens peculiarity
handled here is the *address word*: a single address letter immediately
followed by a digit or a decimal point (``X10``, ``G1``, ``R5``, ``N20``,
``X.5``) becomes an ``ADDR`` token followed by a ``NUMBER`` token, while a
word whose first two characters are letters or underscores (``GOTOF``,
``MYVAR``, ``$AA_IM``) stays one ``NAME``. This works because user names must
start with two letters/underscores.

Any character that cannot start a token raises alarm 12080 (syntax error).
"""

from __future__ import annotations

import math

import re
from dataclasses import dataclass

from nck.alarm_ids import BLOCK_TOO_COMPLEX, SYNTAX_ERROR, VALUE_RANGE_EXCEEDED
from nck.errors import NcAlarmError

MAX_BLOCK_CHARS = 512  # block length limit of the 840D sl block buffer (alarm 12540)

# Token kinds.
NAME = "NAME"  # identifier, keyword, system variable ($…)
ADDR = "ADDR"  # a single address letter directly followed by a number
NUMBER = "NUMBER"  # numeric literal (value already converted)
STRING = "STRING"  # "…" literal
OP = "OP"  # operator or punctuation
EOL = "EOL"

_TWO_CHAR_OPS = ("==", "<>", "<=", ">=", "<<")
_ONE_CHAR_OPS = "+-*/=<>()[],:"


@dataclass(frozen=True, slots=True)
class Token:
    """One token: kind, text (upper case), value (numbers), column (0-based)."""

    kind: str
    text: str
    value: object = None
    col: int = 0


def _is_name_char(ch: str) -> bool:
    return ch.isascii() and (ch.isalnum() or ch in "_$")


def _read_number(text: str, pos: int) -> tuple[int, float | int]:
    """Read an unsigned number at ``pos``: digits, point, ``EX`` exponent."""
    start = pos
    n = len(text)
    while pos < n and text[pos].isdigit() and text[pos].isascii():
        pos += 1
    is_real = False
    if pos < n and text[pos] == ".":
        is_real = True
        pos += 1
        while pos < n and text[pos].isdigit() and text[pos].isascii():
            pos += 1
    mantissa = text[start:pos]
    if mantissa in (".", ""):
        raise NcAlarmError(SYNTAX_ERROR, text[start:start + 8])
    exponent = 0
    # Exponential notation: 1.874EX8, 8.2EX-3
    if text.startswith("EX", pos):
        p = pos + 2
        sign = 1
        if p < n and text[p] in "+-":
            sign = -1 if text[p] == "-" else 1
            p += 1
        q = p
        while q < n and text[q].isdigit() and text[q].isascii():
            q += 1
        if q == p:
            raise NcAlarmError(SYNTAX_ERROR, text[start:q])
        if q - p > 3:
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, text[start:q])
        exponent = sign * int(text[p:q])
        pos = q
        is_real = True
    if len(mantissa) > 20:
        raise NcAlarmError(VALUE_RANGE_EXCEEDED, mantissa[:20])
    if is_real:
        value: float | int = float(f"{mantissa}e{exponent}")
        if math.isinf(value):  # beyond the REAL range (1EX400): value range exceeded, as a long exponent
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, text[start:pos])
    else:
        value = int(mantissa)
    return pos, value


def _read_radix_constant(text: str, pos: int) -> tuple[int, int]:
    """Read ``'H1F'`` (hex) or ``'B1010'`` (binary) starting at the quote."""
    end = text.find("'", pos + 1)
    if end < 0:
        raise NcAlarmError(SYNTAX_ERROR, text[pos:pos + 10])
    body = text[pos + 1:end]
    try:
        if body[:1] == "H" and 1 < len(body) <= 9:
            return end + 1, int(body[1:], 16)
        if body[:1] == "B" and 1 < len(body) <= 33:
            return end + 1, int(body[1:], 2)
    except ValueError:
        pass
    raise NcAlarmError(SYNTAX_ERROR, text[pos:end + 1])


def split_comment(line: str) -> tuple[str, str | None]:
    """Split a source line into code and the comment after ``;`` (outside strings)."""
    in_string = False
    for index, ch in enumerate(line):
        if ch == '"':
            in_string = not in_string
        elif ch == ";" and not in_string:
            return line[:index], line[index + 1:]
    return line, None


_MAIN_RUN_R = re.compile(r"\$R([0-9]+)")


def _name_tokens(name: str, pos: int) -> list[Token]:
    """The tokens of a name. ``$R<n>`` and ``$R[…]`` are the R parameters written as main-run
    variables (004 L259-266, L305-306); they read as ``R<n>`` and ``R[…]`` (the interpreter
    keeps one store for both)."""
    if name == "$R":
        return [Token(NAME, "R", None, pos)]
    found = _MAIN_RUN_R.fullmatch(name)
    if found is not None:
        digits = found.group(1)
        return [Token(ADDR, "R", None, pos), Token(NUMBER, digits, int(digits), pos + 2)]
    return [Token(NAME, name, None, pos)]


def tokenize(code: str) -> list[Token]:
    """Cut the code part of one block (comment already removed) into tokens.

    Raises NcAlarmError 12080 for characters that cannot start a token and
    12540 for blocks longer than :data:`MAX_BLOCK_CHARS`.
    """
    if len(code) > MAX_BLOCK_CHARS:
        raise NcAlarmError(BLOCK_TOO_COMPLEX)
    if '"' not in code and "'" not in code:
        text = code.translate(_ASCII_UPPER)
        fast = _tokenize_plain(text)
        if fast is not None:
            return fast
        return _tokenize_slow(code, text)
    return _tokenize_slow(code, _upper_outside_strings(code))


# The common tokens of a block without strings, in the order the slow lexer
# decides them: an address word (letter + number) before a name.
_NUMBER_RE = r"[0-9]+(?:\.[0-9]*)?|\.[0-9]+"
_PLAIN_TOKEN = re.compile(
    r"(?P<ws>[ \t\r\f\v]+)"
    rf"|(?P<addr>[A-Z])(?P<anum>{_NUMBER_RE})"
    rf"|(?P<num>{_NUMBER_RE})"
    r"|(?P<name>[A-Z_$][A-Z0-9_$]*)"
    r"|(?P<op>==|<>|<=|>=|<<|[-+*/=<>()\[\],:])"
)


def _plain_number(mantissa: str) -> float | int | None:
    """The value of a number without exponent, or None when the slow path must decide."""
    if len(mantissa) > 20:
        return None
    return float(mantissa) if "." in mantissa else int(mantissa)


def _tokenize_plain(text: str) -> list[Token] | None:
    """Tokens of an upper-cased block without strings, or None for anything unusual.

    Gives exactly the tokens of :func:`_tokenize_slow`; numbers with an ``EX``
    exponent, over-long numbers and characters that are not tokens go to the
    slow path (which also raises the alarms).
    """
    tokens: list[Token] = []
    append = tokens.append
    match = _PLAIN_TOKEN.match
    pos = 0
    n = len(text)
    while pos < n:
        found = match(text, pos)
        if found is None:
            return None
        kind = found.lastgroup
        end = found.end()
        if kind == "anum":
            digits = found.group("anum")
            value = _plain_number(digits)
            if value is None or text.startswith("EX", end):
                return None
            append(Token(ADDR, text[pos], None, pos))
            append(Token(NUMBER, digits, value, pos + 1))
        elif kind == "num":
            digits = found.group("num")
            value = _plain_number(digits)
            if value is None or text.startswith("EX", end):
                return None
            append(Token(NUMBER, digits, value, pos))
        elif kind == "name":
            name = found.group("name")
            if name.startswith("$R"):
                tokens.extend(_name_tokens(name, pos))
            else:
                append(Token(NAME, name, None, pos))
        elif kind == "op":
            append(Token(OP, found.group("op"), None, pos))
        pos = end
    append(Token(EOL, "", None, n))
    return tokens


def _tokenize_slow(code: str, text: str) -> list[Token]:
    """The character-by-character lexer (strings, radix constants, exponents, errors)."""
    tokens: list[Token] = []
    pos = 0
    n = len(code)
    while pos < n:
        ch = text[pos]
        if ch in " \t\r\f\v":
            pos += 1
            continue
        if ch == '"':
            end = text.find('"', pos + 1)
            if end < 0:
                raise NcAlarmError(SYNTAX_ERROR, text[pos:pos + 12])
            tokens.append(Token(STRING, code[pos + 1:end], code[pos + 1:end], pos))
            pos = end + 1
            continue
        if ch == "'":
            new_pos, constant = _read_radix_constant(text, pos)
            tokens.append(Token(NUMBER, text[pos:new_pos], constant, pos))
            pos = new_pos
            continue
        if (ch.isdigit() and ch.isascii()) or (ch == "." and pos + 1 < n and text[pos + 1].isdigit()):
            new_pos, value = _read_number(text, pos)
            tokens.append(Token(NUMBER, text[pos:new_pos], value, pos))
            pos = new_pos
            continue
        if ch.isascii() and (ch.isalpha() or ch in "_$"):
            nxt = text[pos + 1] if pos + 1 < n else ""
            if ch.isalpha() and (nxt.isdigit() and nxt.isascii() or nxt == "."):
                # address letter + number: X10, G1, N20, R5, X.5
                tokens.append(Token(ADDR, ch, None, pos))
                new_pos, value = _read_number(text, pos + 1)
                tokens.append(Token(NUMBER, text[pos + 1:new_pos], value, pos + 1))
                pos = new_pos
                continue
            end = pos + 1
            while end < n and _is_name_char(text[end]):
                end += 1
            tokens.extend(_name_tokens(text[pos:end], pos))
            pos = end
            continue
        two = text[pos:pos + 2]
        if two in _TWO_CHAR_OPS:
            tokens.append(Token(OP, two, None, pos))
            pos += 2
            continue
        if ch in _ONE_CHAR_OPS:
            tokens.append(Token(OP, ch, None, pos))
            pos += 1
            continue
        raise NcAlarmError(SYNTAX_ERROR, _printable(code[pos:pos + 10]))
    tokens.append(Token(EOL, "", None, n))
    return tokens


def _upper_outside_strings(code: str) -> str:
    """Upper-case everything except the contents of string literals."""
    parts = code.split('"')
    for index in range(0, len(parts), 2):
        parts[index] = parts[index].translate(_ASCII_UPPER)
    return '"'.join(parts)


# Only ASCII letters change case, so that columns stay aligned with the source.
_ASCII_UPPER = str.maketrans("abcdefghijklmnopqrstuvwxyz", "ABCDEFGHIJKLMNOPQRSTUVWXYZ")


def _printable(fragment: str) -> str:
    """Make a fragment safe for an alarm text (garbage bytes shown as ?)."""
    return "".join(c if c.isprintable() and c.isascii() else "?" for c in fragment)
