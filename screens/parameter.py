"""The Parameter area (OFFSET key): tools, wear, work offsets, R variables, user variables, setting data.

Views (horizontal softkeys): tool list, tool wear, work offsets (vertical:
active chain, overview, details), R variables, user variables (GUD), setting
data. The selected cell moves with the arrow keys; Enter (or the ``Edit``
softkey) opens an input field, and the value goes to the kernel as
``WriteData`` — the kernel checks the access level and the limits, and a
refusal names the level needed. Cells the current level may not write are
dimmed. Tools and edges are added with ``$TC_DP`` writes and deleted with
``DeleteToolEdge``; "Clear all" R parameters asks first (``ClearRParameters``).
"""

from __future__ import annotations

from typing import Any, Callable, ClassVar

from textual import events
from textual.app import ComposeResult

from nck import commands as cmd
from nck import queries
from nck.commands import Accepted
from nck.status import NckStatus

from hmi.area import AreaBase
from hmi.dialogs import ConfirmDialog, ValueDialog
from hmi.i18n import _
from hmi.softkeys import Softkey, SoftkeyMenu, view_softkey
from hmi.widgets.data_table import (
    EDIT_BINDINGS, Column, DataTable, TableCursor, TableWindow, edit_on_typed_key, level_refusal,
)
from screens.parameter_views import (
    active_chain_table, details_table, frame_names, gud_table, overview_table, r_table, setting_table,
    tool_table,
)

VIEWS = ("tools", "wear", "wo_active", "wo_overview", "wo_details", "r", "gud", "sd")
DEFAULT_TOOL_TYPE = 120  # end mill


def level_key(name: str) -> str:
    """Data that share a protection level share this key (one level lookup per table)."""
    upper = name.upper()
    if upper.startswith("R"):
        return "R"
    if upper.startswith("GUD:"):
        return "GUD"
    if upper.startswith("$TC_DP"):
        return upper.split("[")[0]
    if upper.startswith("$P_UIFR") or upper.startswith("$P_UBFR"):
        return upper[:7] + upper[-3:]
    return upper


