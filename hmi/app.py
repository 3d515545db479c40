"""The HMI application: SINUMERIK Operate on a PC keyboard.

Operating areas and the screen convention
-----------------------------------------
Each operating area is a Textual *mode* (its own screen stack, so dialogs of one
area stay open while the operator looks at another). :data:`AREAS` lists them
in panel order. The screen of area ``<id>`` comes from the module
``screens/<id>.py``, which exposes a module attribute ``AreaScreen``: a
subclass of :class:`hmi.area.AreaBase` (see that module for what a subclass
provides). When the module does not exist yet, the app shows
:class:`hmi.placeholder.PlaceholderScreen` for the area.

Keys
----
Every key is global and comes from ``data/keymap.toml`` (:mod:`hmi.keymap`):
the area keys, F1–F8 / Shift+F1–F8 (routed to the softkeys of the current
area), F9 area menu, F10 back, F11 help, F12 alarm cancel and the machine
control panel (:mod:`hmi.mcp`). MCP keys act on the kernel through the bridge
(:mod:`hmi.bridge`), the only code that calls the running kernel; the kernel
is built (machine, NC data directory, NC file system) in :mod:`hmi.startup`.
Ctrl+Left/Right give way to a focused editor where they cannot jog.
"""

from __future__ import annotations

import argparse
import asyncio
import gc
import importlib
import os
import signal
import sys
import traceback
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from textual import events, on
from textual.message import Message
from textual.app import App, SystemCommand
from textual.command import CommandList, CommandPalette
from textual.driver import Driver
from textual.drivers.linux_driver import LinuxDriver
from textual.drivers.web_driver import WebDriver
from textual.screen import Screen
from textual.theme import Theme, ThemeProvider

from nck import commands as cmd
from nck.commands import Accepted, SubmitResult
from nck import queries
from nck.status import NckStatus
from nck import TERMINATION_SIGNALS, StorageError, exit_on_termination

from hmi.alarm_times import AlarmTimes
from hmi.area import MIN_TERMINAL_SIZE, AreaBase
from hmi.bridge import NckBridge
from hmi.css_parse import share_parsed_css
from hmi.browser_driver import PanelBrowserDriver
from hmi.dialog import AreaDialog
from hmi.dialogs import ConfirmDialog
from hmi.exercise_run import EXAM_HELP_LIMITED, ClassroomHost, reports_dir_of, served_dir_of
from hmi.alarm_help import AlarmHelpScreen
from hmi.i18n import LANGUAGES, N_, _, error_text, language, refusal_text, set_language
from hmi.help import HelpScreen, area_keys
from hmi.key_input import own_binding
from hmi.key_settle import BindingsInPlace, wait_for_workers, wait_until_handled
from hmi.keymap import Keymap, default_keymap
from hmi.mcp import MachineControlPanel
from hmi.palette import SOFTKEY_PATH_SEPARATOR, PanelCommandPalette, Place, PlaceProvider, area_places
from hmi.placeholder import PlaceholderScreen
from hmi.serve import DEFAULT_MAX_SESSIONS, DEFAULT_PORT, serve
from hmi.program_lines import ProgramLines
from hmi.messages import AlarmLineClicked, CommandRejected, NckStatusChanged, TerminalClosed
from hmi.startup import start_session
from hmi.softkeys import Softkey, SoftkeyMenu, one_line
from hmi.stack_dump import register_stack_dump
from hmi.terminal_driver import PanelTerminalDriver
from hmi.theme import HMI_THEMES, SINUMERIK_THEME


PANEL_DRIVERS: dict[type[Driver], type[Driver]] = {LinuxDriver: PanelTerminalDriver, WebDriver: PanelBrowserDriver}
"""Textual's drivers and the HMI's own in their place (the panel's key reader)."""

RETAINED_SAVE_PERIOD_S = 5.0
"""Retained NC data that changed (part counters, alarm log …) is written at least this often."""

RETAINED_COMMANDS = (cmd.WriteData, cmd.SetKeyswitch, cmd.EnterPassword, cmd.DeletePassword,
                     cmd.ChangePassword, cmd.DeleteToolEdge, cmd.ClearRParameters,
                     cmd.SetMdaProgram, cmd.WriteMachineSetup, cmd.WriteManualSettings, cmd.SetActualValue,
                     cmd.SetWorkOffsetRotation, cmd.DeleteActiveWorkOffset)
"""Commands that change retained data: the data is saved right after they are accepted."""


GC_GEN0_THRESHOLD = 10_000
"""Allocations between young-generation collections once the HMI runs (Python's default: 700)."""


def freeze_startup_objects() -> None:
    """Keep the garbage collector off the objects that live as long as the app.

    Called once after the first frame: everything built at start (Textual, the
    kernel, the first area) moves to the permanent generation, so a full
    collection no longer walks it (it took 100–150 ms in the middle of a key
    while a program ran), and young collections run less often.
    """
    gc.collect()
    gc.freeze()
    _gen0, gen1, gen2 = gc.get_threshold()
    gc.set_threshold(GC_GEN0_THRESHOLD, gen1, gen2)


@dataclass(frozen=True, slots=True)
class Area:
    """An operating area: mode id (= module name in ``screens/``) and header title."""

    id: str
    title: str
    menu_label: str


