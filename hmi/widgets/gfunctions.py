"""G-function displays: the main groups in a line, and every group in a table."""

from __future__ import annotations

import functools
from typing import Mapping

from rich.table import Table
from rich.text import Text
from textual.widgets import Static

from nck import ISO_MAIN_GROUPS_M, iso_table, localized
from nck.queries import load_toml

from hmi.i18n import _, data_text, language
from hmi.word_help import code_meaning, iso_code_meaning

MAIN_GROUPS = (1, 6, 7, 8, 10, 13, 14, 15)
"""Groups of the G-functions window: motion, plane, TRC, WO, exact stop, unit, dimension, feed."""


def group_meanings() -> dict[int, str]:
    """Group number → meaning, from ``data/gcode/siemens.toml``, in the panel's language."""
    return _group_meanings_in(language())


@functools.cache
def _group_meanings_in(code: str) -> dict[int, str]:
    try:
        table = load_toml("gcode", "siemens.toml")
    except (OSError, ValueError):
        return {}
    return {int(g["number"]): localized(code, "group", g["number"], "meaning", str(g.get("meaning", "")))
            for g in table.get("group", [])}


def iso_group_meanings(dialect: str) -> dict[int, str]:
    """ISO group number → meaning of dialect ``iso-m`` / ``iso-t``, in the panel's language."""
    kind = f"{dialect.replace('-', '_')}_group"
    return {number: data_text(kind, number, "meaning", english)
            for number, english in iso_table(dialect)[1].items()}


def main_groups_line(gcodes: Mapping[int, str], groups: tuple[int, ...] = MAIN_GROUPS) -> Text:
    """The main groups' active codes in one line."""
    text = Text(f" {_('G functions')}  ", style="bold")
    for group in groups:
        text.append(f"{gcodes.get(group, '—'):<8}")
    return text


def all_groups_table(gcodes: Mapping[int, str], meanings: Mapping[int, str] | None = None,
                     iso_dialect: str | None = None) -> Table:
    """Every group with its number, active code and meaning, in two columns.

    Siemens groups (``meanings`` None) say what the active code does where the table knows it
    (the group's meaning otherwise): the same table as the editor's word help
    (:func:`hmi.word_help.code_meaning`), in the panel's language. ``meanings`` are the groups'
    meanings of an ISO dialect (:func:`iso_group_meanings`); with ``iso_dialect`` the active
    ISO codes say what they do (:func:`hmi.word_help.iso_code_meaning`).
    """
    siemens = meanings is None
    meanings = group_meanings() if meanings is None else meanings
    numbers = sorted(set(meanings) | set(gcodes))
    half = (len(numbers) + 1) // 2
    table = Table(expand=True, box=None, padding=(0, 1), show_edge=False)
    for _column_pair in range(2):
        table.add_column(_("Grp"), justify="right", style="bold", width=4)
        table.add_column(_("Active"), style="bold #f39200", width=10)
        table.add_column(_("Meaning"), ratio=1, no_wrap=True, overflow="ellipsis")
    for row in range(half):
        cells: list[str] = []
        for number in (numbers[row], numbers[row + half] if row + half < len(numbers) else None):
            if number is None:
                cells += ["", "", ""]
            else:
                active = gcodes.get(number, "")
                meaning = meanings.get(number, "")
                if siemens and code_meaning(active):
                    meaning = code_meaning(active)
                elif iso_dialect is not None and iso_code_meaning(active, iso_dialect):
                    meaning = iso_code_meaning(active, iso_dialect)
                cells += [str(number), active, meaning]
        table.add_row(*cells)
    return table


class GFunctionsLine(Static):
    """The G-functions window of the main view."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self._key: object = None

    def show(self, gcodes: Mapping[int, str], iso_gcodes: Mapping[int, str] | None = None) -> None:
        """Redraw when the active codes changed (ISO groups while ISO mode is active)."""
        key = tuple(sorted((iso_gcodes or gcodes).items()))
        if key != self._key:
            self._key = key
            if iso_gcodes:
                self.update(main_groups_line(iso_gcodes, ISO_MAIN_GROUPS_M), layout=False)
            else:
                self.update(main_groups_line(gcodes), layout=False)


class GFunctionsTable(Static):
    """All G groups (softkey ``G functions``)."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self._key: object = None

    def show(self, gcodes: Mapping[int, str], iso_gcodes: Mapping[int, str] | None = None) -> None:
        """Redraw when the active codes changed (the ISO table while ISO mode is active)."""
        key = tuple(sorted((iso_gcodes or gcodes).items()))
        if key != self._key:
            self._key = key
            if iso_gcodes:
                dialect = "iso-t" if 16 in iso_gcodes and 8 not in iso_gcodes else "iso-m"
                self.update(all_groups_table(iso_gcodes, iso_group_meanings(dialect), dialect), layout=False)
            else:
                self.update(all_groups_table(gcodes), layout=False)
