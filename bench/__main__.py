"""``python -m bench``: run the benchmarks and print machine time / wall time."""

from __future__ import annotations

import sys

from bench.contour import bench_motion, bench_nck_run


def main() -> int:
    """Run every benchmark; exit code 0."""
    print("2,000-block contours at F3000, G64, default mill (IPO cycle 4 ms)")
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
