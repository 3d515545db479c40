"""The argument parser shared by the ``nck`` commands: a usage error is raised, never an exit.

argparse prints its message and ends the process on a bad command line; the
commands want to answer with their own prefix and exit code 2 instead, and to
stay callable from tests. :class:`CliParser` raises :class:`CliError` for that.
"""

from __future__ import annotations

import argparse


class CliError(Exception):
    """A command-line or file problem (exit code 2)."""


class CliParser(argparse.ArgumentParser):
    """An ``ArgumentParser`` whose usage errors raise :class:`CliError`."""

    def error(self, message: str) -> None:  # type: ignore[override]
        raise CliError(message)
