"""Where the tool touched: the touch a measuring window of JOG works with.

With a cutter (any tool but a 3D probe) the operator scratches the surface and presses
the softkey: the touch is the position of the axes now (the cutter's centre in the plane,
the tool carrier on the tool axis, MCS). A 3D probe (tool type 710) switches on contact and
the kernel stops the JOG motion a little later, inside the probe's overtravel: the touch is
the probe's trigger position (the kernel's ``ContactEvents``), not where the axes braked.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from nck import fixed
from nck.queries import ContactEvents, ProbeDeflected, ReadData
from nck.status import NckStatus

from hmi.i18n import N_, _

PROBE_TOOL_TYPE = 710
"""Tool type of a 3D probe (milling), $TC_DP1."""


@dataclass(frozen=True)
class Touch:
    """One touch: the MCS positions of the path axes; ``seq`` the probe event it came from
    (0 for a cutter's position), ``probe`` True when a probe switched."""

    position_mcs: dict[str, float]
    seq: int = 0
    probe: bool = False


def active_tool_is_probe(ask: Callable[[object], Any], status: NckStatus) -> bool:
    """True when the active tool edge is a 3D probe (type 710)."""
    modal = status.channel.modal
    data = ask(ReadData()).data
    edge = data.tools.get((modal.tool, modal.edge)) if data is not None and modal.tool > 0 else None
    return edge is not None and int(edge.get(1) or 0) == PROBE_TOOL_TYPE


def touch_now(ask: Callable[[object], Any], status: NckStatus, after_seq: int = 0) -> Touch | str:
    """The touch of the active tool now, or why there is none (panel words).

    A probe: its newest trigger (a ``probe`` event of the active tool and edge after
    ``after_seq``); a cutter: the actual position."""
    axes = {a.name: a.position_mcs for a in status.axes if a.kind != "spindle"}
    if not active_tool_is_probe(ask, status):
        return Touch(axes)
    modal = status.channel.modal
    switched = [event for event in ask(ContactEvents(after_seq))
                if event.kind == "probe" and (event.tool, event.edge) == (modal.tool, modal.edge)]
    if not switched:
        return _("The probe has not switched: jog it against the surface")
    newest = switched[-1]
    return Touch({name: float(newest.position_mcs.get(name, value)) for name, value in axes.items()},
                 newest.seq, probe=True)


CONTACT_WORDS = {"probe": N_("probe switched"), "scratch": N_("scratching"), "crash": N_("crash")}


def contact_line(ask: Callable[[object], Any]) -> str:
    """The JOG view's line about the newest contact with the blank or the reference block
    (empty before the first): what happened, where (MCS), and whether the probe is deflected."""
    events = ask(ContactEvents())
    if not events:
        return ""
    newest = events[-1]
    where = "  ".join(f"{axis} {fixed(value)}" for axis, value in newest.position_mcs.items())
    what = _(CONTACT_WORDS.get(newest.kind, newest.kind))
    line = (_("Last contact: {what} on the blank at {where} (MCS)") if newest.solid == "blank"
            else _("Last contact: {what} on the reference block at {where} (MCS)")).format(what=what, where=where)
    return line + ("   — " + _("probe deflected") if ask(ProbeDeflected()) else "")
