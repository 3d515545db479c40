"""The suite's hang watchdog (tests/conftest.py) ends a test that no signal can interrupt.

Seen in CI: a run stalled for 90 minutes although pytest-timeout was on. A test that
blocks SIGALRM stands for every hang where pytest-timeout's signal never runs.

The child run imports the panel while it collects and limits only the test functions to one
second: on a loaded machine the first import of the kernel took longer than that, and the
timeout then hit the fixture instead of the test. The watchdog's limit in the child is two
seconds: it counts from the start of a test's set-up, which here is only the suite's autouse
fixtures (a temporary directory, the panel's language, imported at collection), milliseconds
even on a loaded machine; every second more is a second the suite waits.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

HUNG_TEST = '''
import signal, time

import hmi.i18n  # the suite's autouse fixture imports the panel; at collection, not in the test


def test_hangs_where_no_signal_reaches():
    signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGALRM})
    time.sleep(60)

def test_runs_after_it():
    pass
'''


def test_a_test_past_the_signals_reach_is_ended_with_its_stack_and_the_run_goes_on(tmp_path: Path) -> None:
    (tmp_path / "test_hung.py").write_text(HUNG_TEST)
    env = dict(os.environ, NCK_TEST_HANG_S="2", PYTHONPATH=str(ROOT))
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-n", "1", "-p", "no:cacheprovider", "-p", "tests.conftest",
         "-o", "timeout=1", "-o", "timeout_func_only=true", "--rootdir", str(tmp_path), str(tmp_path / "test_hung.py")],
        cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    output = done.stdout + done.stderr
    assert "in test_hangs_where_no_signal_reaches" in output, output  # the hung test's stack
    assert "crashed while running 'test_hung.py::test_hangs_where_no_signal_reaches'" in output, output
    assert "1 failed, 1 passed" in output, output