class ParameterScreen(AreaBase):
    """The Parameter operating area."""

    AREA_ID: ClassVar[str] = "parameter"
    AREA_TITLE: ClassVar[str] = "PARAMETER"
    CSS_PATH = "parameter.tcss"
    BINDINGS = EDIT_BINDINGS

    def __init__(self) -> None:
        super().__init__(id="area-parameter")
        self.view = "tools"
        self.cursors = {view: TableCursor() for view in VIEWS}
        self.cursors["wear"] = self.cursors["tools"]  # the same edge selected in both lists
        self.detail_frame = "G54"
        self.table: DataTable | None = None
        self._levels: dict[str, int] = {}
        self._levels_at = -1

    # -- kernel data (read through the bridge; writes are commands) ----------------------------
    @property
    def data_view(self) -> queries.DataView:
        """The machine, NC data and machine data, read through the bridge."""
        return self.ask(queries.ReadData())

    def level_of(self, name: str) -> int:
        """The access level writing ``name`` needs (cached per access level)."""
        if self._levels_at != self.access_level:
            self._levels = {}
            self._levels_at = self.access_level
        key = level_key(name)
        if key not in self._levels:
            self._levels[key] = self.ask(queries.RequiredLevel(name))
        return self._levels[key]

    def action_level(self, action_name: str) -> int:
        """The level a protected function (``nck.access.Action`` name) needs; 7 if unknown."""
        return self.ask(queries.ActionLevel(action_name))

    # -- layout -------------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """One window: the table of the view on display."""
        yield TableWindow(id="param-table")

    def on_mount(self) -> None:
        """Show the first view."""
        super().on_mount()
        self.refresh_table()

    # -- softkeys -------------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Views on the horizontal keys, the view's own keys on the vertical ones."""
        def view_key(key_id: str, label: str, view: str, views: tuple[str, ...] = ()) -> Softkey:
            shown = views or (view,)
            return Softkey(key_id, label, f"show_view('{view}')", active=lambda s: s.view in shown)

        horizontal = [
            view_key("param.tools", "Tool\nlist", "tools"),
            view_key("param.wear", "Tool\nwear", "wear"),
            view_key("param.wo", "Work\noffset", "wo_overview", ("wo_active", "wo_overview", "wo_details")),
            view_key("param.r", "R\nvariables", "r"),
            view_key("param.gud", "User\nvariables", "gud"),
            view_key("param.sd", "Setting\ndata", "sd"),
        ]
        return SoftkeyMenu.of(horizontal, self._vertical_keys())

    def _vertical_keys(self) -> list[Softkey | None]:
        edit = Softkey("param.edit", "Edit\n(Enter)", "edit")
        if self.view == "tools":
            tool_level = self.level_of("$TC_DP1[1,1]")
            has_row = lambda s: s.selected_tool() is not None  # noqa: E731
            return [
                Softkey("param.tool.new", "New\ntool", "new_tool", level=tool_level),
                Softkey("param.tool.edge", "New\nedge", "new_edge", level=tool_level, enabled=has_row),
                Softkey("param.tool.del_edge", "Delete\nedge", "delete_tool(True)", level=tool_level,
                        enabled=has_row),
                Softkey("param.tool.del", "Delete\ntool", "delete_tool(False)", level=tool_level,
                        enabled=has_row),
                Softkey("param.tool.search", "Search", "search_tool"),
                None, None, edit,
            ]
        if self.view.startswith("wo_"):
            return [
                view_softkey("param.wo.active", "Active", "wo_active"),
                view_softkey("param.wo.overview", "Overview", "wo_overview"),
                Softkey("param.wo.details", "Details", "frame_details",
                        active=lambda s: s.view == "wo_details"),
                None, None, None, None, None if self.view == "wo_active" else edit,
            ]
        if self.view == "r":
            level = self.action_level("CLEAR_R_PARAMETERS")
            return [Softkey("param.r.clear", "Clear\nall", "clear_r", level=level),
                    None, None, None, None, None, None, edit]
        return [None] * 7 + [edit]

    def menu_recall(self) -> bool:
        """F10: from the frame details back to the overview, else the softkey level."""
        if self.pop_softkeys():
            return True
        if self.view == "wo_details":
            self.action_show_view("wo_overview")
            return True
        return False

    # -- actions ---------------------------------------------------------------------------------
    def action_show_view(self, view: str) -> None:
        """Show ``view`` (a message about the view left goes with it)."""
        if view != self.view:
            self.say("")
        self.view = view
        self.refresh_table()
        self.refresh_softkeys()

    def action_frame_details(self) -> None:
        """Details of the frame selected in the overview (toggles back from the details)."""
        if self.view == "wo_details":
            self.action_show_view("wo_overview")
            return
        if self.view == "wo_overview":
            row = self.cursors["wo_overview"].row
            frames = ["BASE"] + frame_names(self.data_view)
            self.detail_frame = frames[max(0, min(row, len(frames) - 1))]
        self.cursors["wo_details"] = TableCursor()
        self.action_show_view("wo_details")

    def action_cursor(self, rows: int, columns: int) -> None:
        """Arrow keys: move the selected cell."""
        if self.table is None:
            return
        self.cursors[self.view].move(self.table, int(rows), int(columns))
        self.refresh_table()
        self.refresh_softkeys()

    def on_key(self, event: events.Key) -> None:
        """A character typed on the selected cell starts its input (it replaces the value)."""
        if self.table is not None:
            edit_on_typed_key(event, self.action_edit)

    def action_edit(self, typed: str = "") -> None:
        """Enter / Edit: an input field for the selected value.

        ``typed``: the character typed on the cell, which the field starts with instead of the value.
        """
        if self.table is None:
            return
        cursor = self.cursors[self.view]
        cell = self.table.cell(cursor.row, cursor.column)
        if cell is None or not cell.name:
            self.hmi.set_hint(_("This value cannot be changed here"))
            return
        if self.access_level > cell.level:
            self.hmi.set_hint(level_refusal(cell, self.access_level))
            return
        name = cell.name

        def write(text: str | None) -> None:
            if text is not None:
                self.write(name, text.strip())

        self.app.push_screen(ValueDialog(_("Change {name}").format(name=name), cell.edit_text, cell.hint, typed=typed),
                             write)

    def write(self, name: str, value: object) -> bool:
        """Send one ``WriteData``; True when the kernel took it."""
        result = self.submit(cmd.WriteData(name, value))
        self.refresh_table()
        if isinstance(result, Accepted):
            self.hmi.set_hint(f"{name} = {value}")
            return True
        return False

    # tools
    def selected_tool(self) -> tuple[int, int] | None:
        """(T, D) of the selected row of the tool list, or None."""
        tools = sorted(self.data_view.data.tools)
        row = self.cursors[self.view if self.view in ("tools", "wear") else "tools"].row
        return tools[row] if 0 <= row < len(tools) else None

    def action_new_tool(self) -> None:
        """New tool: ask for the T number and the tool type; creates edge D1."""
        def create(text: str | None) -> None:
            if not text:
                return
            parts = text.replace(",", " ").split()
            try:
                tool = int(parts[0])
                kind = int(parts[1]) if len(parts) > 1 else DEFAULT_TOOL_TYPE
            except ValueError:
                self.hmi.set_hint(_("New tool: give the T number and optionally the type, e.g. 12 120"))
                return
            if any(t == tool for t, _edge in self.data_view.data.tools):
                self.hmi.set_hint(_("T{tool} exists already").format(tool=tool))
                return
            if self.write(f"$TC_DP1[{tool},1]", kind):
                self._select_tool(tool, 1)

        self.app.push_screen(ValueDialog(_("New tool: T number and type"), "",
                                         _("e.g. 12 120  (120 end mill, 200 twist drill, 500 roughing tool)")),
                             create)

    def action_new_edge(self) -> None:
        """New edge: the next free D of the selected tool, with the tool's type."""
        selected = self.selected_tool()
        if selected is None:
            return
        tool = selected[0]
        edges = [d for t, d in self.data_view.data.tools if t == tool]
        edge = max(edges) + 1
        kind = self.data_view.data.tools[(tool, 1 if 1 in edges else edges[0])].get(1)
        if self.write(f"$TC_DP1[{tool},{edge}]", int(kind)):
            self._select_tool(tool, edge)

    def action_delete_tool(self, edge_only: bool) -> None:
        """Delete the selected edge (or the whole tool) after asking."""
        selected = self.selected_tool()
        if selected is None:
            return
        tool, edge = selected
        what = f"T{tool} D{edge}" if edge_only else _("tool T{tool} with all its edges").format(tool=tool)

        def delete(yes: bool | None) -> None:
            if yes:
                result = self.submit(cmd.DeleteToolEdge(tool, edge if edge_only else None))
                if isinstance(result, Accepted):
                    self.hmi.set_hint(_("Deleted {what}").format(what=what))
                self.refresh_table()

        self.app.push_screen(ConfirmDialog(_("Delete {what}?").format(what=what)), delete)

    def action_search_tool(self) -> None:
        """Search: put the cursor on the first edge of a T number."""
        def find(text: str | None) -> None:
            if text:
                try:
                    tool = int(text.strip().lstrip("Tt"))
                except ValueError:
                    self.hmi.set_hint(_("Search: give a T number"))
                    return
                if not self._select_tool(tool, None):
                    self.hmi.set_hint(_("T{tool} not found").format(tool=tool))

        self.app.push_screen(ValueDialog(_("Search tool: T number")), find)

    def _select_tool(self, tool: int, edge: int | None) -> bool:
        keys = sorted(self.data_view.data.tools)
        for index, (t, d) in enumerate(keys):
            if t == tool and (edge is None or d == edge):
                self.cursors[self.view].row = index
                self.refresh_table()
                return True
        return False

    # R parameters
    def action_clear_r(self) -> None:
        """Clear all R parameters, after asking."""
        def clear(yes: bool | None) -> None:
            if yes:
                if isinstance(self.submit(cmd.ClearRParameters()), Accepted):
                    self.hmi.set_hint(_("All R parameters are 0"))
                self.refresh_table()

        question = _("Set all {count} R parameters to 0?").format(count=len(self.data_view.data.r))
        self.app.push_screen(ConfirmDialog(question), clear)

    # -- display -----------------------------------------------------------------------------------
    def update_status(self, status: NckStatus) -> None:
        """A new snapshot: redraw the view (programs change R parameters and tools too)."""
        self.refresh_table()

    def read_refused(self) -> DataTable | None:
        """A table saying which level reading the view's data needs, when the current one does not suffice."""
        read = {"tools": "READ_TOOL", "wear": "READ_TOOL", "gud": "READ_USER_DATA"}.get(self.view)
        if read is None:
            return None
        needed = self.action_level(read)
        if self.access_level <= needed:
            return None
        title = (_("Reading tool offsets needs access level {needed} (current level {current})") if read == "READ_TOOL"
                 else _("Reading user variables needs access level {needed} (current level {current})"))
        return DataTable(title.format(needed=needed, current=self.access_level),
                         [Column("", 1)], [], "Set a password or turn the keyswitch (Setup area)")

    def build_table(self) -> DataTable:
        """The table of the view on display."""
        data = self.data_view
        if data.data is None or data.machine_data is None:
            return DataTable("This kernel offers no NC data", [Column("", 1)], [])
        refused = self.read_refused()
        if refused is not None:
            return refused
        status, levels = self.status, self.level_of
        builders: dict[str, Callable[[], DataTable]] = {
            "tools": lambda: tool_table(data, status, levels),
            "wear": lambda: tool_table(data, status, levels, wear=True),
            "wo_active": lambda: active_chain_table(data, status),
            "wo_overview": lambda: overview_table(data, status, levels),
            "wo_details": lambda: details_table(data, self.detail_frame, levels),
            "r": lambda: r_table(data, levels),
            "gud": lambda: gud_table(data, levels),
            "sd": lambda: setting_table(data, levels),
        }
        return builders[self.view]()

    def refresh_table(self) -> None:
        """Rebuild and draw the table of the view on display."""
        if not self.is_mounted:
            return
        self.table = self.build_table()
        self.query_one("#param-table", TableWindow).show(
            self.table, self.cursors[self.view], self.access_level, show_cursor=self.view != "wo_active")


AreaScreen = ParameterScreen
