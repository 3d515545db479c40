"""Every protected write of the Parameter/Setup areas × every reachable access level.

Through kernel commands (the path the screens use): a write is taken exactly when
the current level is at or below the level configured for the datum (USER_CLASS
display data, ``data/access.toml``, the ``protect`` of each MD/SD); a refused
write changes nothing and names the level it needs. Level 0 has no password, so
levels 1–7 are tested (passwords 1–3, keyswitch positions 3…0).
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from nck import commands as c
from nck.access import Action
from nck.kernel import Nck
from nck.ncdata import ToolEdge
from nck.persistence import Session

PASSWORDS = {1: "SUNRISE", 2: "EVENING", 3: "CUSTOMER"}

# (what, command, how the configured level is found, level the trainer ships)
CASES = [
    ("R parameter", c.WriteData("R5", 1.5), ("action", Action.WRITE_R_PARAMETER), 6),
    ("clear all R", c.ClearRParameters(), ("action", Action.CLEAR_R_PARAMETERS), 5),
    ("tool geometry", c.WriteData("$TC_DP3[1,1]", 50), ("action", Action.WRITE_TOOL_GEOMETRY), 4),
    ("new tool", c.WriteData("$TC_DP1[9,1]", 120), ("action", Action.WRITE_TOOL_GEOMETRY), 4),
    ("delete tool", c.DeleteToolEdge(1), ("action", Action.WRITE_TOOL_GEOMETRY), 4),
    ("tool wear", c.WriteData("$TC_DP12[1,1]", -0.1), ("action", Action.WRITE_TOOL_WEAR), 6),
    ("work offset", c.WriteData("$P_UIFR[1,X,TR]", 10), ("action", Action.WRITE_WORK_OFFSET), 6),
    ("work offset rotation", c.WriteData("$P_UIFR[2,Z,RT]", 45), ("action", Action.WRITE_WORK_OFFSET), 6),
    ("base frame", c.WriteData("$P_UBFR[Z,TR]", 1), ("action", Action.WRITE_WORK_OFFSET), 6),
    ("user variable", c.WriteData("GUD:COUNT", 4), ("action", Action.WRITE_USER_DATA), 4),
    ("setting datum", c.WriteData("SD41110", 500), ("md", "SD41110"), 4),
    ("dry run feed", c.WriteData("SD42100", 800), ("md", "SD42100"), 4),
    ("axis MD", c.WriteData("MD32000[X]", 1200), ("md", "MD32000[X]"), 2),
    ("channel MD", c.WriteData("MD20700", 0), ("md", "MD20700"), 2),
    ("R count MD", c.WriteData("MD28050", 50), ("md", "MD28050"), 1),
    ("display MD", c.WriteData("MD9000", 5), ("md", "MD9000"), 3),
]


def snapshot(nck: Nck, session: Session) -> object:
    """Everything a refused write must leave as it was."""
    data = nck.data
    return copy.deepcopy((data.r, data.tools, data.settable_frames, data.base_frame, data.gud,
                          data.setting_data, session.md.retained_changes()))


@pytest.fixture(scope="module")
def data_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One data directory with a tool and a GUD; each test opens its own copy of the state."""
    path = tmp_path_factory.mktemp("matrix")
    session = Session.open(path, install_samples=False)
    session.ncdata.tools.clear()
    session.ncdata.tools[(1, 1)] = ToolEdge({1: 120, 3: 40.0})
    session.ncdata.gud["COUNT"] = 3
    session.ncdata.r[5] = 2.0
    session.save()
    return path


@pytest.mark.parametrize("level", [1, 2, 3, 4, 5, 6, 7])
def test_each_datum_at_each_level(data_dir: Path, tmp_path: Path, level: int) -> None:
    import shutil

    shutil.copytree(data_dir, tmp_path / "d")
    session = Session.open(tmp_path / "d", install_samples=False)
    nck = Nck(**session.kernel_arguments())
    nck.md_store = session.md
    if level in PASSWORDS:
        assert nck.submit(c.EnterPassword(PASSWORDS[level])) == c.Accepted()
    else:
        assert nck.submit(c.SetKeyswitch(7 - level)) == c.Accepted()
    assert nck.status().access_level == level
    for what, command, (kind, key), shipped in CASES:
        configured = session.access.required(key) if kind == "action" else session.md.required_write_level(key)
        assert configured == shipped, f"{what}: configured level {configured}"
        before = snapshot(nck, session)
        result = nck.submit(command)
        if level <= configured:
            assert result == c.Accepted(), f"{what} at level {level}: {result}"
        else:
            assert isinstance(result, c.Rejected), f"{what} at level {level} was taken"
            assert f"level {configured}" in result.reason, result.reason
            assert snapshot(nck, session) == before, f"{what}: a refused write changed data"
        # undo effects that would hide later refusals (a deleted tool, cleared R)
        nck.data.tools.setdefault((1, 1), ToolEdge({1: 120, 3: 40.0}))
    assert nck.internal_errors == []


def test_user_class_changes_the_level_at_once(tmp_path: Path) -> None:
    session = Session.open(tmp_path, install_samples=False)
    nck = Nck(**session.kernel_arguments())
    nck.md_store = session.md
    assert isinstance(nck.submit(c.WriteData("R1", 1)), c.Rejected)  # level 7, R needs 6
    nck.submit(c.EnterPassword("CUSTOMER"))
    assert nck.submit(c.WriteData("MD9222", 7)) == c.Accepted()  # USER_CLASS_WRITE_RPA, so
    assert "level 3" in nck.submit(c.WriteData("MD9222", 2)).reason  # not above one's own level
    nck.submit(c.DeletePassword())
    assert nck.submit(c.WriteData("R1", 1)) == c.Accepted()
