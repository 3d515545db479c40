"""Generated benchmark programs: a long CAM-style ``G1 X… Y… Z…`` program."""

from __future__ import annotations

import math
from pathlib import Path

CAM_BLOCKS = 200_000


def cam_program(blocks: int = CAM_BLOCKS) -> str:
    """A CAM-like program of exactly ``blocks`` lines: a header, ``G1 X Y Z`` moves, M30.

    The moves follow a spiral ramp (0.5 mm chords at radius 50 mm, Z stepping
    down and back every 100 blocks), one block per line, plain enough for every
    peer interpreter to read.
    """
    lines = ["G90 G17 G64 G1 F3000"]
    for k in range(blocks - 2):
        angle = k * 0.01
        lines.append(f"G1 X{50.0 * math.cos(angle):.3f} Y{50.0 * math.sin(angle):.3f} "
                     f"Z{-(k % 100) * 0.01:.3f}")
    lines.append("M30")
    return "\n".join(lines) + "\n"


def write_cam_program(folder: Path, blocks: int = CAM_BLOCKS) -> Path:
    """Write :func:`cam_program` to ``folder/CAM<blocks>.MPF`` and return the path."""
    path = folder / f"CAM{blocks}.MPF"
    path.write_text(cam_program(blocks))
    return path
