"""The project's import graph, read from the source with :mod:`ast`, and the rules checked on it.

Every import statement counts, wherever it stands: at module level, inside a function
(an import moved into a function to dodge a circle is still a circle) and under
``if TYPE_CHECKING:``. Imports built from strings at run time (``importlib``) are not seen.

An edge goes to the module actually named: ``import a.b`` and ``from a import b``
(when ``a/b.py`` exists) point at ``a.b``; ``from a.b import name`` points at ``a.b``.
The parent packages Python initialises on the way are not edges, as in import-linter.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Import:
    """One imported module (and the names taken from it) in one statement."""

    importer: str
    imported: str
    names: tuple[str, ...]
    line: int


def module_files(root: Path, packages: Iterable[str]) -> dict[str, Path]:
    """Map the dotted name of every module under the ``packages`` directories of ``root`` to its file."""
    modules: dict[str, Path] = {}
    for package in packages:
        for path in sorted((root / package).rglob("*.py")):
            parts = list(path.relative_to(root).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            modules[".".join(parts)] = path
    return modules


def _absolute(module: str | None, level: int, importer: str, is_package: bool) -> str:
    """Resolve a (possibly relative) ``from`` target as seen from ``importer``."""
    if level == 0:
        return module or ""
    base = importer.split(".")
    if not is_package:
        base.pop()
    if level > 1:
        base = base[: len(base) - (level - 1)]
    return ".".join(base + ([module] if module else []))


def _statement_imports(node: ast.AST, importer: str, is_package: bool, known: Mapping[str, Path]) -> Iterator[Import]:
    if isinstance(node, ast.Import):
        for alias in node.names:
            yield Import(importer, alias.name, (), node.lineno)
    elif isinstance(node, ast.ImportFrom):
        target = _absolute(node.module, node.level, importer, is_package)
        plain_names: list[str] = []
        for alias in node.names:
            submodule = f"{target}.{alias.name}"
            if submodule in known:
                yield Import(importer, submodule, (), node.lineno)
            else:
                plain_names.append(alias.name)
        if plain_names or not node.names:
            yield Import(importer, target, tuple(plain_names), node.lineno)


def collect_imports(root: Path, packages: Iterable[str]) -> list[Import]:
    """Return every import in the modules of ``packages`` under ``root``, in file and line order."""
    known = module_files(root, packages)
    found: list[Import] = []
    for importer, path in known.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        is_package = path.name == "__init__.py"
        for node in ast.walk(tree):
            found.extend(_statement_imports(node, importer, is_package, known))
    return sorted(found, key=lambda edge: (edge.importer, edge.line, edge.imported))


def in_package(module: str, package: str) -> bool:
    """True when ``module`` is ``package`` itself or lies inside it."""
    return module == package or module.startswith(package + ".")


def module_graph(imports: Iterable[Import], known: Iterable[str]) -> dict[str, set[str]]:
    """The edges between project modules only (self-imports dropped)."""
    nodes = set(known)
    graph: dict[str, set[str]] = {node: set() for node in nodes}
    for edge in imports:
        if edge.imported in nodes and edge.imported != edge.importer:
            graph[edge.importer].add(edge.imported)
    return graph


def strongly_connected(graph: Mapping[str, set[str]]) -> list[frozenset[str]]:
    """Tarjan's algorithm, iterative: the components of more than one module (every circle lies in one)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    components: list[frozenset[str]] = []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work: list[tuple[str, Iterator[str]]] = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            advanced = False
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = counter
                    counter += 1
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(graph[successor]))))
                    advanced = True
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            if advanced:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                members = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    members.add(member)
                    if member == node:
                        break
                if len(members) > 1:
                    components.append(frozenset(members))
    return components


def cycle_edges(graph: Mapping[str, set[str]]) -> set[tuple[str, str]]:
    """Every edge that lies on some circle: the edges inside a strongly connected component."""
    edges: set[tuple[str, str]] = set()
    for component in strongly_connected(graph):
        edges.update((a, b) for a in component for b in graph[a] if b in component)
    return edges


