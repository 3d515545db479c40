"""The Machine area: positions, T/F/S, and the JOG, MDA and AUTO views.

Top: the position window (MCS/WCS by softkey, distance to go, ○ on unreferenced
axes, spindle) and the T, F, S window; a line with the main G groups; below it
the view of the current mode (JOG info, MDA editor, AUTO block window) or a view
chosen by softkey (all G groups, auxiliary functions, program control, block
search, times/counter). MENU RECALL (F10) returns from a softkey view.
"""

from __future__ import annotations

from typing import ClassVar

from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.widgets import ContentSwitcher, Input, Static, TextArea

from nck import commands as cmd
from nck.commands import Accepted
from nck import fixed, trimmed
from nck.queries import RecordedCut
from nck.status import NckStatus

from hmi.area import AreaBase, show_text
from hmi.dialogs import ChoiceDialog, ValueDialog
from hmi.durations import clock
from hmi.focus import focus_now
from hmi.i18n import N_, _, stop_reason_text
from hmi.softkeys import Softkey, SoftkeyMenu, view_softkey
from hmi.simulation_softkeys import overlay_key, view_keys
from hmi.widgets.blocks import BasicBlockWindow, BlockWindow
from hmi.widgets.gfunctions import GFunctionsLine, GFunctionsTable
from hmi.widgets.header import increment_text
from hmi.widgets.positions import PositionWindow
from hmi.widgets.stock_view import StockPicture, StockView, material_events, picture_of

from hmi.widgets.tfs import TfsWindow
from hmi.widgets.fixed_size_input import FixedSizeInput
from screens.machine_jog_form import FieldEdited
from screens.machine_jog_setup import JOG_WINDOWS, JogWindows
from screens.machine_jog_touch import contact_line

MAIN_VIEWS = {"JOG": "view-jog", "MDA": "view-mda", "AUTO": "view-auto"}
PROGRAM_STATE_WORDS = {"aborted": N_("aborted"), "running": N_("running"), "stopped": N_("stopped"),
                       "interrupted": N_("interrupted"), "waiting": N_("waiting")}
"""The program state as the MDA window's title line names it (the header has the long form)."""
PROGRAM_SELECTION_LEVEL = 6
"""Program selection needs keyswitch position 1 (access level 6) or better."""
RECORDING_SHOWN_EVERY_S = 0.25
"""Simultaneous recording draws the growing cut at most this often (control time) while the
channel runs, and at once when it stops or the view is opened. Our choice: the manuals give no
refresh rate, and every drawing copies the blank and works out the path overlay of all chords
so far (5 ms at 30,000 chords, linear), which the 20 snapshots a second of a running program
would otherwise pay each."""
SEARCH_MODES = {
    "contour": N_("with calculation, contour"),
    "end_point": N_("with calculation, end point"),
    "without_calculation": N_("without calculation"),
    "serupro": N_("by program test (SERUPRO)"),
}
"""The block search types the search view offers (002 L18283-18309; :mod:`nck.block_search`)."""


def _check(flag: object) -> str:
    return "[x]" if flag else "[ ]"


