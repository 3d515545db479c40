"""Expression evaluation: operators and predefined functions (angles in degrees).

:func:`evaluate` walks an expression tree and asks a :class:`Scope` for
variables. Arithmetic failures (division by zero, SQRT of a negative number,
overflow) raise alarm 14051; type mismatches 12150/14096.
"""

from __future__ import annotations

import math
import re
from typing import Any, Callable, Protocol

from nck.alarm_ids import (
    ARITHMETIC_ERROR, NAME_NOT_DEFINED, NO_VALID_NUMBER, OPERATION_DOES_NOT_FIT_TYPE, STRING_NOT_AN_AXIS,
    STRING_RESULT_TOO_LONG, SYNTAX_ERROR, WRONG_CALL_ARGUMENTS,
)
from nck.errors import NcAlarmError
from nck.geometry import frame_functions
from nck.geometry.planes import Plane
from nck.geometry.frame_vars import COMPONENTS as FRAME_COMPONENTS
from nck.lang.values import (
    Axis, INT_MAX, INT_MIN, round_half_away, to_bool, to_number, to_string,
)
from nck.lang import ast

EQ_REL_TOL = 1e-12  # REAL comparison tolerance (relative), like the NC's "==" on REALs


class Scope(Protocol):
    """What expressions need from the interpreter."""

    def read_r(self, index: Any) -> float:
        """R parameter ``index``."""

    def read_name(self, name: str) -> Any:
        """A bare name: variable, axis name or system variable without index."""

    def read_index(self, name: str, indices: tuple[Any, ...]) -> Any:
        """``NAME[…]``: R[], array element, system variable with index."""

    def is_axis(self, name: str) -> bool:
        """True if ``name`` is an axis or spindle of the channel."""

    def has_name(self, name: str) -> bool:
        """True if a variable ``name`` is defined (ISVAR)."""


def evaluate(expr: ast.Expr, scope: Scope) -> Any:
    """Evaluate ``expr`` in ``scope``."""
    kind = type(expr)
    if kind is ast.Num:
        return expr.value  # type: ignore[union-attr]
    if kind is ast.RParam:
        return scope.read_r(expr.number)  # type: ignore[union-attr]
    if kind is ast.Binary:
        return _binary(expr, scope)  # type: ignore[arg-type]
    if kind is ast.Str:
        return expr.value  # type: ignore[union-attr]
    if kind is ast.Name:
        return scope.read_name(expr.name)  # type: ignore[union-attr]
    if kind is ast.Index:
        values = tuple(_index_value(i, scope) for i in expr.indices)  # type: ignore[union-attr]
        return scope.read_index(expr.name, values)  # type: ignore[union-attr]
    if kind is ast.Unary:
        return _unary(expr, scope)  # type: ignore[arg-type]
    if kind is ast.Func:
        return call_function(expr, scope)  # type: ignore[arg-type]
    raise NcAlarmError(SYNTAX_ERROR, type(expr).__name__)


def _index_value(expr: ast.Expr, scope: Scope) -> Any:
    """An index may be an axis name (``$AA_IM[X]``) — those evaluate to Axis."""
    if isinstance(expr, ast.Name) and scope.is_axis(expr.name) and not scope.has_name(expr.name):
        return Axis(expr.name)
    if isinstance(expr, ast.Name) and expr.name in FRAME_COMPONENTS and not scope.has_name(expr.name):
        return expr.name  # $P_UIFR[1,X,TR]: frame component names
    return evaluate(expr, scope)


def _number(value: Any) -> int | float:
    return to_number(value)


def _checked(value: float | int) -> float | int:
    if isinstance(value, float) and not math.isfinite(value):
        raise NcAlarmError(ARITHMETIC_ERROR)
    if isinstance(value, int) and not INT_MIN <= value <= INT_MAX:
        return float(value)
    return value


def _unary(expr: ast.Unary, scope: Scope) -> Any:
    value = evaluate(expr.operand, scope)
    if expr.op == "-":
        return _checked(-_number(value))
    if expr.op == "NOT":
        return not to_bool(value)
    if expr.op == "B_NOT":
        return ~_int(value)
    return value


