"""Malformed archives: import answers with its documented ArchiveError and changes nothing.

``Session.import_archive`` promises: "on any problem ArchiveError is raised and
nothing changes". Each case below breaks a good archive in one way (depth,
size, type, value, kind of file); none may escape as another exception.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Callable

import pytest

from nck.ncdata import ToolEdge
from nck.persistence import ArchiveError, Session


def _good(tmp_path: Path) -> tuple[Session, dict[str, Any]]:
    session = Session.open(tmp_path / "data", install_samples=False)
    session.ncdata.tools[(1, 1)] = ToolEdge({1: 100.0})
    session.files.create("PART1.MPF", "G0 X1\nM30\n")
    archive = json.loads(session.export_archive(tmp_path / "good.json").read_text())
    return session, archive


def _section(name: str, change: Callable[[dict[str, Any]], Any]) -> Callable[[dict[str, Any]], Any]:
    def edit(archive: dict[str, Any]) -> None:
        change(archive["sections"][name])
    return edit


def _program(field: str, value: Any) -> Callable[[dict[str, Any]], Any]:
    return lambda archive: archive["programs"][0].__setitem__(field, value)


EDITS: dict[str, Callable[[dict[str, Any]], Any]] = {
    "program text as a number": _program("text", 5),
    "program path as a number": _program("path", 5),
    "program base64 as a list": lambda a: a["programs"].__setitem__(0, {"path": "X.MPF", "base64": [1]}),
    "programs as a table": lambda a: a.__setitem__("programs", {"a": 1}),
    "workpiece as a number": lambda a: a.__setitem__("workpieces", [5]),
    "sections as a list": lambda a: a.__setitem__("sections", [1]),
    "R count 1e10": _section("r_parameters", lambda d: d.__setitem__("count", 10**10)),
    "machine datum as text": _section("machine_data", lambda d: d["machines"].__setitem__(
        "mill", {"MD32000": {"X": "fast"}})),
    "machine datum out of limits": _section("machine_data", lambda d: d["machines"].__setitem__(
        "mill", {"MD32000": {"X": -5.0}})),
    "R value 4000 digits": _section("r_parameters", lambda d: d["values"].__setitem__("1", 10**4000)),
    "alarm entry with text fields": _section("alarm_log", lambda d: d.__setitem__(
        "entries", [{"number": 1, "params": 5}])),
}

RAW: dict[str, str] = {
    "nested 100000 deep": '{"format": "sinumerik-trainer/archive", "format_version": 1, "sections": '
                          + "[" * 100_000 + "]" * 100_000 + "}",
    "5000-digit integer": '{"format": "sinumerik-trainer/archive", "format_version": 1, "sections": {}, '
                          '"workpieces": [' + "9" * 5000 + "]}",
    "NaN": '{"format": "sinumerik-trainer/archive", "format_version": 1, "sections": '
           '{"r_parameters": {"count": 100, "values": {"1": NaN}}}}',
}


def _unchanged(session: Session) -> Callable[[], dict[str, bytes]]:
    root = session.data_dir

    def snapshot() -> dict[str, bytes]:
        return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}
    return snapshot


@pytest.mark.parametrize("case", sorted(EDITS))
def test_a_malformed_archive_gives_archive_error(tmp_path: Path, case: str) -> None:
    session, archive = _good(tmp_path)
    EDITS[case](archive)
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(archive))
    snapshot = _unchanged(session)
    before = snapshot()
    with pytest.raises(ArchiveError):
        session.import_archive(path)
    assert snapshot() == before


@pytest.mark.parametrize("case", sorted(RAW))
def test_a_hostile_archive_text_gives_archive_error(tmp_path: Path, case: str) -> None:
    session, _archive = _good(tmp_path)
    path = tmp_path / "bad.json"
    path.write_text(RAW[case])
    with pytest.raises(ArchiveError):
        session.import_archive(path)


def test_an_archive_that_is_a_fifo_or_a_link_to_dev_zero_gives_archive_error(tmp_path: Path) -> None:
    session, _archive = _good(tmp_path)
    (tmp_path / "linked.json").symlink_to(tmp_path / "good.json")  # the operator's link: followed
    session = session.import_archive(tmp_path / "linked.json")
    os.mkfifo(tmp_path / "fifo.json")
    (tmp_path / "zero.json").symlink_to("/dev/zero")
    for name in ("fifo.json", "zero.json"):
        with pytest.raises(ArchiveError, match="not a regular file"):
            session.import_archive(tmp_path / name)


def test_a_program_larger_than_the_nc_memory_takes_is_refused_by_every_write(tmp_path: Path, monkeypatch) -> None:
    """Programs are read up to ``MAX_IMPORT_BYTES``; no write may store a larger one (it
    could never be opened again). The limit is lowered here to keep the test small."""
    import nck.storage
    from nck.storage import StorageError

    session, archive = _good(tmp_path)
    monkeypatch.setattr(nck.storage, "MAX_IMPORT_BYTES", 1000)
    with pytest.raises(StorageError, match="too large"):
        session.files.save("BIG.MPF", "G0 X1\n" * 200)
    archive["programs"] = [{"path": "MPF/HUGE.MPF", "text": "G0 X1\n" * 200}]
    path = tmp_path / "huge.json"
    path.write_text(json.dumps(archive))
    with pytest.raises(ArchiveError, match="too large"):
        session.import_archive(path, level=1)
    assert not session.files.exists("MPF/HUGE.MPF") and not session.files.exists("MPF/BIG.MPF")
