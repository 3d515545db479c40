"""A part program writes tool data and stored work offsets under the same value rule as every
other door (issue 19, "one write path ... whatever the door: panel, nck md, nck run --set/--tools,
part program, archive import").

Found in the audit: a program stored ``$TC_DP3[1,1]=200000`` or ``$P_UIFR[1,X,SC]=5000`` that
the panel, ``--set`` and the archive import refuse, so the control's own archive could no longer
be imported back. The limits are the one write path's (nck/writes.py: tool values ±100,000 mm,
tool type 0 … 999, cutting edge position 0 … 9 — 1 … 9 in the 828D tool table, digest 828d-3
L652 — translations ±100,000 mm, rotations ±360°, scale 0 … 1000); a program that crosses one gets
the control's limit alarm, 17080 (below the lower limit) or 17090 (above the upper limit)
(data/alarms/language.toml), and nothing is stored. A REAL value written into an INT datum
(tool type, edge position) is rounded like every REAL → INT assignment of the NC language.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nck.cli import main
from nck.persistence import Session


def _run(tmp_path: Path, block: str) -> tuple[int, Path]:
    data_dir = tmp_path / "data"
    Session.open(data_dir)
    program = tmp_path / "W.MPF"
    program.write_text(f"{block}\nM30\n")
    return main(["run", str(program), "--data-dir", str(data_dir)]), data_dir


def _stored(data_dir: Path, name: str) -> dict:
    return json.loads((data_dir / "retained" / name).read_text())["data"]


@pytest.mark.parametrize("block, alarm", [
    ("$TC_DP3[1,1]=200000", 17090),
    ("$TC_DP6[1,1]=-200000", 17080),
    ("$TC_DP1[1,1]=5000", 17090),
    ("$TC_DP2[1,1]=15", 17090),
    ("$P_UIFR[1,X,TR]=200000", 17090),
    ("$P_UIFR[1,X,FI]=-200000", 17080),
    ("$P_UBFR[Y,TR]=200000", 17090),
    ("$P_UIFR[1,Z,RT]=720", 17090),
    ("$P_UIFR[1,X,SC]=5000", 17090),
    ("$P_UIFR[1]=CTRANS(X,200000)", 17090),
])
def test_a_value_outside_the_limits_is_the_limit_alarm_and_nothing_is_stored(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], block: str, alarm: int) -> None:
    data_dir = tmp_path / "data"
    Session.open(data_dir)
    before = {name: _stored(data_dir, name) for name in ("tools.json", "work_offsets.json")}
    code, _ = _run(tmp_path, block)
    err = capsys.readouterr().err
    assert code == 1 and f"ALARM {alarm} " in err and "Traceback" not in err
    assert {name: _stored(data_dir, name) for name in before} == before


def test_a_real_tool_type_is_rounded_and_the_archive_of_a_programmed_state_imports_again(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, data_dir = _run(tmp_path, "$TC_DP1[1,1]=120.4\n$TC_DP3[1,1]=99999\n$P_UIFR[1,X,TR]=-99999")
    assert code == 0
    edge = next(e for e in _stored(data_dir, "tools.json")["edges"] if (e["t"], e["d"]) == (1, 1))
    assert edge["params"]["1"] == 120 and edge["params"]["3"] == 99999
    archive = tmp_path / "all.json"
    assert main(["archive", "export", "--data-dir", str(data_dir), str(archive)]) == 0
    assert main(["archive", "import", "--data-dir", str(data_dir), "--password", "SUNRISE", str(archive)]) == 0
    assert "bad content" not in capsys.readouterr().err

