"""The measuring windows of JOG: Measure workpiece (edge, Z surface) and Measure tool (length).

Manual measuring ("scratching", 002 L31279-31290): the operator jogs the tool (a cutter
turning, or a 3D probe) to the surface and presses the window's softkey. The touch is the
tool's position now (the centre of the cutter in the plane, the tool carrier on Z); the
arithmetic is the kernel's (``nck.queries``: ``edge_position``, ``z_surface``,
``tool_length``, ``offset_for``). The window shows the values before anything is written:

- Measure workpiece: the edge (X/Y: one tool radius beyond the centre in the approach
  direction; Z: the tool tip) in the MCS and the translation that makes it read the
  setpoint; ⇧F5 "Set WO" writes it with ``SetActualValue(point_mcs=…)`` into the active
  offset (under G500 the PRESET/scratching frame).
- Measure tool: the length of the active edge from touching a surface whose Z is known —
  typed as its WCS value (Z0, as on the panel), or the top of the reference block of the
  machine set-up (its fixed-point value); ⇧F5 writes it into the geometry (``$TC_DP3``) or,
  by choice, the difference into the wear (``$TC_DP12``). The radius from touching an edge
  of known X (X0 typed, WCS) in the chosen direction: ``$TC_DP6`` or the wear ``$TC_DP15``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from rich.text import Text
from textual.app import ComposeResult

from nck import commands as cmd, fixed
from nck.queries import (MachineSetupData, ReadData, edge_position, offset_for, tool_length, tool_radius,
                         z_surface)
from nck.status import NckStatus

from hmi.i18n import N_, _
from hmi.softkeys import Softkey
from screens.machine_jog_form import FieldSpec, JogForm
from screens.machine_jog_points import APPROACHES, POINT_WINDOWS, PointWindows
from screens.machine_jog_touch import touch_now

if TYPE_CHECKING:
    from hmi.area import AreaBase

WORKPIECE_WINDOWS = ("measwp", *POINT_WINDOWS)
"""The views of Measure workpiece: edge / Z surface, corner, rotated corner, hole and spigot."""

MEASURE_WINDOWS = (*WORKPIECE_WINDOWS, "meastool")
"""The views of the measuring windows."""

WORKPIECE_FUNCTIONS = (("edge", N_("Edge /\nZ surface"), "measwp"), ("corner", N_("Corner"), "meascorner"),
                       ("rotated", N_("Rotated\ncorner"), "measrot"), ("circle", N_("Hole /\nspigot"), "meascircle"))
"""The vertical softkeys ⇧F1 … ⇧F4 of Measure workpiece: the measuring function (its window)."""

REFERENCES = (N_("Z0 typed (WCS)"), N_("reference block"))
"""Where the surface touched for the tool length is known from."""

TOOL_DATA = (N_("geometry"), N_("wear"))

TOOL_MEASURES = (N_("length"), N_("radius"))
"""What Measure tool measures: the length (touch from above) or the radius (touch an X edge)."""


@dataclass(frozen=True)
class EdgePreview:
    """What "Set WO" of Measure workpiece would write: the edge in the MCS and the offset."""

    axis: str
    edge_mcs: float
    setpoint: float
    translation: float


@dataclass(frozen=True)
class LengthPreview:
    """What Measure tool would write: the length (or radius) of ``tool``/``edge`` and the
    surface (or edge) in the MCS it was measured against."""

    tool: int
    edge: int
    surface_mcs: float
    length: float
    radius: bool = False


def _showing(view: str) -> Callable[[object], bool]:
    """A softkey predicate: the screen shows window ``view``."""
    return lambda screen: getattr(screen, "view", None) == view


def _with_points(screen: object) -> bool:
    """A softkey predicate: the screen shows a window that measures from several points."""
    return getattr(screen, "view", None) in POINT_WINDOWS


def _number(text: str) -> float | None:
    try:
        return float(text.strip())
    except ValueError:
        return None


class MeasureWindows:
    """The measuring windows of one Machine area screen."""

    def __init__(self, screen: AreaBase) -> None:
        self.screen = screen
        self.points = PointWindows(screen)

    def compose(self, axes: tuple[str, ...]) -> ComposeResult:
        """The two windows."""
        yield JogForm("Measure workpiece — edge or Z surface (touch, then ⇧F5 Set WO)", (
            FieldSpec("axis", "Edge in axis (Z: surface)", choices=axes),
            FieldSpec("approach", "Approached in direction", choices=APPROACHES),
            FieldSpec("setpoint", "Setpoint of the edge (WCS)", "mm", initial="0"),
        ), "Jog to the surface   ←/→ choice   ⇧F5 Set WO   F10 back", id="view-measwp")
        yield JogForm("Measure tool — length or radius of the active tool (touch, then ⇧F5)", (
            FieldSpec("measure", "Measure", choices=TOOL_MEASURES),
            FieldSpec("reference", "Length: surface known from", choices=REFERENCES),
            FieldSpec("z0", "Length: Z0 of the surface (WCS)", "mm", initial="0"),
            FieldSpec("approach", "Radius: approached X edge in", choices=APPROACHES),
            FieldSpec("x0", "Radius: X0 of the edge (WCS)", "mm", initial="0"),
            FieldSpec("target", "Write into", choices=TOOL_DATA),
        ), "Touch with the tool tip (length) or its side (radius)   ⇧F5 Set   F10 back",
            id="view-meastool")
        yield from self.points.compose()

    def vertical_softkeys(self, view: str) -> list[Softkey | None]:
        """Measure workpiece: ⇧F1 … ⇧F4 the function, ⇧F5 Set WO, ⇧F6 save point, ⇧F7 delete
        the points; Measure tool: ⇧F5 writes what the window previews."""
        if view in WORKPIECE_WINDOWS:
            return [*(Softkey(f"measwp.{name}", label, f"jog('measure_function', '{window}')",
                              active=_showing(window)) for name, label, window in WORKPIECE_FUNCTIONS),
                    Softkey("measwp.set", "Set\nWO", "jog('measure_set')"),
                    Softkey("measwp.save_point", "Save\npoint", "jog('measure_point')", enabled=_with_points),
                    Softkey("measwp.delete_points", "Delete\npoints", "jog('measure_delete')",
                            enabled=_with_points)]
        return [None] * 4 + [Softkey("meastool.set", "Set\nlength/radius", "jog('measure_set')")]

    # -- previews --------------------------------------------------------------------------
    def _form(self, view: str) -> JogForm:
        return self.screen.query_one(f"#view-{view}", JogForm)

    def edge_preview(self, status: NckStatus) -> EdgePreview | str:
        """The edge from the tool's position now, or what is missing (panel words)."""
        form = self._form("measwp")
        axis = form.value("axis")
        setpoint = _number(form.value("setpoint"))
        if setpoint is None:
            return _("Setpoint: enter a number")
        by_name = {a.name: a for a in status.axes}
        if axis not in by_name:
            return _("{axis}: no such axis").format(axis=axis)
        modal = status.channel.modal
        found = touch_now(self.screen.ask, status)
        if isinstance(found, str):
            return found
        touch = found.position_mcs[axis]
        if axis == "Z":  # a probe's length is to its ball's centre: the surface is a radius lower
            edge = z_surface(touch, modal.tool_length_mm, modal.tool_radius_mm if found.probe else 0.0)
        else:
            approach = 1 if form.value("approach") == "+" else -1
            edge = edge_position(touch, approach, modal.tool_radius_mm)
        return EdgePreview(axis, edge, setpoint, offset_for(edge, setpoint))

    def length_preview(self, status: NckStatus) -> LengthPreview | str:
        """The active tool's length from the tool's position now, or what is missing."""
        modal = status.channel.modal
        if modal.tool <= 0 or modal.edge <= 0:
            return _("No tool active: load one with T,S,M")
        by_name = {a.name: a for a in status.axes}
        if "Z" not in by_name:
            return _("No Z axis")
        z = by_name["Z"]
        form = self._form("meastool")
        if form.value("measure") == "radius":
            x0 = _number(form.value("x0"))
            if x0 is None or "X" not in by_name:
                return _("X0: enter a number")
            edge_mcs = x0 + self._translation_in_force("X", status)
            approach = 1 if form.value("approach") == "+" else -1
            radius = tool_radius(by_name["X"].position_mcs, approach, edge_mcs)
            if radius <= 0:
                return _("Radius {radius}: the tool centre is not before the edge X0 in the approach "
                         "direction — touch the edge, or check X0 and the direction").format(radius=fixed(radius))
            return LengthPreview(modal.tool, modal.edge, edge_mcs, radius, radius=True)
        if form.value("reference") == REFERENCES[1]:
            setup = self.screen.ask(MachineSetupData())
            reference = getattr(setup, "reference", None)
            if reference is None:
                return _("No reference block in the machine set-up")
            surface = reference.top_z_mcs
        else:
            z0 = _number(form.value("z0"))
            if z0 is None:
                return _("Z0: enter a number")
            # the surface's MCS is its WCS value Z0 plus the translations in force (from the
            # offsets themselves, independent of the tool whose length is being measured)
            surface = z0 + self._translation_in_force("Z", status)
        return LengthPreview(modal.tool, modal.edge, surface, tool_length(z.position_mcs, surface))

    def show(self, view: str, status: NckStatus) -> None:
        """Redraw the preview of window ``view``."""
        if view in POINT_WINDOWS:
            self.points.show(view, status)
            return
        form = self._form(view)
        preview = self.edge_preview(status) if view == "measwp" else self.length_preview(status)
        text = Text()
        if isinstance(preview, str):
            text.append(f" {preview}")
        elif isinstance(preview, EdgePreview):
            modal = status.channel.modal
            text.append(" " + _("Tool radius {radius}   length {length}").format(
                radius=fixed(modal.tool_radius_mm), length=fixed(modal.tool_length_mm)) + "\n")
            text.append(" " + _("Edge {axis} (MCS) {edge}   → {axis} {setpoint} in the WCS: translation "
                                "{translation} (no other offset active)").format(
                axis=preview.axis, edge=fixed(preview.edge_mcs), setpoint=fixed(preview.setpoint),
                translation=fixed(preview.translation)), style="bold")
        elif preview.radius:
            text.append(f" T{preview.tool} D{preview.edge}   " + _("edge X (MCS) {edge}").format(
                edge=fixed(preview.surface_mcs)) + "\n")
            text.append(" " + _("Radius = {radius}").format(radius=fixed(preview.length)), style="bold")
        else:
            text.append(f" T{preview.tool} D{preview.edge}   " + _("surface Z (MCS) {surface}").format(
                surface=fixed(preview.surface_mcs)) + "\n")
            text.append(" " + _("Length 1 = {length}").format(length=fixed(preview.length)), style="bold")
        form.show_info(text)

    # -- writing ---------------------------------------------------------------------------
    def set_value(self, view: str, say: Callable[[str], None]) -> None:
        """⇧F5: write the previewed value (Set WO / tool length)."""
        status = self.screen.status
        if status is None:
            return
        if view in POINT_WINDOWS:
            self.points.set_wo(view, say)
            return
        if view == "measwp":
            preview = self.edge_preview(status)
            if isinstance(preview, str):
                say(preview)
                return
            point = {a.name: a.position_mcs for a in status.axes if a.kind != "spindle"}
            point[preview.axis] = preview.edge_mcs
            if isinstance(self.screen.submit(cmd.SetActualValue(preview.axis, preview.setpoint,
                                                                point_mcs=point)), cmd.Accepted):
                say(_("Set WO: edge {axis} = {setpoint}").format(axis=preview.axis, setpoint=fixed(preview.setpoint)))
            return
        length = self.length_preview(status)
        if isinstance(length, str):
            say(length)
            return
        t, d = length.tool, length.edge
        geometry_index, wear_index = (6, 15) if length.radius else (3, 12)
        geometry, wear = self._tool_value(t, d, geometry_index), self._tool_value(t, d, wear_index)
        # the measured value is geometry + wear: the chosen part takes the difference
        if self._form("meastool").value("target") == "wear":
            name, value = f"$TC_DP{wear_index}[{t},{d}]", length.length - geometry
        else:
            name, value = f"$TC_DP{geometry_index}[{t},{d}]", length.length - wear
        if isinstance(self.screen.submit(cmd.WriteData(name, value)), cmd.Accepted):
            say(f"T{t} D{d}: {name} = {fixed(value)}")

    def _translation_in_force(self, axis: str, status: NckStatus) -> float:
        """PRESET frame + base frame + active settable offset (coarse and fine) along ``axis``."""
        data = self.screen.ask(ReadData()).data
        if data is None:
            return 0.0
        offsets = [data.setframe, data.base_frame]
        active = status.channel.modal.gcodes.get(8, "G500")
        if active in data.settable_frames:
            offsets.append(data.settable_frames[active])
        return sum(float(o.trans.get(axis, 0.0)) + float(o.fine.get(axis, 0.0)) for o in offsets)

    def _tool_value(self, tool: int, edge: int, index: int) -> float:
        data = self.screen.ask(ReadData()).data
        found = data.tools.get((tool, edge)) if data is not None else None
        return float(found.get(index)) if found is not None else 0.0
