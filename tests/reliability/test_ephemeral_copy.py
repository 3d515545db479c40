"""``--ephemeral``: a bounded copy of regular files that never outlives its process.

The copy follows no link (a link to ``/dev/zero`` would fill the temporary file
system, a FIFO would block the copy), stops at its size bound with a clear
message, and is removed on every way out: normal end, a failed start, SIGTERM,
and — for a process killed outright — by the next copy made.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

import nck.paths
from hmi.app import main as hmi_main
from nck.cli import main as nck_main
from nck.paths import EPHEMERAL_PREFIX, EphemeralDataDir
from nck.persistence import Session
from tests.reliability.test_terminal_loss import start_hmi, terminals  # noqa: F401 (a fixture)

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def private_temp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A temporary-files folder of this test alone (copies are looked for there)."""
    folder = tmp_path / "temp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


def _copies(folder: Path) -> list[str]:
    return [p.name for p in folder.iterdir() if p.name.startswith(EPHEMERAL_PREFIX)]


def _data_dir(tmp_path: Path) -> Path:
    data_dir = tmp_path / "data"
    Session.open(data_dir, install_samples=False).files.save("MPF/PART.MPF", "G0 X1\nM30\n")
    return data_dir


def test_the_copy_holds_regular_files_and_follows_no_link(tmp_path: Path, private_temp: Path) -> None:
    data_dir = _data_dir(tmp_path)
    victim = tmp_path / "victim.txt"
    victim.write_text("outside\n")
    mpf = data_dir / "nc" / "MPF"
    (mpf / "ZERO.MPF").symlink_to("/dev/zero")
    (mpf / "VICTIM.MPF").symlink_to(victim)
    (data_dir / "nc" / "OUTSIDE").symlink_to(tmp_path, target_is_directory=True)
    os.mkfifo(mpf / "PIPE.MPF")
    with EphemeralDataDir(data_dir) as copy:
        assert sorted(p.name for p in (copy / "nc" / "MPF").iterdir()) == ["PART.MPF"]
        assert not os.path.lexists(copy / "nc" / "OUTSIDE")
        assert (copy / "retained" / "r_parameters.json").read_bytes() == \
            (data_dir / "retained" / "r_parameters.json").read_bytes()
    assert _copies(private_temp) == []


def test_a_copy_past_its_bound_is_refused_and_removed(tmp_path: Path, private_temp: Path,
                                                      monkeypatch: pytest.MonkeyPatch, capsys) -> None:
    data_dir = _data_dir(tmp_path)
    (data_dir / "nc" / "MPF" / "BIG.MPF").write_bytes(b"G0\n" * 2000)
    monkeypatch.setattr(nck.paths, "EPHEMERAL_LIMIT_BYTES", 4000)
    with pytest.raises(OSError, match="larger than"):
        EphemeralDataDir(data_dir)
    assert _copies(private_temp) == []
    program = tmp_path / "P.MPF"
    program.write_text("M30\n")
    assert nck_main(["run", "--ephemeral", "--data-dir", str(data_dir), str(program)]) == 2
    assert hmi_main(["--ephemeral", "--data-dir", str(data_dir)]) == 2
    messages = capsys.readouterr().err
    assert messages.count("larger than") == 2 and "Traceback" not in messages
    assert _copies(private_temp) == []


def test_a_failed_start_leaves_no_copy(tmp_path: Path, private_temp: Path, capsys) -> None:
    data_dir = _data_dir(tmp_path)
    assert hmi_main(["--ephemeral", "--data-dir", str(data_dir), "--program", "NOTHERE.MPF"]) == 2
    program = tmp_path / "P.MPF"
    program.write_text("M30\n")
    assert nck_main(["run", "--ephemeral", "--data-dir", str(data_dir), "--set", "R1", str(program)]) == 2
    assert "Traceback" not in capsys.readouterr().err
    assert _copies(private_temp) == []


FOREGROUND_NCK = (
    "import runpy, signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
    "sys.argv[0] = 'nck'; runpy.run_module('nck', run_name='__main__')"
)
"""``nck`` as a shell runs it in the foreground, where Ctrl+C is not ignored. A test runner started
in the background by a non-interactive shell ignores SIGINT and its children inherit that: Python
then installs no Ctrl+C handler, and the endless run would never see the signal (found in a CI-like
run; Unix tools rightly keep an inherited 'ignore')."""


