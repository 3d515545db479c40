"""The product's TOML tables are read through a parsed copy that never goes stale."""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from nck.resources import CACHE_FOLDER, data_root, read_table


def _write(path: Path, text: str) -> None:
    path.write_text(text, encoding="utf-8")


def test_every_product_table_reads_the_same_through_its_copy() -> None:
    for path in sorted(data_root().rglob("*.toml")):
        with path.open("rb") as handle:
            parsed = tomllib.load(handle)
        assert read_table(path) == parsed, path  # first read (may write the copy)
        assert read_table(path) == parsed, path  # through the copy


def test_a_changed_file_is_parsed_again(tmp_path: Path) -> None:
    table = tmp_path / "t.toml"
    _write(table, "a = 1\n")
    assert read_table(table) == {"a": 1}
    assert (tmp_path / CACHE_FOLDER / "t.toml.marshal").is_file()
    _write(table, "a = 22\n")  # other size
    assert read_table(table) == {"a": 22}
    _write(table, "a = 33\n")  # same size: the modification time tells
    stat = table.stat()
    os.utime(table, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))
    assert read_table(table) == {"a": 33}


def test_a_damaged_copy_is_ignored_and_replaced(tmp_path: Path) -> None:
    table = tmp_path / "t.toml"
    _write(table, "[x]\nb = 'text'\n")
    read_table(table)
    copy = tmp_path / CACHE_FOLDER / "t.toml.marshal"
    copy.write_bytes(b"\x00garbage")
    assert read_table(table) == {"x": {"b": "text"}}
    assert read_table(table) == {"x": {"b": "text"}}


def test_values_the_copy_cannot_keep_are_parsed_every_time(tmp_path: Path) -> None:
    table = tmp_path / "t.toml"
    _write(table, "when = 2026-11-22\n")
    assert str(read_table(table)["when"]) == "2026-11-22"
    assert not (tmp_path / CACHE_FOLDER / "t.toml.marshal").exists()
    assert not list((tmp_path / CACHE_FOLDER).glob("*.tmp"))


def test_a_read_only_folder_still_reads(tmp_path: Path) -> None:
    table = tmp_path / "t.toml"
    _write(table, "a = 1\n")
    (tmp_path / CACHE_FOLDER).write_text("not a folder")  # the copy cannot be written
    assert read_table(table) == {"a": 1}
    assert read_table(table) == {"a": 1}
