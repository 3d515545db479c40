"""The header of every area screen: states, the alarm/message line, program and overrides."""

from __future__ import annotations

from textual import events
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.widgets import Static

from nck.status import AlarmEntry, NckStatus

from hmi.i18n import N_, _, alarm_text
from hmi.messages import AlarmLineClicked
from hmi.widgets.shown_text import show_text

CHANNEL_STATE_TEXT = {
    "reset": N_("Channel reset"),
    "active": N_("Channel active"),
    "interrupted": N_("Channel interrupted"),
}
PROGRAM_STATE_TEXT = {
    "aborted": N_("Program aborted"),
    "running": N_("Program running"),
    "stopped": N_("Program stopped"),
    "interrupted": N_("Program interrupted"),
    "waiting": N_("Program waiting"),
}
MODE_TEXT = {"JOG": "JOG", "MDA": "MDA", "AUTO": "AUTO"}
LEVEL_NAMES = {
    0: N_("Siemens"), 1: N_("Manufacturer"), 2: N_("Service"), 3: N_("User"),
    4: N_("Keyswitch 3"), 5: N_("Keyswitch 2"), 6: N_("Keyswitch 1"), 7: N_("Keyswitch 0"),
}
ALARM_CLASSES = ("-alarm-red", "-alarm-orange", "-alarm-user", "-message", "-hint")


def increment_text(increment: int | None) -> str:
    """Return the JOG increment as the mode line shows it (``INC 100``, ``INC VAR``)."""
    return "INC VAR" if increment is None else f"INC {increment}"


def mode_line(status: NckStatus) -> str:
    """Return mode plus machine function, e.g. ``JOG REF`` or ``JOG INC 100``."""
    channel = status.channel
    text = MODE_TEXT.get(channel.mode, channel.mode)
    function = channel.machine_function
    if function == "INC":
        text += " " + increment_text(channel.increment)
    elif function:
        text += f" {function}"
    return text


def alarm_class(category: str) -> str:
    """Return the header style class for an alarm category."""
    if category in ("user",):
        return "-alarm-user"
    if category in ("program", "channel", "cycle"):
        return "-alarm-orange"
    return "-alarm-red"


PROGRAM_INFLUENCES = (
    ("single_block", "SBL"),
    ("dry_run", "DRY"),
    ("m01", "M01"),
    ("program_test", "PRT"),
    ("rapid_override", "ROV"),
    ("skip_levels", "SKP"),
)
"""Program influences in the order of the Program control view, with their status-line names."""


def influence_text(program_control: object) -> str:
    """The active program influences as the status line names them (``SBL DRY ROV``).

    002 L18120: active single block shows in the status line; the other
    influences of the Program control view are shown beside it the same way.
    """
    get = getattr(program_control, "get", None)
    if get is None:
        return ""
    return " ".join(name for key, name in PROGRAM_INFLUENCES if get(key))


def format_override(value: object) -> str:
    """Return an override percentage without a needless decimal point."""
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return "100"
    return f"{number:.0f}" if number == int(number) else f"{number:g}"


class AreaHeader(Vertical):
    """Three lines: states, alarm/message line, selected program with overrides.

    A click on the alarm line asks for the help of the alarm shown there (:class:`AlarmLineClicked`).
    """

    shown_alarm: AlarmEntry | None = None
    """The alarm on the alarm line (None while it shows a message, a hint or nothing)."""

    def compose(self) -> ComposeResult:
        """The three lines."""
        yield Static("", id="hdr-state", markup=False)
        yield Static("", id="hdr-alarm", markup=False)
        with Horizontal(id="hdr-line3"):
            yield Static("", id="hdr-program", markup=False)
            yield Static("", id="hdr-influences", markup=False)
            yield Static("", id="hdr-overrides", markup=False)

    def show(self, area_title: str, status: NckStatus | None, hint: str = "") -> None:
        """Show the header for ``status`` (updates only lines that changed)."""
        state = self.query_one("#hdr-state", Static)
        alarm = self.query_one("#hdr-alarm", Static)
        program = self.query_one("#hdr-program", Static)
        influences = self.query_one("#hdr-influences", Static)
        overrides_line = self.query_one("#hdr-overrides", Static)
        self.shown_alarm = max(status.alarms, key=lambda entry: entry.seq) if status and status.alarms else None
        if status is None:
            self._set(state, f" {area_title}  │ {_('NCK not connected')}")
            self._set(alarm, "")
            self._set(program, "")
            self._set(influences, "")
            self._set(overrides_line, "")
            return
        channel = status.channel
        level = status.access_level
        parts = [
            f" {area_title}",
            mode_line(status),
            "CHAN1",
            _(CHANNEL_STATE_TEXT.get(channel.channel_state, channel.channel_state)),
            _(PROGRAM_STATE_TEXT.get(channel.program_state, channel.program_state)),
            _("Level {level} {name}").format(level=level, name=_(LEVEL_NAMES.get(level, ""))).rstrip(),
        ]
        if status.emergency_stop:
            parts.insert(1, _("EMERGENCY STOP"))
        self._set(state, "  │ ".join(parts))
        text, css = self.alarm_line(status, hint)
        self._set(alarm, text)
        for name in ALARM_CLASSES:
            alarm.set_class(name == css, name)
        overrides = channel.overrides
        selected = channel.selected_program or _("no program selected")
        right = _("Feed {feed} %   Rapid {rapid} %   Spindle {spindle} % ").format(
            feed=format_override(overrides.get("feed", 100)), rapid=format_override(overrides.get("rapid", 100)),
            spindle=format_override(overrides.get("spindle", 100)))
        self._set(program, f" {selected}")
        self._set(influences, influence_text(channel.program_control))
        self._set(overrides_line, right)

    def on_click(self, event: events.Click) -> None:
        """A click on the alarm line while an alarm is shown: ask for its help."""
        if event.widget is not None and event.widget.id == "hdr-alarm" and self.shown_alarm is not None:
            self.post_message(AlarmLineClicked(self.shown_alarm.number, alarm_text(self.shown_alarm)))

    @staticmethod
    def alarm_line(status: NckStatus, hint: str = "") -> tuple[str, str]:
        """Return the alarm/message line text and its style class.

        The newest pending alarm wins; else the NC message (MSG); else the HMI hint
        (e.g. why a command was refused).
        """
        if status.alarms:
            top = max(status.alarms, key=lambda entry: entry.seq)
            count = len(status.alarms)
            more = "   " + _("(+{count} more)").format(count=count - 1) if count > 1 else ""
            return f" {top.number:>6}  {alarm_text(top)}{more}", alarm_class(top.category)
        if status.channel.message:
            return f" {status.channel.message}", "-message"
        if hint:
            return f" {hint}", "-hint"
        return "", ""

    @staticmethod
    def _set(widget: Static, text: str) -> None:
        show_text(widget, text)  # every header field has a fixed size (hmi.tcss): no new layout
