"""`hmi --program FILE` never replaces an NC program of the same name unasked (issue 19).

Editing a program needs the level of `edit_program` (data/access.toml: 4, keyswitch position 3
or a password; 002 L1355-1388); the old program is kept as a copy in the NC memory.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hmi.app import main as hmi_main
from hmi.startup import build_session
from nck.persistence import Session

OLD = "N10 G0 X1\nM30\n"
NEW = "N10 G0 X2\nM30\n"


def _prepare(tmp_path: Path, keyswitch: int = 0) -> tuple[Path, Path]:
    data_dir = tmp_path / "data"
    session = Session.open(data_dir)
    session.files.save("MPF/MYPART.MPF", OLD)
    session.access.set_keyswitch(keyswitch)
    session.save()
    local = tmp_path / "MYPART.MPF"
    local.write_text(NEW)
    return data_dir, local


def _nc_programs(data_dir: Path) -> dict[str, str]:
    files = Session.open(data_dir).files
    return {e.name: files.read(e.path) for e in files.list_directory("MPF") if e.name.startswith("MYPART")}


def _open(data_dir: Path, local: Path, confirm=None) -> None:
    holder = build_session(data_dir=str(data_dir), program=str(local), confirm=confirm)
    holder.quit()


def test_without_editing_rights_the_program_is_not_replaced(tmp_path: Path) -> None:
    data_dir, local = _prepare(tmp_path)
    asked: list[str] = []
    with pytest.raises(ValueError, match="needs protection level 4"):
        _open(data_dir, local, confirm=lambda q: asked.append(q) or True)
    assert asked == [] and _nc_programs(data_dir) == {"MYPART.MPF": OLD}


def test_with_rights_it_asks_and_a_no_keeps_the_program(tmp_path: Path) -> None:
    data_dir, local = _prepare(tmp_path, keyswitch=3)  # level 4
    asked: list[str] = []
    with pytest.raises(ValueError, match="not replaced"):
        _open(data_dir, local, confirm=lambda q: asked.append(q) or False)
    assert len(asked) == 1 and "MPF/MYPART.MPF already exists" in asked[0]
    assert _nc_programs(data_dir) == {"MYPART.MPF": OLD}
    with pytest.raises(ValueError, match="not replaced"):
        _open(data_dir, local)  # nobody to ask: no


def test_a_yes_replaces_it_and_keeps_the_old_one(tmp_path: Path) -> None:
    data_dir, local = _prepare(tmp_path, keyswitch=3)
    _open(data_dir, local, confirm=lambda q: True)
    assert _nc_programs(data_dir) == {"MYPART.MPF": NEW, "MYPART_OLD1.MPF": OLD}
    local.write_text("N10 G0 X3\nM30\n")
    _open(data_dir, local, confirm=lambda q: True)
    assert _nc_programs(data_dir) == {"MYPART.MPF": "N10 G0 X3\nM30\n", "MYPART_OLD1.MPF": OLD,
                                      "MYPART_OLD2.MPF": NEW}


def test_the_same_text_is_selected_without_a_question(tmp_path: Path) -> None:
    data_dir, local = _prepare(tmp_path)
    local.write_text(OLD)
    _open(data_dir, local, confirm=lambda q: pytest.fail("asked"))
    assert _nc_programs(data_dir) == {"MYPART.MPF": OLD}


def test_the_console_script_says_why(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir, local = _prepare(tmp_path)
    assert hmi_main(["--data-dir", str(data_dir), "--program", str(local)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("hmi: program") and "needs protection level 4" in err
    assert _nc_programs(data_dir) == {"MYPART.MPF": OLD}
