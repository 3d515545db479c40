"""The Setup area's "Machine set-up" list: the blank, the reference block and the instructor's switch.

One row per field of ``nck setup`` (the field names are shown too, so that a lesson
prepared on the panel can be repeated on the command line). While the blank is hidden, a
trainee below the level that may change the set-up sees "hidden" instead of its position
and size: the trainee has to find the blank by measuring (issue 22).
"""

from __future__ import annotations

from typing import Any

from nck.queries import setup_fields

from hmi.i18n import N_, _
from hmi.widgets.data_table import Cell, Column, DataTable, widest_text

HIDDEN_TEXT = N_("hidden")
TITLE = N_("Machine set-up: what is clamped (positions in the MCS)")
LABEL_PARTS = (
    N_("Blank"), N_("Reference block"), N_("shape"), N_("Blank hidden from the trainee"),
    N_("Position X (smallest corner)"), N_("Position Y (smallest corner)"), N_("Position Z (smallest corner)"),
    N_("Size X"), N_("Size Y"), N_("Size Z"), N_("Rotation about Z (about its centre)"),
    N_("Position X (lower face centre)"), N_("Position Y (lower face centre)"), N_("Position Z (lower face centre)"),
    N_("Diameter"), N_("Length"),
)
"""The pieces of the fields' labels ``nck setup`` gives (``Blank: Size X``), translated where shown."""
FIELD_VALUES = (N_("box"), N_("cylinder"), N_("none"), N_("yes"), N_("no"))
"""The word values of the fields (shapes, the hidden switch): shown translated, typed in English."""


def field_label(english: str) -> str:
    """A field's label (``Blank: Size X``) in the panel's language, piece by piece."""
    return ": ".join(_(part) for part in english.split(": "))


def workpiece_table(setup: Any, level: int, needed_level: int) -> DataTable:
    """The set-up ``setup`` as an editable table for access ``level``; edits need ``needed_level``."""
    concealed = setup.hidden and level > needed_level
    rows = []
    for field in setup_fields(setup):
        secret = concealed and field.position
        text = _(HIDDEN_TEXT) if secret else _(field.text)
        label = field_label(field.label)
        hint = (f"{label}: " + (_("box, cylinder or none") if field.name == "blank.shape" else
                                _("box or none") if field.name == "reference.shape" else
                                _("yes or no") if field.name == "hidden" else f"{field.unit}, MCS"))
        rows.append([Cell(label), Cell(text, field.name, "" if secret else field.text, needed_level, hint),
                     Cell("" if secret else field.unit), Cell(field.name)])
    columns = [Column("Field", widest_text(rows, 0, 46), "<"), Column("Value", 14), Column("Unit", 5, "<"),
               Column("Name (nck setup)", 20, "<")]
    note = (_("Enter edit (level {level})   the blank's position is hidden from the trainee") if concealed
            else _("Enter edit (level {level})   ⇧F1 hides / shows the blank's position")).format(level=needed_level)
    return DataTable(TITLE, columns, rows, note)
