"""Run a writing ``nck`` subcommand on its NC data directory: open (or copy), lock, clean up.

``nck md`` and ``nck setup`` work the same way on the data directory: ``--ephemeral`` works on
a temporary copy that is removed afterwards; otherwise the directory is locked for as long as
the command works there (an HMI on the same directory would overwrite what the command writes,
see :mod:`nck.datalock`). Errors of the directory become a message on ``err`` and exit code 2.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, TextIO

from nck.datalock import DataDirLockError, lock_data_dir
from nck.paths import open_data_dir


def run_on_data_dir(command: str, data_dir_option: str | None, ephemeral: bool, err: TextIO,
                    body: Callable[[Path], int]) -> int:
    """Call ``body`` with the data directory to work in and return its exit code.

    ``command`` (``"nck md"``) starts the messages; ``data_dir_option`` and ``ephemeral`` are
    the command's ``--data-dir`` and ``--ephemeral``.
    """
    try:
        data_dir, copy = open_data_dir(data_dir_option, ephemeral)
    except OSError as exc:
        print(f"{command}: data directory {data_dir_option}: {exc.strerror}", file=err)
        return 2
    lock = None
    try:
        if copy is None:
            lock = lock_data_dir(data_dir)
        return body(data_dir)
    except DataDirLockError as exc:
        print(f"{command}: {exc}", file=err)
        return 2
    except OSError as exc:
        print(f"{command}: data directory {data_dir}: {exc.strerror or exc}", file=err)
        return 2
    finally:
        if lock is not None:
            lock.release()
        if copy is not None:
            copy.cleanup()
