"""Keys from the terminal to the focused widget: every key as typed, in the order typed.

A terminal sends Alt+letter as ESC followed by the letter. Textual's parser waits
for the escape delay before it reports such a pair as an Alt key; when the next
ESC arrives sooner (a double press of CYCLE START, key auto-repeat, a burst of
panel keys) it gives up on the held pair and reports it as the two characters
``^`` and the letter, which a focused editor then types into the program.
:class:`PanelKeyParser` reads ESC + one character as the Alt chord at once,
whatever follows and however the bytes were split into reads, and reports every
Alt chord without a character, so that it can never become text (nor, for Alt+B
and Alt+F, a JOG key as Textual's table has it).
:class:`TerminalReader` feeds it the bytes read from the terminal
(:mod:`hmi.terminal_driver`).

Inside the app Textual types a printable key where it lands (the focused
widget's own queue) but runs a bound key only after it has bubbled from that
widget back up to the app; keys typed behind a bound one overtake it there.
:func:`own_binding` finds the keys the focused widget binds itself (cursor keys,
Home, Backspace …), which the app then runs in that widget's queue, in line
with the text around them (:meth:`hmi.app.HmiApp.on_event`).
"""

from __future__ import annotations

import codecs
from collections.abc import Iterable

from textual import events
from textual._xterm_parser import XTermParser
from textual.binding import Binding
from textual.message import Message
from textual.screen import Screen
from textual.widget import Widget

ESC = "\x1b"

SEQUENCE_INTRODUCERS = frozenset("[O")
"""Second characters after ESC that open a longer sequence (CSI, SS3), never an Alt chord.

The HMI asks the terminal for no DCS, OSC or APC replies, so ``ESC P``, ``ESC ]`` …
are Alt chords like any other letter or sign.
"""


def is_alt_chord(key: events.Key) -> bool:
    """Whether the key was pressed with Alt (``alt+g``, ``alt+shift+g``)."""
    return "alt" in key.key.split("+")[:-1]


def _without_text(key: events.Key) -> events.Key:
    """The key as a command only: an Alt chord carries no character to type."""
    if key.character is None or not is_alt_chord(key):
        return key
    return events.Key(key.key, None)


def _as_alt_chord(key: events.Key) -> events.Key:
    """The key pressed with Alt (Textual marks only letters and digits so), without text."""
    return events.Key(key.key if is_alt_chord(key) else f"alt+{key.key}", None)


class PanelKeyParser(XTermParser):
    """Textual's terminal parser with Alt chords read at once and never as text."""

    def _sequence_to_key_events(self, sequence: str, alt: bool = False) -> Iterable[events.Key]:
        if len(sequence) == 2 and sequence[0] == ESC and sequence[1] not in SEQUENCE_INTRODUCERS:
            # Textual's table reads some of these pairs as a macOS Option character (ESC 1 → ¡)
            # or as word moves (ESC b / ESC f → Ctrl+Left/Right, the JOG keys); on the panel
            # each is the Alt chord the operator pressed.
            return [_as_alt_chord(key) for key in super()._sequence_to_key_events(sequence[1], True)]
        return [_without_text(key) for key in super()._sequence_to_key_events(sequence, alt)]


class TerminalReader:
    """Bytes read from the terminal → the messages :class:`PanelKeyParser` makes of them."""

    def __init__(self) -> None:
        self.parser = PanelKeyParser()
        self._decode = codecs.getincrementaldecoder("utf-8")(errors="ignore").decode

    def feed(self, data: bytes) -> list[Message]:
        """The messages complete after ``data`` (a character split over two reads waits)."""
        text = self._decode(data)
        return list(self.parser.feed(text)) if text else []  # "" would end the parser's input

    def tick(self) -> list[Message]:
        """Messages the escape delay has completed (a lone ESC becomes the Escape key)."""
        return list(self.parser.tick())


def own_binding(screen: Screen, focused: Widget | None, key: events.Key) -> Binding | None:
    """The enabled, non-priority binding the focused widget itself has for a key it does not type.

    None for printable keys (the widget types them), for keys bound only by an
    ancestor or the app, and when a priority binding of the app takes the key.
    """
    if focused is None or key.is_printable:
        return None
    active = screen.active_bindings.get(key.key)
    if active is None or active.node is not focused or not active.enabled \
            or active.binding.priority:
        return None
    return active.binding
