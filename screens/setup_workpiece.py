"""The Setup area's "Machine set-up" list: the blank, the reference block and the instructor's switch.

One row per field of ``nck setup`` (the field names are shown too, so that a lesson
prepared on the panel can be repeated on the command line). While the blank is hidden, a
trainee below the level that may change the set-up sees "hidden" instead of its position
and size: the trainee has to find the blank by measuring (issue 22).
"""

from __future__ import annotations

from typing import Any

from nck.queries import setup_fields

from hmi.widgets.data_table import Cell, Column, DataTable

HIDDEN_TEXT = "hidden"
TITLE = "Machine set-up: what is clamped (positions in the MCS)"


def workpiece_table(setup: Any, level: int, needed_level: int) -> DataTable:
    """The set-up ``setup`` as an editable table for access ``level``; edits need ``needed_level``."""
    concealed = setup.hidden and level > needed_level
    columns = [Column("Field", 46, "<"), Column("Value", 14), Column("Unit", 5, "<"),
               Column("Name (nck setup)", 20, "<")]
    rows = []
    for field in setup_fields(setup):
        secret = concealed and field.position
        text = HIDDEN_TEXT if secret else field.text
        hint = (f"{field.label}: " + ("box, cylinder or none" if field.name == "blank.shape" else
                                      "box or none" if field.name == "reference.shape" else
                                      "yes or no" if field.name == "hidden" else f"{field.unit}, MCS"))
        rows.append([Cell(field.label), Cell(text, field.name, "" if secret else field.text, needed_level, hint),
                     Cell("" if secret else field.unit), Cell(field.name)])
    note = (f"Enter edit (level {needed_level})   the blank's position is hidden from the trainee"
            if concealed else f"Enter edit (level {needed_level})   ⇧F1 hides / shows the blank's position")
    return DataTable(TITLE, columns, rows, note)
