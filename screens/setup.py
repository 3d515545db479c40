"""The Setup area: machine data lists, NEW CONFIG and Reset (po), passwords, access level, control time.

Machine data lists (horizontal softkeys): general (1xxxx), channel (2xxxx),
axis (3xxxx; ``Axis +`` / ``Axis −``), display (9xxx): number, identifier,
value, unit, activation (po / re / cf / so), the level a write needs, and ``*``
for a stored value that is not active yet. ``Search`` filters by number or
name. Enter edits the selected value through ``WriteData`` (the kernel checks
level, type and limits). ``Set MD active (cf)`` sends ``ActivateMachineData``;
``Reset (po)`` restarts the simulated NCK from the retained data so that
power-on data take effect. The ``Password`` view shows the access level and
offers set / change / delete password, and the date and time of the control.
``Machine set-up`` lists what is clamped (:mod:`screens.setup_workpiece`): the
instructor moves the blank by typing its position and hides it from the trainee.
"""

from __future__ import annotations

import math
from datetime import datetime, timedelta
from typing import Any, Callable, ClassVar

from rich.text import Text
from textual import events
from textual.app import ComposeResult
from textual.widgets import Input, Static

from nck import commands as cmd
from nck import queries
from nck.commands import Accepted
from nck.status import NckStatus

from hmi.area import AreaBase, show_text
from hmi.dialogs import ConfirmDialog, ValueDialog
from hmi.durations import clock
from hmi.focus import focus_now
from hmi.i18n import LANGUAGES, N_, _, data_text, error_text, language
from hmi.softkeys import Softkey, SoftkeyMenu, one_line, view_softkey
from hmi.theme import HMI_THEMES, THEME_LABELS
from hmi.widgets.data_table import (
    EDIT_BINDINGS, Cell, Column, DataTable, TableCursor, TableWindow, edit_on_typed_key, level_refusal, widest_text,
)
from hmi.widgets.fixed_size_input import FixedSizeInput
from screens.setup_workpiece import workpiece_table

MD_VIEWS = {"general": N_("General machine data"), "channel": N_("Channel machine data"),
            "axis": N_("Axis machine data"), "display": N_("Display machine data")}
TABLE_VIEWS = (*MD_VIEWS, "workpiece")
ACTIVATION_TEXT = {"so": N_("immediately"), "re": N_("at RESET"), "cf": N_("at NEW CONFIG (Set MD active) or RESET"),
                   "po": N_("at POWER ON (Reset (po))")}
LEVEL_NAMES = {0: N_("System"), 1: N_("Manufacturer"), 2: N_("Service"), 3: N_("User")}

wall_clock: Callable[[], datetime] = datetime.now
"""The computer's clock: the control's date at power on (tests replace it)."""


def level_text(level: int) -> str:
    """``"3 — User (password)"``, ``"7 — keyswitch position 0"``."""
    if level in LEVEL_NAMES:
        how = _("password") if level else _("system")
        return f"{level} — {_(LEVEL_NAMES[level])} ({how})"
    return f"{level} — " + _("keyswitch position {position}").format(position=7 - level)


def language_text(active: str) -> Text:
    """The language selection window: every language, the one shown now marked."""
    text = Text(no_wrap=True, end="")
    text.append(" " + _("Language selection") + "\n\n", style="bold underline")
    for code, name in LANGUAGES.items():
        mark = "●" if code == active else "○"
        text.append(f"   {mark} {name}\n", style="bold" if code == active else "")
    text.append("\n   " + _("Choose with the vertical softkeys: every screen changes to the language "
                             "at once,") + "\n   " + _("and the choice is kept for the next start.") + "\n",
                style="dim")
    return text


def theme_text(active: str) -> Text:
    """The colour theme selection window: every theme, the one shown now marked."""
    text = Text(no_wrap=True, end="")
    text.append(" " + _("Colour theme") + "\n\n", style="bold underline")
    for theme in HMI_THEMES:
        mark = "●" if theme.name == active else "○"
        label = one_line(_(THEME_LABELS[theme.name]))
        text.append(f"   {mark} {label}  ({theme.name})\n", style="bold" if theme.name == active else "")
    text.append("\n   " + _("Choose with the vertical softkeys; the choice is kept for the next start.") + "\n",
                style="dim")
    return text


