"""The T, F, S window of the Machine area: active tool, path feed, spindle."""

from __future__ import annotations

from rich.text import Text
from textual.widgets import Static

from nck import fixed
from nck.status import NckStatus

from hmi.i18n import _
from hmi.widgets.header import format_override


def tfs_lines(status: NckStatus) -> Text:
    """Render tool, feed and spindle for one snapshot."""
    modal = status.channel.modal
    overrides = status.channel.overrides
    text = Text()
    # The tool line names the tool once: its name, else its number (T1), else "no tool".
    tool = modal.tool_name or (f"T{modal.tool}" if modal.tool else _("no tool"))
    text.append(f" {tool:<18}", style="bold")
    text.append(f"D{modal.edge}")
    # With MD22550 = 1 a programmed T only prepares the tool until M6 changes it: say
    # which tool waits, so that "T1 D1" without M6 does not pass unnoticed (our choice;
    # the manual leaves the display of the preselection open).
    preselected = modal.aux.get("T")
    if preselected is not None and preselected != str(modal.tool):
        text.append("   " + _("T{tool} preselected").format(tool=preselected), style="bold #f39200")
    text.append("\n")
    text.append(f"   L {fixed(modal.tool_length_mm, 3, 10)}   R {fixed(modal.tool_radius_mm, 3, 8)}\n")
    text.append(" F ", style="bold")
    # Actual: the interpolator's path velocity (rapid in G0, JOG in JOG), always per minute;
    # programmed: F in its feed type. Per revolution (G95, G96, G97) each value carries its own unit.
    actual = fixed(status.channel.path_feed_mm_min, 3, 10)
    if modal.feed_per_revolution:
        text.append(f"{actual} mm/min / {fixed(modal.feed, 3, 8)} {_('mm/rev')}")
    else:
        text.append(f"{actual} / {fixed(modal.feed, 3, 10)} mm/min")
    text.append(f"  {format_override(overrides.get('feed', 100)):>3} %\n")
    spindle = next((a for a in status.axes if a.kind == "spindle"), None)
    if spindle is not None:
        text.append(f" S{spindle.name[-1] if spindle.name[-1].isdigit() else '1'} ", style="bold")
        text.append(f"{fixed(spindle.speed_rpm, 0, 10)} / {fixed(modal.spindle_speed_rpm, 0, 10)} {_('rpm')}   ")
        text.append(f"{modal.spindle_state:<3}")
        text.append(f"  {format_override(overrides.get('spindle', 100)):>3} %\n")
        # A speed limit acting on the setpoint is said, not hidden (DB31 DBX83.1 "setpoint
        # speed limited" / DBX83.2 "setpoint speed increased", 002 L54541-54543).
        if spindle.extra.get("setpoint_limited"):
            text.append("    " + _("setpoint speed limited") + "\n", style="bold #f39200")
        elif spindle.extra.get("setpoint_increased"):
            text.append("    " + _("setpoint speed increased") + "\n", style="bold #f39200")
    return text


class TfsWindow(Static):
    """Tool T/D with length and radius, feed actual/set with override, spindle actual/set."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self._key: object = None

    def show(self, status: NckStatus) -> None:
        """Redraw only when the shown values changed."""
        spindle = tuple((a.speed_rpm, a.extra.get("setpoint_limited"), a.extra.get("setpoint_increased"))
                        for a in status.axes if a.kind == "spindle")
        key = (status.channel.modal, status.channel.path_feed_mm_min,
               tuple(status.channel.overrides.items()), spindle)
        if key == self._key:
            return
        self._key = key
        self.update(tfs_lines(status), layout=False)