@pytest.mark.parametrize("ending", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "Ctrl+C"])
def test_sigterm_or_ctrl_c_removes_the_copy(tmp_path: Path, private_temp: Path, ending: int) -> None:
    """Ctrl+C (SIGINT) ends like SIGTERM: the copy goes, exit status 128 + signal, no traceback."""
    data_dir = _data_dir(tmp_path)
    (data_dir / "retained" / "mda.json").write_text("damaged")  # 4060 on stderr: the copy is made
    program = tmp_path / "LOOP.MPF"
    program.write_text("LOOP\nR1=R1+1\nENDLOOP\nM30\n")
    # PYTHONFAULTHANDLER: should the signal not end the run, SIGABRT makes the child print where it was
    env = dict(os.environ, TMPDIR=str(private_temp), PYTHONFAULTHANDLER="1")
    proc = subprocess.Popen([sys.executable, "-c", FOREGROUND_NCK, "run", "--ephemeral", "--data-dir",
                             str(data_dir), str(program)], cwd=ROOT, env=env, text=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    assert proc.stderr is not None
    assert "ALARM 4060" in proc.stderr.readline()
    assert len(_copies(private_temp)) == 1
    proc.send_signal(ending)
    try:
        _, rest = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGABRT)
        _, rest = proc.communicate(timeout=30)
        pytest.fail(f"the run went on after signal {ending}; where it was:\n{rest[-4000:]}")
    # a shell shows 128 + signal for both: the exit code nck returns, or (Ctrl+C caught by the
    # interpreter while it was already ending) the end by the signal itself
    assert proc.returncode in (128 + ending, -ending) and "Traceback" not in rest, rest[-2000:]
    assert _copies(private_temp) == []
    assert (data_dir / "retained" / "mda.json").read_text() == "damaged"  # the original untouched


def test_copies_of_killed_processes_are_removed_by_the_next_copy(tmp_path: Path, private_temp: Path) -> None:
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True,
                           text=True, check=True)
    abandoned = private_temp / f"{EPHEMERAL_PREFIX}{ended.stdout.strip()}-abc"
    living = private_temp / f"{EPHEMERAL_PREFIX}{os.getpid()}-def"
    foreign = private_temp / f"{EPHEMERAL_PREFIX}x"  # not named by this program: left alone
    for folder in (abandoned, living, foreign):
        (folder / "ncdata").mkdir(parents=True)
    with EphemeralDataDir(_data_dir(tmp_path)):
        assert not abandoned.exists() and living.exists() and foreign.exists()


def test_a_data_directory_the_operator_names_through_a_link_is_copied(tmp_path: Path) -> None:
    """``NCK_DATA_DIR`` may name the data directory through a link (the operator's choice);
    only entries below it are never followed."""
    from nck.paths import EphemeralDataDir

    real = tmp_path / "real"
    (real / "retained").mkdir(parents=True)
    (real / "retained" / "tools.json").write_text("{}")
    (tmp_path / "link").symlink_to(real, target_is_directory=True)
    with EphemeralDataDir(tmp_path / "link") as copy:
        assert (copy / "retained" / "tools.json").read_text() == "{}"


@pytest.mark.skipif(not hasattr(os, "pidfd_open"), reason="needs Linux pidfd_open")
def test_sigterm_to_the_hmi_removes_its_copy(tmp_path: Path, private_temp: Path, monkeypatch: pytest.MonkeyPatch,
                                             terminals) -> None:
    """The HMI's door: ``hmi --ephemeral`` told to end (a service manager, the classroom server)."""
    data_dir = _data_dir(tmp_path)
    monkeypatch.setenv("TMPDIR", str(private_temp))
    hmi = start_hmi(terminals, data_dir, "--ephemeral")
    assert len(_copies(private_temp)) == 1
    os.kill(hmi.pid, signal.SIGTERM)
    status = hmi.wait_exit()
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 128 + signal.SIGTERM
    assert b"Traceback" not in hmi.output
    assert _copies(private_temp) == []
