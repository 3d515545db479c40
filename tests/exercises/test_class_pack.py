"""The class pack (issue 26): exercises with their programs and set-ups as one archive,
written by the instructor (``nck class-pack export``) and imported on each seat
(``nck class-pack import``; the panel: tests/hmi/test_exercises_panel.py).

The round trip goes from an instructor's folder to a fresh data directory, where the
imported exercise starts on its own set-up, its program runs and its check passes — and
fails before the run. Broken, foreign and refused packs change nothing and say why.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from nck.class_pack import read_pack
from nck.cli import main
from nck.exercise import available_exercises
from nck.persistence import Session
from tests.exercises.test_exercise_checks import Scripted

SQUARE = "N10 G54 G90 G0 X10 Y10\nN20 G1 X20 F1000\nN30 Y20\nN40 M30\n"
EXERCISE = """title = "Run the instructor's square"
level = "basic"
summary = "A program of the instructor's pack."
[setup]
programs = ["SQUARE.MPF"]
select = "SQUARE.MPF"
tools = [{ t = 1, d = 1, type = 120, length1 = 80.0, radius = 5.0 }]
offsets = [{ frame = "G54", X = -200.0, Y = -150.0, Z = -250.0 }]
[[step]]
text = "Run SQUARE to its end."
checks = [{ kind = "program_ended", program = "SQUARE" }]
"""


def files_of(directory: Path) -> dict[str, str]:
    """Every file below ``directory`` with its content hash (the data lock left out)."""
    return {str(p.relative_to(directory)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(directory.rglob("*")) if p.is_file() and p.name != ".lock"}


@pytest.fixture()
def pack(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    """A pack of the instructor's own exercise (its program beside it) and a shipped one."""
    folder = tmp_path / "course"
    (folder / "programs").mkdir(parents=True)
    (folder / "20_square.toml").write_text(EXERCISE)
    (folder / "programs" / "SQUARE.MPF").write_text(SQUARE)
    target = tmp_path / "class.pack"
    assert main(["class-pack", "export", str(target), str(folder), "03_single_block_flange"]) == 0
    assert capsys.readouterr().out == f"Class pack written to {target}: 2 exercises, 2 programs\n"
    return target


def seat(tmp_path: Path, name: str = "seat") -> Path:
    directory = tmp_path / name
    Session.open(directory).save()
    return directory


