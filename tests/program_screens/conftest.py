"""Fixtures of the program-screen tests: an NC data directory, the HMI on a real kernel."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.commands import SetKeyswitch
from nck.kernel import Nck
from nck.machine import load_machine

from hmi.app import HmiApp
from hmi.cycle_forms import cycle_menus
from nck import programs_in_execution
from nck.storage import NcFileSystem

SIZE = (160, 48)

DEMO_PROGRAM = (
    "; pocket outline\n"
    "N10 G90 G0 X0 Y0 Z5\n"
    "N20 G1 Z-1 F200\n"
    "N30 X40\n"
    "N40 Y30\n"
    "N50 X0\n"
    "N60 Y0\n"
    "N70 G0 Z50\n"
    "N80 M30\n"
)


def nc_files(root: Path) -> NcFileSystem:
    """The NC file system ``root`` (``MPF``, ``SPF``, ``WKS``)."""
    return NcFileSystem(root)


def make_program_app(root: Path, referenced: bool = True, keyswitch: int = 3) -> HmiApp:
    """The HMI on a real kernel whose programs live in the NC file system ``root``.

    As in the app, the program being executed counts as in use for the file system.
    The keyswitch starts in position 3 (level 4: programs may be edited and selected).
    """
    files = nc_files(root)
    nck = Nck(programs=files, referenced=referenced)
    nck.submit(SetKeyswitch(keyswitch))
    files.in_use_check = lambda: programs_in_execution(nck.status())
    return HmiApp(nck, realtime=False)


def lathe_program_app(root: Path) -> HmiApp:
    """As :func:`make_program_app`, on the lathe ``lathe2``."""
    files = nc_files(root)
    nck = Nck(machine=load_machine("lathe2"), programs=files, referenced=True)
    nck.submit(SetKeyswitch(3))
    files.in_use_check = lambda: programs_in_execution(nck.status())
    return HmiApp(nck, realtime=False)


@pytest.fixture
def data_dir(tmp_path: Path) -> Path:
    """An NC data directory with one part program ``MPF/DEMO.MPF``."""
    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "DEMO.MPF").write_text(DEMO_PROGRAM)
    return root


async def settle(pilot) -> None:
    """Let the editor's check worker finish and its results reach the screen."""
    await pilot.pause()
    await pilot.app.workers.wait_for_complete()
    await pilot.pause()


def keys_to_form(cycle: str) -> list[str]:
    """The keys from the editor to ``cycle``'s form: Shift+F7, the menu's horizontal softkey,
    the key's vertical softkey (and the sub-level's when the key holds several cycles)."""
    for menu_index, menu in enumerate(cycle_menus()):
        for key_index, key in enumerate(menu.keys):
            if cycle in key.cycles:
                keys = ["shift+f7", f"f{menu_index + 1}", f"shift+f{key_index + 1}"]
                if len(key.cycles) > 1:
                    keys.append(f"shift+f{key.cycles.index(cycle) + 1}")
                return keys
    raise AssertionError(f"{cycle} has no softkey")


def on_lathe(cycle: str) -> bool:
    """True for the turning cycles (their menu is the lathe's)."""
    return any(cycle in menu.cycles() for menu in cycle_menus() if menu.machine == "lathe")
