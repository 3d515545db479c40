"""Robustness: random sequences of panel keys never crash the HMI or the kernel."""

from __future__ import annotations

import random

import pytest

from nck.kernel import Nck

from hmi.app import HmiApp
from hmi.keymap import default_keymap
from hmi.programs import DirectoryPrograms
from tests.hmi.conftest import SIZE
from tests.one_key import send_key

PROGRAM = "N10 G90 G0 X10 Y10 Z5\nN20 G1 X30 F2000\nN30 M0\nN40 Y30\nN50 M30\n"


@pytest.mark.parametrize("seed", [1, 2])
async def test_random_panel_keys_keep_everything_alive(seed: int, tmp_path) -> None:
    """60 random keymap keys (plus typing and Enter), kernel advanced between: no crash, no internal error."""
    (tmp_path / "RND.MPF").write_text(PROGRAM)
    nck = Nck(programs=DirectoryPrograms([tmp_path]), referenced=True)
    app = HmiApp(nck, realtime=False)
    keys = [k.strip() for b in default_keymap().bindings if b.id != "app.quit"
            for k in b.keys.split(",")] + ["enter", "down", "escape", "N", "1", "G"]
    rng = random.Random(seed)
    async with app.run_test(size=SIZE) as pilot:
        for _ in range(60):
            await send_key(app, pilot, rng.choice(keys))  # handled before the next, as by pilot.press
            app.bridge.advance(rng.choice([0.0, 0.05, 0.3]))
        await pilot.pause()
        assert app.is_running
        assert app.internal_errors == []
        assert nck.internal_errors == []