AREAS: tuple[Area, ...] = (
    Area("machine", N_("MACHINE"), N_("Machine")),
    Area("parameter", N_("PARAMETER"), N_("Parameter")),
    Area("program", N_("PROGRAM"), N_("Program")),
    Area("program_manager", N_("PROGRAM MANAGER"), N_("Program\nmanager")),
    Area("diagnostics", N_("DIAGNOSTICS"), N_("Diagnostics")),
    Area("setup", N_("SETUP"), N_("Setup")),
)
"""The operating areas in the order of the area menu (F9)."""


def area_screen_factory(area: Area) -> Callable[[], Screen]:
    """Return a factory for the screen of ``area``: ``screens.<id>.AreaScreen`` or a placeholder.

    The module is imported when the area is first shown (a quicker start); an
    area whose module is missing, fails to import or lacks its stylesheet shows
    the placeholder with the reason instead of taking the other areas down.
    """

    def build() -> Screen:
        screen_class, problem = load_area_screen(area)
        if screen_class is None:
            return PlaceholderScreen(area.id, area.title, problem)
        return screen_class()

    return build


def load_area_screen(area: Area) -> tuple[type | None, str]:
    """Import ``screens.<id>`` and return its ``AreaScreen`` class, or None and the reason."""
    module_name = f"screens.{area.id}"
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        if exc.name == module_name:
            return None, ""
        return None, f"{module_name} could not be loaded: {exc}"
    except Exception as exc:  # a broken area must not take the other areas down
        return None, f"{module_name} could not be loaded: {type(exc).__name__}: {exc}"
    screen_class = getattr(module, "AreaScreen", None)
    if screen_class is None:
        return None, f"{module_name} has no AreaScreen"
    missing = _missing_css(screen_class, module)
    if missing:
        return None, f"{module_name}: stylesheet {missing} is missing"
    return screen_class, ""


def _missing_css(screen_class: type, module: Any) -> str:
    """Return the first ``CSS_PATH`` file of an area screen that does not exist, else ``""``."""
    paths = getattr(screen_class, "CSS_PATH", None)
    if not paths:
        return ""
    folder = Path(getattr(module, "__file__", "") or ".").parent
    for entry in [paths] if isinstance(paths, (str, Path)) else list(paths):
        path = Path(entry)
        if not path.is_absolute():
            path = folder / path
        if not path.is_file():
            return path.name
    return ""


