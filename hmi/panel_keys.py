"""Clickable panel keys for the panel in a browser tab (``hmi --serve``, issue 26).

A browser keeps some keys for itself (tab switching, full screen, closing the tab …),
and a trainee at a classroom seat may simply prefer the mouse. Under the softkeys
(which are clickable anyway) a browser tab shows two rows of keys: the operator
panel's (areas, MENU SELECT, RECALL, HELP, ALARM CANCEL) and the machine control
panel's (modes, START/STOP/RESET, axes, overrides, keyswitch, E-STOP). Which keys
appear and their text come from the keymap's ``button`` field (``data/keymap.toml``);
a click runs the key's action as the key would. In a terminal the rows are hidden.
"""

from __future__ import annotations

from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widgets import Static

from hmi.keymap import KeyBinding, Keymap

ROWS = ("op", "mcp")
"""One row per panel: operator panel, machine control panel (keymap scopes)."""


class PanelKey(Static):
    """One clickable key: shows its button text, posts :class:`PanelKey.Pressed` when clicked."""

    class Pressed(Message):
        """The key was clicked."""

        def __init__(self, binding: KeyBinding) -> None:
            super().__init__()
            self.binding = binding

    def __init__(self, binding: KeyBinding) -> None:
        super().__init__(binding.button, id=f"pk-{binding.id.replace('.', '-')}",
                         classes=f"panel-key -{binding.scope}", markup=False)
        self.binding = binding
        self.tooltip = f"{binding.label} ({binding.key_display})"

    def on_click(self) -> None:
        """Do what the key does."""
        self.post_message(self.Pressed(self.binding))


class PanelKeys(Vertical):
    """The operator panel's and machine control panel's keys as two rows; shown only in a browser."""

    def __init__(self, keymap: Keymap, **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self.keymap = keymap

    def compose(self) -> ComposeResult:
        """The two rows of keys, in a browser only: in a terminal the hidden rows would be 36
        widgets more to build and style in every area screen (a third of the Machine area's)."""
        if not self.app.is_web:
            return
        for scope in ROWS:
            with Horizontal(classes="panel-keys-row"):
                for binding in self.keymap.bindings:
                    if binding.button and binding.scope == scope:
                        yield PanelKey(binding)

    def on_mount(self) -> None:
        self.display = self.app.is_web