KERNEL_PACKAGES_BELOW: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("nck.lang", ("nck.interp", "nck.iso", "nck.geometry", "nck.motion", "nck.simulation")),
    ("nck.geometry", ("nck.interp", "nck.iso", "nck.motion", "nck.simulation")),
    ("nck.iso", ("nck.interp", "nck.motion", "nck.simulation")),
    ("nck.interp", ("nck.iso", "nck.motion", "nck.simulation")),
    ("nck.motion", ("nck.lang", "nck.interp", "nck.iso", "nck.geometry", "nck.simulation")),
)
"""The kernel's packages and the ones they may not import (issue 21's map, ``one-door.md``):
``interp -> {lang, geometry, canon}`` and never ``iso``; ``iso -> {lang, geometry}``, a front
end the interpreter does not know; ``geometry -> lang``; ``lang`` is the bottom; the motion
system takes canonical motion and machine data only. The simulation and the kernel's own
modules sit above them all."""


@dataclass(frozen=True)
class LayerRules:
    """What may import what; each rule yields (importer, imported) module pairs that break it."""

    kernel: str = "nck"
    ui_packages: tuple[str, ...] = ("hmi", "screens")
    forbidden_in_kernel: tuple[str, ...] = ("hmi", "screens", "textual", "rich")
    facade: tuple[str, ...] = ("nck", "nck.commands", "nck.status", "nck.queries")
    hmi: str = "hmi"
    screens: str = "screens"
    areas: tuple[str, ...] = ()
    below: tuple[tuple[str, tuple[str, ...]], ...] = KERNEL_PACKAGES_BELOW
    """(kernel package, the kernel packages it may not import): the arrows of issue 21's map."""

    def area_of(self, module: str) -> str:
        """The operating area a ``screens`` module belongs to: the longest area id its name starts with.

        A module that belongs to no area (a shared dialog, the placeholder) is its own unit.
        """
        name = module.removeprefix(self.screens + ".")
        owners = [area for area in self.areas if name == area or name.startswith(area + "_")]
        return max(owners, key=len) if owners else name

    def violations(self, imports: Iterable[Import]) -> set[tuple[str, str]]:
        """The (importer, imported) pairs that break the layer contract."""
        broken: set[tuple[str, str]] = set()
        for edge in imports:
            if self.breaks(edge.importer, edge.imported):
                broken.add((edge.importer, edge.imported))
        return broken

    def breaks(self, importer: str, imported: str) -> bool:
        """True when ``importer`` may not import ``imported``."""
        if in_package(importer, self.kernel):
            if any(in_package(imported, package) for package in self.forbidden_in_kernel):
                return True
            return any(in_package(importer, package) and any(in_package(imported, above) for above in others)
                       for package, others in self.below)
        if not any(in_package(importer, package) for package in self.ui_packages):
            return False
        if in_package(imported, self.kernel):
            return imported not in self.facade
        if in_package(importer, self.hmi):
            # The app may read the registry of areas, never an area's module.
            return in_package(imported, self.screens) and imported != self.screens
        if in_package(importer, self.screens) and in_package(imported, self.screens):
            return imported != self.screens and self.area_of(imported) != self.area_of(importer)
        return False


def is_private(name: str) -> bool:
    """A ``_single_underscore`` name (dunder names are public, and so is ``_``: gettext's
    translate function, :mod:`hmi.i18n`)."""
    return name.startswith("_") and not name.endswith("__") and name != "_"


def private_imports(imports: Iterable[Import]) -> set[tuple[str, str, str]]:
    """(importer, module, name) for every ``_private`` name taken from another module."""
    return {
        (edge.importer, edge.imported, name)
        for edge in imports
        if edge.imported != edge.importer
        for name in edge.names
        if is_private(name)
    }
