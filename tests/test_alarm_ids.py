"""Named alarm numbers (issue 21): every name is a catalogue entry, and bare numbers only go down.

``nck/alarm_ids.py`` names the numbers; ``data/alarms/*.toml`` keeps texts and reactions.
The module constants ``ALARM_… = number`` that modules still hold must name catalogue
entries too. No raise in ``nck/`` is written with a bare number (``NcAlarmError(12080, …)``,
also not as a branch of a conditional: ``NcAlarmError(17040 if … else 12550, …)``).
"""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import nck.alarm_ids as alarm_ids
from nck.resources import alarm_catalog

ROOT = Path(__file__).resolve().parent.parent
RAISERS = {"NcAlarmError", "raise_alarm"}

NOT_ALARM_NUMBERS = {"ALARM_LOG_LIMIT"}
"""``ALARM_…`` constants that are not alarm numbers (the alarm log's length)."""


def named_ids() -> dict[str, int]:
    return {name: value for name, value in vars(alarm_ids).items() if name.isupper() and isinstance(value, int)}


def is_bare_number(expression: ast.expr) -> bool:
    """True for an int literal, or a conditional with an int literal in a branch."""
    if isinstance(expression, ast.IfExp):
        return is_bare_number(expression.body) or is_bare_number(expression.orelse)
    return isinstance(expression, ast.Constant) and type(expression.value) is int


def bare_number_raises(source: str) -> list[int]:
    """Line numbers of calls ``NcAlarmError(<int literal>, …)`` / ``raise_alarm(<int literal>, …)``."""
    lines = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Call) or not node.args:
            continue
        func = node.func
        name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""
        if name in RAISERS and is_bare_number(node.args[0]):
            lines.append(node.lineno)
    return lines


def test_every_name_is_a_catalogue_entry_and_no_number_has_two_names() -> None:
    catalogue = alarm_catalog()
    ids = named_ids()
    assert len(ids) >= 14
    assert {name: number for name, number in ids.items() if number not in catalogue} == {}
    assert [number for number, count in Counter(ids.values()).items() if count > 1] == []


def test_module_alarm_constants_are_catalogue_entries() -> None:
    catalogue = alarm_catalog()
    missing = []
    for path in sorted((ROOT / "nck").rglob("*.py")):
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, (ast.Assign, ast.AnnAssign)) and isinstance(node.value, ast.Constant):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                for target in targets:
                    if (isinstance(target, ast.Name) and target.id.startswith("ALARM_")
                            and target.id not in NOT_ALARM_NUMBERS and node.value.value not in catalogue):
                        missing.append(f"{path.relative_to(ROOT)}: {target.id} = {node.value.value}")
    assert missing == []


def test_no_raise_names_an_alarm_by_a_bare_number() -> None:
    found = {}
    for path in sorted((ROOT / "nck").rglob("*.py")):
        if lines := bare_number_raises(path.read_text(encoding="utf-8")):
            found[str(path.relative_to(ROOT))] = lines
    assert found == {}, f"raise with a name of nck/alarm_ids.py instead of a number: {found}"


def test_the_count_sees_a_bare_number() -> None:
    source = "from nck.errors import NcAlarmError as E\nraise NcAlarmError(12080, 'x')\nnck.raise_alarm(3000)\n"
    assert bare_number_raises(source) == [2, 3]
    assert bare_number_raises("raise NcAlarmError(SYNTAX_ERROR, 'x')\n") == []
    assert bare_number_raises("raise NcAlarmError(ILLEGAL_AXIS_INDEX if bad else 12550, 'x')\n") == [1]
    assert bare_number_raises("raise NcAlarmError(ILLEGAL_AXIS_INDEX if bad else NAME_NOT_DEFINED)\n") == []
