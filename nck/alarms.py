"""The alarm server: active alarms, NC messages and the sequenced alarm log.

Definitions come from the catalogue ``data/alarms/*.toml``
(:func:`nck.resources.alarm_catalog`). Each alarm has exactly one clear
criterion (digest part 1 §8.2):

* ``power_on`` — only a restart of the control clears it;
* ``reset`` — RESET in the channel;
* ``cancel`` — the alarm-cancel key; NC START and RESET clear it too;
* ``nc_start`` — NC START in the channel; RESET clears it too;
* ``self`` — the NCK clears it when the cause has gone (:meth:`AlarmServer.clear_number`).

Part-program alarms ``SETAL(60000 … 69999)`` that are not in the catalogue
get a generic definition (RESET to clear, NC start disable and interpreter
stop). Times are simulated-control seconds passed in by the kernel; the
server never reads a clock.
"""

from __future__ import annotations

from collections import deque
from dataclasses import replace

from nck.resources import AlarmDefinition, alarm_catalog
from nck.status import AlarmEntry, AlarmEvent

ACTIVE_LIMIT = 16  # the NCK keeps up to 16 pending alarms (digest part 1 §8.2)
LOG_LIMIT = 500
HISTORY_LIMIT = 200
CHANNEL_NUMBER = "1"

CLEARED_BY: dict[str, frozenset[str]] = {
    # operator action -> clear criteria it removes
    "reset": frozenset({"reset", "cancel", "nc_start"}),
    "cancel": frozenset({"cancel"}),
    "nc_start": frozenset({"nc_start", "cancel"}),
    "power_on": frozenset({"power_on", "reset", "cancel", "nc_start", "self"}),
}

USER_ALARM_RANGE = range(60000, 70000)


def _user_definition(number: int) -> AlarmDefinition:
    """Generic definition of a cycle/user alarm raised with SETAL."""
    return AlarmDefinition(
        number=number,
        text=f"Channel %1 block %2 cycle alarm {number} %3 %4",
        category="user",
        clear="reset",
        reactions=("nc_start_disable", "interpreter_stop"),
    )


def _unknown_definition(number: int) -> AlarmDefinition:
    """Definition used for a number missing from the catalogue."""
    return AlarmDefinition(
        number=number, text=f"Alarm {number} %1 %2 %3", category="nck", clear="reset",
        reactions=("nc_start_disable", "interpreter_stop"),
    )


