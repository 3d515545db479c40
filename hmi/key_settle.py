"""One key at a time: the next key waits until the widget that took the last one is done.

The app hands a key to the focused widget by putting it into that widget's own
message queue and goes straight on to the next key of the burst. When the key
closes a dialog (Enter in its input field: the field posts ``Submitted``, which
bubbles up to the dialog, which closes), the keys behind it were already handed
to the dialog's field, which is gone a moment later: the first key after a
dialog closed was lost (issue 18: tool list Enter, ``120``, Enter, Right lost
Right). :func:`wait_until_handled` lets the app wait until the widget, its
ancestors and the screen on top have handled everything the key caused, so
the next key goes where the operator sees the focus.

A key that no widget uses travels back up to the app, which runs the binding
of the focused widget, its containers or the screen there, behind every other
key still queued at the app: Enter on a table that opens a dialog came after
the keys typed for the dialog. :class:`BindingsInPlace` runs such a binding
where the key arrived, in the screen's queue, in line with the other keys.
"""

from __future__ import annotations

import asyncio

from textual import events
from textual.app import App
from textual.message_pump import MessagePump
from textual.screen import Screen
from textual.widget import Widget
from textual.worker import Worker, WorkerCancelled

SETTLE_ROUNDS = 12
"""At most this many rounds of messages caused by one key are waited for (bubbling, a dialog closing)."""

SETTLE_LIMIT_S = 2.0
"""A round is waited for at most this long (an area built on its first visit can take a while)."""

SETTLE_POLL_S = 0.05
"""While waiting, markers of widgets removed meanwhile (they never handle them) are given up this often."""


def _busy_pumps(app: App, widget: Widget, first: bool) -> list[MessagePump]:
    """The widgets and screens whose queues may still hold what the key caused."""
    nodes: list[MessagePump] = []
    for start in (widget, app.focused, app.screen):
        if start is None:
            continue
        for node in start.ancestors_with_self:
            if node is app or node in nodes:
                continue
            nodes.append(node)
    return [node for node in nodes
            if (first and node is widget) or node.message_queue_size > 0]


async def wait_until_handled(app: App, widget: Widget) -> None:
    """Wait until ``widget`` has handled the key just put in its queue and all that followed from it.

    Each round puts a marker behind the messages queued at ``widget``, its
    ancestors and the current screen and focus, and waits for the markers; it
    ends when no queue holds anything more.
    """
    loop = asyncio.get_running_loop()
    for round_number in range(SETTLE_ROUNDS):
        markers: dict[asyncio.Future[None], MessagePump] = {}
        for pump in _busy_pumps(app, widget, first=round_number == 0):
            marker = loop.create_future()
            if pump.call_later(_reached, marker):
                markers[marker] = pump
        if not markers:
            return
        waited_s = 0.0
        while markers and waited_s < SETTLE_LIMIT_S:
            _, pending = await asyncio.wait(markers, timeout=SETTLE_POLL_S)
            waited_s += SETTLE_POLL_S
            markers = {marker: pump for marker, pump in markers.items()
                       if marker in pending and getattr(pump, "is_attached", True)}
        if markers:
            return


async def wait_for_workers(node: MessagePump) -> None:
    """Wait until the workers ``node`` runs have ended, each at most :data:`SETTLE_LIMIT_S`.

    The command palette searches in a worker after each typed character; a Down or
    Enter typed behind the characters in one burst must see the list that search
    makes, not the one before it (or none), else the choice is lost.
    """
    for worker in [worker for worker in node.app.workers if worker.node is node and worker.is_running]:
        await asyncio.wait([asyncio.ensure_future(_ended(worker))], timeout=SETTLE_LIMIT_S)


async def _ended(worker: Worker[object]) -> None:
    try:
        await worker.wait()
    except WorkerCancelled:  # a newer search replaced it: nothing to wait for
        pass


def _reached(marker: asyncio.Future[None]) -> None:
    if not marker.done():
        marker.set_result(None)


class BindingsInPlace(Screen):
    """A screen that runs the bindings of its widgets and itself where a key reaches it.

    The app's own bindings (the keymap, all priority bindings) are left to the app.
    """

    async def on_key(self, event: events.Key) -> None:
        """Run the binding the key has in the focus chain, here and now, and stop the key."""
        active = self.active_bindings.get(event.key)
        if active is None or active.node is self.app or not active.enabled or active.binding.priority:
            return
        event.stop()
        event.prevent_default()
        await self.app.run_action(active.binding.action, active.node)
