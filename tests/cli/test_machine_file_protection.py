"""A machine file the user passes cannot lower protection levels (issue 19).

The USER_CLASS display data hold the level each function needs (002 L1319-1411: levels 4-7
"can be altered by the machine tool manufacturer or end user" — on the control, from a level
that has the right, never by whoever hands in a file). The trainer's product value of
MD9215 USER_CLASS_WRITE_SEA (write setting data) is 4 (data/md/display.toml).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.cli import main
from nck.machine import MachineFileError, load_machine
from nck.persistence import Session
from nck.resources import data_path


def _machine_file(tmp_path: Path, extra_md: str) -> Path:
    text = data_path("machines", "mill3.toml").read_text(encoding="utf-8")
    path = tmp_path / "evil.toml"
    path.write_text(text.replace("[md]\n", f"[md]\n{extra_md}\n", 1), encoding="utf-8")
    return path


@pytest.mark.parametrize("extra", ["MD9215 = 7", "MD9201 = 5", "MD9215 = 8", "MD9215 = -1",
                                   'MD9215 = "7"', "MD9215 = true"])
def test_a_machine_file_cannot_loosen_a_user_class(tmp_path: Path, extra: str) -> None:
    with pytest.raises(MachineFileError, match="protection level"):
        load_machine(str(_machine_file(tmp_path, extra)))


def test_a_machine_file_may_make_protection_stricter(tmp_path: Path) -> None:
    machine = load_machine(str(_machine_file(tmp_path, "MD9215 = 2")))
    assert machine.md["MD9215"] == 2


@pytest.mark.parametrize("command", [
    ["run", "{prog}", "--set", "SD42100=2000"],
    ["check", "{prog}"],
    ["md", "SD42100=2000"],
])
def test_every_door_refuses_the_file_and_writes_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], command: list[str]) -> None:
    data_dir = tmp_path / "data"
    Session.open(data_dir)
    before = (data_dir / "retained" / "setting_data.json").read_text()
    prog = tmp_path / "P.MPF"
    prog.write_text("M30\n")
    evil = _machine_file(tmp_path, "MD9215 = 7")
    argv = [part.format(prog=prog) for part in command]
    argv[1:1] = ["--machine", str(evil), "--data-dir", str(data_dir)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "MD9215 = 7 would lower the protection level 4" in err and "Traceback" not in err
    assert (data_dir / "retained" / "setting_data.json").read_text() == before
