"""Alarm list, messages and alarm log of the Diagnostics area: rows, filter, export.

Pure functions over :class:`nck.status.AlarmEntry` / :class:`AlarmEvent`, so
the views and their tests need no running app. Alarms and messages show the
date and time of day the HMI stamped them with (:mod:`hmi.alarm_times`);
entries retained from an earlier power on carry a negative ``seq`` (see
:mod:`nck.persistence`), are marked ``PO-`` and stay below this power on's
entries (the log is ordered by sequence, newest first).
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from datetime import datetime
from typing import Iterable, Sequence

from rich.text import Text

from nck.status import AlarmEntry, AlarmEvent

from hmi.alarm_times import AlarmTimes, date_time_text
from hmi.durations import clock
from hmi.i18n import N_, _, alarm_text

CLEAR_SYMBOLS: dict[str, str] = {
    "power_on": "◉",  # switch the control off and on
    "reset": "⟲",  # RESET key
    "cancel": "✕",  # alarm cancel key (F12)
    "nc_start": "▶",  # NC START
    "self": "◌",  # clears itself when the cause goes
}
CLEAR_NAMES: dict[str, str] = {
    "power_on": "POWER ON", "reset": "RESET", "cancel": "CANCEL", "nc_start": "NC START",
    "self": N_("self-clearing"),
}
CATEGORY_STYLES = {"user": "bold yellow", "message": "cyan", "axis": "bold red"}
STAMP_WIDTH = len("2026-11-26 07:15:00")


def clock_text(seconds: float | None) -> str:
    """``hh:mm:ss.cc`` of a simulated-control time; empty for None."""
    if seconds is None:
        return ""
    return clock(seconds, 2)


def source_text(entry: AlarmEntry) -> str:
    """Where the alarm comes from: program position, else the channel/axis in its parameters."""
    if entry.file:
        where = entry.file
        if entry.n is not None:
            where += f" N{entry.n}"
        elif entry.line:
            where += f" L{entry.line}"
        return where
    if entry.category == "axis" and len(entry.params) >= 2:
        return _("channel {channel} axis {axis}").format(channel=entry.params[0], axis=entry.params[1])
    return "NCK" if entry.category in ("nck", "") else _("channel {channel}").format(channel=1)


def alarm_list_rows(alarms: Iterable[AlarmEntry]) -> list[AlarmEntry]:
    """Active alarms newest first."""
    return sorted(alarms, key=lambda e: e.seq, reverse=True)


def alarm_list_text(alarms: Sequence[AlarmEntry], times: AlarmTimes, selected: int | None = None) -> Text:
    """The alarm list: ``Date and time | Clear | Number | Text | Source``, newest first.

    Row ``selected`` (an index into :func:`alarm_list_rows`) is marked ``▶`` and shown reversed.
    """
    text = Text(no_wrap=True, end="")
    text.append(f"  {_('Date and time'):<{STAMP_WIDTH}} {_('Del'):<4} {_('Number'):>6}  {_('Text'):<90} "
                f"{_('Source')}\n", style="bold")
    rows = alarm_list_rows(alarms)
    if not rows:
        text.append(" " + _("No active alarms."), style="dim")
        return text
    for index, entry in enumerate(rows):
        symbol = CLEAR_SYMBOLS.get(entry.clear, "?")
        start = len(text)
        text.append(f"{_marker(index == selected)}{date_time_text(times.came_at(entry)):<{STAMP_WIDTH}} {symbol:<4} ")
        text.append(f"{entry.number:>6}", style=CATEGORY_STYLES.get(entry.category, "bold"))
        shown = alarm_text(entry)
        body = shown if len(shown) <= 90 else shown[:89] + "…"
        text.append(f"  {body:<90} {source_text(entry)}")
        if index == selected:
            text.stylize("reverse", start, len(text))
        text.append("\n")
    text.append("\n " + _("Clear:") + " ")
    for key in ("cancel", "reset", "nc_start", "power_on", "self"):
        text.append(f"{CLEAR_SYMBOLS[key]} {_(CLEAR_NAMES[key])}   ", style="dim")
    text.append("\n " + _("F12 acknowledges CANCEL alarms; RESET clears RESET, CANCEL and NC START alarms.")
                + "  " + _("▲▼ select an alarm, Alarm help explains it."), style="dim")
    return text


def _marker(selected: bool) -> str:
    """The first column of a list row: ``▶`` on the selected row."""
    return "▶ " if selected else "  "


@dataclass(frozen=True, slots=True)
class MessageLine:
    """One NC or cycle message: when it came (None: not known), its text, where it came from."""

    came_at: datetime | None
    text: str
    source: str


def message_lines(current: str, events: Iterable[AlarmEvent], user_alarms: Iterable[AlarmEntry],
                  times: AlarmTimes) -> list[MessageLine]:
    """Active messages: the NC message (MSG) shown now, and pending cycle/user alarms."""
    lines: list[MessageLine] = []
    if current:
        came = None
        for event in events:
            if event.kind == "message" and event.entry.text == current:
                came = times.event_at(event)
        lines.append(MessageLine(came, current, _("NC program (MSG)")))
    for entry in sorted(user_alarms, key=lambda e: e.seq, reverse=True):
        if entry.category == "user":
            lines.append(MessageLine(times.came_at(entry), f"{entry.number} {alarm_text(entry)}", source_text(entry)))
    return lines


def messages_text(lines: Sequence[MessageLine], history: Sequence[AlarmEvent], times: AlarmTimes) -> Text:
    """Active messages, then the recent message history (newest first)."""
    text = Text(no_wrap=True, end="")
    text.append(f" {_('Date and time'):<{STAMP_WIDTH}} {_('Message'):<100} {_('Source')}\n", style="bold")
    if not lines:
        text.append(" " + _("No active messages.") + "\n", style="dim")
    for line in lines:
        text.append(f" {date_time_text(line.came_at):<{STAMP_WIDTH}} {line.text[:100]:<100} {line.source}\n")
    shown = [e for e in reversed(history) if e.kind == "message"][:12]
    if shown:
        text.append("\n " + _("Recent NC messages") + "\n", style="bold")
        for event in shown:
            body = event.entry.text or _("(message cleared)")
            text.append(f" {date_time_text(times.event_at(event)):<{STAMP_WIDTH}} {body[:100]}\n",
                        style=None if event.entry.text else "dim")
    return text


# -- alarm log --------------------------------------------------------------------------
@dataclass(frozen=True, slots=True)
class LogFilter:
    """Number range (inclusive) and a text the entry must contain (case-insensitive)."""

    low: int | None = None
    high: int | None = None
    text: str = ""

    def matches(self, entry: AlarmEntry) -> bool:
        """True when ``entry`` passes the filter."""
        if self.low is not None and entry.number < self.low:
            return False
        if self.high is not None and entry.number > self.high:
            return False
        return not self.text or self.text.lower() in alarm_text(entry).lower()

    def describe(self) -> str:
        """The filter as the operator typed it (empty when none)."""
        parts = []
        if self.low is not None or self.high is not None:
            parts.append(f"{self.low if self.low is not None else ''}-{self.high if self.high is not None else ''}")
        if self.text:
            parts.append(f'"{self.text}"')
        return " ".join(parts)


def parse_filter(typed: str) -> LogFilter:
    """``10000-19999``, ``10720``, ``-20000``, ``limit``, or ``10000-19999 limit``.

    A leading number or range limits the numbers; the rest is a text to find.
    Raises ValueError for a range whose ends are reversed (its text in the panel's language).
    """
    words = typed.strip().split(maxsplit=1)
    if not words:
        return LogFilter()
    first = words[0]
    low = high = None
    rest = typed.strip()
    head, dash, tail = first.partition("-")
    if all(part.isascii() and part.isdigit() or not part for part in (head, tail)) \
            and (head or tail) and (dash or head):
        low = int(head) if head else None
        high = int(tail) if tail else (None if dash else low)
        rest = words[1] if len(words) > 1 else ""
        if low is not None and high is not None and low > high:
            raise ValueError(_("number range {range}: the first number must not exceed the second").format(range=first))
    return LogFilter(low, high, rest.strip())


def log_rows(history: Iterable[AlarmEntry], log_filter: LogFilter = LogFilter()) -> list[AlarmEntry]:
    """Alarm-log entries (no messages) that pass the filter, newest first."""
    kept = [e for e in history if e.category != "message" and log_filter.matches(e)]
    return list(reversed(kept))


def _earlier(entry: AlarmEntry) -> str:
    return "PO-" if entry.seq < 0 else ""


def _went_text(entry: AlarmEntry, times: AlarmTimes, pending: str = "—") -> str:
    """When the alarm went; ``pending`` while it has not."""
    return pending if entry.went_s is None else date_time_text(times.went_at(entry))


def log_text(rows: Sequence[AlarmEntry], log_filter: LogFilter, total: int, times: AlarmTimes,
             first: int = 0, count: int = 30, selected: int | None = None) -> Text:
    """The alarm log window: ``Come | Go | Number | Text``, newest first, a filter line.

    Row ``selected`` (an index into ``rows``) is marked ``▶`` and shown reversed.
    """
    text = Text(no_wrap=True, end="")
    described = log_filter.describe()
    text.append(" " + _("{shown} of {total} entries").format(shown=len(rows), total=total)
                + (" — " + _("filter: {filter}").format(filter=described) if described else ""), style="dim")
    text.append("   " + _("(PO- = before the last power on)") + "\n", style="dim")
    text.append(f"  {'':<3} {_('Come'):<{STAMP_WIDTH}} {_('Go'):<{STAMP_WIDTH}} {_('Number'):>6}  {_('Text')}\n",
                style="bold")
    for index in range(first, min(first + count, len(rows))):
        entry = rows[index]
        start = len(text)
        text.append(f"{_marker(index == selected)}{_earlier(entry):<3} "
                    f"{date_time_text(times.came_at(entry)):<{STAMP_WIDTH}} {_went_text(entry, times):<{STAMP_WIDTH}} ")
        text.append(f"{entry.number:>6}", style=CATEGORY_STYLES.get(entry.category, "bold"))
        text.append(f"  {alarm_text(entry)[:90]}")
        if index == selected:
            text.stylize("reverse", start, len(text))
        text.append("\n")
    return text


def log_as_csv(rows: Sequence[AlarmEntry], times: AlarmTimes) -> str:
    """The alarm log as CSV (``earlier,come,go,number,clear,text,source``)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["earlier_power_on", "come", "go", "number", "clear", "text", "source"])
    for entry in rows:
        writer.writerow([int(entry.seq < 0), date_time_text(times.came_at(entry)), _went_text(entry, times, ""),
                         entry.number, entry.clear, alarm_text(entry), source_text(entry)])
    return out.getvalue()


def log_as_text(rows: Sequence[AlarmEntry], times: AlarmTimes) -> str:
    """The alarm log as plain text, one entry a line."""
    lines = [_("Alarm log (newest first)"), ""]
    for entry in rows:
        lines.append(f"{_earlier(entry):<3} {date_time_text(times.came_at(entry))}  "
                     f"{_went_text(entry, times, 'pending'):<{STAMP_WIDTH}}  {entry.number:>6}  {alarm_text(entry)}")
    return "\n".join(lines) + "\n"
