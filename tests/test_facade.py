"""The façade's names imported on first use (``nck/__init__.py``, PEP 562).

The kernel, its composition root, the NC file system, the servo trace and the panel's refusals
are imported when a client first asks for them, so that ``nck check`` starts without them. The
names must stay the same names: every one under ``TYPE_CHECKING`` (what mypy and the import
graph see) is in the table ``__getattr__`` reads, and resolves to its module's object.
"""

from __future__ import annotations

import ast
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import nck

ROOT = Path(__file__).resolve().parent.parent


def type_checking_imports() -> dict[str, tuple[str, ...]]:
    """``{module: names}`` of the imports inside ``if TYPE_CHECKING:`` of ``nck/__init__.py``."""
    tree = ast.parse((ROOT / "nck" / "__init__.py").read_text(encoding="utf-8"))
    found: dict[str, tuple[str, ...]] = {}
    for node in tree.body:
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
            for statement in node.body:
                assert isinstance(statement, ast.ImportFrom) and statement.module
                found[statement.module] = tuple(alias.name for alias in statement.names)
    return found


def test_the_names_imported_on_first_use_are_those_the_type_checker_sees() -> None:
    assert type_checking_imports() == vars(nck)["_ON_FIRST_USE"]


@pytest.mark.parametrize("module, name", [(module, name) for module, names in type_checking_imports().items()
                                          for name in names])
def test_a_name_imported_on_first_use_is_its_modules_object(module: str, name: str) -> None:
    assert getattr(nck, name) is getattr(importlib.import_module(module), name)


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError):
        nck.no_such_name  # noqa: B018
    with pytest.raises(ImportError):
        from nck import no_such_name  # type: ignore[attr-defined]  # noqa: F401


def test_the_command_line_loads_no_kernel_until_a_command_runs_one() -> None:
    loaded = subprocess.run(
        [sys.executable, "-c", "import sys, nck.cli; print(' '.join(sorted(sys.modules)))"],
        cwd=ROOT, capture_output=True, text=True, check=True).stdout.split()
    assert {"nck.kernel", "nck.build", "nck.grade"} & set(loaded) == set()
