"""Sentences the kernel writes for the panel (``nck.phrase.Phrase``) are said in the panel's
language: the simulation's events (issue 27), a field that is itself a phrase too."""

from __future__ import annotations

from hmi.i18n import reason_text
from nck import commands as c
from nck.access import AccessControl, AccessState
from nck.kernel import Nck
from nck.simulation.run import SimEvent


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



def test_logbook_entries_in_german(german: None) -> None:
    """The diagnosis logbook keeps English sentences (the log export, the tests) that the
    German panel says in German: a wrong password, a keyswitch turn, activated machine data."""
    nck = Nck(access=AccessControl(AccessState()))
    nck.submit(c.EnterPassword("WRONG"))
    nck.submit(c.SetKeyswitch(3))
    nck.submit(c.ActivateMachineData())
    texts = [entry.text for entry in nck.logbook]
    assert texts == ["password not accepted (failed attempt 1)", "keyswitch position 3: access level 7 -> 4",
                     "machine data activated (NEW CONFIG)"]
    assert [reason_text(text) for text in texts] == [
        "Kennwort nicht akzeptiert (Fehlversuch 1)", "Schlüsselschalterstellung 3: Zugriffsstufe 7 -> 4",
        "Maschinendaten aktiviert (NEW CONFIG)"]
