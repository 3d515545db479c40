"""Parser: one source line of a Siemens-mode program → :class:`nck.lang.ast.Block`.

Block layout: ``[/n] [N123 | :123] [LABEL:] statement… [; comment]``.
Expressions follow the operator priority of the 840D sl (highest first):
``NOT B_NOT`` · ``* / DIV MOD`` · ``+ -`` · ``B_AND`` · ``B_XOR`` · ``B_OR`` ·
``AND`` · ``XOR`` · ``OR`` · ``<<`` · ``== <> < > <= >=``.
Every error is an :class:`NcAlarmError` (12080 syntax error unless a more
specific number applies); nothing else escapes :func:`parse_block`.
"""

from __future__ import annotations

from nck.alarm_ids import BLOCK_TOO_COMPLEX, G_FUNCTION_UNKNOWN, IDENTIFIER_TOO_LONG, NAME_NOT_DEFINED, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.declarations import DeclarationParser
from nck.lang.expressions import (  # noqa: F401 - re-exported vocabulary
    BUILTIN_PROCS, DATA_TYPES, GOTO_KINDS, MAX_NAME_CHARS, MAX_NESTING, RESERVED, SIMPLE_CONTROL,
    VALUE_ADDRESSES, int_literal, syntax_error,
)
from nck.lang.gcodes import named_gcodes, normalize
from nck.lang.lexer import ADDR, EOL, NAME, NUMBER, OP, split_comment, tokenize


LANGUAGE_SWITCHES = ("G290", "G291")  # Siemens / ISO dialect: alone in their block (003 L393)


