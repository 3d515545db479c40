"""The view softkeys a simulation shows wherever it is drawn: the editor's simulation (ids
``sim.*``) and the Machine area's simultaneous recording (``simrec.*``).

One builder for both: ``prefix`` is the softkeys' id prefix and the prefix of the screen's
actions, which each screen provides as ``<prefix>_view(view)``, ``<prefix>_zoom(direction)``,
``<prefix>_fit`` and ``<prefix>_overlay``.
"""

from __future__ import annotations

from typing import Any, Callable

from hmi.softkeys import Softkey

def view_keys(prefix: str, shown_view: Callable[[Any], str] | None = None,
              turning: Callable[[Any], bool] | None = None) -> list[Softkey]:
    """The projection keys (top view, the two sections), Zoom +/- and Fit; with
    ``shown_view`` (the screen → the view drawn) the drawn projection's key is shown pressed.
    ``turning`` (the screen → it is a lathe's, whose views draw the half section): the projection
    keys are greyed there, because the half section is the one view of a lathe (choice: the manuals do not
    describe the simulation's views; a mill's top view of a lathe's path is a line)."""
    def milling(screen: Any) -> bool:
        return turning is None or not turning(screen)

    def shown(view: str) -> Callable[[Any], bool] | None:
        if shown_view is None:
            return None
        return lambda screen: milling(screen) and shown_view(screen) == view

    return [
        Softkey(f"{prefix}.xy", "Top view\nXY", f"{prefix}_view('XY')", enabled=milling, active=shown("XY")),
        Softkey(f"{prefix}.xz", "Side view\nXZ", f"{prefix}_view('XZ')", enabled=milling, active=shown("XZ")),
        Softkey(f"{prefix}.yz", "Side view\nYZ", f"{prefix}_view('YZ')", enabled=milling, active=shown("YZ")),
        Softkey(f"{prefix}.zoom_in", "Zoom +", f"{prefix}_zoom(1)"),
        Softkey(f"{prefix}.zoom_out", "Zoom -", f"{prefix}_zoom(-1)"),
        Softkey(f"{prefix}.fit", "Fit", f"{prefix}_fit"),
    ]


def overlay_key(prefix: str, overlay_on: Callable[[Any], bool]) -> Softkey:
    """Path on/off: the toolpath drawn over the material (pressed while it is)."""
    return Softkey(f"{prefix}.overlay", "Path\non/off", f"{prefix}_overlay", active=overlay_on)
