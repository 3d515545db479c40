"""Messages of the Diagnostics and Machine areas that were English on a German panel (issue 27,
found walking the panel): the trace's refusals of its settings, the alarm log filter's reversed
range, the block search's empty target."""

from __future__ import annotations

import pytest

from hmi.i18n import _, error_text
from nck import TraceError
from nck.trace import TraceSettings, validate
from hmi.area import DialogLine
from screens.diagnostics_alarms import parse_filter
from tests.burst import burst
from tests.hmi.conftest import SIZE
from tests.hmi.test_workflows import programs, real_app, select_in_auto, text_of  # noqa: F401 - the programs fixture


def test_a_trace_setting_is_refused_in_german(german: None) -> None:
    with pytest.raises(TraceError) as refused:
        validate(TraceSettings(signals=(), trigger="now", duration_s=1.0), machine=None)
    assert str(refused.value) == "choose at least one signal"  # the command line's English
    assert error_text(refused.value) == "mindestens ein Signal wählen"
    assert error_text(TraceError("trace_duration")) == "die Dauer muss größer als 0 s sein"


def test_a_reversed_number_range_of_the_alarm_log_filter_is_refused_in_german(german: None) -> None:
    with pytest.raises(ValueError, match="^Nummernbereich 20-10: die erste Nummer darf nicht größer"):
        parse_filter("20-10")


async def test_the_block_search_asks_for_its_target_in_german(german: None, programs) -> None:  # noqa: F811
    """AUTO, STEP.MPF selected, F5 Block search, Enter on the empty field: the window's title
    names the search type and the dialog line asks for the target, both in German."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await burst(pilot, "f5", "enter")
        assert text_of(app, "#search-title").strip() == "Satzsuchlauf mit Berechnung, Kontur"
        assert str(app.screen.query_one(DialogLine).render()).strip() == "Satznummer oder Suchtext eingeben"


async def test_a_greyed_softkey_is_named_whole_in_german(tmp_path) -> None:
    """Machine area in JOG, F4 (Program control, greyed there): the message names the softkey as
    one word (Programm-/beeinfl. -> Programmbeeinfl.), not with the label's line break."""
    from hmi.app import make_app
    from tests.burst import burst
    from tests.hmi.conftest import SIZE

    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        async with app.run_test(size=SIZE) as pilot:
            await burst(pilot, "alt+m", "f4")
            line = str(app.screen.query_one("#dialog-line").render()).strip()
    finally:
        app.nc_session.quit()
    assert line == "Programmbeeinfl.: in diesem Zustand nicht möglich"


def test_the_block_search_types_title_is_german(german: None) -> None:
    """The search window's title names the search type (was English after 'Satzsuchlauf')."""
    from screens.machine import SEARCH_MODES

    assert [_(SEARCH_MODES[mode]) for mode in ("contour", "end_point", "without_calculation", "serupro")] == [
        "mit Berechnung, Kontur", "mit Berechnung, Endpunkt", "ohne Berechnung", "über Programmtest (SERUPRO)"]


def test_the_parameter_areas_sentences_built_with_values_are_german(german: None) -> None:
    """Sentences with values (a level, a frame, an axis) were built as English f-strings: now
    templates of the catalogue (the table window, the edit dialog's line, the material view)."""
    assert _("Reading tool offsets needs access level {needed} (current level {current})").format(
        needed=4, current=7) == "Lesen der Werkzeugkorrekturen erfordert Zugriffsstufe 4 (aktuelle Stufe 7)"
    assert _("{frame} rotation about {axis} in degrees (-360 … 360)").format(frame="G54", axis="Z") == (
        "G54 Drehung um Z in Grad (-360 … 360)")
    assert _("block {number}/{count}, line {line}: {modal}").format(number=3, count=9, line=12, modal="G1") == (
        "Satz 3/9, Zeile 12: G1")


def test_a_cycle_call_the_form_cannot_show_is_said_in_german(german: None) -> None:
    from hmi.cycle_forms import read_call

    assert read_call("CYCLE81(1,2,3,4,5,6)") == "CYCLE81: mehr als 5 Parameter, die Eingabemaske kann den Aufruf nicht zeigen"
