"""The descriptions Textual's own widgets give their keys, marked for the catalogue.

The F11 help lists the keys the area and its focused widget bind (:func:`hmi.help.area_keys`),
each with its binding's description in the panel's language. The panel's own bindings are
written with ``Binding(…)`` and found in the source; the widgets Textual brings (an input
field, the program editor's text area, a table, the program tree, the palette) declare
theirs in Textual's code. This table holds those texts (as Textual 8.2 writes them), so
that the catalogue translates them too; ``tests/i18n/test_widget_keys.py`` fails when a widget
of :data:`TEXTUAL_WIDGETS` describes a key with a text not listed here (a new Textual).
"""

from __future__ import annotations

from textual.command import CommandPalette
from textual.containers import VerticalScroll
from textual.screen import Screen
from textual.widgets import DataTable, Input, OptionList, TextArea, Tree

from hmi.i18n import N_

TEXTUAL_WIDGETS = (Input, TextArea, DataTable, Tree, OptionList, VerticalScroll, CommandPalette, Screen)
"""The Textual widgets (and their bases) whose keys the panel lets through to the operator."""

TEXTUAL_KEY_DESCRIPTIONS = (
    N_("Move cursor left"),
    N_("Move cursor left and select"),
    N_("Move cursor left a word"),
    N_("Move cursor left a word and select"),
    N_("Move cursor right or accept the completion suggestion"),
    N_("Move cursor right and select"),
    N_("Move cursor right a word"),
    N_("Move cursor right a word and select"),
    N_("Delete character left"),
    N_("Select all"),
    N_("Go to start"),
    N_("Go to end"),
    N_("Select line start"),
    N_("Select line end"),
    N_("Delete character right"),
    N_("Submit"),
    N_("Delete left to start of word"),
    N_("Delete all to the left"),
    N_("Delete right to start of word"),
    N_("Delete all to the right"),
    N_("Cut selected text"),
    N_("Copy selected text"),
    N_("Paste text from the clipboard"),
    N_("Scroll Up"),
    N_("Scroll Down"),
    N_("Scroll Left"),
    N_("Scroll Right"),
    N_("Scroll Home"),
    N_("Scroll End"),
    N_("Page Up"),
    N_("Page Down"),
    N_("Page Left"),
    N_("Page Right"),
    N_("Cursor up"),
    N_("Cursor down"),
    N_("Cursor left"),
    N_("Cursor right"),
    N_("Cursor word left"),
    N_("Cursor word right"),
    N_("Cursor line start"),
    N_("Cursor line end"),
    N_("Cursor page up"),
    N_("Cursor page down"),
    N_("Cursor left word select"),
    N_("Cursor right word select"),
    N_("Cursor line start select"),
    N_("Cursor line end select"),
    N_("Cursor up select"),
    N_("Cursor down select"),
    N_("Cursor left select"),
    N_("Cursor right select"),
    N_("Select line"),
    N_("Cut"),
    N_("Copy"),
    N_("Paste"),
    N_("Delete to line start"),
    N_("Delete to line end"),
    N_("Delete line"),
    N_("Undo"),
    N_("Redo"),
    N_("Select"),
    N_("Page up"),
    N_("Page down"),
    N_("Top"),
    N_("Bottom"),
    N_("Home"),
    N_("End"),
    N_("Cursor to parent"),
    N_("Cursor to next ancestor"),
    N_("Cursor to previous sibling"),
    N_("Cursor to next sibling"),
    N_("Toggle"),
    N_("Expand or collapse all"),
    N_("Cursor Up"),
    N_("Cursor Down"),
    N_("Down"),
    N_("Last"),
    N_("First"),
    N_("Up"),
    N_("Go to bottom"),
    N_("Go to top"),
    N_("Next command"),
    N_("Exit the command palette"),
    N_("Next page"),
    N_("Previous page"),
    N_("Previous command"),
    N_("Focus Next"),
    N_("Focus Previous"),
)
"""Every description of a key binding of :data:`TEXTUAL_WIDGETS` (each once)."""
