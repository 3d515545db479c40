"""Top-level definitions nobody names: a function, class or constant of ``nck/``, ``hmi/`` or
``screens/`` whose name occurs nowhere in the project's Python files but at its definition.

A name is counted as a whole word in every file (code, docstrings, ``__all__``, tests), so a
definition used only through ``getattr`` with a literal name still counts as used. Tables of
translation markers (assignments whose value calls ``N_``) exist for the message catalogue
and are not reported. Two definitions of one name hide each other (a known blind spot).
"""

from __future__ import annotations

import ast
import re
from collections import Counter
from pathlib import Path
from typing import Iterable

WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def _defined_names(node: ast.stmt) -> list[str]:
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return [node.name]
    value: ast.expr | None = None
    targets: list[ast.expr] = []
    if isinstance(node, ast.Assign):
        targets, value = node.targets, node.value
    elif isinstance(node, ast.AnnAssign):
        targets, value = [node.target], node.value
    if value is not None and any(isinstance(call, ast.Call) and isinstance(call.func, ast.Name)
                                 and call.func.id == "N_" for call in ast.walk(value)):
        return []  # a table of translation markers
    return [target.id for target in targets if isinstance(target, ast.Name)]


def unnamed_definitions(root: Path, defining: Iterable[str], using: Iterable[str],
                        not_a_use: str = "architecture_allowlist.py") -> set[tuple[str, str]]:
    """(file relative to ``root``, name) of every top-level definition in the packages
    ``defining`` whose name occurs only once in the Python files of ``using`` (the file
    named ``not_a_use``, the list of known breaks, does not count)."""
    words: Counter[str] = Counter()
    for package in using:
        for path in sorted((root / package).rglob("*.py")):
            if path.name == not_a_use:
                continue
            words.update(WORD.findall(path.read_text(encoding="utf-8")))
    found: set[tuple[str, str]] = set()
    for package in defining:
        for path in sorted((root / package).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"))
            for node in tree.body:
                for name in _defined_names(node):
                    if not name.startswith("__") and words[name] <= 1:
                        found.add((path.relative_to(root).as_posix(), name))
    return found
