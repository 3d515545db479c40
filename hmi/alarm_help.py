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
from hmi.i18n import N_, _, data_text

CLEARING: dict[str, str] = {
    "power_on": N_("Switch the control off and on again (POWER ON)."),
    "reset": N_("Press RESET: the alarm goes, a running program is aborted."),
    "cancel": N_("Press the alarm cancel key (F12) or the softkey Acknowledge alarm."),
    "nc_start": N_("Press NC START to continue the program, or RESET to abort it."),
    "self": N_("It clears itself as soon as its cause is gone."),
}
"""How an alarm with each clear criterion is cleared (the criteria of the alarm catalogue)."""

REACTIONS: dict[str, str] = {
    "nc_start_disable": N_("NC START is disabled"),
    "interpreter_stop": N_("the program stops at the block"),
    "feed_stop": N_("the feed is stopped"),
    "braking": N_("the axes are braked"),
    "emergency_stop": N_("the drives lose their enable (emergency stop)"),
}
"""The control's reactions to an alarm, in the operator's words."""


def definition_of(number: int) -> AlarmDefinition | None:
    """The catalogue entry of alarm ``number`` (None for a number not in the catalogue)."""
    return alarm_catalog().get(number)


def reaction_text(reactions: tuple[str, ...]) -> str:
    """The control's reactions as one sentence."""
    if not reactions:
        return _("No reaction: the alarm only informs.")
    said = "; ".join(_(REACTIONS.get(reaction, reaction)) for reaction in reactions)
    return said[0].upper() + said[1:] + "."


def help_text(number: int, shown: str = "") -> Text:
    """The help page of alarm ``number``; ``shown`` is its text as displayed (with its values)."""
    definition = definition_of(number)
    text = Text(end="")
    text.append(f"{number}  ", style="bold")
    text.append(f"{shown or (data_text('alarm', number, 'text', definition.text) if definition else '')}\n\n")
    if definition is None:
        text.append(_("No help is stored for this alarm number.") + "\n", style="dim")
        return text
    sections = (
        (_("What happened"), data_text("alarm", number, "explanation", definition.explanation)),
        (_("What to do"), data_text("alarm", number, "remedy", definition.remedy)),
        (_("How it is cleared"), _(CLEARING.get(definition.clear, definition.clear))),
        (_("Reaction of the control"), reaction_text(definition.reactions)),
    )
    for title, body in sections:
        text.append(f"{title}\n", style="bold underline")
        text.append(f"{body}\n\n")
    source = (_("manual {lines}").format(lines=definition.help_source) if definition.help_source
              else _("the trainer's own description"))
    text.append(_("Source: {source}").format(source=source), style="dim")
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
            yield Static(_("ALARM HELP — {number}   (F10 or Esc closes)").format(number=self.number),
                         id="alarm-help-title",
                         markup=False)
            yield Static(help_text(self.number, self._shown), id="alarm-help-body", markup=False)

    def on_mount(self) -> None:
        """Focus the page so the arrow keys and PgUp/PgDn scroll it."""
        focus_now(self.query_one("#alarm-help-box"))