class HmiApp(ClassroomHost, MachineControlPanel, App):
    """The SINUMERIK Operate trainer.

    Args:
        nck: the kernel facade (``nck.kernel.Nck`` or a compatible object).
        realtime: advance the kernel from a wall-clock timer (False in tests).
        keymap: the key table (default: ``data/keymap.toml``).
        on_quit: called before the app exits (saves NC data).
        alarm_times: the wall-clock stamps of the alarm log (those the NC data session retains).
    """

    CSS_PATH = "hmi.tcss"
    TITLE = "SINUMERIK Operate trainer"
    COMMANDS = App.COMMANDS | {PlaceProvider}
    """The command palette (``app.palette``, Ctrl+P): system commands and the panel's places."""
    BINDINGS = [binding.to_binding() for binding in default_keymap().bindings]
    """Every key of ``data/keymap.toml``, as priority bindings (they work over editors)."""

    def __init__(self, nck: Any, *, realtime: bool = True, keymap: Keymap | None = None,
                 on_quit: Callable[[], None] | None = None, alarm_times: AlarmTimes | None = None) -> None:
        self.keymap = keymap or default_keymap()
        share_parsed_css()
        super().__init__()
        for theme in HMI_THEMES:
            self.register_theme(theme)
        self.theme = SINUMERIK_THEME.name
        for name in set(self.available_themes) - {theme.name for theme in HMI_THEMES}:
            self.unregister_theme(name)  # the palette's Theme command offers the HMI's themes only
        self.bridge = NckBridge(nck, realtime=realtime, alarm_times=alarm_times)
        self.latest_status: NckStatus | None = None
        self.hint = ""
        """The message last written on a dialog line (each area keeps its own)."""
        self.internal_errors: list[str] = []
        self.init_panel()
        self._on_quit = on_quit
        self.nc_session: Any = None  # hmi.startup.NcDataSession when running on a data directory
        self._program_cache: dict[str, ProgramLines] = {}
        self._held_updates = 0
        self._keys_behind_palette: list[events.Key] | None = None
        """Keys that came while the command the palette chose waits to run (None: no hold)."""
        self.area_screens: list[AreaBase] = []
        """The area screens built so far (each area's screen lives as long as the app)."""
        self._snapshot_shown = False
        self.ending = False
        """Set once the HMI has begun to quit (a second quit request is then ignored)."""
        self.exit_notes: list[str] = []
        """What could not be kept or saved at quit: printed on stderr once the screen is closed."""
        self.freeze_gc_at_start = False
        """Set by :func:`main`: call :func:`freeze_startup_objects` after the first frame."""
        for area in AREAS:
            self.add_mode(area.id, self._remembered(area_screen_factory(area)))

    def _remembered(self, factory: Callable[[], Screen]) -> Callable[[], Screen]:
        """Wrap an area factory so that the app knows every area screen built (for quitting)."""
        def build() -> Screen:
            screen = factory()
            if isinstance(screen, AreaBase):
                self.area_screens.append(screen)
            return screen

        return build

    def get_driver_class(self) -> type[Driver]:
        """Textual's driver for this platform; on a Linux/macOS terminal and in a browser tab
        (``hmi --serve``) with the HMI's key reader."""
        driver = super().get_driver_class()
        return PANEL_DRIVERS.get(driver, driver)

    def get_theme_variable_defaults(self) -> dict[str, str]:
        """The HMI's own colour variables (``$softkey-background`` …), from the theme."""
        return dict(SINUMERIK_THEME.variables)

    # -- repaint hold on area switches ------------------------------------------------------
    def delay_update(self, delay: float = 0.05) -> None:
        """Hold repaints while an area switch is under way (Textual calls this in ``switch_mode``).

        Textual holds them for a fixed 50 ms to hide the transition; here the hold
        ends as soon as the new area has taken the newest status
        (:meth:`release_held_update`, called from ``AreaBase.on_screen_resume``),
        with ``delay`` only as the fallback for screens that never call it.
        """
        self._begin_batch()
        self._held_updates += 1
        self.set_timer(delay, self.release_held_update, name="delay_update")

    def release_held_update(self) -> None:
        """End one repaint hold of :meth:`delay_update` (no-op when none is held)."""
        if self._held_updates <= 0:
            return
        self._held_updates -= 1
        self._end_batch()
        if not self._batch_count:
            self.screen.refresh()

    def push_screen(self, screen: Any, callback: Any = None, wait_for_dismiss: bool = False) -> Any:
        """Show ``screen``; a dialog hands its result to ``callback`` as it closes (:mod:`hmi.dialog`)."""
        if callback is not None and isinstance(screen, AreaDialog) and not wait_for_dismiss:
            screen.result_handler = callback
            callback = None
        return super().push_screen(screen, callback, wait_for_dismiss)

    # -- start ---------------------------------------------------------------------------
    def on_resize(self, event: events.Resize) -> None:
        """Below :data:`MIN_TERMINAL_SIZE` every area shows one line with the size needed."""
        self.show_size_fit(event.size.width, event.size.height)

    def show_size_fit(self, width: int, height: int) -> None:
        """Set the app's ``-too-small`` class for a terminal of ``width`` × ``height``."""
        self.set_class(width < MIN_TERMINAL_SIZE[0] or height < MIN_TERMINAL_SIZE[1], "-too-small")

    def on_mount(self) -> None:
        """Connect the kernel and open the Machine area."""
        self.show_size_fit(*self.size)
        self.latest_status = self.bridge.status
        self.bridge.attach(self)
        self._apply_kept_theme()
        if self.nc_session is not None and self.bridge.realtime:
            self.set_interval(RETAINED_SAVE_PERIOD_S, self.save_nc_data, name="nc-data-save")
        self.switch_mode("machine")
        if self.bridge.realtime:  # the real panel, not a test's
            self._quit_on_termination()
        if self.freeze_gc_at_start:
            self.call_after_refresh(freeze_startup_objects)

    async def on_event(self, event: events.Event) -> None:
        """Run a key the focused widget binds itself in that widget's queue, in line with text.

        A key handed to the focused widget is handled, with all it caused (a
        dialog closed by Enter), before the next key is taken
        (:func:`hmi.key_settle.wait_until_handled`).

        Textual would let such a key (Up, Home, Backspace in an editor) bubble back up
        to the app before its binding runs, so that characters typed behind it in the
        same burst were inserted first (issue 18: ``AAA``, Up, ``BBB`` gave ``AAABBB``).

        A key that comes back up to the app has been offered to every binding where it
        arrived (each screen of the HMI runs them in place, :class:`BindingsInPlace`;
        the keymap's are priority bindings, run before the key went down). It ends
        here: Textual would try it again on the focus of the moment, a dialog opened
        by a later key of the burst (Ctrl+U, Enter on the tool list emptied the new
        field). A screen of Textual's own (the command palette) is not one of ours: its bindings
        run as Textual runs them.
        """
        if isinstance(event, events.Key) and event.is_forwarded:
            if not isinstance(self.screen, BindingsInPlace):
                # A screen of Textual's own (the command palette): its bindings (Escape) run
                # where Textual runs them, when the key comes back up to the app.
                await super().on_event(event)
            return
        if not isinstance(event, events.Key):
            await super().on_event(event)
            return
        if self._keys_behind_palette is not None:
            self._keys_behind_palette.append(event)
            return
        self.exercise_key(event.key)
        focused = self.focused
        binding = own_binding(self.screen, focused, event)
        if binding is not None and focused is not None \
                and focused.call_later(focused.run_action, binding.action):
            self.app_focus = True  # as Textual does on a key
        else:
            await super().on_event(event)
        target = focused or self.screen
        if target.is_attached:
            await wait_until_handled(self, target)
        if isinstance(self.screen, CommandPalette):
            # Enter on the list: the choice travels from the list to the palette, which closes
            # and queues the command (the keys behind wait for it, :meth:`post_message`)
            await wait_until_handled(self, self.screen.query_one(CommandList))
        if isinstance(self.screen, CommandPalette):  # the keys behind a typed name see its search's list
            await wait_for_workers(self.screen)

    # -- keys behind the palette's choice ----------------------------------------------------
    def post_message(self, message: Message) -> bool:
        """Queue ``message``; the palette's choice starts holding the keys behind it.

        The palette posts ``Closed`` and then queues the chosen command with ``call_later``,
        behind the keys already in the queue: an area key typed right after Enter would run
        first and the command would then take the panel elsewhere (or pop a screen that is
        gone). From here on keys wait until the command has run (:meth:`_palette_closed`).
        """
        if isinstance(message, CommandPalette.Closed) and message.option_selected:
            self._keys_behind_palette = self._keys_behind_palette or []
        return super().post_message(message)

    @on(CommandPalette.Closed)
    def _palette_closed(self) -> None:
        """The palette's command is queued next: release the held keys after it, in their order."""
        if self._keys_behind_palette is not None:
            self.call_later(self._release_keys_behind_palette)

    async def _release_keys_behind_palette(self) -> None:
        held, self._keys_behind_palette = self._keys_behind_palette or [], None
        for key in held:
            await self.on_event(key)

    async def on_cursor_position(self, event: events.CursorPosition) -> None:
        """Turn a lone ``ESC [1;2R`` back into Shift+F3 (VSK3), in its place among the keys.

        Terminals send Shift+F3 as ``ESC [1;2R``, which Textual's parser reads as a cursor
        position report (row 1, column 2). The HMI never asks for a cursor position in
        full-screen mode, so such a report can only be the key. It is handled now, not
        posted: posted, it came behind the keys of the same burst.
        """
        if (event.x, event.y) == (1, 0):
            event.stop()
            key = events.Key("shift+f3", None)
            key.set_sender(self)
            await self.on_event(key)

    # -- kernel ---------------------------------------------------------------------------
    def submit(self, command: Any, answers_refusal: bool = True) -> SubmitResult:
        """Send a command to the kernel; an accepted command clears the dialog line.

        The areas show the snapshot the command made at once, so that the next
        key of a burst (a softkey after the keyswitch) meets the new state.
        ``answers_refusal`` False: the command follows from an earlier key (the + / −
        key let go) and leaves the refusal of a later key on the dialog line.
        """
        result = self.bridge.submit(command)
        self.exercise_command(command, isinstance(result, Accepted))
        self.show_snapshot(self.bridge.status)
        area = self.area_screen
        if answers_refusal and isinstance(result, Accepted) and area is not None and area.area_hint:
            area.say("")  # the refusal it showed is no longer the last word
        if isinstance(result, Accepted) and isinstance(command, RETAINED_COMMANDS):
            self.save_nc_data()
        return result

    def save_nc_data(self) -> None:
        """Write the retained NC data that changed (no-op without a data directory)."""
        if self.nc_session is None:
            return
        try:
            self.nc_session.save()
        except OSError as exc:  # a full or read-only disk: say so, keep running
            self.set_hint(_("NC data could not be saved: {error}").format(error=error_text(exc)))

    # -- colour theme ---------------------------------------------------------------------------
    def _apply_kept_theme(self) -> None:
        """The theme kept in the data directory; from now on every change of theme is kept."""
        if self.nc_session is not None and self.nc_session.theme in {theme.name for theme in HMI_THEMES}:
            self.theme = self.nc_session.theme
        self.theme_changed_signal.subscribe(self, self._keep_theme)

    def _keep_theme(self, theme: Theme) -> None:
        """A theme was chosen (Setup or the palette): keep it for the next start (atomic write)."""
        if self.nc_session is not None and self.nc_session.theme != theme.name:
            self.nc_session.theme = theme.name
            self.save_nc_data()

    # -- language -------------------------------------------------------------------------------
    def select_language(self, code: str) -> str:
        """Show the operator texts in language ``code`` from now on (Setup ▸ Change language).

        The choice is kept in the NC data directory (retained section ``display``) and every
        area is built again in the new language; the area shown stays shown, in the same
        view. Refused (nothing changes) while an area holds unsaved text: building it again
        would lose it. Returns what to say on the dialog line ("" when nothing needs saying).
        """
        if code == language():
            return ""
        unsaved = [work for work in (screen.unsaved_work() for screen in self.area_screens) if work]
        if unsaved:
            return _("Language not changed: {reason}").format(reason=unsaved[0])
        set_language(code)
        if self.nc_session is not None:
            self.nc_session.language = code
            self.save_nc_data()
        self.run_worker(self._rebuild_areas(), group="language", exclusive=True)
        return ""

    async def _rebuild_areas(self) -> None:
        """Build every area built so far anew (its texts come from the catalogue as it composes)."""
        current = self.current_mode
        old = self.area_screen
        view = getattr(old, "view", None)
        for area in AREAS:
            if area.id != current:
                await self._renew_area(area)
        spare = next(area.id for area in AREAS if area.id != current)
        await self.switch_mode(spare)
        await self._renew_area(next(area for area in AREAS if area.id == current))
        await self.switch_mode(current)
        new = self.area_screen
        show_view = getattr(new, "action_show_view", None)
        if view is not None and callable(show_view) and getattr(new, "view", None) != view:
            show_view(view)

    async def _renew_area(self, area: Area) -> None:
        """Drop the screen of ``area`` (if built); the next visit builds a fresh one."""
        self.area_screens = [screen for screen in self.area_screens if screen.AREA_ID != area.id]
        await self.remove_mode(area.id)
        self.add_mode(area.id, self._remembered(area_screen_factory(area)))

    def power_on_reset(self) -> bool:
        """Reset (po): save, restart the simulated NCK from the retained data; False without one."""
        if self.nc_session is None:
            return False
        # The override switches are hardware of the machine control panel: a restarted NCK
        # reads them where they stand.
        switches = dict(self.bridge.status.channel.overrides)
        self.bridge.replace_kernel(self.nc_session.power_on())
        for which, percent in switches.items():
            self.bridge.submit(cmd.SetOverride(which, percent))
        self.bridge.poll(force=True)
        return True

    def on_nck_status_changed(self, message: NckStatusChanged) -> None:
        """Hand the newest snapshot to the area screens of the current stack.

        Not the message's own: it was read when it was posted, and keys queued before it
        may have changed the kernel since (their commands show their snapshot at once).
        Shown after them, the older snapshot would undo on screen what they did.
        """
        self.show_snapshot(self.bridge.status)

    def show_snapshot(self, status: NckStatus) -> None:
        """Hand ``status`` to the area screens of the current stack (once per snapshot)."""
        if status is self.latest_status and self._snapshot_shown:
            return
        self.latest_status = status
        if not self.is_running:  # shutting down: the screens are being taken apart
            self._snapshot_shown = False
            return
        self._snapshot_shown = True
        self.exercise_snapshot(status)
        for screen in self.screen_stack:
            if isinstance(screen, AreaBase):
                try:
                    screen.show_status(status)
                except Exception as exc:  # a display bug must not end the operator's session
                    self.report_internal_error(exc)

    def report_internal_error(self, exc: Exception) -> None:
        """Keep an HMI bug's traceback, say so on the dialog line, and carry on.

        Under pytest the error is raised again so that tests fail on it.
        """
        self.internal_errors.append("".join(traceback.format_exception(exc)))
        if "PYTEST_CURRENT_TEST" in os.environ:
            raise exc
        self.set_hint(f"HMI internal error: {type(exc).__name__}: {exc}")

    def on_alarm_line_clicked(self, message: AlarmLineClicked) -> None:
        """A click on the header's alarm line: the help of the alarm shown there."""
        self.show_alarm_help(message.number, message.text)

    def show_alarm_help(self, number: int, text: str = "") -> None:
        """Open the help of alarm ``number`` (``text``: as displayed, with its values); none in an exam."""
        if self.exam_running:
            self.set_hint(_(EXAM_HELP_LIMITED))
            return
        if isinstance(self.screen, AlarmHelpScreen):
            return
        self.push_screen(AlarmHelpScreen(number, text))

    def on_command_rejected(self, message: CommandRejected) -> None:
        """Show why the kernel refused a command."""
        alarm = message.refusal.alarm
        prefix = f"{alarm}: " if alarm else ""
        self.set_hint(f"{prefix}{refusal_text(message.refusal)}")

    def set_hint(self, text: str) -> None:
        """Write the dialog line of the current area: the message belongs to that area only."""
        self.hint = text
        area = self.area_screen if self.is_running else None
        if area is not None:
            area.say(text)

    @property
    def area_screen(self) -> AreaBase | None:
        """The area screen at the bottom of the current mode's stack."""
        for screen in reversed(self.screen_stack):
            if isinstance(screen, AreaBase):
                return screen
        return None

    def program_names(self) -> list[str]:
        """Paths of the part programs the kernel can select (for the selection dialog).

        The same path the Program manager's Execute selects (``MPF/PART1.MPF``),
        so that the header shows a program the same way however it was selected.
        """
        try:
            return list(self.bridge.query(queries.ProgramNames()))
        except (StorageError, OSError):  # an unreadable NC folder shows as an empty list
            return []

    def program_text(self, name: str) -> ProgramLines | None:
        """The lines of a part program from the kernel's program source, or None.

        The last program read is kept (the block window asks at every refresh).
        """
        cached = self._program_cache.get(name)
        if cached is not None:
            return cached
        source = self.bridge.query(queries.ProgramSource())
        reader = getattr(source, "read_program", None)
        found = None
        if callable(reader):
            try:
                found = reader(name)
            except (StorageError, OSError):  # an unreadable program is shown as not available
                found = None
        if found is None:
            return None
        result = ProgramLines(str(found[0]), str(found[1]))
        self._program_cache = {name: result}
        return result

    # -- operator panel ---------------------------------------------------------------------
    def action_switch_area(self, area_id: str) -> None:
        """Area key: show the operating area ``area_id``.

        Dialogs of the area being left are cancelled (as Escape would): a dialog
        is never left pending to come back on the next visit.
        """
        while isinstance(self.screen, (AreaDialog, CommandPalette)):
            self.screen.dismiss(None)
        area = self.area_screen
        if area is not None:
            area.clear_softkey_levels()
        self.switch_mode(area_id)

    def action_softkey(self, slot_id: str) -> None:
        """F1–F8 / Shift+F1–F8: press a softkey of the top screen (area or dialog)."""
        top = self.screen
        handler = getattr(top, "press_softkey", None)
        if callable(handler):
            handler(slot_id)

    # -- command palette ---------------------------------------------------------------------
    def action_command_palette(self) -> None:
        """Ctrl+P: the command palette (it finds any softkey by name: not in an exam)."""
        if self.exam_running:
            self.set_hint(_(EXAM_HELP_LIMITED))
            return
        if any(isinstance(screen, CommandPalette) for screen in self.screen_stack):
            return  # one is open already, perhaps under the key overview (F11) opened over it
        if self.use_command_palette:
            self.push_screen(PanelCommandPalette(id="--command-palette", placeholder=_("Search for commands…")))

    def search_themes(self) -> None:
        """The palette's theme list (the Theme command), its search field in the panel's language."""
        self.push_screen(PanelCommandPalette(providers=[ThemeProvider], placeholder=_("Search for themes…")))

    def get_system_commands(self, screen: Screen) -> Any:
        """The palette's system commands: theme, keys (the F11 help), screenshot, quit (Ctrl+Q's way)."""
        yield SystemCommand(_("Theme"), _("Change the colour theme"), self.action_change_theme)
        yield SystemCommand(_("Keys"), _("Show the keys in force (as F11)"), self.action_help)
        yield SystemCommand(_("Screenshot"), _("Save an SVG picture of the screen"),
                            lambda: self.set_timer(0.1, self.deliver_screenshot))
        yield SystemCommand(_("Quit"), _("Quit the HMI (NC data is saved first)"), self.action_quit_hmi)

    def palette_places(self) -> list[Place]:
        """Every operating area and the softkeys of its top level (:mod:`hmi.palette`).

        An area already shown lists its softkeys as they are now (its view); one not
        shown yet as a fresh screen of it would.
        """
        built = {screen.AREA_ID: screen for screen in self.area_screens}
        places: list[Place] = []
        for area in AREAS:
            screen = built.get(area.id)
            if screen is None:
                screen_class, _problem = load_area_screen(area)
                screen = screen_class() if screen_class is not None else None
            menu = screen.softkey_menu() if screen is not None else SoftkeyMenu.of()
            places += area_places(area.id, area.menu_label, menu, self.keymap,
                                  lambda key, screen=screen: getattr(screen, key.submenu)() if key.submenu else None)
        return places

    def action_go_to_place(self, area_id: str, softkey_id: str = "") -> None:
        """Show the area ``area_id`` and press its softkey ``softkey_id`` on the top level
        (``more/version``: the softkeys in turn, each on the level the one before opened)."""
        if self.current_mode != area_id:
            self.action_switch_area(area_id)
        if softkey_id:
            self.call_after_refresh(self._press_softkeys, softkey_id.split(SOFTKEY_PATH_SEPARATOR), True)

    def _press_softkeys(self, softkey_ids: list[str], from_top: bool = False) -> None:
        area = self.area_screen
        if area is None:
            return
        if from_top:
            area.clear_softkey_levels()
        if area.current_menu().find(softkey_ids[0]) is None:
            area.say(_("This softkey is not offered in the current view"))
            return
        area.press_softkey_id(softkey_ids[0])
        if len(softkey_ids) > 1:
            self.call_after_refresh(self._press_softkeys, softkey_ids[1:])

    def area_menu(self) -> SoftkeyMenu:
        """The area menu shown by MENU SELECT (F9)."""
        keys = [
            Softkey(f"area.{area.id}", area.menu_label, f"app.switch_area('{area.id}')")
            for area in AREAS
        ]
        return SoftkeyMenu.of(keys)

    def action_menu_select(self) -> None:
        """F9: show the operating areas on the horizontal softkeys."""
        area = self.area_screen
        if area is not None and area is self.screen:
            area.push_softkeys(self.area_menu())

    def action_menu_recall(self) -> None:
        """F10: close the top dialog, else go back one softkey level / view."""
        if not isinstance(self.screen, AreaBase) and len(self.screen_stack) > 1:
            self.screen.dismiss(None)
            return
        area = self.area_screen
        if area is not None:
            area.menu_recall()

    def action_help(self) -> None:
        """F11: show or hide the overlay of the keys in force."""
        if isinstance(self.screen, HelpScreen):
            self.screen.dismiss(None)
            return
        if any(isinstance(node, HelpScreen) for node in self.children):
            return  # another area's help is still being closed: its id "help" is taken until then
        area = self.area_screen
        menu = area.current_menu() if area is not None else SoftkeyMenu.of()
        own_keys = area_keys(area) if area is not None and area is self.screen else []
        label = next((shown.menu_label for shown in AREAS if area is not None and shown.id == area.AREA_ID), "")
        title = one_line(_(label))  # the area's name as its softkey says it (Programm-Manager)
        self.push_screen(HelpScreen(self.keymap, menu, own_keys, title))

    def action_alarm_cancel(self) -> None:
        """F12: acknowledge the alarms whose clear criterion is CANCEL."""
        self.submit(cmd.CancelAlarms())

    def _quit_on_termination(self) -> None:
        """SIGTERM/SIGHUP while running: quit without asking (:meth:`quit_unattended`)."""
        loop = asyncio.get_running_loop()
        for number in TERMINATION_SIGNALS:
            try:
                loop.add_signal_handler(number, self.quit_unattended, 128 + number)
            except (NotImplementedError, RuntimeError, ValueError):  # no signals here (Windows, thread)
                return

    @on(TerminalClosed)
    def _quit_on_terminal_closed(self) -> None:
        """The terminal has gone away: quit without asking, as after the hang-up signal."""
        self.quit_unattended(128 + signal.SIGHUP)

    def quit_concerns(self) -> list[str]:
        """What quitting now would interrupt or leave unsaved (empty: quit without asking)."""
        concerns = []
        status = self.latest_status
        if status is not None and status.channel.channel_state in ("active", "interrupted"):
            program = status.channel.selected_program or _("the MDA program")
            concern = _("{program} is running") if status.channel.channel_state == "active" \
                else _("{program} is interrupted")
            concerns.append(concern.format(program=program))
        concerns += [work for work in (screen.unsaved_work() for screen in self.area_screens) if work]
        return concerns

    def action_quit_hmi(self) -> None:
        """Ctrl+Q: leave; with a program running or interrupted, or unsaved text, ask first."""
        concerns = self.quit_concerns() if self.is_running else []
        if not concerns:
            self.quit_now()
            return

        def answered(yes: bool | None) -> None:
            if yes:
                self.quit_now()

        lines = [concern[:1].upper() + concern[1:] + "." for concern in concerns]
        self.push_screen(ConfirmDialog("\n".join([_("Quit the HMI?"), *lines, _(
            "Unsaved program text is kept in the editor journal and offered at the next start.")])),
                         answered)

    def quit_now(self) -> None:
        """Keep unsaved editor text in the journal, save NC data, then leave.

        When the journal cannot be written the HMI stays open and says why (the
        text would be lost otherwise).
        """
        failures = self._keep_unsaved_text()
        if failures:
            self.set_hint(_("Not quit: unsaved text could not be kept in the journal: {error}").format(
                error=error_text(failures[0])))
            return
        self._leave(0)

    def quit_unattended(self, exit_code: int) -> None:
        """Quit without asking: the terminal is gone, or SIGTERM/SIGHUP told the HMI to end.

        Nobody can answer "Quit the HMI?" (a program running or unsaved text) nor
        read the dialog line, so the HMI keeps what it can, notes what it could not
        keep (a journal that cannot be written) for stderr (:attr:`exit_notes`),
        saves, gives the data directory free and ends with ``exit_code`` (128 + the
        signal, as a shell reports a process ended by it; a lost terminal counts as
        a hang-up).
        """
        if self.ending:
            return
        for failure in self._keep_unsaved_text():
            self.exit_notes.append(f"hmi: unsaved text could not be kept in the journal: {failure}")
        self._leave(exit_code)

    def _keep_unsaved_text(self) -> list[OSError]:
        """Write every area's unsaved text into the journal; return the errors of those that failed."""
        failures = []
        for screen in self.area_screens:
            try:
                screen.keep_before_quit()
            except OSError as exc:
                failures.append(exc)
        return failures

    def _leave(self, exit_code: int) -> None:
        """Save NC data (a failure is reported, the app still quits), then end the app."""
        self.ending = True
        if self.exercise_run is not None:  # the report is written, the trainee's session saved below
            self.exit_notes.append(f"hmi: {self.end_exercise()}")
        if self._on_quit is not None:
            try:
                self._on_quit()
            except Exception as exc:  # a failed save is reported, the app still quits
                self.exit_notes.append(f"hmi: saving NC data failed: {exc}")
        self.exit(return_code=exit_code)


