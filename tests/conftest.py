"""Suite-wide set-up: tests never touch the user's real NC data directory."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

# Headless commands read the user's NC data directory by default; point the default at a
# directory that does not exist so every test starts from fresh NC data, whatever the
# machine running the suite has set up. Subprocesses inherit the variable.
os.environ["NCK_DATA_DIR"] = str(Path(tempfile.gettempdir()) / f"nck-tests-no-data-{os.getpid()}")
