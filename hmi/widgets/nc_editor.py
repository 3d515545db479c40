"""The NC program editor widget: a Textual ``TextArea`` that knows the Siemens NC language.

What it adds to ``TextArea``:

* syntax highlighting of NC blocks (block numbers, G and M words, addresses,
  keywords, labels, variables, strings, comments, skip levels), computed lazily
  per displayed line by a small regular-expression lexer, so a 200,000-line
  program costs nothing until a line is shown;
* error markers: each faulty line gets a red gutter mark and a red underline; the
  screen shows the alarm number and text of the line under the cursor;
* pure helpers the screen uses for the editor softkeys: renumber blocks,
  search, next error.

The lexer here only colours text; whether a block is valid is decided by the
kernel's check (``nck.check``), never by this module.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from collections.abc import Sequence
from typing import Any, Callable, Iterable, Mapping

from rich.segment import Segment
from rich.style import Style
from rich.text import Text
from textual.binding import Binding
from textual.document._document import Document
from textual.document._document_navigator import DocumentNavigator
from textual.document._wrapped_document import WrappedDocument
from textual.document._document import Location
from textual.document._edit import Edit, EditResult
from textual.expand_tabs import get_tab_widths
from textual.geometry import Size
from rich.cells import cell_len
from textual.strip import Strip
from textual.widgets import TextArea

# ---------------------------------------------------------------------------------------------
# Lexing for colours
# ---------------------------------------------------------------------------------------------

NC_KEYWORDS: frozenset[str] = frozenset(
    """
    IF ELSE ENDIF WHILE ENDWHILE FOR TO ENDFOR LOOP ENDLOOP REPEAT UNTIL CASE OF DEFAULT
    GOTO GOTOF GOTOB GOTOC DEF INT REAL BOOL CHAR STRING AXIS FRAME PROC RET EXTERN
    VAR SAVE DISPLOF NOT AND OR XOR B_AND B_OR B_NOT B_XOR DIV MOD MSG SETAL STOPRE
    TRANS ATRANS ROT AROT SCALE ASCALE MIRROR AMIRROR SUPA CFC CFTCP CFIN DIAMON DIAMOF
    TRUE FALSE SIN COS TAN ASIN ACOS ATAN2 SQRT ABS POT TRUNC ROUND LN EXP MINVAL MAXVAL
    SPOS SPOSA WAITS WAITM M17 LUD GUD NCK CHAN ENDPROC G500 G53 G153 REPEATB
    """.split()
)
"""Words of the NC language coloured as keywords (control flow, definitions, functions)."""

NC_ADDRESSES: frozenset[str] = frozenset(
    "A B C D E F H I J K L P Q R S T U V W X Y Z CR AR RP AP TURN SF IP".split()
)
"""Address letters (and multi-letter addresses) whose words are coloured as addresses."""

_TOKEN = re.compile(
    r"""
    (?P<comment>;.*$)
    |(?P<string>"[^"]*"?)
    |(?P<variable>\$[A-Za-z_][A-Za-z0-9_]*)
    |(?P<word>[A-Za-z_][A-Za-z0-9_]*)
    |(?P<number>\d+\.?\d*|\.\d+)
    |(?P<space>\s+)
    |(?P<other>.)
    """,
    re.VERBOSE,
)
_SKIP = re.compile(r"\s*/\d?")
_MAIN_BLOCK = re.compile(r"\s*:\d+")
_ADDRESS_WORD = re.compile(r"([A-Za-z]+?)(\d*)$")

TOKEN_STYLES: dict[str, Style] = {
    "comment": Style(color="#7f8c9a", italic=True),
    "string": Style(color="#e6c07b"),
    "variable": Style(color="#c678dd"),
    "keyword": Style(color="#ff9e3d", bold=True),
    "gword": Style(color="#61afef", bold=True),
    "mword": Style(color="#e5a0ff", bold=True),
    "address": Style(color="#98c379"),
    "number": Style(color="#d7dde8"),
    "block_number": Style(color="#8a93a3"),
    "label": Style(color="#56b6c2", bold=True),
    "skip": Style(color="#ff6b6b"),
}
"""Rich style of each token kind (dark panel background assumed)."""

ERROR_LINE_STYLE = Style(underline=True, color="#ff8080")
ERROR_GUTTER_STYLE = Style(color="#ffffff", bgcolor="#b3261e", bold=True)


def tokenize_line(line: str) -> list[tuple[int, int, str]]:
    """Split one program line into coloured spans ``(start, end, kind)``.

    Kinds are the keys of :data:`TOKEN_STYLES`. Plain identifiers, operators and
    spaces are not returned. Never raises, whatever the text.
    """
    spans: list[tuple[int, int, str]] = []
    position = 0
    skip = _SKIP.match(line)
    if skip:
        spans.append((skip.start() + len(skip.group()) - len(skip.group().lstrip()), skip.end(), "skip"))
        position = skip.end()
    main_block = _MAIN_BLOCK.match(line, position)
    if main_block:
        spans.append((main_block.end() - len(main_block.group().lstrip()), main_block.end(), "block_number"))
        position = main_block.end()
    at_block_start = True  # only block number / label may come first
    for match in _TOKEN.finditer(line, position):
        kind = match.lastgroup
        start, end = match.span()
        if kind == "space":
            continue
        if kind == "word":
            word = match.group().upper()
            rest = line[end:]
            if at_block_start and re.fullmatch(r"N\d+", word):
                spans.append((start, end, "block_number"))
                continue  # a label may still follow the block number
            if at_block_start and rest.startswith(":") and not rest.startswith(":="):
                spans.append((start, end + 1, "label"))
                at_block_start = False
                continue
            at_block_start = False
            if word in NC_KEYWORDS:
                spans.append((start, end, "keyword"))
            elif re.fullmatch(r"G\d+", word):
                spans.append((start, end, "gword"))
            elif re.fullmatch(r"M\d+", word):
                spans.append((start, end, "mword"))
            elif re.fullmatch(r"N\d+", word):
                spans.append((start, end, "block_number"))
            else:
                address = _ADDRESS_WORD.match(word)
                if address and address.group(1) in NC_ADDRESSES:
                    letters_end = start + len(address.group(1))
                    spans.append((start, letters_end, "address"))
                    if letters_end < end:
                        spans.append((letters_end, end, "number"))
            continue
        at_block_start = False
        if kind in ("comment", "string", "variable", "number"):
            spans.append((start, end, kind))
    return spans


def highlight_line(line: str) -> Text:
    """Return ``line`` as a Rich ``Text`` with the NC colours applied."""
    text = Text(line, end="", no_wrap=True)
    for start, end, kind in tokenize_line(line):
        text.stylize(TOKEN_STYLES[kind], start, end)
    return text


# ---------------------------------------------------------------------------------------------
# Editing helpers (pure)
# ---------------------------------------------------------------------------------------------

_BLOCK_NUMBER = re.compile(r"^(?P<lead>\s*(?:/\d?\s*)?)(?P<n>[Nn]\d+\s*)?")
_LEADING_LABEL = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*):(?!=)")
_JUMP_TO_N = re.compile(r"\b(GOTO[FBC]?\s+)[Nn](\d+)", re.IGNORECASE)


def _is_block_line(line: str) -> bool:
    """True if a line holds a block that gets a block number when renumbering."""
    stripped = line.strip()
    if not stripped or stripped.startswith((";", "%")):
        return False
    if _MAIN_BLOCK.match(line):
        return False  # main blocks keep their ":nn" number
    if stripped.split()[0].upper() == "PROC":
        return False
    label = _LEADING_LABEL.match(line)
    return not (label and not re.fullmatch(r"[Nn]\d+", label.group(1)))


def renumber_blocks(text: str, start: int = 10, step: int = 10) -> str:
    """Give every block line a block number ``N<start>``, ``N<start+step>`` … in order.

    Existing block numbers are replaced, blocks without one get one (after a skip
    slash). Empty lines, comment-only lines, ``%`` header lines, ``PROC`` lines,
    main blocks (``:10``) and lines that begin with a label are left alone.
    Jumps to block numbers (``GOTOF N120``) are rewritten to the new numbers.
    """
    lines = text.split("\n")
    mapping: dict[str, str] = {}
    out: list[str] = []
    number = start
    for line in lines:
        if not _is_block_line(line):
            out.append(line)
            continue
        match = _BLOCK_NUMBER.match(line)
        assert match is not None  # the pattern can match the empty string
        lead = match.group("lead")
        old = match.group("n")
        body = line[match.end():]
        if old:
            mapping.setdefault(old.strip().upper()[1:], str(number))
        out.append(f"{lead}N{number} {body}".rstrip() if body.strip() else f"{lead}N{number}")
        number += step

    def rewrite(jump: re.Match[str]) -> str:
        return f"{jump.group(1)}N{mapping.get(jump.group(2), jump.group(2))}"

    return "\n".join(_JUMP_TO_N.sub(rewrite, line) for line in out)


def find_text(
    lines: Iterable[str], query: str, after: tuple[int, int] = (0, -1), wrap: bool = True
) -> tuple[int, int] | None:
    """Find ``query`` (case-insensitive) after position ``after`` = (row, column).

    Returns the (row, column) of the next occurrence, wrapping round to the top
    when ``wrap`` is set, or None.
    """
    if not query:
        return None
    needle = query.upper()
    all_lines = list(lines) if not isinstance(lines, list) else lines
    row0, column0 = after
    for row in range(row0, len(all_lines)):
        first = column0 + 1 if row == row0 else 0
        column = all_lines[row].upper().find(needle, max(first, 0))
        if column >= 0:
            return row, column
    if wrap:
        for row in range(0, min(row0 + 1, len(all_lines))):
            column = all_lines[row].upper().find(needle)
            if column >= 0 and (row, column) != (row0, column0) and (row < row0 or column <= column0):
                return row, column
    return None


# ---------------------------------------------------------------------------------------------
# The widget
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class ErrorMark:
    """An alarm found by the check on one line.

    Attributes:
        line: 0-based line index in the editor.
        number: SINUMERIK alarm number.
        text: formatted alarm text.
    """

    line: int
    number: int
    text: str

    @property
    def label(self) -> str:
        """``12080 Syntax error …`` as shown in the message line."""
        return f"{self.number} {self.text}"


class _NcDocument(Document):
    """``Document`` that joins its lines into ``text`` once per change, not at every call.

    ``TextArea`` asks for the whole text while rendering each line (to decide on
    a placeholder) and the screen compares it with the saved text; on a
    200,000-line program every join costs milliseconds.
    """

    def __init__(self, text: str) -> None:
        super().__init__(text)
        self._joined: str | None = None

    @property
    def text(self) -> str:
        """The document text (joined once per change)."""
        if self._joined is None:
            self._joined = self._newline.join(self._lines)
        return self._joined

    def replace_range(self, start: Location, end: Location, text: str) -> EditResult:
        """Edit the text (see ``Document.replace_range``); the joined text is made again."""
        self._joined = None
        return super().replace_range(start, end, text)


class _IdentityRows(Sequence):
    """Row table of an unwrapped document, where display row ``i`` is line ``i``.

    ``WrappedDocument`` keeps a tuple and a list per line to map rows to lines
    and back (about 150 bytes a line). Without soft wrap the mapping is the
    identity, so the table only needs its length; ``make`` builds the entry of
    a row when asked.
    """

    def __init__(self, count: int, make: Callable[[int], Any]) -> None:
        self._count = count
        self._make = make

    def __len__(self) -> int:
        return self._count

    def __getitem__(self, index: Any) -> Any:
        if isinstance(index, slice):
            return [self._make(row) for row in range(*index.indices(self._count))]
        if index < 0:
            index += self._count
        if not 0 <= index < self._count:
            raise IndexError(index)
        return self._make(index)


def _row_info(row: int) -> tuple[int, int]:
    return (row, 0)


def _row_offsets(row: int) -> list[int]:
    return [row]


_NO_BREAKS: list[int] = []
_ONE_SECTION = [0]
# Shared inner lists: WrappedDocument only ever replaces them, never mutates them.


def _tab_widths(line: str, size: int) -> list[int]:
    if not line:
        return _NO_BREAKS
    if "\t" in line:
        return [width for _, width in get_tab_widths(line, size)]
    return _ONE_SECTION


class _CountedWrappedDocument(WrappedDocument):
    """``WrappedDocument`` that keeps no per-line row tables when nothing is wrapped.

    Textual sums the wrap offsets of every line for each rendered line; on a
    200,000-line program that costs a fifth of a second per line. The row table
    has one entry per display row, so its length is the height. Without soft
    wrap (the NC editor never wraps) the row tables are :class:`_IdentityRows`
    and an edit only updates the tab widths of the lines it touched.
    """

    @property
    def height(self) -> int:
        """The number of display rows."""
        return len(self._offset_to_line_info)

    def _identity_rows(self, count: int) -> None:
        self._offset_to_line_info = _IdentityRows(count, _row_info)  # type: ignore[assignment]
        self._line_index_to_offsets = _IdentityRows(count, _row_offsets)  # type: ignore[assignment]

    def wrap(self, width: int, tab_width: int | None = None) -> None:
        """Without soft wrap every line is one row: build the tables directly (fast path)."""
        if width:
            super().wrap(width, tab_width)
            return
        lines = self.document.lines
        unchanged_tabs = not tab_width or tab_width == self._tab_width
        if (self._width == 0 and unchanged_tabs and isinstance(self._offset_to_line_info, _IdentityRows)
                and len(self._offset_to_line_info) == len(lines) and lines):
            # Already unwrapped, and every edit since went through wrap_range, which keeps
            # the tables current: a resize needs no new tables.
            return
        self._width = 0
        if tab_width:
            self._tab_width = tab_width
        count = len(lines)
        size = self._tab_width
        self._wrap_offsets = [_NO_BREAKS] * count
        self._identity_rows(count)
        self._tab_width_cache = [_tab_widths(line, size) for line in lines]

    def wrap_range(self, start: Location, old_end: Location, new_end: Location) -> None:
        """After an edit: without soft wrap only the edited lines' tab widths change."""
        if self._width or not isinstance(self._offset_to_line_info, _IdentityRows):
            super().wrap_range(start, old_end, new_end)
            return
        lines = self.document.lines
        old_count = len(self._tab_width_cache)
        top = max(0, min(start[0], old_end[0], old_count - 1, len(lines) - 1))
        old_bottom = max(top, min(max(start[0], old_end[0]), old_count - 1))
        new_bottom = max(top, min(max(start[0], new_end[0]), len(lines) - 1))
        size = self._tab_width
        edited = [_tab_widths(line, size) for line in lines[top:new_bottom + 1]]
        self._tab_width_cache[top:old_bottom + 1] = edited
        self._wrap_offsets[top:old_bottom + 1] = [_NO_BREAKS] * len(edited)
        self._identity_rows(len(lines))


