"""A panel on a kernel without an NC file system (the test doubles of the Pilot tests) gets a
temporary one; it must not outlive the app or the process (hundreds of ``nc-data-*`` folders
were left in the temporary directory by the test suite)."""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

from hmi.exercise_run import ExerciseRun
from hmi.program_files import ProgramFiles
from nck.exercise import load_exercises

SCRIPT = """
from types import SimpleNamespace
from hmi.exercise_run import ExerciseRun
from hmi.program_files import ProgramFiles
from nck.exercise import load_exercises
files = ProgramFiles.of_app(SimpleNamespace())
files.fs.save("MPF/AB.MPF", "M30\\n")
print(files.fs.root)
"""


def test_the_temporary_file_system_is_gone_when_the_process_ends(tmp_path: Path) -> None:
    env = {**os.environ, "TMPDIR": str(tmp_path)}
    done = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True, check=True)
    root = Path(done.stdout.strip())
    assert root.parent.parent == tmp_path and root.parent.name.startswith("nc-data-")
    assert not root.exists() and list(tmp_path.iterdir()) == []


def test_the_temporary_file_system_goes_when_the_app_lets_go() -> None:
    app = SimpleNamespace()
    files = ProgramFiles.of_app(app)
    files.fs.save("MPF/AB.MPF", "M30\n")
    assert ProgramFiles.of_app(app) is files and files.fs.root.is_dir()
    ProgramFiles.forget(app)  # an exercise started: the screens look for the new file system
    assert not files.fs.root.parent.exists()


def test_an_exercise_dropped_without_its_end_leaves_no_private_directory(tmp_path: Path) -> None:
    exercise = {e.exercise_id: e for e in load_exercises()}["01_power_on_reference"]
    run = ExerciseRun(exercise, tmp_path / "reports")
    run.open_session()
    root = run.private_root
    assert (root / "data").is_dir()
    run.session.quit()  # the data directory given free, as an app ending would
    del run
    gc.collect()
    assert not root.exists()
