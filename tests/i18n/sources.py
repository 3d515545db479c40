"""The texts of the code that the gettext catalogues must translate, found in the source.

A text is taken from ``hmi/`` and ``screens/`` where it is

* the literal argument of ``_("…")`` (translated where shown) or ``N_("…")`` (a table
  defined at import, translated where shown), and of ``Reason("…")`` / ``Phrase("…")`` in the
  kernel modules of :data:`KERNEL_MODULES` (the exercise checks' reasons, which the side window
  translates, and the simulation's events);
* the title and note of a ``DataTable(…)`` and the title of a ``Column(…)`` (the table
  window draws them translated), the title and hint of a ``JogForm(…)`` and the label of a
  ``FieldSpec(…)`` (the JOG windows draw them translated);
* the label of a softkey: the second argument of ``Softkey(…)``, ``view_softkey(…)`` and
  the areas' softkey builders of :data:`LABELLED` (the softkey bars and the palette
  translate every label).

``python -m tests.i18n.sources`` adds the texts missing from each catalogue
``data/lang/<code>/hmi.po`` (with an empty translation to fill in) and lists the
entries no code uses any more. It is a development tool; the product never runs it.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("hmi", "screens")
MARKERS = frozenset({"_", "N_", "Reason", "Phrase"})
KERNEL_MODULES = ("nck/exercise_checks.py", "nck/simulation/run.py", "nck/kernel.py", "nck/kernel_access.py")
"""Modules of the kernel whose texts the panel translates: the exercise checks' ``Reason(…)``,
the simulation events' and the logbook's ``Phrase(…)`` (``nck.phrase``)."""
LABELLED = frozenset({"Softkey", "view_softkey", "view_key", "_view_key", "_search_mode_key"})
"""Functions whose second argument is a softkey label (the areas' small softkey builders)."""


def _name(node: ast.expr) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return ""


TABLE_TEXTS: dict[str, tuple[tuple[int, str], ...]] = {
    "Column": ((0, "title"),), "DataTable": ((0, "title"), (3, "note")),
    "JogForm": ((0, "title"), (2, "hint")), "FieldSpec": ((1, "label"),),
    "Binding": ((2, "description"),),
}
"""The data tables' and the JOG windows' texts (hmi.widgets.data_table and
screens.machine_jog_form draw them translated): position and keyword."""


def _arguments(node: ast.Call, name: str) -> list[ast.expr]:
    if name in MARKERS:
        return node.args[:1]
    if name in LABELLED:
        return node.args[1:2]
    chosen: list[ast.expr] = []
    for position, keyword in TABLE_TEXTS.get(name, ()):
        if len(node.args) > position:
            chosen.append(node.args[position])
        chosen += [k.value for k in node.keywords if k.arg == keyword]
    return chosen


def texts_of(source: str, filename: str = "<source>") -> dict[str, int]:
    """Every translatable literal of one module with the line it is on."""
    found: dict[str, int] = {}
    for node in ast.walk(ast.parse(source, filename)):
        if not isinstance(node, ast.Call):
            continue
        for argument in _arguments(node, _name(node.func)):
            if isinstance(argument, ast.Constant) and isinstance(argument.value, str) and argument.value.strip():
                found.setdefault(argument.value, node.lineno)
    return found


def code_texts() -> dict[str, str]:
    """Every translatable text of the panel -> the first place it occurs (``path:line``)."""
    texts: dict[str, str] = {}
    paths = [path for package in PACKAGES for path in sorted((ROOT / package).rglob("*.py"))]
    for path in paths + [ROOT / module for module in KERNEL_MODULES]:
        relative = path.relative_to(ROOT)
        for text, line in texts_of(path.read_text(encoding="utf-8"), str(relative)).items():
            texts.setdefault(text, f"{relative}:{line}")
    return texts


def po_quote(text: str) -> str:
    """``text`` as one quoted .po string."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\t", "\\t")
    return f'"{escaped}"'


def update_catalogues() -> int:
    """Append the missing texts to every catalogue; print the stale ones. Returns 0."""
    from nck.translations import LANGUAGES, SOURCE_LANGUAGE, read_po

    texts = code_texts()
    for code in LANGUAGES:
        if code == SOURCE_LANGUAGE:
            continue
        path = ROOT / "data" / "lang" / code / "hmi.po"
        known = read_po(path) if path.is_file() else {}
        present = set(known) | _untranslated(path)
        missing = [text for text in texts if text not in present]
        with path.open("a", encoding="utf-8") as handle:
            for text in missing:
                handle.write(f"\n#: {texts[text]}\nmsgid {po_quote(text)}\nmsgstr \"\"\n")
        print(f"{path.relative_to(ROOT)}: {len(missing)} added")
        for text in sorted(present - set(texts)):
            print(f"  no longer used: {text!r}")
    return 0


def _untranslated(path: Path) -> set[str]:
    """The msgids of ``path`` whatever their translation (empty or fuzzy ones too)."""
    if not path.is_file():
        return set()
    ids: set[str] = set()
    current: list[str] | None = None
    for raw in path.read_text(encoding="utf-8").splitlines():
        line = raw.strip()
        if line.startswith("msgid "):
            current = [ast.literal_eval(line[6:])]
        elif line.startswith('"') and current is not None:
            current.append(ast.literal_eval(line))
        else:
            if current is not None and "".join(current):
                ids.add("".join(current))
            current = None
    if current is not None and "".join(current):
        ids.add("".join(current))
    return ids


if __name__ == "__main__":
    sys.exit(update_catalogues())
