"""The position window of the Machine area: axes, distance to go, spindle."""

from __future__ import annotations

from rich.text import Text
from textual.widgets import Static

from nck import fixed
from nck.status import AxisStatus, NckStatus

from hmi.i18n import _

UNREFERENCED_MARK = "○"
"""Shown beside an axis that is not referenced (it disappears after REF)."""


def format_mm(value: float, width: int = 12) -> str:
    """A position with 3 decimals, right aligned, never ``-0.000``."""
    return fixed(value, 3, width)


def position_lines(status: NckStatus, mcs: bool, selected_axis: str | None) -> Text:
    """Render the position window for one snapshot."""
    text = Text()
    system = _("MCS") if mcs else _("WCS")
    text.append(f" {system:<8}{_('Position [mm]'):>20}{_('Dist-to-go'):>18}\n", style="bold")
    for axis in status.axes:
        if axis.kind == "spindle":
            continue
        _axis_line(text, axis, mcs, axis.name == selected_axis)
    for axis in status.axes:
        if axis.kind != "spindle":
            continue
        marker = "▸" if axis.name == selected_axis else " "
        text.append(f"{marker}{axis.name:<4}", style="bold")
        text.append("   ")
        text.append(format_mm(axis.position_mcs if mcs else axis.position_wcs, 17) + "°")
        text.append(f"{fixed(axis.speed_rpm, 0, 13)} {_('rpm')}  {status.channel.modal.spindle_state}\n")
    return text


def _axis_line(text: Text, axis: AxisStatus, mcs: bool, selected: bool) -> None:
    marker = "▸" if selected else " "
    text.append(f"{marker}{axis.name:<4}", style="bold reverse" if selected else "bold")
    text.append(f" {UNREFERENCED_MARK if not axis.referenced else ' '} ", style="bold")
    value = axis.position_mcs if mcs else axis.position_wcs
    unit = "°" if axis.kind == "rotary" else " "
    text.append(format_mm(value, 17) + unit, style="bold")
    text.append(format_mm(axis.distance_to_go, 17) + "\n")


class PositionWindow(Static):
    """Actual positions (MCS or WCS), distance to go, reference marks and the spindle."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self._shown: Text | None = None

    def show(self, status: NckStatus, mcs: bool, selected_axis: str | None) -> None:
        """Redraw only when what the window shows changed.

        The snapshot's axes also carry drive values (motor temperature, current)
        that change at idle; comparing the rendered text keeps the window quiet
        until a shown digit changes.
        """
        lines = position_lines(status, mcs, selected_axis)
        if lines == self._shown:
            return
        self._shown = lines
        self.update(lines, layout=False)
