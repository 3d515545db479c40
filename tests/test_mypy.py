"""mypy on the kernel as a ratchet: the error count may only go down.

``tests/mypy_baseline.txt`` holds the number of errors mypy reports on ``nck/`` today (the
settings are in ``pyproject.toml`` under ``[tool.mypy]``). More errors fail the test; fewer
fail it too, with the new number to write into the file, so the ceiling follows every fix.
mypy runs without its incremental cache (about 5 s for nck/): the cache gave 145 errors where a
fresh run gives 143 after the tree changed under it (mixins of the kernel), so the count depends
on nothing but the code.
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = Path(__file__).with_name("mypy_baseline.txt")


def mypy_errors(target: str = "nck", cwd: Path = ROOT) -> list[str]:
    """The ``error:`` lines mypy reports on ``target`` (relative to ``cwd``) with the project's settings."""
    assert importlib.util.find_spec("mypy"), "mypy is missing: run `make .venv/.installed` (the test extra pins it)"
    completed = subprocess.run(
        [
            *(sys.executable, "-m", "mypy", "--config-file", str(ROOT / "pyproject.toml")),
            *("--no-incremental", "--cache-dir", os.devnull),
            *("--no-error-summary", "--no-pretty", "--no-color-output"),
            target,
        ],
        cwd=cwd,
        capture_output=True,
        text=True,
        check=False,
    )
    assert completed.returncode in (0, 1) and not completed.stderr, completed.stderr or completed.stdout
    return [line for line in completed.stdout.splitlines() if ": error:" in line]


def test_mypy_error_count_on_the_kernel_only_goes_down() -> None:
    recorded = int(BASELINE.read_text(encoding="utf-8").split()[0])
    errors = mypy_errors()
    assert len(errors) <= recorded, (
        f"mypy reports {len(errors)} errors on nck/, more than the {recorded} recorded; fix the new ones:\n"
        + "\n".join(errors)
    )
    assert len(errors) == recorded, (
        f"mypy reports {len(errors)} errors on nck/, fewer than the {recorded} recorded: "
        f"write {len(errors)} into tests/mypy_baseline.txt"
    )


def test_the_count_sees_a_type_error(tmp_path: Path) -> None:
    (tmp_path / "broken_sample.py").write_text('count: int = "three"\n\n\ndef ok() -> str:\n    return "fine"\n')
    errors = mypy_errors("broken_sample.py", tmp_path)
    assert len(errors) == 1 and "broken_sample.py:1:" in errors[0]
