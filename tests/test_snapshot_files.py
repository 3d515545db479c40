"""Every SVG snapshot belongs to a test that still exists.

Syrupy reports a snapshot no test uses only in a run without pytest-xdist; ``make test``
runs with it, so a deleted snapshot test would leave its SVG behind unnoticed (it happened:
b276ba2 restored a test that a refactoring had dropped along with its neighbours). A
snapshot lives in ``<test dir>/__snapshots__/<test module>/<test name>[<parameters>…].svg``.
This checks the module and the test function; a parameter dropped from a test that still
exists is not caught here.
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent


def _test_functions(module: Path) -> set[str]:
    tree = ast.parse(module.read_text(encoding="utf-8"))
    return {node.name for node in ast.walk(tree) if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))}


def test_every_snapshot_file_belongs_to_an_existing_test() -> None:
    snapshots = sorted(TESTS.glob("**/__snapshots__/*/*.svg"))
    assert snapshots  # the layout above still holds
    orphans = []
    functions: dict[Path, set[str]] = {}
    for svg in snapshots:
        module = svg.parent.parent.parent / f"{svg.parent.name}.py"
        if module not in functions:
            functions[module] = _test_functions(module) if module.exists() else set()
        test_name = svg.name.split("[", 1)[0].removesuffix(".svg")
        if test_name not in functions[module]:
            orphans.append(str(svg.relative_to(TESTS)))
    assert orphans == []
