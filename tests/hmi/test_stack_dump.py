"""SIGUSR1 writes every thread's stack into the data directory's HMI folder (diagnosing a hung HMI)."""

from __future__ import annotations

import faulthandler
import os
import threading
from pathlib import Path

import pytest

from hmi.stack_dump import STACK_DUMP_SIGNAL, STACK_FILE_NAME, register_stack_dump

pytestmark = pytest.mark.skipif(STACK_DUMP_SIGNAL is None, reason="no SIGUSR1 on this platform")


@pytest.fixture
def restore_sigusr1():
    yield
    faulthandler.unregister(STACK_DUMP_SIGNAL)


def test_the_signal_writes_every_threads_stack(tmp_path: Path, restore_sigusr1) -> None:
    waiting = threading.Event()
    helper = threading.Thread(target=waiting.wait, name="helper", daemon=True)
    helper.start()
    handle = register_stack_dump(tmp_path / "hmi")
    try:
        os.kill(os.getpid(), STACK_DUMP_SIGNAL)  # delivered to this thread before kill returns
    finally:
        waiting.set()
        os.close(handle)
    dump = (tmp_path / "hmi" / STACK_FILE_NAME).read_text()
    assert "test_the_signal_writes_every_threads_stack" in dump  # this thread
    assert dump.count("Thread 0x") + dump.count("Current thread 0x") >= 2  # the helper too


def test_the_file_is_never_written_through_a_link(tmp_path: Path, restore_sigusr1) -> None:
    outside = tmp_path / "outside.txt"
    outside.write_text("keep")
    (tmp_path / "hmi").mkdir()
    (tmp_path / "hmi" / STACK_FILE_NAME).symlink_to(outside)
    with pytest.raises(OSError, match="not a regular file"):
        register_stack_dump(tmp_path / "hmi")
    assert outside.read_text() == "keep"


def test_a_hard_link_of_another_file_is_neither_truncated_nor_written(tmp_path: Path, restore_sigusr1) -> None:
    """A hard link shares its content with the outside file: the start would truncate it."""
    outside = tmp_path / "outside.txt"
    outside.write_text("keep")
    (tmp_path / "hmi").mkdir()
    os.link(outside, tmp_path / "hmi" / STACK_FILE_NAME)
    with pytest.raises(OSError, match="hard link"):
        register_stack_dump(tmp_path / "hmi")
    assert outside.read_text() == "keep"


def test_a_fifo_in_its_place_is_refused_without_blocking(tmp_path: Path, restore_sigusr1) -> None:
    (tmp_path / "hmi").mkdir()
    os.mkfifo(tmp_path / "hmi" / STACK_FILE_NAME)
    with pytest.raises(OSError):  # ENXIO: no reader; never a wait for one
        register_stack_dump(tmp_path / "hmi")
