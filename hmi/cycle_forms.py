"""The cycle input forms of the program editor as data: menus, parameters, checks, call lines.

The editor's cycle softkeys (``[menus.*]``) and the forms (``[forms.<CYCLE>]``: title, softkey
label, sketch, parameters with unit, range, default and help) are read from
``data/cycles/cycles.toml``. This module turns field texts into a call line
(``CYCLE81(10,0,1,-10,0)``), reads a call line back into field texts (Recompile), switches the
modal call of a line and says why a value is refused. It holds no widgets.

An empty field is a parameter that is not programmed: the call keeps its place empty
(``CYCLE83(10,0,2,,20)``) and the cycle uses its own default, so a hand-written call with
empty places reads back and writes back unchanged.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from nck import trimmed
from nck.queries import load_toml

from hmi.i18n import _

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]{0,23}$")


@dataclass(frozen=True)
class CycleParam:
    """One parameter of a cycle call: its name, unit, range and help line.

    ``kind`` is ``"number"`` or ``"name"`` (a program name, written in quotes, e.g. the
    contour subprogram of CYCLE95); ``default`` is the text a new call starts with.
    """

    name: str
    unit: str
    help: str
    default: str
    min_value: float | None = None
    max_value: float | None = None
    choices: tuple[int, ...] = ()
    integer: bool = False
    kind: str = "number"

    def range_text(self) -> str:
        """The permitted values as the form shows them."""
        if self.kind == "name":
            return _("program name")
        if self.choices:
            return " / ".join(str(c) for c in self.choices)
        low, high = _limit(self.min_value), _limit(self.max_value)
        if self.integer:
            return _("{low} … {high} whole").format(low=low, high=high)
        return f"{low} … {high}"

    def refusal(self, text: str) -> str | None:
        """Why ``text`` is not a value of this parameter, or None when it is (empty: not programmed)."""
        text = text.strip()
        if self.kind == "name":
            if _NAME.match(text) is None:
                return _("{name}: '{text}' is not a program name (letters, digits, _; 24 at most)").format(
                    name=self.name, text=text)
            return None
        if not text:
            return None
        try:
            value = float(text)
        except ValueError:
            return _("{name}: '{text}' is not a number").format(name=self.name, text=text)
        if self.choices:
            if value not in self.choices:
                return _("{name}: only {values} permitted").format(name=self.name, values=self.range_text())
            return None
        if self.integer and value != int(value):
            return _("{name}: only whole numbers permitted").format(name=self.name)
        if self.min_value is not None and value < self.min_value:
            return _("{name}: value below the lower limit {limit}").format(name=self.name, limit=_limit(self.min_value))
        if self.max_value is not None and value > self.max_value:
            return _("{name}: value above the upper limit {limit}").format(name=self.name, limit=_limit(self.max_value))
        return None

    def argument(self, text: str) -> str:
        """The field text as the call writes it (a checked text: see :meth:`refusal`)."""
        text = text.strip()
        if self.kind == "name":
            return f'"{text.upper()}"'
        return trimmed(float(text)) if text else ""

    def field_text(self, argument: str) -> str | None:
        """The field text of a call's argument; None when the form cannot show it."""
        if self.kind == "name":
            quoted = re.fullmatch(r'"([^"]*)"', argument)
            return quoted[1] if quoted else None
        if not argument:
            return ""
        try:
            float(argument)
        except ValueError:
            return None
        return argument


@dataclass(frozen=True)
class CycleForm:
    """The input form of one cycle."""

    cycle: str
    title: str
    key_label: str
    sketch: str
    params: tuple[CycleParam, ...]
    sketch_name: str = ""
    """The name of the shared sketch in ``[sketches]`` (its translations are keyed by it); empty: own sketch."""

    def defaults(self) -> list[str]:
        """The field texts of a new call."""
        return [p.default for p in self.params]

    def call_line(self, texts: list[str]) -> str:
        """The call with the field texts in the order of the parameters (trailing empties left out)."""
        args = [param.argument(text) for param, text in zip(self.params, texts)]
        while args and not args[-1]:
            args.pop()
        return f"{self.cycle}({','.join(args)})"


@dataclass(frozen=True)
class MenuKey:
    """A vertical softkey of a cycle menu: one cycle (its form), several (a sub-level) or MCALL."""

    label: str
    cycles: tuple[str, ...] = ()
    mcall: bool = False


@dataclass(frozen=True)
class CycleMenu:
    """A horizontal softkey of the editor's cycle level (Drilling, Milling, Turning)."""

    menu_id: str
    label: str
    keys: tuple[MenuKey, ...]
    machine: str = ""

    def cycles(self) -> list[str]:
        """Every cycle of the menu, in the order of its keys."""
        return [cycle for key in self.keys for cycle in key.cycles]


@cache
def cycle_forms() -> dict[str, CycleForm]:
    """Every cycle form of the data, by cycle name."""
    data = load_toml("cycles", "cycles.toml")
    sketches = data.get("sketches", {})
    return {name: _form(name, entry, sketches) for name, entry in data.get("forms", {}).items()}


