"""Suite-wide set-up: tests never touch the user's real NC data directory."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

# Headless commands read the user's NC data directory by default; point the default at a
# directory that does not exist so every test starts from fresh NC data, whatever the
# machine running the suite has set up. Subprocesses inherit the variable.
os.environ["NCK_DATA_DIR"] = str(Path(tempfile.gettempdir()) / f"nck-tests-no-data-{os.getpid()}")


import pytest  # noqa: E402


@pytest.fixture(autouse=True)
def _run_in_a_temporary_directory(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Exports (programs, alarm log, trace CSV) go to the current directory: keep them out of the tree."""
    monkeypatch.chdir(tmp_path)
