"""Every test that ``tests/README.md`` names exists (issue 20: the table matches the tests).

The README names tests as ``tests/dir/file.py::test_name``, ``file.py::test_name`` (a file of
that name under tests/), ``::test_name`` (the file named last in the same row) and
``::test_prefix_*`` (at least one test starts with the prefix). A renamed or deleted test makes
this fail with the names that no longer resolve.
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path

TESTS = Path(__file__).resolve().parent
README = TESTS / "README.md"
REFERENCE = re.compile(r"`([^`]*?\.py)?::([A-Za-z0-9_]+\*?)`|`([^`:]*?\.py)`")


@functools.cache
def functions_of(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return {node.name for node in ast.walk(tree) if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))}


@functools.cache
def resolve(name: str) -> Path | None:
    if name.startswith("tests/"):
        path = TESTS.parent / name
        return path if path.is_file() else None
    found = sorted(TESTS.rglob(name))
    return found[0] if len(found) == 1 else None


def references() -> list[tuple[int, str, str]]:
    """(README line, file, test name or prefix*) of every test reference."""
    out: list[tuple[int, str, str]] = []
    for number, line in enumerate(README.read_text(encoding="utf-8").splitlines(), start=1):
        last_file: str | None = None
        for match in REFERENCE.finditer(line):
            file, test, bare_file = match.group(1), match.group(2), match.group(3)
            if bare_file:
                last_file = bare_file
                continue
            file = file or last_file
            assert file, f"README line {number}: ::{test} without a file before it"
            last_file = file
            out.append((number, file, test))
    return out


def test_the_readme_names_tests() -> None:
    assert len(references()) > 100


def test_every_test_named_in_the_readme_exists() -> None:
    missing = []
    for number, file, test in references():
        path = resolve(file)
        if path is None:
            missing.append(f"line {number}: {file} (no such file, or the name is not unique)")
            continue
        names = functions_of(path)
        found = any(n.startswith(test[:-1]) for n in names) if test.endswith("*") else test in names
        if not found:
            missing.append(f"line {number}: {file}::{test}")
    assert not missing, "\n".join(missing)


def test_every_bad_program_and_golden_case_named_in_the_readme_exists() -> None:
    text = README.read_text(encoding="utf-8")
    paths = re.findall(r"`(tests/[^`*]+\.(?:mpf|py)|tests/[^`.*]+)`", text)
    golden = re.findall(r"`(\d\d_[a-z0-9_]+)`", text)
    assert paths and golden
    missing = [p for p in paths if not (TESTS.parent / p).exists()]
    missing += [g for g in golden if not (TESTS / "golden" / g / "main.mpf").is_file()]
    assert not missing, missing


STATUSES = ("tested", "partly", "not modelled", "fails today")


def status_counts() -> dict[str, dict[str, int]]:
    """Per digest section, how many rows carry each status (the first words of column 3)."""
    counts: dict[str, dict[str, int]] = {}
    section = None
    for line in README.read_text(encoding="utf-8").splitlines():
        heading = re.match(r"## (\S+) — ", line)
        if heading:
            section = heading.group(1)
            counts[section] = dict.fromkeys(STATUSES, 0)
            continue
        row = re.match(r"\| (\d+) \| [^|]+ \| ([^|]+) \|", line)
        if section and row:
            status = next(s for s in STATUSES if row.group(2).strip().startswith(s))
            counts[section][status] += 1
    return counts


def test_the_counts_and_the_summary_match_the_rows() -> None:
    text = README.read_text(encoding="utf-8")
    counts = status_counts()
    total = dict.fromkeys(STATUSES, 0)
    for section, by_status in counts.items():
        row = re.search(rf"^\| {re.escape(section)} \| (\d+) \| (\d+) \| (\d+) \| (\d+) \| (\d+) \|$", text, re.M)
        assert row, f"{section} is missing in the summary"
        assert [int(v) for v in row.groups()] == [sum(by_status.values()), *by_status.values()], section
        block = text[text.index(f"## {section} — "):]
        line = re.search(r"^Counts: tested (\d+), partly (\d+), not modelled (\d+), fails today (\d+)", block, re.M)
        assert line and [int(v) for v in line.groups()] == list(by_status.values()), section
        for status in STATUSES:
            total[status] += by_status[status]
    row = re.search(r"^\| all \| (\d+) \| (\d+) \| (\d+) \| (\d+) \| (\d+) \|$", text, re.M)
    assert row and [int(v) for v in row.groups()] == [129, *total.values()]
