"""``nck archive import``: the archive is one more door to the one write path.

An import changes NC data like the panel, ``nck md`` and ``nck run --set`` do,
so it obeys the same rule (issue 19): each datum it changes needs its
protection level (README: work offsets and wear level 6, tool geometry and
setting data level 4, machine data level 2 or higher; CUSTOMER opens level 3,
SUNRISE level 1), each value is checked against its datum's limits, and a
refused or malformed archive changes nothing and never shows a traceback.
"""

from __future__ import annotations

import io
import json
from pathlib import Path
from typing import Any

import pytest

from nck.cli import main as nck_main
from nck.cli_archive import run as archive_run
from nck.persistence import Session


def _archive(tmp_path: Path, name: str, archive: dict[str, Any]) -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(archive))
    return path


def _exported(tmp_path: Path) -> tuple[Path, dict[str, Any]]:
    data_dir = tmp_path / "data"
    out, err = io.StringIO(), io.StringIO()
    assert archive_run(["export", str(tmp_path / "all.json"), "--data-dir", str(data_dir)], out, err) == 0, err.getvalue()
    return data_dir, json.loads((tmp_path / "all.json").read_text())


def _import(tmp_path: Path, data_dir: Path, path: Path, *extra: str) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    code = archive_run(["import", str(path), "--data-dir", str(data_dir), *extra], out, err)
    return code, err.getvalue()


def _retained(data_dir: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in (data_dir / "retained").iterdir()}


def _with_tool(archive: dict[str, Any], radius_mm: Any) -> dict[str, Any]:
    # a tool added beside those of the fresh data directory (the samples' T1 and T2)
    archive["sections"]["tools"]["edges"].append({"t": 7, "d": 1, "params": {"1": 120.0, "6": radius_mm}})
    return archive


def test_an_unchanged_archive_imports_at_the_keyswitch_level(tmp_path: Path) -> None:
    data_dir, _archive_data = _exported(tmp_path)
    assert _import(tmp_path, data_dir, tmp_path / "all.json") == (0, "")


def test_tool_geometry_needs_its_level_as_through_every_other_door(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir, archive = _exported(tmp_path)
    path = _archive(tmp_path, "tool.json", _with_tool(archive, 5.0))
    before = _retained(data_dir)
    code, message = _import(tmp_path, data_dir, path)
    assert code == 1 and "needs protection level 4" in message and "$TC_DP" in message
    assert _retained(data_dir) == before
    # the same write through nck run --set is refused with the same level
    program = tmp_path / "P.MPF"
    program.write_text("M30\n")
    assert nck_main(["run", "--data-dir", str(data_dir), "--set", "$TC_DP6[7,1]=5", str(program)]) == 2
    assert "needs protection level 4" in capsys.readouterr().err
    assert _import(tmp_path, data_dir, path, "--password", "CUSTOMER")[0] == 0
    assert Session.open(data_dir, install_samples=False).ncdata.tools[(7, 1)].get(6) == 5.0


@pytest.mark.parametrize("case, edit", [
    ("tool radius beyond the limit", lambda a: _with_tool(a, 1e300)),
    ("tool radius as text", lambda a: _with_tool(a, "big")),
    ("setting datum as text", lambda a: a["sections"]["setting_data"]["values"].__setitem__("SD42100", "fast")),
    ("work offset of an axis the machine lacks",
     lambda a: a["sections"]["work_offsets"]["settable"].__setitem__("G54", {"trans": {"Q": 1.0}})),
    ("settable frame that does not exist",
     lambda a: a["sections"]["work_offsets"]["settable"].__setitem__("G99", {"trans": {"X": 1.0}})),
    ("machine datum below its limit",
     lambda a: a["sections"]["machine_data"]["machines"].__setitem__("mill", {"MD32000": {"X": -5.0}})),
    ("user variable holding a table",
     lambda a: a["sections"]["user_data"]["gud"].__setitem__("A", {"b": 1})),
    ("program path naming a directory", lambda a: a.__setitem__("programs", [{"path": "MPF", "text": "M30\n"}])),
    ("workpiece naming a directory", lambda a: a.__setitem__("workpieces", ["MPF"])),
])
def test_a_value_the_datum_does_not_take_is_refused_and_nothing_changes(tmp_path: Path, case: str, edit) -> None:
    data_dir, archive = _exported(tmp_path)
    edit(archive)
    before = _retained(data_dir)
    code, message = _import(tmp_path, data_dir, _archive(tmp_path, "bad.json", archive), "--password", "SUNRISE")
    assert code == 2, (case, message)
    assert message.startswith("nck archive: ") and "Traceback" not in message
    assert _retained(data_dir) == before
    assert not (data_dir / "nc" / "WKS" / "MPF").exists()


def test_passwords_are_imported_only_at_level_1(tmp_path: Path) -> None:
    data_dir, archive = _exported(tmp_path)
    archive["sections"]["access"]["keyswitch_position"] = 3
    path = _archive(tmp_path, "access.json", archive)
    code, message = _import(tmp_path, data_dir, path, "--with-access", "--password", "CUSTOMER")
    assert code == 1 and "passwords needs protection level 1" in message
    assert _import(tmp_path, data_dir, path, "--with-access", "--password", "SUNRISE")[0] == 0
    assert Session.open(data_dir, install_samples=False).access.state.keyswitch_position == 3


def test_the_archive_door_is_reached_through_nck(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert nck_main(["archive", "export", str(tmp_path / "a.json"), "--data-dir", str(tmp_path / "d")]) == 0
    assert nck_main(["archive", "import", str(tmp_path / "a.json"), "--data-dir", str(tmp_path / "d")]) == 0
    assert nck_main(["archive", "import", str(tmp_path / "missing.json"), "--data-dir", str(tmp_path / "d")]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_an_export_never_writes_through_a_link(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("keep\n")
    (tmp_path / "a.json").symlink_to(victim)
    out, err = io.StringIO(), io.StringIO()
    assert archive_run(["export", str(tmp_path / "a.json"), "--data-dir", str(tmp_path / "d")], out, err) == 2
    assert "not a regular file" in err.getvalue() and victim.read_text() == "keep\n"


def test_the_protection_levels_of_a_user_variable_are_not_loosened_by_an_import(tmp_path: Path) -> None:
    """``DEF NCK REAL SECRET APWP 2`` (004 L428-429): part programs below level 2 may not write
    SECRET. An archive holding the same value but no protection would lift that at level 7."""
    data_dir, _unused = _exported(tmp_path)
    session = Session.open(data_dir, install_samples=False)
    session.ncdata.gud["SECRET"] = 1.0
    session.ncdata.gud_access["SECRET"] = {"write": 2}
    session.save()
    archive = json.loads(session.export_archive(tmp_path / "with-secret.json").read_text())
    archive["sections"]["user_data"]["access"] = {}
    path = _archive(tmp_path, "loosened.json", archive)
    code, message = _import(tmp_path, data_dir, path, "--password", "CUSTOMER")
    assert code == 1 and "protection levels of SECRET needs protection level 2" in message
    assert Session.open(data_dir, install_samples=False).ncdata.gud_access["SECRET"] == {"write": 2}
    assert _import(tmp_path, data_dir, path, "--password", "SUNRISE")[0] == 0