def _int(value: Any) -> int:
    number = _number(value)
    if isinstance(number, float):
        if not math.isfinite(number) or abs(number) > 2**53:
            raise NcAlarmError(ARITHMETIC_ERROR)
        return round_half_away(number)
    return number


def equal(a: Any, b: Any) -> bool:
    """The NC's "==": strings by text, numbers with the REAL tolerance."""
    if isinstance(a, str) or isinstance(b, str):
        if isinstance(a, str) and isinstance(b, str):
            return a == b
        if isinstance(a, str) and len(a) == 1 and isinstance(b, int):
            return ord(a) == b
        if isinstance(b, str) and len(b) == 1 and isinstance(a, int):
            return ord(b) == a
        raise NcAlarmError(OPERATION_DOES_NOT_FIT_TYPE, "==")
    x, y = _number(a), _number(b)
    if isinstance(x, float) or isinstance(y, float):
        return math.isclose(x, y, rel_tol=EQ_REL_TOL, abs_tol=1e-12)
    return x == y


def _compare(op: str, a: Any, b: Any) -> bool:
    if op == "==":
        return equal(a, b)
    if op == "<>":
        return not equal(a, b)
    if isinstance(a, str) and isinstance(b, str):
        x: Any = a
        y: Any = b
    else:
        x, y = _number(a), _number(b)
    if op == "<":
        return x < y
    if op == ">":
        return x > y
    if op == "<=":
        return x <= y or equal(a, b)
    return x >= y or equal(a, b)


def _binary(expr: ast.Binary, scope: Scope) -> Any:
    op = expr.op
    left = evaluate(expr.left, scope)
    right = evaluate(expr.right, scope)
    if op == ":":  # frame chaining
        return frame_functions.chain(left, right)
    if op == "+":
        return _checked(_number(left) + _number(right))
    if op == "-":
        return _checked(_number(left) - _number(right))
    if op == "*":
        return _checked(_number(left) * _number(right))
    if op == "/":
        divisor = _number(right)
        if divisor == 0:
            raise NcAlarmError(ARITHMETIC_ERROR)
        return _checked(float(_number(left)) / divisor)
    if op == "DIV":
        a, b = _int(left), _int(right)
        if b == 0:
            raise NcAlarmError(ARITHMETIC_ERROR)
        quotient = abs(a) // abs(b)
        return quotient if (a >= 0) == (b >= 0) else -quotient
    if op == "MOD":
        a_num, b_num = _number(left), _number(right)
        if b_num == 0:
            raise NcAlarmError(ARITHMETIC_ERROR)
        result = math.fmod(a_num, b_num)
        if isinstance(a_num, int) and isinstance(b_num, int):
            return int(result)
        return result
    if op in ("==", "<>", "<", ">", "<=", ">="):
        return _compare(op, left, right)
    if op == "AND":
        return to_bool(left) and to_bool(right)
    if op == "OR":
        return to_bool(left) or to_bool(right)
    if op == "XOR":
        return to_bool(left) != to_bool(right)
    if op == "B_AND":
        return _int(left) & _int(right)
    if op == "B_OR":
        return _int(left) | _int(right)
    if op == "B_XOR":
        return _int(left) ^ _int(right)
    if op == "<<":
        return to_string(left) + to_string(right)
    raise NcAlarmError(SYNTAX_ERROR, op)


# ----------------------------------------------------------------------------- functions
def _deg(f: Callable[[float], float]) -> Callable[[float], float]:
    return lambda x: f(math.radians(x))


def _arc(f: Callable[[float], float]) -> Callable[[float], float]:
    def wrapped(x: float) -> float:
        if not -1.0 - 1e-12 <= x <= 1.0 + 1e-12:
            raise NcAlarmError(ARITHMETIC_ERROR)
        return math.degrees(f(max(-1.0, min(1.0, x))))
    return wrapped


def _sqrt(x: float) -> float:
    if x < 0:
        raise NcAlarmError(ARITHMETIC_ERROR)
    return math.sqrt(x)


def _ln(x: float) -> float:
    if x <= 0:
        raise NcAlarmError(ARITHMETIC_ERROR)
    return math.log(x)


