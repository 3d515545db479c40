"""`nck md`: read and write MD/SD of a data directory with level and limit checks."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from nck.cli_md import run
from nck.persistence import Session

ROOT = Path(__file__).resolve().parents[2]


def md(data_dir: Path, *args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    code = run(["--data-dir", str(data_dir), *args], out, err)
    return code, out.getvalue(), err.getvalue()


def test_read_by_number_and_identifier(tmp_path: Path) -> None:
    code, out, err = md(tmp_path, "MD32000[X]", "$MA_MAX_AX_VELO[X]", "SD42100", "$SC_DRY_RUN_FEED")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0] == lines[1] == "MD32000[X] $MA_MAX_AX_VELO[X] = 30000 mm/min"
    assert lines[2] == lines[3] == "SD42100 $SC_DRY_RUN_FEED = 5000 mm/min"


def test_axis_datum_without_axis_lists_every_axis(tmp_path: Path) -> None:
    code, out, _ = md(tmp_path, "MD36110")
    assert code == 0
    assert out.splitlines()[:3] == ["MD36110[X] $MA_POS_LIMIT_PLUS[X] = 500 mm",
                                    "MD36110[Y] $MA_POS_LIMIT_PLUS[Y] = 400 mm",
                                    "MD36110[Z] $MA_POS_LIMIT_PLUS[Z] = 400 mm"]


def test_fresh_dir_keyswitch_0_refuses_md_write(tmp_path: Path) -> None:
    code, out, err = md(tmp_path, "MD32000[X]=5000")
    assert code == 1 and out == ""
    assert "needs protection level 2" in err and "level 7" in err
    assert md(tmp_path, "MD32000[X]")[1].strip().endswith("= 30000 mm/min")


def test_password_evening_allows_and_says_when_it_takes_effect(tmp_path: Path) -> None:
    code, out, err = md(tmp_path, "--password", "EVENING", "MD32000[X]=5000")
    assert code == 0, err
    assert out.startswith("MD32000[X] $MA_MAX_AX_VELO[X] = 5000 mm/min (was 30000)")
    assert "takes effect at NEW CONFIG" in out
    assert md(tmp_path, "$MA_MAX_AX_VELO[X]")[1].strip().endswith("= 5000 mm/min")
    # the password was for that call only
    assert Session.open(tmp_path, install_samples=False).access.level == 7
    assert md(tmp_path, "MD32000[X]=6000")[0] == 1


@pytest.mark.parametrize("name, effect", [("SD42100=100", "immediately"),
                                          ("MD36110[X]=300", "at RESET"),
                                          ("MD10070=2", "at POWER ON"),
                                          ("MD32200[0,X]=3", "immediately")])
def test_activation_is_reported(tmp_path: Path, name: str, effect: str) -> None:
    code, out, err = md(tmp_path, "--password", "EVENING", name)
    assert code == 0, err
    assert f"takes effect {effect}" in out


def test_customer_is_not_enough_for_md32000(tmp_path: Path) -> None:
    code, _, err = md(tmp_path, "--password", "CUSTOMER", "MD32000[X]=5000")
    assert code == 1 and "needs protection level 2" in err and "level 3" in err


def test_setting_data_with_keyswitch_level(tmp_path: Path) -> None:
    assert md(tmp_path, "SD42100=100")[0] == 1
    session = Session.open(tmp_path, install_samples=False)
    session.access.set_keyswitch(3)  # level 4
    session.save()
    code, out, _ = md(tmp_path, "$SC_DRY_RUN_FEED=100")
    assert code == 0 and "= 100 mm/min (was 5000)" in out


@pytest.mark.parametrize("write", ["MD32000[X]=-1", "MD32000[X]=fast", "SD42101=13",
                                   "MD9004=9", "MD36110[X]=1e12"])
def test_limits_refused_and_nothing_written(tmp_path: Path, write: str) -> None:
    before = md(tmp_path, "--password", "SUNRISE", "MD32000[X]", "SD42101", "MD9004", "MD36110[X]")[1]
    code, out, err = md(tmp_path, "--password", "SUNRISE", write)
    assert code == 1 and out == "" and "refused" in err
    assert md(tmp_path, "--password", "SUNRISE", "MD32000[X]", "SD42101", "MD9004", "MD36110[X]")[1] == before


def test_all_writes_are_checked_before_any_is_made(tmp_path: Path) -> None:
    code, _, err = md(tmp_path, "--password", "EVENING", "SD42100=100", "MD32000[X]=-5")
    assert code == 1 and "nothing was written" in err
    assert md(tmp_path, "SD42100")[1].strip().endswith("= 5000 mm/min")


@pytest.mark.parametrize("args", [["MD99999"], ["$MA_NOPE[X]"], ["MD32000[Q]=5"],
                                  ["--machine", "no_such_machine", "MD32000[X]"], ["--bogus"]])
def test_command_line_problems_exit_2(tmp_path: Path, args: list[str]) -> None:
    code, _, err = md(tmp_path, *args)
    assert code == 2 and err.startswith("nck md:")


def test_wrong_password_exits_1(tmp_path: Path) -> None:
    code, _, err = md(tmp_path, "--password", "WRONG", "MD32000[X]=5000")
    assert code == 1 and "password not accepted" in err
    assert md(tmp_path, "--password", "TOOLONGPASSWORD", "SD42100")[0] == 1


def test_ephemeral_writes_nothing_back(tmp_path: Path) -> None:
    code, out, _ = md(tmp_path, "--ephemeral", "--password", "EVENING", "MD32000[X]=5000")
    assert code == 0 and "5000" in out
    assert md(tmp_path, "MD32000[X]")[1].strip().endswith("= 30000 mm/min")


def test_other_machine(tmp_path: Path) -> None:
    code, out, _ = md(tmp_path, "--machine", "lathe2", "MD20100")
    assert code == 0 and out.startswith("MD20100 $MC_DIAMETER_AX_DEF = X")


def test_listing_everything(tmp_path: Path) -> None:
    code, out, _ = md(tmp_path)
    assert code == 0
    assert "MD32000[SP] $MA_MAX_AX_VELO[SP] = 8000 rev/min" in out  # a spindle speed
    assert "SD43420[X] $SA_WORKAREA_LIMIT_PLUS[X]" in out
    assert "MD20154" not in out  # readable only from level 2


def test_damaged_file_reported_as_alarm(tmp_path: Path) -> None:
    md(tmp_path, "SD42100")
    (tmp_path / "retained" / "setting_data.json").write_text("{\"format\":")
    code, out, err = md(tmp_path, "SD42100")
    assert code == 0 and out.strip().endswith("= 5000 mm/min")
    assert err.startswith("ALARM 4060 - - Retained data setting_data.json unreadable")  # no backup yet


def test_console_entry_dispatches_md(tmp_path: Path) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-m", "nck", "md", "--data-dir", str(tmp_path),
                           "MD32000[X]=5000"], capture_output=True, text=True, env=env)
    assert proc.returncode == 1 and "protection level 2" in proc.stderr
    proc = subprocess.run([sys.executable, "-m", "nck", "md", "--data-dir", str(tmp_path),
                           "--password", "EVENING", "MD32000[X]=5000"],
                          capture_output=True, text=True, env=env)
    assert proc.returncode == 0 and "takes effect" in proc.stdout


def test_bare_number_finds_setting_data_too(tmp_path: Path) -> None:
    """`nck md 42100` answers as `nck md SD42100` (one catalogue for MD and SD)."""
    code, out, err = md(tmp_path, "42100")
    assert code == 0, err
    assert out == md(tmp_path, "SD42100")[1] == "SD42100 $SC_DRY_RUN_FEED = 5000 mm/min\n"


def test_spindle_and_rotary_data_in_their_own_units(tmp_path: Path) -> None:
    """Software limits of a spindle are angles, its maximum velocity is a speed (rev/min);
    a linear axis keeps mm and mm/min."""
    code, out, err = md(tmp_path, "MD36100[SP]", "MD32000[SP]", "MD36100[X]")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].endswith(" deg") and lines[1].endswith(" rev/min") and lines[2].endswith(" mm")


@pytest.mark.parametrize(("machine", "mode"), [("mill3", 1), ("lathe2", 0)])
def test_md22550_shows_the_tool_change_mode_the_machine_runs(tmp_path: Path, machine: str, mode: int) -> None:
    """MD22550 TOOL_CHANGE_MODE: 1 on the mill (T prepares, M6 changes: a magazine, 002
    L57620-57625), 0 on the lathe (T changes at once: a turret, 002 L57616-57619); the
    kernel behaves so (tests/kernel/test_values_on_screen.py)."""
    code, out, err = md(tmp_path, "--machine", machine, "MD22550")
    assert code == 0, err
    assert out.strip() == f"MD22550 $MC_TOOL_CHANGE_MODE = {mode}"
