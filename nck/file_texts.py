"""Program texts (and folder listings) kept by file identity, read again only when the file changed.

A subprogram or cycle called 2,000 times (a hole pattern with a modal ``CYCLE81``) was read,
decoded and hashed on every call. :class:`FileTexts` keeps each text with the signature of the
file it was read from — device, inode, size, modification and status-change times, as one
``stat`` reports them — and returns the kept text while a new ``stat`` of the same path gives the
same signature. Writing a file in place changes its times (and usually its size); replacing it
(an atomic save) changes its inode; so the next call reads the new text.

The limit is the file system's time stamp granularity: a rewrite of the same size that lands in
the same time-stamp tick as the read before it (a few milliseconds at most on Linux) keeps
the old text until the file changes again — a gap editors and ``nck.storage`` saves do not hit.
:class:`FolderNames` keeps a folder's entry names the same way (a folder's times change when an
entry is added, removed or renamed), with the same limit for two changes within one tick.
"""

from __future__ import annotations

import os
from stat import S_ISDIR
from typing import Callable

TEXTS_KEPT = 64
"""Texts kept per cache; the oldest half goes when it is full (a program calls few names)."""

Signature = tuple[int, int, int, int, int]


def signature(stat: os.stat_result) -> Signature:
    """What identifies one version of a file: device, inode, size, mtime and ctime (ns)."""
    return (stat.st_dev, stat.st_ino, stat.st_size, stat.st_mtime_ns, stat.st_ctime_ns)


class FileTexts:
    """Texts by path, each valid while its file's :func:`signature` stays the same."""

    def __init__(self, limit: int = TEXTS_KEPT) -> None:
        self.limit = limit
        self._texts: dict[str, tuple[Signature, str]] = {}

    def text(self, path: str, stat: os.stat_result, read: Callable[[], str]) -> str:
        """The text of ``path`` whose ``stat`` the caller took just before: the kept one when the
        file is unchanged, else ``read()`` (which may raise; nothing is kept then)."""
        key = signature(stat)
        kept = self._texts.get(path)
        if kept is not None and kept[0] == key:
            return kept[1]
        text = read()
        if len(self._texts) >= self.limit:
            for old in list(self._texts)[: self.limit // 2]:
                del self._texts[old]
        self._texts[path] = (key, text)
        return text


class FolderNames:
    """The entries of folders by name in capitals (paths in listing order), each listing kept while
    the folder's :func:`signature` stays the same."""

    def __init__(self, limit: int = TEXTS_KEPT) -> None:
        self.limit = limit
        self._listings: dict[str, tuple[Signature, dict[str, tuple[str, ...]]]] = {}

    def named(self, folder: str) -> dict[str, tuple[str, ...]]:
        """Entry name in capitals → the paths of the entries so named (several on a case-sensitive
        file system), in the order ``os.scandir`` lists them. Raises OSError when ``folder`` is not
        a folder (through a link) or cannot be listed."""
        status = os.stat(folder)
        if not S_ISDIR(status.st_mode):
            raise NotADirectoryError(folder)
        key = signature(status)
        kept = self._listings.get(folder)
        if kept is not None and kept[0] == key:
            return kept[1]
        listing: dict[str, list[str]] = {}
        with os.scandir(folder) as scan:
            for entry in scan:
                listing.setdefault(entry.name.upper(), []).append(entry.path)
        names = {name: tuple(paths) for name, paths in listing.items()}
        if len(self._listings) >= self.limit:
            self._listings.clear()
        self._listings[folder] = (key, names)
        return names
