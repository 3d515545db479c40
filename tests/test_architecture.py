"""Import rules: the kernel stays pure, arrows run one way, the UI goes through the façade.

The rules (the rules of the house and issue 21's target map):

- ``nck/`` imports no UI library, no wall clock and no threads; it never imports ``hmi``/``screens``.
- The kernel's packages import downwards only (``tests/import_graph.KERNEL_PACKAGES_BELOW``):
  ``nck.interp`` never imports ``nck.iso`` (the dialect sits in front of the interpreter),
  ``nck.iso`` and ``nck.geometry`` never the interpreter, ``nck.lang`` none of them, the motion
  system no language or geometry.
- ``hmi/`` and ``screens/`` import the kernel only through its façade (``nck``, ``nck.commands``,
  ``nck.status``, ``nck.queries``); ``hmi/`` reads only the ``screens`` registry, not an area's
  module; a screen never imports the module of another operating area.
- No import circles, counting function-local and ``TYPE_CHECKING`` imports.
- No ``_private`` name imported from another module.
- No top-level definition that nothing names (``tests/definition_uses.py``).

Today's breaks are listed in ``architecture_allowlist.py``; those lists may only shrink.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from hmi.app import AREAS
from tests import architecture_allowlist as allowed
from tests.definition_uses import unnamed_definitions
from tests.import_graph import (
    LayerRules,
    collect_imports,
    cycle_edges,
    module_files,
    module_graph,
    private_imports,
    strongly_connected,
)

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("nck", "hmi", "screens")
FORBIDDEN_IN_NCK = {"textual", "rich", "hmi", "screens", "threading", "time", "datetime"}
RULES = LayerRules(areas=tuple(area.id for area in AREAS))


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


def ratchet_report(found: set, listed: frozenset, what: str) -> list[str]:
    """What is wrong between the breaks ``found`` and the ``listed`` ones: new breaks and stale entries."""
    problems = [f"new {what}: {item}" for item in sorted(found - listed)]
    problems += [f"{what} gone, delete it from architecture_allowlist.py: {item}" for item in sorted(listed - found)]
    return problems


@pytest.fixture(scope="module")
def project_imports():
    return collect_imports(ROOT, PACKAGES)


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


def test_layer_contract_holds_apart_from_the_listed_breaks(project_imports) -> None:
    assert ratchet_report(RULES.violations(project_imports), allowed.LAYER_BREAKS, "layer break") == []


def test_no_import_circles_apart_from_the_listed_ones(project_imports) -> None:
    graph = module_graph(project_imports, module_files(ROOT, PACKAGES))
    assert ratchet_report(cycle_edges(graph), allowed.CYCLE_EDGES, "edge on an import circle") == []


def test_no_private_names_imported_across_modules_apart_from_the_listed_ones(project_imports) -> None:
    assert ratchet_report(private_imports(project_imports), allowed.PRIVATE_IMPORTS, "private import") == []


KERNEL_HOLDERS = {"hmi.bridge", "hmi.startup"}
"""The bridge holds the kernel; startup builds it and hands it to the app (for the bridge)."""


def kernel_reads(path: Path) -> list[int]:
    """Lines of ``path`` that take the attribute ``nck`` of an object (``bridge.nck``, ``getattr(x, "nck")``)."""
    lines = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Attribute) and node.attr == "nck":
            lines.append(node.lineno)
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in ("getattr", "setattr")
              and len(node.args) >= 2 and isinstance(node.args[1], ast.Constant) and node.args[1].value == "nck"):
            lines.append(node.lineno)
    return sorted(lines)


def test_only_the_bridge_touches_the_kernel() -> None:
    # Screens ask the bridge (bridge.query, bridge.submit); the kernel object stays in the bridge.
    offenders = {}
    for module, path in module_files(ROOT, ("hmi", "screens")).items():
        if module not in KERNEL_HOLDERS and (lines := kernel_reads(path)):
            offenders[module] = lines
    assert offenders == {}


# --- the checks themselves, on deliberately broken trees -------------------------------------


def write_tree(root: Path, files: dict[str, str]) -> Path:
    """Create ``files`` (relative path -> source) under ``root``, with an ``__init__.py`` in every package."""
    for relative, source in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        for package in path.relative_to(root).parents:
            if package != Path("."):
                (root / package / "__init__.py").touch()
        path.write_text(source, encoding="utf-8")
    return root


def test_a_circle_through_function_local_and_type_checking_imports_is_found(tmp_path: Path) -> None:
    root = write_tree(
        tmp_path,
        {
            "pkg/a.py": "def later():\n    from pkg.b import thing\n    return thing\n",
            "pkg/b.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from . import c\nthing = 1\n",
            "pkg/c.py": "import pkg.a\n",
            "pkg/d.py": "import pkg.a\n",
        },
    )
    graph = module_graph(collect_imports(root, ["pkg"]), module_files(root, ["pkg"]))
    assert strongly_connected(graph) == [frozenset({"pkg.a", "pkg.b", "pkg.c"})]
    assert cycle_edges(graph) == {("pkg.a", "pkg.b"), ("pkg.b", "pkg.c"), ("pkg.c", "pkg.a")}


def test_a_tree_without_circles_has_no_circle_edges(tmp_path: Path) -> None:
    root = write_tree(tmp_path, {"pkg/a.py": "from pkg import b\n", "pkg/b.py": "from .c import x\n", "pkg/c.py": "x = 1\n"})
    graph = module_graph(collect_imports(root, ["pkg"]), module_files(root, ["pkg"]))
    assert graph["pkg.a"] == {"pkg.b"} and graph["pkg.b"] == {"pkg.c"}
    assert cycle_edges(graph) == set()


def test_every_layer_rule_reports_its_break(tmp_path: Path) -> None:
    root = write_tree(
        tmp_path,
        {
            "nck/kernel.py": "def f():\n    import textual.app\n    from hmi import bridge\n",
            "nck/commands.py": "",
            "nck/interp/block_run.py": "from nck.iso.macros import expand\nfrom nck.lang import parser\n",
            "nck/iso/macros.py": "from nck.interp import block_run\nfrom nck.geometry import frames\n",
            "nck/lang/parser.py": "from nck.geometry.frames import Frame\n",
            "nck/geometry/frames.py": "from nck.lang import parser\nfrom nck.motion import servo\n",
            "nck/motion/servo.py": "from nck.canon import Motion\nfrom nck.lang.values import REAL\n",
            "nck/canon.py": "",
            "hmi/bridge.py": "from nck.kernel import Nck\nfrom nck import commands\nfrom screens import AREAS\n",
            "hmi/app.py": "from screens.machine import AreaScreen\n",
            "screens/program.py": "from screens.program_edit import EditActions\nfrom nck.status import NckStatus\n",
            "screens/program_edit.py": "from screens.machine import jog\nimport rich.text\n",
            "screens/program_manager.py": "from screens.program_files import ProgramFiles\n",
            "screens/program_files.py": "",
            "screens/machine.py": "from hmi.area import AreaScreen\nfrom screens.dialogs import ChoiceDialog\n",
            "screens/dialogs.py": "",
        },
    )
    rules = LayerRules(areas=("machine", "program", "program_manager"))
    assert rules.violations(collect_imports(root, ["nck", "hmi", "screens"])) == {
        ("nck.kernel", "textual.app"),
        ("nck.kernel", "hmi.bridge"),
        ("nck.interp.block_run", "nck.iso.macros"),
        ("nck.iso.macros", "nck.interp.block_run"),
        ("nck.lang.parser", "nck.geometry.frames"),
        ("nck.geometry.frames", "nck.motion.servo"),
        ("nck.motion.servo", "nck.lang.values"),
        ("hmi.bridge", "nck.kernel"),
        ("hmi.app", "screens.machine"),
        ("screens.program_edit", "screens.machine"),
        ("screens.program_manager", "screens.program_files"),
        ("screens.machine", "screens.dialogs"),
    }


def test_private_names_taken_from_another_module_are_reported(tmp_path: Path) -> None:
    root = write_tree(
        tmp_path,
        {
            "pkg/a.py": "_hidden = 1\n__version__ = '1'\npublic = 2\n",
            "pkg/b.py": "from pkg.a import _hidden, __version__, public\nfrom . import a\n",
            "pkg/c.py": "def f():\n    from .a import _hidden as h\n",
        },
    )
    assert private_imports(collect_imports(root, ["pkg"])) == {
        ("pkg.b", "pkg.a", "_hidden"),
        ("pkg.c", "pkg.a", "_hidden"),
    }


def test_a_screen_reaching_past_the_bridge_is_found(tmp_path: Path) -> None:
    sample = tmp_path / "screen.py"
    sample.write_text("class S:\n    def f(self):\n        kernel = self.hmi.bridge.nck\n"
                      "        return getattr(self.app.bridge, 'nck').machine, self.ask(None)\n")
    assert kernel_reads(sample) == [3, 4]


def test_the_ratchet_reports_new_breaks_and_stale_entries() -> None:
    listed = frozenset({("a", "b"), ("c", "d")})
    assert ratchet_report({("a", "b"), ("c", "d")}, listed, "break") == []
    assert ratchet_report({("a", "b"), ("c", "d"), ("e", "f")}, listed, "break") == ["new break: ('e', 'f')"]
    assert ratchet_report({("a", "b")}, listed, "break") == [
        "break gone, delete it from architecture_allowlist.py: ('c', 'd')"
    ]


USING_PACKAGES = (*PACKAGES, "tests", "bench")


def test_no_definition_that_nothing_names_apart_from_the_listed_ones() -> None:
    found = unnamed_definitions(ROOT, PACKAGES, USING_PACKAGES)
    assert ratchet_report(found, allowed.UNNAMED_DEFINITIONS, "unnamed definition") == []


def test_a_definition_nothing_names_is_found(tmp_path: Path) -> None:
    (tmp_path / "nck").mkdir()
    (tmp_path / "tests").mkdir()
    (tmp_path / "nck" / "a.py").write_text(
        "from nck.b import used\nLIMIT = 3\nWORDS = (N_('x'),)\n\n\ndef helper():\n    return used\n\n\n"
        "class Orphan:\n    pass\n")
    (tmp_path / "nck" / "b.py").write_text("def used():\n    return 1\n")
    (tmp_path / "tests" / "test_a.py").write_text("from nck.a import helper\n")
    found = unnamed_definitions(tmp_path, ("nck",), ("nck", "tests"))
    assert found == {("nck/a.py", "LIMIT"), ("nck/a.py", "Orphan")}
