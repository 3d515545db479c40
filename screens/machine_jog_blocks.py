"""The NC blocks the JOG windows T,S,M and Position hand to the kernel, from what was typed.

Pure text functions: each returns the blocks, or raises :class:`EntryError` with
the panel's words for a field that cannot be used. The kernel checks the rest
(an unknown tool is its alarm 17191, a speed beyond the limit its clamp) when
the blocks run, as it does for blocks typed in MDA.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from nck import trimmed

from hmi.i18n import N_, _

SPINDLE_FUNCTIONS = ("—", "M3", "M4", "M5")
"""Spindle direction of the T,S,M window: unchanged, clockwise, counter-clockwise, stop."""

UNCHANGED = "—"
"""A choice field's value that leaves its function as it is."""

UNITS = {UNCHANGED: "", "mm": "G71", "inch": "G70"}
"""Unit of the T,S,M window and the G code that selects it (G group 13)."""

_NUMBER = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)$")
_TOOL_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class EntryError(ValueError):
    """A field holds something the window cannot turn into a block: ``template`` (English, a
    text of the catalogue) filled from ``fields``; ``str()`` is the English message, :meth:`text`
    the message for the dialog line in the panel's language."""

    def __init__(self, template: str, **fields: object) -> None:
        self.template = template
        self.fields = fields
        super().__init__(template.format(**fields))

    def text(self) -> str:
        """The message in the panel's language (a field's label, a text of the catalogue, too)."""
        return _(self.template).format(**{name: _(value) if isinstance(value, str) else value
                                          for name, value in self.fields.items()})


@dataclass(frozen=True)
class TsmEntry:
    """What the T,S,M window holds (texts as typed, choices as shown)."""

    tool: str = ""
    edge: str = ""
    speed_rpm: str = ""
    spindle: str = "—"
    m_function: str = ""
    work_offset: str = UNCHANGED
    unit: str = UNCHANGED


def _number(text: str, field: str) -> str:
    value = text.strip()
    if not _NUMBER.match(value):
        raise EntryError(N_("{field}: enter a number"), field=field)
    return value


def _whole(text: str, field: str, low: int, high: int) -> int:
    value = text.strip()
    if not value.isdigit() or not low <= int(value) <= high:
        raise EntryError(N_("{field}: enter a whole number {low} … {high}"), field=field, low=low, high=high)
    return int(value)


def tool_word(text: str) -> str:
    """``T5`` for a number, ``T="CUTTER_10"`` for a name (002 tool names are identifiers)."""
    value = text.strip().strip('"')
    if value.isdigit():
        return f"T{int(value)}"
    if _TOOL_NAME.match(value):
        return f'T="{value}"'
    raise EntryError(N_("T: enter a tool number or a tool name"))


def tsm_blocks(entry: TsmEntry) -> str:
    """The blocks of the T,S,M window: work offset and unit, tool change, spindle, M function.

    An empty field or ``—`` leaves that function as it is. Raises :class:`EntryError`
    when nothing is asked for or a field cannot be used.
    """
    blocks: list[str] = []
    modal = [code for code in (entry.work_offset, UNITS.get(entry.unit, "")) if code and code != UNCHANGED]
    if modal:  # kept after the job: MD20152 of groups 8 and 13
        blocks.append(" ".join(modal))
    if entry.tool.strip():
        words = [tool_word(entry.tool), "M6"]
        if entry.edge.strip():
            words.append(f"D{_whole(entry.edge, 'D', 1, 12)}")
        blocks.append(" ".join(words))
    elif entry.edge.strip():
        blocks.append(f"D{_whole(entry.edge, 'D', 1, 12)}")
    spindle = []
    if entry.speed_rpm.strip():
        speed = _number(entry.speed_rpm, N_("Spindle speed"))
        if float(speed) < 0:
            raise EntryError(N_("Spindle speed: enter a speed of 0 or more"))
        spindle.append(f"S{speed}")
    if entry.spindle in ("M3", "M4", "M5"):
        spindle.append(entry.spindle)
    if spindle:
        blocks.append(" ".join(spindle))
    if entry.m_function.strip():
        blocks.append(f"M{_whole(entry.m_function, N_('Other M function'), 0, 99)}")
    if not blocks:
        raise EntryError(N_("T,S,M: fill in at least one field"))
    return "\n".join(blocks) + "\n"


def position_blocks(axis: str, position: str, feed_mm_min: str, rapid: bool) -> str:
    """The block of the Position window: ``axis`` to ``position`` in the WCS, G90.

    With ``rapid`` the axis moves with G0, else with G1 at ``feed_mm_min`` (G94).
    """
    target = _number(position, axis)
    if rapid:
        return f"G90 G0 {axis}{target}\n"
    feed = _number(feed_mm_min, N_("Feed"))
    if float(feed) <= 0:
        raise EntryError(N_("Feed: enter a feed greater than 0"))
    return f"G90 G94 G1 {axis}{target} F{feed}\n"


def probing_blocks(axis: str, direction: int, retraction_plane_mm: float, safety_distance_mm: float,
                   measuring_feed_mm_min: float) -> str:
    """The blocks of CYCLE START in Measure workpiece with a 3D probe (the settings for manual mode).

    The probe searches the surface from where it stands: ``MEAS=1`` moves it at the measuring
    feed at most 2 × the safety distance in ``direction`` (+1/−1) along ``axis`` and ends where
    it switched (MEAS: measuring with deletion of the distance to go, 002 L10817, L32646). Then it backs off: an edge (X, Y) by
    the safety distance, a Z surface (always searched downwards) up to the retraction plane
    (WCS Z of the active work offset). Without a switch it stops at the end of the search and
    backs off the same way; the window then says no touch was made.
    """
    if axis == "Z":
        return (f"G91 G94 MEAS=1 G1 Z{trimmed(-2.0 * safety_distance_mm, 3)} F{trimmed(measuring_feed_mm_min, 3)}\n"
                f"G90 G0 Z{trimmed(retraction_plane_mm, 3)}\n")
    return (f"G91 G94 MEAS=1 G1 {axis}{trimmed(2.0 * safety_distance_mm * direction, 3)} "
            f"F{trimmed(measuring_feed_mm_min, 3)}\nG91 G0 {axis}{trimmed(-safety_distance_mm * direction, 3)}\nG90\n")
