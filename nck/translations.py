"""Operator texts in more than one language: gettext catalogues and per-language data tables.

English is the source language: code writes its texts in English and the data tables
(``data/alarms``, ``data/md``, ``data/gcode``) hold English. Every other language is a
folder ``data/lang/<code>/``:

* ``hmi.po`` — the gettext catalogue of the texts in code (``msgid`` English, ``msgstr``
  the language's text). It is read by :func:`read_po` into a
  :class:`gettext.NullTranslations` subclass, so no compile step and no extra package is
  needed at run time; the result is the same on every machine.
* ``<table>.toml`` — overlays of the data tables, keyed by the entry's identity with the
  same field names as the English entry: ``[alarm.10860] text = "…"`` in ``alarms.toml``,
  ``[md.32000] title = "…"`` in ``md.toml``, ``[group.1] meaning = "…"`` (also ``[code.G1]``,
  ``[iso_m_group.1]``, ``[iso_t_group.1]``, ``[iso_t_code.G71]``) in ``gcode.toml``, ``[key."nc.reset"] label = "…"``
  in ``keymap.toml``, ``[m_function.M3] meaning = "…"`` (also ``[system_variable."$P_F"]``,
  ``[system_variable_prefix."$MN_"]``) in ``words.toml``, ``[cycle_form.CYCLE81] title = "…"``
  and ``[cycle_param."CYCLE81.RTP"] help = "…"``, ``[cycle_sketch.drill] text = "…"``, ``[cycle_menu.drilling] label = "…"``,
  ``[cycle_menu_key."drilling.0"] label = "…"`` (the editor's
  cycle forms) in ``cycles.toml``,
  ``[exercise.<id>] title = "…"`` (also ``level``, ``summary``) and ``[exercise_step."<id>.<step number>"]
  text = "…"`` (also ``hint``) in ``exercises.toml``, ``[refusal.<key>] text = "…"`` (the kernel's
  refusals of operator commands, ``data/refusals.toml``) in ``refusals.toml``.

Pure: reads files below ``data/`` only, keeps no state but caches of those files.
"""

from __future__ import annotations

import ast
import functools
import gettext
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable

from nck.resources import AlarmDefinition, alarm_catalog, alarm_text, data_path, read_table

SOURCE_LANGUAGE = "en"
LANGUAGES: dict[str, str] = {"en": "English", "de": "Deutsch"}
"""Every language of the operator texts by code, with its name in its own language."""

OVERLAY_TABLES: dict[str, str] = {"alarm": "alarms.toml", "md": "md.toml", "group": "gcode.toml",
                                  "code": "gcode.toml", "iso_m_group": "gcode.toml",
                                  "iso_t_group": "gcode.toml", "iso_m_code": "gcode.toml",
                                  "iso_t_code": "gcode.toml", "key": "keymap.toml",
                                  "m_function": "words.toml", "system_variable": "words.toml",
                                  "system_variable_prefix": "words.toml",
                                  "cycle_form": "cycles.toml", "cycle_param": "cycles.toml",
                                  "cycle_sketch": "cycles.toml", "cycle_menu": "cycles.toml",
                                  "cycle_menu_key": "cycles.toml",
                                  "exercise": "exercises.toml", "exercise_step": "exercises.toml",
                                  "refusal": "refusals.toml", "action": "access.toml"}
"""Kind of data entry -> the overlay file in ``data/lang/<code>/`` that translates it."""


class UnknownLanguage(ValueError):
    """A language code that has no texts; ``str()`` names the known ones."""

    def __init__(self, code: str) -> None:
        super().__init__(f"language '{code}' is not available (choose {', '.join(LANGUAGES)})")
        self.code = code


def check_language(code: str) -> str:
    """Return ``code`` when it is a known language; else raise :class:`UnknownLanguage`."""
    if code not in LANGUAGES:
        raise UnknownLanguage(code)
    return code


class PoTranslations(gettext.NullTranslations):
    """A gettext catalogue read from a ``.po`` file (untranslated or fuzzy entries are left out)."""

    def __init__(self, catalog: dict[str, str]) -> None:
        super().__init__()
        self.catalog = catalog

    def gettext(self, message: str) -> str:
        """The translation of ``message``, or ``message`` itself when there is none."""
        return self.catalog.get(message, message)

    def ngettext(self, msgid1: str, msgid2: str, n: int) -> str:
        """Plural forms are not used: the singular or plural English id, translated."""
        return self.gettext(msgid1 if n == 1 else msgid2)