def test_round_trip_the_imported_exercise_runs_and_is_checked(
        tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    document = json.loads(pack.read_text())  # the archive format: envelope, programs as in an NC archive
    assert (document["format"], document["format_version"], document["content"]) == (
        "sinumerik-trainer/archive", 1, "class-pack")
    assert {"path": "MPF/SQUARE.MPF", "text": SQUARE} in document["programs"]
    data_dir = seat(tmp_path)
    assert main(["class-pack", "import", str(pack), "--data-dir", str(data_dir), "--password", "EVENING"]) == 0
    assert "2 exercises, 2 programs (4 files new or changed)" in capsys.readouterr().out
    exercises = {e.exercise_id: e for e in available_exercises(data_dir)}
    assert exercises["20_square"].title == "Run the instructor's square"
    assert exercises["03_single_block_flange"].source == data_dir / "exercises" / "03_single_block_flange.toml"
    assert len(exercises) == len(available_exercises(None)) + 1  # the shipped ones and the new one
    # the seat's copy runs on a private data directory with its programs and set-up
    session = Scripted(exercises["20_square"], tmp_path / "private")
    assert session.session.files.read("MPF/SQUARE.MPF") == SQUARE
    assert "SQUARE" in session.nck.status().channel.selected_program
    session.reference()
    assert not session.progress.finished  # not done before the run
    assert "SQUARE has not run to its end" in " ".join(session.progress.results[0].why_not)
    session.run_program()
    assert session.progress.finished and session.progress.report("x")["score"] == 100
    x_axis = session.nck.status().axes[0]  # N20 X20 in G54, which the set-up put at X-200
    assert (x_axis.position_wcs, x_axis.position_mcs) == (pytest.approx(20.0), pytest.approx(-180.0))


def test_reimport_changes_nothing(tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = seat(tmp_path)
    argv = ["class-pack", "import", str(pack), "--data-dir", str(data_dir), "--password", "EVENING"]
    assert main(argv) == 0
    before = files_of(data_dir)
    assert main(argv) == 0
    assert "(0 files new or changed)" in capsys.readouterr().out.splitlines()[-1]
    assert files_of(data_dir) == before


def test_import_needs_the_service_level(tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = seat(tmp_path)
    before = files_of(data_dir)
    assert main(["class-pack", "import", str(pack), "--data-dir", str(data_dir)]) == 1
    assert capsys.readouterr().err == ("nck class-pack: refused: importing a class pack needs protection "
                                       "level 2; the current level is level 7 (keyswitch position 0)\n")
    assert files_of(data_dir) == before


def broken_packs(tmp_path: Path, pack: Path) -> dict[str, tuple[bytes, str]]:
    """Pack files that cannot be used, each with the words its message must hold."""
    good = json.loads(pack.read_text())

    def variant(**changes: object) -> bytes:
        return json.dumps({**good, **changes}).encode()

    nc_archive = tmp_path / "nc.arc"
    Session.open(tmp_path / "other").export_archive(nc_archive)
    bad_check = EXERCISE.replace('kind = "program_ended"', 'kind = "eval"')
    return {
        "garbage": (b"\x00\xffPK\x03\x04 not json", "not a readable class pack (not UTF-8 text)"),
        "truncated": (pack.read_bytes()[:200], "not a readable class pack (truncated or garbled at byte"),
        "empty": (b"", "not a readable class pack (empty file)"),
        "foreign": (b'{"name": "something else"}', "not a class pack (not an archive of this trainer)"),
        "nc_data": (nc_archive.read_bytes(), "an NC data archive, not a class pack"),
        "newer": (variant(format_version=2), "archive version 2 not supported"),
        "bad_check": (variant(exercises=[{"file": "20_square.toml", "text": bad_check}]), "unknown check 'eval'"),
        "bad_toml": (variant(exercises=[{"file": "20_square.toml", "text": "title = "}]), "20_square.toml: "),
        "escaping_name": (variant(exercises=[{"file": "../evil.toml", "text": EXERCISE}]),
                          "'../evil.toml' is not an exercise file name"),
        "escaping_program": (variant(programs=[{"path": "MPF/../../x.MPF", "text": "M30"}]),
                             "MPF/../../x.MPF is not a program of an exercise"),
        "program_missing": (variant(programs=[]), "program SQUARE.MPF is neither in the pack nor shipped"),
        "bad_base64": (variant(programs=[{"path": "MPF/SQUARE.MPF", "base64": "%%%"}]), "bad content"),
        "not_a_list": (variant(exercises={"a": 1}), "'exercises' must be a list of tables"),
    }


def test_broken_or_foreign_packs_change_nothing_and_say_why(
        tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = seat(tmp_path)
    before = files_of(data_dir)
    for name, (raw, words) in broken_packs(tmp_path, pack).items():
        bad = tmp_path / f"{name}.pack"
        bad.write_bytes(raw)
        code = main(["class-pack", "import", str(bad), "--data-dir", str(data_dir), "--password", "EVENING"])
        err = capsys.readouterr().err
        assert code == 2, name
        assert err.startswith(f"nck class-pack: {bad}: ") and words in err, (name, err)
        assert err.endswith("; nothing was imported\n") and "Traceback" not in err, (name, err)
    assert main(["class-pack", "import", str(tmp_path / "missing.pack"), "--data-dir", str(data_dir)]) == 2
    assert "not a readable class pack (No such file or directory)" in capsys.readouterr().err
    assert files_of(data_dir) == before


def test_a_pack_is_no_nc_data_archive(tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = seat(tmp_path)
    assert main(["archive", "import", str(pack), "--data-dir", str(data_dir)]) == 2
    assert "a class pack, not NC data (import it with 'nck class-pack import')" in capsys.readouterr().err


def test_export_of_what_cannot_be_packed_writes_nothing(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "course"
    folder.mkdir()
    (folder / "21_lost.toml").write_text(EXERCISE.replace("SQUARE.MPF", "LOST.MPF"))
    target = tmp_path / "class.pack"
    assert main(["class-pack", "export", str(target), str(folder)]) == 2
    assert "21_lost.toml: program LOST.MPF not found" in capsys.readouterr().err
    assert main(["class-pack", "export", str(target), "99_no_such_exercise"]) == 2
    assert "99_no_such_exercise: neither an exercise file nor a shipped exercise" in capsys.readouterr().err
    assert not target.exists()


def test_exercise_list_shows_the_imported_ones(tmp_path: Path, pack: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = seat(tmp_path)
    assert main(["class-pack", "import", str(pack), "--data-dir", str(data_dir), "--password", "EVENING"]) == 0
    capsys.readouterr()
    assert main(["exercise", "list", "--data-dir", str(data_dir)]) == 0
    assert any(line.startswith("20_square ") for line in capsys.readouterr().out.splitlines())
    assert read_pack(pack).programs["SQUARE.MPF"] == SQUARE.encode()
