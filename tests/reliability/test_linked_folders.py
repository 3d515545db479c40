"""Folders of the data directory that are links (or pipes, or files) are never followed.

``nc/``, ``nc/MPF``, ``nc/SPF``, ``nc/WKS``, ``retained/`` and the workpiece
folders hold what the program writes and lists. A symbolic link in place of one
of them would send every save, every sample program and every listing to a
folder outside the data directory. Such an entry is set aside (renamed
``<name>.bad-<n>``, the link itself — nothing it points to is touched), a new
empty folder takes its place and alarm 4060 names it; the program keeps working.
A workpiece folder that is a link is skipped in the listing (reported) and no
program is read or written through it.
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest

from hmi.startup import build_session
from nck.cli import main as nck_main
from nck.cli_md import run as md_run
from nck.persistence import ALARM_DEFAULTS_LOADED, Session
from nck.storage import NcFileSystem, StorageError

FOLDERS = ["nc", "nc/MPF", "nc/SPF", "nc/WKS", "retained"]


def _outside(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "KEEP.MPF").write_text("M30\n")
    return outside, {"KEEP.MPF": "M30\n"}


def _content(folder: Path) -> dict[str, str]:
    return {p.name: p.read_text() for p in folder.iterdir()}


def _plant(data_dir: Path, folder: str, kind: str, outside: Path) -> None:
    entry = data_dir / folder
    entry.parent.mkdir(parents=True, exist_ok=True)
    if kind == "link":
        entry.symlink_to(outside, target_is_directory=True)
    elif kind == "dangling":
        entry.symlink_to(outside / "missing")
    elif kind == "fifo":
        os.mkfifo(entry)
    else:
        entry.write_text("a file where a folder belongs\n")


@pytest.mark.parametrize("kind", ["link", "dangling", "fifo", "file"])
@pytest.mark.parametrize("folder", FOLDERS)
def test_an_odd_folder_is_set_aside_and_a_new_one_used(tmp_path: Path, folder: str, kind: str) -> None:
    outside, before = _outside(tmp_path)
    data_dir = tmp_path / "data"
    _plant(data_dir, folder, kind, outside)
    session = Session.open(data_dir)  # installs the samples, writes every section
    session.files.save("MPF/NEW.MPF", "G0 X1\nM30\n")
    session.ncdata.r[1] = 5.0
    session.save()
    assert _content(outside) == before
    assert os.path.isdir(data_dir / folder) and not os.path.islink(data_dir / folder)
    kept = data_dir / f"{folder}.bad-1"
    assert os.path.lexists(kept)
    if kind in ("link", "dangling"):
        assert kept.is_symlink()
    alarms = [(a.number, a.params[0], a.params[2]) for a in session.startup_alarms]
    assert (ALARM_DEFAULTS_LOADED, folder, f"{folder}.bad-1") in alarms
    again = Session.open(data_dir)
    assert again.startup_alarms == [] and again.ncdata.r[1] == 5.0
    assert again.files.read("MPF/NEW.MPF") == "G0 X1\nM30\n"


def test_a_linked_workpiece_is_listed_as_odd_and_never_read_or_written(tmp_path: Path) -> None:
    outside, before = _outside(tmp_path)
    fs = NcFileSystem(tmp_path / "nc")
    fs.create_workpiece("REAL")
    (tmp_path / "nc" / "WKS" / "EVIL.WPD").symlink_to(outside, target_is_directory=True)
    assert fs.scan_directory("WKS")[1] == ["EVIL.WPD"]
    for action in (lambda: fs.save("WKS/EVIL.WPD/NEW.MPF", "M30\n"),
                   lambda: fs.read("WKS/EVIL.WPD/KEEP.MPF"),
                   lambda: fs.list_directory("WKS/EVIL.WPD"),
                   lambda: fs.copy("WKS/EVIL.WPD", "WKS/COPY.WPD"),
                   lambda: fs.copy("MPF/NONE.MPF", "WKS/EVIL.WPD")):
        with pytest.raises(StorageError):
            action()
    assert fs.read_program("WKS/EVIL.WPD/KEEP.MPF") is None
    assert [e.path for e in fs.all_programs()] == ["WKS/REAL.WPD/REAL.MPF"]
    assert _content(outside) == before
    assert not (tmp_path / "nc" / "WKS" / "COPY.WPD").exists()


def test_every_door_keeps_working_with_a_linked_program_folder(tmp_path: Path, capsys) -> None:
    outside, before = _outside(tmp_path)
    program = tmp_path / "P.MPF"
    program.write_text("R1=1\nM30\n")
    results = []
    for door in ("md", "check", "run", "hmi"):
        data_dir = tmp_path / f"data-{door}"
        _plant(data_dir, "nc/MPF", "link", outside)
        if door == "md":
            err = io.StringIO()
            results.append(md_run(["--data-dir", str(data_dir), "MD28050"], io.StringIO(), err))
            assert "4060" in err.getvalue()
        elif door == "hmi":
            holder = build_session(data_dir=str(data_dir))
            assert 4060 in [a.number for a in holder.nck.status().alarms]
            holder.quit()
            results.append(0)
        else:
            results.append(nck_main([door, "--data-dir", str(data_dir), str(program)]))
        assert _content(outside) == before
        assert not (data_dir / "nc" / "MPF").is_symlink()
    messages = capsys.readouterr().err
    assert results == [0, 0, 0, 0]
    assert "Traceback" not in messages and "4060" in messages
