"""Reading the TOML files an operator names on the command line (machine file, tool table).

Such a file comes from anywhere: it may be a link to ``/dev/zero``, a FIFO, a
huge file or TOML nested 100,000 levels deep (the standard parser recurses and
ends in ``RecursionError``). :func:`load_operator_toml` reads at most
:data:`OPERATOR_TOML_LIMIT_BYTES` of a regular file (a link the operator made is
followed, to a regular file only) and turns every way it can fail into
:class:`OperatorFileError` with a message for the user.
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from nck.regular_files import read_regular_bytes

OPERATOR_TOML_LIMIT_BYTES = 4 * 1024 * 1024
"""Largest machine file or tool table read (real ones are a few kilobytes)."""


class OperatorFileError(Exception):
    """The file cannot be used; ``str()`` says why (without the file name)."""


def load_operator_toml(path: Path | str) -> dict[str, Any]:
    """The TOML table in the file ``path``; OperatorFileError says why not."""
    try:
        raw = read_regular_bytes(path, OPERATOR_TOML_LIMIT_BYTES, follow_links=True)
    except OSError as exc:
        raise OperatorFileError(f"cannot be read ({exc.strerror or exc})") from None
    try:
        return tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise OperatorFileError("is not UTF-8 text") from None
    except tomllib.TOMLDecodeError as exc:
        raise OperatorFileError(f"is not valid TOML: {exc}") from None
    except RecursionError:
        raise OperatorFileError("is nested too deeply") from None
