"""The base class of every operating-area screen.

Convention (see also ``hmi/app.py``): each operating area lives in
``screens/<area>.py`` and exposes a module attribute ``AreaScreen``: a subclass
of :class:`AreaBase`. The app puts one instance per area into Textual ``MODES``
(one screen stack per area). A subclass:

- sets ``AREA_ID`` (``"parameter"``) and ``AREA_TITLE`` (``"PARAMETER"``),
  and ``CSS_PATH`` for its ``.tcss`` next to the module;
- yields its windows from :meth:`AreaBase.compose_content` (the header, the
  softkey bars and the dialog line are composed by the base class);
- returns its top softkey level from :meth:`AreaBase.softkey_menu` and pushes
  sub-levels with :meth:`AreaBase.push_softkeys` (F10 goes back one level);
- reacts to new kernel snapshots in :meth:`AreaBase.update_status` (called only
  when ``seq`` changed, and when the area becomes visible again);
- acts on the kernel only through :meth:`AreaBase.submit` with ``nck.commands``.

Softkey actions are Textual actions of the screen (``action_<name>``), e.g.
``Softkey("machine.gfunc", "G functions", "show_view('gfunc')")``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from textual import events
from textual.actions import parse as parse_action
from textual.app import ComposeResult
from textual.containers import Container, Horizontal
from textual.screen import Screen
from textual.widgets import Static

from nck.commands import SubmitResult
from nck.status import NckStatus

from hmi.focus import FocusRepaintsItsWidgets
from hmi.i18n import N_, _
from hmi.key_settle import BindingsInPlace
from hmi.panel_keys import PanelKey, PanelKeys
from hmi.softkeys import HorizontalSoftkeys, SoftkeyCell, SoftkeyMenu, VerticalSoftkeys, one_line
from hmi.widgets.header import AreaHeader
from hmi.widgets.shown_text import show_text

if TYPE_CHECKING:
    from hmi.host import AreaHost


MIN_TERMINAL_SIZE = (120, 36)
"""The smallest terminal (columns, rows) the layout reads well in; below it one line says so."""

TOO_SMALL_TEXT = N_("The panel needs a terminal of at least {columns} × {rows} characters: "
                    "please make the window larger.")
"""Shown instead of the area's windows while the terminal is smaller (app class ``-too-small``)."""


class DialogLine(Static):
    """The line above the horizontal softkeys: operator hints and refused commands."""


