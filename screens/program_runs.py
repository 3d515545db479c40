"""Live checks and the toolpath simulation of the program editor.

A mixin of :class:`screens.program.ProgramScreen`. Both work on a copy of the
text off the key path, each in a child process (:mod:`hmi.child_job`: the
screen does not share the interpreter lock with them) waited for by a worker
thread: the check streams its alarms back in batches (each faulty line gets its
mark as soon as it is known; a newer check stops an older one); the simulation
runs the program once as AUTO runs it (``CheckContext.simulate``) and both views
draw that one run: the material view the blank it cut, the toolpath view its
executed path.

Both run on the session's machine and a copy of its NC data (tools, work offsets,
R parameters, setting data): :meth:`CheckAndSimulation.check_setting` asks the
bridge for them (query ``CheckSetting``) in the UI thread, before the worker
starts; the answer's ``iter_check`` and ``simulate`` are what the workers call.
"""

from __future__ import annotations

import math
import pickle
import threading
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

from textual import work
from textual.timer import Timer
from textual.worker import Worker, WorkerState, get_current_worker

from nck import ProgramLanguage, alarm_text_in, program_language
from nck.queries import CheckSetting, Scrubber

from hmi.child_job import ChildJob
from hmi.durations import short_clock
from hmi.focus import focus_now
from hmi.i18n import N_, _, counted, language
from hmi.softkeys import Softkey, SoftkeyMenu
from hmi.simulation_softkeys import overlay_key, view_keys
from hmi.widgets.nc_editor import ErrorMark
from hmi.widgets.stock_view import StockPicture, material_events, picture_of
from hmi.widgets.toolpath import PieceArrays

CHECK_DEBOUNCE_S = 0.4
"""Quiet time after the last keystroke before the check starts."""

STREAM_BATCH = 50
"""Check results are handed to the screen in batches of this many alarms."""

SPEEDS_BLOCKS_S = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, math.inf)
"""The simulation's playing speeds (Speed - / Speed +), blocks per second; inf: at once."""
DEFAULT_SPEED = 3
PLAY_TICK_S = 0.1
"""Playing shows the blocks due every this many seconds."""
PROGRESS_EVERY_S = 0.5
"""A simulation still calculating says how many blocks it has run, this often."""
WORKER_DESCRIPTION = "editor"
"""Given to every worker of the editor: without one, Textual describes a worker by the repr() of
its arguments — the whole program text, the NC data, a simulation with its 100,000s of chords —
in the UI thread at every start (measured: ~100 ms per scrub step of a 20,000-block program)."""


def speed_text(blocks_s: float) -> str:
    """A playing speed in the panel's words."""
    return _("at once") if blocks_s == math.inf else _("{rate} blocks/s").format(rate=f"{blocks_s:g}")


def path_of(simulation: Any) -> PieceArrays:
    """The simulation's executed path as the toolpath view's straight pieces, its own arrays (no
    copy): the WCS, on a lathe the half section the material view draws (Z, 0, radius)."""
    starts, ends = simulation.drawn_path()
    return PieceArrays(starts, ends, simulation.path.rapid, simulation.path.lines)


def _first_alarm(simulation: Any) -> str:
    """The run's first alarm, number and text, in the panel's language."""
    alarm = simulation.alarms[0]
    return f"{alarm.number} {alarm_text_in(language(), alarm.number, alarm.params)}"


def called_place(program: str, line: int | None) -> str:
    """Where in a called cycle or subprogram an alarm came (said after the call's line)."""
    return _("(in {program}, line {line})").format(program=program, line=line)


def alarm_line(simulation: Any) -> str:
    """The program's line the run's first alarm belongs to; for an alarm in a cycle or
    subprogram the line of the call and where in the called program it came."""
    alarm = simulation.alarms[0]
    place = simulation.alarm_places[0] if simulation.alarm_places else None
    if place is None or place.called_file is None:
        return str(alarm.line)
    return f"{place.line} {called_place(place.called_file, place.called_line)}"