class AlarmServer:
    """Raise, clear and log alarms; keep NC messages apart."""

    def __init__(self, log_limit: int = LOG_LIMIT) -> None:
        self._catalog = alarm_catalog()
        self._active: list[AlarmEntry] = []
        self._log: deque[AlarmEvent] = deque(maxlen=log_limit)
        self._history: deque[AlarmEntry] = deque(maxlen=HISTORY_LIMIT)
        self._seq = 0
        self.message = ""
        self.changed = False  # set on every change; the kernel resets it

    # -- definitions --------------------------------------------------------
    def definition(self, number: int) -> AlarmDefinition:
        """Return the catalogue definition (generic for unknown and user alarms)."""
        found = self._catalog.get(number)
        if found is not None:
            return found
        if number in USER_ALARM_RANGE:
            return _user_definition(number)
        return _unknown_definition(number)

    # -- raising and clearing -----------------------------------------------
    def raise_alarm(
        self,
        number: int,
        params: tuple[str, ...] | list[str] = (),
        *,
        now_s: float,
        block: str = "",
        file: str | None = None,
        line: int | None = None,
        n: int | None = None,
    ) -> AlarmEntry:
        """Raise alarm ``number``; the channel/block placeholders are filled in here.

        An alarm already pending with the same number and parameters is not
        raised twice; the pending entry is returned.
        """
        definition = self.definition(number)
        full = self._prefixed(definition, tuple(str(p) for p in params), block)
        for entry in self._active:
            if entry.number == number and entry.params == full:
                return entry
        self._seq += 1
        entry = AlarmEntry(
            seq=self._seq, number=number, text=definition.format(full),
            category=definition.category, clear=definition.clear, came_s=now_s,
            params=full, file=file, line=line, n=n,
        )
        self._active.append(entry)
        if len(self._active) > ACTIVE_LIMIT:
            self._went(self._active.pop(0), now_s)
        self._history.append(entry)
        self._append("came", now_s, entry)
        return entry

    def clear(self, action: str, now_s: float, keep: frozenset[int] = frozenset()) -> list[int]:
        """Clear every alarm the operator ``action`` removes; return their numbers.

        ``action`` is ``reset``, ``cancel``, ``nc_start`` or ``power_on``;
        numbers in ``keep`` stay (their cause persists, e.g. E-stop still pressed).
        """
        criteria = CLEARED_BY[action]
        gone = [e for e in self._active if e.clear in criteria and e.number not in keep]
        for entry in gone:
            self._active.remove(entry)
            self._went(entry, now_s)
        return [e.number for e in gone]

    def clear_number(self, number: int, now_s: float) -> bool:
        """Clear a pending alarm by number (self-clearing alarms, whose cause went)."""
        gone = [e for e in self._active if e.number == number]
        for entry in gone:
            self._active.remove(entry)
            self._went(entry, now_s)
        return bool(gone)

    def set_message(self, text: str, now_s: float) -> None:
        """Show the NC message ``text`` (MSG); an empty text clears it."""
        if text == self.message:
            return
        self.message = text
        self._seq += 1
        entry = AlarmEntry(seq=self._seq, number=0, text=text, category="message",
                           clear="self", came_s=now_s)
        self._append("message", now_s, entry)

    # -- queries --------------------------------------------------------------
    @property
    def active(self) -> tuple[AlarmEntry, ...]:
        """Pending alarms, oldest first."""
        return tuple(self._active)

    def is_active(self, number: int) -> bool:
        """True while alarm ``number`` is pending."""
        return any(e.number == number for e in self._active)

    def has_reaction(self, reaction: str) -> bool:
        """True while any pending alarm has ``reaction`` (e.g. ``nc_start_disable``)."""
        return any(reaction in self.definition(e.number).reactions for e in self._active)

    def reactions_of(self, number: int) -> tuple[str, ...]:
        """The reactions of alarm ``number``."""
        return self.definition(number).reactions

    @property
    def last_seq(self) -> int:
        """Sequence number of the newest log event (0 when none)."""
        return self._log[-1].seq if self._log else 0

    def log_since(self, seq: int) -> tuple[AlarmEvent, ...]:
        """Log events newer than ``seq`` (those still held in the bounded log)."""
        return tuple(event for event in self._log if event.seq > seq)

    def load_history(self, entries: list[AlarmEntry]) -> None:
        """Put retained entries (older than anything raised since power on) in front."""
        kept = list(self._history)
        self._history.clear()
        for entry in list(entries) + kept:
            self._history.append(entry)

    def history(self) -> tuple[AlarmEntry, ...]:
        """The alarm log as the diagnosis screen shows it: each alarm with come/go times."""
        return tuple(self._history)

    # -- internals ------------------------------------------------------------
    def _prefixed(self, definition: AlarmDefinition, params: tuple[str, ...], block: str) -> tuple[str, ...]:
        """Put the channel and block in front when the text starts with them."""
        return definition.with_channel(params, CHANNEL_NUMBER, block)

    def _went(self, entry: AlarmEntry, now_s: float) -> None:
        gone = replace(entry, went_s=now_s)
        for index, old in enumerate(self._history):
            if old.seq == entry.seq:
                self._history[index] = gone
                break
        self._append("went", now_s, gone)

    def _append(self, kind: str, now_s: float, entry: AlarmEntry) -> None:
        self._seq += 1
        self._log.append(AlarmEvent(seq=self._seq, kind=kind, time_s=now_s, entry=entry))
        self.changed = True
