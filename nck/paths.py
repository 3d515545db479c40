"""Where the NC data directory is: the user's data directory, a given path, or a temporary copy.

The NC data directory holds everything the simulated control retains: the NC
file system (``nc/``), the retained data (``retained/``, see
:mod:`nck.persistence`). Its default is the per-user data directory of the
platform (via ``platformdirs``); the environment variable ``NCK_DATA_DIR``
overrides that default. ``--ephemeral`` works on a temporary copy that is
thrown away at the end.
"""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
from pathlib import Path

from nck.atomic import TEMP_MARK
from nck.regular_files import copy_regular_tree, is_plain_directory

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


EPHEMERAL_PREFIX = "nck-ephemeral-"
EPHEMERAL_LIMIT_BYTES = 256 * 1024 * 1024
"""Most a temporary copy may hold (the NC memory of programs and data is far smaller)."""


class EphemeralDataDir:
    """A temporary copy of an NC data directory; nothing is written back.

    Only directories and regular files are copied — links, FIFOs and devices
    are never followed (:mod:`nck.regular_files`) — and at most
    :data:`EPHEMERAL_LIMIT_BYTES`; a copy that fails is removed before the
    error (an ``OSError``) reaches the caller. The copy is removed by
    :meth:`cleanup`, at the latest when the process exits normally (``atexit``;
    the entry points turn SIGTERM/SIGHUP into a normal exit). A copy whose
    process died without either (SIGKILL) carries the dead PID in its name and
    is removed when the next copy is made. Use as a context manager or call
    :meth:`cleanup` at the end::

        with EphemeralDataDir(source) as path:
            ...
    """

    def __init__(self, source: str | Path | None = None) -> None:
        remove_abandoned_copies()
        self._temp = Path(tempfile.mkdtemp(prefix=f"{EPHEMERAL_PREFIX}{os.getpid()}-"))
        self.path = self._temp / "ncdata"
        origin = Path(source).expanduser() if source else default_data_dir()
        try:
            if origin.is_dir():  # the directory the operator names may be a link; nothing below it is followed
                copy_regular_tree(origin.resolve(), self.path, EPHEMERAL_LIMIT_BYTES, _is_temp_file)
            else:
                self.path.mkdir()
        except BaseException:
            self.cleanup()
            raise
        atexit.register(self.cleanup)

    def cleanup(self) -> None:
        """Delete the temporary copy (again is harmless)."""
        shutil.rmtree(self._temp, ignore_errors=True)
        atexit.unregister(self.cleanup)

    def __enter__(self) -> Path:
        return self.path

    def __exit__(self, *exc: object) -> None:
        self.cleanup()


def _is_temp_file(name: str) -> bool:
    return name.startswith(".") and TEMP_MARK in name


def _process_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # exists, but belongs to someone else
        return True
    return True


def remove_abandoned_copies(temp_dir: Path | None = None) -> list[Path]:
    """Remove this user's temporary copies whose process has ended; return them."""
    removed: list[Path] = []
    if os.name != "posix":  # no process probe there (os.kill would end the process)
        return removed
    folder = Path(temp_dir or tempfile.gettempdir())
    user = os.getuid()
    try:
        candidates = [p for p in folder.iterdir() if p.name.startswith(EPHEMERAL_PREFIX)]
    except OSError:
        return removed
    for candidate in candidates:
        pid_text = candidate.name[len(EPHEMERAL_PREFIX):].partition("-")[0]
        try:
            mine = candidate.lstat().st_uid == user and is_plain_directory(candidate)
        except OSError:
            continue
        if mine and pid_text.isdigit() and not _process_alive(int(pid_text)):
            shutil.rmtree(candidate, ignore_errors=True)
            removed.append(candidate)
    return removed


def open_data_dir(data_dir: str | Path | None, ephemeral: bool = False) -> tuple[Path, EphemeralDataDir | None]:
    """Return the directory to work in and, for ``ephemeral``, the copy to clean up later."""
    if ephemeral:
        copy = EphemeralDataDir(data_dir)
        return copy.path, copy
    return resolve_data_dir(data_dir), None
