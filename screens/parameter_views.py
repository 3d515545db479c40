"""The tables of the Parameter area, built from the NC data (an :class:`nck.queries.DataView`, read only).

Each ``*_table`` function returns a :class:`~hmi.widgets.data_table.DataTable`
whose editable cells name the datum for ``WriteData``: ``$TC_DP<n>[t,d]``,
``$P_UIFR[n,axis,comp]``, ``$P_UBFR[axis,comp]``, ``R<n>``, ``GUD:<name>``,
``SD…``. ``levels(name)`` returns the access level a write needs (from the
kernel), so cells the operator may not change are shown dimmed.
"""

from __future__ import annotations

from typing import Any, Callable

from nck import fixed, trimmed
from nck.queries import DataView
from nck.status import NckStatus

from hmi.i18n import N_, _, data_text
from hmi.widgets.data_table import Cell, Column, DataTable, widest_text

LevelOf = Callable[[str], int]

TOOL_TYPES = {
    100: N_("Milling tool"), 110: N_("Ball end mill"), 111: N_("Ball end mill (conical)"), 120: N_("End mill"),
    121: N_("End mill with corner rounding"), 130: N_("Angle head cutter"), 140: N_("Face mill"),
    145: N_("Thread cutter"), 150: N_("Side mill"), 155: N_("Bevel cutter"), 200: N_("Twist drill"),
    205: N_("Solid drill"), 210: N_("Boring bar"), 220: N_("Centre drill"), 230: N_("Countersink"),
    231: N_("Counterbore"), 240: N_("Tap"), 250: N_("Reamer"), 500: N_("Roughing tool"), 510: N_("Finishing tool"),
    520: N_("Plunge cutter"), 530: N_("Parting tool"), 540: N_("Threading tool"), 550: N_("Button tool"),
    560: N_("Rotary drill"), 580: N_("3D turning tool"), 700: N_("Slotting saw"), 710: N_("3D probe"),
    711: N_("Edge probe"), 725: N_("Calibrating tool"), 730: N_("Stop"), 900: N_("Auxiliary tool"),
}
TOOL_GEOMETRY = ((1, N_("Type"), 6), (3, N_("Length 1"), 10), (4, N_("Length 2"), 10), (5, N_("Length 3"), 10),
                 (6, N_("Radius"), 10), (2, N_("Pos"), 4))
TOOL_WEAR = ((12, N_("ΔLength 1"), 11), (13, N_("ΔLength 2"), 11), (14, N_("ΔLength 3"), 11), (15, N_("ΔRadius"), 11))
FRAME_COMPONENTS = (("TR", N_("Translation")), ("FI", N_("Fine")), ("RT", N_("Rotation")), ("SC", N_("Scale")),
                    ("MI", N_("Mirror")))
SETTING_DATA = (
    ("JOG", "SD41110", None), ("JOG", "SD41010", None), ("JOG", "SD41200", None),
    (N_("Spindle"), "SD43210", "spindle"), (N_("Spindle"), "SD43220", "spindle"),
    (N_("Spindle"), "SD43230", "spindle"),
    (N_("Work area"), "SD43400", "linear"), (N_("Work area"), "SD43420", "linear"),
    (N_("Work area"), "SD43410", "linear"), (N_("Work area"), "SD43430", "linear"),
    (N_("Dry run"), "SD42100", None), (N_("Dry run"), "SD42101", None),
)


def edit_text(value: Any) -> str:
    """The start text of an input field for ``value``."""
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, float):
        return trimmed(value)
    return str(value)


def _datum(name: str, text: str, value: Any, levels: LevelOf, hint: str = "") -> Cell:
    return Cell(text, name, edit_text(value), levels(name), hint)


def path_axes(view: DataView) -> list[str]:
    """Names of the machine's linear and rotary axes (no spindles)."""
    return [a.name for a in view.machine.axes if a.kind != "spindle"]


def tool_table(view: DataView, status: NckStatus | None, levels: LevelOf, wear: bool = False) -> DataTable:
    """The tool list (geometry) or tool wear list: one row per cutting edge."""
    fields = TOOL_WEAR if wear else TOOL_GEOMETRY
    columns = [Column("", 1, "<"), Column("T", 6), Column("D", 3), Column("Tool type", 18, "<")]
    columns += [Column(title, width) for _param, title, width in fields]
    active = (status.channel.modal.tool, status.channel.modal.edge) if status is not None else (0, 0)
    rows = []
    for (tool, edge), data in sorted(view.data.tools.items()):
        kind = int(data.get(1))
        row = [Cell("▶" if (tool, edge) == active else ""), Cell(str(tool)), Cell(str(edge)),
               Cell(_(TOOL_TYPES[kind]) if kind in TOOL_TYPES
                    else (_("type {kind}").format(kind=kind) if kind else "—"))]
        for param, title, _width in fields:
            value = data.get(param)
            shown = str(int(value)) if param in (1, 2) else fixed(value)
            unit = "" if param in (1, 2) else " mm"
            row.append(_datum(f"$TC_DP{param}[{tool},{edge}]", shown, value, levels,
                              f"T{tool} D{edge} {_(title)}{unit}"))
        rows.append(row)
    if wear:
        title = N_("Tool wear  (ΔLength / ΔRadius are added to the geometry values)")
    else:
        title = N_("Tool list  (lengths and radius in mm; Pos = cutting edge position)")
    note = _("↑↓←→ select   Enter edit") + ("" if wear else "   " + _("▶ active tool/edge"))
    return DataTable(title, columns, rows, note)


