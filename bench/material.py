"""Material-removal benchmark: a 200 × 150 mm plate at 0.2 mm cut by a 200,000-block CAM program.

The program finishes a wavy surface with an 8 mm ball end mill in 1,000 passes along X
(0.15 mm apart); each pass alternates straight blocks (with Z following the surface) and
shallow arcs (G2/G3, radius 2 mm). ``python -m bench.material FILE`` runs one simulation in
this process and prints its phase times (wall and CPU) as JSON (the suite measures the whole
child: wall time and peak RSS).
"""

from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

PASSES = 1000
BLOCKS_PER_PASS = 200
PLATE_MM = (200.0, 150.0)
RESOLUTION_MM = 0.2


def surface_z(x: float, y: float) -> float:
    """The finished surface (mm): 1 to 3 mm below the top."""
    return -2.0 - 0.9 * math.sin(x / 17.0) * math.cos(y / 23.0)


def material_program() -> str:
    """The CAM program: WORKPIECE, tool call, 1,000 passes of 200 blocks, M30."""
    lines = ['WORKPIECE(,"",,"BOX",112,0,-20,-20,0,0,200,150)', "T1 M6", "D1 S8000 M3 G17 G90 G64",
             "G0 X0 Y0 Z5", f"G1 Z{surface_z(0.0, 0.0):.3f} F4000"]
    step_y = PLATE_MM[1] / PASSES
    for k in range(PASSES):
        y = k * step_y
        forward = k % 2 == 0
        if k:
            lines.append(f"G1 Y{y:.3f}")
        for j in range(1, BLOCKS_PER_PASS):
            x = PLATE_MM[0] * j / (BLOCKS_PER_PASS - 1)
            x = x if forward else PLATE_MM[0] - x
            if j % 2:
                lines.append(f"G1 X{x:.3f} Z{surface_z(x, y):.3f}")
            else:
                lines.append(f"G{2 if (j // 2) % 2 else 3} X{x:.3f} Y{y:.3f} CR=2")
    lines += ["G0 Z20", "M30"]
    return "\n".join(lines) + "\n"


def write_material_program(folder: Path) -> Path:
    """Write :func:`material_program` to ``folder/PLATE.MPF``."""
    path = folder / "PLATE.MPF"
    path.write_text(material_program())
    return path


def main(argv: list[str]) -> int:
    """Simulate the program at ``argv[0]``; print the phase times (s, wall and this process's
    CPU) and figures as JSON."""
    from nck.ncdata import NcData, ToolEdge
    from nck.simulation.blank import blank_from_text
    from nck.simulation.run import record, sweep_path
    from nck.simulation.zmap import ZMap

    path = Path(argv[0])
    text = path.read_text()
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 110.0, 3: 80.0, 6: 4.0})  # ball end mill D8
    started, started_cpu = time.perf_counter(), time.process_time()
    recording = record(path.name, text, data=data, resolution_mm=RESOLUTION_MM)
    run, toolpath = recording.run, recording.path
    recorded, recorded_cpu = time.perf_counter(), time.process_time()
    blank = blank_from_text(text)
    assert blank is not None
    zmap = ZMap(blank, RESOLUTION_MM)
    sweep_path(zmap, toolpath)
    swept, swept_cpu = time.perf_counter(), time.process_time()
    print(json.dumps({
        "run_s": recorded - started, "sweep_s": swept - recorded, "total_s": swept - started,
        "run_cpu_s": recorded_cpu - started_cpu, "sweep_cpu_s": swept_cpu - recorded_cpu,
        "status": run.status, "blocks": run.blocks, "chords": int(len(toolpath.starts)),
        "machine_time_s": run.machine_time_s, "removed_mm3": zmap.removed_volume_mm3(),
        "cells": int(zmap.heights.size),
    }))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
