"""An operating system's refusal of a file operation as a keyed refusal (``data/refusals.toml``).

An ``OSError``'s own text (``strerror``) is the C library's English sentence; a panel that
shows it in another language needs a key. :func:`os_refusal` picks one by the error's kind
(``errno``): no such file or directory, permission denied, disk full, read-only file system,
not a regular file, a file where a folder belongs, too large; any other error says that the
file could not be written (or read, ``failed="os_read_failed"``). The sentence is ``{path}: {what}``: the path is the error's
own (``filename``) unless given, the kind's text (``what``, with its key ``what_key``) is said
in the panel's language as an access refusal's is (``hmi.i18n.refusal_fields_in``).
Pure: no file is touched.
"""

from __future__ import annotations

import errno
from pathlib import Path

from nck.refused import Refused, refusal_texts
from nck.regular_files import FileTooLarge, NotAFolder, NotARegularFile

ERRNO_KEYS = {
    errno.ENOENT: "os_no_such_file",
    errno.ENOTDIR: "os_no_such_file",
    errno.EACCES: "os_permission_denied",
    errno.EPERM: "os_permission_denied",
    errno.ENOSPC: "os_disk_full",
    errno.EDQUOT: "os_disk_full",
    errno.EROFS: "os_read_only",
    errno.EISDIR: "os_is_a_folder",
}
"""The refusal key of each error number a trainee meets at a file operation."""


def os_refusal(error: OSError, *, path: Path | str | None = None, failed: str = "os_write_failed") -> Refused:
    """The keyed refusal of ``error``: ``{path}: {what}`` with the error's ``filename`` (or
    ``path``), the kind's text alone when neither is known."""
    key, fields = _kind(error, failed)
    where = path if path is not None else error.filename
    if where is None or str(where) == "":
        return Refused(key, **fields)
    return Refused("os_at_path", path=str(where), what_key=key, what=refusal_texts()[key].format(**fields), **fields)


def _kind(error: OSError, failed: str) -> tuple[str, dict[str, object]]:
    """The refusal key of ``error``'s kind and the values of its placeholders."""
    if isinstance(error, NotARegularFile):
        return "os_not_regular", {}
    if isinstance(error, NotAFolder):
        return "os_not_a_folder", {}
    if isinstance(error, FileTooLarge):
        if error.limit_bytes >= 1 << 20:
            return "os_too_large_mb", {"size_mb": error.limit_bytes >> 20}
        return "os_too_large_bytes", {"size_bytes": error.limit_bytes}
    return ERRNO_KEYS.get(error.errno or 0, failed), {}


__all__ = ["ERRNO_KEYS", "os_refusal"]
