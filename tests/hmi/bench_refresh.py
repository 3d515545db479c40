"""Benchmark (not a test): time to first frame and CPU cost of one refresh with a program running.

Run: ``.venv/bin/python -m tests.hmi.bench_refresh``
"""

from __future__ import annotations

import asyncio
import statistics
import sys
import tempfile
import time
from pathlib import Path

START = time.perf_counter()

from nck import commands as c  # noqa: E402
from nck.kernel import Nck  # noqa: E402

from hmi.app import HmiApp  # noqa: E402
from hmi.programs import DirectoryPrograms  # noqa: E402

PROGRAM = "N10 G90 G0 X0 Y0 Z10\nN20 G1 X100 Y50 F600\nN30 G1 X0 Y0\nN40 M30\n"


async def measure() -> None:
    folder = Path(tempfile.mkdtemp())
    (folder / "BENCH.MPF").write_text(PROGRAM)
    nck = Nck(programs=DirectoryPrograms([folder]), referenced=True)
    app = HmiApp(nck, realtime=False)
    first_frame: list[float] = []
    async with app.run_test(size=(160, 48)) as pilot:
        app.call_after_refresh(lambda: first_frame.extend(
            [time.perf_counter() - START, time.process_time()]))
        await pilot.pause()
        await pilot.pause()
        nck.submit(c.SetKeyswitch(1))
        nck.submit(c.SelectMode("AUTO"))
        nck.submit(c.SelectProgram("BENCH.MPF"))
        nck.submit(c.CycleStart())
        await pilot.pause()
        costs: list[float] = []
        kernel: list[float] = []
        for _ in range(100):
            t0 = time.process_time()
            nck.tick(0.05)
            t1 = time.process_time()
            app.bridge.poll()
            await pilot.pause()
            t2 = time.process_time()
            kernel.append(t1 - t0)
            costs.append(t2 - t1)
        running = app.bridge.status.channel.program_state
        idle: list[float] = []
        for _ in range(50):
            t0 = time.process_time()
            await pilot.pause()
            idle.append(time.process_time() - t0)
    print(f"time to first frame: {first_frame[0] * 1000:.0f} ms wall, {first_frame[1] * 1000:.0f} ms CPU "
          "(from the start of the interpreter, imports included)")
    print(f"refresh (HMI only) CPU per frame: median {statistics.median(costs) * 1000:.2f} ms, "
          f"p95 {sorted(costs)[94] * 1000:.2f} ms; kernel tick 50 ms: median "
          f"{statistics.median(kernel) * 1000:.2f} ms; program state at end: {running}")
    print(f"test-harness pause without changes: median {statistics.median(idle) * 1000:.2f} ms "
          f"(included in the refresh figure above)")


if __name__ == "__main__":
    asyncio.run(measure())
    sys.exit(0)
