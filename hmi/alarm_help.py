"""Alarm help: what an alarm means, its causes, what to do and how it is cleared.

The texts are catalogue data (``explanation``, ``remedy``, ``help_source`` of each entry of
``data/alarms/*.toml``); how the alarm is cleared and how the control reacts follow from the
entry's ``clear`` and ``reactions``. The help opens from the selected alarm of the alarm list
and alarm log (softkey ``Alarm help``) and from a click on the header's alarm line.
"""

from __future__ import annotations

from rich.text import Text
from textual.app import ComposeResult
from textual.containers import VerticalScroll
from textual.widgets import Static

from nck.queries import AlarmDefinition, alarm_catalog

from hmi.dialog import AreaDialog
from hmi.focus import focus_now

CLEARING: dict[str, str] = {
    "power_on": "Switch the control off and on again (POWER ON).",
    "reset": "Press RESET: the alarm goes, a running program is aborted.",
    "cancel": "Press the alarm cancel key (F12) or the softkey Acknowledge alarm.",
    "nc_start": "Press NC START to continue the program, or RESET to abort it.",
    "self": "It clears itself as soon as its cause is gone.",
}
"""How an alarm with each clear criterion is cleared (the criteria of the alarm catalogue)."""

REACTIONS: dict[str, str] = {
    "nc_start_disable": "NC START is disabled",
    "interpreter_stop": "the program stops at the block",
    "feed_stop": "the feed is stopped",
    "braking": "the axes are braked",
    "emergency_stop": "the drives lose their enable (emergency stop)",
}
"""The control's reactions to an alarm, in the operator's words."""


def definition_of(number: int) -> AlarmDefinition | None:
    """The catalogue entry of alarm ``number`` (None for a number not in the catalogue)."""
    return alarm_catalog().get(number)


def reaction_text(reactions: tuple[str, ...]) -> str:
    """The control's reactions as one sentence."""
    if not reactions:
        return "No reaction: the alarm only informs."
    said = "; ".join(REACTIONS.get(reaction, reaction) for reaction in reactions)
    return said[0].upper() + said[1:] + "."


def help_text(number: int, shown: str = "") -> Text:
    """The help page of alarm ``number``; ``shown`` is its text as displayed (with its values)."""
    definition = definition_of(number)
    text = Text(end="")
    text.append(f"{number}  ", style="bold")
    text.append(f"{shown or (definition.text if definition else '')}\n\n")
    if definition is None:
        text.append("No help is stored for this alarm number.\n", style="dim")
        return text
    sections = (
        ("What happened", definition.explanation),
        ("What to do", definition.remedy),
        ("How it is cleared", CLEARING.get(definition.clear, definition.clear)),
        ("Reaction of the control", reaction_text(definition.reactions)),
    )
    for title, body in sections:
        text.append(f"{title}\n", style="bold underline")
        text.append(f"{body}\n\n")
    source = f"manual {definition.help_source}" if definition.help_source else "the trainer's own description"
    text.append(f"Source: {source}", style="dim")
    return text


class AlarmHelpScreen(AreaDialog[None]):
    """The help of one alarm (F10 or Escape closes)."""

    def __init__(self, number: int, shown: str = "") -> None:
        super().__init__(id="alarm-help")
        self.number = number
        self._shown = shown

    def compose(self) -> ComposeResult:
        """A title and the scrollable help page."""
        with VerticalScroll(id="alarm-help-box"):
            yield Static(f"ALARM HELP — {self.number}   (F10 or Esc closes)", id="alarm-help-title",
                         markup=False)
            yield Static(help_text(self.number, self._shown), id="alarm-help-body", markup=False)

    def on_mount(self) -> None:
        """Focus the page so the arrow keys and PgUp/PgDn scroll it."""
        focus_now(self.query_one("#alarm-help-box"))
