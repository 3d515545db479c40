"""Word help: what the word under the editor's cursor means, from the data tables.

A G function shows its meaning, its group and whether it is modal (``data/gcode/siemens.toml``,
the table the G functions screen shows too; on a line read in ISO dialect the same from
``data/gcode/iso_m.toml`` / ``iso_t.toml``); an M function or a system variable its meaning
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
from typing import Callable

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


def _functions_of(table_file: str, key: Callable[[str], str]) -> dict[str, GFunction]:
    """Every member of every G group of ``data/gcode/<table_file>`` by ``key(name)``."""
    table: dict[str, GFunction] = {}
    for group in load_toml("gcode", table_file).get("group", []):
        codes = group.get("codes", {})
        for name in group.get("members", []):
            if name:
                table[key(name)] = GFunction(name, int(group["number"]), str(group.get("meaning", "")),
                                             bool(group.get("modal", True)), str(codes.get(name, "")))
    return table


@functools.cache
def g_functions() -> dict[str, GFunction]:
    """Every member of every Siemens G group by name."""
    return _functions_of("siemens.toml", str)


@functools.cache
def iso_g_functions(dialect: str) -> dict[str, GFunction]:
    """Every member of every G group of ISO dialect ``dialect`` (``iso-m``, ``iso-t``), by its
    normalized name (``G00`` as ``G0``)."""
    return _functions_of(f"{dialect.replace('-', '_')}.toml", normalized)


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


def word_help(word: str, dialect: str = "siemens") -> str:
    """One line saying what ``word`` means in the panel's language (``""`` when no table knows
    it), on a line read in language mode ``dialect`` (``siemens``, ``iso-m``, ``iso-t``)."""
    name = normalized(word)
    if not name:
        return ""
    if dialect != "siemens":
        iso = iso_g_functions(dialect).get(name)
        if iso is not None:
            return _iso_help(iso, dialect)
    g_function = g_functions().get(name) if dialect == "siemens" else None
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


def _iso_help(g_function: GFunction, dialect: str) -> str:
    """``G71: stock removal … — ISO Dialect T group 18 (…), non-modal (this block only)``."""
    modality = _("modal") if g_function.modal else _("non-modal (this block only)")
    group_meaning = data_text(f"{dialect.replace('-', '_')}_group", g_function.group, "meaning",
                              g_function.group_meaning)
    meaning = iso_code_meaning(g_function.name, dialect)
    dialect_name = _("ISO Dialect T") if dialect == "iso-t" else _("ISO Dialect M")
    group = _("group {number} ({meaning})").format(number=g_function.group, meaning=group_meaning)
    return f"{g_function.name}: {meaning} — {dialect_name} {group}, {modality}"


def iso_code_meaning(name: str, dialect: str) -> str:
    """The meaning of ISO code ``name`` (``G00`` or ``G0``) of ``dialect`` (``iso-m``, ``iso-t``)
    in the panel's language (``""`` when the table has none)."""
    g_function = iso_g_functions(dialect).get(normalized(name))
    if g_function is None or not g_function.meaning:
        return ""
    return data_text(f"{dialect.replace('-', '_')}_code", g_function.name, "meaning", g_function.meaning)


def code_meaning(name: str) -> str:
    """The meaning of one G function in the panel's language (``""`` when the table has none)."""
    g_function = g_functions().get(name)
    if g_function is None or not g_function.meaning:
        return ""
    return data_text("code", name, "meaning", g_function.meaning)
