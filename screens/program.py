"""The Program area: the NC program editor with live checks and the toolpath simulation.

The editor shows one program of the NC file system (opened from the Program
manager, or the last one again with the PROGRAM key Alt+P):

* NC colours, line numbers, the cursor line highlighted;
* a check of the whole text runs shortly after each change, in a worker
  thread, and streams its alarms: each faulty line gets a gutter mark and an
  underline, the alarm number and text of the cursor line stand in the
  message line under the editor, and ``Next error`` (Shift+F1) jumps there;
* the message line also says what the word under the cursor means (G function with its
  group and whether it is modal, M function, system variable, cycle with its parameters:
  :mod:`hmi.word_help`);
* softkeys for Edit (mark, copy, cut, paste, delete, undo, redo), Search /
  Replace, Renumber (step 10), Save, Simulation, Execute and Close;
* unsaved text goes into a journal every few seconds (``hmi.journal``); after a
  crash the editor offers to restore it;
* the program being executed, and files that are not UTF-8 text, open
  read-only with a message.

Files are read and written only through the NC file system (``nck.storage``);
:mod:`hmi.program_files` finds it in the app.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, ClassVar

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.timer import Timer
from textual.widgets import Input, Static, TextArea
from textual.widgets.text_area import Selection

from nck import Action, ProgramLanguage, StorageError, required_level
from nck import commands as cmd
from nck.commands import Rejected
from nck.status import NckStatus

from hmi.area import AreaBase
from hmi.dialog import AreaDialog
from hmi.dialogs import ChoiceDialog
from hmi.focus import focus_now
from hmi.i18n import N_, _, error_text, refusal_text
from hmi.journal import AUTOSAVE_PERIOD_S, EditorJournal, text_hash
from hmi.program_files import ProgramFiles, decode_program
from hmi.softkeys import Softkey, SoftkeyMenu
from hmi.widgets.nc_editor import NcEditor
from hmi.widgets.stock_view import StockView
from hmi.widgets.toolpath import ToolpathView
from hmi.word_help import word_at, word_help
from hmi.widgets.fixed_size_input import FixedSizeInput
from screens.program_cycles import CycleActions
from screens.program_edit import EditActions
from screens.program_runs import CheckAndSimulation

DISCARD_ALL = N_("Discard all unsaved texts")
RESTORE_ONE = N_("Restore unsaved text")
DISCARD_ONE = N_("Discard unsaved text")
"""The journal dialogs' choices that the code answers (shown translated, returned as written)."""
SAVE_CHANGES = N_("Save changes")
DISCARD_CHANGES = N_("Discard changes")
KEEP_UNSAVED = N_("Keep unsaved for now")
BACK_TO_EDITOR = N_("Back to the editor")
"""The choices of the unsaved-changes dialog on closing a program."""


def edit_level() -> int:
    """The access level that may edit programs (``data/access.toml``, 7 when unknown)."""
    try:
        return required_level(Action.EDIT_PROGRAM)
    except (KeyError, ValueError):
        return 7


def _is_executing(status: NckStatus | None, program: str | None) -> bool:
    """True when ``program`` is the selected program and the channel is not in reset."""
    if status is None or program is None:
        return False
    channel = status.channel
    selected = channel.selected_program
    if not selected:
        return False
    same = Path(selected).name.upper() == Path(program).name.upper()
    return same and (channel.channel_state != "reset" or channel.program_state != "aborted")