class BlockParser(DeclarationParser):
    """Recursive-descent parser of the statements of one block."""

    def statement(self, stmts: list[ast.Statement]) -> None:
        tok = self.tok
        if tok.kind == ADDR:
            self._address_statement(stmts)
            return
        if tok.kind != NAME:
            raise syntax_error(tok)
        name = tok.text
        if name == "IF":
            self.advance()
            cond = self.expression()
            if self.tok.kind == NAME and self.tok.text in GOTO_KINDS:
                stmts.append(ast.IfGoto(cond, self._goto()))
            else:
                stmts.append(ast.Control("IF", cond=cond))
            return
        if name == "CASE":
            stmts.append(self._case())
            return
        if name == "REDEF":  # 004 L529-536: attribute redefinition is not offered by this NC
            raise NcAlarmError(NAME_NOT_DEFINED, "REDEF")
        if name in ("WHILE", "UNTIL"):
            self.advance()
            stmts.append(ast.Control(name, cond=self.expression()))
            return
        if name == "REPEATB" or (name == "REPEAT" and self.peek().kind == NAME
                                 and self.peek().text not in RESERVED):
            stmts.append(self._section_repeat())
            return
        if name in SIMPLE_CONTROL:
            self.advance()
            stmts.append(ast.Control(name))
            return
        if name == "FOR":
            self.advance()
            var = self._assign_target()
            self.expect_op("=")
            start = self.expression()
            if not self.is_name("TO"):
                raise syntax_error(self.tok)
            self.advance()
            end = self.expression()
            stmts.append(ast.Control("FOR", var=var, start=start, end=end))
            return
        if name in GOTO_KINDS:
            stmts.append(self._goto())
            return
        if name == "DEF":
            stmts.append(self._def())
            return
        if name == "PROC":
            stmts.append(self._proc())
            return
        if name == "EXTERN":
            stmts.append(self._extern())
            return
        if name in ("STOPRE", "RET", "GOTOS", "SBLOF", "SBLON", "DISPLOF", "DISPLON", "WAITS"):
            self.advance()
            args: tuple[ast.Expr | None, ...] = ()
            if self.is_op("("):
                args = self._arguments()
            stmts.append(ast.Builtin(name, args))
            return
        if name == "CALL":
            self.advance()
            stmts.append(ast.Builtin("CALL", (self.expression(),)))
            return
        if name == "MCALL":
            self.advance()
            stmts.append(ast.ModalCall(self._modal_call_target()))
            return
        if name in ("MSG", "SETAL", "CONTOURTAB"):
            self.advance()
            if not self.is_op("("):
                raise syntax_error(self.tok)
            stmts.append(ast.Builtin(name, self._arguments()))
            return
        if name in RESERVED:
            raise syntax_error(tok)
        self.advance()
        # NAME = value / NAME[i] = value
        if self.is_op("["):
            indices = self._indices()
            self.expect_op("=")
            value = self.expression()
            if name in VALUE_ADDRESSES:
                stmts.append(ast.AddressWord(name, value, indices=indices))
            else:
                stmts.append(ast.Assign(ast.Index(name, indices), value))
            return
        if self.is_op("="):
            self.advance()
            value = self.expression()
            if name in VALUE_ADDRESSES or (len(name) == 1 and name != "R"):
                stmts.append(ast.AddressWord(name, value))
            else:
                stmts.append(ast.Assign(ast.Name(name), value))
            return
        if len(name) == 1:
            # X-5, X+5, X 10: address letter with a signed constant
            if name == "R":
                raise syntax_error(tok)
            stmts.append(self._address_constant(name))
            return
        if name in named_gcodes():
            stmts.append(ast.GWord(name))
            return
        if len(name) > MAX_NAME_CHARS:
            raise NcAlarmError(IDENTIFIER_TOO_LONG, name[:MAX_NAME_CHARS])
        if self.is_op("("):
            stmts.append(ast.Call(name, self._arguments()))
            return
        stmts.append(ast.Call(name))

    def _modal_call_target(self) -> ast.Call | None:
        tok = self.tok
        if tok.kind == EOL:
            return None
        if tok.kind == ADDR and tok.text == "L":
            self.advance()
            number = self.advance()
            if not isinstance(number.value, int):
                raise syntax_error(number, "L" + number.text)
            return ast.Call("L" + number.text)
        if tok.kind == NAME and tok.text not in RESERVED and len(tok.text) > 1:
            self.advance()
            return ast.Call(tok.text, self._arguments() if self.is_op("(") else None)
        raise syntax_error(tok, "MCALL")

    def _address_constant(self, letter: str) -> ast.Statement:
        sign = 1
        if self.tok.kind == OP and self.tok.text in "+-":
            sign = -1 if self.advance().text == "-" else 1
        if self.tok.kind != NUMBER:
            raise syntax_error(self.tok, letter + self.tok.text)
        value = self.advance().value
        if letter == "G":
            raise NcAlarmError(G_FUNCTION_UNKNOWN, f"G{'-' if sign < 0 else ''}{value}")
        return ast.AddressWord(letter, ast.Num(sign * value))  # type: ignore[operator]

    def _address_statement(self, stmts: list[ast.Statement]) -> None:
        letter = self.advance().text
        num = self.advance()
        if self.is_op("="):
            # extended address: R10=, X1=, M2=, S1=, I1=
            self.advance()
            ext = int_literal(num)
            value = self.expression()
            if letter == "R":
                stmts.append(ast.Assign(ast.RParam(ext), value))
            elif letter in "MSHTDF":
                stmts.append(ast.AddressWord(letter, value, ext=ext))
            elif letter in "GNLP":
                raise syntax_error(num, letter + num.text + "=")
            else:
                stmts.append(ast.AddressWord(letter + num.text, value))
            return
        if letter == "G":
            if isinstance(num.value, float):
                raise NcAlarmError(G_FUNCTION_UNKNOWN, "G" + num.text)
            stmts.append(ast.GWord(normalize("G" + num.text)))
            return
        if letter == "L":
            if isinstance(num.value, float):
                raise syntax_error(num, "L" + num.text)
            stmts.append(ast.Call("L" + num.text))
            return
        if letter == "R":
            raise syntax_error(num, "R" + num.text)
        if letter == "N":
            raise syntax_error(num, "N" + num.text)
        stmts.append(ast.AddressWord(letter, ast.Num(num.value)))  # type: ignore[arg-type]

    def _assign_target(self) -> ast.Name | ast.Index | ast.RParam:
        tok = self.tok
        if tok.kind == ADDR and tok.text == "R":
            self.advance()
            return ast.RParam(int_literal(self.advance()))
        if tok.kind == NAME and tok.text not in RESERVED:
            self.advance()
            if self.is_op("["):
                return ast.Index(tok.text, self._indices())
            return ast.Name(tok.text)
        raise syntax_error(tok)


