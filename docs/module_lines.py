"""Lines of Python per package at a git revision: the module map's figures in docs/architecture.md.

    python docs/module_lines.py BEFORE [AFTER]     (AFTER defaults to HEAD; run in the repository)

A package is a folder of ``nck/``, ``hmi/`` or ``screens/`` (``nck`` alone = the modules at
the top of ``nck/``). Counts every line of the ``.py`` files, blank and comment lines included,
read from the revision's tree (not the work tree), so any two revisions can be compared.
"""

from __future__ import annotations

import subprocess
import sys
from collections import Counter

ROOTS = ("nck", "hmi", "screens")


def git(*args: str) -> str:
    """Output of a git command in the current repository."""
    return subprocess.run(("git", *args), capture_output=True, text=True, check=True).stdout


def package_lines(revision: str) -> tuple[Counter[str], Counter[str]]:
    """(lines, files) per package at ``revision``."""
    lines: Counter[str] = Counter()
    files: Counter[str] = Counter()
    for path in git("ls-tree", "-r", "--name-only", revision, "--", *ROOTS).split():
        if not path.endswith(".py"):
            continue
        parts = path.split("/")
        package = ".".join(parts[:2]) if len(parts) > 2 else parts[0]
        lines[package] += git("show", f"{revision}:{path}").count("\n")
        files[package] += 1
    return lines, files


def main(argv: list[str]) -> None:
    """Print a Markdown table: files and lines per package before and after."""
    before_rev, after_rev = argv[1], (argv[2] if len(argv) > 2 else "HEAD")
    before_lines, before_files = package_lines(before_rev)
    after_lines, after_files = package_lines(after_rev)
    short = {rev: git("rev-parse", "--short", rev).strip() for rev in (before_rev, after_rev)}
    print(f"| package | files {short[before_rev]} | lines {short[before_rev]} "
          f"| files {short[after_rev]} | lines {short[after_rev]} |")
    print("|---|---:|---:|---:|---:|")
    for package in sorted(set(before_lines) | set(after_lines)):
        print(f"| `{package}` | {before_files[package]} | {before_lines[package]} "
              f"| {after_files[package]} | {after_lines[package]} |")
    print(f"| total | {sum(before_files.values())} | {sum(before_lines.values())} "
          f"| {sum(after_files.values())} | {sum(after_lines.values())} |")


if __name__ == "__main__":
    main(sys.argv)
