"""Word help: what the word under the editor's cursor means, from the data tables.

A G function shows its meaning, its group and whether it is modal (``data/gcode/siemens.toml``,
the table the G functions screen shows too); an M function or a system variable its meaning
(``data/gcode/words.toml``); a standard cycle its title and parameter list (its input form in
``data/cycles/cycles.toml``). Other words have no help.

The texts are shown in the panel's language: the codes' meanings and the G groups' meanings from
the overlays ``data/lang/<code>/gcode.toml`` (``[code.G1]``, ``[group.1]``), the M functions and
system variables from ``data/lang/<code>/words.toml``; the words around them from the gettext
catalogue.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

from nck.queries import load_toml

from hmi.i18n import _, data_text

_WORD = re.compile(r"\$?[A-Za-z_][A-Za-z0-9_]*")
_NUMBERED = re.compile(r"([GM])0*(\d+)")


@dataclass(frozen=True, slots=True)
class GFunction:
    """One member of a G group: the group's number and meaning, modal or not, its own meaning (English)."""

    name: str
    group: int
    group_meaning: str
    modal: bool
    meaning: str


@functools.cache
def g_functions() -> dict[str, GFunction]:
    """Every member of every Siemens G group by name."""
    table: dict[str, GFunction] = {}
    for group in load_toml("gcode", "siemens.toml").get("group", []):
        codes = group.get("codes", {})
        for name in group.get("members", []):
            if name:
                table[name] = GFunction(name, int(group["number"]), str(group.get("meaning", "")),
                                        bool(group.get("modal", True)), str(codes.get(name, "")))
    return table


@functools.cache
def _words() -> dict:
    return load_toml("gcode", "words.toml")


@functools.cache
def _cycle_forms() -> dict:
    return load_toml("cycles", "cycles.toml").get("forms", {})


def word_at(line: str, column: int) -> str:
    """The word the cursor stands on or right behind (``""`` if none), e.g. ``G1``, ``$AA_IM``."""
    for match in _WORD.finditer(line):
        if match.start() <= column <= match.end():
            return match.group()
    return ""


def normalized(word: str) -> str:
    """Upper case; ``G01`` is ``G1``, ``M03`` is ``M3``."""
    upper = word.upper()
    numbered = _NUMBERED.fullmatch(upper)
    return f"{numbered.group(1)}{int(numbered.group(2))}" if numbered else upper


def word_help(word: str) -> str:
    """One line saying what ``word`` means in the panel's language (``""`` when no table knows it)."""
    name = normalized(word)
    if not name:
        return ""
    g_function = g_functions().get(name)
    if g_function is not None:
        modality = _("modal") if g_function.modal else _("non-modal (this block only)")
        group = _("group {number} ({meaning})").format(
            number=g_function.group,
            meaning=data_text("group", g_function.group, "meaning", g_function.group_meaning))
        meaning = code_meaning(name)
        return f"{name}: {meaning} — {group}, {modality}" if meaning else f"{name}: {group}, {modality}"
    words = _words()
    for kind, section in (("m_function", "m_functions"), ("system_variable", "system_variables")):
        english = words.get(section, {}).get(name)
        if english is not None:
            return f"{name}: {data_text(kind, name, 'meaning', english)}"
    for prefix, english in words.get("system_variable_prefixes", {}).items():
        if name.startswith(prefix):
            return f"{name}: {data_text('system_variable_prefix', prefix, 'meaning', english)}"
    form = _cycle_forms().get(name)
    if form is not None:
        params = ", ".join(str(param["name"]) for param in form.get("params", []))
        title = _("cycle {title}").format(title=data_text("cycle_form", name, "title", form.get("title", "")))
        return f"{name}: {title} — {name}({params})"
    return ""


def code_meaning(name: str) -> str:
    """The meaning of one G function in the panel's language (``""`` when the table has none)."""
    g_function = g_functions().get(name)
    if g_function is None or not g_function.meaning:
        return ""
    return data_text("code", name, "meaning", g_function.meaning)
