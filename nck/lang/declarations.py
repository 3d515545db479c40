"""Parsing of declarations and block-level structures: DEF, PROC, EXTERN, CASE, REPEAT.

:class:`DeclarationParser` extends the expression parser with the statements
that have a grammar of their own; the block parser (:mod:`nck.lang.parser`)
builds on it.
"""

from __future__ import annotations

from nck.alarm_ids import ARRAY_TOO_MANY_DIMENSIONS, IDENTIFIER_TOO_LONG, SYNTAX_ERROR, VALUE_OUTSIDE_LIMITS, VALUE_RANGE_EXCEEDED
from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.expressions import (
    DATA_TYPES, GOTO_KINDS, MAX_NAME_CHARS, RESERVED, VALUE_ADDRESSES, TokenParser, syntax_error,
)
from nck.lang.lexer import ADDR, NAME, NUMBER


class DeclarationParser(TokenParser):
    """DEF / PROC / EXTERN / CASE / REPEAT on top of :class:`TokenParser`."""

    def _section_repeat(self) -> ast.SectionRepeat:
        single = self.advance().text == "REPEATB"
        labels: list[str] = []
        while self.tok.kind == NAME and self.tok.text not in RESERVED and not self.is_op("=", 1):
            labels.append(self.advance().text)
        if not labels or len(labels) > (1 if single else 2):
            raise syntax_error(self.tok, "REPEAT")
        passes = None
        if self.tok.kind == NAME and self.tok.text == "P" and self.is_op("=", 1):
            self.advance()
            self.advance()
            passes = self.expression()
        elif self.tok.kind == ADDR and self.tok.text == "P":
            self.advance()
            passes = ast.Num(self.advance().value)  # type: ignore[arg-type]
        if not self.at_end():
            raise syntax_error(self.tok)
        return ast.SectionRepeat(single, labels[0], labels[1] if len(labels) > 1 else None, passes)

    def _case(self) -> ast.Case:
        self.advance()  # CASE
        expr = self.expression()  # CASE (<expr>) OF … and CASE <expr> OF … (002 L23209)
        if not self.is_name("OF"):
            raise syntax_error(self.tok)
        self.advance()
        branches: list[tuple[ast.Expr, ast.Goto]] = []
        default = None
        while not self.at_end():
            if self.is_name("DEFAULT"):
                self.advance()
                if not (self.tok.kind == NAME and self.tok.text in GOTO_KINDS):
                    raise syntax_error(self.tok)
                default = self._goto()
                if not self.at_end():
                    raise syntax_error(self.tok)
                break
            constant = self._unary()
            if not isinstance(constant, (ast.Num, ast.Str)):
                raise syntax_error(self.tok, "CASE")
            if not (self.tok.kind == NAME and self.tok.text in GOTO_KINDS):
                raise syntax_error(self.tok)
            branches.append((constant, self._goto()))
        if not branches and default is None:
            raise syntax_error(self.tok, "CASE")
        return ast.Case(expr, tuple(branches), default)

    def _def(self) -> ast.Def:
        self.advance()  # DEF
        scope = None
        if self.tok.kind == NAME and self.tok.text in ("NCK", "CHAN"):
            scope = self.advance().text
        # preprocessing stop attributes (accepted, no effect) and access attributes (004 L415-433):
        # the part-program levels APRP/APWP (APR/APW: part program and OPI) are kept on the DEF;
        # the OPI-only ones APRB/APWB concern the panel's door and are accepted without effect
        read_level = write_level = None
        while self.tok.kind == NAME and self.tok.text in ("SYNR", "SYNW", "SYNRW", "APRP", "APWP", "APRB", "APWB", "APR", "APW"):
            attr = self.advance().text
            if attr.startswith("AP"):
                level = self._small_int()
                if not 0 <= level <= 7:
                    raise NcAlarmError(VALUE_OUTSIDE_LIMITS, f"{attr} {level}")
                if attr in ("APRP", "APR"):
                    read_level = level
                elif attr in ("APWP", "APW"):
                    write_level = level
        if not (self.tok.kind == NAME and self.tok.text in DATA_TYPES):
            raise syntax_error(self.tok)
        dtype = self.advance().text
        string_len = None
        if dtype == "STRING":
            if not self.is_op("["):
                raise syntax_error(self.tok)
            self.advance()
            string_len = self._small_int()
            self.expect_op("]")
            if not 1 <= string_len <= 200:
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, f"STRING[{string_len}]")
        lower = upper = None
        while self.tok.kind == NAME and self.tok.text in ("LLI", "ULI", "PHU"):
            attr = self.advance().text
            value = self._unary()
            if attr == "LLI":
                lower = value
            elif attr == "ULI":
                upper = value
        names = [self._var_decl()]
        while self.is_op(","):
            self.advance()
            names.append(self._var_decl())
        if not self.at_end():
            raise syntax_error(self.tok)
        return ast.Def(dtype, tuple(names), scope, string_len, lower, upper, read_level, write_level)

    def _small_int(self) -> int:
        tok = self.advance()
        if tok.kind != NUMBER or not isinstance(tok.value, int):
            raise syntax_error(tok)
        return tok.value

    def _var_decl(self) -> ast.VarDecl:
        tok = self.tok
        if tok.kind != NAME or tok.text in RESERVED or tok.text.startswith("$"):
            if tok.kind == ADDR:
                raise syntax_error(tok, tok.text + self.peek().text)
            raise syntax_error(tok)
        name = self.advance().text
        if len(name) > MAX_NAME_CHARS:
            raise NcAlarmError(IDENTIFIER_TOO_LONG, name[:MAX_NAME_CHARS])
        dims: tuple[ast.Expr, ...] = ()
        if self.is_op("["):
            dims = self._indices()
            if len(dims) > 3:
                raise NcAlarmError(ARRAY_TOO_MANY_DIMENSIONS, name)
        init = None
        rep = False
        if self.is_op("="):
            self.advance()
            if self.tok.kind == NAME and self.tok.text in ("SET", "REP") and self.is_op("(", 1):
                rep = self.advance().text == "REP"
                values = self._arguments()
                if any(v is None for v in values) or not values:
                    raise syntax_error(self.tok)
                init = tuple(v for v in values if v is not None)
            elif dims and self.is_op("("):
                values = self._arguments()
                if any(v is None for v in values) or not values:
                    raise syntax_error(self.tok)
                init = tuple(v for v in values if v is not None)
            else:
                init = (self.expression(),)
        return ast.VarDecl(name, dims, init, rep)

    def _param_decl(self, with_name: bool) -> ast.ParamDecl:
        by_ref = False
        if self.is_name("VAR"):
            self.advance()
            by_ref = True
        if not (self.tok.kind == NAME and self.tok.text in DATA_TYPES):
            raise syntax_error(self.tok)
        dtype = self.advance().text
        if dtype == "STRING" and self.is_op("["):
            self.advance()
            self._small_int()
            self.expect_op("]")
        name = None
        if with_name or (self.tok.kind == NAME and self.tok.text not in RESERVED):
            tok = self.tok
            if tok.kind != NAME or tok.text in RESERVED:
                raise syntax_error(tok)
            name = self.advance().text
            if len(name) < 2 or name in VALUE_ADDRESSES or name.startswith("$"):
                raise NcAlarmError(SYNTAX_ERROR, name)
        dims = 0
        if self.is_op("["):
            self.advance()
            dims = 1
            while not self.is_op("]"):
                if self.at_end():
                    raise syntax_error(self.tok)
                if self.advance().text == ",":
                    dims += 1
            self.advance()
        return ast.ParamDecl(dtype, name, by_ref, dims)

    def _param_list(self, with_name: bool) -> tuple[ast.ParamDecl, ...]:
        if not self.is_op("("):
            return ()
        self.advance()
        params: list[ast.ParamDecl] = []
        if self.is_op(")"):
            self.advance()
            return ()
        while True:
            params.append(self._param_decl(with_name))
            if self.is_op(","):
                self.advance()
                continue
            self.expect_op(")")
            return tuple(params)

    def _subprogram_name(self) -> str:
        """The name after PROC / EXTERN: an identifier or ``L<number>``."""
        tok = self.tok
        if tok.kind == ADDR and tok.text == "L":
            self.advance()
            return "L" + self.advance().text
        if tok.kind == NAME and tok.text not in RESERVED:
            return self.advance().text
        raise syntax_error(tok)

    def _proc(self) -> ast.Proc:
        self.advance()
        name = self._subprogram_name()
        params = self._param_list(with_name=True)
        attributes: set[str] = set()
        while self.tok.kind == NAME and self.tok.text in ("SAVE", "DISPLOF", "SBLOF", "DISPLON", "ACTBLOCNO"):
            attributes.add(self.advance().text)
        if not self.at_end():
            raise syntax_error(self.tok)
        return ast.Proc(name, params, "SAVE" in attributes, "SBLOF" in attributes,
                        "DISPLOF" in attributes)

    def _extern(self) -> ast.Extern:
        self.advance()
        name = self._subprogram_name()
        params = self._param_list(with_name=False)
        if not self.at_end():
            raise syntax_error(self.tok)
        return ast.Extern(name, params)
