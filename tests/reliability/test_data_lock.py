"""Concurrent use: two HMI processes on one NC data directory — a lock and a clear message."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from hmi.app import main as hmi_main
from hmi.startup import build_session
from nck.datalock import DataDirInUse, lock_data_dir
from nck.persistence import Session

ROOT = Path(__file__).resolve().parents[2]

HOLDER = """
import sys
from hmi.startup import build_session
holder = build_session(data_dir=sys.argv[1])
print("ready", flush=True)
sys.stdin.readline()
holder.quit()
print("quit", flush=True)
"""


def _start_holder(data_dir: Path) -> subprocess.Popen[str]:
    proc = subprocess.Popen([sys.executable, "-c", HOLDER, str(data_dir)], cwd=ROOT, text=True,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout is not None
    assert proc.stdout.readline().strip() == "ready", proc.stderr.read() if proc.stderr else ""
    return proc


def test_second_lock_in_the_same_directory_is_refused_with_the_holder(tmp_path: Path) -> None:
    first = lock_data_dir(tmp_path)
    with pytest.raises(DataDirInUse) as refused:
        lock_data_dir(tmp_path)
    assert str(tmp_path) in str(refused.value) and str(os.getpid()) in str(refused.value)
    first.release()
    first.release()  # twice is harmless
    with lock_data_dir(tmp_path) as again:
        assert again.held
    assert not again.held


def test_a_second_hmi_process_gets_a_clear_message_and_changes_nothing(tmp_path: Path, capsys) -> None:
    data_dir = tmp_path / "data"
    holder = _start_holder(data_dir)
    try:
        before = {p: p.read_bytes() for p in data_dir.rglob("*") if p.is_file() and p.name != ".lock"}
        with pytest.raises(DataDirInUse):
            build_session(data_dir=str(data_dir))
        assert hmi_main(["--data-dir", str(data_dir)]) == 2
        message = capsys.readouterr().err
        assert "in use by process" in message and str(holder.pid) in message and str(data_dir) in message
        assert "Traceback" not in message
        after = {p: p.read_bytes() for p in data_dir.rglob("*") if p.is_file() and p.name != ".lock"}
        assert after == before
    finally:
        assert holder.stdin is not None
        holder.stdin.write("\n")
        holder.stdin.flush()
        holder.wait(timeout=30)
    assert holder.returncode == 0
    session = build_session(data_dir=str(data_dir))  # free again after the first one quit
    session.quit()


def test_a_killed_hmi_leaves_no_stale_lock(tmp_path: Path) -> None:
    holder = _start_holder(tmp_path)
    with pytest.raises(DataDirInUse):
        lock_data_dir(tmp_path)
    holder.send_signal(signal.SIGKILL)
    holder.wait(timeout=30)
    with lock_data_dir(tmp_path) as lock:
        assert lock.held


def test_ephemeral_copy_needs_no_lock(tmp_path: Path) -> None:
    original = Session.open(tmp_path)
    original.ncdata.r[1] = 11.0
    original.save()
    with lock_data_dir(tmp_path) as lock:
        session = build_session(data_dir=str(tmp_path), ephemeral=True)
        copy = session.session.data_dir
        assert copy != tmp_path and not copy.is_relative_to(tmp_path)
        assert session.session.ncdata.r[1] == 11.0  # the copy holds the original's data
        session.session.ncdata.r[1] = 99.0
        assert getattr(session, "data_lock", None) is None  # the copy is not locked …
        session.quit()
        assert lock.held  # … and the original's lock is left alone
    assert not copy.exists()
    assert Session.open(tmp_path).ncdata.r[1] == 11.0  # nothing written back


def test_a_quit_session_frees_the_directory(tmp_path: Path) -> None:
    first = build_session(data_dir=str(tmp_path))
    with pytest.raises(DataDirInUse):
        build_session(data_dir=str(tmp_path))
    first.quit()
    second = build_session(data_dir=str(tmp_path))
    second.quit()


def test_nck_md_refuses_a_directory_an_hmi_works_on(tmp_path: Path) -> None:
    import io

    from nck.cli_md import run as md_run

    holder = _start_holder(tmp_path)
    try:
        err = io.StringIO()
        code = md_run(["--data-dir", str(tmp_path), "--password", "EVENING", "MD32000[X]=5000"],
                      io.StringIO(), err)
        assert code == 2 and "in use by process" in err.getvalue()
    finally:
        holder.send_signal(signal.SIGKILL)
        holder.wait(timeout=30)
    out = io.StringIO()
    assert md_run(["--data-dir", str(tmp_path), "MD32000[X]"], out, io.StringIO()) == 0
    assert "30000" in out.getvalue()


def test_nck_run_with_the_data_dir_of_a_running_hmi_is_refused(tmp_path: Path, capsys) -> None:
    from nck.cli import main as nck_main

    program = tmp_path / "P.MPF"
    program.write_text("R1=1\nM30\n")
    data_dir = tmp_path / "data"
    holder = _start_holder(data_dir)
    try:
        assert nck_main(["run", "--data-dir", str(data_dir), str(program)]) == 2
        assert "in use by process" in capsys.readouterr().err
        assert nck_main(["run", "--data-dir", str(data_dir), "--ephemeral", str(program)]) == 0
    finally:
        holder.send_signal(signal.SIGKILL)
        holder.wait(timeout=30)
    assert nck_main(["run", "--data-dir", str(data_dir), str(program)]) == 0
    with lock_data_dir(data_dir):  # and nck released it again
        pass