def report_on_stderr(text: str) -> None:
    """Write a line for the operator on stderr; nothing when the terminal is gone."""
    try:
        print(text, file=sys.stderr)
    except OSError:  # the terminal has been hung up: nobody is left to read it
        pass


def detach_lost_terminal() -> None:
    """Point stdout and stderr at the null device when their terminal has gone away.

    Python flushes both streams as it ends; a flush to a hung-up terminal fails
    (EIO) and turns any exit code into 120, so a lost terminal's ``128 + SIGHUP``
    would not reach the process that watches the HMI. What is still buffered
    then goes to the null device: nobody is left to read it.
    """
    for stream in {id(s): s for s in (sys.stdout, sys.stderr, sys.__stdout__, sys.__stderr__) if s}.values():
        try:
            stream.flush()
        except ValueError:  # closed: Python will not flush it again
            continue
        except OSError:
            null = os.open(os.devnull, os.O_WRONLY)
            try:
                os.dup2(null, stream.fileno())
            finally:
                os.close(null)


def make_app(machine: str | None = None, data_dir: str | None = None, ephemeral: bool = False,
             *, nck: Any = None, program: str | None = None, realtime: bool = True,
             confirm: Callable[[str], bool] | None = None, lang: str | None = None,
             reports_dir: str | None = None, class_dir: str | None = None) -> HmiApp:
    """Build the application (shared by the console script and the tests).

    Args:
        machine: machine name or TOML path (default mill).
        data_dir: NC data directory (passed through to the kernel's storage).
        ephemeral: work on a temporary copy of the NC data.
        nck: an existing kernel (tests); built from the other options when None.
        program: a part program to select at start (for AUTOMATIC).
        realtime: advance the kernel from the wall clock (False: tests advance it).
        confirm: asks the user a yes/no question before the panel starts (replacing a
            program with ``program``); None answers no.
        lang: the language of the operator texts (``--lang``); None: the one kept in the
            data directory (English for a new one).
        reports_dir: where exercise reports go (``--reports-dir``); None: ``exercise_reports``
            of the data directory — with ``ephemeral`` of the directory copied, so that the
            reports outlive the copy (:func:`hmi.exercise_run.reports_dir_of`).
        class_dir: the data directory whose class packs the panel lists and imports into
            (``--class-dir``; a browser tab's the one served); None: its own.
    """
    on_quit = None
    session = None
    if nck is None:
        session, nck = start_session(machine, data_dir, ephemeral, program, confirm)
        on_quit = session.quit
        if lang is not None:  # --lang: this language from now on, kept for the next start
            session.language = lang
        set_language(session.language)
    elif lang is not None:
        set_language(lang)
    app = HmiApp(nck, realtime=realtime, on_quit=on_quit,
                 alarm_times=session.alarm_times if session is not None else None)
    app.nc_session = session
    if reports_dir is not None or ephemeral:
        app.exercise_report_dir = reports_dir_of(reports_dir, data_dir)
    if class_dir is not None:
        app.class_pack_dir = served_dir_of(class_dir)
    return app


