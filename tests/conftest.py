"""Suite-wide set-up: tests never touch the user's real NC data directory."""

from __future__ import annotations

import faulthandler
import gc
import os
import tempfile
from pathlib import Path

# Headless commands read the user's NC data directory by default; point the default at a
# directory that does not exist so every test starts from fresh NC data, whatever the
# machine running the suite has set up. Subprocesses inherit the variable.
os.environ["NCK_DATA_DIR"] = str(Path(tempfile.gettempdir()) / f"nck-tests-no-data-{os.getpid()}")


import pytest  # noqa: E402
from hypothesis import settings  # noqa: E402

# Property tests draw the same examples on every machine: Hypothesis switches to a fixed seed
# by itself when it sees a CI environment variable, so a random seed here would test other
# programs than CI does (CI stalled twice on an example never drawn here). `make fuzz`
# explores with random seeds (``--hypothesis-profile=fuzz``).
settings.register_profile("suite", derandomize=True, database=None, deadline=None, print_blob=True)
settings.register_profile("fuzz", derandomize=False, database=None, deadline=None, print_blob=True)
settings.load_profile("suite")


@pytest.fixture(autouse=True)
def _run_in_a_temporary_directory(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Exports (programs, alarm log, trace CSV) go to the current directory: keep them out of the tree."""
    monkeypatch.chdir(tmp_path)


@pytest.fixture(autouse=True)
def _no_disk_flush(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> None:
    """Writes skip ``os.fsync`` except in the tests marked ``durability`` (tests/data/test_atomic.py).

    Every write of NC data is atomic: a temporary file, flushed to the disk with ``fsync``,
    then renamed over the target (``nck.atomic``). The rename is what a test can see; the
    flush only matters if the machine loses power, which no test can stage. On this VM a
    flush costs ~3 ms of waiting and every panel a test starts writes a fresh data
    directory (the sample programs, the retained data): 54 flushes, ~0.15 s, per start.
    """
    if request.node.get_closest_marker("durability") is None:
        monkeypatch.setattr(os, "fsync", lambda fd: None)


@pytest.fixture(autouse=True)
def _english_panel_texts():
    """Every test starts with the panel's texts in English and leaves them so (hmi.i18n)."""
    from hmi.i18n import set_language

    set_language("en")
    yield
    set_language("en")


# ------------------------------------------------------------------ hang watchdog
HANG_WATCHDOG_S = float(os.environ.get("NCK_TEST_HANG_S", "420"))
"""A test still running after this many seconds has hung past pytest-timeout's reach.

pytest-timeout (``timeout = 300`` in pyproject.toml) interrupts a test with a signal,
which Python handles only when the main thread runs Python code. A test blocked where
no signal handler can run (a C-level lock, a deadlock on the interpreter lock) would
stall the whole suite until CI's limit. This watchdog is faulthandler's C thread: it
writes every thread's stack to the terminal and ends the worker process, so the run
goes on (pytest-xdist reports the test as crashed and starts a new worker) and the log
shows where the test hung. Seen: a property test looping for ever — Hypothesis takes
pytest-timeout's exception for a failing example and goes on shrinking.
``NCK_TEST_HANG_S`` sets it (the watchdog's own test)."""

_watchdog_stream = None


def pytest_configure(config: pytest.Config) -> None:
    global _watchdog_stream
    _watchdog_stream = os.fdopen(os.dup(2), "w")  # the real stderr, not the per-test capture


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None):
    faulthandler.dump_traceback_later(HANG_WATCHDOG_S, exit=True, file=_watchdog_stream)
    try:
        yield
    finally:
        faulthandler.cancel_dump_traceback_later()


# ------------------------------------------------------------------ garbage collection
# Measured on two Pilot test files (24 tests, 2026-11-28): Python's cyclic garbage
# collector took 6.6 s of their 17.7 s CPU. Every App a test starts leaves some hundred
# thousand objects (strips with their caches, styles) that the collector walks again and
# again at its default thresholds (700, 10, 10): 4,361 collections. With the
# collection made once per 10,000 allocations and everything imported and collected by
# then kept out of the walks (``gc.freeze``), the same files took 2.7 s of GC and 14.3 s
# in all. Garbage is still collected; only less often. The panel makes its own setting
# when it starts (``hmi.app.freeze_startup_objects``).
gc.set_threshold(10_000, 10, 10)


def pytest_collection_finish(session: pytest.Session) -> None:
    """Keep the objects of the imports and the collected tests out of the collector's walks."""
    gc.collect()
    gc.freeze()
