"""A skip level ``/n`` in the middle of an ISO block, decided when the block runs.

ISO dialects manual §2.1 (ranked item 4): ``N5 G00 X100. /3 YY100`` runs as
``N5 G00 X100.`` when skip level 3 is active (the rest of the block is
dropped, even text that would not translate) and as the whole block when it
is not (then ``YY100`` raises 12080). The Siemens interpreter only knows a
skip mark at the start of a block, so the line becomes::

    /3 <whole block>                  (each of its Siemens blocks)
    /3 GOTOF ISO_SKIP_<line>
    <the block up to the slash>
    ISO_SKIP_<line>:

and, when the whole block does not translate, the alarm waits behind a jump
that only the inactive level takes::

    /3 GOTOF ISO_SKIPE_<line>
    <the block up to the slash>
    GOTOF ISO_SKIP_<line>
    ISO_SKIPE_<line>:
    <the alarm>
    ISO_SKIP_<line>:

Consecutive blocks with the same mark read the skip switch once, so both
halves see the same level state. Only the first mid-block slash is decided
at run time; a second one in the same block, and one in a block that also
starts with a skip mark, are resolved as if their level were off.
"""

from __future__ import annotations

import copy
import re
from typing import Any, Callable

from nck.errors import NcAlarmError
from nck.iso.lexing import strip_comments

LABEL = "ISO_SKIP_{line}"
ERROR_LABEL = "ISO_SKIPE_{line}"
_START = re.compile(r"^\s*/")
_SLASH = re.compile(r"/\s*(\d*)")


class AlarmBlock(str):
    """A place in a line's block list where executing raises :attr:`alarm`."""

    alarm: NcAlarmError

    def __new__(cls, alarm: NcAlarmError) -> "AlarmBlock":
        block = super().__new__(cls, "")
        block.alarm = alarm
        return block


def mid_block_skip(raw: str) -> tuple[int, str] | None:
    """``(level, text before the slash)`` of the first ``/n`` after the block start, or None
    (also for a block that starts with a skip mark and for a level outside 1..9)."""
    if "/" not in raw:
        return None
    text = strip_comments(raw)
    if _START.match(text) or "/" not in text:
        return None
    position = text.index("/")
    if not text[:position].strip():
        return None
    match = _SLASH.match(text, position)
    digits = match.group(1) if match else ""
    level = int(digits) if digits else 0
    if digits and not 1 <= level <= 9:
        return None  # 14060 comes from the normal lexing of the whole block
    return level, text[:position]


def expand(raw: str, line: int, modal: Any,
           translate_line: Callable[[str, Any], list[str]]) -> list[str] | None:
    """The blocks of ``raw`` with its mid-block skip decided at run time, or None when the
    line has none. ``translate_line(text, modal)`` translates one ISO line."""
    found = mid_block_skip(raw)
    if found is None:
        return None
    level, head = found
    mark = "/" if level == 0 else f"/{level}"
    partial_modal = copy.deepcopy(modal)
    partial = translate_line(head, partial_modal)
    label = LABEL.format(line=line)
    try:
        whole = translate_line(raw, modal)
    except NcAlarmError as alarm:
        error_label = ERROR_LABEL.format(line=line)
        for name, value in vars(partial_modal).items():
            setattr(modal, name, value)  # the block as it runs with the level active
        return ([f"{mark} GOTOF {error_label}"] + partial
                + [f"GOTOF {label}", f"{error_label}:", AlarmBlock(alarm), f"{label}:"])
    return [f"{mark} {block}" for block in whole] + [f"{mark} GOTOF {label}"] + partial + [f"{label}:"]