def path_note(simulation: Any) -> str:
    """The toolpath view's note: where the run stopped, else its blocks and pieces."""
    if simulation.alarms:
        return _("stopped at line {line}: {alarm}").format(line=alarm_line(simulation),
                                                           alarm=_first_alarm(simulation))
    if simulation.status == "timeout":
        return _("stopped after {blocks} blocks").format(blocks=simulation.blocks)
    return (counted(simulation.blocks, N_("{count} block"), N_("{count} blocks")) + ", "
            + counted(len(simulation.path.starts), N_("{count} move"), N_("{count} moves")))


def material_note(simulation: Any) -> str:
    """One line: how the run ended (its alarm), the events, the machining time."""
    parts = [_("time {time}").format(time=short_clock(simulation.machine_time_s))]
    if simulation.alarms:
        alarm = simulation.alarms[0]
        parts.append(_("alarm {number} at line {line}").format(number=alarm.number, line=alarm_line(simulation)))
    if simulation.events:
        parts.append(material_events(simulation))
    if not simulation.alarms and not simulation.events:
        parts.append(_("no alarms"))
    return ", ".join(parts)


class CheckAndSimulation:
    """Checks as you type, next error, and the simulation view (mixin)."""

    program: str | None
    binary: bool
    simulating: bool
    _generation: int
    _marks_generation: int
    _check_running: bool
    _checked_setting: bytes
    _language: ProgramLanguage | None
    _check_timer: Timer | None
    editor: Any
    toolpath: Any
    stock: Any
    sim_material: bool
    _material: Any = None
    _material_blocks: list[tuple[int, int]] = []
    _material_step: int = 0
    _scrubber: Scrubber | None = None
    _scrub_lock: threading.Lock = threading.Lock()
    _shown_note: str = ""
    _step_pending: bool = False
    _step_line: int | None = None  # the line the step on its way marks (None: the cursor moved since)
    _step_moves_cursor: bool = True
    _play_timer: Timer | None = None
    _play_until: int | None = None
    _play_due: float = 0.0
    _speed: int = DEFAULT_SPEED
    files: Any
    status: Any
    app: Any
    ask: Any

    def _simulation_menu(self) -> SoftkeyMenu:
        return SoftkeyMenu.of(
            [
                *view_keys("sim", lambda s: s.toolpath.view, lambda s: s.on_lathe),
                Softkey("sim.rerun", "Recalculate", "simulate_run"),
                Softkey("sim.back", "Editor", "simulate"),
            ],
            [
                Softkey("sim.play", "Start /\nStop", "sim_play", active=lambda s: s.sim_playing),
                Softkey("sim.to_cursor", "Run to\ncursor", "sim_run_to_cursor"),
                Softkey("sim.material", "Material", "sim_material", active=lambda s: s.sim_material),
                Softkey("sim.slower", "Speed -", "sim_speed(-1)"),
                Softkey("sim.faster", "Speed +", "sim_speed(1)"),
                Softkey("sim.step_back", "Block ◀", "sim_step(-1)"),
                Softkey("sim.step_forward", "Block ▶", "sim_step(1)"),
                overlay_key("sim", lambda s: s.stock.overlay),
            ],
        )

    def check_setting(self) -> Any:
        """The session's machine and a copy of its NC data for one check or simulation
        (``nck.check.CheckContext``: ``iter_check``, ``simulate``); ask in the UI thread."""
        return self.ask(CheckSetting())

    # -- checks ---------------------------------------------------------------------------------
    def schedule_check(self) -> None:
        """Run the check after a short quiet time (debounce)."""
        if self._check_timer is not None:
            self._check_timer.stop()
        self._check_timer = self.set_timer(CHECK_DEBOUNCE_S, self.check_now)

    def action_check_now(self) -> None:
        """Check now softkey."""
        self.check_now()

    def check_now(self) -> None:
        """Start a check of the current text in a worker thread (older checks are abandoned)."""
        if self._check_timer is not None:
            self._check_timer.stop()
            self._check_timer = None
        if self.program is None or self.binary:
            return
        self._generation += 1
        self._check_running = True
        self._show_cursor_message()
        setting = self.check_setting()
        self._checked_setting = pickle.dumps(setting)
        self._language = program_language(self.editor.text, setting.machine)
        self._check_worker(self._generation, self.program, self.editor.text,
                           self.files.program_source(self.program), setting)

    def check_again_if_the_setting_changed(self) -> None:
        """Check the open program again when the machine or NC data it was checked on changed
        meanwhile (a tool edge added in the Parameter area, machine data made active by
        Reset (po)): its marks would say what the old data said."""
        if self.program is None or self.binary or not self._checked_setting:
            return
        if pickle.dumps(self.check_setting()) != self._checked_setting:
            self.check_now()

    @work(thread=True, exclusive=True, group="program-check", exit_on_error=False, description=WORKER_DESCRIPTION)
    def _check_worker(self, generation: int, program: str, text: str, programs: Any, setting: Any) -> None:
        """The check of ``text``, off the key path: in a child process (:class:`hmi.child_job.ChildJob`)
        that sends the faulty lines' marks in batches; a newer check stops it at once."""
        worker = get_current_worker()
        name = Path(program).name
        panel_language = language()

        def check(send: Any) -> list[ErrorMark]:
            batch: list[ErrorMark] = []
            # What the program does wrong comes as alarms; an exception here is a bug of the check
            # (on_worker_state_changed reports it).
            for alarm in setting.iter_check(name, text, programs=programs):
                said = alarm_text_in(panel_language, alarm.number, alarm.text_params, alarm.text)
                if alarm.called_file is not None:  # marked on the call: say where it came
                    said += "  " + called_place(alarm.called_file, alarm.called_line)
                batch.append(ErrorMark((alarm.line or 1) - 1, alarm.number, said))
                if len(batch) >= STREAM_BATCH:
                    send(batch)
                    batch = []
            return batch

        def stale() -> bool:
            return worker.is_cancelled or generation != self._generation

        job = ChildJob(check)
        for batch in job.messages(stale):
            self.app.call_from_thread(self._apply_marks, generation, batch, False)
        if not stale():
            self.app.call_from_thread(self._apply_marks, generation, job.result, True)

    def on_worker_state_changed(self, event: Worker.StateChanged) -> None:
        """A check or simulation that raised is a bug, not a problem of the program (those are
        alarms and simulation events): the app's internal-error report keeps its traceback (and
        fails a test run); the editor carries on without the check's marks or the picture."""
        if event.state != WorkerState.ERROR or event.worker.group not in ("program-check",
                                                                          "program-material"):
            return
        if event.worker.group == "program-check":
            self._check_running = False
            self._show_cursor_message()
        else:
            self.stock.set_picture(StockPicture(), _("simulation not possible"))
            self.toolpath.set_pieces([], _("simulation not possible"))
        error = event.worker.error
        report = getattr(self.app, "report_internal_error", None)
        if report is None or not isinstance(error, Exception):
            raise error  # type: ignore[misc]
        report(error)

    def _apply_marks(self, generation: int, marks: list[ErrorMark], done: bool) -> None:
        if generation != self._generation or not self._ready:
            return
        first = self._marks_generation != generation
        self._marks_generation = generation
        self.editor.set_error_marks(marks, replace=first)
        if done:
            self._check_running = False
        self._show_cursor_message()

    def action_next_error(self) -> None:
        """Next error softkey: put the cursor on the next faulty line."""
        line = self.editor.next_error_line()
        if line is None:
            self.say(_("No errors found"))
            return
        self.editor.move_cursor((line, 0), center=True)
        focus_now(self.editor)
        self._show_cursor_message()

    # -- simulation ----------------------------------------------------------------------------
    def action_simulate(self) -> None:
        """Simulation softkey: show the toolpath (again: back to the editor)."""
        self.simulating = not self.simulating
        self._menu_stack.clear()
        self._show_view()
        self.refresh_softkeys()
        if self.simulating:
            self._mark_current_block(self.status)
            self.action_simulate_run()
            focus_now(self.stock if self.sim_material else self.toolpath)
        else:
            self.leave_simulation()
            focus_now(self.editor)

    def leave_simulation(self) -> None:
        """Back to the editor's text: playing stops, a run still going is dropped (its child is
        stopped) and the result shown is forgotten — the next Simulation runs the text again."""
        self.simulating = False
        self._stop_playing()
        self.workers.cancel_group(self, "program-material")
        self._material = None
        self._scrubber = None

    def action_simulate_run(self) -> None:
        """Interpret the text headless and draw its toolpath."""
        if self.program is None:
            return
        self._stop_playing()
        self.toolpath.set_pieces([], _("calculating …"))
        self.stock.set_picture(StockPicture(), _("calculating …"))
        self._material = None
        self._scrubber = None
        self.stock.highlight_line = self.editor.cursor_location[0] + 1
        setting = self.check_setting()
        programs = self.files.program_source(self.program)
        self._material_worker(self.program, self.editor.text, programs, setting)

    @work(thread=True, exclusive=True, group="program-material", exit_on_error=False,
          description=WORKER_DESCRIPTION)
    def _material_worker(self, program: str, text: str, programs: Any, setting: Any) -> None:
        """The AUTO run and the material removal, off the key path: in a child process
        (:class:`hmi.child_job.ChildJob`; this thread only waits for it and shows its progress).
        A newer run (Recalculate, another program, back to the editor) cancels this one: the
        child is stopped at once."""
        worker = get_current_worker()
        name = Path(program).name

        def simulate(send: Any) -> Any:
            shown_at = time.monotonic()

            def give_up(blocks: int) -> bool:
                nonlocal shown_at
                if time.monotonic() - shown_at >= PROGRESS_EVERY_S:
                    shown_at = time.monotonic()
                    send(blocks)
                return False

            # What the program does wrong comes as alarms and events of the simulation; an
            # exception here is a bug (ChildJobFailed: on_worker_state_changed reports it).
            return setting.simulate(name, text, programs=programs, give_up=give_up)

        job = ChildJob(simulate)
        for blocks in job.messages(lambda: worker.is_cancelled):
            self.app.call_from_thread(self._show_progress, worker, blocks)
        if not worker.is_cancelled:
            self.app.call_from_thread(self._show_material, job.result)

    def _show_progress(self, worker: Worker[Any], blocks: int) -> None:
        """How far a long simulation has come (its worker is still the current one)."""
        if worker.is_cancelled or self._material is not None:
            return
        note = _("calculating … {blocks} blocks").format(blocks=blocks)
        self.toolpath.set_pieces([], note)
        self.stock.set_picture(StockPicture(), note)

    def _show_material(self, simulation: Any) -> None:
        """A finished simulation: show the whole program cut, the note says how it ended; the
        toolpath view (Material off) draws the same run's path; the cursor's block is marked."""
        self._material = simulation
        self._scrubber = Scrubber(simulation)
        self._scrub_lock = threading.Lock()
        self.toolpath.set_path(path_of(simulation), path_note(simulation), turning=simulation.turning)
        self._material_blocks = simulation.blocks_in_order()
        self._material_step = len(self._material_blocks) - 1
        self._shown_note = material_note(simulation)
        self.stock.set_picture(picture_of(simulation, simulation.zmap, len(simulation.path.starts)),
                               self._shown_note)
        self.mark_cursor_block(ready_step_back=True)

    def mark_cursor_block(self, *, ready_step_back: bool = False) -> None:
        """The editor's cursor line in the simulation: its path highlighted in both views and, in
        the material view, the material its block removed (``ready_step_back``: then the blank is
        cut up to where Block ◀ will need it, see :meth:`_scrub_worker`)."""
        if not self.simulating:
            return
        line = self.editor.cursor_location[0] + 1
        self.stock.highlight_line = line
        self._step_line = None  # a step on its way no longer moves the cursor: the operator did
        self._mark_current_block(self.status)
        if self._material is not None:
            self._scrub_worker(self._material, None, self._material_step, line,
                               self._step_back_start() if ready_step_back else None)

    def action_sim_step(self, direction: int) -> None:
        """Block ◀ / Block ▶: show the blank as cut up to the block before / after; the editor
        cursor follows the block shown."""
        self._stop_playing()
        self._show_block(self._material_step + direction, ready_step_back=direction < 0)

    def _step_back_start(self) -> int:
        """Where the block before the one shown starts (chords): Block ◀ cuts the blank there first."""
        step = self._material_step
        return self._material_blocks[step - 2][1] if step >= 2 else 0

    def _show_block(self, step: int, move_cursor: bool = True, ready_step_back: bool = False) -> None:
        """Show the blank as cut up to block ``step`` (index into the executed blocks); its line
        is marked and the editor cursor goes there together with the new picture
        (:meth:`_show_step`: the key repaints the screen once, not once for the cursor and once
        more for the picture)."""
        if self._material is None or not self._material_blocks:
            return
        step = min(max(step, 0), len(self._material_blocks) - 1)
        self._material_step = step
        line, chords = self._material_blocks[step]
        self._step_pending = True
        self._step_line, self._step_moves_cursor = line, move_cursor
        self._scrub_worker(self._material, chords, step, line, self._step_back_start() if ready_step_back else None)

    @work(thread=True, exclusive=True, group="program-material-step", exit_on_error=False,
          description=WORKER_DESCRIPTION)
    def _scrub_worker(self, simulation: Any, chords: int | None, step: int, line: int,
                      ready_at: int | None = None) -> None:
        """The blank after ``chords`` chords (None: the picture shown stays) and the cut of the
        block of source ``line``, off the key path. Then, with ``ready_at``, the blank is cut up
        to that many chords while the operator looks at the picture: the next Block ◀ starts
        there instead of re-cutting from the simulation's last copy below it (at the end of a
        200,000-block plate, up to a few thousand chords)."""
        worker = get_current_worker()

        def current() -> bool:
            return not worker.is_cancelled and self._scrubber is not None and self._scrubber.simulation is simulation

        with self._scrub_lock:
            if not current():
                return
            cut = self._scrubber.block_cut(line)
            model = self._scrubber.goto(chords) if chords is not None else None
            picture = picture_of(simulation, model, chords) if model is not None and chords is not None else None
        if worker.is_cancelled:
            return
        self.app.call_from_thread(self._show_step, simulation, picture, cut, step, line)
        if ready_at is not None:
            with self._scrub_lock:
                if current():
                    self._scrubber.goto(ready_at)

    def _show_step(self, simulation: Any, picture: StockPicture | None, cut: Any, step: int, line: int) -> None:
        if simulation is not self._material or step != self._material_step:
            return  # a newer step or simulation is on its way
        if picture is not None:
            self._step_pending = False
            chords = picture.shown_chords
            shown_line = self._material_blocks[step][0]
            self._shown_note = _("block {number}/{count}, line {line}: {modal}").format(
                number=step + 1, count=len(self._material_blocks), line=shown_line, modal=simulation.modal_at(chords))
            if self._step_line == line:
                self.stock.highlight_line = line
                if self._step_moves_cursor:
                    self.editor.move_cursor((max(line - 1, 0), 0), center=True)
        else:
            picture = self.stock.picture
        if self.stock.highlight_line != line:
            cut = None  # the cursor moved on meanwhile: its own cut is on its way
        picture = replace(picture, cut_top=cut.top if cut is not None else None,
                          cut_bottom=cut.bottom if cut is not None else None)
        self.stock.set_picture(picture, self._play_note())

    # -- playing -------------------------------------------------------------------------------
    def _play_note(self) -> str:
        """The note under the picture, with the playing speed while playing."""
        if self._play_timer is None:
            return self._shown_note
        return f"▶ {speed_text(SPEEDS_BLOCKS_S[self._speed])}  {self._shown_note}"

    @property
    def sim_playing(self) -> bool:
        """True while the simulation plays block by block."""
        return self._play_timer is not None

    def action_sim_play(self) -> None:
        """Start / Stop: play the blocks one after another at the chosen speed (from the first
        block again when the last one is shown)."""
        if self._play_timer is not None:
            self._stop_playing()
        elif self._material_blocks:
            if self._material_step >= len(self._material_blocks) - 1:
                self._show_block(0)
            self._play_until = None
            self._start_playing()

    def action_sim_run_to_cursor(self) -> None:
        """Run to cursor: play up to the next run of the cursor's block (after the last one: its
        first run); at the top speed the view goes there at once."""
        if self._material is None or not self._material_blocks:
            return
        line = self.editor.cursor_location[0] + 1
        steps = [i for i, (block_line, _chords) in enumerate(self._material_blocks) if block_line == line]
        if not steps:
            self.say(_("Line {line} was not executed").format(line=line))
            return
        later = [i for i in steps if i > self._material_step]
        target = later[0] if later else steps[0]
        if target < self._material_step or SPEEDS_BLOCKS_S[self._speed] == math.inf:
            self._stop_playing()
            self._show_block(target, move_cursor=False)
            return
        self._play_until = target
        self._start_playing()

    def action_sim_speed(self, direction: int) -> None:
        """Speed - / Speed +: blocks per second while playing."""
        self._speed = min(max(self._speed + direction, 0), len(SPEEDS_BLOCKS_S) - 1)
        self.say(_("Simulation speed: {speed}").format(speed=speed_text(SPEEDS_BLOCKS_S[self._speed])))
        if self._play_timer is not None:
            self.stock.status_text = self._play_note()

    def _start_playing(self) -> None:
        self._play_due = 0.0
        if self._play_timer is None:
            self._play_timer = self.set_interval(PLAY_TICK_S, lambda: self.sim_tick(PLAY_TICK_S))
        self.stock.status_text = self._play_note()
        self.refresh_softkeys()

    def _stop_playing(self) -> None:
        if self._play_timer is not None:
            self._play_timer.stop()
            self._play_timer = None
            self.stock.status_text = self._shown_note
            self.refresh_softkeys()

    def sim_tick(self, elapsed_s: float) -> None:
        """Playing on by ``elapsed_s`` seconds: the blocks due at the speed are shown."""
        if self._play_timer is None or self._step_pending:
            return  # the last step is still being cut: no steps pile up
        last = len(self._material_blocks) - 1 if self._play_until is None else self._play_until
        speed = SPEEDS_BLOCKS_S[self._speed]
        self._play_due += elapsed_s * speed if speed != math.inf else last + 1
        whole = int(self._play_due)
        if whole < 1:
            return
        self._play_due -= whole
        step = min(self._material_step + whole, last)
        self._show_block(step, move_cursor=self._play_until is None)
        if step >= last:
            self._stop_playing()

    def action_sim_overlay(self) -> None:
        """Path on/off: the toolpath over the material."""
        self.stock.action_overlay()
        self.refresh_softkeys()

    def action_sim_material(self) -> None:
        """Material: the blank being cut (on) or the toolpath alone (off)."""
        self.sim_material = not self.sim_material
        self._show_view()
        focus_now(self.stock if self.sim_material else self.toolpath)
        self.refresh_softkeys()

    def action_sim_view(self, view: str) -> None:
        """Choose the projection (top view or a section)."""
        self.toolpath.action_view(view)
        self.stock.action_view(view)
        self.refresh_softkeys()

    def action_sim_zoom(self, direction: int) -> None:
        """Zoom in/out."""
        self.toolpath.action_zoom(direction)
        self.stock.action_zoom(direction)

    def action_sim_pan(self, dh: int, dv: int) -> None:
        """Pan the view."""
        self.toolpath.action_pan(dh, dv)
        self.stock.action_pan(dh, dv)

    def action_sim_fit(self) -> None:
        """Fit the whole path."""
        self.toolpath.action_fit()
        self.stock.action_fit()
