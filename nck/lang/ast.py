"""Syntax tree of a Siemens-mode NC block.

A parsed source line is a :class:`Block`: skip level, block number, label and
an ordered tuple of statements. Expressions are small immutable nodes
(:class:`Num`, :class:`Str`, :class:`Name`, :class:`Index`, :class:`Unary`,
:class:`Binary`, :class:`Func`). All names are upper case.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union


# ----------------------------------------------------------------------------- expressions
@dataclass(frozen=True, slots=True)
class Num:
    """A numeric literal (int or float) or TRUE/FALSE (bool)."""

    value: int | float | bool


@dataclass(frozen=True, slots=True)
class Str:
    """A string literal."""

    value: str


@dataclass(frozen=True, slots=True)
class Name:
    """A bare name: a variable, constant, axis name or a parameterless function."""

    name: str


@dataclass(frozen=True, slots=True)
class Index:
    """``NAME[i, j, …]``: R parameter ``R[expr]``, array element, system variable."""

    name: str
    indices: tuple["Expr", ...]


@dataclass(frozen=True, slots=True)
class RParam:
    """``R10`` (constant index) — kept apart from Index for speed and clarity."""

    number: int


@dataclass(frozen=True, slots=True)
class Unary:
    """``-x``, ``+x``, ``NOT x``, ``B_NOT x``."""

    op: str
    operand: "Expr"


@dataclass(frozen=True, slots=True)
class Binary:
    """A binary operation ``left op right``."""

    op: str
    left: "Expr"
    right: "Expr"


@dataclass(frozen=True, slots=True)
class Func:
    """A function call ``NAME(args)`` inside an expression (SIN, AC, IC, …)."""

    name: str
    args: tuple["Expr | None", ...]


Expr = Union[Num, Str, Name, Index, RParam, Unary, Binary, Func]


# ----------------------------------------------------------------------------- statements
@dataclass(frozen=True, slots=True)
class GWord:
    """A G function: ``G1``, ``G90``, ``G641`` or a named one (``BRISK``, ``TRANS``)."""

    code: str


@dataclass(frozen=True, slots=True)
class AddressWord:
    """An address with a value: ``X10``, ``X=R1+5``, ``M2=5``, ``F200``, ``CR=5``.

    ``address`` is the address name (``X``, ``X1``, ``CR``, ``F``); ``ext`` the
    address extension of ``M2=``/``S1=``/``H3=``/``T1=``/``D1=`` style words.
    ``indices`` holds the bracket part of axis-specific words (``FA[X]=100``).
    """

    address: str
    value: Expr
    ext: int | None = None
    indices: tuple[Expr, ...] = ()


@dataclass(frozen=True, slots=True)
class Assign:
    """``target = value`` where target is ``R10``, ``R[e]``, a variable or ``$…`` variable.

    The parser cannot always tell an axis/address word (``X=…``) from a
    variable assignment (``MYVAR=…``); such words are produced as Assign with
    a :class:`Name` target and classified by the interpreter.
    """

    target: Union[Name, Index, RParam]
    value: Expr


@dataclass(frozen=True, slots=True)
class VarDecl:
    """One name of a DEF: dimensions and initial values (list for arrays)."""

    name: str
    dims: tuple[Expr, ...] = ()
    init: tuple[Expr, ...] | None = None
    init_rep: bool = False  # REP(v): fill every element


@dataclass(frozen=True, slots=True)
class Def:
    """``DEF [NCK|CHAN] [APRP n] [APWP n] … type [LLI v] [ULI v] name[dims]=init, …``.

    ``read_level``/``write_level``: protection level for part-program reads/writes of a GUD
    (APRP/APR, APWP/APW); None when not given.
    """

    type: str
    names: tuple[VarDecl, ...]
    scope: str | None = None  # None (LUD/PUD), "NCK" or "CHAN" (GUD)
    string_len: int | None = None
    lower: Expr | None = None
    upper: Expr | None = None
    read_level: int | None = None
    write_level: int | None = None


@dataclass(frozen=True, slots=True)
class ParamDecl:
    """A formal parameter of PROC / EXTERN: ``[VAR] type name[dims]``."""

    type: str
    name: str | None
    by_ref: bool = False
    dims: int = 0


@dataclass(frozen=True, slots=True)
class Proc:
    """``PROC NAME(params) [SAVE] [DISPLOF]`` — first block of a subprogram."""

    name: str
    params: tuple[ParamDecl, ...] = ()
    save: bool = False
    sblof: bool = False  # the whole subprogram is one single-block step
    displof: bool = False  # its blocks are not shown in the block display


@dataclass(frozen=True, slots=True)
class Extern:
    """``EXTERN NAME(type, VAR type, …)``."""

    name: str
    params: tuple[ParamDecl, ...] = ()


@dataclass(frozen=True, slots=True)
class Call:
    """A subprogram call: ``L123``, ``CONTOUR``, ``CONTOUR(1, R5)``; passes via ``P``."""

    name: str
    args: tuple[Expr | None, ...] | None = None


@dataclass(frozen=True, slots=True)
class ModalCall:
    """``MCALL NAME(args)`` / ``MCALL L12``: call after every motion block; ``MCALL`` alone ends it."""

    call: Call | None


@dataclass(frozen=True, slots=True)
class Goto:
    """``GOTOF``/``GOTOB``/``GOTO``/``GOTOC`` to a label, block number or string expression."""

    kind: str
    label: str | None = None
    number: int | None = None
    expr: Expr | None = None

    @property
    def target_text(self) -> str:
        """The target as written (for alarm texts)."""
        if self.label is not None:
            return self.label
        if self.number is not None:
            return f"N{self.number}"
        return "<expr>"


@dataclass(frozen=True, slots=True)
class IfGoto:
    """``IF cond GOTOx target`` (the single-line conditional jump)."""

    cond: Expr
    goto: Goto


@dataclass(frozen=True, slots=True)
class SectionRepeat:
    """Program section repetition.

    ``REPEATB LBL P=n`` repeats the block labelled LBL; ``REPEAT LBL P=n`` the
    blocks from LBL up to the REPEAT block (or up to a block labelled
    ``ENDLABEL``); ``REPEAT LBL1 LBL2 P=n`` the blocks from LBL1 to LBL2.
    """

    single_block: bool
    start: str
    end: str | None = None
    passes: Expr | None = None


@dataclass(frozen=True, slots=True)
class Case:
    """``CASE(expr) OF`` or ``CASE expr OF``: ``c1 GOTOF l1 c2 GOTOF l2 … DEFAULT GOTOF ld``."""

    expr: Expr
    branches: tuple[tuple[Expr, Goto], ...]
    default: Goto | None = None


@dataclass(frozen=True, slots=True)
class Control:
    """A control-structure statement.

    ``kind`` is one of IF, ELSE, ENDIF, WHILE, ENDWHILE, FOR, ENDFOR, LOOP,
    ENDLOOP, REPEAT, UNTIL. ``cond`` for IF/WHILE/UNTIL; FOR has ``var``
    (the loop variable as an assignable target), ``start`` and ``end``.
    """

    kind: str
    cond: Expr | None = None
    var: Union[Name, Index, RParam, None] = None
    start: Expr | None = None
    end: Expr | None = None


@dataclass(frozen=True, slots=True)
class Builtin:
    """A predefined procedure: MSG, SETAL, STOPRE, RET, GOTOS, SBLOF/SBLON, DISPLOF/DISPLON."""

    name: str
    args: tuple[Expr | None, ...] = ()


Statement = Union[GWord, AddressWord, Assign, Def, Proc, Extern, Call, Goto, IfGoto, Case, Control,
                  Builtin, SectionRepeat, ModalCall]


@dataclass(frozen=True, slots=True)
class Block:
    """One parsed NC block (one source line).

    Attributes:
        line: 1-based source line.
        text: the source text (without line end).
        skip_level: None when not skippable, 0 for ``/`` or ``/0``, 1…9 for ``/n``.
        number: the block number of ``N…`` or ``:…``, if any.
        main_block: True for ``:…`` main blocks.
        label: jump label defined in this block, if any.
        statements: the statements in source order.
        comment: the text after ``;``.
    """

    line: int
    text: str
    skip_level: int | None = None
    number: int | None = None
    main_block: bool = False
    label: str | None = None
    statements: tuple[Statement, ...] = field(default_factory=tuple)
    comment: str | None = None

    @property
    def is_empty(self) -> bool:
        """True for blocks with no statements (comments, labels, numbers only)."""
        return not self.statements
