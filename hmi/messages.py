"""App-wide messages of the HMI, named as past-tense events.

The bridge posts them to the app; the app hands the snapshot to the area
screens (attributes down, messages up).
"""

from __future__ import annotations

from textual.message import Message

from nck.commands import Rejected
from nck.status import NckStatus


class NckStatusChanged(Message):
    """A new kernel snapshot with a different ``seq`` is available."""

    def __init__(self, status: NckStatus) -> None:
        super().__init__()
        self.status = status

    def can_replace(self, message: Message) -> bool:
        """A newer snapshot makes an unprocessed older one pointless."""
        return isinstance(message, NckStatusChanged)


class CommandRejected(Message):
    """The kernel refused an operator command; ``refusal`` (its key, reason and alarm) is shown on
    the dialog line in the panel's language."""

    def __init__(self, command: object, refusal: Rejected) -> None:
        super().__init__()
        self.command = command
        self.refusal = refusal


class TerminalClosed(Message):
    """The terminal has gone away (window closed, connection dropped): its input ended.

    Posted by the terminal driver (:mod:`hmi.terminal_driver`); nobody is left to
    answer a question, so the app ends without asking.
    """


class AlarmLineClicked(Message):
    """The operator clicked the header's alarm line while alarm ``number`` was shown on it."""

    def __init__(self, number: int, text: str) -> None:
        super().__init__()
        self.number = number
        self.text = text
