"""Hostile retained files through every door: 4065, the bad file kept aside, the backup used.

A sample of the corpus (:mod:`tests.reliability.hostile_files`) runs with the
test suite; the whole corpus, through every door, runs under ``make fuzz``.
The answer expected for every case is the one the manual gives for a damaged
retained file restored from its backup: alarm 4065 naming the file.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.reliability.hostile_files import (
    CORPUS, DOORS, FAST_SAMPLE, FOLDER_CORPUS, make_template, try_door, try_door_without_backup,
    try_folder_door,
)


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


@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("hostile", _cases(("gud nested 100000 deep", "FIFO")))
def test_a_hostile_backup_gives_4060_on_every_door(template, hostile, door, tmp_path) -> None:
    try_door_without_backup(template, hostile, door, tmp_path)


@pytest.mark.fuzz
@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("hostile", _cases())
def test_the_hostile_corpus_as_backups_through_every_door(template, hostile, door, tmp_path) -> None:
    try_door_without_backup(template, hostile, door, tmp_path)


@pytest.mark.parametrize("folder, kind", [pytest.param(f, k, id=f"{f} {k}") for f, k in FOLDER_CORPUS])
def test_every_hostile_folder_gives_4060_and_a_new_folder(template, folder, kind, tmp_path) -> None:
    try_folder_door(template, folder, kind, "session", tmp_path)


@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("folder, kind", [("nc/MPF", "link"), ("retained", "FIFO")])
def test_a_hostile_folder_gives_4060_on_every_door(template, folder, kind, door, tmp_path) -> None:
    try_folder_door(template, folder, kind, door, tmp_path)


@pytest.mark.fuzz
@pytest.mark.parametrize("door", sorted(DOORS))
@pytest.mark.parametrize("folder, kind", [pytest.param(f, k, id=f"{f} {k}") for f, k in FOLDER_CORPUS])
def test_the_hostile_folders_through_every_door(template, folder, kind, door, tmp_path) -> None:
    try_folder_door(template, folder, kind, door, tmp_path)


@pytest.mark.parametrize("hostile", _cases(("FIFO", "link to /dev/zero", "gud nested 100000 deep", "directory")))
def test_a_hostile_backup_behind_a_bad_file_gives_4060(template, hostile, tmp_path) -> None:
    """Both generations unusable: standard values with 4060, both kept aside (never a hang)."""
    import json
    import shutil

    from nck.atomic import backup_path
    from nck.persistence import Session

    data_dir = tmp_path / "data"
    shutil.copytree(template, data_dir, symlinks=True)
    main = data_dir / "retained" / f"{hostile.section}.json"
    document = json.loads(main.read_text())
    main.write_text("damaged")
    hostile.plant(backup_path(main), document, tmp_path / "victim.txt")
    session = Session.open(data_dir, install_samples=False)
    assert [a.number for a in session.startup_alarms] == [4060]
    assert (data_dir / "retained" / f"{hostile.section}.json.bad-1").exists()
    assert os.path.lexists(data_dir / "retained" / f"{hostile.section}.json.bak.bad-1")


def test_the_hmi_start_never_ends_with_an_empty_message(tmp_path: Path, monkeypatch, capsys) -> None:
    """An exception without text at the start (MemoryError of an R count of 10^10 did it) printed
    'hmi: ' and nothing more; the line names what went wrong, without a traceback."""
    import hmi.app

    def fail(*_args: object, **_kwargs: object) -> None:
        raise MemoryError()

    monkeypatch.setattr(hmi.app, "make_app", fail)
    assert hmi.app.main(["--data-dir", str(tmp_path / "data")]) == 2
    err = capsys.readouterr().err
    assert err == "hmi: cannot start: internal error (MemoryError)\n"
