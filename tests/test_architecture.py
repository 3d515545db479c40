"""Import rules: the kernel stays pure."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FORBIDDEN_IN_NCK = {"textual", "rich", "hmi", "screens", "threading", "time", "datetime"}


def imported_modules(path: Path) -> set[str]:
    """Return the top-level names of every module a file imports."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module.split(".")[0])
    return names


def test_nck_imports_no_ui_clock_or_threads() -> None:
    offenders = {}
    for path in sorted((ROOT / "nck").rglob("*.py")):
        bad = imported_modules(path) & FORBIDDEN_IN_NCK
        # The command line (not the kernel) may read the wall clock for --realtime/--timeout guards.
        if path.name == "cli.py" or path.parent.name == "cli":
            bad -= {"time"}
        if bad:
            offenders[str(path.relative_to(ROOT))] = sorted(bad)
    assert offenders == {}


def test_forbidden_import_is_detected(tmp_path: Path) -> None:
    sample = tmp_path / "x.py"
    sample.write_text("import textual.app\nfrom rich import print\n")
    assert imported_modules(sample) == {"textual", "rich"}
