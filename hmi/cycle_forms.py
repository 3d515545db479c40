"""The cycle input forms of the program editor as data: parameters, checks, call lines.

The forms (menu, title, sketch, parameters with unit, range, default and help) are read from
``data/cycles/cycles.toml`` (``[forms.<CYCLE>]``). This module turns field texts into a call
line (``CYCLE81(10,0,1,-10,0)``), reads a call line back into field texts (Recompile) and
says why a value is refused. It holds no widgets.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from nck.queries import load_toml


@dataclass(frozen=True)
class CycleParam:
    """One parameter of a cycle call: its name, unit, range and help line."""

    name: str
    unit: str
    help: str
    default: float
    min_value: float | None = None
    max_value: float | None = None
    choices: tuple[int, ...] = ()

    def range_text(self) -> str:
        """The permitted values as the form shows them."""
        if self.choices:
            return " / ".join(str(c) for c in self.choices)
        return f"{_number(self.min_value)} … {_number(self.max_value)}"

    def refusal(self, text: str) -> str | None:
        """Why ``text`` is not a value of this parameter, or None when it is."""
        try:
            value = float(text.strip())
        except ValueError:
            return f"{self.name}: '{text.strip()}' is not a number"
        if self.choices:
            if value not in self.choices:
                return f"{self.name}: only {self.range_text()} permitted"
            return None
        if self.min_value is not None and value < self.min_value:
            return f"{self.name}: value below the lower limit {_number(self.min_value)}"
        if self.max_value is not None and value > self.max_value:
            return f"{self.name}: value above the upper limit {_number(self.max_value)}"
        return None


@dataclass(frozen=True)
class CycleForm:
    """The input form of one cycle."""

    cycle: str
    menu: str
    title: str
    sketch: str
    params: tuple[CycleParam, ...]

    def defaults(self) -> list[str]:
        """The field texts of a new call."""
        return [_number(p.default) for p in self.params]

    def call_line(self, texts: list[str]) -> str:
        """The call with the field texts as numbers, in the order of the parameters."""
        return f"{self.cycle}({','.join(_number(float(t)) for t in texts)})"


@cache
def cycle_forms() -> dict[str, CycleForm]:
    """Every cycle form of the data, by cycle name."""
    forms = load_toml("cycles", "cycles.toml").get("forms", {})
    return {name: _form(name, entry) for name, entry in forms.items()}


def forms_of_menu(menu: str) -> list[CycleForm]:
    """The forms under the editor softkey ``menu`` (``drilling`` …), in the data's order."""
    return [form for form in cycle_forms().values() if form.menu == menu]


_CALL = re.compile(
    r"^(?P<head>\s*(?:N\d+\s+)?(?:MCALL\s+)?)(?P<cycle>[A-Z_][A-Z0-9_]*)\s*\((?P<args>[^()]*)\)"
    r"(?P<tail>\s*(?:;.*)?)$",
    re.IGNORECASE,
)


@dataclass(frozen=True)
class CallLine:
    """A cycle call read from an editor line: what stands around it and the field texts."""

    form: CycleForm
    head: str
    texts: list[str]
    tail: str

    def with_call(self, call: str) -> str:
        """The line with its call replaced by ``call`` (block number, MCALL, comment kept)."""
        return f"{self.head}{call}{self.tail}"


def read_call(line: str, menu: str) -> CallLine | str | None:
    """The call of a form of ``menu`` on ``line``; a reason when the form cannot show it.

    None: the line calls no cycle of this menu (the softkey opens a new form). Empty
    arguments take the default; a value that is not a plain number (a variable, an
    expression) cannot be shown in a form.
    """
    match = _CALL.match(line)
    if match is None:
        return None
    form = cycle_forms().get(match["cycle"].upper())
    if form is None or form.menu != menu:
        return None
    args = [a.strip() for a in match["args"].split(",")] if match["args"].strip() else []
    if len(args) > len(form.params):
        return f"{form.cycle}: more than {len(form.params)} parameters, the form cannot show the call"
    texts = form.defaults()
    for index, arg in enumerate(args):
        if not arg:
            continue
        try:
            float(arg)
        except ValueError:
            return f"{form.params[index].name} = {arg} is not a number: the form cannot show the call"
        texts[index] = arg
    return CallLine(form, match["head"], texts, match["tail"])


def _form(name: str, entry: dict) -> CycleForm:
    params = tuple(
        CycleParam(
            name=p["name"], unit=p.get("unit", ""), help=p["help"], default=float(p["default"]),
            min_value=p.get("min"), max_value=p.get("max"), choices=tuple(p.get("choices", ())),
        )
        for p in entry["params"]
    )
    return CycleForm(name, entry["menu"], entry["title"], entry["sketch"].strip("\n"), params)


def _number(value: float | None) -> str:
    """A value as the call line writes it: no trailing zeros, integers without a point."""
    if value is None:
        return ""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text
