"""The one place that finds and reads the ``data/`` tables.

In a source checkout (editable install) the tables are read from ``data/`` at
the repository root; in a wheel they are packaged as ``nck/_data``.
"""

from __future__ import annotations

import functools
import marshal
import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any


@functools.cache
def data_root() -> Path:
    """Return the directory that holds the ``data/`` tables."""
    here = Path(__file__).resolve().parent
    for candidate in (here.parent / "data", here / "_data"):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError("the data/ tables of the product are missing")


def data_path(*parts: str) -> Path:
    """Return the path of a file or folder below ``data/``."""
    return data_root().joinpath(*parts)


CACHE_FOLDER = "__pycache__"


def read_table(path: Path) -> dict[str, Any]:
    """Parse a TOML file of the product's tables, through a parsed copy beside it.

    The parsed table is kept as ``__pycache__/<name>.marshal`` next to the
    file, stamped with the file's size and modification time (as Python does
    for its bytecode); a changed file is parsed again. Parsing every table at
    every start cost a command like ``nck run`` about 30 ms. Where the folder
    cannot be written (an installed product), the file is simply parsed.
    Raises OSError and ``tomllib.TOMLDecodeError`` like ``tomllib.load``.
    """
    stat = path.stat()
    stamp = (stat.st_mtime_ns, stat.st_size)
    cache = path.parent / CACHE_FOLDER / f"{path.name}.marshal"
    try:
        cached_stamp, table = marshal.loads(cache.read_bytes())
        if tuple(cached_stamp) == stamp and isinstance(table, dict):
            return table
    except (OSError, ValueError, EOFError, TypeError):
        pass  # no parsed copy yet, or an unreadable one: parse the file
    with path.open("rb") as handle:
        table = tomllib.load(handle)
    try:
        blob = marshal.dumps((stamp, table))
        cache.parent.mkdir(exist_ok=True)
        partial = cache.with_name(f"{cache.name}.{os.getpid()}.tmp")
        partial.write_bytes(blob)
        os.replace(partial, cache)  # atomic: a reader sees the old copy or the new one
    except (OSError, ValueError):
        pass  # read-only folder, or values marshal cannot keep (dates): parse next time
    return table


@functools.cache
def load_toml(*parts: str) -> dict[str, Any]:
    """Read one TOML table below ``data/`` (cached; treat the result as read-only)."""
    return read_table(data_path(*parts))


@dataclass(frozen=True, slots=True)
class AlarmDefinition:
    """One entry of the alarm catalogue (``data/alarms/*.toml``).

    Attributes:
        number: the SINUMERIK alarm number.
        text: the alarm text with ``%1`` … placeholders.
        category: source of the alarm, e.g. ``program``, ``channel``, ``axis``, ``nck``.
        clear: clear criterion: ``power_on``, ``reset``, ``cancel``, ``nc_start`` or ``self``.
        reactions: reactions of the NCK, e.g. ``nc_start_disable``, ``interpreter_stop``,
            ``feed_stop``, ``braking``, ``emergency_stop``.
        explanation: the alarm help: what happened and its typical causes.
        remedy: the alarm help: what the operator does about it (how it is cleared
            follows from ``clear``).
        help_source: the manual lines the help's facts come from (``"002 L1897"``),
            empty where the text is the trainer's own.
    """

    number: int
    text: str
    category: str
    clear: str
    reactions: tuple[str, ...]
    explanation: str = ""
    remedy: str = ""
    help_source: str = ""

    def with_channel(self, params: tuple[str, ...], channel: str, block: str) -> tuple[str, ...]:
        """``params`` with the channel (and block) in front when the text starts with them."""
        prefix: list[str] = []
        if "Channel %1" in self.text or "channel %1" in self.text:
            prefix.append(channel)
            if "block %2" in self.text or "Block %2" in self.text:
                prefix.append(block)
        return tuple(prefix) + params

    def format(self, params: tuple[str, ...] | list[str]) -> str:
        """Return the text with ``%1`` … replaced by ``params`` (missing ones left empty)."""
        out = self.text
        # Replace from the highest index down so that %1 does not eat %10.
        for index in range(9, 0, -1):
            value = params[index - 1] if index <= len(params) else ""
            out = out.replace(f"%{index}", str(value))
        return " ".join(out.split())


@functools.cache
def alarm_catalog() -> dict[int, AlarmDefinition]:
    """Return every alarm of ``data/alarms/*.toml`` by number.

    Each file holds ``[[alarm]]`` tables; a number defined twice is an error in
    the data and raises ``ValueError``.
    """
    catalog: dict[int, AlarmDefinition] = {}
    for path in sorted(data_path("alarms").glob("*.toml")):
        table = read_table(path)
        for entry in table.get("alarm", []):
            number = int(entry["number"])
            if number in catalog:
                raise ValueError(f"alarm {number} defined twice (second time in {path.name})")
            catalog[number] = AlarmDefinition(
                number=number,
                text=entry["text"],
                category=entry.get("category", "program"),
                clear=entry.get("clear", "reset"),
                reactions=tuple(entry.get("reactions", ())),
                explanation=entry.get("explanation", ""),
                remedy=entry.get("remedy", ""),
                help_source=entry.get("help_source", ""),
            )
    return catalog


def alarm_text(number: int, params: tuple[str, ...] | list[str] = ()) -> str:
    """Return the formatted text of an alarm, or a generic text for an unknown number."""
    definition = alarm_catalog().get(number)
    if definition is None:
        return f"Alarm {number} " + " ".join(str(p) for p in params)
    return definition.format(params)
