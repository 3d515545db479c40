"""HMI figures, measured in a process of their own (``python -m bench.hmi_probe SPAWN_EPOCH``).

Prints one JSON object: time from process spawn to the first frame, CPU time
per screen refresh while a program runs, keypress-to-repaint latency (Pilot)
while it runs, and the peak RSS. With ``--program FILE`` that program is
selected in AUTO before the measurements (memory with a large program).
"""

from __future__ import annotations

import asyncio
import json
import resource
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

SHORT_PROGRAM = ("N10 G90 G0 X0 Y0 Z10\n"
                 + "".join(f"N{20 + 10 * k} G1 X{(k * 7) % 100} Y{(k * 3) % 50} F600\n" for k in range(200))
                 + "N9990 M30\n")


def _percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(fraction * (len(ordered) - 1))))]


async def measure(spawn_epoch: float, program: Path | None) -> dict[str, float | str]:
    """Run the HMI under Textual's Pilot and collect the figures."""
    from nck import commands as c
    from nck.kernel import Nck

    from hmi.app import HmiApp
    from hmi.programs import DirectoryPrograms

    folder = Path(tempfile.mkdtemp())
    name = "BENCH.MPF"
    if program is not None:
        shutil.copy(program, folder / program.name.upper())
        name = program.name.upper()
    else:
        (folder / name).write_text(SHORT_PROGRAM)
    nck = Nck(programs=DirectoryPrograms([folder]), referenced=True)
    app = HmiApp(nck, realtime=False)
    first_frame: list[float] = []
    out: dict[str, float | str] = {}
    async with app.run_test(size=(160, 48)) as pilot:
        app.call_after_refresh(lambda: first_frame.append(time.time()))
        await pilot.pause()
        await pilot.pause()
        nck.submit(c.SetKeyswitch(1))
        nck.submit(c.SelectMode("AUTO"))
        nck.submit(c.SelectProgram(name))
        nck.submit(c.CycleStart())
        await pilot.pause()
        refresh_cpu: list[float] = []
        for _ in range(60):
            nck.tick(0.05)
            t0 = time.process_time()
            app.bridge.poll()
            await pilot.pause()
            refresh_cpu.append(time.process_time() - t0)
        latency: list[float] = []
        for k in range(40):
            nck.tick(0.05)
            app.bridge.poll()
            await pilot.pause()
            key = "alt+o" if k % 2 == 0 else "alt+m"
            t0 = time.perf_counter()
            await pilot.press(key)
            await pilot.pause()
            latency.append(time.perf_counter() - t0)
        out["program_state"] = str(app.bridge.status.channel.program_state)
    out["first_frame_s"] = first_frame[0] - spawn_epoch if first_frame else float("nan")
    out["refresh_cpu_ms_median"] = statistics.median(refresh_cpu) * 1000.0
    out["refresh_cpu_ms_p95"] = _percentile(refresh_cpu, 0.95) * 1000.0
    out["key_latency_ms_median"] = statistics.median(latency) * 1000.0
    out["key_latency_ms_p95"] = _percentile(latency, 0.95) * 1000.0
    out["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return out


def main(argv: list[str]) -> int:
    """Entry point: ``SPAWN_EPOCH [--program FILE]``."""
    spawn = float(argv[0]) if argv else time.time()
    program = Path(argv[argv.index("--program") + 1]) if "--program" in argv else None
    print(json.dumps(asyncio.run(measure(spawn, program))))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