class AreaBase(FocusRepaintsItsWidgets, BindingsInPlace):
    """A SINUMERIK operating area: header, content, vertical and horizontal softkeys."""

    AREA_ID: ClassVar[str] = "area"
    """Mode name of the area in the app (``machine``, ``parameter`` …)."""

    AREA_TITLE: ClassVar[str] = "AREA"
    """Area name shown first in the header."""

    def __init__(self, name: str | None = None, id: str | None = None,  # noqa: A002
                 classes: str | None = None) -> None:
        super().__init__(name=name, id=id, classes=classes)
        self.status: NckStatus | None = None
        self.area_hint = ""
        """The message on this area's dialog line."""
        self._menu_stack: list[SoftkeyMenu] = []

    # -- layout ----------------------------------------------------------------------
    def compose(self) -> ComposeResult:
        """Header, content with the vertical softkeys beside it, dialog line, horizontal softkeys
        (and in a browser tab the panel keys to click)."""
        yield AreaHeader(id="header")
        with Horizontal(id="area-body"):
            with Container(id="area-content"):
                yield from self.compose_content()
            yield Static("", id="exercise-side", markup=False)
            yield VerticalSoftkeys(id="vsk")
        yield DialogLine("", id="dialog-line", markup=False)
        yield HorizontalSoftkeys(id="hsk")
        yield PanelKeys(self.hmi.keymap, id="panel-keys")
        yield Static(_(TOO_SMALL_TEXT).format(columns=MIN_TERMINAL_SIZE[0], rows=MIN_TERMINAL_SIZE[1]),
                     id="too-small", markup=False)

    def compose_content(self) -> ComposeResult:
        """Yield the windows of the area (override)."""
        yield from ()

    # -- app and kernel access -----------------------------------------------------------
    @property
    def hmi(self) -> AreaHost:
        """The application, as far as an area may use it (:class:`hmi.host.AreaHost`)."""
        return self.app  # type: ignore[return-value]

    @property
    def access_level(self) -> int:
        """The current access level (0 most, 7 least privileged)."""
        return self.status.access_level if self.status is not None else 7

    @property
    def on_lathe(self) -> bool:
        """True on a lathe: the machine has no geometry axis Y (our choice; the status names no kind)."""
        if self.status is None:
            return False
        linear = {axis.name for axis in self.status.axes if axis.kind == "linear"}
        return "X" in linear and "Z" in linear and "Y" not in linear

    def submit(self, command: Any) -> SubmitResult:
        """Send an operator command to the kernel through the bridge."""
        return self.hmi.submit(command)

    def ask(self, question: object) -> Any:
        """Ask the kernel a read-only question of :mod:`nck.queries` through the bridge."""
        return self.hmi.bridge.query(question)

    # -- softkeys ------------------------------------------------------------------------
    def softkey_menu(self) -> SoftkeyMenu:
        """Return the top softkey level of the area (override)."""
        return SoftkeyMenu.of()

    def current_menu(self) -> SoftkeyMenu:
        """The softkey level on display: the last pushed one, else the top level."""
        return self._menu_stack[-1] if self._menu_stack else self.softkey_menu()

    def push_softkeys(self, menu: SoftkeyMenu) -> None:
        """Show a softkey sub-level; MENU RECALL (F10) returns to the previous one."""
        self._menu_stack.append(menu)
        self.refresh_softkeys()

    def pop_softkeys(self) -> bool:
        """Leave the current sub-level; False when already at the top level."""
        if not self._menu_stack:
            return False
        self._menu_stack.pop()
        self.refresh_softkeys()
        return True

    def clear_softkey_levels(self) -> None:
        """Return to the top softkey level."""
        self._menu_stack.clear()
        self.refresh_softkeys()

    def menu_recall(self) -> bool:
        """MENU RECALL: go back one level (softkey level or view); False if nothing to do.

        Subclasses with views of their own extend this.
        """
        return self.pop_softkeys()

    def refusal_of(self, label: str) -> str:
        """What the message line says when the softkey ``label`` (translated) is greyed by the
        area's state; areas that know the cause more precisely (the editor is read-only) say it."""
        return _("{softkey}: not possible in this state").format(softkey=label)

    def press_softkey(self, slot_id: str) -> bool:
        """Run the softkey in slot ``h1`` … ``v8`` if it is allowed; True if it ran."""
        key = self.current_menu().slot(slot_id)
        if key is None:
            return False
        if not key.allowed(self, self.access_level):
            # the area's message: an accepted command (the keyswitch turned) clears it
            label = one_line(_(key.label))
            if self.access_level > key.level:
                self.say(_("{softkey}: needs access level {level}").format(softkey=label, level=key.level))
            else:
                self.say(self.refusal_of(label))
            return False
        try:
            self.perform(key.action)
        except Exception as exc:  # a broken softkey must not end the operator's session
            report = getattr(self.app, "report_internal_error", None)
            if report is None:
                raise
            report(exc)
            return False
        self.refresh_softkeys()
        return True

    def perform(self, action: str) -> None:
        """Run a softkey action now: ``name(args)`` on this screen, ``app.name(args)`` on the app."""
        target: object = self
        if action.startswith("app."):
            target, action = self.app, action[4:]
        name, _separator, raw_args = action.partition("(")
        args = parse_action(f"x({raw_args}")[2] if raw_args else ()
        method = getattr(target, f"action_{name}", None)
        if method is None:
            raise AttributeError(f"softkey action {action!r} has no action_{name} method")
        method(*args)

    def press_softkey_id(self, softkey_id: str) -> bool:
        """Press the softkey with id ``softkey_id`` on the current level (tests, scripts)."""
        slot = self.current_menu().find(softkey_id)
        return self.press_softkey(slot) if slot else False

    def refresh_softkeys(self) -> None:
        """Redraw both bars from the current level and state."""
        if not self.is_mounted:
            return
        menu = self.current_menu()
        level = self.access_level
        self.query_one(HorizontalSoftkeys).show_menu(menu, self, level)
        self.query_one(VerticalSoftkeys).show_menu(menu, self, level)

    def on_softkey_cell_pressed(self, message: SoftkeyCell.Pressed) -> None:
        """A mouse click on a softkey does what its function key does."""
        self.press_softkey(message.slot_id)

    async def on_panel_key_pressed(self, message: PanelKey.Pressed) -> None:
        """A click on a panel key (browser tab) does what the key does, and an exercise
        records it as that key (the instructor's replay shows the same as for a key press)."""
        self.hmi.exercise_key(message.binding.keys.split(",")[0].strip())
        await self.app.run_action(message.binding.action)

    # -- quitting --------------------------------------------------------------------------
    def unsaved_work(self) -> str:
        """What quitting the HMI now would leave unsaved in this area (``""``: nothing; override)."""
        return ""

    def keep_before_quit(self) -> None:
        """Write what must survive quitting, while the area still exists (override; raise ``OSError``)."""

    # -- status ----------------------------------------------------------------------------
    def show_status(self, status: NckStatus | None) -> None:
        """Take a new snapshot: header, content (:meth:`update_status`) and softkeys."""
        self.status = status
        if not self.is_mounted:
            return
        self.query_one(AreaHeader).show(_(self.AREA_TITLE), status)
        show_text(self.query_one("#exercise-side", Static), self.hmi.exercise_side)
        if status is not None:
            self.update_status(status)
        self.refresh_softkeys()

    def update_status(self, status: NckStatus) -> None:
        """Show a new snapshot in the area's windows (override)."""

    def show_hint(self, text: str) -> None:
        """Write ``text`` on the dialog line (empty clears it)."""
        if self.is_mounted:
            show_text(self.query_one(DialogLine), text)

    def say(self, text: str) -> None:
        """Write ``text`` on this area's dialog line and keep it when the area is shown again.

        A message belongs to its area: other areas do not show it, and an area
        clears it when its cause is gone (a new view, an accepted command).
        """
        self.area_hint = text
        self.hmi.hint = text
        self.show_hint(text)

    def on_mount(self) -> None:
        """Show what is known as soon as the screen exists."""
        self.set_class(bool(self.hmi.exercise_side), "-exercise")  # an exercise's side window
        self.show_status(self.hmi.latest_status)
        self.show_hint(self.area_hint)

    def on_screen_resume(self, event: events.ScreenResume | None = None) -> None:
        """Coming back to the area (area key): show the newest snapshot at once.

        Textual calls this with the event (subclasses that extend it call it
        without). The area's styles need no fresh cascade: nothing restyles a
        hidden area except its own class changes, which Textual applies as they
        happen; skipping the whole-screen restyle makes an area key much faster.
        Once the area shows the newest snapshot the app may repaint.
        """
        self.show_status(self.hmi.latest_status)
        self.show_hint(self.area_hint)
        if event is not None:
            event.refresh_styles = False
            release = getattr(self.app, "release_held_update", None)
            if callable(release):
                release()