class ProgramScreen(EditActions, CycleActions, CheckAndSimulation, AreaBase):
    """The program editor (area PROGRAM)."""

    AREA_ID: ClassVar[str] = "program"
    AREA_TITLE: ClassVar[str] = "PROGRAM"
    CSS_PATH = "program.tcss"

    def __init__(self, name: str | None = None, id: str | None = None,  # noqa: A002
                 classes: str | None = None) -> None:
        super().__init__(name=name, id=id or "area-program", classes=classes)
        self.program: str | None = None
        """NC name of the open program (``/MPF/PART1.MPF``), None when nothing is open."""
        self.saved_text = ""
        self.read_only_reason = ""
        self.binary = False
        self.simulating = False
        self.sim_material = True
        self.search_open = False
        self._dirty = False
        self._generation = 0
        self._marks_generation = -1
        self._check_running = False
        self._checked_setting = b""  # the machine and NC data the last check ran on, pickled
        self._language: ProgramLanguage | None = None  # how its lines are read (word help)
        self._check_timer: Timer | None = None
        self._journaled_hash = ""
        self._mark_anchor: tuple[int, int] | None = None
        self._restore_offered = False
        self._loading = False
        self._leave_asked = False

    # -- layout ------------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """Title line, editor (or simulation), search bar, message line."""
        with Vertical(id="prog-body"):
            yield Static("", id="prog-title", markup=False)
            with Horizontal(id="prog-work"):
                yield NcEditor("", id="prog-editor", read_only=True)
                yield ToolpathView(id="prog-toolpath")
                yield StockView(id="prog-stock")
            with Horizontal(id="prog-search"):
                yield FixedSizeInput(placeholder=_("search"), id="prog-find")
                yield FixedSizeInput(placeholder=_("replace with"), id="prog-replace")
            yield Static("", id="prog-message", markup=False)

    @property
    def editor(self) -> NcEditor:
        """The editor widget."""
        return self.query_one("#prog-editor", NcEditor)

    @property
    def toolpath(self) -> ToolpathView:
        """The simulation widget."""
        return self.query_one("#prog-toolpath", ToolpathView)

    @property
    def stock(self) -> StockView:
        """The material-removal view of the simulation."""
        return self.query_one("#prog-stock", StockView)

    @property
    def files(self) -> ProgramFiles:
        """The NC file system as the editor uses it."""
        return ProgramFiles.of_app(self.app)

    @property
    def journal(self) -> EditorJournal:
        """The editor journal in the NC data directory."""
        return EditorJournal(self.files.journal_dir)

    def on_mount(self) -> None:
        """Start the autosave timer; offer a journal restore; show the empty state."""
        super().on_mount()
        self.set_interval(AUTOSAVE_PERIOD_S, self.autosave)
        self._show_view()
        self._update_title()
        if not self._open_requested() and self.program is None:
            self.call_after_refresh(self.offer_restore)

    def on_screen_resume(self) -> None:
        """Back in the area: open what the Program manager asked for, else the last program."""
        super().on_screen_resume()
        if self._ready:
            if not self._open_requested():
                self.check_again_if_the_setting_changed()
            self._update_read_only()

    def _open_requested(self) -> bool:
        requested, at_end = self.files.take_open_request() or (None, False)
        if requested is None and self.program is None and self.files.last_program:
            requested = self.files.last_program
        if requested is None or requested == self.program:
            return False
        self.open_program(requested, at_end=at_end)
        return True

    @property
    def _ready(self) -> bool:
        """True once the windows exist (``is_mounted`` is still False inside ``on_mount``)."""
        return bool(self.query("#prog-editor"))

    # -- softkeys ------------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Top level: Edit, Search, Renumber, Save, Simulation, Execute, Close."""
        if self.simulating:
            return self._simulation_menu()
        has_program = lambda s: s.program is not None  # noqa: E731
        writable = lambda s: s.program is not None and not s.editor.read_only  # noqa: E731
        return SoftkeyMenu.of(
            [
                Softkey("program.edit", "Edit", "edit_menu", enabled=has_program, submenu="edit_menu"),
                Softkey("program.search", "Search", "search", enabled=has_program,
                        active=lambda s: s.search_open, submenu="search_menu"),
                Softkey("program.renumber", "Renumber", "renumber", enabled=writable),
                Softkey("program.save", "Save", "save", enabled=writable),
                Softkey("program.simulate", "Simulation", "simulate", enabled=has_program),
                Softkey("program.execute", "Execute", "execute", enabled=has_program),
                Softkey("program.manager", "Programs", "app.switch_area('program_manager')"),
                Softkey("program.close", "Close", "close", enabled=has_program),
            ],
            [
                # VSK3 (Shift+F3) carries nothing essential; terminals send it like a cursor
                # position report, which HmiApp.on_cursor_position turns back into the key.
                Softkey("program.next_error", "Next\nerror", "next_error", enabled=has_program),
                Softkey("program.start", "Start of\nprogram", "cursor_start", enabled=has_program),
                Softkey("program.check", "Check\nnow", "check_now", enabled=has_program),
                Softkey("program.end", "End of\nprogram", "cursor_end", enabled=has_program),
                Softkey("program.undo", "Undo", "undo", enabled=writable),
                Softkey("program.redo", "Redo", "redo", enabled=writable),
                Softkey("program.cycles", "Cycles /\nRecompile", "cycles", enabled=writable),
                Softkey("program.restore", "Restore\nunsaved", "offer_restore_any"),
            ],
        )

    def action_edit_menu(self) -> None:
        """Edit softkey: show the edit sub-level."""
        self.push_softkeys(self.edit_menu())

    def pop_softkeys(self) -> bool:
        """Leave the current softkey level; leaving the Edit level ends a marking (as Mark again)."""
        if self._mark_anchor is not None:
            self.unmark()
        return super().pop_softkeys()

    def clear_softkey_levels(self) -> None:
        """Back to the top softkey level (another area chosen, a program closed): no marking
        stays, and the search bar closes with its softkey level."""
        if self._mark_anchor is not None:
            self.unmark()
        if self.search_open:
            self.search_open = False
            self._show_view()
        super().clear_softkey_levels()

    def action_pop_menu(self) -> None:
        """Back one softkey level."""
        self.pop_softkeys()

    def menu_recall(self) -> bool:
        """F10: leave the search bar / simulation / sub-level."""
        if self.search_open:
            self.action_close_search()
            return True
        if self.pop_softkeys():
            return True
        if self.simulating:
            self.action_simulate()
            return True
        return False

    # -- opening and closing -----------------------------------------------------------------
    def open_program(self, program: str, *, text: str | None = None, offer_journal: bool = True,
                     at_end: bool = False) -> bool:
        """Show ``program`` in the editor (read from the NC file system unless ``text`` is given).

        The cursor starts on the first line, or with ``at_end`` behind the text (a new
        program: what the operator types goes below its header line). Returns False
        (with a message) when it cannot be read.
        """
        if self.program is not None and self.program != program and self.is_modified():
            self.journal_now()
        try:
            canonical = self.files.canonical(program)
            raw = self.files.fs.read_bytes(canonical) if text is None else text.encode("utf-8")
        except (StorageError, OSError) as exc:  # a file problem is a notification, never a traceback
            # the refusal names the program itself ("MPF/X.MPF does not exist", "MPF/X.MPF: permission denied")
            self.say(_("Not opened: {error}").format(error=error_text(exc, failed="os_read_failed")))
            return False
        decoded, binary = decode_program(raw)
        if self.simulating:  # a program opens in the editor, never beside another one's simulation
            self.leave_simulation()
            self._menu_stack.clear()
            self._show_view()
        self.program = canonical
        self.binary = binary
        self.saved_text = decoded
        self._dirty = False
        self._stop_marking()
        self._journaled_hash = ""
        self.files.last_program = self.program
        editor = self.editor
        self._loading = True  # the Changed message of load_text is not an edit
        editor.load_text(decoded)
        if at_end:
            editor.move_cursor(editor.document.end)
        editor.set_error_marks([])
        self._update_read_only()
        if binary:
            self.say(_("{program} is not a UTF-8 text file: opened read-only").format(program=self.program))
        self._update_title()
        self.refresh_softkeys()
        focus_now(editor)
        if not binary:
            self.check_now()
            entry = self.journal.entry(self.program) if offer_journal else None
            if entry is not None and entry.text != decoded:
                self._ask_restore(entry)
        return True

    def is_modified(self) -> bool:
        """True when the editor text differs from the saved file."""
        return self.program is not None and self._dirty and self.editor.text != self.saved_text

    def close_program(self) -> None:
        """Close the editor (no question asked: callers ask first)."""
        if self.program is not None:
            self.journal.discard(self.program)
            if self.files.last_program == self.program:
                self.files.last_program = None
        self.program = None
        self.saved_text = ""
        self._dirty = False
        self.binary = False
        self.leave_simulation()
        self.editor.load_text("")
        self.editor.set_error_marks([])
        self._update_read_only()
        self._show_view()
        self._update_title()
        self.clear_softkey_levels()

    def action_close(self) -> None:
        """Close softkey: ask about unsaved changes, then back to the Program manager."""
        if not self.is_modified():
            self.close_program()
            self.perform("app.switch_area('program_manager')")
            return
        self._ask_unsaved(after="manager")

    def _ask_unsaved(self, after: str) -> None:
        program = self.program

        def decided(choice: str | None) -> None:
            if choice is None:  # cancelled (Escape, F10, an area key): the text stays in the journal
                return
            if choice == BACK_TO_EDITOR or program != self.program:
                if self.app.current_mode != self.AREA_ID:
                    self.perform("app.switch_area('program')")
                return
            if choice == SAVE_CHANGES and not self.action_save():
                return
            if choice == KEEP_UNSAVED:
                self.journal_now()
                return
            self.close_program()
            if after == "manager":
                self.perform("app.switch_area('program_manager')")

        self.app.push_screen(
            ChoiceDialog(
                _("{program} has unsaved changes").format(program=program),
                [SAVE_CHANGES, DISCARD_CHANGES, KEEP_UNSAVED, BACK_TO_EDITOR],
            ),
            decided,
        )

    def on_screen_suspend(self) -> None:
        """Leaving the area: keep unsaved text in the journal and ask about it."""
        if self.is_modified():
            self.journal_now()
            self.app.call_later(self._ask_after_leave)

    def unsaved_work(self) -> str:
        """What quitting now would leave unsaved: the program with changes (else ``""``)."""
        return _("unsaved changes in {program}").format(program=self.program) if self.is_modified() else ""

    def keep_before_quit(self) -> None:
        """The app is about to close (Ctrl+Q): unsaved text goes into the journal, offered next time.

        Runs while the editor still exists; an ``OSError`` of the write reaches the app,
        which then stays open and says why.
        """
        if self.program is not None and not self.binary:
            self._journaled_hash = ""
            self.write_journal()

    def _ask_after_leave(self) -> None:
        if self.app.current_mode == self.AREA_ID or not self.is_modified():
            return
        if isinstance(self.app.screen, AreaDialog):
            # A key behind the area key opened a dialog first (Ctrl+Q asks about this text
            # too): no second question over it; the text waits in the editor and the journal.
            return
        self._ask_unsaved(after="stay")

    # -- journal -------------------------------------------------------------------------------
    def autosave(self) -> None:
        """Timer: write unsaved text into the journal if it changed since the last time."""
        try:
            self.write_journal()
        except OSError as exc:
            self.say(_("Journal could not be written: {error}").format(error=error_text(exc)))

    def write_journal(self) -> None:
        """Write unsaved text into the journal if it changed since the last write (``OSError`` if it cannot)."""
        if self.program is None or self.binary or not self._dirty:
            return
        text = self.editor.text
        digest = text_hash(text)
        if text == self.saved_text:
            if self._journaled_hash:
                self.journal.discard(self.program)
                self._journaled_hash = ""
            return
        if digest != self._journaled_hash:
            self.journal.write(self.program, text, text_hash(self.saved_text))
            self._journaled_hash = digest

    def journal_now(self) -> None:
        """Write the journal at once (before leaving, closing, crashing risks)."""
        self._journaled_hash = ""
        self.autosave()

    def offer_restore(self) -> None:
        """If the journal holds unsaved text from an earlier session, offer to restore it."""
        if self._restore_offered:
            return
        self._restore_offered = True
        self.action_offer_restore_any()

    def action_offer_restore_any(self) -> None:
        """Restore softkey: list the journal entries and restore the chosen one."""
        try:
            entries = self.journal.entries()
        except OSError:
            entries = []
        if not entries:
            if self.program is not None:
                self.say(_("No unsaved programs in the journal"))
            return
        by_label = {_("Restore {program}").format(program=e.program): e for e in entries}

        def chosen(choice: str | None) -> None:
            if choice in by_label:
                entry = by_label[choice]
                self._restore(entry)
            elif choice == _(DISCARD_ALL):
                for entry in entries:
                    self.journal.discard(entry.program)
                self.say(_("Unsaved texts discarded"))

        self.app.push_screen(
            ChoiceDialog(
                _("Unsaved program text from an earlier session was found"),
                [*by_label, _(DISCARD_ALL)],
                translate=False,
            ),
            chosen,
        )

    def _ask_restore(self, entry: Any) -> None:
        def chosen(choice: str | None) -> None:
            if choice == RESTORE_ONE:
                self._restore(entry)
            elif choice == DISCARD_ONE:
                self.journal.discard(entry.program)

        self.app.push_screen(
            ChoiceDialog(_("{program}: unsaved text from an earlier session").format(program=entry.program),
                         [RESTORE_ONE, DISCARD_ONE, N_("Decide later")]),
            chosen,
        )

    def _restore(self, entry: Any) -> None:
        if self.program != entry.program:
            if not self.open_program(entry.program, offer_journal=False):
                # the file is gone: restore into a fresh editor under the old name
                self.open_program(entry.program, text="", offer_journal=False)
            if self.program is None:
                return
        editor = self.editor
        editor.replace(entry.text, (0, 0), editor.document.end)
        self._dirty = True
        self._update_title()
        self.say(_("{program}: unsaved text restored (not saved yet)").format(program=entry.program))
        self.schedule_check()

    # -- read-only rules -----------------------------------------------------------------------
    def refusal_of(self, label: str) -> str:
        """A greyed softkey of the editor: the reason the text is read-only, when it is (the
        simulation's keys are never greyed for that: a lathe's projection keys say the state)."""
        if self.read_only_reason and not self.simulating:
            return _("{softkey}: {reason}").format(softkey=label, reason=self.read_only_reason)
        return super().refusal_of(label)

    def _update_read_only(self) -> None:
        reason = ""
        executing = False
        if self.program is None:
            reason = _("no program")
        elif self.binary:
            reason = _("not a text file")
        elif _is_executing(self.status, self.program):
            reason, executing = _("program is being executed"), True
        elif self.files.is_in_use(self.program):
            reason = _("program is in use (selected)")
        elif self.access_level > edit_level():
            reason = _("editing needs access level {level}").format(level=edit_level())
        changed = reason != self.read_only_reason
        self.read_only_reason = reason
        if self._ready:
            self.editor.read_only = bool(reason)
            if changed and executing:
                self.say(_("{program} is being executed: editing is not possible").format(program=self.program))
        if changed:
            self._update_title()
            self.refresh_softkeys()

    def update_status(self, status: NckStatus) -> None:
        """A new snapshot: read-only while executing; current block in the simulation."""
        self._update_read_only()
        if self.simulating:
            self._mark_current_block(status)

    def _mark_current_block(self, status: NckStatus | None) -> None:
        """Mark in the toolpath view the block being executed (when the machine runs the program
        shown), else the block of the editor's cursor line."""
        line = self.editor.cursor_location[0] + 1
        block = status.channel.current_block if status is not None else None
        if block is not None and self.program and Path(block.file).name.upper() == Path(self.program).name.upper():
            line = block.line
        self.toolpath.current_line = line

    # -- editing events ----------------------------------------------------------------------
    def on_text_area_changed(self, event: TextArea.Changed) -> None:
        """Text changed: mark modified, schedule a check."""
        if self.program is None:
            return
        if self._loading:
            self._loading = False
            return
        self._dirty = True
        self._update_title()
        self.schedule_check()

    def on_text_area_selection_changed(self, event: TextArea.SelectionChanged) -> None:
        """Cursor moved: extend a marked block, show the alarm of the cursor line."""
        if self._mark_anchor is not None:
            selection = event.selection
            if selection.start == selection.end and selection.end != self._mark_anchor:
                self.editor.selection = Selection(self._mark_anchor, selection.end)
        self._show_cursor_message()
        self._update_title()
        if self.simulating and self.editor.cursor_location[0] + 1 != self.stock.highlight_line:
            self.mark_cursor_block()

    def _show_cursor_message(self) -> None:
        if not self._ready:
            return
        mark = self.editor.error_at_cursor()
        message = self.query_one("#prog-message", Static)
        count = len(self.editor.error_marks)
        if mark is not None:
            message.update(f"⚠ {mark.label}", layout=False)  # one line of fixed size: no layout pass
            message.set_class(True, "-error")
        else:
            state = _("checking …") if self._check_running else (
                _("{count} faulty line(s) — Shift+F1: next error").format(count=count) if count
                else _("no errors found"))
            meaning = self._word_meaning()
            message.update((f"{state}   │ {meaning}" if meaning else state) if self.program else "", layout=False)
            message.set_class(False, "-error")

    def _word_meaning(self) -> str:
        """What the word under the cursor means (G/M function, system variable, cycle), or ""."""
        row, column = self.editor.cursor_location
        dialect = self._language.dialect_at(row) if self._language is not None else "siemens"
        return word_help(word_at(self.editor.document.get_line(row), column), dialect)

    def _update_title(self) -> None:
        if not self._ready:
            return
        title = self.query_one("#prog-title", Static)
        if self.program is None:
            title.update(_("No program open — Program manager (Alt+N): select a program and press Open"), layout=False)
            return
        flags = []
        if self._dirty:  # cheap on every cursor move; is_modified() compares the text
            flags.append(_("modified"))
        if self.read_only_reason:
            flags.append(_("read-only: {reason}").format(reason=self.read_only_reason))
        lines = self.editor.document.line_count
        row, column = self.editor.cursor_location
        suffix = f"  [{', '.join(flags)}]" if flags else ""
        place = _("line {line}/{lines}  col {column}").format(line=row + 1, lines=lines, column=column + 1)
        title.update(f" {self.program}{suffix}   {place}", layout=False)  # one line of fixed size: no layout pass

    # -- save, execute -------------------------------------------------------------------------
    def action_save(self) -> bool:
        """Save softkey: write the text atomically through the NC file system."""
        if self.program is None or self.editor.read_only:
            if self.read_only_reason:
                self.say(_("Not saved: {reason}").format(reason=self.read_only_reason))
            return False
        text = self.editor.text
        try:
            self.files.fs.save(self.program, text)
        except (StorageError, OSError) as exc:  # a file problem is a notification, never a traceback
            # the refusal names what is in the way ("MPF/X.MPF: larger than …", "WKS/W.WPD does not exist")
            self.say(_("Not saved: {reason}").format(reason=error_text(exc)))
            return False
        self.saved_text = text
        self._dirty = False
        self.journal.discard(self.program)
        self._journaled_hash = ""
        self._update_title()
        self.say(_("{program} saved").format(program=self.program))
        return True

    def action_execute(self) -> None:
        """Execute softkey: save, select the program in AUTO and go to the Machine area."""
        if self.program is None:
            return
        if self.is_modified() and not self.action_save():
            return
        if self.status is not None and self.status.channel.mode != "AUTO":
            result = self.submit(cmd.SelectMode("AUTO"))
            if isinstance(result, Rejected):
                self.say(_("Execute: {reason}").format(reason=refusal_text(result)))
                return
        result = self.submit(cmd.SelectProgram(self.program))
        if isinstance(result, Rejected):
            self.say(_("Execute: {reason}").format(reason=refusal_text(result)))
            return
        self.perform("app.switch_area('machine')")

    # -- view switching --------------------------------------------------------------------------
    def _show_view(self) -> None:
        if not self._ready:
            return
        self.editor.set_class(self.simulating, "-beside")  # the program beside the simulation
        self.toolpath.display = self.simulating and not self.sim_material
        self.stock.display = self.simulating and self.sim_material
        self.query_one("#prog-search").display = self.search_open and not self.simulating


AreaScreen = ProgramScreen
"""The area screen the app puts into its MODES (convention of ``hmi/app.py``)."""
