"""Editable data tables of the Parameter and Setup areas.

A :class:`DataTable` is a list of rows of :class:`Cell` s; a cell that names a
datum (``R10``, ``$TC_DP3[1,1]``, ``MD32000[X]`` …) can be edited: the area
opens a :class:`hmi.dialogs.ValueDialog` and sends ``WriteData`` to the kernel, which checks
the access level and the limits. :class:`TableCursor` keeps the selected row
and column and the first row on display; :func:`render_table` draws a table as
fixed-width text with the selected cell in inverse video and data the current
access level may not write dimmed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from rich.text import Text
from textual import events
from textual.binding import Binding
from textual.widget import Widget

from hmi.i18n import _


EDIT_BINDINGS = [  # the keys of an editable table (screen bindings)
    Binding("up", "cursor(-1, 0)", "Up", show=False),
    Binding("down", "cursor(1, 0)", "Down", show=False),
    Binding("left", "cursor(0, -1)", "Left", show=False),
    Binding("right", "cursor(0, 1)", "Right", show=False),
    Binding("pageup", "cursor(-20, 0)", "Page up", show=False),
    Binding("pagedown", "cursor(20, 0)", "Page down", show=False),
    Binding("enter", "edit", "Edit", show=False),
]


def typed_on_cell(event: events.Key) -> str | None:
    """The character a key types on the selected cell of an editable table, or None.

    On the control, typing on a selected value starts its input: the typed character
    replaces the value and the input goes on in the field (Enter, Tab and the keymap's
    keys are no characters here; they arrive as bindings).
    """
    character = event.character
    if event.is_printable and character is not None and len(character) == 1 and character.isprintable():
        return character
    return None


def edit_on_typed_key(event: events.Key, edit: Callable[[str], None]) -> None:
    """Start the selected cell's input with the character ``event`` types (see :func:`typed_on_cell`)."""
    typed = typed_on_cell(event)
    if typed is not None:
        event.stop()
        event.prevent_default()
        edit(typed)


@dataclass(frozen=True, slots=True)
class Column:
    """A table column: heading, width in characters, alignment (``<`` or ``>``)."""

    title: str
    width: int
    align: str = ">"


@dataclass(frozen=True, slots=True)
class Cell:
    """One table cell; ``name`` is the datum it shows when it can be edited.

    ``edit_text`` is what the input field starts with; ``level`` the access
    level needed to write it (7 = everybody); ``hint`` a line about the value
    (unit, limits, activation) for the edit dialog.
    """

    text: str
    name: str | None = None
    edit_text: str = ""
    level: int = 7
    hint: str = ""


def widest_text(rows: list[list[Cell]], column: int, at_least: int) -> int:
    """A width for ``column`` that holds the text of each of its cells in ``rows`` (at least
    ``at_least``): for columns of labels or units, whose texts are longer in some languages."""
    return max([at_least] + [len(row[column].text) for row in rows if column < len(row)])


def level_refusal(cell: Cell, access_level: int) -> str:
    """Why ``cell`` cannot be changed at ``access_level`` (above the level it needs), in the panel's language."""
    return _("{name}: needs access level {level} (current level {current})").format(
        name=cell.name, level=cell.level, current=access_level)


@dataclass(slots=True)
class DataTable:
    """Rows of cells under column headings, with a title line and a note below."""

    title: str
    columns: list[Column]
    rows: list[list[Cell]] = field(default_factory=list)
    note: str = ""

    def editable_columns(self) -> list[int]:
        """Indices of the columns that hold at least one editable cell."""
        return [i for i in range(len(self.columns))
                if any(i < len(row) and row[i].name for row in self.rows)]

    def cell(self, row: int, column: int) -> Cell | None:
        """The cell at ``row``/``column`` (None outside the table)."""
        if 0 <= row < len(self.rows) and 0 <= column < len(self.rows[row]):
            return self.rows[row][column]
        return None


