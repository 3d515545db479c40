"""mypy on the kernel as a ratchet: the error count may only go down.

``tests/mypy_baseline.txt`` holds the number of errors mypy reports on ``nck/`` today (the
settings are in ``pyproject.toml`` under ``[tool.mypy]``). More errors fail the test; fewer
fail it too, with the new number to write into the file, so the ceiling follows every fix.
mypy's cache lives in the virtual environment: only changed modules are checked again.
"""

from __future__ import annotations

import hashlib
import importlib.util
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = Path(__file__).with_name("mypy_baseline.txt")


def cache_dir() -> Path:
    """A cache per checkout: inside the virtual environment when it is the checkout's, else in tmp."""
    venv = Path(sys.prefix)
    if venv.parent == ROOT:
        return venv / "mypy_cache"
    checkout = hashlib.sha256(str(ROOT).encode()).hexdigest()[:12]
    return Path(tempfile.gettempdir()) / f"mypy-cache-{checkout}"


def mypy_errors(target: str = "nck", cwd: Path = ROOT, cache: str = "nck") -> list[str]:
    """The ``error:`` lines mypy reports on ``target`` (relative to ``cwd``) with the project's settings."""
    assert importlib.util.find_spec("mypy"), "mypy is missing: run `make .venv/.installed` (the test extra pins it)"
    completed = subprocess.run(
        [
            *(sys.executable, "-m", "mypy", "--config-file", str(ROOT / "pyproject.toml")),
            *("--cache-dir", str(cache_dir() / cache), "--no-error-summary", "--no-pretty", "--no-color-output"),
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
    errors = mypy_errors("broken_sample.py", tmp_path, cache="sample")  # own cache: may run in parallel
    assert len(errors) == 1 and "broken_sample.py:1:" in errors[0]
