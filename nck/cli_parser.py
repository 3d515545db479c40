"""The argument parser shared by the ``nck`` commands: a usage error is raised, never an exit.

argparse prints its message and ends the process on a bad command line; the
commands want to answer with their own prefix and exit code 2 instead, and to
stay callable from tests. :class:`CliParser` raises :class:`CliError` for that.
"""

from __future__ import annotations

import argparse
from typing import Sequence, TextIO


class CliError(Exception):
    """A command-line or file problem (exit code 2)."""


class CliParser(argparse.ArgumentParser):
    """An ``ArgumentParser`` whose usage errors raise :class:`CliError`."""

    def error(self, message: str) -> None:  # type: ignore[override]
        raise CliError(message)

    def parse_command(self, argv: Sequence[str], err: TextIO) -> argparse.Namespace | int:
        """The parsed options, or the exit code the command ends with: 2 after a usage message
        (prefixed with the command's name) on ``err``, or ``--help``'s code after the help."""
        try:
            return self.parse_args(argv)
        except CliError as exc:
            print(f"{self.prog}: {exc}", file=err)
            return 2
        except SystemExit as exc:  # --help
            return int(exc.code or 0)
