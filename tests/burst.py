"""Keys sent as a terminal sends a burst: all at once, before the app handles the first.

``pilot.press`` waits until the app is idle after every key, so it never shows
what happens when several keys arrive in one read of the terminal (a fast
typist, auto-repeat, a paste, ``tmux send-keys`` with several keys).
:func:`burst` puts every key event into the app's queue first and only then
lets the app run.
"""

from __future__ import annotations

from textual import events
from textual.pilot import Pilot

NAMED_CHARACTERS = {"space": " ", "enter": "\r", "tab": "\t", "escape": "\x1b",
                    "backspace": "\x7f", "minus": "-", "full_stop": ".", "comma": ",",
                    "equals_sign": "=", "left_parenthesis": "(", "right_parenthesis": ")",
                    "semicolon": ";", "quotation_mark": "\"", "underscore": "_", "slash": "/"}


def key_event(key: str) -> events.Key:
    """The event the terminal driver makes for ``key`` (``a``, ``enter``, ``shift+f1`` …)."""
    if len(key) == 1:
        return events.Key(key if key.isalnum() else _name_of(key), key)
    return events.Key(key, NAMED_CHARACTERS.get(key))


def _name_of(character: str) -> str:
    for name, char in NAMED_CHARACTERS.items():
        if char == character:
            return name
    raise ValueError(f"no key name for {character!r}: add it to NAMED_CHARACTERS")


async def burst(pilot: Pilot, *keys: str) -> None:
    """Queue all ``keys`` at once, then wait until the app has handled them."""
    app = pilot.app
    for key in keys:
        event = key_event(key)
        event.set_sender(app)
        app.post_message(event)
    await pilot.pause()
    await pilot.pause()
