"""`nck run --set/--tools` write through the same protection and limit checks as the panel
and `nck md` (issue 19, "protection through every door").

Levels: keyswitch position 0 is level 7, "no inputs" (002 L1381-1388); position 1 (level 6)
allows "tool wear entry, and work offset entry" (002 L1372-1379); a password overrides the
keyswitch (002 L1403-1406); CUSTOMER opens level 3 (002 L1439-1449). The trainer's levels for
each function are the USER_CLASS data in data/md/display.toml (R parameters 6, tool geometry 4,
setting data 4).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import nck.cli
from nck.cli import main
from nck.persistence import Session


def _program(tmp_path: Path, text: str = "R1=$SC_DRY_RUN_FEED R2=$TC_DP3[1,1] R3=R9\nM30\n") -> Path:
    path = tmp_path / "P.MPF"
    path.write_text(text)
    return path


def _retained(data_dir: Path) -> dict[str, str]:
    folder = data_dir / "retained"
    return {p.name: p.read_text() for p in sorted(folder.glob("*.json"))}


@pytest.mark.parametrize("setting", ["SD42100=2000", "R9=5", "$TC_DP3[1,1]=100", "$P_UIFR[1,X,TR]=10"])
def test_set_at_keyswitch_0_is_refused_and_nothing_is_saved(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], setting: str) -> None:
    data_dir = tmp_path / "data"
    Session.open(data_dir)  # a fresh data directory: keyswitch position 0, level 7
    before = _retained(data_dir)
    assert main(["run", str(_program(tmp_path)), "--data-dir", str(data_dir), "--set", setting]) == 2
    err = capsys.readouterr().err
    assert "refused" in err and "level 7" in err and "Traceback" not in err
    assert _retained(data_dir) == before


def test_the_stored_keyswitch_and_a_password_give_the_level(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(nck.cli, "wait_s", lambda seconds: None)  # a wrong password waits 1 s
    data_dir = tmp_path / "data"
    session = Session.open(data_dir)
    session.access.set_keyswitch(1)  # level 6: work offsets and R parameters, not tool geometry
    session.save()
    program = str(_program(tmp_path))
    assert main(["run", program, "--json", "--data-dir", str(data_dir), "--set", "R9=5",
                 "--set", "$P_UIFR[1,X,TR]=10"]) == 0
    assert json.loads(capsys.readouterr().out)["r"]["3"] == 5.0
    assert main(["run", program, "--data-dir", str(data_dir), "--set", "$TC_DP3[1,1]=100"]) == 2
    assert "needs protection level 4" in capsys.readouterr().err
    assert main(["run", program, "--data-dir", str(data_dir), "--set", "$TC_DP3[1,1]=100",
                 "--password", "WRONG"]) == 2
    assert "password not accepted" in capsys.readouterr().err
    assert main(["run", program, "--json", "--data-dir", str(data_dir), "--set", "$TC_DP3[1,1]=100",
                 "--set", "SD42100=2000", "--password", "CUSTOMER"]) == 0
    assert json.loads(capsys.readouterr().out)["r"] == {"1": 2000.0, "2": 100.0, "3": 5.0, "9": 5.0}
    again = Session.open(data_dir)  # saved like a panel write
    assert again.ncdata.setting_data["SD42100"] == 2000.0
    assert again.access.level == 6  # the password was for this call only


@pytest.mark.parametrize("setting, words", [
    ("SD42100=fast", "SD42100: “fast” is not valid, enter a number"),
    ("SD42100=-5", "below the lower limit"),
    ("SD42101=1.5", "“1.5” is not valid, enter a whole number"),
    ("R9=abc", "“abc” is not a number"),
    ("R99999=1", "R parameter 99999 does not exist"),
    ("$TC_DP1[1,1]=120.5", "whole number"),
    ("$TC_DP3[1,1]=1e9", "outside"),
    ("$P_UIFR[1,Q,TR]=1", "no axis Q"),
    ("$P_UIFR[1,X,SC]=0", "scale factor"),
])
def test_values_are_type_and_limit_checked(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                           setting: str, words: str) -> None:
    data_dir = tmp_path / "data"
    Session.open(data_dir)
    before = _retained(data_dir)
    assert main(["run", str(_program(tmp_path)), "--data-dir", str(data_dir), "--set", setting,
                 "--password", "SUNRISE"]) == 2
    err = capsys.readouterr().err
    assert words in err and "could not convert" not in err and "Traceback" not in err
    assert _retained(data_dir) == before


def test_tool_table_follows_the_tool_geometry_level(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    tools = tmp_path / "tools.toml"
    tools.write_text("[[edge]]\nt = 1\nlength1 = 75\nradius = 4\n")
    data_dir = tmp_path / "data"
    Session.open(data_dir)
    before = _retained(data_dir)
    program = str(_program(tmp_path))
    assert main(["run", program, "--data-dir", str(data_dir), "--tools", str(tools)]) == 2
    assert "--tools $TC_DP3[1,1]: refused: Writing tool geometry" in capsys.readouterr().err
    assert _retained(data_dir) == before
    huge = tmp_path / "huge.toml"
    huge.write_text("[[edge]]\nt = 1\nlength1 = 1e12\n")
    assert main(["run", program, "--data-dir", str(data_dir), "--tools", str(huge),
                 "--password", "CUSTOMER"]) == 2
    assert "outside" in capsys.readouterr().err
    assert main(["run", program, "--json", "--data-dir", str(data_dir), "--tools", str(tools),
                 "--password", "CUSTOMER"]) == 0
    assert json.loads(capsys.readouterr().out)["r"]["2"] == 75.0


def test_fresh_nc_data_without_a_data_directory_is_level_7_too(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("NCK_DATA_DIR", str(tmp_path / "none"))  # no user data directory
    program = str(_program(tmp_path))
    assert main(["run", program, "--set", "SD42100=2000"]) == 2
    assert main(["run", program, "--json", "--set", "SD42100=2000", "--password", "CUSTOMER"]) == 0
    assert json.loads(capsys.readouterr().out)["r"]["1"] == 2000.0
