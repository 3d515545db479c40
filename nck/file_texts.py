"""Program texts (and folder listings) kept by file identity, read again only when the file changed.

A subprogram or cycle called 2,000 times (a hole pattern with a modal ``CYCLE81``) was read,
decoded and hashed on every call. :class:`FileTexts` keeps each text with the signature of the
file it was read from — device, inode, size, modification and status-change times, as one
``stat`` reports them — and returns the kept text while a new ``stat`` of the same path gives the
same signature. Writing a file in place changes its times (and usually its size); replacing it
(an atomic save) changes its inode; so the next call reads the new text.

The limit is the file system's time stamp granularity: a rewrite of the same size that lands in
the same time-stamp tick as the read before it (a few milliseconds at most on Linux) keeps
the old text until the file changes again (kernels with fine-grained time stamps, Linux 6.13 on,
do not have the gap; the NC file system's own writes clear its caches, so they never hit it).
:class:`FolderNames` keeps a folder's entry names the same way (a folder's times change when an
entry is added, removed or renamed), with the same limit for two changes within one tick.
"""

from __future__ import annotations

import os
from stat import S_ISDIR
from typing import Callable, Generic, TypeVar

ENTRIES_KEPT = 64
"""Texts or listings kept per cache; the oldest half goes when it is full (a program calls few names)."""

TEXT_KEPT_MAX_CHARS = 1_000_000
"""Longer texts are read on every call and not kept: a cache lives as long as its file system or
interpreter, and the texts worth keeping are the cycles and subprograms called again and again."""

Signature = tuple[int, int, int, int, int]
Value = TypeVar("Value")


def signature(stat: os.stat_result) -> Signature:
    """What identifies one version of a file: device, inode, size, mtime and ctime (ns)."""
    return (stat.st_dev, stat.st_ino, stat.st_size, stat.st_mtime_ns, stat.st_ctime_ns)


class SignatureCache(Generic[Value]):
    """Values by path, each valid while its file's :func:`signature` stays the same."""

    def __init__(self, limit: int = ENTRIES_KEPT) -> None:
        self.limit = limit
        self._kept: dict[str, tuple[Signature, Value]] = {}

    def get(self, path: str, stat: os.stat_result, compute: Callable[[], Value],
            keep: Callable[[Value], bool] = lambda value: True) -> Value:
        """The value of ``path`` whose ``stat`` the caller took just before: the kept one when
        the file is unchanged, else ``compute()`` (which may raise; nothing is kept then), kept
        when ``keep`` says so."""
        key = signature(stat)
        kept = self._kept.get(path)
        if kept is not None and kept[0] == key:
            return kept[1]
        value = compute()
        self._kept.pop(path, None)
        if keep(value):
            if len(self._kept) >= self.limit:
                for old in list(self._kept)[: self.limit // 2]:
                    del self._kept[old]
            self._kept[path] = (key, value)
        return value

    def clear(self) -> None:
        """Forget everything kept (the owner changed files itself)."""
        self._kept.clear()


class FileTexts:
    """Program texts by path, each read again only when its file changed."""

    def __init__(self, limit: int = ENTRIES_KEPT) -> None:
        self._cache: SignatureCache[str] = SignatureCache(limit)

    def text(self, path: str, stat: os.stat_result, read: Callable[[], str]) -> str:
        """The text of ``path`` whose ``stat`` the caller took just before: the kept one when the
        file is unchanged, else ``read()`` (which may raise). Texts longer than
        :data:`TEXT_KEPT_MAX_CHARS` are not kept."""
        return self._cache.get(path, stat, read, lambda text: len(text) <= TEXT_KEPT_MAX_CHARS)

    def clear(self) -> None:
        """Forget every kept text."""
        self._cache.clear()


class FolderNames:
    """The entries of folders by name in capitals (paths in listing order), each listing kept while
    the folder's :func:`signature` stays the same."""

    def __init__(self, limit: int = ENTRIES_KEPT) -> None:
        self._cache: SignatureCache[dict[str, tuple[str, ...]]] = SignatureCache(limit)

    def named(self, folder: str) -> dict[str, tuple[str, ...]]:
        """Entry name in capitals → the paths of the entries so named (several on a case-sensitive
        file system), in the order ``os.scandir`` lists them. Raises OSError when ``folder`` is not
        a folder (through a link) or cannot be listed."""
        status = os.stat(folder)
        if not S_ISDIR(status.st_mode):
            raise NotADirectoryError(folder)
        return self._cache.get(folder, status, lambda: _listing(folder))

    def clear(self) -> None:
        """Forget every kept listing."""
        self._cache.clear()


def _listing(folder: str) -> dict[str, tuple[str, ...]]:
    listing: dict[str, list[str]] = {}
    with os.scandir(folder) as scan:
        for entry in scan:
            listing.setdefault(entry.name.upper(), []).append(entry.path)
    return {name: tuple(paths) for name, paths in listing.items()}