def widest_line_cells(lines: Iterable[str], tab_width: int) -> int:
    """Cells of the widest line (tabs expanded); plain ASCII lines are measured by length."""
    widest = 0
    for line in lines:
        if line.isascii() and "\t" not in line and line.isprintable():
            width = len(line)
        else:
            width = cell_len(line.expandtabs(tab_width))
        if width > widest:
            widest = width
    return widest


class NcEditor(TextArea):
    """A ``TextArea`` for NC programs: line numbers, NC colours, error marks in the gutter."""

    DEFAULT_CSS = """
    NcEditor { border: none; padding: 0; }
    """

    BINDINGS = [
        Binding("ctrl+home", "document_start", "Start of program", show=False),
        Binding("ctrl+end", "document_end", "End of program", show=False),
    ]

    def __init__(self, text: str = "", *, read_only: bool = False, **kwargs: object) -> None:
        super().__init__(
            text,
            read_only=read_only,
            show_line_numbers=True,
            soft_wrap=False,
            tab_behavior="focus",
            theme="css",
            **kwargs,  # type: ignore[arg-type]
        )
        self.cursor_blink = False
        self._error_marks: dict[int, ErrorMark] = {}

    def _set_document(self, text: str, language: str | None) -> None:
        """Build a plain-text document (NC colours come from :meth:`get_line`) with fast wrapping."""
        self._highlight_query = None
        self.document = _NcDocument(text)
        self.wrapped_document = _CountedWrappedDocument(self.document, tab_width=self.indent_width)
        self._max_line_cells: int | None = None
        self.navigator = DocumentNavigator(self.wrapped_document)
        self._build_highlight_map()
        self.move_cursor((0, 0))
        self._rewrap_and_refresh_virtual_size()

    def _line_cells(self, row: int) -> int:
        return cell_len(self.document.get_line(row).expandtabs(self.indent_width))

    def _refresh_size(self) -> None:
        """Virtual size without measuring every line after each edit.

        The widest line is measured once per loaded document; edits can only
        widen it (see :meth:`edit`). After deleting the widest line the view just
        keeps a little more room to scroll sideways.
        """
        if self.soft_wrap:
            super()._refresh_size()
            return
        if getattr(self, "_max_line_cells", None) is None:
            self._max_line_cells = widest_line_cells(self.document.lines, self.indent_width)
        row = min(self.cursor_location[0], self.document.line_count - 1)
        width = max(self._max_line_cells, self._line_cells(row) if row >= 0 else 0)
        self._max_line_cells = width
        self.virtual_size = Size(width + self.gutter_width + 1, self.document.line_count)
        self._refresh_scrollbars()

    def edit(self, edit: Edit) -> EditResult:
        """Apply an edit; widen the virtual size if an edited line became the widest."""
        result = super().edit(edit)
        if not self.soft_wrap and getattr(self, "_max_line_cells", None) is not None:
            top = edit.top[0]
            bottom = min(result.end_location[0], self.document.line_count - 1)
            widest = max((self._line_cells(row) for row in range(top, bottom + 1)), default=0)
            if widest > self._max_line_cells:
                self._max_line_cells = widest
                self._refresh_size()
        return result

    def action_document_start(self) -> None:
        """Cursor to the first line."""
        self.move_cursor((0, 0), center=True)

    def action_document_end(self) -> None:
        """Cursor to the end of the last line."""
        self.move_cursor(self.document.end, center=True)

    # -- errors --------------------------------------------------------------------------------

    @property
    def error_marks(self) -> Mapping[int, ErrorMark]:
        """The current error marks by 0-based line index."""
        return self._error_marks

    def set_error_marks(self, marks: Iterable[ErrorMark], replace: bool = True) -> None:
        """Show ``marks`` (replacing the old ones unless ``replace`` is False) and repaint."""
        if replace:
            self._error_marks = {}
        for mark in marks:
            self._error_marks.setdefault(mark.line, mark)
        self._line_cache.clear()
        self.refresh()

    def error_at_cursor(self) -> ErrorMark | None:
        """The error mark of the cursor line, if any."""
        return self._error_marks.get(self.cursor_location[0])

    def next_error_line(self) -> int | None:
        """The first faulty line after the cursor line (wrapping round), or None."""
        if not self._error_marks:
            return None
        row = self.cursor_location[0]
        later = sorted(line for line in self._error_marks if line > row)
        return later[0] if later else min(self._error_marks)

    # -- rendering -----------------------------------------------------------------------------

    def _build_highlight_map(self) -> None:
        """Colours are computed per line in :meth:`get_line`; only drop the render cache."""
        self._line_cache.clear()
        self._highlights.clear()

    def get_line(self, line_index: int) -> Text:
        """Return the line with NC colours (and the error underline) applied."""
        text = highlight_line(self.document.get_line(line_index))
        if line_index in self._error_marks:
            text.stylize(ERROR_LINE_STYLE)
        return text

    def _render_line(self, y: int) -> Strip:
        """Render as ``TextArea`` does, then put the error mark into the gutter."""
        strip = super()._render_line(y)
        if not self._error_marks or not self.show_line_numbers:
            return strip
        scroll_y = self.scroll_offset[1]
        try:
            line_index, section = self.wrapped_document._offset_to_line_info[y + scroll_y]
        except IndexError:
            return strip
        if section != 0 or line_index not in self._error_marks:
            return strip
        width = self.gutter_width
        number = str(line_index + self.line_number_start)
        gutter = Strip([Segment(f"{number:>{width - 2}}! ", ERROR_GUTTER_STYLE)], width)
        return Strip.join([gutter, strip.crop(width, strip.cell_length)])
