"""The Machine set-up table of the Setup area (``screens.setup_workpiece``)."""

from __future__ import annotations

import pytest

from hmi.i18n import set_language
from nck.workpiece import default_machine_setup
from screens.setup_workpiece import workpiece_table


@pytest.mark.parametrize("language", ["en", "de"])
def test_the_field_column_holds_every_label(language: str) -> None:
    """No label of the table is cut short (the longest, the reference block's rotation, was
    shown as "Rotation about Z (about its …")."""
    set_language(language)
    try:
        table = workpiece_table(default_machine_setup("mill"), level=4, needed_level=2)
    finally:
        set_language("en")
    labels = [row[0].text for row in table.rows]
    assert any("Rotation" in label or "Drehung" in label for label in labels)
    assert max(len(label) for label in labels) <= table.columns[0].width