def md_table(store: Any, scope: str, axis: str | None, search: str, level: int) -> DataTable:
    """One machine-data list as an editable table."""
    rows = []
    for row in store.rows("md", scope, axis=axis, search=search or None, level=level):
        d = row.ref.definition
        title = data_text("md", d.number, "title", d.title)
        if d.array:
            hint = _("{identifier}: {title}. Array of {count}: give index and value, e.g. 0 5 "
                     "(takes effect {when})").format(
                identifier=d.identifier, title=title, count=d.array, when=_(ACTIVATION_TEXT[d.activation]))
            edit = "0 "
        else:
            edit = row.value_text if d.type != "bool" else ("1" if store.value(row.ref) else "0")
            limits = f", {d.min:g} … {d.max:g}" if d.min is not None and d.max is not None else ""
            hint = _("{identifier}: {title} ({unit}{limits}); takes effect {when}").format(
                identifier=d.identifier, title=title, unit=_(row.unit) or d.type, limits=limits,
                when=_(ACTIVATION_TEXT[d.activation]))
        rows.append([Cell(str(d.number)), Cell(d.name),
                     Cell(row.value_text, row.ref.text, edit, row.write_level, hint),
                     Cell(_(row.unit)), Cell(row.activation), Cell(str(row.write_level)),
                     Cell("*" if row.pending else "")])
    columns = [Column("Number", 7, "<"), Column("Name", 30, "<"), Column("Value", 30),
               Column("Unit", widest_text(rows, 3, 8), "<"), Column("Act", 3, "<"), Column("Lvl", 3), Column("", 1, "<")]
    title = _(MD_VIEWS[scope]) + (" — " + _("axis {axis}").format(axis=axis) if axis else "")
    if search:
        title += "  " + _("(search: {text})").format(text=search)
    return DataTable(title, columns, rows,
                     "Enter edit   * stored, not active yet   Act: po power on, re reset, cf new config, so at once")