def parse_block(text: str, line: int = 1, inserted: bool = False) -> ast.Block:
    """Parse one source line into a Block; raise NcAlarmError on any error in the line.

    ``inserted``: a block the NC builds itself (the ISO start block), where the language
    switch G291 may share the block with the reset G codes. Nesting deeper than Python's
    stack is alarm 12540; any other exception is a fault of the parser and is not turned
    into an alarm (it fails the tests instead of blaming the program).
    """
    try:
        return _parse_block(text, line, inserted)
    except RecursionError:
        raise NcAlarmError(BLOCK_TOO_COMPLEX, line=line) from None


def _parse_block(text: str, line: int, inserted: bool = False) -> ast.Block:
    stripped = text.strip()
    if stripped.startswith("%"):
        # program header (%MPF123, %_N_PART_MPF): not a block
        return ast.Block(line=line, text=text, comment=stripped)
    code, comment = split_comment(text)
    tokens = tokenize(code)
    parser = BlockParser(tokens)
    skip_level = None
    number = None
    main_block = False
    label = None
    if parser.is_op("/"):
        parser.advance()
        skip_level = 0
        if parser.tok.kind == NUMBER and parser.tok.col == tokens[0].col + 1:
            value = parser.tok.value
            if not isinstance(value, int) or value > 9:
                raise NcAlarmError(SYNTAX_ERROR, "/" + parser.tok.text)
            skip_level = value
            parser.advance()
    for _ in range(2):
        if number is None and parser.tok.kind == ADDR and parser.tok.text == "N":
            parser.advance()
            number = int_literal(parser.advance())
        elif number is None and parser.is_op(":") and parser.peek().kind == NUMBER:
            parser.advance()
            number = int_literal(parser.advance())
            main_block = True
        elif label is None and parser.tok.kind == NAME and parser.is_op(":", 1):
            candidate = parser.tok.text
            if candidate in RESERVED or candidate.startswith("$") or len(candidate) < 2:
                raise syntax_error(parser.tok)
            if len(candidate) > MAX_NAME_CHARS:
                raise NcAlarmError(IDENTIFIER_TOO_LONG, candidate[:MAX_NAME_CHARS])
            label = candidate
            parser.advance()
            parser.advance()
    stmts: list[ast.Statement] = []
    while not parser.at_end():
        parser.statement(stmts)
    _check_single_statements(stmts, inserted)
    return ast.Block(
        line=line,
        text=text,
        skip_level=skip_level,
        number=number,
        main_block=main_block,
        label=label,
        statements=tuple(stmts),
        comment=comment,
    )


def _check_single_statements(stmts: list[ast.Statement], inserted: bool = False) -> None:
    """Control structures, DEF, PROC and EXTERN must stand alone in their block, and so must
    the language switches G290/G291 (ISO dialects manual: "programmed alone in an NC block")."""
    if len(stmts) <= 1:
        return
    for stmt in stmts:
        if isinstance(stmt, (ast.Def, ast.Proc, ast.Extern, ast.Control, ast.SectionRepeat)):
            label = stmt.kind if isinstance(stmt, ast.Control) else type(stmt).__name__.upper()
            raise NcAlarmError(SYNTAX_ERROR, label)
        if isinstance(stmt, ast.GWord) and stmt.code in LANGUAGE_SWITCHES and not inserted:
            raise NcAlarmError(SYNTAX_ERROR, stmt.code)
