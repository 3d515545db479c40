"""Sentences the kernel writes for the panel (``nck.phrase.Phrase``) are said in the panel's
language: the simulation's events (issue 27), a field that is itself a phrase too."""

from __future__ import annotations

import pytest

from hmi.i18n import reason_text, set_language
from nck.simulation.run import SimEvent


@pytest.fixture
def german():
    set_language("de")
    yield
    set_language("en")


def test_a_simulation_event_keeps_its_english_text() -> None:
    event = SimEvent("rapid_cut", line=3, n=None, depth_mm=1.5)
    assert event.text == "line 3: rapid traverse into material (1.50 mm deep)"
    assert reason_text(event.text) == "line 3: rapid traverse into material (1.50 mm deep)"


def test_simulation_events_in_german(german: None) -> None:
    assert reason_text(SimEvent("rapid_cut", line=3, n=None, depth_mm=1.5).text) == \
        "Zeile 3: Eilgang ins Material (1.50 mm tief)"
    assert reason_text(SimEvent("holder_in_material", line=7, n=40, depth_mm=12.0).text) == \
        "N40: Werkzeughalter unter der Oberfläche (Schnitt 12.00 mm tief)"
    assert reason_text(SimEvent("spindle_stopped", line=2, n=None, depth_mm=0.25).text) == \
        "Zeile 2: Schnitt bei stehender Spindel (0.25 mm tief)"
