"""The Diagnostics area: alarms, messages, alarm log, service screens, utilisation, trace.

Views (horizontal softkeys): alarm list, messages, alarm log, service overview,
service axis/spindle, service drive, trace; ``More`` leads to system
utilisation, version and the logbook. The vertical softkeys belong to the
view on display (acknowledge, filter/export, axis +/−, trace settings).
Everything shown comes from the status snapshot and from read-only questions to the
kernel through the bridge (``nck.queries``: alarm history, logbook, buffer fill, counters);
the utilisation figures are the bridge's measurement of the kernel's compute time.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, ClassVar

from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import ContentSwitcher, Input, Static

import nck as nck_package
from nck import commands as cmd
from nck import queries
from nck.status import NckStatus
from nck import ExportTargetExists, TraceError, signal_unit, write_export

from hmi.alarm_times import date_time_text
from hmi.area import AreaBase, show_text
from hmi.dialogs import ConfirmDialog, ValueDialog
from hmi.focus import focus_now
from hmi.i18n import N_, _, alarm_text, counted, error_text, exercise_text, reason_text
from hmi.softkeys import Softkey, SoftkeyMenu
from hmi.widgets.plot import TracePlot
from hmi.widgets.fixed_size_input import FixedSizeInput
from screens.diagnostics_alarms import (
    LogFilter, alarm_list_rows, alarm_list_text, log_as_csv, log_as_text, log_rows, log_text, message_lines,
    messages_text, parse_filter,
)
from screens.diagnostics_service import (
    axis_rows, drive_rows, overview_text, rows_text, utilisation_rows,
)
from screens.diagnostics_exercises import exercises_text
from screens.diagnostics_trace import TraceSession

VIEWS = ("alarms", "messages", "log", "overview", "axis", "drive", "utilisation", "trace",
         "version", "logbook", "exercises")
TITLES = {
    "alarms": N_("Alarm list"), "messages": N_("Messages"), "log": N_("Alarm log"),
    "overview": N_("Service overview"), "axis": N_("Service axis/spindle"), "drive": N_("Service drive"),
    "utilisation": N_("System utilisation"), "trace": N_("Trace"), "version": N_("Version"),
    "logbook": N_("Logbook"), "exercises": N_("Exercises"),
}
LOG_PAGE = 30
UTILISATION_REFRESH_S = 1.0
"""System utilisation redraws its measured figures once per second of control time (our
choice where the manuals are silent: they are means over the last calls, and a redraw with
every snapshot, 20 a second, only floods the terminal)."""


def _view_key(key_id: str, label: str, view: str) -> Softkey:
    return Softkey(key_id, label, f"show_view('{view}')", active=lambda s, v=view: s.view == v)


AXIS_KINDS = {"linear": N_("linear"), "rotary": N_("rotary"), "spindle": N_("spindle")}
"""The kinds of a machine axis (``nck.machine``) as the version screen names them."""


class DiagnosticsScreen(AreaBase):
    """The Diagnostics operating area."""

    AREA_ID: ClassVar[str] = "diagnostics"
    AREA_TITLE: ClassVar[str] = "DIAGNOSTICS"
    CSS_PATH = "diagnostics.tcss"
    AUTO_FOCUS = ""  # the filter field takes the keys only after the Filter softkey (None = the app's "*")
    BINDINGS: ClassVar[list[Binding]] = [
        Binding("left", "arrow(-1)", "Trace cursor left", show=False),
        Binding("right", "arrow(1)", "Trace cursor right", show=False),
        Binding("pagedown", "page(1)", "Older log entries", show=False),
        Binding("pageup", "page(-1)", "Newer log entries", show=False),
        Binding("up", "select_row(-1)", "Select the alarm or exercise above", show=False),
        Binding("down", "select_row(1)", "Select the alarm or exercise below", show=False),
    ]
    """Cursor keys move the trace cursor or select an alarm or an exercise, page keys scroll the
    alarm log."""

    def __init__(self) -> None:
        super().__init__(id="area-diagnostics")
        self.view = "alarms"
        self.axis_index = 0
        self.log_filter = LogFilter()
        self.log_first = 0
        self.selected_row = 0  # the selected alarm of the alarm list or the alarm log (row index)
        self.export_dir = Path.cwd()
        self.trace: TraceSession | None = None
        self._log_seq = -1
        self._utilisation_cycle: int | None = None  # IPO cycle of the figures on display
        self.exercises: list = []
        self.exercise_index = 0
        self._running_exercise: str | None = None

    # -- kernel data (read-only questions through the bridge) ------------------------------
    def _history(self) -> tuple:
        return self.ask(queries.AlarmHistory())

    # -- layout ---------------------------------------------------------------------------
    def compose_content(self) -> ComposeResult:
        """A title line and one window per view."""
        yield Static("", id="diag-title", markup=False)
        with ContentSwitcher(id="diag-views", initial="view-alarms"):
            for view in VIEWS:
                with Vertical(id=f"view-{view}", classes="diag-view"):
                    if view == "log":
                        yield FixedSizeInput(placeholder=_("number range and/or text, e.g. 10000-19999 limit"),
                                    id="log-filter")
                    if view == "trace":
                        yield Static("", id="trace-settings", markup=False)
                        yield TracePlot(id="trace-plot")
                    else:
                        yield Static("", id=f"diag-{view}", classes="diag-body", markup=False)

    def on_mount(self) -> None:
        """No cursor blink; a trace session on the machine's axes."""
        self.query_one("#log-filter", Input).cursor_blink = False
        machine = self.ask(queries.ReadData()).machine
        if machine is not None:
            self.trace = TraceSession(machine)
        super().on_mount()
        self._show_view()

    # -- softkeys -----------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Views on the horizontal keys; the view's own keys on the vertical ones."""
        horizontal = [
            _view_key("diag.alarms", "Alarm\nlist", "alarms"),
            _view_key("diag.messages", "Messages", "messages"),
            _view_key("diag.log", "Alarm\nlog", "log"),
            _view_key("diag.overview", "Service\noverview", "overview"),
            _view_key("diag.axis", "Service\naxis", "axis"),
            _view_key("diag.drive", "Service\ndrive", "drive"),
            _view_key("diag.trace", "Trace", "trace"),
            Softkey("diag.more", "More\n▸", "more", submenu="more_menu"),
        ]
        return SoftkeyMenu.of(horizontal, self._vertical_keys())

    def more_menu(self) -> SoftkeyMenu:
        return SoftkeyMenu.of([
            _view_key("diag.utilisation", "System\nutilis.", "utilisation"),
            _view_key("diag.version", "Version", "version"),
            _view_key("diag.logbook", "Logbook", "logbook"),
            _view_key("diag.exercises", "Exercises", "exercises"),
        ], self._vertical_keys())

    def _vertical_keys(self) -> list[Softkey | None]:
        alarm_help = Softkey("diag.alarm_help", "Alarm\nhelp", "alarm_help",
                             enabled=lambda s: s.selected_alarm() is not None)
        if self.view == "alarms":
            return [Softkey("diag.ack", "Acknowl.\nalarm", "acknowledge",
                            enabled=lambda s: bool(s.status and any(a.clear == "cancel" for a in s.status.alarms))),
                    alarm_help]
        if self.view == "log":
            return [
                Softkey("diag.log.filter", "Filter", "focus_filter"),
                Softkey("diag.log.unfilter", "Clear\nfilter", "clear_filter"),
                Softkey("diag.log.csv", "Export\nCSV", "export_log('csv')"),
                Softkey("diag.log.text", "Export\ntext", "export_log('text')"),
                Softkey("diag.log.older", "Older\n▼", "page_log(1)"),
                Softkey("diag.log.newer", "Newer\n▲", "page_log(-1)"),
                alarm_help,
            ]
        if self.view == "exercises":
            return [
                Softkey("diag.ex.start", "Start\nexercise", "exercise_start",
                        enabled=lambda s: not s.hmi.exercise_side),
                Softkey("diag.ex.end", "End\nexercise", "exercise_end", enabled=lambda s: bool(s.hmi.exercise_side)),
                Softkey("diag.ex.down", "Next\n▼", "exercise_select(1)"),
                Softkey("diag.ex.up", "Previous\n▲", "exercise_select(-1)"),
                Softkey("diag.ex.import", "Import\nclass pack", "exercise_import",
                        level=self.ask(queries.ActionLevel("IMPORT_CLASS_PACK")),
                        enabled=lambda s: not s.hmi.exercise_side),
            ]
        if self.view in ("axis", "drive"):
            return [Softkey("diag.axis.next", "Axis +", "next_axis(1)"),
                    Softkey("diag.axis.prev", "Axis −", "next_axis(-1)")]
        if self.view == "trace":
            return [
                Softkey("diag.trace.slot", "Signal\nslot +", "trace_slot"),
                Softkey("diag.trace.signal", "Select\nsignal", "trace_signal",
                        enabled=lambda s: s.trace is not None and not s.trace.running),
                Softkey("diag.trace.trigger", "Trigger", "trace_trigger",
                        enabled=lambda s: s.trace is not None and not s.trace.running),
                Softkey("diag.trace.duration", "Duration", "trace_duration",
                        enabled=lambda s: s.trace is not None and not s.trace.running),
                Softkey("diag.trace.start", "Start /\nstop", "trace_start",
                        active=lambda s: s.trace is not None and s.trace.running),
                Softkey("diag.trace.csv", "Export\nCSV", "trace_export"),
                Softkey("diag.trace.left", "Cursor\n◀", "trace_cursor(-1)"),
                Softkey("diag.trace.right", "Cursor\n▶", "trace_cursor(1)"),
            ]
        return []

    def menu_recall(self) -> bool:
        """F10: leave the More level, else go back to the alarm list."""
        if self.pop_softkeys():
            return True
        if self.view != "alarms":
            self.action_show_view("alarms")
            return True
        return False

    # -- actions -----------------------------------------------------------------------------
    def action_show_view(self, view: str) -> None:
        """Show ``view``."""
        self.view = view
        self.selected_row = 0
        if self._menu_stack:
            self._menu_stack[-1] = self.more_menu()
        self._show_view()

    def action_more(self) -> None:
        """The second softkey level (utilisation, version, logbook)."""
        self.push_softkeys(self.more_menu())

    def action_acknowledge(self) -> None:
        """Acknowledge the alarms with clear criterion CANCEL (as F12)."""
        self.submit(cmd.CancelAlarms())

    def _selectable_rows(self) -> list:
        """The rows ▲▼ select in: the active alarms, or the (filtered) alarm log."""
        if self.view == "alarms":
            return alarm_list_rows(self.status.alarms) if self.status is not None else []
        if self.view == "log":
            return log_rows(self._history(), self.log_filter)
        return []

    def selected_alarm(self) -> Any:
        """The selected entry of the alarm list or alarm log (None when there is none)."""
        rows = self._selectable_rows()
        return rows[min(self.selected_row, len(rows) - 1)] if rows else None

    def action_select_row(self, step: int) -> None:
        """▲▼ in the alarm list and alarm log: select the alarm above or below; in the exercise
        list the exercise (as Next ▼ / Previous ▲)."""
        if self.view == "exercises":
            self.action_exercise_select(step)
            return
        rows = self._selectable_rows()
        if not rows:
            return
        self.selected_row = max(0, min(self.selected_row + int(step), len(rows) - 1))
        if self.view == "log" and not self.log_first <= self.selected_row < self.log_first + LOG_PAGE:
            self.log_first = self.selected_row - (LOG_PAGE - 1 if step > 0 else 0)
        self._log_seq = -1
        self._refresh_view()

    def action_alarm_help(self) -> None:
        """Alarm help: what the selected alarm means and what to do about it."""
        entry = self.selected_alarm()
        if entry is not None:
            self.hmi.show_alarm_help(entry.number, alarm_text(entry))

    def action_exercise_select(self, step: int) -> None:
        """Next ▼ / Previous ▲: move the selection in the exercise list."""
        if self.exercises:
            self.exercise_index = (self.exercise_index + int(step)) % len(self.exercises)
        self._refresh_view()

    def action_exercise_start(self) -> None:
        """Start the selected exercise on its own set-up."""
        if not self.exercises:
            return
        exercise = self.exercises[self.exercise_index]
        said = self.hmi.start_exercise(exercise)
        self._running_exercise = exercise_text(exercise, "title") if self.hmi.exercise_side else None
        self.say(said)
        self._refresh_view()

    def action_exercise_end(self) -> None:
        """End the running exercise: the report is written, the own data come back."""
        said = self.hmi.end_exercise()
        self._running_exercise = None
        self.say(said)
        self._refresh_view()

    def action_exercise_import(self) -> None:
        """Import class pack: ask for the pack's file, import it, show the new list."""
        def imported(path: str | None) -> None:
            if not path:
                return
            self.say(self.hmi.import_class_pack(path))
            self.exercises = []  # read again with the imported ones
            self._refresh_view()

        self.app.push_screen(ValueDialog(_("Import class pack"), f"{self.export_dir}{os.sep}",
                                         _("The class pack's file (written by nck class-pack export)")), imported)

    def action_next_axis(self, step: int) -> None:
        """Axis + / Axis −: the next or previous machine axis (spindles included)."""
        count = len(self.status.axes) if self.status is not None else 1
        self.axis_index = (self.axis_index + int(step)) % max(count, 1)
        self._refresh_view()

    def action_focus_filter(self) -> None:
        """Put the cursor into the log filter field."""
        focus_now(self.query_one("#log-filter", Input))

    def action_clear_filter(self) -> None:
        """Show every log entry again."""
        self.query_one("#log-filter", Input).value = ""
        self.apply_filter("")

    def apply_filter(self, typed: str) -> bool:
        """Filter the alarm log by ``typed`` (number range and/or text); False if not understood."""
        try:
            self.log_filter = parse_filter(typed)
        except ValueError as exc:
            self.show_hint(str(exc))
            return False
        self.log_first = 0
        self.selected_row = 0
        self._log_seq = -1
        self._refresh_view()
        return True

    def on_input_submitted(self, message: Input.Submitted) -> None:
        """Enter in the filter field applies it and gives the focus back."""
        if message.input.id == "log-filter":
            if self.apply_filter(message.value):
                self.set_focus(None)

    def action_page_log(self, direction: int) -> None:
        """Older ▼ / Newer ▲: scroll the alarm log by a page."""
        total = len(log_rows(self._history(), self.log_filter))
        self.log_first = max(0, min(self.log_first + int(direction) * LOG_PAGE, max(total - LOG_PAGE, 0)))
        self.selected_row = self.log_first
        self._log_seq = -1
        self._refresh_view()

    def action_export_log(self, kind: str) -> None:
        """Write the (filtered) alarm log as ``alarm_log.csv`` or ``alarm_log.txt``."""
        rows = log_rows(self._history(), self.log_filter)
        name = "alarm_log.csv" if kind == "csv" else "alarm_log.txt"
        path = Path(self.export_dir) / name
        times = self.hmi.bridge.alarm_times
        data = (log_as_csv(rows, times) if kind == "csv" else log_as_text(rows, times)).encode("utf-8")

        def write(replace: bool) -> Path:
            write_export(path, data, replace=replace)
            return path

        self._export(write, _("Alarm log written to {path}") + " " + counted(len(rows), N_("({count} entry)"), N_("({count} entries)")),
                     _("Export failed"))

    def _export(self, write: Callable[[bool], Path], done: str, failed: str) -> None:
        """Run an export; when its file exists, ask before replacing it (links are refused)."""
        def attempt(replace: bool) -> None:
            try:
                path = write(replace)
            except ExportTargetExists as exc:
                question = _("{name} already exists in {folder}. Replace it?").format(
                    name=Path(exc.filename).name, folder=Path(exc.filename).parent)
                self.app.push_screen(ConfirmDialog(question), lambda yes: attempt(True) if yes else None)
                return
            except OSError as exc:
                self.say(f"{failed}: {error_text(exc)}")
                return
            self.say(done.format(path=path))  # kept when the area comes back from the question

        attempt(False)

    def action_trace_slot(self) -> None:
        """Edit the next signal slot."""
        if self.trace is not None:
            self.trace.next_slot()
            self._refresh_view()

    def action_trace_signal(self) -> None:
        """The next signal for the slot being edited."""
        if self.trace is not None:
            self.trace.next_signal()
            self._refresh_view()

    def action_trace_trigger(self) -> None:
        """Start now ↔ on NC START."""
        if self.trace is not None:
            self.trace.toggle_trigger()
            self._refresh_view()

    def action_trace_duration(self) -> None:
        """The next recording duration."""
        if self.trace is not None:
            self.trace.next_duration()
            self._refresh_view()

    def action_trace_start(self) -> None:
        """Start the trace (armed for NC START or recording now), or stop a running one."""
        if self.trace is None:
            return
        if self.trace.running:
            self.trace.stop()
        elif not self.trace.chosen:
            self.show_hint(_("Trace: choose at least one signal"))
            return
        elif not self.hmi.bridge.traceable:
            self.show_hint(_("Trace: this kernel cannot be traced"))
            return
        else:
            try:
                self.trace.start(self.hmi.bridge.attach_trace)
            except TraceError as exc:
                self.show_hint(_("Trace: {reason}").format(reason=error_text(exc)))
                return
            self.query_one(TracePlot).cursor = 0
        self._refresh_view()

    def action_trace_export(self) -> None:
        """Write the recorded samples as ``trace.csv``."""
        if self.trace is None:
            return
        if not (self.trace.recorder is not None and self.trace.recorder.sample_count):
            self.show_hint(_("Trace export: nothing recorded yet"))
            return
        trace = self.trace
        self._export(lambda replace: trace.export(Path(self.export_dir), replace), _("Trace written to {path}"),
                     _("Trace export"))

    def action_arrow(self, direction: int) -> None:
        """Left/Right in the trace view: move the cursor by a hundredth of the recording."""
        if self.view == "trace":
            plot = self.query_one(TracePlot)
            plot.move_cursor(int(direction) * max(1, len(plot.times) // 100))

    def action_page(self, direction: int) -> None:
        """Page Down/Up in the alarm log: older/newer entries."""
        if self.view == "log":
            self.action_page_log(direction)

    def action_trace_cursor(self, direction: int) -> None:
        """Move the cursor by a fiftieth of the recording."""
        plot = self.query_one(TracePlot)
        plot.move_cursor(int(direction) * max(1, len(plot.times) // 50))

    # -- display ---------------------------------------------------------------------------------
    def update_status(self, status: NckStatus) -> None:
        """Refresh the view on display."""
        self._refresh_view()

    def _show_view(self) -> None:
        if not self.is_mounted:
            return
        self.query_one("#diag-views", ContentSwitcher).current = f"view-{self.view}"
        self.set_focus(None)
        self._log_seq = -1
        self._utilisation_cycle = None
        self._refresh_view()
        self.refresh_softkeys()

    def _refresh_view(self) -> None:
        if not self.is_mounted:
            return
        status = self.status
        show_text(self.query_one("#diag-title", Static), Text(f" {_(TITLES[self.view])}", style="bold"))
        if status is None:
            return
        handler = getattr(self, f"_render_{self.view}")
        handler(status)

    def _render_exercises(self, status: NckStatus) -> None:
        if not self.exercises:
            try:
                self.exercises = self.hmi.exercise_list()
            except queries.ExerciseError as exc:
                self.say(_("Exercises cannot be read: {error}").format(error=exc))
        running = self._running_exercise if self.hmi.exercise_side else None
        show_text(self._body("exercises"), exercises_text(self.exercises, self.exercise_index, running))

    def _body(self, view: str) -> Static:
        return self.query_one(f"#diag-{view}", Static)

    def _render_alarms(self, status: NckStatus) -> None:
        rows = len(status.alarms)
        self.selected_row = min(self.selected_row, max(rows - 1, 0))
        show_text(self._body("alarms"), alarm_list_text(status.alarms, self.hmi.bridge.alarm_times,
                                                        self.selected_row if rows else None))

    def _render_messages(self, status: NckStatus) -> None:
        events = self.ask(queries.AlarmLogSince(0))
        times = self.hmi.bridge.alarm_times
        lines = message_lines(status.channel.message, events, status.alarms, times)
        show_text(self._body("messages"), messages_text(lines, events, times))

    def _render_log(self, status: NckStatus) -> None:
        if status.alarm_log_seq == self._log_seq:
            return
        self._log_seq = status.alarm_log_seq
        history = self._history()
        rows = log_rows(history, self.log_filter)
        total = len([e for e in history if e.category != "message"])
        self.selected_row = min(self.selected_row, max(len(rows) - 1, 0))
        show_text(self._body("log"), log_text(rows, self.log_filter, total, self.hmi.bridge.alarm_times,
                                              self.log_first, LOG_PAGE, self.selected_row if rows else None))

    def _selected_axis(self, status: NckStatus) -> Any:
        self.axis_index %= max(len(status.axes), 1)
        return status.axes[self.axis_index] if status.axes else None

    def _render_overview(self, status: NckStatus) -> None:
        show_text(self._body("overview"), overview_text(status))

    def _render_axis(self, status: NckStatus) -> None:
        axis = self._selected_axis(status)
        if axis is not None:
            title = (_("Spindle {name}  ({number} of {count}, Axis +/− to change)") if axis.kind == "spindle"
                     else _("Axis {name}  ({number} of {count}, Axis +/− to change)"))
            show_text(self._body("axis"), rows_text(
                title.format(name=axis.name, number=self.axis_index + 1, count=len(status.axes)),
                axis_rows(status, axis)))

    def _render_drive(self, status: NckStatus) -> None:
        axis = self._selected_axis(status)
        if axis is not None:
            show_text(self._body("drive"), rows_text(
                _("Drive of {name}  ({number} of {count}, Axis +/− to change)").format(
                    name=axis.name, number=self.axis_index + 1, count=len(status.axes)),
                drive_rows(status, axis)))

    def _render_utilisation(self, status: NckStatus) -> None:
        counters = self.ask(queries.Counters())
        ipo = counters.ipo_cycle_s or 0.004
        shown = self._utilisation_cycle
        if shown is not None and 0 <= counters.cycles_done - shown < UTILISATION_REFRESH_S / ipo:
            return  # a new kernel (Reset (po)) counts from 0 again: drawn at once
        self._utilisation_cycle = counters.cycles_done
        rows = utilisation_rows(self.hmi.bridge.utilisation, ipo, self.ask(queries.BufferFill()),
                                counters.cycles_done, counters.blocks_interpreted)
        show_text(self._body("utilisation"), rows_text(
            _("Measured on this computer (wall-clock time spent per simulated IPO cycle)"), rows))

    def _render_trace(self, status: NckStatus) -> None:
        machine = self.ask(queries.ReadData()).machine
        if machine is not None and (self.trace is None or self.trace.machine is not machine) and not (
                self.trace is not None and self.trace.running):
            self.trace = TraceSession(machine)  # a new kernel (Reset (po)) may have other axes
        if self.trace is None:
            return
        show_text(self.query_one("#trace-settings", Static), self.trace.settings_text())
        plot = self.query_one(TracePlot)
        recorder = self.trace.recorder
        if recorder is None:
            plot.set_data([], [], [], [])
            return
        same_signals = plot.names == list(recorder.settings.signals)
        if same_signals and len(plot.times) == recorder.sample_count:
            return
        grown = recorder.sample_count - len(plot.times)
        if same_signals and recorder.state == "recording" and 0 < grown < max(25, len(plot.times) // 200):
            return  # while recording, redraw the curves in steps (the refresh budget)

        names = list(recorder.settings.signals)
        plot.set_data(recorder.times_s, names, [signal_unit(n) for n in names],
                      [recorder.columns[n] for n in names])

    def _render_version(self, status: NckStatus) -> None:
        machine = self.ask(queries.ReadData()).machine
        rows = [
            (N_("Product"), _("SINUMERIK Operate trainer (828D / 840D sl behaviour)"), ""),
            (N_("NCK kernel version"), str(getattr(nck_package, "__version__", "?")), ""),
            (N_("Machine"), status.machine_name or "—", ""),
        ]
        if machine is not None:
            axes = ", ".join(f"{a.name} ({_(AXIS_KINDS.get(a.kind, a.kind))})" for a in machine.axes)
            rows.append((N_("Axes"), axes, ""))
            rows.append((N_("IPO cycle"), f"{self.ask(queries.Counters()).ipo_cycle_s * 1000:.1f}", "ms"))
            rows.append((N_("Block buffer (MD28060)"), str(machine.md_value("MD28060", None, "—")), N_("blocks")))
        text = Text(no_wrap=True, end="")
        text.append(f" {_('Component'):<28}{_('Version / configuration')}\n", style="bold")
        for name, value, unit in rows:
            text.append(f" {_(name):<28}{value} {_(unit)}\n")
        show_text(self._body("version"), text)

    LOGBOOK_KINDS = (N_("access"), N_("data"))
    """The logbook's kinds of change (``nck.status.LogbookEntry.kind``), said in the panel's language."""

    def _render_logbook(self, status: NckStatus) -> None:
        entries = list(self.ask(queries.Logbook()))
        text = Text(no_wrap=True, end="")
        text.append(" " + _("Current access level: {level}").format(level=status.access_level) + "\n", style="bold")
        text.append(f" {_('Date / time'):<20} {_('Kind'):<8} {_('Change')}\n", style="bold")
        if not entries:
            text.append(" " + _("No access-level or machine-data changes since power on."), style="dim")
        times = self.hmi.bridge.alarm_times
        first = max(len(entries) - 40, 0)
        for index in reversed(range(first, len(entries))):
            entry = entries[index]
            stamp = date_time_text(times.logbook_at(index))
            text.append(f" {stamp:<20} {_(entry.kind):<8} {reason_text(entry.text)}\n")
        show_text(self._body("logbook"), text)


AreaScreen = DiagnosticsScreen
