"""Parser: one source line of a Siemens-mode program → :class:`nck.lang.ast.Block`.

Block layout: ``[/n] [N123 | :123] [LABEL:] statement… [; comment]``.
Expressions follow the operator priority of the 840D sl (highest first):
``NOT B_NOT`` · ``* / DIV MOD`` · ``+ -`` · ``B_AND`` · ``B_XOR`` · ``B_OR`` ·
``AND`` · ``XOR`` · ``OR`` · ``<<`` · ``== <> < > <= >=``.
Every error is an :class:`NcAlarmError` (12080 syntax error unless a more
specific number applies); nothing else escapes :func:`parse_block`.
"""

from __future__ import annotations

from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.gcodes import named_gcodes, normalize
from nck.lang.lexer import ADDR, EOL, NAME, NUMBER, OP, STRING, Token, split_comment, tokenize

MAX_NESTING = 32  # parenthesis / bracket depth accepted in one expression
MAX_NAME_CHARS = 31

DATA_TYPES = ("INT", "REAL", "BOOL", "CHAR", "STRING", "AXIS", "FRAME")
GOTO_KINDS = ("GOTOF", "GOTOB", "GOTO", "GOTOC")
SIMPLE_CONTROL = ("ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "LOOP", "ENDLOOP", "REPEAT")
BUILTIN_PROCS = ("MSG", "SETAL", "STOPRE", "RET", "GOTOS", "SBLOF", "SBLON", "DISPLOF", "DISPLON")
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
     "CHF", "CHR", "SF", "SR", "OVR", "OVRA", "ACC")
)

