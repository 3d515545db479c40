"""Keys sent one at a time, each handled before the next, without ``pilot.press``'s idle waits.

``pilot.press`` waits twice per key for the process to be idle (20 ms sleeps each, more
while the app works). :func:`send_key` posts the same Key event Pilot makes and lets the
app and the screen drain their queues (``pause(0)``): each key is still handled before
the next one comes, about three times faster. (For keys that arrive all at once, as a
terminal's burst, see :mod:`tests.burst`.)
"""

from __future__ import annotations

from textual import events
from textual.keys import _character_to_key, key_to_character


def key_event(key: str) -> events.Key:
    """The Key event Pilot's ``press`` would send for ``key`` (a key name or one character)."""
    name = _character_to_key(key) if len(key) == 1 and not key.isalnum() else key
    char = key if len(key) == 1 else key_to_character(key)
    return events.Key(name, char)


async def send_key(app, pilot, key: str) -> None:
    """Send one key and wait until the screen has handled it."""
    event = key_event(key)
    event.set_sender(app)
    app.post_message(event)
    await pilot.pause(0)