class SetupScreen(AreaBase):
    """The Setup operating area."""

    AREA_ID: ClassVar[str] = "setup"
    AREA_TITLE: ClassVar[str] = "SETUP"
    CSS_PATH = "setup.tcss"
    BINDINGS = EDIT_BINDINGS
    AUTO_FOCUS = ""  # the arrow keys move in the list until Search puts the cursor in the field

    def __init__(self) -> None:
        super().__init__(id="area-setup")
        self.view = "general"
        self.axis_index = 0
        self.search = ""
        self.cursors = {view: TableCursor() for view in TABLE_VIEWS}
        self.table: DataTable | None = None
        self.power_on_at: datetime | None = None  # wall clock at the NCK's power on, set when first shown
        self._drawn_key: tuple = ()

    @property
    def data_view(self) -> queries.DataView:
        """The machine and its machine data, read through the bridge (writes are commands)."""
        return self.ask(queries.ReadData())

    @property
    def axis(self) -> str:
        """The axis whose axis machine data are listed."""
        names = [a.name for a in self.data_view.machine.axes]
        return names[self.axis_index % len(names)]

    # -- layout -------------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """Search field and MD table, or the access window."""
        yield FixedSizeInput(placeholder=_("search by number or name, Enter applies (empty: all)"), id="md-search")
        yield TableWindow(id="setup-table")
        yield Static("", id="setup-access", markup=False)

    def on_mount(self) -> None:
        """No blinking cursor; show the first list."""
        self.query_one("#md-search", Input).cursor_blink = False
        super().on_mount()
        self.action_show_view(self.view)

    # -- softkeys ---------------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Lists and the password view on the horizontal keys, their own keys on the vertical ones."""
        horizontal = [
            view_softkey("setup.general", "General\nMD", "general"),
            view_softkey("setup.channel", "Channel\nMD", "channel"),
            view_softkey("setup.axis", "Axis\nMD", "axis"),
            view_softkey("setup.display", "Display\nMD", "display"),
            view_softkey("setup.workpiece", "Machine\nset-up", "workpiece"),
            view_softkey("setup.password", "Password", "password", submenu="password_menu"),
            Softkey("setup.new_config", "Set MD\nactive (cf)", "new_config",
                    enabled=lambda s: s.status is not None and s.status.channel.channel_state == "reset"),
            Softkey("setup.power_on", "Reset\n(po)", "power_on"),
        ]
        return SoftkeyMenu.of(horizontal, self._vertical_keys())

    def password_menu(self) -> SoftkeyMenu:
        """The vertical keys of the password view (the command palette lists them under Password)."""
        return SoftkeyMenu.of((), self._vertical_keys("password"))

    def language_menu(self) -> SoftkeyMenu:
        """The language softkeys (the palette lists them under Change language)."""
        return SoftkeyMenu.of((), self._vertical_keys("language"))

    def theme_menu(self) -> SoftkeyMenu:
        """The colour theme softkeys (the palette lists them under Change theme)."""
        return SoftkeyMenu.of((), self._vertical_keys("theme"))

    def _vertical_keys(self, view: str | None = None) -> list[Softkey | None]:
        """The vertical keys of ``view`` (None: the view shown now)."""
        view = view or self.view
        if view == "password":
            return [
                Softkey("setup.pw.set", "Set\npassword", "set_password"),
                Softkey("setup.pw.change", "Change\npassword", "change_password", level=3),
                Softkey("setup.pw.delete", "Delete\npassword", "delete_password"),
                None,
                Softkey("setup.language", "Change\nlanguage", "show_view('language')", submenu="language_menu"),
                Softkey("setup.theme", "Change\ntheme", "show_view('theme')", submenu="theme_menu"),
            ]
        if view == "theme":
            return [Softkey(f"setup.theme.{theme.name}", THEME_LABELS[theme.name], f"select_theme('{theme.name}')",
                            active=lambda s, name=theme.name: s.app.theme == name)
                    for theme in HMI_THEMES]
        if view == "language":
            return [Softkey(f"setup.language.{code}", name, f"select_language('{code}')",
                            active=lambda s, code=code: language() == code)
                    for code, name in LANGUAGES.items()]
        if view == "workpiece":
            level = self.ask(queries.ActionLevel("WRITE_MACHINE_SETUP"))
            return [Softkey("setup.workpiece.hide", "Hide\nblank", "toggle_hidden", level=level,
                            active=lambda s: bool(s.machine_setup and s.machine_setup.hidden)),
                    None, None, None, None, None, None, Softkey("setup.edit", "Edit\n(Enter)", "edit")]
        keys: list[Softkey | None] = [
            Softkey("setup.search", "Search", "focus_search"),
            Softkey("setup.search.clear", "Show\nall", "clear_search", enabled=lambda s: bool(s.search)),
        ]
        if view == "axis":
            keys += [Softkey("setup.axis.next", "Axis +", "next_axis(1)"),
                     Softkey("setup.axis.prev", "Axis −", "next_axis(-1)")]
        else:
            keys += [None, None]
        return keys + [None, None, None, Softkey("setup.edit", "Edit\n(Enter)", "edit")]

    # -- actions -----------------------------------------------------------------------------------
    def action_show_view(self, view: str) -> None:
        """Show a machine-data list or the password window (a message about the view left goes with it)."""
        if view != self.view:
            self.say("")
        self.view = view
        if self.is_mounted:
            table_view = view in TABLE_VIEWS
            self.query_one("#md-search").display = view in MD_VIEWS
            self.query_one("#setup-table").display = table_view
            self.query_one("#setup-access").display = not table_view
        self.refresh_view()
        self.refresh_softkeys()

    def action_select_language(self, code: str) -> None:
        """A language softkey: the panel's texts in that language from now on (kept at restart)."""
        self.say(self.hmi.select_language(code))

    def action_select_theme(self, name: str) -> None:
        """A theme softkey: the panel in that colour theme from now on (kept at restart)."""
        self.app.theme = name
        self.refresh_view()
        self.refresh_softkeys()

    def action_next_axis(self, step: int) -> None:
        """Axis + / Axis −."""
        self.axis_index = (self.axis_index + int(step)) % max(len(self.data_view.machine.axes), 1)
        self.cursors["axis"] = TableCursor()
        self.refresh_view()

    def action_focus_search(self) -> None:
        """Put the cursor into the search field."""
        focus_now(self.query_one("#md-search", Input))

    def action_clear_search(self) -> None:
        """Show every datum of the list again."""
        self.query_one("#md-search", Input).value = ""
        self.apply_search("")

    def apply_search(self, text: str) -> None:
        """Filter the lists by number or part of the name."""
        self.search = text.strip()
        self.cursors.update({view: TableCursor() for view in MD_VIEWS})
        self.refresh_view()
        self.refresh_softkeys()

    def on_input_submitted(self, message: Input.Submitted) -> None:
        """Enter in the search field applies it and gives the focus back."""
        if message.input.id == "md-search":
            message.stop()
            self.apply_search(message.value)
            self.set_focus(None)

    def action_cursor(self, rows: int, columns: int) -> None:
        """Arrow keys: move the selected row."""
        if self.table is not None and self.view in TABLE_VIEWS:
            self.cursors[self.view].move(self.table, int(rows), int(columns))
            self.refresh_view()

    def on_key(self, event: events.Key) -> None:
        """A character typed on the selected cell starts its input (it replaces the value)."""
        if self.table is not None:
            edit_on_typed_key(event, self.action_edit)

    def action_edit(self, typed: str = "") -> None:
        """Enter / Edit: an input field for the selected machine datum.

        ``typed``: the character typed on the cell, which the field starts with instead of the value.
        """
        if self.table is None or self.view not in TABLE_VIEWS:
            return
        cursor = self.cursors[self.view]
        cell = self.table.cell(cursor.row, cursor.column)
        if cell is None or not cell.name:
            return
        if self.access_level > cell.level:
            self.hmi.set_hint(level_refusal(cell, self.access_level))
            return
        name = cell.name
        if self.view == "workpiece":
            title = _("Change {name}").format(name=cell.hint.split(":")[0])
            self.app.push_screen(ValueDialog(title, cell.edit_text, cell.hint, typed=typed),
                                 lambda text: self.write_setup_field(name, text))
            return
        definition = self.data_view.machine_data.resolve(name).definition

        def write(text: str | None) -> None:
            if text is None:
                return
            target, value = name, text.strip()
            if definition.array:
                parts = value.split(None, 1)
                if len(parts) != 2 or not (parts[0].isascii() and parts[0].isdigit()):
                    self.hmi.set_hint(_("{name} is an array: give index and value, e.g. 0 5").format(name=name))
                    return
                index, value = parts
                axis = f",{name.split('[')[1].rstrip(']')}" if "[" in name else ""
                target = f"{definition.key}[{index}{axis}]"
            result = self.submit(cmd.WriteData(target, value))
            if isinstance(result, Accepted):
                self.hmi.set_hint(_("{name} = {value}: takes effect {when}").format(
                    name=target, value=value, when=_(ACTIVATION_TEXT[definition.activation])))
            self.refresh_view()

        self.app.push_screen(ValueDialog(_("Change {name}").format(name=name), cell.edit_text, cell.hint, typed=typed),
                             write)

    @property
    def machine_setup(self) -> Any:
        """What is clamped (``nck.commands.MachineSetup``), or None for a kernel without NC data."""
        return self.ask(queries.MachineSetupData())

    def write_setup_field(self, name: str, text: str | None) -> None:
        """Write one field of the machine set-up (the kernel checks the level)."""
        setup = self.machine_setup
        if text is None or setup is None:
            return
        try:
            changed = queries.with_field(setup, name, text, self.data_view.machine.kind)
        except queries.SetupFieldError as error:
            self.hmi.set_hint(error_text(error))
            return
        if isinstance(self.submit(cmd.WriteMachineSetup(changed)), Accepted):
            self.hmi.set_hint(_("Machine set-up: {name} = {value}").format(name=name, value=text.strip()))
        self.refresh_view()
        self.refresh_softkeys()

    def action_toggle_hidden(self) -> None:
        """Hide blank: the trainee no longer sees where the blank is (pressed again: shown)."""
        setup = self.machine_setup
        if setup is not None:
            self.write_setup_field("hidden", "no" if setup.hidden else "yes")

    def action_new_config(self) -> None:
        """Set MD active (cf): stored machine data of activation cf and re take effect."""
        store = self.data_view.machine_data
        pending = list(store.pending()) if store is not None else []
        if isinstance(self.submit(cmd.ActivateMachineData()), Accepted):
            self.hmi.set_hint(_("Machine data active: {names}").format(names=", ".join(pending)) if pending
                              else _("Machine data active"))
        self.refresh_view()

    def action_power_on(self) -> None:
        """Reset (po): restart the simulated NCK after asking."""
        def restart(yes: bool | None) -> None:
            if not yes:
                return
            if self.hmi.power_on_reset():
                self.power_on_at = wall_clock()
                self.hmi.set_hint(_("NCK restarted (power on): every stored machine datum is active"))
            else:
                self.hmi.set_hint(_("Reset (po) needs the NC data directory (the kernel runs without one)"))
            self.refresh_view()

        self.app.push_screen(ConfirmDialog(
            _("Restart the NCK (power off/on)? Programs are aborted; axes must be referenced again.")), restart)

    def action_set_password(self) -> None:
        """Set password: a level 1–3 password raises the access level."""
        def enter(text: str | None) -> None:
            if text:
                if isinstance(self.submit(cmd.EnterPassword(text)), Accepted):
                    self.hmi.set_hint(_("Access level {level}").format(
                        level=level_text(self.hmi.bridge.status.access_level)))
                self.refresh_view()

        self.app.push_screen(ValueDialog(_("Set password"), "", _("at most 8 characters"), password=True), enter)

    def action_change_password(self) -> None:
        """Change password: level, new password, the same again."""
        def ask_new(level_text_: str | None) -> None:
            if not level_text_:
                return
            if level_text_.strip() not in ("1", "2", "3"):
                self.hmi.set_hint(_("Change password: levels 1, 2 and 3 have passwords"))
                return
            level = int(level_text_)

            def ask_again(first: str | None) -> None:
                if not first:
                    return

                def confirm(second: str | None) -> None:
                    if second is None:
                        return
                    if second != first:
                        self.hmi.set_hint(_("The two entries differ: password not changed"))
                        return
                    if isinstance(self.submit(cmd.ChangePassword(level, first)), Accepted):
                        self.hmi.set_hint(_("New password for level {level} stored").format(level=level))
                    self.refresh_view()

                self.app.push_screen(ValueDialog(_("Repeat the new password"), "", password=True), confirm)

            self.app.push_screen(ValueDialog(_("New password for level {level}").format(level=level), "",
                                             _("at most 8 characters"), password=True), ask_again)

        current = self.access_level if self.access_level in (1, 2, 3) else 3
        self.app.push_screen(ValueDialog(_("Change password of level (1–3)"), str(current)), ask_new)

    def action_delete_password(self) -> None:
        """Delete password: back to the keyswitch level."""
        if isinstance(self.submit(cmd.DeletePassword()), Accepted):
            self.hmi.set_hint(_("Password deleted: access level {level}").format(
                level=level_text(self.hmi.bridge.status.access_level)))
        self.refresh_view()

    # -- display -------------------------------------------------------------------------------------
    def update_status(self, status: NckStatus) -> None:
        """A new snapshot: the access window follows the level and the time; a list is
        drawn again only when the level changed (its values change through this screen's
        commands, which redraw it themselves)."""
        key = (status.access_level, status.channel.channel_state, status.alarm_log_seq)
        if self.view == "password" or key != self._drawn_key:
            self._drawn_key = key
            self.refresh_view()

    def on_screen_resume(self) -> None:
        """Back in the area: the lists may have changed meanwhile (RESET activates MD)."""
        super().on_screen_resume()
        self.refresh_view()

    def refresh_view(self) -> None:
        """Draw the list or the access window."""
        if not self.is_mounted:
            return
        store = self.data_view.machine_data
        if store is None:
            self.table = DataTable("This kernel offers no machine data", [Column("", 1)], [])
            self.query_one("#setup-table", TableWindow).show(self.table, TableCursor(), self.access_level)
            return
        if self.view == "workpiece":
            setup = self.machine_setup
            self.table = (workpiece_table(setup, self.access_level, self.ask(queries.ActionLevel("WRITE_MACHINE_SETUP")))
                          if setup is not None else DataTable("This kernel has no machine set-up", [Column("", 1)], []))
            self.query_one("#setup-table", TableWindow).show(self.table, self.cursors[self.view], self.access_level)
        elif self.view in MD_VIEWS:
            axis = self.axis if self.view == "axis" else None
            self.table = md_table(store, self.view, axis, self.search, self.access_level)
            self.query_one("#setup-table", TableWindow).show(self.table, self.cursors[self.view],
                                                             self.access_level)
        elif self.view == "language":
            show_text(self.query_one("#setup-access", Static), language_text(language()))
        elif self.view == "theme":
            show_text(self.query_one("#setup-access", Static), theme_text(self.app.theme))
        else:
            show_text(self.query_one("#setup-access", Static), self.access_text())

    def access_text(self) -> Text:
        """Access level, keyswitch, password state, pending MD, and the control's date and time."""
        status = self.status
        level = status.access_level if status is not None else 7
        state = self.ask(queries.AccessStatus())
        keyswitch = status.keyswitch_position if status is not None else None
        if keyswitch is None and state is not None:
            keyswitch = state.keyswitch_position
        password = getattr(state, "password_level", None)
        text = Text(no_wrap=True, end="")
        text.append(" " + _("Access level") + "\n", style="bold underline")
        text.append(f"   {_('Current access level'):<23}{level_text(level)}\n", style="bold")
        if keyswitch is not None:
            text.append(f"   {_('Keyswitch position'):<23}{keyswitch}  "
                        + _("(level {level})").format(level=7 - keyswitch) + "\n")
        state_text = (_("set (level {level}, {name})").format(level=password, name=_(LEVEL_NAMES[password]))
                      if password else _("none"))
        text.append(f"   {_('Password'):<23}{state_text}\n")
        text.append("   " + _("A password overrides the keyswitch until it is deleted, also over power off/on.")
                    + "\n", style="dim")
        text.append("\n " + _("Protection levels") + "\n", style="bold underline")
        for number in range(8):
            how = (_("system") if number == 0 else _("password") if number <= 3
                   else _("keyswitch position {position}").format(position=7 - number))
            name = _(LEVEL_NAMES[number]) if number in LEVEL_NAMES else ""
            text.append(f"   {number}  {name:<14}{how}\n", style="bold" if number == level else "")
        text.append("\n " + _("Machine data") + "\n", style="bold underline")
        store = self.data_view.machine_data
        pending = store.pending() if store is not None else []
        text.append(f"   {_('Stored, not active'):<23}" + (", ".join(pending) if pending else _("none")) + "\n")
        text.append("\n " + _("Date and time of the control") + "\n", style="bold underline")
        seconds = status.time_s if status is not None else 0.0
        if self.power_on_at is None:  # the area may be built long after power on
            self.power_on_at = wall_clock() - timedelta(seconds=seconds)
        moment = self.power_on_at + timedelta(seconds=seconds)
        text.append(f"   {_('Date / time'):<23}{moment:%Y-%m-%d %H:%M:%S}\n")
        text.append(f"   {_('Since power on'):<23}{clock(math.floor(seconds))} "
                    + _("(simulated control time)") + "\n")
        return text


AreaScreen = SetupScreen
