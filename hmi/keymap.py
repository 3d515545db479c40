"""The key bindings of the operator panel and machine control panel, read from ``data/keymap.toml``.

The table is the one place where keys live: the app builds its Textual bindings
from it, the help overlay (F11) lists it, and the tests read it to press the
same keys an operator would.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

from textual.binding import Binding

from nck.queries import load_toml

ACTIONS: frozenset[str] = frozenset(
    {
        "switch_area", "softkey", "menu_select", "menu_recall", "help", "alarm_cancel",
        "quit_hmi", "mode", "machine_function", "cycle_increment", "single_block",
        "cycle_start", "cycle_stop", "reset", "select_axis", "select_spindle", "jog",
        "rapid_overlay", "feed_override", "spindle_override", "keyswitch", "emergency_stop",
        "handwheel", "command_palette",
    }
)
"""Every action id a key may name (the ``action_<id>`` methods of the app)."""

SCOPES = ("op", "mcp", "softkey")


class KeymapError(ValueError):
    """``data/keymap.toml`` names an unknown action, a duplicate key or id, or misses a field."""


@dataclass(frozen=True, slots=True)
class KeyBinding:
    """One key of the table.

    Attributes:
        id: dotted binding id (``nc.cycle_start``).
        keys: Textual key names, comma separated (``alt+g``).
        action: action with arguments, e.g. ``switch_area('machine')``.
        label: short description for the help overlay.
        panel: the SINUMERIK panel key it stands for.
        scope: ``op``, ``mcp`` or ``softkey``.
        button: text of its clickable key in a browser tab (``""``: no button).
    """

    id: str
    keys: str
    action: str
    label: str
    panel: str
    scope: str
    button: str = ""

    @property
    def action_name(self) -> str:
        """The action id without its arguments."""
        return self.action.split("(", 1)[0]

    @property
    def key_display(self) -> str:
        """The keys as an operator reads them: ``Alt+G``, ``Shift+F1``, ``Ctrl+PgUp``."""
        return ", ".join(display_key(k.strip()) for k in self.keys.split(","))

    def to_binding(self) -> Binding:
        """Return the Textual binding (priority, so MCP keys work while an editor has focus)."""
        return Binding(
            self.keys, self.action, self.label, show=False, priority=True, id=self.id,
            key_display=self.key_display,
        )


@dataclass(frozen=True, slots=True)
class Switches:
    """Switch positions of the MCP (override tables, JOG increments)."""

    feed_override_percent: tuple[float, ...]
    spindle_override_percent: tuple[float, ...]
    increments: tuple[int, ...]
    jog_release_ms: int


@dataclass(frozen=True, slots=True)
class Keymap:
    """The whole table: bindings in file order and the switch positions."""

    bindings: tuple[KeyBinding, ...]
    switches: Switches

    def by_id(self, binding_id: str) -> KeyBinding:
        """Return the binding with this id (KeyError if there is none)."""
        for binding in self.bindings:
            if binding.id == binding_id:
                return binding
        raise KeyError(binding_id)

    def key_of(self, binding_id: str) -> str:
        """Return the first Textual key name of a binding id (what tests press)."""
        return self.by_id(binding_id).keys.split(",")[0].strip()


_NAMED = {
    "pageup": "PgUp", "pagedown": "PgDn", "right": "Right", "left": "Left", "up": "Up",
    "down": "Down", "escape": "Esc", "enter": "Enter",
}


def display_key(key: str) -> str:
    """Return a Textual key name in panel notation (``ctrl+pageup`` → ``Ctrl+PgUp``)."""
    parts = key.split("+")
    shown = []
    for part in parts:
        if part in _NAMED:
            shown.append(_NAMED[part])
        elif re.fullmatch(r"f\d+", part):
            shown.append(part.upper())
        elif len(part) == 1:
            shown.append(part.upper())
        else:
            shown.append(part.capitalize())
    return "+".join(shown)


def parse_keymap(table: dict) -> Keymap:
    """Check and convert the TOML table of ``data/keymap.toml``.

    Raises:
        KeymapError: listing every problem found (not only the first).
    """
    problems: list[str] = []
    bindings: list[KeyBinding] = []
    seen_ids: set[str] = set()
    seen_keys: set[str] = set()
    for index, entry in enumerate(table.get("key", []), start=1):
        missing = [f for f in ("id", "key", "action", "label") if f not in entry]
        if missing:
            problems.append(f"key #{index}: missing {', '.join(missing)}")
            continue
        binding = KeyBinding(
            id=entry["id"], keys=entry["key"], action=entry["action"], label=entry["label"],
            panel=entry.get("panel", ""), scope=entry.get("scope", "op"), button=entry.get("button", ""),
        )
        if binding.action_name not in ACTIONS:
            problems.append(f"key {binding.id}: unknown action {binding.action_name!r}")
        if binding.scope not in SCOPES:
            problems.append(f"key {binding.id}: unknown scope {binding.scope!r}")
        if binding.id in seen_ids:
            problems.append(f"key {binding.id}: id used twice")
        for key in (k.strip() for k in binding.keys.split(",")):
            if key in seen_keys:
                problems.append(f"key {binding.id}: {key} bound twice")
            seen_keys.add(key)
        seen_ids.add(binding.id)
        bindings.append(binding)
    raw = table.get("switches", {})
    try:
        switches = Switches(
            feed_override_percent=tuple(float(v) for v in raw["feed_override_percent"]),
            spindle_override_percent=tuple(float(v) for v in raw["spindle_override_percent"]),
            increments=tuple(int(v) for v in raw["increments"]),
            jog_release_ms=int(raw.get("jog_release_ms", 150)),
        )
    except (KeyError, TypeError, ValueError) as exc:
        problems.append(f"[switches]: {exc}")
        switches = Switches((100.0,), (100.0,), (1,), 150)
    if problems:
        raise KeymapError("data/keymap.toml: " + "; ".join(problems))
    return Keymap(bindings=tuple(bindings), switches=switches)


@functools.cache
def default_keymap() -> Keymap:
    """Return the product's keymap (``data/keymap.toml``), checked."""
    return parse_keymap(load_toml("keymap.toml"))
