"""One guided exercise being done on the panel (issue 26).

Starting an exercise writes its set-up into a private data directory (a new temporary
folder), opens a session and kernel on it and hands the kernel to the bridge; the
trainee's own session and kernel are put aside untouched and come back when the
exercise ends. While it runs, :class:`ExerciseRun` feeds the exercise's
:class:`nck.queries.ExerciseProgress` with every snapshot, command and key, and gives
the side window its text. The end writes the scored report as text and JSON (with the
recording of the session) into the report folder and removes the private directory.
"""

from __future__ import annotations

import shutil
import tempfile
import weakref
from datetime import datetime
from pathlib import Path
from typing import Any

from nck import StorageError, queries
from nck.status import NckStatus

from hmi.i18n import N_, _, counted, error_text, exercise_text, reason_text, step_text
from hmi.program_files import ProgramFiles
from hmi.startup import start_session

REPORTS_FOLDER = "exercise_reports"
"""The folder of a data directory the exercise reports go to (unless ``--reports-dir`` names one)."""


def served_dir_of(data_dir: str | None) -> Path:
    """The data directory ``data_dir`` (``--data-dir``, None: the user's), absolute: the one a
    browser tab's panel copies, where its reports and class packs go."""
    return (Path(data_dir).expanduser() if data_dir else queries.default_data_dir()).absolute()


def reports_dir_of(reports_dir: str | None, data_dir: str | None) -> Path:
    """Where reports go: ``reports_dir`` (``--reports-dir``), else :data:`REPORTS_FOLDER` of the
    data directory ``data_dir`` (``--data-dir``, None: the user's) — the directory itself, not a
    temporary copy of it, so that a report outlives an ``--ephemeral`` panel or a browser tab."""
    if reports_dir:
        return Path(reports_dir).expanduser().absolute()
    return served_dir_of(data_dir) / REPORTS_FOLDER


EXAM_HELP_LIMITED = N_("Exam: help is limited to the key overview (F11)")
"""Said instead of opening the command palette or an alarm's help during an exam."""
CLASS_PACK_COUNTS = (N_("{count} exercise"), N_("{count} exercises"), N_("{count} program"), N_("{count} programs"))
"""The texts of ``ClassPack.summary`` (nck.class_pack), which the panel translates through it."""


class ExerciseRun:
    """The exercise on the panel: its progress, its private session and the trainee's put aside.

    Args:
        exercise: the exercise (``nck.queries.Exercise``).
        report_dir: where the reports are written.
    """

    def __init__(self, exercise: Any, report_dir: Path) -> None:
        self.exercise = exercise
        self.report_dir = report_dir
        self.progress = queries.ExerciseProgress(exercise.steps, exercise.final_checks)
        self.private_root = Path(tempfile.mkdtemp(prefix="nck-exercise-"))
        # removed by close(); also when the run is dropped unended (an app that ended without
        # End exercise, a failed test) or at the latest when the process ends
        self._remove_private = weakref.finalize(self, shutil.rmtree, self.private_root, True)
        self.session: Any = None
        self.trainee_session: Any = None
        self.trainee_kernel: Any = None
        self.trainee_estop_pressed = False
        self.report: dict[str, Any] | None = None
        self.report_paths: tuple[Path, Path] | None = None

    def open_session(self) -> Any:
        """Write the set-up into the private directory; return the kernel built on it."""
        directory = self.private_root / "data"
        try:
            queries.prepare_data_dir(self.exercise, directory)
            self.session, kernel = start_session(self.exercise.machine, str(directory))
        except BaseException:
            self._remove_private()
            raise
        return kernel

    def start_commands(self) -> list[Any]:
        """What the set-up asks of the new kernel at once (program selection, E-stop)."""
        return queries.start_commands(self.exercise)

    # -- following the session ------------------------------------------------------------
    def observe_status(self, status: NckStatus, data: Any) -> None:
        """A snapshot (and the NC data) of the exercise's kernel."""
        self.progress.observe_status(status, data)

    def observe_command(self, command: Any, accepted: bool) -> None:
        """An operator command and whether the kernel took it."""
        self.progress.observe_command(command, accepted)

    def observe_key(self, key: str) -> None:
        """A key the trainee pressed."""
        self.progress.observe_key(key)

    def side_text(self) -> str:
        """The side window: exercise, current step, its hint (none in an exam)."""
        exercise = self.exercise
        lines = [_("EXERCISE: {title}").format(title=exercise_text(exercise, "title")), ""]
        if self.progress.finished:
            lines += [_("All steps done."), "", _("End the exercise for the report:"),
                      _("Diagnostics, More, Exercises, End exercise.")]
            return "\n".join(lines)
        index = self.progress.current
        lines += [_("Step {number} of {count}").format(number=index + 1, count=len(exercise.steps)),
                  step_text(exercise, index, "text")]
        if exercise.steps[index].hint and not exercise.exam:
            lines += ["", _("Hint: {hint}").format(hint=step_text(exercise, index, "hint"))]
        why = self.progress.results[index].why_not
        if why:
            lines += ["", _("Still open:"), *(f"- {reason_text(reason)}" for reason in why)]
        return "\n".join(lines)

    # -- the end ----------------------------------------------------------------------------
    def finish(self, time_s: float) -> tuple[Path, Path]:
        """End the session at control time ``time_s``, score it, write the report files; return
        their paths (text, JSON)."""
        self.progress.observe_end(time_s)
        self.report = self.progress.report(self.exercise.title)
        name = f"{self.exercise.exercise_id}-{datetime.now():%Y%m%d-%H%M%S}"
        self.report_paths = queries.save_report(self.report_dir, name, self.report, self.progress.events,
                                                self.exercise.exercise_id, self.report_in_panel_language())
        return self.report_paths

    def report_in_panel_language(self) -> str:
        """The text of the report (:attr:`report`) in the panel's language: title, steps and
        every sentence translated (the JSON file keeps the English)."""
        exercise, report = self.exercise, self.report or {}
        shown = dict(report, title=exercise_text(exercise, "title"),
                     steps=[dict(step, text=step_text(exercise, index, "text"))
                            for index, step in enumerate(report.get("steps", []))])
        return queries.report_text(shown, reason_text)

    def close(self) -> None:
        """Give the private data directory free and remove it."""
        try:
            if self.session is not None:
                self.session.quit()
        finally:
            self._remove_private()


