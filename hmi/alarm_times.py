"""Date and time of day of the alarm log's and the logbook's entries, stamped by the HMI.

The kernel is clock-free: it counts seconds since its power on. The operator
reads alarms and messages "with date and time" (002 L74605-74607), so the HMI
stamps the wall clock when it reads an entry from the kernel's log (at most one
refresh period after it happened) and keeps the stamps of the retained alarm log
across restarts (``came_at`` / ``went_at`` in its entries, ISO 8601 text with the
UTC offset). The log keeps its order by sequence, not by these stamps: a wall clock
set back never reorders it. The diagnosis logbook (access-level and data changes) is
stamped the same way; its entries live only since power on, so its stamps are not retained.
"""

from __future__ import annotations

from datetime import datetime
from typing import Callable, Mapping

from nck.status import AlarmEntry, AlarmEvent

DATE_TIME_FORMAT = "%Y-%m-%d %H:%M:%S"
"""How a stamp is shown: ISO date and 24-hour time, the same in every locale (a choice)."""

UNKNOWN_TEXT = "unknown"
"""Shown for an entry without a stamp (a log retained before the HMI stamped entries)."""


def local_now() -> datetime:
    """The wall clock in the local time zone (the default clock of :class:`AlarmTimes`)."""
    return datetime.now().astimezone()


def date_time_text(stamp: datetime | None) -> str:
    """A stamp as the alarm list and log show it (``2026-11-26 07:15:00``), else ``unknown``."""
    return UNKNOWN_TEXT if stamp is None else stamp.strftime(DATE_TIME_FORMAT)


def _parsed(text: object) -> datetime | None:
    if not isinstance(text, str):
        return None
    try:
        return datetime.fromisoformat(text)
    except ValueError:  # a damaged stamp in the retained log: shown as unknown
        return None


class AlarmTimes:
    """The wall-clock stamps of the alarm log (when each alarm came and went, each message
    showed) and of the logbook (when each change was made).

    Alarms are identified by their entry's ``seq`` (negative for entries retained from an
    earlier power on, see :mod:`nck.persistence`), messages by their log event's ``seq``.

    Args:
        clock: returns the current wall-clock time (replace it in tests).
    """

    def __init__(self, clock: Callable[[], datetime] = local_now) -> None:
        self.clock = clock
        self._came: dict[int, datetime] = {}
        self._went: dict[int, datetime] = {}
        self._events: dict[int, datetime] = {}
        self._logbook: list[datetime] = []

    def record(self, event: AlarmEvent) -> None:
        """Stamp a log event the HMI has just read (a second reading keeps the first stamp)."""
        now = self.clock()
        self._events.setdefault(event.seq, now)
        if event.kind == "came":
            self._came.setdefault(event.entry.seq, now)
        elif event.kind == "went":
            self._went.setdefault(event.entry.seq, now)

    def record_logbook(self, count: int) -> None:
        """Stamp the logbook entries the HMI has just seen (the kernel's logbook holds ``count``)."""
        now = self.clock()
        while len(self._logbook) < count:
            self._logbook.append(now)

    def logbook_at(self, index: int) -> datetime | None:
        """When the logbook entry at ``index`` was made (None when the HMI never saw it)."""
        return self._logbook[index] if 0 <= index < len(self._logbook) else None

    def came_at(self, entry: AlarmEntry) -> datetime | None:
        """When the alarm came (None when the HMI never saw it come)."""
        return self._came.get(entry.seq)

    def went_at(self, entry: AlarmEntry) -> datetime | None:
        """When the alarm went (None while pending or not seen)."""
        return self._went.get(entry.seq)

    def event_at(self, event: AlarmEvent) -> datetime | None:
        """When the HMI read a log event (messages shown or cleared)."""
        return self._events.get(event.seq)

    def retained(self) -> dict[int, dict[str, str]]:
        """The stamps of this power on's alarms, by entry ``seq``, for the retained log."""
        stamps: dict[int, dict[str, str]] = {}
        for name, table in (("came_at", self._came), ("went_at", self._went)):
            for seq, stamp in table.items():
                if seq > 0:
                    stamps.setdefault(seq, {})[name] = stamp.isoformat()
        return stamps

    def restart(self, retained: Mapping[int, Mapping[str, object]]) -> None:
        """A new power on: forget this one's stamps, take those of the retained entries."""
        self._came.clear()
        self._went.clear()
        self._events.clear()
        self._logbook.clear()
        for seq, stamps in retained.items():
            for name, table in (("came_at", self._came), ("went_at", self._went)):
                stamp = _parsed(stamps.get(name))
                if stamp is not None:
                    table[seq] = stamp