@dataclass(slots=True)
class TableCursor:
    """Selected row and column of a table, and its first row on display."""

    row: int = 0
    column: int = -1
    top: int = 0

    def clamp(self, table: DataTable, height: int) -> None:
        """Keep the cursor inside ``table`` and on display in ``height`` rows."""
        self.row = max(0, min(self.row, len(table.rows) - 1))
        editable = table.editable_columns()
        if editable and self.column not in editable:
            later = [c for c in editable if c >= self.column]
            self.column = later[0] if later else editable[-1]
        height = max(height, 1)
        if self.row < self.top:
            self.top = self.row
        elif self.row >= self.top + height:
            self.top = self.row - height + 1
        self.top = max(0, min(self.top, max(len(table.rows) - height, 0)))

    def move(self, table: DataTable, rows: int = 0, columns: int = 0) -> None:
        """Move by ``rows`` and, among the editable columns, by ``columns``."""
        self.row += rows
        editable = table.editable_columns()
        if columns and editable:
            index = editable.index(self.column) if self.column in editable else 0
            self.column = editable[max(0, min(index + columns, len(editable) - 1))]


def _fit(text: str, width: int, align: str) -> str:
    if len(text) > width:
        text = text[: max(width - 1, 0)] + "…"
    return text.rjust(width) if align == ">" else text.ljust(width)


def render_table(table: DataTable, cursor: TableCursor, height: int, level: int,
                 show_cursor: bool = True) -> Text:
    """Draw ``table`` in ``height`` lines (title, heading, rows, note)."""
    text = Text(no_wrap=True, end="")
    text.append(f" {_(table.title)}\n", style="bold")
    heading = " ".join(_fit(_(c.title), c.width, c.align) for c in table.columns)
    text.append(f" {heading}\n", style="bold underline")
    body = max(height - 3, 1)
    cursor.clamp(table, body)
    shown = table.rows[cursor.top: cursor.top + body]
    for offset, row in enumerate(shown):
        index = cursor.top + offset
        text.append(" ")
        for position, (column, cell) in enumerate(zip(table.columns, row)):
            style = ""
            if cell.name and level > cell.level:
                style = "dim"
            if show_cursor and index == cursor.row and (position == cursor.column or (
                    cursor.column < 0 and position == 0)):
                style = "reverse"
            elif show_cursor and index == cursor.row:
                style = (style + " bold").strip()
            text.append(_fit(cell.text, column.width, column.align), style=style)
            text.append(" ")
        text.append("\n")
    if not table.rows:
        text.append(" " + _("(no entries)") + "\n", style="dim")
    for _blank_line in range(body - max(len(shown), 1)):
        text.append("\n")
    more = ""
    if len(table.rows) > body:
        more = _("rows {first}–{last} of {total}").format(
            first=cursor.top + 1, last=cursor.top + len(shown), total=len(table.rows)) + "   "
    text.append(f" {more}{_(table.note)}", style="dim")
    return text


class TableWindow(Widget):
    """A window that draws a :class:`DataTable` in whatever height it has."""

    DEFAULT_CSS = """
    TableWindow { height: 1fr; text-wrap: nowrap; text-overflow: clip; }
    """

    def __init__(self, id: str | None = None) -> None:  # noqa: A002
        super().__init__(id=id)
        self._model: tuple[DataTable, TableCursor, int, bool] | None = None
        self._shown_key: object = None

    def show(self, table: DataTable, cursor: TableCursor, level: int, show_cursor: bool = True) -> None:
        """Draw ``table`` with ``cursor`` for access level ``level`` (at the next repaint).

        Nothing is repainted when table, cursor and level are what the window
        already shows (the areas call this on every kernel snapshot).
        """
        self._model = (table, cursor, level, show_cursor)
        key = (table, cursor.row, cursor.column, cursor.top, level, show_cursor)
        if key == self._shown_key:
            return
        self._shown_key = key
        self.refresh()

    def render(self) -> Text:
        """The table in the window's current height."""
        if self._model is None:
            return Text("")
        table, cursor, level, show_cursor = self._model
        drawn = render_table(table, cursor, self.size.height or 30, level, show_cursor)
        self._shown_key = (table, cursor.row, cursor.column, cursor.top, level, show_cursor)  # clamped
        return drawn
