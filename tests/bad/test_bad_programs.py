"""Bad programs: each file states the alarm it must raise and the line.

The header comment is ``; ALARM <number> LINE <line>``. Every program is run
headless; the run must stop with exactly that alarm at that line, and
``nck check`` must report the same number.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from nck.cli import main
from nck.headless import interpret_only
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.ncdata import NcData

HERE = Path(__file__).parent
PROGRAMS = sorted(HERE.glob("*.mpf"))
HEADER = re.compile(r"^; ALARM (\d+) LINE (\d+)(?: FILE (\S+))?")


def expected(path: Path) -> tuple[int, int, str]:
    match = HEADER.match(path.read_text().splitlines()[0])
    assert match, f"{path.name} lacks its '; ALARM n LINE l [FILE f]' header"
    return int(match.group(1)), int(match.group(2)), match.group(3) or path.name


@pytest.mark.parametrize("path", PROGRAMS, ids=[p.stem for p in PROGRAMS])
def test_bad_program_raises_its_alarm(path: Path) -> None:
    number, line, file = expected(path)
    result = interpret_only(load_machine(), DirectorySource(HERE), NcData(), path.name,
                            text=path.read_text(), max_blocks=100_000)
    assert result.status == "alarm"
    assert [(a.number, a.file, a.line) for a in result.alarms] == [(number, file, line)]


@pytest.mark.parametrize("path", PROGRAMS[:12], ids=[p.stem for p in PROGRAMS[:12]])
def test_check_reports_the_alarm(path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    number, line, file = expected(path)
    assert main(["check", str(path)]) == 1
    err = capsys.readouterr().err
    assert re.search(rf"^ALARM {number} {file}:{line} ", err, re.M), err


def test_every_language_alarm_has_a_bad_program() -> None:
    import tomllib

    table = tomllib.loads((HERE.parent.parent / "data" / "alarms" / "language.toml").read_text())
    covered = {expected(p)[0] for p in PROGRAMS}
    assert {a["number"] for a in table["alarm"]} <= covered
