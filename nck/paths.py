"""Where the NC data directory is: the user's data directory, a given path, or a temporary copy.

The NC data directory holds everything the simulated control retains: the NC
file system (``nc/``), the retained data (``retained/``, see
:mod:`nck.persistence`). Its default is the per-user data directory of the
platform (via ``platformdirs``); the environment variable ``NCK_DATA_DIR``
overrides that default. ``--ephemeral`` works on a temporary copy that is
thrown away at the end.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

APP_NAME = "sinumerik-trainer"
ENV_DATA_DIR = "NCK_DATA_DIR"


def default_data_dir() -> Path:
    """The default NC data directory (``$NCK_DATA_DIR`` or the platform user data dir)."""
    override = os.environ.get(ENV_DATA_DIR)
    if override:
        return Path(override).expanduser()
    try:
        import platformdirs
    except ImportError:  # pragma: no cover - platformdirs is a dependency
        base = Path(os.environ.get("XDG_DATA_HOME", Path.home() / ".local" / "share"))
        return base / APP_NAME / "ncdata"
    return platformdirs.user_data_path(APP_NAME, appauthor=False) / "ncdata"


def resolve_data_dir(data_dir: str | Path | None) -> Path:
    """The directory for ``--data-dir`` (the default when None), created if missing."""
    path = Path(data_dir).expanduser() if data_dir else default_data_dir()
    path.mkdir(parents=True, exist_ok=True)
    return path


class EphemeralDataDir:
    """A temporary copy of an NC data directory; nothing is written back.

    Use as a context manager or call :meth:`cleanup` at the end::

        with EphemeralDataDir(source) as path:
            ...
    """

    def __init__(self, source: str | Path | None = None) -> None:
        self._temp = Path(tempfile.mkdtemp(prefix="nck-ephemeral-"))
        self.path = self._temp / "ncdata"
        origin = Path(source).expanduser() if source else default_data_dir()
        if origin.is_dir():
            shutil.copytree(origin, self.path, ignore=shutil.ignore_patterns(".*.tmp-*"))
        else:
            self.path.mkdir()

    def cleanup(self) -> None:
        """Delete the temporary copy."""
        shutil.rmtree(self._temp, ignore_errors=True)

    def __enter__(self) -> Path:
        return self.path

    def __exit__(self, *exc: object) -> None:
        self.cleanup()


def open_data_dir(data_dir: str | Path | None, ephemeral: bool = False) -> tuple[Path, EphemeralDataDir | None]:
    """Return the directory to work in and, for ``ephemeral``, the copy to clean up later."""
    if ephemeral:
        copy = EphemeralDataDir(data_dir)
        return copy.path, copy
    return resolve_data_dir(data_dir), None