class ClassroomHost:
    """The app's part of the classroom (mixed into ``hmi.app.HmiApp``): start and end an
    exercise, feed it what happens on the panel, keep the side window's text.

    The app calls :meth:`exercise_key`, :meth:`exercise_command` and
    :meth:`exercise_snapshot` from its key, command and snapshot paths.
    """

    bridge: Any
    nc_session: Any
    estop_pressed: bool  # the machine control panel's E-stop button (hmi.mcp)
    exercise_run: ExerciseRun | None = None
    exercise_side: str = ""
    """The side window's text ("" while no exercise runs)."""
    exercise_report_dir: Path | None = None
    """Where reports go (None: ``exercise_reports`` in the trainee's data directory, else a temporary folder)."""
    class_pack_dir: Path | None = None
    """The data directory whose class packs the panel lists and imports into (``--class-dir``:
    a browser tab's the one served, not its copy); None: the trainee's own."""

    @property
    def exam_running(self) -> bool:
        """An exam runs: no hints, the access level fixed (the set-up locks it in the kernel's
        retained access state), help limited to the key overview."""
        return self.exercise_run is not None and bool(self.exercise_run.exercise.exam)

    def start_exercise(self, exercise: Any) -> str:
        """Load ``exercise``'s set-up into a private data directory and run the panel on it.

        Returns what to say on the dialog line. The trainee's session and kernel are put
        aside unchanged (saved first) until :meth:`end_exercise`.
        """
        if self.exercise_run is not None:
            return _("Exercise '{title}' is still running: end it first").format(
                title=exercise_text(self.exercise_run.exercise, "title"))
        if exercise.waits_for:
            return _("This exercise waits for {what}").format(what=exercise_text(exercise, "waits_for"))
        unsaved = self._unsaved_work()
        if unsaved:
            return _("Not started: {unsaved} (save or close it first)").format(unsaved=unsaved)
        try:
            run = ExerciseRun(exercise, self._report_dir())  # makes its private data folder
            kernel = run.open_session()
        except (queries.ExerciseError, StorageError, OSError) as exc:  # a broken exercise file or a file
            # that cannot be written: say so, keep the trainee's panel (anything else is a bug)
            return _("Exercise could not be started: {error}").format(error=error_text(exc))
        self.save_nc_data()  # type: ignore[attr-defined]
        run.trainee_session = self.nc_session
        run.trainee_kernel = self.bridge.replace_kernel(kernel)
        run.trainee_estop_pressed = self.estop_pressed
        self.nc_session = run.session
        ProgramFiles.forget(self)  # the Program manager and the editor work on the exercise's programs
        for command in run.start_commands():
            self.bridge.submit(command)
        self.estop_pressed = self.bridge.status.emergency_stop  # the mushroom as the set-up left it
        self.exercise_run = run
        self.exercise_snapshot(self.bridge.poll(force=True))
        self._mark_areas(True)
        return _("Exercise started: {title}").format(title=exercise_text(exercise, "title"))

    def end_exercise(self) -> str:
        """Score the exercise, write its report, give the trainee's own panel back."""
        run = self.exercise_run
        if run is None:
            return _("No exercise is running")
        unsaved = self._unsaved_work()
        if unsaved and not self.ending:  # type: ignore[attr-defined]
            return _("Not ended: {unsaved} (save or close it first)").format(unsaved=unsaved)
        try:
            text_path = run.finish(self.bridge.poll().time_s)[0]
            said = _("Exercise ended, score {score}/100: report in {path}").format(
                score=run.report["score"] if run.report else 0, path=text_path)
        except OSError as exc:
            said = _("The exercise report could not be written: {error}").format(error=error_text(exc))
        finally:
            self.exercise_run = None
            self.exercise_side = ""
            self.bridge.replace_kernel(run.trainee_kernel)
            self.nc_session = run.trainee_session
            self.estop_pressed = run.trainee_estop_pressed
            ProgramFiles.forget(self)
            run.close()
            self._mark_areas(False)
            self.bridge.poll(force=True)
        return said

    def exercise_list(self) -> list[Any]:
        """The exercises to choose from: the shipped ones and those class packs brought into the
        trainee's data directory (``ExerciseError`` names a file that cannot be read)."""
        return queries.available_exercises(self._class_dir())

    def import_class_pack(self, path: str) -> str:
        """Check the class pack ``path`` whole, then write its exercises and programs into the
        trainee's data directory, or the one served to this browser tab (:mod:`nck.class_pack`,
        file by file atomically); return what to say. The caller checks the protection level."""
        if self.exercise_run is not None:
            return _("Class pack not imported: end the running exercise first")
        data_dir = self._class_dir()
        if data_dir is None:
            return _("Class pack not imported: the panel runs without a data directory")
        try:
            pack = queries.read_pack(path)
        except queries.PackError as exc:  # a file the system cannot read: said by its kind (error_text)
            cause = exc.__cause__
            reason = error_text(cause, failed="os_read_failed") if isinstance(cause, OSError) else str(exc)
            return _("Class pack not imported: {error}").format(error=reason)
        except OSError as exc:
            return _("Class pack not imported: {error}").format(error=error_text(exc, failed="os_read_failed"))
        try:
            written = queries.install_pack(pack, data_dir)
        except OSError as exc:  # writing into the class folder
            return _("Class pack not imported: {error}").format(error=error_text(exc))
        return (_("Class pack imported: {summary}").format(summary=pack.summary(_)) + " "
                + counted(len(written), N_("({count} file new or changed)"), N_("({count} files new or changed)")))

    def _class_dir(self) -> Path | None:
        """Where class packs are listed from and imported into (see :attr:`class_pack_dir`)."""
        return self.class_pack_dir if self.class_pack_dir is not None else self._trainee_data_dir()

    def _trainee_data_dir(self) -> Path | None:
        """The trainee's own data directory (not an exercise's private one); None without one."""
        run = self.exercise_run
        session = run.trainee_session if run is not None else self.nc_session
        return Path(session.session.data_dir) if session is not None else None

    def _unsaved_work(self) -> str:
        """Unsaved text of an area (it belongs to the data directory about to be swapped)."""
        return next((work for work in (a.unsaved_work() for a in self.area_screens) if work), "")  # type: ignore[attr-defined]

    def _mark_areas(self, running: bool) -> None:
        """Show or hide the side window: the class ``-exercise`` on the app and on every area
        built so far (a hidden area is restyled only by its own class changes; areas built
        later take it when they mount, ``hmi.area``)."""
        self.set_class(running, "-exercise")  # type: ignore[attr-defined]
        for screen in self.area_screens:  # type: ignore[attr-defined]
            screen.set_class(running, "-exercise")

    def _report_dir(self) -> Path:
        if self.exercise_report_dir is not None:
            return self.exercise_report_dir
        data_dir = self._trainee_data_dir()
        if data_dir is not None:
            return data_dir / REPORTS_FOLDER
        return Path(tempfile.gettempdir()) / "nck-exercise-reports"

    # -- what the app feeds in --------------------------------------------------------------
    def exercise_key(self, key: str) -> None:
        """A key reached the app."""
        if self.exercise_run is not None:
            self.exercise_run.observe_key(key)

    def exercise_command(self, command: Any, accepted: bool) -> None:
        """A command went to the kernel."""
        if self.exercise_run is not None:
            self.exercise_run.observe_command(command, accepted)

    def exercise_snapshot(self, status: NckStatus) -> None:
        """A new snapshot: check the step, refresh the side window's text."""
        run = self.exercise_run
        if run is None:
            return
        run.observe_status(status, self.bridge.query(queries.ReadData()).data)
        self.exercise_side = run.side_text()
