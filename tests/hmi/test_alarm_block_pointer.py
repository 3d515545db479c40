"""On an alarm the block window marks the block that raised it (issue 18).

ALARM_DEMO's N30 `G1 Z-1` has no feedrate: 10860 names block N30 (its own comment
says so). Seen in tmux: the ▶ stood on N20, the block still in execution when N30
was prepared. Keys go as a burst.
"""

from __future__ import annotations

from pathlib import Path

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst

SIZE = (160, 48)
PROGRAM = Path(__file__).resolve().parents[2] / "data" / "programs" / "ALARM_DEMO.MPF"


async def test_pointer_on_the_block_that_raised_the_alarm() -> None:
    nck = Nck(programs=MemorySource({"ALARM_DEMO.MPF": PROGRAM.read_text()}), referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        assert app.submit(c.SelectMode("AUTO")) == c.Accepted()
        assert app.submit(c.SelectProgram("ALARM_DEMO.MPF")) == c.Accepted()
        await burst(pilot, "alt+m", "alt+g")
        app.bridge.run_until(lambda s: s.channel.stop_reason == "alarm", max_s=20)
        assert [a.number for a in app.bridge.status.alarms] == [10860]
        await pilot.pause()
        shown = str(app.screen.query_one("#auto-blocks").render()).splitlines()
        marked = [line for line in shown if line.startswith("▶")]
        assert [line.rstrip() for line in marked] == ["▶N30 G1 Z-1"], shown