class MachineScreen(AreaBase):
    """The Machine operating area."""

    AREA_ID: ClassVar[str] = "machine"
    AREA_TITLE: ClassVar[str] = "MACHINE"
    CSS_PATH = "machine.tcss"
    AUTO_FOCUS = None  # focus follows the view (_focus_for); Textual's auto focus only fought it

    def __init__(self) -> None:
        super().__init__(id="area-machine")
        # After power-up the HMI shows the actual values in the MCS (002 L31480, L31569);
        # MD9424 only chooses which workpiece system (WCS or SZS) the softkey switches to.
        self.show_mcs = True
        self.view: str | None = None
        self.search_type = "contour"
        """The block search type chosen on the search view (a key of SEARCH_MODES)."""
        self.show_basic_blocks = False
        """The basic block display (vertical softkey Basic blocks in AUTO and MDA) is on."""
        self._shown_mode: str | None = None
        self._recording_shown_at_s: float | None = None  # control time of the last recording drawn
        self._mda_loaded = False
        self.jog = JogWindows(self)
        """The setting-up windows of JOG (T,S,M, Set WO, Position, Settings)."""

    # -- layout --------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """Position and T/F/S windows, G functions line, and the switchable views."""
        with Horizontal(id="mach-top"):
            yield PositionWindow(id="positions", classes="window")
            yield TfsWindow(id="tfs", classes="window")
        yield GFunctionsLine(id="gline")
        with ContentSwitcher(id="mach-views", initial="view-jog"):
            with Vertical(id="view-jog", classes="view"):
                yield Static("", id="jog-info", markup=False)
            with Vertical(id="view-mda", classes="view"):
                yield Static(" MDA", id="mda-title", classes="view-title", markup=False)
                yield TextArea("", id="mda-editor", soft_wrap=False, show_line_numbers=False)
                yield from self._basic_block_window("mda")
            with Vertical(id="view-auto", classes="view"):
                yield Static("", id="auto-title", classes="view-title", markup=False)
                yield BlockWindow(height_lines=20, id="auto-blocks")
                yield from self._basic_block_window("auto")
            with Vertical(id="view-gfunc", classes="view"):
                yield Static(" " + _("G functions — all groups"), classes="view-title", markup=False)
                yield GFunctionsTable(id="gfunc-table")
            with Vertical(id="view-aux", classes="view"):
                yield Static(" " + _("Auxiliary functions"), classes="view-title", markup=False)
                yield Static("", id="aux-table", markup=False)
            with Vertical(id="view-progctl", classes="view"):
                yield Static(" " + _("Program control"), classes="view-title", markup=False)
                yield Static("", id="progctl-table", markup=False)
            with Vertical(id="view-search", classes="view"):
                yield Static("", id="search-title", classes="view-title", markup=False)
                yield Static(" " + _("Search target: a block number (N70) or text in the block; "
                                     "Enter or ⇧F1 starts the search, ⇧F2-⇧F5 choose the search mode."),
                             markup=False)
                yield FixedSizeInput(placeholder="N…", id="search-input")
                yield Static("", id="search-info", markup=False)
            with Vertical(id="view-simrec", classes="view"):
                yield StockView(id="simrec-stock")
            with Vertical(id="view-times", classes="view"):
                yield Static(" " + _("Times / Counter"), classes="view-title", markup=False)
                yield Static("", id="times-table", markup=False)
            yield from self.jog.compose()

    @staticmethod
    def _basic_block_window(mode: str) -> ComposeResult:
        """The basic block display under the mode's own window (shown by the softkey)."""
        yield Static(" " + _("Basic blocks — end positions absolute in the WCS"),
                     classes="view-title basic-blocks", markup=False)
        yield BasicBlockWindow(id=f"{mode}-basic", classes="basic-blocks")

    def on_mount(self) -> None:
        """Cursor blink off (calm display, stable snapshots), then the base class."""
        self.query_one("#mda-editor", TextArea).cursor_blink = False
        self.query_one("#search-input", Input).cursor_blink = False
        super().on_mount()

    # -- softkeys ----------------------------------------------------------------------------
    def _mode(self) -> str:
        return self.status.channel.mode if self.status is not None else "JOG"

    def _reset_state(self) -> bool:
        return self.status is not None and self.status.channel.channel_state == "reset"

    def softkey_menu(self) -> SoftkeyMenu:
        """Horizontal softkeys of the Machine area; vertical ones depend on the view."""
        horizontal = [
            Softkey("machine.mcs", "Act. val.\nMCS", "toggle_mcs", active=lambda s: s.show_mcs),
            view_softkey("machine.gfunc", "G\nfunctions", "gfunc"),
            view_softkey("machine.aux", "Auxiliary\nfunctions", "aux"),
            view_softkey("machine.progctl", "Program\ncontrol", "progctl",
                         enabled=lambda s: s._mode() in ("AUTO", "MDA")),
            view_softkey("machine.search", "Block\nsearch", "search",
                         enabled=lambda s: s._mode() == "AUTO" and s._search_allowed()
                         and bool(s.status.channel.selected_program)),
            view_softkey("machine.times", "Times/\nCounter", "times"),
            Softkey("machine.select", "Select\nprogram", "select_program",
                    level=PROGRAM_SELECTION_LEVEL,
                    enabled=lambda s: s._mode() == "AUTO" and s._reset_state()),
            view_softkey("machine.simrec", "Simult.\nrecording", "simrec",
                         enabled=lambda s: s._mode() == "AUTO"),
        ]
        return SoftkeyMenu.of(horizontal, self._vertical_softkeys())

    def _vertical_softkeys(self) -> list[Softkey | None]:
        view = self.view or MAIN_VIEWS.get(self._mode(), "view-jog")
        if view == "progctl":
            pc = (lambda s: s.status.channel.program_control)
            return [
                Softkey("progctl.sbl_type", _("Single block") + f"\n{self.hmi.single_block_type}",
                        "toggle_sbl_type"),
                Softkey("progctl.dry_run", "Dry run\nfeed", "toggle_control('dry_run')",
                        active=lambda s: bool(pc(s).get("dry_run"))),
                Softkey("progctl.m01", "Programmed\nstop M01", "toggle_control('m01')",
                        active=lambda s: bool(pc(s).get("m01"))),
                Softkey("progctl.program_test", "Program\ntest", "toggle_control('program_test')",
                        active=lambda s: bool(pc(s).get("program_test"))),
                Softkey("progctl.rov", "Rapid\noverride", "toggle_control('rapid_override')",
                        active=lambda s: bool(pc(s).get("rapid_override"))),
                Softkey("progctl.skip", "Skip\nlevels …", "choose_skip_level"),
            ]
        if view == "search":
            return [
                Softkey("search.start", "Start\nsearch", "start_search",
                        enabled=lambda s: s._search_allowed()),
                self._search_mode_key("search.contour", "Contour", "contour"),
                self._search_mode_key("search.end_point", "End\npoint", "end_point"),
                self._search_mode_key("search.without", "Without\ncalculation", "without_calculation"),
                self._search_mode_key("search.serupro", "SERUPRO", "serupro"),
            ]
        if view == "simrec":
            return [*view_keys("simrec", turning=lambda s: s.on_lathe),
                    overlay_key("simrec", lambda s: s.query_one("#simrec-stock", StockView).overlay)]
        if view == "times":
            return [
                Softkey("times.reset_parts", "Reset\npart count", "set_counter('$AC_ACTUAL_PARTS', 0)"),
                Softkey("times.required", "Required\nparts …", "enter_required_parts"),
            ]
        if view == "view-mda":
            return [Softkey("mda.delete", "Delete\nblocks", "clear_mda",
                            enabled=lambda s: s._reset_state()),
                    self._basic_blocks_key("mda")]
        if view == "view-auto":
            return [Softkey("auto.select", "Select\nprogram", "select_program",
                            level=PROGRAM_SELECTION_LEVEL,
                            enabled=lambda s: s._reset_state()),
                    self._basic_blocks_key("auto")]
        if view == "view-jog" or view in JOG_WINDOWS:
            return self.jog.vertical_softkeys(self.view)
        return []

    def _search_allowed(self) -> bool:
        """A block search may start in RESET, and again from "search target found" (cascaded
        search, 002 L18329-18332)."""
        return self._reset_state() or (
            self.status is not None and self.status.channel.stop_reason == "search target found")

    @staticmethod
    def _basic_blocks_key(mode: str) -> Softkey:
        return Softkey(f"{mode}.basic_blocks", "Basic\nblocks", "toggle_basic_blocks",
                       active=lambda s: s.show_basic_blocks)

    @staticmethod
    def _search_mode_key(key_id: str, label: str, search_type: str) -> Softkey:
        return Softkey(key_id, label, f"choose_search_type('{search_type}')",
                       active=lambda s: s.search_type == search_type)

    # -- softkey actions ------------------------------------------------------------------
    def action_toggle_mcs(self) -> None:
        """Actual values in the machine (MCS) or workpiece (WCS) coordinate system."""
        self.show_mcs = not self.show_mcs
        self._redraw()

    def action_toggle_basic_blocks(self) -> None:
        """The basic block display under the AUTO / MDA window on or off."""
        self.show_basic_blocks = not self.show_basic_blocks
        self.set_class(self.show_basic_blocks, "-basic-blocks")
        self._redraw()

    def action_show_view(self, view: str) -> None:
        """Show a softkey view; the same softkey again returns to the mode's view."""
        self.view = None if self.view == view else view
        if self.view in JOG_WINDOWS:
            self.jog.opened(self.view)
        self._redraw()

    def on_field_edited(self, event: FieldEdited) -> None:
        """A field of a JOG window changed: redraw its preview."""
        self._redraw()

    def action_jog(self, what: str, *args: str) -> None:
        """A softkey of a setting-up window of JOG (:meth:`JogWindows.run`)."""
        self.jog.run(what, *args)
        self._redraw()  # a window's preview shows what the softkey did (a point saved …)

    def menu_recall(self) -> bool:
        """F10: leave a softkey view first, then softkey levels."""
        if self.view is not None:
            self.view = None
            self._redraw()
            return True
        return super().menu_recall()

    def action_toggle_control(self, name: str) -> None:
        """A program-control switch on/off."""
        current = bool(self.status.channel.program_control.get(name)) if self.status else False
        self.submit(cmd.SetProgramControl(name, not current))

    def action_toggle_sbl_type(self) -> None:
        """Single block type SBL1 (action blocks) ⇄ SBL2 (every block)."""
        app = self.hmi
        app.single_block_type = "SBL2" if app.single_block_type == "SBL1" else "SBL1"
        if self.status is not None and self.status.channel.program_control.get("single_block"):
            self.submit(cmd.SetProgramControl("single_block", app.single_block_type))
        self._redraw()

    def action_choose_skip_level(self) -> None:
        """Choose a skip level /0 … /9 to switch on or off."""
        active = self._skip_levels()
        choices = [f"/{n}  {_('on') if n in active else _('off')}" for n in range(10)]

        def toggle(choice: str | None) -> None:
            if choice is None:
                return
            level = int(choice[1])
            levels = set(self._skip_levels())
            levels.symmetric_difference_update({level})
            self.submit(cmd.SetProgramControl("skip_levels", frozenset(levels)))

        self.app.push_screen(ChoiceDialog(_("Skip levels (Enter switches on/off)"), choices, translate=False), toggle)

    def _skip_levels(self) -> frozenset[int]:
        if self.status is None:
            return frozenset()
        value = self.status.channel.program_control.get("skip_levels") or ()
        return frozenset(int(v) for v in value)  # type: ignore[union-attr]

    def action_select_program(self) -> None:
        """Choose the part program for AUTOMATIC from the programs the kernel knows."""
        names = self.hmi.program_names()
        selected = self.status.channel.selected_program if self.status else None

        def select(choice: str | None) -> None:
            if choice:
                self.submit(cmd.SelectProgram(choice))

        self.app.push_screen(
            ChoiceDialog(_("Select program"), names, selected, empty_text=N_("no part programs"), translate=False),
            select,
        )

    def action_choose_search_type(self, search_type: str) -> None:
        """A search mode softkey: the type the next search uses."""
        self.search_type = search_type
        self._redraw()

    def action_start_search(self) -> None:
        """Start the block search of the chosen type to the target typed in the search field."""
        target = self.query_one("#search-input", Input).value.strip()
        if not target:
            self.show_hint(_("Enter a block number or text to search for"))
            return
        if isinstance(self.submit(cmd.StartBlockSearch(target, self.search_type)), Accepted):
            self.view = None
            self._redraw()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter in the search field starts the search."""
        if event.input.id == "search-input":
            self.action_start_search()

    def action_set_counter(self, name: str, value: int) -> None:
        """Write a part counter (``$AC_ACTUAL_PARTS`` …)."""
        self.submit(cmd.WriteData(name, value))

    def action_enter_required_parts(self) -> None:
        """Ask for the number of parts required ($AC_REQUIRED_PARTS)."""
        current = self.status.channel.parts_required if self.status else 0

        def write(text: str | None) -> None:
            if text is not None:  # the kernel reads the number and says what is wrong with it
                self.submit(cmd.WriteData("$AC_REQUIRED_PARTS", text))

        self.app.push_screen(ValueDialog(_("Required parts ($AC_REQUIRED_PARTS)"), str(current)), write)

    def action_clear_mda(self) -> None:
        """Delete the MDA blocks."""
        self.query_one("#mda-editor", TextArea).text = ""
        self.submit(cmd.SetMdaProgram(""))

    # -- MDA ---------------------------------------------------------------------------------
    def on_text_area_changed(self, event: TextArea.Changed) -> None:
        """Typing enters the MDA blocks at once."""
        if event.text_area.id == "mda-editor" and self._mda_loaded:
            text = event.text_area.text
            if self.status is None or text != self.status.channel.mda_text:
                self.submit(cmd.SetMdaProgram(text))

    def before_cycle_start(self) -> bool:
        """CYCLE START in MDA runs what the editor holds: make sure the kernel has it.

        In a JOG window (T,S,M, Position) its blocks become the MDA job; False when the
        window cannot be run (the dialog line says why) and no NC START is to be given.
        """
        if self.view in JOG_WINDOWS:
            return self.jog.before_cycle_start(self.view)
        if self._mode() == "MDA" and self._reset_state():
            text = self.query_one("#mda-editor", TextArea).text
            if self.status is not None and text != self.status.channel.mda_text:
                self.submit(cmd.SetMdaProgram(text))
        return True

    # -- status ------------------------------------------------------------------------------
    def update_status(self, status: NckStatus) -> None:
        """Show a snapshot in every window of the current view."""
        if not self._mda_loaded:
            editor = self.query_one("#mda-editor", TextArea)
            editor.load_text(status.channel.mda_text)
            self._mda_loaded = True
        if status.channel.mode != self._shown_mode:
            self._shown_mode = status.channel.mode
            # a setting-up window stays while its MDA job runs and when JOG comes back
            if not self.jog.keeps_window(self.view):
                self.view = None
        if self.jog.follow(status):
            return  # the job ended: JOG was selected and shown meanwhile
        self._redraw()

    def _redraw(self) -> None:
        status = self.status
        if status is None or not self.is_mounted:
            return
        channel = status.channel
        selected_axis = self.hmi.selected_axis
        self.query_one(PositionWindow).show(status, self.show_mcs, selected_axis)
        self.query_one(TfsWindow).show(status)
        self.query_one(GFunctionsLine).show(channel.modal.gcodes, getattr(channel.modal, "iso_gcodes", None))
        view_id = f"view-{self.view}" if self.view else MAIN_VIEWS.get(channel.mode, "view-jog")
        switcher = self.query_one(ContentSwitcher)
        if switcher.current != view_id:
            switcher.current = view_id
            self._recording_shown_at_s = None  # a view just opened is drawn at once
        self._focus_for(view_id)
        if view_id == "view-jog":
            show_text(self.query_one("#jog-info", Static), self._jog_text(status))
        elif view_id == "view-mda":
            show_text(self.query_one("#mda-title", Static), 
                " " + _("MDA — type blocks, CYCLE START (Alt+G) runs them")
                + f"   {_(PROGRAM_STATE_WORDS.get(channel.program_state, channel.program_state))}")
            if self.show_basic_blocks:
                self.query_one("#mda-basic", BasicBlockWindow).show(channel)
        elif view_id == "view-auto":
            show_text(self.query_one("#auto-title", Static), self._auto_title(status))
            program = (self.hmi.program_text(channel.selected_program)
                       if channel.selected_program else None)
            self.query_one("#auto-blocks", BlockWindow).show(channel, program, status.alarms)
            if self.show_basic_blocks:
                self.query_one("#auto-basic", BasicBlockWindow).show(channel)
        elif view_id == "view-gfunc":
            self.query_one(GFunctionsTable).show(channel.modal.gcodes, getattr(channel.modal, "iso_gcodes", None))
        elif view_id == "view-aux":
            show_text(self.query_one("#aux-table", Static), self._aux_text(status))
        elif view_id == "view-progctl":
            show_text(self.query_one("#progctl-table", Static), self._progctl_text(status))
        elif view_id == "view-times":
            show_text(self.query_one("#times-table", Static), self._times_text(status))
        elif view_id == "view-simrec":
            self._show_recording(status)
        elif self.view in JOG_WINDOWS:
            self.jog.show(self.view, status)
        elif view_id == "view-search":
            show_text(self.query_one("#search-title", Static),
                      " " + _("Block search") + f" {_(SEARCH_MODES[self.search_type])}")
            show_text(self.query_one("#search-info", Static),
                      " " + _("Program: {program}").format(program=channel.selected_program or "—")
                      + f"   {stop_reason_text(channel.stop_reason)}")
        self.refresh_softkeys()

    def _focus_for(self, view_id: str) -> None:
        focused = self.focused
        if view_id == "view-mda":
            editor = self.query_one("#mda-editor", TextArea)
            if focused is not editor:
                focus_now(editor)
        elif view_id == "view-search":
            field = self.query_one("#search-input", Input)
            if focused is not field:
                focus_now(field)
        elif view_id == "view-simrec":
            stock = self.query_one("#simrec-stock", StockView)
            if focused is not stock:
                focus_now(stock)
        elif self.view in JOG_WINDOWS:
            pass  # the window puts the focus into its fields (JogWindows.show)
        elif focused is not None:
            self.set_focus(None)

    # -- simultaneous recording ---------------------------------------------------------------
    def _show_recording(self, status: NckStatus) -> None:
        """The cut of the running program as far as it executed (asked of the kernel anew, at most
        every :data:`RECORDING_SHOWN_EVERY_S` while the channel runs; only a grown cut is drawn
        again)."""
        shown_at = self._recording_shown_at_s
        if (shown_at is not None and status.channel.channel_state == "active"
                and status.time_s - shown_at < RECORDING_SHOWN_EVERY_S):
            return
        self._recording_shown_at_s = status.time_s
        stock = self.query_one("#simrec-stock", StockView)
        cut = self.ask(RecordedCut())
        if cut is None:
            if not stock.picture.empty or not stock.status_text:
                stock.set_picture(StockPicture(turning=self.on_lathe),
                                  _("Simultaneous recording: starts with the next program start (CYCLE START)"))
            return
        chords = len(cut.path.starts)
        lines = cut.path.lines
        where = _("line {line}").format(line=int(lines[-1])) if len(lines) else _("no motion yet")
        state = {"ended": N_("ended"), "full": N_("recording stopped (too long)")}.get(cut.status, N_("recording"))
        note = f"{_(state)} ({where}), {material_events(cut)}"
        if chords != stock.picture.shown_chords or note != stock.status_text or stock.picture.empty:
            stock.set_picture(picture_of(cut, cut.zmap, chords), note)

    def action_simrec_view(self, view: str) -> None:
        """Simultaneous recording: choose the projection (top view or a section)."""
        self.query_one("#simrec-stock", StockView).action_view(view)
        self.refresh_softkeys()

    def action_simrec_zoom(self, direction: int) -> None:
        """Simultaneous recording: zoom in/out."""
        self.query_one("#simrec-stock", StockView).action_zoom(direction)

    def action_simrec_fit(self) -> None:
        """Simultaneous recording: fit the blank."""
        self.query_one("#simrec-stock", StockView).action_fit()

    def action_simrec_overlay(self) -> None:
        """Simultaneous recording: the toolpath over the material on/off."""
        self.query_one("#simrec-stock", StockView).action_overlay()
        self.refresh_softkeys()

    # -- view texts ----------------------------------------------------------------------------
    def _jog_text(self, status: NckStatus) -> Text:
        channel = status.channel
        app = self.hmi
        function = channel.machine_function
        text = Text()
        text.append(" JOG", style="bold")
        if function == "REF":
            text.append("  " + _("REF POINT — reference point approach") + "\n", style="bold")
            text.append(" " + _("Select an axis (Alt+X/Y/Z/C) and press + (Ctrl+Right).") + "\n")
            missing = [a.name for a in status.axes if a.kind != "spindle" and not a.referenced]
            text.append(" " + _("Not referenced:") + " "
                        + (" ".join(missing) if missing else _("none — all axes referenced")) + "\n")
        elif function == "REPOS":
            text.append("  " + _("REPOS — repositioning to the interruption point") + "\n", style="bold")
            for axis, way in channel.repos_offsets.items():
                text.append(f"   {axis:<4}{fixed(way, 3, 12)}\n")
        elif function == "INC" and channel.increment is None:
            size_mm = self.jog.variable_increment_mm()
            text.append("  " + _("INC VAR — variable increment {size} mm (SD41010)").format(size=f"{size_mm:g}")
                        + "\n", style="bold")
            if size_mm == 0:
                text.append(" " + _("SD41010 is 0: the axis keys do not move. Set the variable increment "
                                    "in Settings (⇧F6).") + "\n", style="bold #f39200")
        elif function == "INC":
            text.append(f"  {increment_text(channel.increment)} (x 0.001 mm)\n", style="bold")
        else:
            text.append("  " + _("continuous") + "\n", style="bold")
        text.append("\n " + _("Selected axis: {axis}").format(axis=app.selected_axis or "—") + "      "
                    + _("Rapid overlay: {state}").format(state=_("ON") if app.rapid_overlay else _("off")) + "\n")
        contact = contact_line(self.ask)
        if contact:
            text.append(f" {contact}\n", style="bold")
        # Two lines: one would wrap at the 120-column minimum (the window is 104 wide there).
        text.append(" " + _("Keys: Alt+X/Y/Z/C/V axis   Ctrl+Right / Ctrl+Left traverse   Alt+W rapid") + "\n"
                    "       " + _("Alt+I increment   Alt+R REF   Alt+E REPOS") + "\n", style="dim")
        return text

    def _auto_title(self, status: NckStatus) -> Text:
        channel = status.channel
        sbl = channel.program_control.get("single_block")
        text = Text()
        text.append(f" {channel.selected_program or _('no program selected')}", style="bold")
        if sbl:
            text.append(f"   SBL ({sbl})", style="bold #f39200")
        if channel.stop_reason:
            text.append("   " + _("stopped: {reason}").format(reason=stop_reason_text(channel.stop_reason)))
        text.append("   " + _("runtime {time}").format(time=clock(channel.program_runtime_s))
                    + "   " + _("parts {count}").format(count=channel.part_count))
        return text

    def _aux_text(self, status: NckStatus) -> Text:
        modal = status.channel.modal
        text = Text()
        text.append(f" {_('Function'):<10}{_('Active'):<12}\n", style="bold")
        text.append(f" {'T':<10}{modal.tool_name or modal.tool}\n")
        text.append(f" {'D':<10}{modal.edge}\n")
        text.append(f" {'S':<10}{trimmed(modal.spindle_speed_rpm)}  {modal.spindle_state}\n")
        text.append(f" {'F':<10}{trimmed(modal.feed)}\n")
        for key, value in sorted(modal.aux.items()):
            text.append(f" {key:<10}{value}\n")
        return text

    def _progctl_text(self, status: NckStatus) -> Text:
        pc = status.channel.program_control
        levels = sorted(self._skip_levels())
        text = Text()
        sbl = pc.get("single_block")
        text.append(f" {_check(sbl)} {_('Single block'):<22}" + _("type {type}").format(type=self.hmi.single_block_type)
                    + "   " + _("(Alt+K on/off, ⇧F1 type)") + "\n")
        text.append(f" {_check(pc.get('dry_run'))} {_('Dry run feed (DRY)')}\n")
        text.append(f" {_check(pc.get('m01'))} {_('Programmed stop (M01)')}\n")
        text.append(f" {_check(pc.get('program_test'))} {_('Program test (PRT)')}\n")
        text.append(f" {_check(pc.get('rapid_override'))} {_('Rapid traverse override (ROV)')}\n")
        shown = " ".join(f"/{n}" for n in levels) if levels else _("none")
        text.append("     " + _("Skip levels active: {levels}").format(levels=shown) + "\n")
        return text

    def _times_text(self, status: NckStatus) -> Text:
        channel = status.channel
        text = Text()
        rows = ((N_("Program runtime"), clock(channel.program_runtime_s)),
                (N_("Last program runtime"), clock(channel.program_runtime_last_s)),
                (N_("Part count"), channel.part_count), (N_("Required parts"), channel.parts_required),
                (N_("Total parts"), channel.parts_total))
        for label, value in rows:
            text.append(f" {_(label):<25}{value}\n")
        return text


AreaScreen = MachineScreen
"""The area convention: ``screens.<area>.AreaScreen`` is the area's screen class."""
