"""Softkeys as a model, and the two softkey bars that show them.

A :class:`Softkey` says what a panel softkey does (an action of the screen),
which access level it needs and when it can be used; a :class:`SoftkeyMenu` is
one softkey level: eight horizontal (F1–F8) and eight vertical (Shift+F1–F8)
slots. The bars only display a menu; the area screen decides what is allowed.

Access levels follow SINUMERIK: 0 is the most privileged, 7 the least
(keyswitch position 0). A softkey with ``level=5`` needs level 5 or better
(0…5).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Sequence

from rich.cells import cell_len
from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widgets import Static

from hmi.i18n import _

Predicate = Callable[[Any], bool]
"""A predicate over the area screen (which offers ``.status``, ``.access_level`` …)."""


WORD_BREAK = re.compile(r"-\n(?=[a-zäöüß])")
"""A label's line break inside a word (``Satz-\nsuchlauf``): on one line the word is whole again."""


def one_line(label: str) -> str:
    """A softkey label on one line: ``Block\nsearch`` → ``Block search``, ``Sub-\nprograms`` →
    ``Subprograms``, ``Programm-\nManager`` → ``Programm-Manager`` (a compound keeps its hyphen)."""
    return " ".join(WORD_BREAK.sub("", label).replace("-\n", "-").split())


@dataclass(frozen=True)
class Softkey:
    """One softkey.

    Attributes:
        id: stable id (``machine.gfunc``), used by tests and training material.
        label: text on the key in English; ``\\n`` splits it over two lines. The bars show it
            in the panel's language (the catalogue ``data/lang/<code>/hmi.po``).
        action: Textual action run on the area screen (``show_view('gfunc')``);
            prefix ``app.`` for an app action.
        level: the least privileged access level that may use it (7 = everybody).
        enabled: predicate: the key can be used in the current state (else greyed).
        active: predicate: a toggle that is on (shown pressed).
    """

    id: str
    label: str
    action: str
    level: int = 7
    enabled: Predicate | None = None
    active: Predicate | None = None
    submenu: str = ""
    """The area screen's method that builds the softkey level this key opens (``"more_menu"``),
    so that the command palette can list that level's softkeys under this key; "" for none."""

    def allowed(self, context: Any, access_level: int) -> bool:
        """True when the access level suffices and the state allows the key."""
        if access_level > self.level:
            return False
        if self.enabled is None:
            return True
        try:
            return bool(self.enabled(context))
        except Exception:  # a predicate that cannot answer greys the key, it never crashes
            return False

    def pressed(self, context: Any) -> bool:
        """True when the key is a toggle that is currently on."""
        if self.active is None:
            return False
        try:
            return bool(self.active(context))
        except Exception:
            return False


def view_softkey(softkey_id: str, label: str, view: str, **options: Any) -> Softkey:
    """A softkey that shows ``view`` of its area and is shown pressed while that view is up."""
    return Softkey(softkey_id, label, f"show_view('{view}')", active=lambda s: s.view == view, **options)


def _pad(keys: Iterable[Softkey | None]) -> tuple[Softkey | None, ...]:
    items = list(keys)[:8]
    return tuple(items + [None] * (8 - len(items)))


@dataclass(frozen=True)
class SoftkeyMenu:
    """One softkey level: up to 8 horizontal and 8 vertical keys (``None`` = empty slot)."""

    horizontal: tuple[Softkey | None, ...] = field(default_factory=lambda: (None,) * 8)
    vertical: tuple[Softkey | None, ...] = field(default_factory=lambda: (None,) * 8)

    @classmethod
    def of(cls, horizontal: Sequence[Softkey | None] = (),
           vertical: Sequence[Softkey | None] = ()) -> SoftkeyMenu:
        """Build a menu, padding both bars to eight slots."""
        return cls(_pad(horizontal), _pad(vertical))

    def slot(self, slot_id: str) -> Softkey | None:
        """Return the key in slot ``h1`` … ``h8`` or ``v1`` … ``v8``."""
        bar = self.horizontal if slot_id[0] == "h" else self.vertical
        index = int(slot_id[1:]) - 1
        return bar[index] if 0 <= index < len(bar) else None

    def find(self, softkey_id: str) -> str | None:
        """Return the slot id holding the softkey ``softkey_id``, or None."""
        for prefix, bar in (("h", self.horizontal), ("v", self.vertical)):
            for index, key in enumerate(bar):
                if key is not None and key.id == softkey_id:
                    return f"{prefix}{index + 1}"
        return None


