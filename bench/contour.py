"""A 2,000-block milling contour, run on the motion system alone and through ``nck run``.

Reports simulated machine time, wall time and their ratio (how many times
faster than real time the simulation runs), and the same ratio on the CPU
time of this process (steadier on a busy machine). Measured in process: Python
start-up and imports are not included (``bench.suite`` measures the whole
``nck run`` child).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

from nck.canon import Motion, Source
from nck.machine import load_machine
from nck.motion.system import PlannedMotion

BLOCKS = 2000


@dataclass
class BenchResult:
    """One benchmark: name, simulated seconds, wall seconds."""

    name: str
    machine_s: float
    wall_s: float
    cpu_s: float = 0.0

    @property
    def ratio(self) -> float:
        """Machine time per wall time."""
        return self.machine_s / self.wall_s if self.wall_s > 0 else math.inf

    @property
    def cpu_ratio(self) -> float:
        """Machine time per CPU time of this process."""
        return self.machine_s / self.cpu_s if self.cpu_s > 0 else math.inf

    def line(self) -> str:
        return (f"{self.name:<34} machine {self.machine_s:9.2f} s   wall {self.wall_s:7.3f} s   "
                f"{self.ratio:9.0f}x real time   (CPU {self.cpu_s:6.3f} s: {self.cpu_ratio:6.0f}x)")


def contour_points(blocks: int = BLOCKS, turns: float = 4.0) -> list[tuple[str, float, float, float | None, float | None]]:
    """A wavy contour around a Ø120 pocket: (G code, X, Y, centre X, centre Y); every 10th an arc.

    With ``turns`` = 4 the blocks are about 0.8 mm long (a dense CAM contour);
    with 40 about 8 mm (a typical hand-written or coarse CAM contour).
    """
    out = []
    radius = 60.0
    for k in range(blocks):
        angle = 2.0 * math.pi * (k + 1) / blocks * turns
        r = radius + 8.0 * math.sin(angle * 7.0)
        x, y = r * math.cos(angle), r * math.sin(angle)
        if k % 10 == 9:
            out.append(("G3", x, y, 0.0, 0.0))
        else:
            out.append(("G1", x, y, None, None))
    return out


def contour_program(blocks: int = BLOCKS, turns: float = 40.0) -> str:
    """The contour as a part program (G64 continuous path, F3000)."""
    lines = ["N1 G90 G17 G64 G0 X60 Y0 Z5", "N2 G1 Z-2 F1000", "N3 F3000"]
    n = 4
    for kind, x, y, cx, cy in contour_points(blocks - 3, turns):
        if kind == "G3":
            lines.append(f"N{n} G3 X{x:.3f} Y{y:.3f} CR={math.hypot(x - (cx or 0), y - (cy or 0)):.3f}")
        else:
            lines.append(f"N{n} G1 X{x:.3f} Y{y:.3f}")
        n += 1
    lines.append(f"N{n} M30")
    return "\n".join(lines) + "\n"


def bench_motion(blocks: int = BLOCKS, turns: float = 40.0, step_s: float = 0.5) -> BenchResult:
    """The planned motion alone: canonical segments pushed as the buffer allows."""
    motion = PlannedMotion(load_machine(), referenced=True)
    items = [Motion(kind="G0", source=Source("B", 1, 1), plane="G17", end_wcs={}, end_mcs={"X": 60.0, "Y": 0.0})]
    for k, (kind, x, y, cx, cy) in enumerate(contour_points(blocks - 1, turns)):
        center = {"X": cx, "Y": cy} if cx is not None else None
        items.append(Motion(kind=kind, source=Source("B", k + 2, k + 2), plane="G17", end_wcs={},
                            end_mcs={"X": x, "Y": y}, center_mcs=center, feed_mm_min=3000.0,
                            gcodes={10: "G64", 21: "BRISK"}))
    start = time.perf_counter()
    cpu = time.process_time()
    pending = items
    index = 0
    while True:
        while index < len(pending) and motion.can_accept():
            motion.push(pending[index])
            index += 1
        if index >= len(pending) and motion.is_idle():
            break
        motion.advance(step_s)
    length = "~0.8 mm" if turns < 10 else "~8 mm"
    return BenchResult(f"motion only, {length} blocks", motion.time_s, time.perf_counter() - start,
                       time.process_time() - cpu)


def bench_nck_run(blocks: int = BLOCKS, turns: float = 40.0) -> BenchResult:
    """``nck run`` of the contour (interpreter, kernel, motion) through the headless loop."""
    from nck.headless import run_program
    from nck.interp.sources import MemorySource
    from nck.ncdata import NcData

    text = contour_program(blocks, turns)
    machine = load_machine()
    programs = MemorySource({"BENCH.MPF": text})
    run_program(machine, programs, NcData(), "BENCH.MPF", timeout_s=1.0, keep_commands=False)  # imports
    start = time.perf_counter()
    cpu = time.process_time()
    result = run_program(machine, programs, NcData(), "BENCH.MPF", keep_commands=False)
    wall = time.perf_counter() - start
    cpu = time.process_time() - cpu
    if result.status != "ended":
        raise RuntimeError(f"nck run ended with {result.status}: {result.alarms}")
    length = "~0.8 mm" if turns < 10 else "~8 mm"
    return BenchResult(f"nck run, {length} blocks", result.machine_time_s, wall, cpu)