def _component_word(title: str) -> str:
    """A frame component's name inside a sentence: lower case in English, the noun as translated."""
    translated = _(title)
    return title.lower() if translated == title else translated


def frame_names(view: DataView) -> list[str]:
    """The settable frames in the NC data: G54…G57, then G505… in order."""
    def order(name: str) -> int:
        number = int(name[1:])
        return number if number < 100 else number - 400
    return sorted(view.data.settable_frames, key=order)


def frame_index(name: str) -> int:
    """``$P_UIFR`` index of a settable frame name (G54 → 1, G505 → 5)."""
    number = int(name[1:])
    return number - 53 if 54 <= number <= 57 else number - 500


def frame_var(frame: str, axis: str, comp: str) -> str:
    """The ``WriteData`` name of one frame component (``BASE`` = base frame)."""
    if frame == "BASE":
        return f"$P_UBFR[{axis},{comp}]"
    return f"$P_UIFR[{frame_index(frame)},{axis},{comp}]"


def _offset(view: DataView, frame: str) -> Any:
    return view.data.base_frame if frame == "BASE" else view.data.settable_frames.get(frame)


def overview_table(view: DataView, status: NckStatus | None, levels: LevelOf) -> DataTable:
    """Work offsets: base frame and every settable frame, translation and rotation per axis."""
    axes = path_axes(view)
    geometry = [a for a in axes if a in ("X", "Y", "Z")]
    columns = [Column("", 1, "<"), Column("Work offset", 12, "<")]
    columns += [Column(f"{a} [mm]", 11) for a in axes]
    columns += [Column(f"Rot {a} [°]", 10) for a in geometry]
    active = status.channel.modal.gcodes.get(8, "G500") if status is not None else "G500"
    rows = []
    for frame in ["BASE"] + frame_names(view):
        offset = _offset(view, frame)
        label = _("Base frame") if frame == "BASE" else frame
        row = [Cell("▶" if frame == active else ""), Cell(label)]
        for axis in axes:
            value = float(offset.trans.get(axis, 0.0))
            row.append(_datum(frame_var(frame, axis, "TR"), fixed(value), value, levels,
                              _("{frame} {axis} translation in mm (active at the next selection of the frame)").format(frame=label, axis=axis)))
        for axis in geometry:
            value = float(offset.rot.get(axis, 0.0))
            row.append(_datum(frame_var(frame, axis, "RT"), fixed(value), value, levels,
                              _("{frame} rotation about {axis} in degrees (-360 … 360)").format(frame=label, axis=axis)))
        rows.append(row)
    return DataTable("Work offsets — overview  (changes take effect when the frame is next selected)",
                     columns, rows, "↑↓←→ select   Enter edit   Details: all components of the frame")


def details_table(view: DataView, frame: str, levels: LevelOf) -> DataTable:
    """One frame in full: translation, fine offset, rotation, scale and mirror per axis."""
    label = _("Base frame") if frame == "BASE" else frame
    offset = _offset(view, frame)
    columns = [Column("Axis", 6, "<"), Column("Translation", 12), Column("Fine", 10),
               Column("Rotation [°]", 13), Column("Scale", 9), Column("Mirror", 7)]
    rows = []
    for axis in path_axes(view):
        row = [Cell(axis)]
        for comp, title in FRAME_COMPONENTS:
            if comp == "MI":
                value: Any = bool(offset.mirror.get(axis, False))
                row.append(Cell(_("yes") if value else _("no"), frame_var(frame, axis, comp),
                                "1" if value else "0", levels(frame_var(frame, axis, comp)),
                                _("{frame} {axis} mirror: 1 on, 0 off").format(frame=label, axis=axis)))
                continue
            table = {"TR": offset.trans, "FI": offset.fine, "RT": offset.rot, "SC": offset.scale}[comp]
            value = float(table.get(axis, 1.0 if comp == "SC" else 0.0))
            places = 5 if comp == "SC" else 3
            row.append(_datum(frame_var(frame, axis, comp), fixed(value, places), value, levels,
                              f"{label} {axis} {_component_word(title)}"))
        rows.append(row)
    return DataTable(_("Work offset {frame} — details").format(frame=label), columns, rows,
                     "Enter edit   Details again / F10: back to the overview")