@dataclass(frozen=True, slots=True)
class SoftkeyView:
    """What one softkey cell shows: label, key hint, and its state classes."""

    label: str
    hint: str
    allowed: bool
    pressed: bool
    empty: bool


def label_in_width(hint: str, label: str, width: int) -> str:
    """A softkey's ``label`` as its cell shows it after ``hint``: the lines run on (the cell wraps
    them at its edge), and a word the label breaks with a hyphen (``Setting-\ndaten``) is whole
    (``Settingdaten``) when the cell is ``width`` wide enough for the label on one line."""
    whole = one_line(label)
    return whole if 0 < width and cell_len(f"{hint} {whole}") <= width else label.replace("\n", " ")


class SoftkeyCell(Static):
    """One softkey on the panel (a cell of a bar)."""

    class Pressed(Message):
        """The softkey was clicked with the mouse (keys go through F1–F8 instead)."""

        def __init__(self, slot_id: str) -> None:
            super().__init__()
            self.slot_id = slot_id

    def __init__(self, slot_id: str, hint: str) -> None:
        super().__init__("", id=f"sk-{slot_id}", classes="softkey -empty", markup=False)
        self.slot_id = slot_id
        self.hint = hint
        self._shown: SoftkeyView | None = None

    def show(self, view: SoftkeyView) -> None:
        """Display ``view``; does nothing when it is unchanged."""
        if view == self._shown:
            return
        self._shown = view
        self.set_class(view.empty, "-empty")
        self.set_class(not view.allowed and not view.empty, "-disabled")
        self.set_class(view.pressed, "-active")
        self._draw()

    def _draw(self) -> None:
        """Write the shown view's hint and label for the cell's width now."""
        view = self._shown
        text = Text()
        if view is not None and not view.empty:
            text.append(f"{view.hint} ", style="dim")
            text.append(label_in_width(view.hint, view.label, self.content_size.width))
        self.update(text, layout=False)

    def on_resize(self) -> None:
        """The cell's width changed (and is known after the first layout): draw the label for it."""
        if self._shown is not None:
            self._draw()

    def on_click(self) -> None:
        """Mouse users may click a softkey; it does the same as its function key."""
        self.post_message(self.Pressed(self.slot_id))


class _SoftkeyBar:
    """Shared behaviour of both bars."""

    PREFIX = "h"

    def show_menu(self, menu: SoftkeyMenu, context: Any, access_level: int) -> None:
        """Show the keys of ``menu`` for ``context`` at ``access_level``."""
        keys = menu.horizontal if self.PREFIX == "h" else menu.vertical
        for index, key in enumerate(keys):
            cell = self.query_one(f"#sk-{self.PREFIX}{index + 1}", SoftkeyCell)  # type: ignore[attr-defined]
            if key is None:
                cell.show(SoftkeyView("", cell.hint, False, False, True))
            else:
                cell.show(SoftkeyView(_(key.label), cell.hint, key.allowed(context, access_level),
                                      key.pressed(context), False))


class HorizontalSoftkeys(_SoftkeyBar, Horizontal):
    """The eight horizontal softkeys under the screen (F1–F8)."""

    PREFIX = "h"

    def compose(self) -> ComposeResult:
        """Eight cells."""
        for index in range(1, 9):
            yield SoftkeyCell(f"h{index}", f"F{index}")


class VerticalSoftkeys(_SoftkeyBar, Vertical):
    """The eight vertical softkeys beside the screen (Shift+F1–F8)."""

    PREFIX = "v"

    def compose(self) -> ComposeResult:
        """Eight cells."""
        for index in range(1, 9):
            yield SoftkeyCell(f"v{index}", f"⇧F{index}")
