"""Units with an English word in them are said in German on a German panel (issue 27): the
service screens' "bits" (referenced status) and degrees of a rotary axis or spindle."""

from __future__ import annotations

from hmi.i18n import _
from screens.diagnostics_service import rows_text


def test_the_service_screens_units_are_german(german: None) -> None:
    text = rows_text("Achse", [("Referenced status", "1", "bits"), ("Position setpoint", "90.000", "deg"),
                              ("Velocity actual value", "0.0", "deg/min")]).plain
    lines = text.splitlines()
    assert lines[2].startswith(" Referenzierstatus") and lines[2].split()[-2:] == ["1", "Bit"]
    assert lines[3].split()[-1] == "Grad" and lines[4].split()[-1] == "Grad/min"
    assert _("rev/min") == "U/min"


def test_a_softkey_label_broken_with_a_hyphen_is_whole_where_the_cell_has_room() -> None:
    """F6 Setting-/daten in a horizontal cell (19 columns) reads Settingdaten; a vertical cell
    (13 columns) keeps the break where the whole word would not fit (Rück-/übersetzen)."""
    from hmi.softkeys import label_in_width

    assert label_in_width("F6", "Setting-\ndaten", 19) == "Settingdaten"
    assert label_in_width("⇧F7", "Zyklen / Rück-\nübersetzen", 13) == "Zyklen / Rück- übersetzen"
    assert label_in_width("F5", "Block\nsearch", 19) == "Block search"
    assert label_in_width("F6", "Setting-\ndaten", 0) == "Setting- daten"  # before the first layout
