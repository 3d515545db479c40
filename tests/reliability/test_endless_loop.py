"""Endless loops in AUTOMATIC: the HMI stays responsive; NC STOP and RESET end the loop."""

from __future__ import annotations

from pathlib import Path

from nck import commands as c
from nck.kernel import Nck

from hmi.app import HmiApp
from hmi.keymap import default_keymap
from hmi.programs import DirectoryPrograms
from tests.hmi.conftest import SIZE

LOOPS = {
    "COUNT.MPF": "N10 LBL: R1=R1+1\nN20 GOTOB LBL\nN30 M30\n",  # no motion at all
    "WHILE.MPF": "N10 WHILE 1\nN20 R1=R1+1\nN30 ENDWHILE\nN40 M30\n",
    "MOVE.MPF": "N10 G91 G1 F5000\nN20 LBL: X1\nN30 X-1\nN40 R1=R1+1\nN50 GOTOB LBL\nN60 M30\n",
}


def key(binding_id: str) -> str:
    """The first key bound to ``binding_id`` in data/keymap.toml."""
    binding = next(b for b in default_keymap().bindings if b.id == binding_id)
    return binding.keys.split(",")[0].strip()


def timed_advance(app: HmiApp, sim_s: float) -> None:
    """Advance the kernel by ``sim_s`` in 20 ms steps (as the HMI timer does)."""
    for _ in range(round(sim_s / 0.02)):
        app.bridge.advance(0.02)


async def test_endless_loops_stop_with_nc_stop_and_end_with_reset(tmp_path: Path) -> None:
    for name, text in LOOPS.items():
        (tmp_path / name).write_text(text)
    nck = Nck(programs=DirectoryPrograms([tmp_path]), referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        for name in LOOPS:
            assert app.submit(c.SelectMode("AUTO")).__class__.__name__ == "Accepted"
            assert app.submit(c.SelectProgram(name)).__class__.__name__ == "Accepted"
            await pilot.press(key("nc.cycle_start"))
            await pilot.pause()
            timed_advance(app, 2.0)
            status = nck.status()
            assert status.channel.channel_state == "active", name
            counted = nck.data.r[1]
            assert counted > 0, name
            # the panel still answers while the loop runs
            await pilot.press(key("area.diagnostics"))
            await pilot.pause()
            await pilot.press(key("area.machine"))
            await pilot.pause()
            assert app.is_running and app.internal_errors == []
            await pilot.press(key("nc.cycle_stop"))
            await pilot.pause()
            timed_advance(app, 0.5)
            stopped = nck.data.r[1]
            timed_advance(app, 1.0)
            assert nck.data.r[1] == stopped, f"{name}: the loop went on after NC STOP"
            assert nck.status().channel.channel_state == "interrupted"
            await pilot.press(key("nc.reset"))
            await pilot.pause()
            timed_advance(app, 0.5)
            assert nck.status().channel.channel_state == "reset", name
            assert nck.internal_errors == [] and app.internal_errors == []
            nck.data.r[1] = 0.0