def _tan(x: float) -> float:
    if abs(math.cos(math.radians(x))) < 1e-15:
        raise NcAlarmError(ARITHMETIC_ERROR)
    return math.tan(math.radians(x))


def _exp(x: float) -> float:
    if x > 709:
        raise NcAlarmError(ARITHMETIC_ERROR)
    return math.exp(x)


def _trunc(x: float) -> float:
    return float(math.trunc(x))


def _round(x: float) -> float:
    return float(round_half_away(x))


def _roundup(x: float) -> float:
    return float(math.ceil(x)) if x >= 0 else float(math.floor(x))


ONE_ARG: dict[str, Callable[[float], float]] = {
    "SIN": _deg(math.sin),
    "COS": _deg(math.cos),
    "TAN": _tan,
    "ASIN": _arc(math.asin),
    "ACOS": _arc(math.acos),
    "ATAN": lambda x: math.degrees(math.atan(x)),
    "SQRT": _sqrt,
    "ABS": abs,
    "POT": lambda x: x * x,
    "TRUNC": _trunc,
    "ROUND": _round,
    "ROUNDUP": _roundup,
    "LN": _ln,
    "EXP": _exp,
}


def _atan2(y: float, x: float) -> float:
    return math.degrees(math.atan2(y, x))


TWO_ARG: dict[str, Callable[[float, float], float]] = {
    "ATAN2": _atan2,
    "MINVAL": min,
    "MAXVAL": max,
}


def call_function(expr: ast.Func, scope: Scope) -> Any:
    """Evaluate a predefined function (alarm 12550 for unknown names)."""
    name = expr.name
    args = expr.args
    if any(a is None for a in args):
        raise NcAlarmError(SYNTAX_ERROR, name)
    if name in ("SET", "REP"):
        # Only meaningful as the whole right side of an array assignment (handled there).
        raise NcAlarmError(SYNTAX_ERROR, name)
    if name in ("AC", "IC"):
        # Only meaningful as an address value; the interpreter handles that case.
        raise NcAlarmError(SYNTAX_ERROR, name)
    if name in frame_functions.NAMES:  # CTRANS(X,10), CROT(Z,45), … → FRAME value
        return frame_functions.call(name, [_index_value(a, scope) for a in args],  # type: ignore[arg-type]
                                    frame_functions_length_mm(scope), _active_plane(scope))
    if name in ONE_ARG:
        _arity(name, args, 1)
        return _checked(ONE_ARG[name](float(_number(evaluate(args[0], scope)))))  # type: ignore[arg-type]
    if name in TWO_ARG:
        _arity(name, args, 2)
        a = float(_number(evaluate(args[0], scope)))  # type: ignore[arg-type]
        b = float(_number(evaluate(args[1], scope)))  # type: ignore[arg-type]
        return _checked(TWO_ARG[name](a, b))
    if name == "BOUND":
        _arity(name, args, 3)
        low, high, value = (float(_number(evaluate(a, scope))) for a in args)  # type: ignore[arg-type]
        if low > high:
            raise NcAlarmError(ARITHMETIC_ERROR)
        return min(max(value, low), high)
    if name == "STRLEN":
        _arity(name, args, 1)
        return len(to_string(evaluate(args[0], scope)))  # type: ignore[arg-type]
    if name in ("TOUPPER", "TOLOWER"):
        _arity(name, args, 1)
        text = to_string(evaluate(args[0], scope))  # type: ignore[arg-type]
        return text.upper() if name == "TOUPPER" else text.lower()
    if name == "NUMBER":
        _arity(name, args, 1)
        text = to_string(evaluate(args[0], scope)).strip()  # type: ignore[arg-type]
        try:
            value = float(text)
        except ValueError:
            raise NcAlarmError(NO_VALID_NUMBER, text[:20]) from None
        return _checked(value)
    if name == "ISNUMBER":
        _arity(name, args, 1)
        try:
            return math.isfinite(float(to_string(evaluate(args[0], scope)).strip()))  # type: ignore[arg-type]
        except ValueError:
            return False
    if name == "SUBSTR":
        if len(args) not in (2, 3):
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
        text = to_string(evaluate(args[0], scope))  # type: ignore[arg-type]
        start = _int(evaluate(args[1], scope))  # type: ignore[arg-type]
        length = _int(evaluate(args[2], scope)) if len(args) == 3 else len(text)  # type: ignore[arg-type]
        if start < 0 or length < 0:
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
        return text[start:start + length]
    if name == "INDEX":
        _arity(name, args, 2)
        text = to_string(evaluate(args[0], scope))  # type: ignore[arg-type]
        char = to_string(evaluate(args[1], scope))  # type: ignore[arg-type]
        return text.find(char[:1]) if char else -1
    if name == "AXNAME":
        _arity(name, args, 1)
        text = to_string(evaluate(args[0], scope)).upper()  # type: ignore[arg-type]
        if not scope.is_axis(text):
            raise NcAlarmError(STRING_NOT_AN_AXIS, text[:20])
        return Axis(text)
    if name == "AXSTRING":
        _arity(name, args, 1)
        return str(evaluate(args[0], scope))  # type: ignore[arg-type]
    if name == "ISVAR":
        _arity(name, args, 1)
        return scope.has_name(to_string(evaluate(args[0], scope)).upper())  # type: ignore[arg-type]
    if name == "ISAXIS":
        _arity(name, args, 1)
        index = _int(evaluate(args[0], scope))  # type: ignore[arg-type]
        axes = [n for n in ("X", "Y", "Z") if scope.is_axis(n)]
        return 1 <= index <= len(axes)
    if name == "SPRINT":
        if not args:
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
        return sprint(to_string(evaluate(args[0], scope)),  # type: ignore[arg-type]
                      [evaluate(a, scope) for a in args[1:]])  # type: ignore[arg-type]
    raise NcAlarmError(NAME_NOT_DEFINED, name)