def active_chain_table(view: DataView, status: NckStatus | None) -> DataTable:
    """The active frame chain: system frame for PRESET/scratching, base frame, active settable
    frame, and the total offset."""
    axes = path_axes(view)
    active = status.channel.modal.gcodes.get(8, "G500") if status is not None else "G500"
    rows = []
    setframe = view.data.setframe  # the system frame for PRESET and scratching (Set WO under G500)
    rows.append([Cell(_("PRESET / scratching ($P_SETFR)"))] + [Cell(fixed(setframe.trans.get(a, 0.0))) for a in axes])
    base = view.data.base_frame
    rows.append([Cell(_("Base frame"))] + [Cell(fixed(base.trans.get(a, 0.0))) for a in axes])
    settable = view.data.settable_frames.get(active) if active != "G500" else None
    label = (_("Settable frame {frame}") if settable is not None else _("Settable frame {frame} (zero)")).format(
        frame=active)
    rows.append([Cell(label)] + [
        Cell(fixed((settable.trans.get(a, 0.0) + settable.fine.get(a, 0.0)) if settable else 0.0))
        for a in axes])
    rows.append([Cell(_("Programmable frame"))] + [Cell(_("(program)")) for _axis in axes])
    if status is not None:
        by_name = {a.name: a for a in status.axes}
        rows.append([Cell(_("Total (MCS − WCS, with tool)"))] + [
            Cell(fixed(by_name[a].position_mcs - by_name[a].position_wcs) if a in by_name else "")
            for a in axes])
    columns = [Column("Frame", widest_text(rows, 0, 30), "<")] + [Column(f"{a} [mm]", 11) for a in axes]
    return DataTable(_("Active work offset chain  (active settable frame: {frame})").format(frame=active), columns, rows,
                     "Rotations, scale and mirror: see Overview / Details")


def r_table(view: DataView, levels: LevelOf) -> DataTable:
    """The R parameters with their values."""
    columns = [Column("R parameter", 12, "<"), Column("Value", 20)]
    rows = []
    for index, value in enumerate(view.data.r):
        rows.append([Cell(f"R{index}"), _datum(f"R{index}", fixed(value, 5), value, levels,
                                               f"R{index} (REAL)")])
    return DataTable("R variables", columns, rows,
                     "Enter edit   Clear all: every R parameter to 0 (asks first)")


def _type_name(value: Any) -> str:
    if isinstance(value, bool):
        return "BOOL"
    if isinstance(value, int):
        return "INT"
    if isinstance(value, float):
        return "REAL"
    if isinstance(value, str):
        return "STRING"
    return type(value).__name__.upper()


def _value_text(value: Any) -> str:
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, float):
        return fixed(value, 5)
    return str(value)


def gud_table(view: DataView, levels: LevelOf) -> DataTable:
    """The global user variables (GUD) with their types; arrays one row per element."""
    columns = [Column("Name", 24, "<"), Column("Type", 12, "<"), Column("Value", 24)]
    rows = []
    for name, value in sorted(view.data.gud.items()):
        if isinstance(value, list):
            for index, item in enumerate(value):
                rows.append([Cell(f"{name}[{index}]"), Cell(f"{_type_name(item)}[{len(value)}]"),
                             _datum(f"GUD:{name}[{index}]", _value_text(item), item, levels,
                                    f"{name}[{index}] ({_type_name(item)})")])
        else:
            rows.append([Cell(name), Cell(_type_name(value)),
                         _datum(f"GUD:{name}", _value_text(value), value, levels,
                                f"{name} ({_type_name(value)})")])
    return DataTable("User variables — global user data (GUD, defined with DEF NCK/CHAN)",
                     columns, rows, "Enter edit   Local user data (LUD) exist only while their program runs")


def setting_table(view: DataView, levels: LevelOf) -> DataTable:
    """Setting data: JOG, spindle limits, working area limits with enables, dry run."""
    store = view.machine_data
    columns = [Column("Group", 10, "<"), Column("Number", 8, "<"), Column("Name", 30, "<"),
               Column("Axis", 5, "<"), Column("Value", 14), Column("Unit", 8, "<")]
    spindles = [a.name for a in view.machine.axes if a.kind == "spindle"]
    linear = [a.name for a in view.machine.axes if a.kind == "linear"]
    rows = []
    for group, key, axes_kind in SETTING_DATA:
        definition = store.catalog.get(key)
        if definition is None:
            continue
        targets: list[str | None] = [None]
        if axes_kind == "spindle":
            targets = list(spindles)
        elif axes_kind == "linear":
            targets = list(linear)
        for axis in targets:
            name = f"{key}[{axis}]" if axis else key
            value = store.value(name)
            if definition.type == "bool":
                shown = _("on") if value else _("off")
            elif definition.type == "real":
                shown = fixed(value)
            else:
                shown = str(value)
            limits = ""
            if definition.min is not None and definition.max is not None:
                limits = f", {definition.min:g} … {definition.max:g}"
            unit = store.unit(name)
            title = data_text("md", definition.number, "title", definition.title)
            hint = f"{definition.identifier}: {title} ({_(unit) or definition.type}{limits})"
            rows.append([Cell(_(group)), Cell(key), Cell(definition.name), Cell(axis or ""),
                         _datum(name, shown, value, levels, hint), Cell(_(unit))])
    return DataTable("Setting data  (take effect at once)", columns, rows,
                     "Enter edit   Work area limits act when their enable is on (G25/G26, WALIMON)")
