"""Measure workpiece from several touches: corner, rotated corner, hole and spigot (issue 22).

Manual measuring with the active cutter or a 3D probe (002 L31279-31290; SINUMERIK
Operate's "Measure workpiece" of JOG): the operator touches the workpiece, saves the
touch as a point (⇧F6 "Save point": P1, P2, …; with a probe its trigger position, see
:mod:`screens.machine_jog_touch`), and the window shows what it measured before ⇧F5
"Set WO" writes it into the active work offset (under G500 the PRESET/scratching frame;
a rotation only into a settable offset G54 …).

- Corner (right angle, edges parallel to X and Y): P1 touches the edge across X, P2 the
  edge across Y; each edge lies one tool radius beyond the touch in its approach direction.
- Rotated corner: P1 and P2 on edge 1, P3 on edge 2 (perpendicular to edge 1). The angle of
  edge 1 against X (folded into −45° … 45°) is written as the rotation about Z of the work
  offset, then the corner is set to X0/Y0 (``SetWorkOffsetRotation``, ``SetActualValue``).
- Hole / spigot: 3 or 4 touches on the wall, from inside (hole) or outside (spigot); the
  centre is set to X0/Y0.

The arithmetic is the kernel's (``nck.queries``: ``corner``, ``rotated_corner``, ``circle``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from rich.text import Text
from textual.app import ComposeResult

from nck import commands as cmd, fixed
from nck.queries import circle, corner, offset_for, rotated_corner
from nck.status import NckStatus

from hmi.i18n import N_, _
from screens.machine_jog_form import FieldSpec, JogForm
from screens.machine_jog_touch import Touch, touch_now

if TYPE_CHECKING:
    from hmi.area import AreaBase

APPROACHES = ("+", "−")
"""The direction the tool moved in when it touched an edge (+: towards larger values)."""

DIRECTIONS = {"+X": (1.0, 0.0), "−X": (-1.0, 0.0), "+Y": (0.0, 1.0), "−Y": (0.0, -1.0)}
"""Approach directions of a rotated corner's edges (roughly: the edge need not be parallel)."""

CIRCLES = (N_("hole"), N_("spigot"))

POINTS_NEEDED = {"meascorner": (2, 2), "measrot": (3, 3), "meascircle": (3, 4)}
"""Points each window needs: (fewest, most)."""

POINT_WINDOWS = tuple(POINTS_NEEDED)
"""The views of the windows measuring from several points."""


@dataclass(frozen=True)
class PointsResult:
    """What "Set WO" would write: the workpiece point (MCS, X/Y) that gets ``setpoint``, the
    rotation about Z (``None``: none written), and a line describing the measurement."""

    x_mcs: float
    y_mcs: float
    setpoint: tuple[float, float]
    angle_deg: float | None
    what: str


def _number(text: str) -> float | None:
    try:
        return float(text.strip())
    except ValueError:
        return None


def _sign(choice: str) -> int:
    return 1 if choice == "+" else -1


