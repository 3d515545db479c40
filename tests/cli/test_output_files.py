"""``nck run --segments FILE`` / ``--trace FILE`` write like every export: atomically, never through a link.

The file named is replaced as a whole when the run is over (a reader never sees
half a file, a failed write leaves the old one); a symbolic link, FIFO or device
in its place is refused before the run starts (exit 2, a clear message) and the
file it points to stays untouched (issue 19, "never follow links for files the
program writes ... exports").
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from nck.cli import main

VICTIM_TEXT = "an outside file that must stay as it is\n"


@pytest.fixture(autouse=True)
def _private_data_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NCK_DATA_DIR", str(tmp_path / "no-user-data"))


def _program(tmp_path: Path) -> Path:
    program = tmp_path / "P.MPF"
    program.write_text("G1 X10 Y5 F600\nG0 Z2\nM30\n")
    return program


@pytest.mark.parametrize("option", ["--segments", "--trace"])
def test_an_output_file_linked_outside_is_refused_and_the_target_untouched(
        tmp_path: Path, option: str, capsys: pytest.CaptureFixture[str]) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text(VICTIM_TEXT)
    out = tmp_path / "out.txt"
    out.symlink_to(victim)
    assert main(["run", str(_program(tmp_path)), option, str(out)]) == 2
    message = capsys.readouterr().err
    assert "not a regular file" in message and "Traceback" not in message
    assert victim.read_text() == VICTIM_TEXT and out.is_symlink()


@pytest.mark.parametrize("option", ["--segments", "--trace"])
def test_a_dangling_link_creates_nothing_where_it_points(tmp_path: Path, option: str) -> None:
    out = tmp_path / "out.txt"
    out.symlink_to(tmp_path / "created-through-link")
    assert main(["run", str(_program(tmp_path)), option, str(out)]) == 2
    assert not (tmp_path / "created-through-link").exists()


@pytest.mark.parametrize("option", ["--segments", "--trace"])
def test_a_fifo_in_place_of_the_output_is_refused_without_blocking(tmp_path: Path, option: str) -> None:
    out = tmp_path / "out.fifo"
    os.mkfifo(out)
    assert main(["run", str(_program(tmp_path)), option, str(out)]) == 2


def test_outputs_replace_an_existing_file_as_a_whole_and_leave_no_temporary_file(tmp_path: Path) -> None:
    segments, trace = tmp_path / "seg.jsonl", tmp_path / "trace.csv"
    segments.write_text("old\n" * 1000)
    trace.write_text("old\n")
    assert main(["run", str(_program(tmp_path)), "--segments", str(segments), "--trace", str(trace)]) == 0
    lines = segments.read_text().splitlines()
    assert [json.loads(line)["motion"] for line in lines] == ["G1", "G0"]
    assert trace.read_text().startswith("t_s,")
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == []
