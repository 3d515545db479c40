"""The Program manager area: the NC directories, and what an operator does with programs.

Left: the directory tree (``NC`` → Part programs, Subprograms, Workpieces and
their folders). Right: ``Name | Type | Length | Date`` of the chosen directory;
the program selected for execution is marked ``▶``.

Horizontal softkeys: Execute (select for AUTO), New, Open, Copy, Paste, Rename,
Delete (with confirmation), Search. Vertical: Import, Export, the three NC
directories, Refresh. The rules of the NC file system apply: valid names only,
no overwriting, and the program being executed can be neither renamed nor
deleted.

Keys in the windows: ↑/↓ move, Enter opens (a program in the editor, a folder in
the list), ← / → move between the tree and the list.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import ClassVar

from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.widgets import DataTable, Input, Static, Tree

from nck import Action, ExportTargetExists, ProgramEntry, required_level
from nck import commands as cmd
from nck.commands import Rejected
from nck.status import NckStatus

from hmi.area import AreaBase
from hmi.dialog import AreaDialog
from hmi.dialogs import ChoiceDialog, ConfirmDialog
from hmi.focus import focus_now
from hmi.i18n import N_, _, counted, error_text, refusal_text
from hmi.journal import EditorJournal
from hmi.program_files import DIRECTORIES, ProgramFileError, ProgramFiles, format_modified
from hmi.softkeys import Softkey, SoftkeyMenu
from hmi.widgets.fixed_size_input import FixedSizeInput

CANCEL = N_("Cancel")
DELETE = N_("Delete")
"""The choices of the delete dialog (shown translated, returned as written)."""


def _level(action: str, fallback: int) -> int:
    """The access level an action needs (``data/access.toml``), or ``fallback``."""
    try:
        return required_level(Action(action))
    except (KeyError, ValueError):
        return fallback


def selection_level() -> int:
    """Level that may select a program for execution (keyswitch 1 = level 6 by default)."""
    return _level("select_program", 6)


def edit_level() -> int:
    """Level that may create, change or delete programs."""
    return _level("edit_program", 4)


class PromptDialog(AreaDialog[str | None]):
    """Ask for one line of text (a name, a path, a search text); Enter confirms, F10/Esc cancels."""

    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]
    DEFAULT_CSS = """
    PromptDialog { align: center middle; }
    PromptDialog #prompt-box { width: 80; height: auto; background: $panel; border: tall $primary; padding: 1 2; }
    PromptDialog #prompt-title { text-style: bold; margin-bottom: 1; }
    PromptDialog #prompt-keys { color: $secondary; margin-top: 1; }
    """

    def __init__(self, title: str, value: str = "", hint: str = "") -> None:
        super().__init__(classes="prompt-dialog")
        self._title = title
        self._value = value
        self._hint = hint

    def compose(self) -> ComposeResult:
        """Title, input field, key hint."""
        with Vertical(id="prompt-box"):
            yield Static(self._title, id="prompt-title", markup=False)
            yield FixedSizeInput(self._value, id="prompt-input")
            yield Static(self._hint or _("Enter confirm   F10 cancel"), id="prompt-keys", markup=False)

    def on_mount(self) -> None:
        """Focus the field."""
        focus_now(self.query_one(Input))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter: return the text."""
        self.dismiss(event.value)

    def action_cancel(self) -> None:
        """Close without a value."""
        self.dismiss(None)


def _executing_program(status: NckStatus | None) -> str | None:
    """The selected program while the channel is executing it (not in reset), else None."""
    if status is None:
        return None
    channel = status.channel
    if channel.selected_program and (channel.channel_state != "reset" or channel.program_state != "aborted"):
        return channel.selected_program
    return None


class ProgramList(DataTable):
    """The file list: Name, Type, Length, Date; Home/End go to the first/last entry, PgUp/PgDn by a page."""

    BINDINGS = [
        Binding("left", "app.focus_previous", "Tree", show=False),
        Binding("home", "first_entry", "First entry", show=False),
        Binding("end", "last_entry", "Last entry", show=False),
        Binding("pageup", "page_entries(-1)", "Page up", show=False),
        Binding("pagedown", "page_entries(1)", "Page down", show=False),
    ]

    def action_first_entry(self) -> None:
        """Home: the first entry."""
        self.move_cursor(row=0)

    def action_last_entry(self) -> None:
        """End: the last entry."""
        self.move_cursor(row=max(self.row_count - 1, 0))

    def action_page_entries(self, pages: int) -> None:
        """PgUp/PgDn: as many entries up or down as the list shows at once."""
        shown = max(self.scrollable_content_region.height - self.header_height, 1)
        row = self.cursor_row + int(pages) * shown
        self.move_cursor(row=min(max(row, 0), max(self.row_count - 1, 0)))


