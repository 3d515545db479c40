"""Files the operator names (machine file, tool table, program) cannot crash or exhaust a door.

A machine file or tool table nested 100,000 levels deep made the TOML parser
recurse until RecursionError: a traceback in ``nck md``, "ALARM 1 Internal
error" in ``nck run``/``check``, "hmi: maximum recursion depth exceeded".
Such files, and links to devices or pipes, are answered with a clear message
and exit 2 (a file that could not be used, cli contract); reads are bounded.
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest

from hmi.app import main as hmi_main
from nck.cli import main as nck_main
from nck.cli_md import run as md_run
from nck.interp.sources import PROGRAM_FILE_LIMIT_BYTES


@pytest.fixture(autouse=True)
def _private_data_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NCK_DATA_DIR", str(tmp_path / "no-user-data"))


def _deep_toml(tmp_path: Path) -> Path:
    path = tmp_path / "deep.toml"
    path.write_text("a = " + "[" * 100_000 + "]" * 100_000 + "\n")
    return path


def _program(tmp_path: Path) -> Path:
    program = tmp_path / "P.MPF"
    program.write_text("G0 X1\nM30\n")
    return program


def test_a_deeply_nested_machine_file_is_refused_by_every_door(tmp_path: Path, capsys) -> None:
    deep = str(_deep_toml(tmp_path))
    err = io.StringIO()
    assert md_run(["--ephemeral", "--machine", deep, "MD28050"], io.StringIO(), err) == 2
    assert "nested too deeply" in err.getvalue()
    assert nck_main(["run", "--machine", deep, str(_program(tmp_path))]) == 2
    assert nck_main(["check", "--machine", deep, str(_program(tmp_path))]) == 2
    assert hmi_main(["--ephemeral", "--machine", deep]) == 2
    messages = capsys.readouterr().err
    assert messages.count("nested too deeply") == 3
    assert "Internal error" not in messages and "recursion" not in messages


def test_a_deeply_nested_tool_table_is_refused(tmp_path: Path, capsys) -> None:
    assert nck_main(["run", "--tools", str(_deep_toml(tmp_path)), str(_program(tmp_path))]) == 2
    message = capsys.readouterr().err
    assert "nested too deeply" in message and "Internal error" not in message


@pytest.mark.parametrize("kind", ["FIFO", "link to /dev/zero"])
def test_a_tool_table_that_is_no_regular_file_is_refused_without_reading(tmp_path: Path, kind: str, capsys) -> None:
    tools = tmp_path / "tools.toml"
    if kind == "FIFO":
        os.mkfifo(tools)
    else:
        tools.symlink_to("/dev/zero")  # the reader checks the kind before it reads a byte
    assert nck_main(["run", "--tools", str(tools), str(_program(tmp_path))]) == 2
    assert "not a regular file" in capsys.readouterr().err


def test_a_program_file_larger_than_the_nc_memory_is_refused(tmp_path: Path, capsys) -> None:
    program = tmp_path / "HUGE.MPF"
    with open(program, "wb") as handle:  # sparse: no disk space used
        handle.truncate(PROGRAM_FILE_LIMIT_BYTES + 1)
    assert nck_main(["check", str(program)]) == 2
    assert "larger than 50 MB" in capsys.readouterr().err
