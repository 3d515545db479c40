"""Build the interpreter's program lines from an ISO text (hook for ``load_program``)."""

from __future__ import annotations

import re
from typing import Callable

from nck.errors import NcAlarmError
from nck.iso import ISO_DIALECTS
from nck.iso.translate import translate
from nck.iso.words import IsoSettings
from nck.iso.skipping import AlarmBlock
from nck.lang.lines import Line
from nck.lang.parser import parse_block

_SWITCH_TO_ISO = re.compile(r"(?<![A-Z0-9_])G291(?![0-9])", re.IGNORECASE)
_PROC_FIRST = re.compile(r"^\s*(N\d+\s+)?PROC\b", re.IGNORECASE)
_NUMBERED_PROC = re.compile(r"^(\s*(?:N\d+\s+)?PROC\s+)O?(\d+)\b", re.IGNORECASE)


def wants_iso(text: str, dialect: str) -> bool:
    """True if ``text`` must go through the ISO translator.

    ISO mode translates every program except Siemens ones whose first line is
    ``PROC`` (cycles, macros written in Siemens); Siemens mode translates a
    program that switches to ISO with G291.
    """
    if dialect in ISO_DIALECTS:
        first = next((line for line in text.splitlines() if line.strip()), "")
        return not _PROC_FIRST.match(first) or bool(_NUMBERED_PROC.match(first))
    return bool(_SWITCH_TO_ISO.search(text))


def iso_lines(name: str, text: str, dialect: str, settings: IsoSettings | None,
              located: Callable[[NcAlarmError, str, int, int | None], NcAlarmError],
              guess_n: Callable[[str], int | None], main: bool = False,
              switch_dialect: str = "iso-m") -> list[Line]:
    """The program's :class:`~nck.lang.lines.Line` list, one or more per ISO line.

    ``dialect`` is the language mode (``siemens``: a text switching with G291 into
    ``switch_dialect``)."""
    lines: list[Line] = []
    iso = dialect in ISO_DIALECTS
    if iso and _numbered_proc_lines(text, name, located, guess_n, lines):
        return lines
    for iso_line in translate(text, dialect if iso else switch_dialect, settings,
                              start_in_iso=iso, main=main and iso):
        number, raw = iso_line.number, iso_line.text
        if iso_line.error is not None:
            lines.append(Line(number, raw, None, located(iso_line.error, name, number, guess_n(raw))))
            continue
        for block_text in iso_line.blocks or [""]:
            if isinstance(block_text, AlarmBlock):  # mid-block /n: the alarm of the whole block
                lines.append(Line(number, raw, None, located(block_text.alarm, name, number,
                                                             guess_n(raw))))
                continue
            try:
                lines.append(Line(number, raw or block_text,
                                  parse_block(block_text, number, inserted=not raw)))  # start block
            except NcAlarmError as alarm:
                lines.append(Line(number, raw, None, located(alarm, name, number, guess_n(raw))))
    return lines


def _numbered_proc_lines(text: str, name: str, located: Callable, guess_n: Callable,
                         lines: list[Line]) -> bool:
    """A Siemens-mode macro headed ``PROC 0010`` (the manual's form; Siemens names may not
    start with a digit): its lines are parsed as Siemens blocks, the PROC name read as
    ``_N_0010``. Returns False (nothing added) for any other program."""
    raw_lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    if raw_lines and raw_lines[-1] == "":
        raw_lines.pop()
    first = next((i for i, line in enumerate(raw_lines) if line.strip()), None)
    if first is None or not _NUMBERED_PROC.match(raw_lines[first]):
        return False
    for number, raw in enumerate(raw_lines, start=1):
        block_text = _NUMBERED_PROC.sub(r"\1_N_\2", raw) if number == first + 1 else raw
        try:
            lines.append(Line(number, raw, parse_block(block_text, number)))
        except NcAlarmError as alarm:
            lines.append(Line(number, raw, None, located(alarm, name, number, guess_n(raw))))
    return True
