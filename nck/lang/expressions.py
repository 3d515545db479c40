"""Expression parsing and the shared vocabulary of the NC block parser.

:class:`TokenParser` walks the tokens of one block and parses expressions with
the operator priority of the 840D sl (highest first): ``NOT B_NOT`` ·
``* / DIV MOD`` · ``+ -`` · ``B_AND`` · ``B_XOR`` · ``B_OR`` · ``AND`` · ``XOR`` ·
``OR`` · ``<<`` · ``== <> < > <= >=``. It also holds the reserved words and the
addresses that take a value with ``=``.
"""

from __future__ import annotations

from nck.alarm_ids import BLOCK_TOO_COMPLEX, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.lexer import ADDR, EOL, NAME, NUMBER, OP, STRING, Token

MAX_NESTING = 32  # parenthesis / bracket depth accepted in one expression
MAX_NAME_CHARS = 31

DATA_TYPES = ("INT", "REAL", "BOOL", "CHAR", "STRING", "AXIS", "FRAME")
GOTO_KINDS = ("GOTOF", "GOTOB", "GOTO", "GOTOC")
SIMPLE_CONTROL = ("ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "LOOP", "ENDLOOP", "REPEAT")
BUILTIN_PROCS = ("MSG", "SETAL", "STOPRE", "RET", "GOTOS", "SBLOF", "SBLON", "DISPLOF", "DISPLON", "CALL",
                 "MCALL", "WAITS", "CONTOURTAB")
RESERVED = frozenset(
    DATA_TYPES + GOTO_KINDS + SIMPLE_CONTROL + BUILTIN_PROCS
    + ("IF", "WHILE", "FOR", "TO", "UNTIL", "DEF", "PROC", "EXTERN", "AND", "OR", "XOR",
       "NOT", "B_AND", "B_OR", "B_XOR", "B_NOT", "DIV", "MOD", "TRUE", "FALSE", "VAR",
       "SET", "REP", "AC", "IC", "NCK", "CHAN", "LLI", "ULI", "SAVE", "DISPLOF", "CASE", "OF",
       "DEFAULT", "REPEATB")
)
# Addresses that take a value with "=" and are never variables.
VALUE_ADDRESSES = frozenset(
    ("CR", "AR", "RP", "AP", "TURN", "SPOS", "SPOSA", "FA", "LIMS", "ANG", "RND", "RNDM", "RPL",
     "CHF", "CHR", "ADIS", "ADISPOS", "SF", "SR", "OVR", "OVRA", "ACC", "MEAS", "MEAW")
)

# Binary operator levels, lowest priority first.
_LEVELS: tuple[tuple[str, ...], ...] = (
    (":",),  # frame chaining: CTRANS(X,10):CROT(Z,45)
    ("==", "<>", "<", ">", "<=", ">="),
    ("<<",),
    ("OR",),
    ("XOR",),
    ("AND",),
    ("B_OR",),
    ("B_XOR",),
    ("B_AND",),
    ("+", "-"),
    ("*", "/", "DIV", "MOD"),
)


def syntax_error(tok: Token, text: str | None = None) -> NcAlarmError:
    return NcAlarmError(SYNTAX_ERROR, text if text is not None else (tok.text or "end of block"))


class TokenParser:
    """Token cursor and expression parser over the tokens of one block."""

    def __init__(self, tokens: list[Token]) -> None:
        self.tokens = tokens
        self.pos = 0
        self.depth = 0

    # -- token helpers -------------------------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.tokens[self.pos]

    def peek(self, offset: int = 1) -> Token:
        index = min(self.pos + offset, len(self.tokens) - 1)
        return self.tokens[index]

    def advance(self) -> Token:
        tok = self.tokens[self.pos]
        if tok.kind != EOL:
            self.pos += 1
        return tok

    def is_op(self, text: str, offset: int = 0) -> bool:
        tok = self.peek(offset) if offset else self.tok
        return tok.kind == OP and tok.text == text

    def is_name(self, text: str) -> bool:
        return self.tok.kind == NAME and self.tok.text == text

    def expect_op(self, text: str) -> None:
        if not self.is_op(text):
            raise syntax_error(self.tok)
        self.advance()

    def at_end(self) -> bool:
        return self.tok.kind == EOL

    # -- expressions ---------------------------------------------------------------------
    def expression(self) -> ast.Expr:
        self.depth += 1
        if self.depth > MAX_NESTING:
            raise NcAlarmError(BLOCK_TOO_COMPLEX)
        try:
            return self._binary(0)
        finally:
            self.depth -= 1

    def _binary(self, level: int) -> ast.Expr:
        if level == len(_LEVELS):
            return self._unary()
        ops = _LEVELS[level]
        left = self._binary(level + 1)
        while self.tok.kind in (OP, NAME) and self.tok.text in ops:
            op = self.advance().text
            right = self._binary(level + 1)
            left = ast.Binary(op, left, right)
        return left

    def _unary(self) -> ast.Expr:
        tok = self.tok
        if (tok.kind == OP and tok.text in "+-") or (tok.kind == NAME and tok.text in ("NOT", "B_NOT")):
            self.advance()
            self.depth += 1
            if self.depth > MAX_NESTING * 4:
                raise NcAlarmError(BLOCK_TOO_COMPLEX)
            try:
                operand = self._unary()
            finally:
                self.depth -= 1
            if tok.text == "+":
                return operand
            if tok.text == "-" and isinstance(operand, ast.Num) and not isinstance(operand.value, bool):
                return ast.Num(-operand.value)
            return ast.Unary(tok.text, operand)
        return self._primary()

    def _primary(self) -> ast.Expr:
        tok = self.tok
        if tok.kind == NUMBER:
            self.advance()
            return ast.Num(tok.value)  # type: ignore[arg-type]
        if tok.kind == STRING:
            self.advance()
            return ast.Str(str(tok.value))
        if tok.kind == OP and tok.text == "(":
            self.advance()
            inner = self.expression()
            self.expect_op(")")
            return inner
        if tok.kind == ADDR:
            self.advance()
            num = self.advance()
            if tok.text == "R":
                return ast.RParam(int_literal(num))
            return ast.Name(tok.text + num.text)  # axis literal such as (S1) or X1
        if tok.kind == NAME:
            self.advance()
            name = tok.text
            if name == "TRUE":
                return ast.Num(True)
            if name == "FALSE":
                return ast.Num(False)
            if name in RESERVED and not (name in ("AC", "IC", "SET", "REP") and self.is_op("(")):
                raise syntax_error(tok)
            if self.is_op("("):
                return ast.Func(name, self._arguments())
            if self.is_op("["):
                return ast.Index(name, self._indices())
            return ast.Name(name)
        raise syntax_error(tok)

    def _arguments(self) -> tuple[ast.Expr | None, ...]:
        """``( a, , b )`` — empty positions are None (omitted parameters)."""
        self.expect_op("(")
        args: list[ast.Expr | None] = []
        if self.is_op(")"):
            self.advance()
            return ()
        while True:
            if self.is_op(",") or self.is_op(")"):
                args.append(None)
            else:
                args.append(self.expression())
            if self.is_op(","):
                self.advance()
                continue
            self.expect_op(")")
            return tuple(args)

    def _indices(self) -> tuple[ast.Expr, ...]:
        self.expect_op("[")
        items = [self.expression()]
        while self.is_op(","):
            self.advance()
            items.append(self.expression())
        self.expect_op("]")
        return tuple(items)

    # -- statements ----------------------------------------------------------------------

    def _goto(self) -> ast.Goto:
        kind = self.advance().text
        tok = self.tok
        if tok.kind == ADDR and tok.text == "N":
            self.advance()
            return ast.Goto(kind, number=int_literal(self.advance()))
        if tok.kind == NAME and tok.text not in RESERVED and not self.is_op("[", 1):
            self.advance()
            return ast.Goto(kind, label=tok.text)
        if tok.kind == EOL:
            raise syntax_error(tok)
        return ast.Goto(kind, expr=self.expression())


def int_literal(tok: Token) -> int:
    if tok.kind != NUMBER or not isinstance(tok.value, int):
        raise syntax_error(tok)
    return tok.value
