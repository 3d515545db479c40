"""Hostile retained files through every door: 4065, the bad file kept aside, the backup used.

A sample of the corpus (:mod:`tests.reliability.hostile_files`) runs with the
test suite; the whole corpus, through every door, runs under ``make fuzz``.
The answer expected for every case is the one the manual gives for a damaged
retained file restored from its backup: alarm 4065 naming the file.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.reliability.hostile_files import CORPUS, DOORS, FAST_SAMPLE, make_template, try_door


@pytest.fixture(scope="module")
def template() -> Path:
    return make_template()


def _cases(names: tuple[str, ...] | None = None) -> list:
    return [pytest.param(h, id=h.name) for h in CORPUS if names is None or h.name in names]


@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("hostile", _cases(FAST_SAMPLE))
def test_a_hostile_file_gives_4065_and_the_backup_on_every_door(template, hostile, door, tmp_path) -> None:
    try_door(template, hostile, door, tmp_path)


@pytest.mark.parametrize("hostile", _cases())
def test_every_hostile_file_gives_4065_and_the_backup(template, hostile, tmp_path) -> None:
    try_door(template, hostile, "session", tmp_path)


@pytest.mark.fuzz
@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("hostile", _cases())
def test_the_hostile_corpus_through_every_door(template, hostile, door, tmp_path) -> None:
    try_door(template, hostile, door, tmp_path)