# Binary operator levels, lowest priority first.
_LEVELS: tuple[tuple[str, ...], ...] = (
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


def _syntax(tok: Token, text: str | None = None) -> NcAlarmError:
    return NcAlarmError(12080, text if text is not None else (tok.text or "end of block"))


class _Parser:
    """Recursive-descent parser over the tokens of one block."""

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
            raise _syntax(self.tok)
        self.advance()

    def at_end(self) -> bool:
        return self.tok.kind == EOL

    # -- expressions ---------------------------------------------------------------------
    def expression(self) -> ast.Expr:
        self.depth += 1
        if self.depth > MAX_NESTING:
            raise NcAlarmError(12540)
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
                raise NcAlarmError(12540)
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
                return ast.RParam(_int_literal(num))
            return ast.Name(tok.text + num.text)  # axis literal such as (S1) or X1
        if tok.kind == NAME:
            self.advance()
            name = tok.text
            if name == "TRUE":
                return ast.Num(True)
            if name == "FALSE":
                return ast.Num(False)
            if name in RESERVED and name not in ("AC", "IC"):
                raise _syntax(tok)
            if self.is_op("("):
                return ast.Func(name, self._arguments())
            if self.is_op("["):
                return ast.Index(name, self._indices())
            return ast.Name(name)
        raise _syntax(tok)

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
    def statement(self, stmts: list[ast.Statement]) -> None:
        tok = self.tok
        if tok.kind == ADDR:
            self._address_statement(stmts)
            return
        if tok.kind != NAME:
            raise _syntax(tok)
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
                raise _syntax(self.tok)
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
        if name in ("STOPRE", "RET", "GOTOS", "SBLOF", "SBLON", "DISPLOF", "DISPLON"):
            self.advance()
            args: tuple[ast.Expr | None, ...] = ()
            if self.is_op("("):
                args = self._arguments()
            stmts.append(ast.Builtin(name, args))
            return
        if name in ("MSG", "SETAL"):
            self.advance()
            if not self.is_op("("):
                raise _syntax(self.tok)
            stmts.append(ast.Builtin(name, self._arguments()))
            return
        if name in RESERVED:
            raise _syntax(tok)
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
                raise _syntax(tok)
            stmts.append(self._address_constant(name))
            return
        if name in named_gcodes():
            stmts.append(ast.GWord(name))
            return
        if len(name) > MAX_NAME_CHARS:
            raise NcAlarmError(12420, name[:MAX_NAME_CHARS])
        if self.is_op("("):
            stmts.append(ast.Call(name, self._arguments()))
            return
        stmts.append(ast.Call(name))

    def _address_constant(self, letter: str) -> ast.Statement:
        sign = 1
        if self.tok.kind == OP and self.tok.text in "+-":
            sign = -1 if self.advance().text == "-" else 1
        if self.tok.kind != NUMBER:
            raise _syntax(self.tok, letter + self.tok.text)
        value = self.advance().value
        if letter == "G":
            raise NcAlarmError(12470, f"G{'-' if sign < 0 else ''}{value}")
        return ast.AddressWord(letter, ast.Num(sign * value))  # type: ignore[operator]

    def _address_statement(self, stmts: list[ast.Statement]) -> None:
        letter = self.advance().text
        num = self.advance()
        if self.is_op("="):
            # extended address: R10=, X1=, M2=, S1=, I1=
            self.advance()
            ext = _int_literal(num)
            value = self.expression()
            if letter == "R":
                stmts.append(ast.Assign(ast.RParam(ext), value))
            elif letter in "MSHTDF":
                stmts.append(ast.AddressWord(letter, value, ext=ext))
            elif letter in "GNLP":
                raise _syntax(num, letter + num.text + "=")
            else:
                stmts.append(ast.AddressWord(letter + num.text, value))
            return
        if letter == "G":
            if isinstance(num.value, float):
                raise NcAlarmError(12470, "G" + num.text)
            stmts.append(ast.GWord(normalize("G" + num.text)))
            return
        if letter == "L":
            if isinstance(num.value, float):
                raise _syntax(num, "L" + num.text)
            stmts.append(ast.Call("L" + num.text))
            return
        if letter == "R":
            raise _syntax(num, "R" + num.text)
        if letter == "N":
            raise _syntax(num, "N" + num.text)
        stmts.append(ast.AddressWord(letter, ast.Num(num.value)))  # type: ignore[arg-type]

    def _assign_target(self) -> ast.Name | ast.Index | ast.RParam:
        tok = self.tok
        if tok.kind == ADDR and tok.text == "R":
            self.advance()
            return ast.RParam(_int_literal(self.advance()))
        if tok.kind == NAME and tok.text not in RESERVED:
            self.advance()
            if self.is_op("["):
                return ast.Index(tok.text, self._indices())
            return ast.Name(tok.text)
        raise _syntax(tok)

    def _goto(self) -> ast.Goto:
        kind = self.advance().text
        tok = self.tok
        if tok.kind == ADDR and tok.text == "N":
            self.advance()
            return ast.Goto(kind, number=_int_literal(self.advance()))
        if tok.kind == NAME and tok.text not in RESERVED and not self.is_op("[", 1):
            self.advance()
            return ast.Goto(kind, label=tok.text)
        if tok.kind == EOL:
            raise _syntax(tok)
        return ast.Goto(kind, expr=self.expression())

    def _section_repeat(self) -> ast.SectionRepeat:
        single = self.advance().text == "REPEATB"
        labels: list[str] = []
        while self.tok.kind == NAME and self.tok.text not in RESERVED and not self.is_op("=", 1):
            labels.append(self.advance().text)
        if not labels or len(labels) > (1 if single else 2):
            raise _syntax(self.tok, "REPEAT")
        passes = None
        if self.tok.kind == NAME and self.tok.text == "P" and self.is_op("=", 1):
            self.advance()
            self.advance()
            passes = self.expression()
        elif self.tok.kind == ADDR and self.tok.text == "P":
            self.advance()
            passes = ast.Num(self.advance().value)  # type: ignore[arg-type]
        if not self.at_end():
            raise _syntax(self.tok)
        return ast.SectionRepeat(single, labels[0], labels[1] if len(labels) > 1 else None, passes)

    def _case(self) -> ast.Case:
        self.advance()  # CASE
        self.expect_op("(")
        expr = self.expression()
        self.expect_op(")")
        if not self.is_name("OF"):
            raise _syntax(self.tok)
        self.advance()
        branches: list[tuple[ast.Expr, ast.Goto]] = []
        default = None
        while not self.at_end():
            if self.is_name("DEFAULT"):
                self.advance()
                if not (self.tok.kind == NAME and self.tok.text in GOTO_KINDS):
                    raise _syntax(self.tok)
                default = self._goto()
                if not self.at_end():
                    raise _syntax(self.tok)
                break
            constant = self._unary()
            if not isinstance(constant, (ast.Num, ast.Str)):
                raise _syntax(self.tok, "CASE")
            if not (self.tok.kind == NAME and self.tok.text in GOTO_KINDS):
                raise _syntax(self.tok)
            branches.append((constant, self._goto()))
        if not branches and default is None:
            raise _syntax(self.tok, "CASE")
        return ast.Case(expr, tuple(branches), default)

    def _def(self) -> ast.Def:
        self.advance()  # DEF
        scope = None
        if self.tok.kind == NAME and self.tok.text in ("NCK", "CHAN"):
            scope = self.advance().text
        # access attributes and preprocessing stop attributes (accepted, not enforced)
        while self.tok.kind == NAME and self.tok.text in ("SYNR", "SYNW", "SYNRW", "APRP", "APWP", "APRB", "APWB", "APR", "APW"):
            attr = self.advance().text
            if attr.startswith("AP"):
                self._small_int()
        if not (self.tok.kind == NAME and self.tok.text in DATA_TYPES):
            raise _syntax(self.tok)
        dtype = self.advance().text
        string_len = None
        if dtype == "STRING":
            if not self.is_op("["):
                raise _syntax(self.tok)
            self.advance()
            string_len = self._small_int()
            self.expect_op("]")
            if not 1 <= string_len <= 200:
                raise NcAlarmError(12160, f"STRING[{string_len}]")
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
            raise _syntax(self.tok)
        return ast.Def(dtype, tuple(names), scope, string_len, lower, upper)

    def _small_int(self) -> int:
        tok = self.advance()
        if tok.kind != NUMBER or not isinstance(tok.value, int):
            raise _syntax(tok)
        return tok.value

    def _var_decl(self) -> ast.VarDecl:
        tok = self.tok
        if tok.kind != NAME or tok.text in RESERVED or tok.text.startswith("$"):
            if tok.kind == ADDR:
                raise _syntax(tok, tok.text + self.peek().text)
            raise _syntax(tok)
        name = self.advance().text
        if len(name) > MAX_NAME_CHARS:
            raise NcAlarmError(12420, name[:MAX_NAME_CHARS])
        dims: tuple[ast.Expr, ...] = ()
        if self.is_op("["):
            dims = self._indices()
            if len(dims) > 3:
                raise NcAlarmError(12190, name)
        init = None
        rep = False
        if self.is_op("="):
            self.advance()
            if self.tok.kind == NAME and self.tok.text in ("SET", "REP") and self.is_op("(", 1):
                rep = self.advance().text == "REP"
                values = self._arguments()
                if any(v is None for v in values) or not values:
                    raise _syntax(self.tok)
                init = tuple(v for v in values if v is not None)
            elif dims and self.is_op("("):
                values = self._arguments()
                if any(v is None for v in values) or not values:
                    raise _syntax(self.tok)
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
            raise _syntax(self.tok)
        dtype = self.advance().text
        if dtype == "STRING" and self.is_op("["):
            self.advance()
            self._small_int()
            self.expect_op("]")
        name = None
        if with_name or (self.tok.kind == NAME and self.tok.text not in RESERVED):
            tok = self.tok
            if tok.kind != NAME or tok.text in RESERVED:
                raise _syntax(tok)
            name = self.advance().text
            if len(name) < 2 or name in VALUE_ADDRESSES or name.startswith("$"):
                raise NcAlarmError(12080, name)
        dims = 0
        if self.is_op("["):
            self.advance()
            dims = 1
            while not self.is_op("]"):
                if self.at_end():
                    raise _syntax(self.tok)
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

    def _proc(self) -> ast.Proc:
        self.advance()
        tok = self.tok
        if tok.kind == ADDR and tok.text == "L":
            self.advance()
            name = "L" + self.advance().text
        elif tok.kind == NAME and tok.text not in RESERVED:
            name = self.advance().text
        else:
            raise _syntax(tok)
        params = self._param_list(with_name=True)
        attributes: set[str] = set()
        while self.tok.kind == NAME and self.tok.text in ("SAVE", "DISPLOF", "SBLOF", "DISPLON", "ACTBLOCNO"):
            attributes.add(self.advance().text)
        if not self.at_end():
            raise _syntax(self.tok)
        return ast.Proc(name, params, "SAVE" in attributes, "SBLOF" in attributes,
                        "DISPLOF" in attributes)

    def _extern(self) -> ast.Extern:
        self.advance()
        tok = self.tok
        if tok.kind == ADDR and tok.text == "L":
            self.advance()
            name = "L" + self.advance().text
        elif tok.kind == NAME and tok.text not in RESERVED:
            name = self.advance().text
        else:
            raise _syntax(tok)
        params = self._param_list(with_name=False)
        if not self.at_end():
            raise _syntax(self.tok)
        return ast.Extern(name, params)


def _int_literal(tok: Token) -> int:
    if tok.kind != NUMBER or not isinstance(tok.value, int):
        raise _syntax(tok)
    return tok.value


def parse_block(text: str, line: int = 1) -> ast.Block:
    """Parse one source line into a Block; raise NcAlarmError on any error."""
    try:
        return _parse_block(text, line)
    except NcAlarmError:
        raise
    except RecursionError:
        raise NcAlarmError(12540, line=line) from None
    except (ValueError, OverflowError, TypeError, IndexError) as exc:
        raise NcAlarmError(12080, str(exc)[:20], line=line) from None


def _parse_block(text: str, line: int) -> ast.Block:
    stripped = text.strip()
    if stripped.startswith("%"):
        # program header (%MPF123, %_N_PART_MPF): not a block
        return ast.Block(line=line, text=text, comment=stripped)
    code, comment = split_comment(text)
    tokens = tokenize(code)
    parser = _Parser(tokens)
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
                raise NcAlarmError(12080, "/" + parser.tok.text)
            skip_level = value
            parser.advance()
    for _ in range(2):
        if number is None and parser.tok.kind == ADDR and parser.tok.text == "N":
            parser.advance()
            number = _int_literal(parser.advance())
        elif number is None and parser.is_op(":") and parser.peek().kind == NUMBER:
            parser.advance()
            number = _int_literal(parser.advance())
            main_block = True
        elif label is None and parser.tok.kind == NAME and parser.is_op(":", 1):
            candidate = parser.tok.text
            if candidate in RESERVED or candidate.startswith("$") or len(candidate) < 2:
                raise _syntax(parser.tok)
            if len(candidate) > MAX_NAME_CHARS:
                raise NcAlarmError(12420, candidate[:MAX_NAME_CHARS])
            label = candidate
            parser.advance()
            parser.advance()
    stmts: list[ast.Statement] = []
    while not parser.at_end():
        parser.statement(stmts)
    _check_single_statements(stmts)
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


def _check_single_statements(stmts: list[ast.Statement]) -> None:
    """Control structures, DEF, PROC and EXTERN must stand alone in their block."""
    if len(stmts) <= 1:
        return
    for stmt in stmts:
        if isinstance(stmt, (ast.Def, ast.Proc, ast.Extern, ast.Control, ast.SectionRepeat)):
            label = stmt.kind if isinstance(stmt, ast.Control) else type(stmt).__name__.upper()
            raise NcAlarmError(12080, label)
