"""SVG snapshots of the main screens in German (issue 27): Machine JOG, MDA and AUTO, Parameter
(tool list, active work offsets), the alarm list, the Program manager and Setup. The English
pictures of the same screens are in tests/hmi,
tests/diagnostics, tests/program_screens and tests/parameter_setup; these set the panel's
language to German first (as Setup ▸ Change language or ``hmi --lang de`` do)."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from hmi.app import HmiApp, make_app
from hmi.i18n import set_language
from tests.diagnostics.conftest import app_on
from tests.diagnostics.staged import AUTO_LIMIT, JOG_LIMIT, StagedKernel, stamped
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck
from tests.parameter_setup.conftest import FROZEN_NOW
from tests.program_screens.conftest import DEMO_PROGRAM, make_program_app, nc_files

PINNED_NS = 1_790_000_000 * 10**9  # 2026-09-21 14:13 UTC


@pytest.fixture(autouse=True)
def german(monkeypatch: pytest.MonkeyPatch) -> None:
    """The panel's texts in German (the suite's fixture puts English back afterwards); the Setup
    area's date and time from a fixed moment, as in tests/parameter_setup."""
    import screens.setup

    monkeypatch.setattr(screens.setup, "wall_clock", lambda: FROZEN_NOW)
    set_language("de")


def test_machine_jog(snap_compare) -> None:
    """JOG after power on: header (MASCHINE, Kanal RESET), MKS/WKS window, softkeys in German."""
    assert snap_compare(HmiApp(FakeNck(), realtime=False), terminal_size=SIZE)


def test_machine_jog_with_alarm(snap_compare) -> None:
    """An alarm in the header line, its text from data/lang/de/alarms.toml."""
    fake = FakeNck(referenced=True)
    fake.alarms.append(AUTO_LIMIT)  # 10720 with its parameters: channel 1, N10, X, +
    assert snap_compare(HmiApp(fake, realtime=False), terminal_size=SIZE)


def test_alarm_list(snap_compare) -> None:
    """Diagnostics ▸ alarm list: German columns, alarm texts and clear legend."""
    nck = StagedKernel()
    nck.staged_alarms = (AUTO_LIMIT, JOG_LIMIT)

    async def run_before(pilot) -> None:
        await pilot.press("alt+a")
        await pilot.pause()

    assert snap_compare(stamped(app_on(nck)), terminal_size=SIZE, run_before=run_before)


def test_program_manager(snap_compare, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Program manager with two part programs and a subprogram (dates pinned, TZ=UTC)."""
    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "DEMO.MPF").write_text(DEMO_PROGRAM)
    (root / "MPF" / "POCKET.MPF").write_text("N10 G0 X0 Y0\nN20 M30\n")
    (root / "SPF" / "CONTOUR.SPF").write_text("G1 X10\nM17\n")
    for folder in ("MPF", "SPF"):
        for path in (root / folder).iterdir():
            os.utime(path, ns=(PINNED_NS, PINNED_NS))
    monkeypatch.setenv("TZ", "UTC")
    time.tzset()
    try:
        assert snap_compare(make_program_app(root), terminal_size=SIZE, press=["alt+n"])
    finally:
        monkeypatch.undo()
        time.tzset()


@pytest.mark.parametrize(("name", "keys"), [
    ("axis_md", ["alt+s", "f3"]),
    ("password", ["alt+s", "f6"]),
    ("language", ["alt+s", "f6", "shift+f5"]),
])
def test_setup(snap_compare, tmp_path: Path, name: str, keys: list[str]) -> None:
    """Setup: axis machine data (German titles in the hint), the password view, the language selection."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        assert snap_compare(app, terminal_size=SIZE, press=keys)
    finally:
        app.nc_session.quit()


def test_machine_mda(snap_compare) -> None:
    """MDA with a block typed: the MDA window's title and state word in German."""
    from tests.hmi.test_machine_snapshots import app_on, referenced_fake

    assert snap_compare(app_on(referenced_fake()), terminal_size=SIZE, press=["alt+d", *"G0 X12.5 Y-7 Z-3"])


def test_machine_auto(snap_compare) -> None:
    """AUTO with a program stopped in single block: header, program window, softkeys in German."""
    from tests.hmi.test_machine_snapshots import app_on, auto_fake

    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE)


@pytest.mark.parametrize(("name", "keys"), [
    ("tools", ["alt+o", "down"]),
    ("wo_active", ["alt+o", "f3", "shift+f1"]),
])
def test_parameter(snap_compare, tmp_path: Path, name: str, keys: list[str]) -> None:
    """Parameter: the tool list and the active work offsets (frame names, totals) in German."""
    from tests.parameter_setup.conftest import fill

    app = make_app(data_dir=str(tmp_path), realtime=False, lang="de")
    try:
        fill(app)
        assert snap_compare(app, terminal_size=SIZE, press=["alt+t", "alt+t", *keys])
    finally:
        app.nc_session.quit()