class ProgramManagerScreen(AreaBase):
    """The Program manager (area PROGRAM MANAGER)."""

    AREA_ID: ClassVar[str] = "program_manager"
    AREA_TITLE: ClassVar[str] = "PROGRAM MANAGER"
    CSS_PATH = "program_manager.tcss"

    def __init__(self) -> None:
        super().__init__(id="area-program-manager")
        self.directory = "MPF"
        self.entries: list[ProgramEntry] = []
        self._clipboard: str | None = None
        self._search_text = ""

    # -- layout ------------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """Directory tree and file list."""
        with Horizontal(id="pm-body"):
            tree: Tree[str] = Tree("NC", id="pm-tree", data="/")
            tree.show_root = True
            tree.guide_depth = 2
            yield tree
            with Vertical(id="pm-right"):
                yield Static("", id="pm-path", markup=False)
                yield ProgramList(id="pm-list", cursor_type="row", zebra_stripes=False)
                yield Static("", id="pm-info", markup=False)

    @property
    def files(self) -> ProgramFiles:
        """The NC file system as the screens use it."""
        return ProgramFiles.of_app(self.app)

    @property
    def table(self) -> ProgramList:
        """The file list."""
        return self.query_one("#pm-list", ProgramList)

    def on_mount(self) -> None:
        """Columns, tree, first listing."""
        super().on_mount()
        table = self.table
        table.add_column(" ", key="mark", width=1)
        table.add_column(_("Name"), key="name", width=28)
        # Type and Length as narrow as their values (MPF, at most 8 digits: 50 MB): beside the
        # exercise side window the list keeps every column at 120 columns (program_manager.tcss)
        table.add_column(_("Type"), key="type", width=5)
        table.add_column(_("Length"), key="size", width=8)
        table.add_column(_("Date"), key="date", width=16)
        self.rebuild_tree()
        self.show_directory("MPF")
        focus_now(table)
        self._hint_unsaved_journal()

    def _hint_unsaved_journal(self) -> None:
        """After a crash, point at the unsaved editor text the journal still holds."""
        try:
            entries = EditorJournal(self.files.journal_dir).entries()
        except OSError:
            return
        if entries:
            names = ", ".join(e.program for e in entries[:3])
            self.say(_("Unsaved text from an earlier session ({names}): PROGRAM (Alt+P) offers to restore it").format(
                names=names))

    def on_screen_resume(self) -> None:
        """Back in the area: list again (files may have changed in the editor)."""
        super().on_screen_resume()
        if self._ready:
            self.refresh_listing()

    @property
    def _ready(self) -> bool:
        """True once the windows exist (``is_mounted`` is still False inside ``on_mount``)."""
        return bool(self.query("#pm-list"))

    # -- softkeys ------------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Execute, New, Open, Copy, Paste, Rename, Delete, Search / Import, Export, directories."""
        on_program = lambda s: s.current_entry() is not None and s.current_entry().kind != "WPD"  # noqa: E731
        on_entry = lambda s: s.current_entry() is not None  # noqa: E731
        return SoftkeyMenu.of(
            [
                Softkey("pm.execute", "Execute", "execute", level=selection_level(),
                        enabled=lambda s: s.current_entry() is not None and s.current_entry().kind == "MPF"),
                Softkey("pm.new", "New", "new", level=edit_level()),
                Softkey("pm.open", "Open", "open", enabled=on_entry),
                Softkey("pm.copy", "Copy", "copy", enabled=on_program),
                Softkey("pm.paste", "Paste", "paste", level=edit_level(), enabled=lambda s: s._clipboard is not None),
                Softkey("pm.rename", "Rename", "rename", level=edit_level(), enabled=on_program),
                Softkey("pm.delete", "Delete", "delete", level=edit_level(), enabled=on_entry),
                Softkey("pm.search", "Search", "search"),
            ],
            [
                Softkey("pm.import", "Import", "import_file", level=edit_level()),
                Softkey("pm.export", "Export", "export_file", enabled=on_program),
                None,
                Softkey("pm.dir_mpf", "Part\nprograms", "show_directory('MPF')",
                        active=lambda s: s.directory == "MPF"),
                Softkey("pm.dir_spf", "Sub-\nprograms", "show_directory('SPF')",
                        active=lambda s: s.directory == "SPF"),
                Softkey("pm.dir_wks", "Work-\npieces", "show_directory('WKS')",
                        active=lambda s: s.directory.startswith("WKS")),
                None,
                Softkey("pm.refresh", "Refresh", "refresh_listing"),
            ],
        )

    # -- tree and list ---------------------------------------------------------------------------
    def rebuild_tree(self) -> None:
        """NC → the three directories, workpiece folders below Workpieces."""
        tree = self.query_one("#pm-tree", Tree)
        tree.clear()
        root = tree.root
        root.expand()
        for directory, title in DIRECTORIES:
            if directory != "WKS":
                root.add_leaf(_(title), data=directory)
                continue
            node = root.add(_(title), data=directory, expand=True)
            for folder in self._workpieces():
                node.add_leaf(folder.name, data=folder.path)

    def _workpieces(self) -> list[ProgramEntry]:
        try:
            return [e for e in self.files.fs.list_directory("WKS") if e.kind == "WPD"]
        except (OSError, ProgramFileError):
            return []

    def on_tree_node_selected(self, event: Tree.NodeSelected) -> None:
        """Enter on a directory: list it and move to the list."""
        path = event.node.data
        if path and path != "/" and path != "NC":
            self.show_directory(path)
            focus_now(self.table)

    def show_directory(self, directory: str) -> None:
        """List ``directory`` in the right window."""
        self.directory = directory
        self.refresh_listing()

    def action_show_directory(self, directory: str) -> None:
        """Directory softkeys."""
        self.show_directory(directory)
        focus_now(self.table)

    def action_refresh_listing(self) -> None:
        """Refresh softkey."""
        self.rebuild_tree()
        self.refresh_listing()

    def refresh_listing(self, select: str | None = None) -> None:
        """Read the directory again and redraw the list (cursor on ``select`` if given)."""
        if not self._ready:
            return
        table = self.table
        previous = select or (self.current_entry().path if self.current_entry() else None)
        try:
            self.entries, odd = self.files.fs.scan_directory(self.directory)
        except (OSError, ProgramFileError) as exc:
            self.entries, odd = [], []
            self.say(error_text(exc, failed="os_read_failed"))
        if odd:
            self.say(_("{directory}: skipped {names} (not a regular file or folder)").format(
                directory=self.directory, names=", ".join(odd)))
        selected = (self.status.channel.selected_program if self.status else None) or ""
        selected_name = Path(selected).name.upper()
        table.clear()
        for entry in self.entries:
            marked = entry.kind != "WPD" and entry.name.upper() == selected_name
            mark = Text("▶" if marked else " ", style="bold #f39200")
            name = Text(entry.name + ("/" if entry.kind == "WPD" else ""))
            if marked:
                name.stylize("bold #f39200")
            size = Text(f"{entry.size_bytes}", justify="right")
            table.add_row(mark, name, entry.kind, size, format_modified(entry.modified_ns), key=entry.path)
        if previous:
            for index, entry in enumerate(self.entries):
                if entry.path == previous:
                    table.move_cursor(row=index)
                    break
        title = _(dict(DIRECTORIES).get(self.directory, N_("Workpiece")))
        count = counted(len(self.entries), N_("({count} entry)"), N_("({count} entries)"))
        self.query_one("#pm-path", Static).update(f" {title}   {self.directory}   {count}")
        self._update_info()
        self.refresh_softkeys()

    def _update_info(self) -> None:
        selected = self.status.channel.selected_program if self.status else None
        text = (" " + _("Selected for execution: {program}").format(program=selected) if selected
                else " " + _("No program selected"))
        executing = _executing_program(self.status)
        if executing:
            text += "  " + _("(being executed)")
        self.query_one("#pm-info", Static).update(text)

    def current_entry(self) -> ProgramEntry | None:
        """The entry under the list cursor."""
        if not self._ready or not self.entries:
            return None
        row = self.table.cursor_row
        return self.entries[row] if 0 <= row < len(self.entries) else None

    def on_data_table_row_selected(self, event: DataTable.RowSelected) -> None:
        """Enter on a row: open it."""
        self.action_open()

    def on_data_table_row_highlighted(self, event: DataTable.RowHighlighted) -> None:
        """Cursor moved: softkeys depend on the entry."""
        self.refresh_softkeys()

    def update_status(self, status: NckStatus) -> None:
        """A new snapshot: the selection mark may have moved."""
        if not self._ready:
            return
        selected = status.channel.selected_program
        if selected != getattr(self, "_shown_selection", None) or _executing_program(status) != getattr(
            self, "_shown_executing", None
        ):
            self._shown_selection = selected
            self._shown_executing = _executing_program(status)
            self.refresh_listing()

    # -- actions ---------------------------------------------------------------------------------
    def _in_use(self) -> set[str]:
        executing = _executing_program(self.status)
        return {executing} if executing else set()

    def action_open(self) -> None:
        """Open: a folder is listed, a program goes into the editor."""
        entry = self.current_entry()
        if entry is None:
            return
        if entry.kind == "WPD":
            self.show_directory(entry.path)
            return
        self.files.request_open(entry.path)
        self.perform("app.switch_area('program')")

    def action_execute(self) -> None:
        """Execute: select the program for AUTO and go to the Machine area."""
        entry = self.current_entry()
        if entry is None or entry.kind != "MPF":
            self.say(_("Only a part program (MPF) can be selected"))
            return
        if self.status is not None and self.status.channel.mode != "AUTO":
            result = self.submit(cmd.SelectMode("AUTO"))
            if isinstance(result, Rejected):
                self.say(_("Execute: {reason}").format(reason=refusal_text(result)))
                return
        result = self.submit(cmd.SelectProgram(entry.path))
        if isinstance(result, Rejected):
            self.say(_("Execute: {reason}").format(reason=refusal_text(result)))
            return
        self.refresh_listing()
        self.perform("app.switch_area('machine')")

    def action_new(self) -> None:
        """New: ask for a name and create an empty program (a folder in Workpieces)."""
        directory = self.directory
        question = (_("New workpiece in {directory}: name") if directory == "WKS"
                    else _("New subprogram in {directory}: name") if directory == "SPF"
                    else _("New program in {directory}: name"))

        def create(name: str | None) -> None:
            if not name:
                return
            try:
                path = self.files.create(directory, name)
            except (ProgramFileError, OSError) as exc:
                self.say(_("New: {exc}").format(exc=error_text(exc)))
                return
            self.rebuild_tree()
            self.refresh_listing(select=path)
            self.say(_("{path} created").format(path=path))
            if not path.endswith(".WPD"):
                self.files.request_open(path, at_end=True)
                self.perform("app.switch_area('program')")

        self.app.push_screen(PromptDialog(question.format(directory=directory), ""), create)

    def action_copy(self) -> None:
        """Copy: remember the program for Paste."""
        entry = self.current_entry()
        if entry is not None and entry.kind != "WPD":
            self._clipboard = entry.path
            self.say(_("{path} copied — Paste puts a copy into the directory shown").format(path=entry.path))
            self.refresh_softkeys()

    def action_paste(self) -> None:
        """Paste: a copy of the copied program into the directory shown."""
        if self._clipboard is None:
            return
        try:
            path = self.files.paste_copy(self._clipboard, self.directory)
        except (ProgramFileError, OSError) as exc:
            self.say(_("Paste: {exc}").format(exc=error_text(exc)))
            return
        self.refresh_listing(select=path)
        self.say(_("{path} created as a copy of {clipboard}").format(path=path, clipboard=self._clipboard))

    def action_rename(self) -> None:
        """Rename: ask for the new name (refused for the program being executed)."""
        entry = self.current_entry()
        if entry is None or entry.kind == "WPD":
            return
        if entry.path in self._in_use() or entry.name.upper() in {Path(p).name.upper() for p in self._in_use()}:
            self.say(_("{path} is being executed and cannot be renamed").format(path=entry.path))
            return

        def rename(name: str | None) -> None:
            if not name:
                return
            try:
                path = self.files.fs.rename(entry.path, name).path
            except (ProgramFileError, OSError) as exc:
                self.say(_("Rename: {exc}").format(exc=error_text(exc)))
                return
            self.refresh_listing(select=path)
            self.say(_("{path} renamed to {new}").format(path=entry.path, new=path))

        self.app.push_screen(PromptDialog(_("Rename {path} to:").format(path=entry.path), entry.name), rename)

    def action_delete(self) -> None:
        """Delete: ask, then delete (refused for the program being executed)."""
        entry = self.current_entry()
        if entry is None:
            return
        if entry.name.upper() in {Path(p).name.upper() for p in self._in_use()}:
            self.say(_("{path} is being executed and cannot be deleted").format(path=entry.path))
            return

        def confirmed(choice: str | None) -> None:
            if choice != DELETE:
                return
            try:
                self.files.fs.delete(entry.path)
            except (ProgramFileError, OSError) as exc:
                self.say(_("Delete: {exc}").format(exc=error_text(exc)))
                return
            if entry.kind == "WPD":
                self.rebuild_tree()
            self.refresh_listing()
            self.say(_("{path} deleted").format(path=entry.path))

        question = (_("Delete the workpiece folder and everything in it {path}?") if entry.kind == "WPD"
                    else _("Delete the program {path}?"))
        self.app.push_screen(ChoiceDialog(question.format(path=entry.path), [CANCEL, DELETE]), confirmed)

    def action_search(self) -> None:
        """Search: find a program by (part of) its name in all NC directories."""

        def search(text: str | None) -> None:
            if not text:
                return
            self._search_text = text
            self.find_next(text)

        self.app.push_screen(PromptDialog(_("Search program name:"), self._search_text), search)

    def find_next(self, text: str) -> bool:
        """Move the cursor to the next program whose name contains ``text`` (all directories)."""
        needle = text.upper()
        folders = ["MPF", "SPF"] + [e.path for e in self._workpieces()]
        start = folders.index(self.directory) if self.directory in folders else 0
        current_row = self.table.cursor_row if self.entries else -1
        for step in range(len(folders) + 1):
            folder = folders[(start + step) % len(folders)]
            entries = self.files.fs.list_directory(folder)
            for index, entry in enumerate(entries):
                if step == 0 and index <= current_row:
                    continue
                if needle in entry.name.upper() and entry.kind != "WPD":
                    self.directory = folder
                    self.refresh_listing(select=entry.path)
                    focus_now(self.table)
                    self.say(_("Found {path}").format(path=entry.path))
                    return True
        self.say(_("No program name contains '{text}'").format(text=text))
        return False

    def action_import_file(self) -> None:
        """Import: copy a file of the PC into the directory shown."""
        directory = self.directory if self.directory != "WKS" else "MPF"

        def do_import(path: str | None) -> None:
            if not path:
                return
            try:
                target = self.files.fs.import_file(Path(path).expanduser(), directory).path
            except (ProgramFileError, OSError) as exc:
                self.say(_("Import: {exc}").format(exc=error_text(exc, failed="os_read_failed")))
                return
            self.directory = directory
            self.refresh_listing(select=target)
            self.say(_("{path} imported as {target}").format(path=path, target=target))

        self.app.push_screen(PromptDialog(_("Import into {directory}: path of the file on this PC").format(
            directory=directory), ""), do_import)

    def action_export_file(self) -> None:
        """Export: write a copy of the program to a path of the PC."""
        entry = self.current_entry()
        if entry is None or entry.kind == "WPD":
            return

        def do_export(path: str | None, replace: bool = False) -> None:
            if not path:
                return
            try:
                target = self.files.fs.export_file(entry.path, os.path.expanduser(path), replace)  # (keeps a final /)
            except ExportTargetExists as exc:
                question = _("{filename} already exists. Replace it?").format(filename=exc.filename)
                self.app.push_screen(ConfirmDialog(question),
                                     lambda yes: do_export(path, True) if yes else None)
                return
            except (ProgramFileError, OSError) as exc:
                self.say(_("Export: {exc}").format(exc=error_text(exc)))
                return
            self.say(_("{path} exported to {target}").format(path=entry.path, target=target))

        question = _("Export {path} to (file or folder on this PC):").format(path=entry.path)
        self.app.push_screen(PromptDialog(question, str(Path.cwd())), do_export)


AreaScreen = ProgramManagerScreen
"""The area screen the app puts into its MODES (convention of ``hmi/app.py``)."""
