"""The kernel's refusals have keys (issue 27): every key the code refuses with has its English text
in ``data/refusals.toml`` (the German one: ``test_data_parity``), and the panel says a refusal in
its language, a refusal that raised an alarm in the alarm's text."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from hmi.i18n import refusal_text
from nck import commands as cmd
from nck.access import AccessControl, AccessDenied, AccessState, Action
from nck.kernel import Nck
from nck.refusals import refusal_texts, refuse, rejected_by
from nck.refused import Refused

ROOT = Path(__file__).resolve().parents[2]


def refusal_classes() -> set[str]:
    """``refuse`` and the names of the exceptions that are raised with a refusal key
    (:class:`nck.refused.Refused` and its subclasses; AccessDenied's first argument is the key
    of what it refuses)."""
    names = {"refuse"}
    found = [Refused]
    while found:
        kind = found.pop()
        names.add(kind.__name__)
        found += kind.__subclasses__()
    return names


def code_trees():
    for folder in ("nck", "hmi", "screens"):
        for path in (ROOT / folder).rglob("*.py"):
            yield ast.parse(path.read_text(encoding="utf-8"))


def refused_keys() -> set[str]:
    """The keys of every ``refuse("…")`` call and every refusal exception raised with a key in
    the kernel and the panel."""
    names = refusal_classes()
    keys: set[str] = set()
    for tree in code_trees():
        for node in ast.walk(tree):
            if (isinstance(node, ast.Call) and isinstance(node.func, (ast.Name, ast.Attribute))
                    and (node.func.id if isinstance(node.func, ast.Name) else node.func.attr) in names
                    and node.args and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)):
                keys.add(node.args[0].value)
    return keys


def code_strings() -> set[str]:
    """Every string constant of the kernel and the panel (a key chosen from a table is one)."""
    return {node.value for tree in code_trees() for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str)}


def test_every_refusal_key_has_a_text_and_every_text_a_refusal() -> None:
    import nck.manual_settings, nck.md_catalog, nck.value_text, nck.writes  # noqa: F401 - their refusal classes
    used = refused_keys()
    assert {"password_empty", "md_write", "gud_missing", "value_missing"} <= used
    assert used - set(refusal_texts()) == set()
    assert set(refusal_texts()) - used - code_strings() == set()


def test_a_refusal_from_an_exception_is_keyed_and_said_in_the_panels_language(german: None) -> None:
    """An access refusal (AccessDenied) and a data write's refusal reach the panel with their key:
    the English reason stays, the panel says them in German, the action's title too."""
    control = AccessControl(AccessState(keyswitch_position=0))
    with pytest.raises(AccessDenied) as denied:
        control.require(Action.WRITE_TOOL_GEOMETRY, "$TC_DP3[1,1]")
    rejected = rejected_by(denied.value)
    assert rejected.reason == ("Writing tool geometry ($TC_DP3[1,1]) needs protection level "
                               f"{denied.value.needed_level} or lower (current level 7)")
    assert refusal_text(rejected) == ("Werkzeuggeometrie schreiben ($TC_DP3[1,1]) erfordert Schutzstufe "
                                      f"{denied.value.needed_level} oder niedriger (aktuelle Stufe 7)")
    with pytest.raises(AccessDenied) as denied:
        control.change_password(2, "SECRET")
    assert refusal_text(rejected_by(denied.value)) == ("Das Ändern des Kennworts der Stufe 2 erfordert "
                                                       "Schutzstufe 2 oder niedriger (aktuelle Stufe 7)")
    kernel = Nck()
    result = kernel.submit(cmd.WriteData("R1", "abc"))
    assert isinstance(result, cmd.Rejected) and result.reason == "R1: “abc” is not a number"
    assert refusal_text(result) == "R1: „abc“ ist keine Zahl"


def test_a_frame_value_refusal_names_the_component_in_the_panels_language(german: None) -> None:
    """The refusal of a work offset's fine offset names it in German, not "G54 X fine offset"."""
    result = Nck().submit(cmd.WriteData("$P_UIFR[1,X,FI]", "abc"))
    assert isinstance(result, cmd.Rejected) and result.reason == "G54 X fine offset: “abc” is not a number"
    assert refusal_text(result) == "G54 X Feinverschiebung: „abc“ ist keine Zahl"


def test_a_machine_data_value_refusal_quotes_in_the_panels_language(german: None) -> None:
    """The quotes of a refused machine data value belong to the language's text („…“ in German)."""
    result = Nck().submit(cmd.WriteData("SD42100", "fast"))
    assert isinstance(result, cmd.Rejected) and result.reason == "SD42100: “fast” is not valid, enter a number"
    assert refusal_text(result) == "SD42100: „fast“ ist ungültig, eine Zahl eingeben"


def test_a_set_up_field_refusal_is_said_in_the_panels_language(german: None) -> None:
    """The Setup area's refusal of a set-up value (SetupFieldError) is keyed like the kernel's."""
    from nck.queries import SetupFieldError, with_field
    from nck.workpiece import default_machine_setup
    with pytest.raises(SetupFieldError) as refused:
        with_field(default_machine_setup("mill"), "blank.size_x", "-5")
    assert str(refused.value) == "blank.size_x: must be greater than 0"
    assert refusal_text(rejected_by(refused.value)) == "blank.size_x: muss größer als 0 sein"


def test_a_refusal_keeps_its_english_reason_and_fields() -> None:
    refusal = refuse("program_not_found", program="PART.MPF")
    assert refusal.reason == "Program PART.MPF not found"
    assert (refusal.key, refusal.fields) == ("program_not_found", (("program", "PART.MPF"),))
    with pytest.raises(KeyError):
        refuse("no_such_refusal")


def test_the_panel_says_a_refusal_in_its_language(german: None) -> None:
    assert refusal_text(refuse("program_not_found", program="PART.MPF")) == "Programm PART.MPF nicht gefunden"
    # alarm 10860 (data/alarms/language.toml) with its German text of data/lang/de/alarms.toml
    raised = cmd.Rejected("Channel 1 block N30: no feedrate programmed", alarm=10860, alarm_params=("1", "N30"))
    assert refusal_text(raised) == "Kanal 1 Satz N30: kein Vorschub programmiert"
    assert refusal_text(cmd.Rejected("a text from elsewhere")) == "a text from elsewhere"


def test_english_shows_the_reason(tmp_path: Path) -> None:
    assert refusal_text(refuse("stop_not_active")) == "NC STOP acts only while the channel is active"