@cache
def cycle_menus() -> tuple[CycleMenu, ...]:
    """The menus of the cycle level in the data's order; keys of cycles without a form are left out."""
    forms = cycle_forms()
    menus = []
    for menu_id, entry in load_toml("cycles", "cycles.toml").get("menus", {}).items():
        keys = []
        for key in entry["keys"]:
            cycles = tuple(c for c in key.get("cycles", ()) if c in forms)
            if cycles or key.get("mcall"):
                keys.append(MenuKey(key["label"], cycles, bool(key.get("mcall"))))
        menus.append(CycleMenu(menu_id, entry["label"], tuple(keys), entry.get("machine", "")))
    return tuple(menus)


_CALL = re.compile(
    r"^(?P<head>\s*(?:N\d+\s+)?(?P<mcall>MCALL\s+)?)(?P<cycle>[A-Z_][A-Z0-9_]*)\s*\((?P<args>[^()]*)\)"
    r"(?P<tail>\s*(?:;.*)?)$",
    re.IGNORECASE,
)
_MCALL_ONLY = re.compile(r"^(?P<head>\s*(?:N\d+\s+)?)MCALL(?P<tail>\s*(?:;.*)?)$", re.IGNORECASE)


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


def read_call(line: str) -> CallLine | str | None:
    """The call of a cycle with a form on ``line``; a reason when the form cannot show it.

    None: the line calls no cycle that has a form. Empty arguments stay empty (not
    programmed); a value that is not a plain number (a variable, an expression) cannot be
    shown in a form.
    """
    match = _CALL.match(line)
    if match is None:
        return None
    form = cycle_forms().get(match["cycle"].upper())
    if form is None:
        return None
    args = _split_args(match["args"])
    if len(args) > len(form.params):
        return _("{cycle}: more than {count} parameters, the form cannot show the call").format(
            cycle=form.cycle, count=len(form.params))
    texts = [""] * len(form.params) if args else form.defaults()
    for index, arg in enumerate(args):
        text = form.params[index].field_text(arg)
        if text is None:
            return _("{name} = {value} cannot be shown in the form").format(name=form.params[index].name, value=arg)
        texts[index] = text
    return CallLine(form, match["head"], texts, match["tail"])


def called_cycle(line: str) -> str | None:
    """The name of the cycle (upper case) that ``line`` calls, None when it calls none."""
    match = _CALL.match(line)
    return match["cycle"].upper() if match is not None else None


def modal_call_toggled(line: str) -> str | None:
    """``line`` with its modal call switched: a drilling call gets / loses ``MCALL``.

    None when the line holds neither a call of a cycle that may be called modally nor a
    lone ``MCALL`` (the caller inserts a new ``MCALL`` line: modal call off).
    """
    match = _CALL.match(line)
    if match is not None and match["cycle"].upper() in _modal_cycles():
        start, end = match.span("mcall")
        if match["mcall"]:
            return line[:start] + line[end:]
        return f"{line[:match.start('cycle')]}MCALL {line[match.start('cycle'):]}"
    return None


def is_modal_call_off(line: str) -> bool:
    """True when ``line`` is a lone ``MCALL`` (the modal call switched off)."""
    return _MCALL_ONLY.match(line) is not None


@cache
def _modal_cycles() -> frozenset[str]:
    """The cycles of the menus that have a modal call key (the drilling cycles)."""
    drilling = {c for menu in cycle_menus() if any(k.mcall for k in menu.keys) for c in menu.cycles()}
    positions = set(load_toml("cycles", "cycles.toml").get("modal_call", {}).get("passed_into", ()))
    return frozenset(drilling - positions)


def _split_args(args: str) -> list[str]:
    """The arguments of a call, split at the commas outside quotes, stripped."""
    if not args.strip():
        return []
    parts, current, quoted = [], "", False
    for char in args:
        if char == '"':
            quoted = not quoted
        if char == "," and not quoted:
            parts.append(current.strip())
            current = ""
        else:
            current += char
    return [*parts, current.strip()]


def _form(name: str, entry: dict, sketches: dict) -> CycleForm:
    params = tuple(
        CycleParam(
            name=p["name"], unit=p.get("unit", ""), help=p["help"], default=_default_text(p["default"]),
            min_value=p.get("min"), max_value=p.get("max"), choices=tuple(p.get("choices", ())),
            integer=bool(p.get("integer", False)), kind=p.get("kind", "number"),
        )
        for p in entry["params"]
    )
    sketch_name = entry["sketch"] if entry["sketch"] in sketches else ""
    sketch = sketches.get(entry["sketch"], entry["sketch"])
    return CycleForm(name, entry["title"], entry.get("key", name), sketch.strip("\n"), params, sketch_name)


def _default_text(default: float | int | str) -> str:
    return default if isinstance(default, str) else trimmed(default)


def _limit(value: float | None) -> str:
    """A range limit as the form shows it (none: empty)."""
    return "" if value is None else trimmed(value)