def counted_text(count: int, one: str, many: str, translate: Callable[[str], str] = str) -> str:
    """``one`` for a count of 1, else ``many`` (English texts holding ``{count}``), through
    ``translate``, with the count filled in: "1 program", "2 programs". The languages shown have
    this one rule (English and German: the singular only for 1)."""
    return translate(one if count == 1 else many).replace("{count}", str(count))


def _po_string(line: str) -> str:
    """The text of one quoted ``.po`` string (C escapes as Python's)."""
    value = ast.literal_eval(line)
    if not isinstance(value, str):
        raise ValueError(f"not a .po string: {line!r}")
    return value


def read_po(path: Path) -> dict[str, str]:
    """Parse a ``.po`` file into ``{msgid: msgstr}``.

    Supports what the catalogues use: ``msgid``/``msgstr`` with continuation
    lines, comments, the ``#, fuzzy`` flag (such entries are skipped) and the
    header entry (empty msgid, skipped). Entries with an empty ``msgstr`` are
    kept out too, so an untranslated text falls back to English.
    """
    catalog: dict[str, str] = {}
    msgid: list[str] = []
    msgstr: list[str] = []
    target: list[str] | None = None
    fuzzy = next_fuzzy = False  # the flag comment stands before the entry it marks

    def finish() -> None:
        key, value = "".join(msgid), "".join(msgstr)
        if key and value and not fuzzy:
            catalog[key] = value

    for raw in path.read_text(encoding="utf-8").splitlines():
        line = raw.strip()
        if line.startswith("#,") and "fuzzy" in line:
            next_fuzzy = True
        elif not line or line.startswith("#"):
            continue
        elif line.startswith("msgid "):
            finish()
            msgid, msgstr = [_po_string(line[6:])], []
            fuzzy, next_fuzzy = next_fuzzy, False
            target = msgid
        elif line.startswith("msgstr "):
            msgstr = [_po_string(line[7:])]
            target = msgstr
        elif line.startswith('"') and target is not None:
            target.append(_po_string(line))
        else:
            raise ValueError(f"{path.name}: cannot read line {raw!r}")
    finish()
    return catalog


@functools.cache
def gettext_catalogue(code: str) -> gettext.NullTranslations:
    """The gettext catalogue of language ``code`` (English: the identity)."""
    check_language(code)
    if code == SOURCE_LANGUAGE:
        return gettext.NullTranslations()
    path = data_path("lang", code, "hmi.po")
    return PoTranslations(read_po(path) if path.is_file() else {})


@functools.cache
def overlay(code: str, kind: str) -> dict[str, dict[str, Any]]:
    """The overlay of ``kind`` (a key of :data:`OVERLAY_TABLES`) in language ``code``: key -> fields."""
    check_language(code)
    if code == SOURCE_LANGUAGE:
        return {}
    path = data_path("lang", code, OVERLAY_TABLES[kind])
    if not path.is_file():
        return {}
    table = read_table(path).get(kind, {})
    return {str(key): dict(fields) for key, fields in table.items()}


def localized(code: str, kind: str, key: object, field: str, english: str) -> str:
    """The text ``field`` of entry ``key`` of ``kind`` in language ``code``; ``english`` where none."""
    entry = overlay(code, kind).get(str(key))
    if entry is None:
        return english
    text = entry.get(field)
    return text if isinstance(text, str) and text else english


def alarm_definition(number: int, code: str) -> AlarmDefinition | None:
    """The catalogue's definition of alarm ``number`` with its text in language ``code``."""
    definition = alarm_catalog().get(number)
    if definition is None or code == SOURCE_LANGUAGE:
        return definition
    return replace(definition, text=localized(code, "alarm", number, "text", definition.text))


def alarm_text_in(code: str, number: int, params: tuple[str, ...] | list[str], english: str | None = None) -> str:
    """The text of alarm ``number`` with its parameters (as raised) in language ``code``.

    ``english`` is the text as the kernel formatted it (None: the catalogue's English text
    with ``params``); it is returned for English and for alarms outside the catalogue
    (cycle alarms, unknown numbers).
    """
    if english is None:
        english = alarm_text(number, params)
    if code == SOURCE_LANGUAGE:
        return english
    definition = alarm_definition(number, code)
    if definition is None:
        return english
    return definition.format(params)
