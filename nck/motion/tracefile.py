"""``nck run --trace FILE``: the sampled MCS setpoints of every IPO cycle as CSV."""

from __future__ import annotations

from typing import Any, TextIO

import numpy as np


def start_trace(motion: Any) -> None:
    """Switch recording on for a motion system that can record (the planned motion)."""
    enable = getattr(motion, "enable_trace", None)
    if enable is not None:
        enable()


def write_trace_csv(motion: Any, out: TextIO) -> int:
    """Write ``t_s`` and one column per path axis (mm, MCS); return the number of rows."""
    trace = getattr(motion, "trace", None)
    names = list(getattr(motion, "names", []))
    out.write(",".join(["t_s", *names]) + "\n")
    if trace is None:
        return 0
    times, rows = trace()
    if times.size == 0:
        return 0
    table = np.round(np.column_stack([times, rows]), 6) + 0.0  # no -0.000000
    np.savetxt(out, table, delimiter=",", fmt=["%.3f"] + ["%.6f"] * rows.shape[1])
    return int(times.size)
