"""The machine control panel (MCP) of the HMI: mode keys, NC START/STOP/RESET, axes, switches.

:class:`MachineControlPanel` is a mixin of the app: its ``action_*`` methods are
the targets of the MCP keys of ``data/keymap.toml``. Every effect on the kernel
goes through ``self.submit`` (the bridge); the panel's own state (selected
axis, rapid overlay, single block type, the held + / − key) lives here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from textual.timer import Timer
from textual.widgets import Input, TextArea

from nck import commands as cmd
from nck.commands import Accepted, Rejected
from nck.status import NckStatus

from hmi.i18n import _

AXIS_KEY_NAMES = ("X", "Y", "Z")
"""The axis keys 1-3 of the machine control panel select the axis of this name (a lathe's
panel has X and Z keys); the key after them selects the 4th axis by its position."""

if TYPE_CHECKING:
    from hmi.area import AreaBase
    from hmi.bridge import NckBridge
    from hmi.keymap import Keymap


def _next_position(table: tuple[float, ...], current: float, step: int) -> float:
    """Return the switch position ``step`` positions from the one nearest ``current``."""
    nearest = min(range(len(table)), key=lambda i: abs(table[i] - current))
    return table[max(0, min(len(table) - 1, nearest + step))]


class MachineControlPanel:
    """MCP actions and state, mixed into the app (which provides submit, bridge, keymap …)."""

    if TYPE_CHECKING:
        bridge: NckBridge
        keymap: Keymap
        area_screen: AreaBase | None
        focused: Any
        current_mode: str

        def submit(self, command: Any, answers_refusal: bool = True) -> Any: ...
        def set_hint(self, text: str) -> None: ...
        def set_timer(self, delay: float, callback: Any) -> Timer: ...

    def init_panel(self) -> None:
        """Start state: axis 1 selected, rapid overlay off, single block type SBL1."""
        self.selected_axis_index = 0
        self.spindle_selected = False
        self.rapid_overlay = False
        self.single_block_type = "SBL1"
        self._jog_release_timer: Timer | None = None
        self._jogging: tuple[str, int] | None = None  # (axis, direction) of the held + / − key
        self.estop_pressed = False
        self._keyswitch_turned_to: int | None = None

    def _status(self) -> NckStatus:
        return self.bridge.status

    def action_mode(self, mode: str) -> None:
        """Mode keys JOG / MDA / AUTO (JOG again leaves REF/REPOS/INC)."""
        status = self._status()
        if mode == status.channel.mode == "JOG" and status.channel.machine_function:
            self.submit(cmd.SelectMachineFunction(None))
            return
        self.submit(cmd.SelectMode(mode))

    def action_machine_function(self, function: str) -> None:
        """REF POINT / REPOS keys: toggle the machine function in JOG."""
        current = self._status().channel.machine_function
        self.submit(cmd.SelectMachineFunction(None if current == function else function))

    def action_cycle_increment(self) -> None:
        """INC key: continuous → 1 → 10 → 100 → 1000 → 10000 → VAR → 1 …"""
        channel = self._status().channel
        steps: list[int | None] = [*self.keymap.switches.increments, None]
        if channel.machine_function != "INC":
            nxt = steps[0]
        else:
            try:
                nxt = steps[(steps.index(channel.increment) + 1) % len(steps)]
            except ValueError:
                nxt = steps[0]
        if isinstance(self.submit(cmd.SelectIncrement(nxt)), Rejected):
            return
        if channel.machine_function != "INC":
            self.submit(cmd.SelectMachineFunction("INC"))

    def action_single_block(self) -> None:
        """SINGLE BLOCK: toggle single block (of the type chosen in program control)."""
        current = self._status().channel.program_control.get("single_block")
        self.submit(cmd.SetProgramControl("single_block", None if current else self.single_block_type))

    def action_cycle_start(self) -> None:
        """CYCLE START (NC START); in MDA the editor's text is the program."""
        area = self.area_screen
        before = getattr(area, "before_cycle_start", None)
        if callable(before) and before() is False:
            return  # the area said why there is nothing to start (a JOG window with a wrong entry)
        self.submit(cmd.CycleStart())

    def action_cycle_stop(self) -> None:
        """CYCLE STOP (NC STOP)."""
        self.submit(cmd.CycleStop())

    def action_reset(self) -> None:
        """RESET of the channel / mode group."""
        self._release_jog()
        self.submit(cmd.Reset())

    def axis_names(self) -> tuple[str, ...]:
        """Names of the path axes (not spindles), as the status shows them."""
        return tuple(a.name for a in self._status().axes if a.kind != "spindle")

    def spindle_names(self) -> tuple[str, ...]:
        """Names of the spindles."""
        return tuple(a.name for a in self._status().axes if a.kind == "spindle")

    @property
    def selected_axis(self) -> str | None:
        """The axis the + / − keys traverse."""
        if self.spindle_selected:
            spindles = self.spindle_names()
            return spindles[0] if spindles else None
        axes = self.axis_names()
        return axes[self.selected_axis_index] if self.selected_axis_index < len(axes) else None

    def action_select_axis(self, index: int) -> None:
        """Axis keys X, Y, Z (the axis of that name: on the lathe X and Z), 4th axis (by position)."""
        axes = self.axis_names()
        if index < len(AXIS_KEY_NAMES):
            name = AXIS_KEY_NAMES[index]
            if name not in axes:
                self.set_hint(_("This machine has no axis {name}").format(name=name))
                return
            index = axes.index(name)
        if index >= len(axes):
            self.set_hint(_("This machine has no axis {name}").format(name=index + 1))
            return
        self.selected_axis_index = index
        self.spindle_selected = False
        self._refresh_area()

    def action_select_spindle(self) -> None:
        """Spindle key."""
        if not self.spindle_names():
            self.set_hint(_("This machine has no spindle"))
            return
        self.spindle_selected = True
        self._refresh_area()

    def action_rapid_overlay(self) -> None:
        """RAPID: toggle the rapid traverse overlay for JOG."""
        self.rapid_overlay = not self.rapid_overlay
        self._refresh_area()

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Let Ctrl+Left/Right reach a focused text editor unless they can jog.

        The + / − keys traverse an axis in the Machine area in JOG (and in REF /
        REPOS); anywhere else with an editor or input field focused, the keys keep
        their editing meaning (word left / right).
        """
        if action == "jog" and isinstance(self.focused, (TextArea, Input)):
            channel = self._status().channel
            can_jog = channel.mode == "JOG" or channel.machine_function in ("REF", "REPOS")
            if not (can_jog and self.current_mode == "machine"):
                return False
        return True

    def action_jog(self, direction: int) -> None:
        """+ / − keys: traverse the selected axis.

        In INC each press is one increment; in continuous JOG the axis moves while
        the key repeats and stops ``jog_release_ms`` after the last repeat.
        """
        axis = self.selected_axis
        if axis is None:
            self.set_hint(_("No axis selected"))
            return
        channel = self._status().channel
        continuous = channel.machine_function != "INC"
        if continuous and self._jogging == (axis, direction) and self._jog_release_timer:
            self._jog_release_timer.reset()
            return
        if self._jogging is not None:
            self._release_jog()
        result = self.submit(cmd.Jog(axis, direction, rapid=self.rapid_overlay))
        if continuous and isinstance(result, Accepted):
            self._jogging = (axis, direction)
            if self.bridge.realtime:
                delay = self.keymap.switches.jog_release_ms / 1000
                self._jog_release_timer = self.set_timer(delay, self._release_jog)

    def action_handwheel(self, detents: int) -> None:
        """Handwheel on the keyboard: one detent moves the selected axis by the INC increment.

        The increment keys give the handwheel its weighting, so it moves only with INC
        selected (our reading of the panel: INC 1/10/100… weights the handwheel); in
        continuous JOG the dialog line says so. Detents add up like INC presses.
        """
        axis = self.selected_axis
        if axis is None:
            self.set_hint(_("No axis selected"))
            return
        if self._status().channel.machine_function != "INC":
            self.set_hint(_("Handwheel: select its weighting with INC (Alt+I) first"))
            return
        self.submit(cmd.Jog(axis, 1 if detents > 0 else -1))

    def _release_jog(self) -> None:
        """The + / − key was let go: stop continuous JOG."""
        if self._jog_release_timer is not None:
            self._jog_release_timer.stop()
            self._jog_release_timer = None
        if self._jogging is not None:
            axis = self._jogging[0]
            self._jogging = None
            self.submit(cmd.Jog(axis, 0), answers_refusal=False)

    def release_jog(self) -> None:
        """Tests: let go of the + / − key (the realtime app does this by timer)."""
        self._release_jog()

    def action_feed_override(self, step: int) -> None:
        """Feed override switch one position up / down."""
        current = float(self._status().channel.overrides.get("feed", 100.0))
        table = self.keymap.switches.feed_override_percent
        self.submit(cmd.SetOverride("feed", _next_position(table, current, step)))

    def action_spindle_override(self, step: int) -> None:
        """Spindle override switch one position up / down."""
        current = float(self._status().channel.overrides.get("spindle", 100.0))
        table = self.keymap.switches.spindle_override_percent
        self.submit(cmd.SetOverride("spindle", _next_position(table, current, step)))

    def keyswitch_position(self) -> int:
        """The keyswitch position.

        The snapshot's ``keyswitch_position`` when the kernel reports it; else the
        position this panel last turned the switch to; else (at start) the one the
        access level implies (levels 7…4 are positions 0…3; a password hides it: 0).
        """
        status = self._status()
        position = getattr(status, "keyswitch_position", None)
        if isinstance(position, int):
            return position
        if self._keyswitch_turned_to is not None:
            return self._keyswitch_turned_to
        level = status.access_level
        return 7 - level if 4 <= level <= 7 else 0

    def action_keyswitch(self) -> None:
        """Keyswitch: 0 → 1 → 2 → 3 → 0 (levels 7 → 6 → 5 → 4)."""
        target = (self.keyswitch_position() + 1) % 4
        if isinstance(self.submit(cmd.SetKeyswitch(target)), Accepted):
            self._keyswitch_turned_to = target

    def _refresh_area(self) -> None:
        area = self.area_screen
        if area is not None:
            area.show_status(self.bridge.status)

    def action_emergency_stop(self) -> None:
        """EMERGENCY STOP mushroom: press, or release (RESET then acknowledges alarm 3000)."""
        self._release_jog()
        result = self.submit(cmd.EmergencyStop(pressed=not self.estop_pressed))
        if isinstance(result, Accepted):
            self.estop_pressed = not self.estop_pressed
            self._refresh_area()
