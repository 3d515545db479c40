"""The headless command line ``nck`` (contract: check, run, md, version)."""

from __future__ import annotations

import sys

from nck import __version__


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``nck`` console script; returns the exit code."""
    args = sys.argv[1:] if argv is None else argv
    if args[:1] == ["version"]:
        print(f"nck {__version__}")
        return 0
    print("usage: nck {check,run,md,version} ...", file=sys.stderr)
    return 2