class PointWindows:
    """The corner, rotated corner and hole/spigot windows of one Machine area screen."""

    def __init__(self, screen: AreaBase) -> None:
        self.screen = screen
        self.points: dict[str, list[Touch]] = {view: [] for view in POINT_WINDOWS}

    def compose(self) -> ComposeResult:
        """The three windows."""
        hint = N_("Touch, ⇧F6 save point   ⇧F7 delete points   ⇧F5 Set WO   F10 back")
        yield JogForm("Measure workpiece — right-angled corner (P1 on the X edge, P2 on the Y edge)", (
            FieldSpec("x_approach", "X edge approached in", choices=APPROACHES),
            FieldSpec("y_approach", "Y edge approached in", choices=APPROACHES),
            FieldSpec("x0", "X0 of the corner (WCS)", "mm", initial="0"),
            FieldSpec("y0", "Y0 of the corner (WCS)", "mm", initial="0"),
        ), hint, id="view-meascorner")
        yield JogForm("Measure workpiece — rotated corner (P1, P2 on edge 1, P3 on edge 2)", (
            FieldSpec("first", "Edge 1 approached in", choices=tuple(DIRECTIONS)),
            FieldSpec("third", "Edge 2 approached in", choices=("+Y", "−Y", "+X", "−X")),
            FieldSpec("x0", "X0 of the corner (WCS)", "mm", initial="0"),
            FieldSpec("y0", "Y0 of the corner (WCS)", "mm", initial="0"),
        ), hint, id="view-measrot")
        yield JogForm("Measure workpiece — hole or spigot (3 or 4 points on the wall)", (
            FieldSpec("kind", "Measure", choices=CIRCLES),
            FieldSpec("x0", "X0 of the centre (WCS)", "mm", initial="0"),
            FieldSpec("y0", "Y0 of the centre (WCS)", "mm", initial="0"),
        ), hint, id="view-meascircle")

    def _form(self, view: str) -> JogForm:
        return self.screen.query_one(f"#view-{view}", JogForm)

    # -- points ----------------------------------------------------------------------------
    def save_point(self, view: str, say: Callable[[str], None]) -> None:
        """⇧F6: the touch now becomes the next point (a probe: a trigger newer than the last point)."""
        status = self.screen.status
        if status is None or view not in POINTS_NEEDED:
            return
        points = self.points[view]
        most = POINTS_NEEDED[view][1]
        if len(points) >= most:
            say(_("{count} points saved: ⇧F5 Set WO, or ⇧F7 delete the points").format(count=most))
            return
        found = touch_now(self.screen.ask, status, max((p.seq for p in points), default=0))
        if isinstance(found, str):
            say(found)
            return
        points.append(found)
        say(_("P{number} saved").format(number=len(points)))

    def delete_points(self, view: str) -> None:
        """⇧F7: forget the points of window ``view``."""
        if view in self.points:
            self.points[view].clear()

    # -- result ----------------------------------------------------------------------------
    def result(self, view: str, status: NckStatus) -> PointsResult | str:
        """What the points measured, or what is missing (panel words)."""
        form = self._form(view)
        x0, y0 = _number(form.value("x0")), _number(form.value("y0"))
        if x0 is None or y0 is None:
            return _("X0 / Y0: enter a number")
        points = self.points[view]
        fewest = POINTS_NEEDED[view][0]
        if len(points) < fewest:
            return _("Touch and save P{number} ({count} points needed)").format(number=len(points) + 1, count=fewest)
        radius = status.channel.modal.tool_radius_mm
        xy = [(p.position_mcs["X"], p.position_mcs["Y"]) for p in points]
        if view == "meascorner":
            x, y = corner(xy[0][0], _sign(form.value("x_approach")), xy[1][1], _sign(form.value("y_approach")),
                          radius)
            return PointsResult(x, y, (x0, y0), None, _("Corner"))
        if view == "measrot":
            if xy[0] == xy[1]:
                return _("P1 and P2 are the same point: touch edge 1 at two places")
            found = rotated_corner(xy[0], xy[1], DIRECTIONS[form.value("first")], xy[2],
                                   DIRECTIONS[form.value("third")], radius)
            return PointsResult(found.x_mm, found.y_mm, (x0, y0), found.angle_deg,
                                _("Corner, edge 1 at {angle}°").format(angle=fixed(found.angle_deg)))
        hole = form.value("kind") == "hole"
        (ax, ay), (bx, by), (cx, cy) = xy[:3]
        if abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) < 1e-6:
            return _("P1, P2, P3 lie on a straight line: touch the wall at places around it")
        found_circle = circle(xy, radius, hole)
        if found_circle.diameter_mm <= 0.0:
            return _("No spigot that size: touch it from outside (or choose hole)")
        return PointsResult(found_circle.x_mm, found_circle.y_mm, (x0, y0), None,
                            (_("Centre of the hole, Ø {diameter}") if hole else _("Centre of the spigot, Ø {diameter}"))
                            .format(diameter=fixed(found_circle.diameter_mm)))

    def show(self, view: str, status: NckStatus) -> None:
        """Redraw the preview of window ``view``: the points and what they measured."""
        text = Text()
        modal = status.channel.modal
        text.append(" " + _("Tool radius {radius}").format(radius=fixed(modal.tool_radius_mm)) + "  ")
        for number, point in enumerate(self.points[view], start=1):
            text.append(f" P{number} X {fixed(point.position_mcs['X'])} Y {fixed(point.position_mcs['Y'])}"
                        + (" " + _("(probe)") if point.probe else ""))
        text.append("\n")
        found = self.result(view, status)
        if isinstance(found, str):
            text.append(f" {found}")
        else:
            tx, ty = offset_for(found.x_mcs, found.setpoint[0]), offset_for(found.y_mcs, found.setpoint[1])
            text.append(f" {found.what}: X (MCS) {fixed(found.x_mcs)}  Y (MCS) {fixed(found.y_mcs)}\n", style="bold")
            if found.angle_deg is None:
                text.append(" " + _("→ X {x} Y {y} in the WCS: translation X {tx} Y {ty} (no other offset active)").format(
                    x=fixed(found.setpoint[0]), y=fixed(found.setpoint[1]), tx=fixed(tx), ty=fixed(ty)), style="bold")
            else:
                text.append(" " + _("→ rotation Z {angle}°, corner X {x} Y {y} in the WCS (into G54 …, not G500)").format(
                    angle=fixed(found.angle_deg), x=fixed(found.setpoint[0]), y=fixed(found.setpoint[1])), style="bold")
        self._form(view).show_info(text)

    def set_wo(self, view: str, say: Callable[[str], None]) -> None:
        """⇧F5: write the rotation (rotated corner) and the X/Y setpoints at the measured point."""
        status = self.screen.status
        if status is None:
            return
        found = self.result(view, status)
        if isinstance(found, str):
            say(found)
            return
        if found.angle_deg is not None and not isinstance(
                self.screen.submit(cmd.SetWorkOffsetRotation(found.angle_deg)), cmd.Accepted):
            return
        point = dict(self.points[view][0].position_mcs)
        point.update(X=found.x_mcs, Y=found.y_mcs)
        for axis, value in zip(("X", "Y"), found.setpoint):
            if not isinstance(self.screen.submit(cmd.SetActualValue(axis, value, point_mcs=point)), cmd.Accepted):
                return
        say(_("Set WO: X {x} Y {y}").format(x=fixed(found.setpoint[0]), y=fixed(found.setpoint[1]))
            + (", " + _("rotation {angle}°").format(angle=fixed(found.angle_deg)) if found.angle_deg is not None else ""))
