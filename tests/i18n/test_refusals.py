"""The kernel's refusals have keys (issue 27): every key the code refuses with has its English text
in ``data/refusals.toml`` (the German one: ``test_data_parity``), and the panel says a refusal in
its language, a refusal that raised an alarm in the alarm's text."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from hmi.i18n import refusal_text, set_language
from nck import commands as cmd
from nck.refusals import refusal_texts, refuse

ROOT = Path(__file__).resolve().parents[2]


def refused_keys() -> set[str]:
    """The keys of every ``refuse("…")`` call in the kernel and the panel."""
    keys: set[str] = set()
    for folder in ("nck", "hmi", "screens"):
        for path in (ROOT / folder).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "refuse"
                        and node.args and isinstance(node.args[0], ast.Constant)):
                    keys.add(node.args[0].value)
    return keys


def test_every_refusal_key_has_a_text_and_every_text_a_refusal() -> None:
    used = refused_keys()
    assert used - set(refusal_texts()) == set()
    assert set(refusal_texts()) - used == set()


def test_a_refusal_keeps_its_english_reason_and_fields() -> None:
    refusal = refuse("program_not_found", program="PART.MPF")
    assert refusal.reason == "Program PART.MPF not found"
    assert (refusal.key, refusal.fields) == ("program_not_found", (("program", "PART.MPF"),))
    with pytest.raises(KeyError):
        refuse("no_such_refusal")


@pytest.fixture
def german():
    set_language("de")
    yield
    set_language("en")


def test_the_panel_says_a_refusal_in_its_language(german: None) -> None:
    assert refusal_text(refuse("program_not_found", program="PART.MPF")) == "Programm PART.MPF nicht gefunden"
    # alarm 10860 (data/alarms/language.toml) with its German text of data/lang/de/alarms.toml
    raised = cmd.Rejected("Channel 1 block N30: no feedrate programmed", alarm=10860, alarm_params=("1", "N30"))
    assert refusal_text(raised) == "Kanal 1 Satz N30: kein Vorschub programmiert"
    assert refusal_text(cmd.Rejected("a text from elsewhere")) == "a text from elsewhere"


def test_english_shows_the_reason(tmp_path: Path) -> None:
    assert refusal_text(refuse("stop_not_active")) == "NC STOP acts only while the channel is active"
