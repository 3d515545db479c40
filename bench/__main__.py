"""``python -m bench``: the benchmark suite (table → bench/results.md), then the motion contours.

``BENCH_QUICK=1`` skips the 200,000-block ``nck run`` and the HMI with the long
program and runs each interpreter once; ``BENCH_REPEATS=N`` sets the repeats.
"""

from __future__ import annotations

import sys

from bench.contour import bench_motion, bench_nck_run
from bench.suite import RESULTS, run_suite


def main() -> int:
    """Run every benchmark; exit code 0."""
    text = run_suite()
    analysis = RESULTS.with_name("analysis.md")
    if analysis.exists():  # the hand-written profile notes travel with every table
        text += "\n" + analysis.read_text(encoding="utf-8")
    print(text)
    RESULTS.write_text(text, encoding="utf-8")
    print(f"written to {RESULTS}")
    print("2,000-block contours at F3000, G64, default mill (IPO cycle 4 ms), in process")
    print(bench_motion(turns=40.0).line())
    print(bench_motion(turns=4.0).line())
    for turns in (40.0, 4.0):
        try:
            print(bench_nck_run(turns=turns).line())
        except Exception as exc:  # noqa: BLE001 - a benchmark reports, it does not crash
            print(f"nck run: not measured ({exc})", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