_FORMAT = re.compile(r"%(\.(\d+))?([DFSBEXRC%])")
SPRINT_MAX_CHARS = 400  # longest SPRINT result (14099 beyond)


def sprint(template: str, values: list[Any]) -> str:
    """SPRINT: ``%D`` integer, ``%F`` real (``%.2F`` decimals, default 6), ``%S`` string,
    ``%B`` TRUE/FALSE, ``%E`` exponent, ``%X`` hex, ``%R`` real as written, ``%C`` char."""
    remaining = list(values)

    def take() -> Any:
        if not remaining:
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, "SPRINT")
        return remaining.pop(0)

    def replace(match: re.Match) -> str:
        digits, code = match.group(2), match.group(3)
        if code == "%":
            return "%"
        if digits is not None and (len(digits) > 3 or int(digits) > SPRINT_MAX_CHARS):
            raise NcAlarmError(STRING_RESULT_TOO_LONG, "SPRINT")  # the result could not fit: refused before it is built
        value = take()
        if code == "D":
            return str(_int(value))
        if code == "F":
            return f"{float(_number(value)):.{int(digits) if digits else 6}f}"
        if code == "E":
            return f"{float(_number(value)):.{int(digits) if digits else 6}E}"
        if code == "X":
            return f"{_int(value):X}"
        if code == "B":
            return "TRUE" if to_bool(value) else "FALSE"
        if code == "C":
            return chr(_int(value) % 256) if not isinstance(value, str) else value[:1]
        return to_string(value)

    text = _FORMAT.sub(replace, template)
    if remaining:
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, "SPRINT")
    if len(text) > SPRINT_MAX_CHARS:
        raise NcAlarmError(STRING_RESULT_TOO_LONG, "SPRINT")
    return text


def _arity(name: str, args: tuple, count: int) -> None:
    if len(args) != count:
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)


def _active_plane(scope: Scope) -> Plane | None:
    """The active working plane for CRPL(0, …); None without an interpreter."""
    interp: Any = getattr(scope, "interp", None)
    builder = getattr(interp, "builder", None)
    if builder is None:
        return None
    return builder.path.plane(interp.modal)


def frame_functions_length_mm(scope: Scope) -> float:
    """mm per programmed length unit (G70/G700) for frame functions; 1 without an interpreter."""
    interp: Any = getattr(scope, "interp", None)
    builder = getattr(interp, "builder", None)
    if builder is None:
        return 1.0
    return builder.path.units(interp.modal).position_mm
