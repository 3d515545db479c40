"""Corrupted retained data, fuzzed: any bytes in any NC-data file end with alarm 4060/4065, never an exception.

Each example damages the main file (and sometimes its backup) of one retained
section with random bytes or a mutation of the real content; starting again
must succeed, name the file in a 4065 (backup used) or 4060 (standard values)
alarm unless the damage left valid data, keep the bad file for inspection, and
leave every other section intact.
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck.atomic import backup_path
from nck.ncdata import ToolEdge
from nck.persistence import SECTIONS, Session

SECTION_NAMES = sorted(SECTIONS)


def _template() -> Path:
    """A data directory with two generations of every section."""
    root = Path(tempfile.mkdtemp(prefix="nck-corrupt-template-"))
    atexit.register(shutil.rmtree, root, True)  # one per test process: gone when it ends
    session = Session.open(root, install_samples=False)
    data = session.ncdata
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 75.5, 6: 5.0})
    data.r[3] = 3.5
    data.settable_frames["G54"].trans["X"] = -250.0
    session.save()
    data.tools[(2, 1)] = ToolEdge({1: 200.0, 3: 100.0})
    data.r[4] = 4.5
    data.settable_frames["G54"].trans["Y"] = -120.0
    session.save()
    return root


TEMPLATE = _template()


@st.composite
def damages(draw: st.DrawFn) -> tuple[str, bytes, bytes | None]:
    """(section, new main bytes, new backup bytes or None to keep the backup)."""
    name = draw(st.sampled_from(SECTION_NAMES))
    original = (TEMPLATE / "retained" / f"{name}.json").read_bytes()

    def damaged() -> bytes:
        kind = draw(st.sampled_from(["binary", "truncate", "flip", "text"]))
        if kind == "binary":
            return draw(st.binary(max_size=300))
        if kind == "truncate":
            return original[: draw(st.integers(0, max(len(original) - 1, 0)))]
        if kind == "text":
            return draw(st.text(max_size=200)).encode("utf-8", "surrogatepass")
        raw = bytearray(original)
        for _ in range(draw(st.integers(1, 5))):
            if raw:
                raw[draw(st.integers(0, len(raw) - 1))] = draw(st.integers(0, 255))
        return bytes(raw)

    main = damaged()
    backup = damaged() if draw(st.booleans()) else None
    return name, main, backup


def _check(damage: tuple[str, bytes, bytes | None], root: Path) -> None:
    name, main_bytes, backup_bytes = damage
    shutil.copytree(TEMPLATE, root)
    main = root / "retained" / f"{name}.json"
    main.write_bytes(main_bytes)
    if backup_bytes is not None:
        backup_path(main).write_bytes(backup_bytes)
    session = Session.open(root, install_samples=False)
    numbers = [a.number for a in session.startup_alarms]
    assert set(numbers) <= {4060, 4065} and len(numbers) <= 1
    if numbers:
        alarm = session.startup_alarms[0]
        assert alarm.params[0] == f"{name}.json"
        assert list((root / "retained").glob(f"{name}.json.bad-*")), "the bad file was not kept"
    data = session.ncdata
    if name != "tools":
        assert set(data.tools) == {(1, 1), (2, 1)}
    if name != "work_offsets":
        assert data.settable_frames["G54"].trans["Y"] == -120.0
    assert Session.open(root, install_samples=False).startup_alarms == []  # whole again


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck), database=None)
@given(damages())
def test_any_damage_to_a_data_file_ends_with_an_alarm_not_an_exception(damage) -> None:
    with tempfile.TemporaryDirectory() as temp:
        _check(damage, Path(temp) / "data")


@pytest.mark.fuzz
@settings(max_examples=3000, deadline=None, suppress_health_check=list(HealthCheck), database=None)
@given(damages())
def test_any_damage_to_a_data_file_long(damage) -> None:
    with tempfile.TemporaryDirectory() as temp:
        _check(damage, Path(temp) / "data")