def ask_on_terminal(question: str) -> bool:
    """A yes/no question on the terminal before the panel starts; no when nobody can answer."""
    if not sys.stdin.isatty():
        return False
    try:
        return input(f"hmi: {question} [y/N] ").strip().lower() in ("y", "yes")
    except EOFError:
        return False


def terminal_attached() -> bool:
    """Whether the panel has a terminal to draw on: standard input and output are terminals,
    or a Textual driver of its own is named (a browser served the panel, TEXTUAL_DRIVER)."""
    if os.environ.get("TEXTUAL_DRIVER"):
        return True
    return sys.stdin.isatty() and sys.stdout.isatty()


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``hmi`` console script."""
    parser = argparse.ArgumentParser(prog="hmi", description="SINUMERIK Operate trainer")
    parser.add_argument("--machine", help="machine name (data/machines) or TOML file")
    parser.add_argument("--data-dir", help="NC data directory")
    parser.add_argument("--ephemeral", action="store_true",
                        help="work on a temporary copy of the NC data (nothing is saved)")
    parser.add_argument("--program", help="part program to select in AUTO at start")
    parser.add_argument("--lang", choices=sorted(LANGUAGES),
                        help="language of the operator texts (kept for the next start; "
                             "default: the one chosen last, English at first)")
    parser.add_argument("--reports-dir", metavar="DIR",
                        help="where exercise reports are written (default: exercise_reports in the data "
                             "directory; with --ephemeral or --serve in the one copied)")
    parser.add_argument("--class-dir", metavar="DIR",
                        help="data directory whose class packs the Exercises list shows and imports into "
                             "(default: the panel's own; --serve passes the directory served)")
    parser.add_argument("--serve", action="store_true",
                        help="serve the panel to browsers (classroom): one panel on a private copy of the "
                             "NC data per browser tab (needs textual-serve, installed by make)")
    parser.add_argument("--host", default="127.0.0.1", help="--serve: address to listen on (default 127.0.0.1)")
    parser.add_argument("--port", type=int, default=DEFAULT_PORT, help=f"--serve: port (default {DEFAULT_PORT})")
    parser.add_argument("--max-sessions", type=int, default=DEFAULT_MAX_SESSIONS, metavar="N",
                        help=f"--serve: at most N browser panels at once (default {DEFAULT_MAX_SESSIONS})")
    args = parser.parse_args(argv)
    if args.serve:
        if args.max_sessions < 1 or not 0 < args.port < 65536:
            print("hmi: --max-sessions needs 1 or more, --port a port number 1…65535", file=sys.stderr)
            return 2
        return serve(args.host, args.port, args.max_sessions, args.machine, args.data_dir,
                     str(reports_dir_of(args.reports_dir, args.data_dir)), args.lang,
                     str(served_dir_of(args.data_dir)))
    started = time.perf_counter()
    # SIGTERM/SIGHUP while starting or ending: a normal exit, so a temporary copy is removed
    with exit_on_termination():
        try:
            app = make_app(args.machine, args.data_dir, args.ephemeral, program=args.program,
                           confirm=ask_on_terminal, lang=args.lang, reports_dir=args.reports_dir,
                           class_dir=args.class_dir)
        except Exception as exc:  # a CLI/file problem: a clear message, no traceback
            # an exception without text (MemoryError) must not leave a bare "hmi: "
            message = str(exc) or f"cannot start: internal error ({type(exc).__name__})"
            print(f"hmi: {message}", file=sys.stderr)
            return 2
        if not terminal_attached():
            print("hmi: the panel needs a terminal on standard input and output "
                  "(for work without one use nck)", file=sys.stderr)
            if app.nc_session is not None:
                app.nc_session.quit()
            return 2
        app.started_at = started  # type: ignore[attr-defined]
        app.freeze_gc_at_start = True
        if app.nc_session is not None:
            try:  # kill -USR1 <pid>: every thread's stack into <data dir>/hmi/thread-stacks.txt
                register_stack_dump(Path(app.nc_session.session.data_dir) / "hmi")
            except OSError as exc:
                print(f"hmi: thread stacks cannot be written on SIGUSR1: {exc}", file=sys.stderr)
        app.run()
        for note in app.exit_notes:
            report_on_stderr(note)
        detach_lost_terminal()
    return app.return_code or 0
