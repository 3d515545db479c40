"""Crashes: SIGKILL during program save, NC-data save, MD write and editor autosave.

A worker subprocess writes alternately two versions (A and B) of one thing as
fast as it can; the test kills it without warning at a varying moment, then
starts again on the data directory the way the HMI does. Each time the data
must be consistent — the old or the new version, never a torn mixture — and
no start-up alarm may report a damaged file (the writes are atomic, so the
backup is never needed). The editor journal still holds the unsaved text.
"""

from __future__ import annotations

import io
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from hmi.journal import EditorJournal
from nck.cli_md import run as md_run
from nck.persistence import Session
from nck.storage import NcFileSystem

ROOT = Path(__file__).resolve().parents[2]
PROGRAM_CHARS = 300_000

WORKER = r"""
import sys
from pathlib import Path
mode, root = sys.argv[1], Path(sys.argv[2])
i = 0
if mode == "program":
    from nck.storage import NcFileSystem
    fs = NcFileSystem(root / "nc")
    def step(i):
        fs.save("MPF/CRASH.MPF", "AB"[i % 2] * %(chars)d + "\nM30\n")
elif mode == "ncdata":
    from nck.persistence import Session
    session = Session.open(root, install_samples=False)
    def step(i):
        data = session.ncdata
        for n in range(40):
            data.r[n] = float(i)
        data.settable_frames["G54"].trans["X"] = float(i)
        session.save()
elif mode == "md":
    import io
    from nck.cli_md import run
    def step(i):
        value = 5000 + (i % 2) * 1000
        args = ["--data-dir", str(root), "--password", "EVENING", f"MD32000[X]={value}"]
        assert run(args, io.StringIO(), sys.stderr) == 0
elif mode == "journal":
    from hmi.journal import EditorJournal
    journal = EditorJournal(root / "journal")
    def step(i):
        journal.write("/MPF/PART1.MPF", "AB"[i % 2] * %(chars)d, base_sha256="0" * 64)
step(0)
step(1)
print("ready", flush=True)
i = 2
while True:
    step(i)
    i += 1
""".replace("%(chars)d", str(PROGRAM_CHARS))


def _kill_during_writes(mode: str, root: Path, round_no: int) -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-c", WORKER, mode, str(root)], cwd=ROOT, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert proc.stdout is not None
    line = proc.stdout.readline().strip()
    if line != "ready":
        proc.kill()
        pytest.fail(f"worker {mode} did not start: {proc.communicate()[1][-2000:]}")
    try:
        proc.wait(timeout=0.005 + 0.013 * (round_no % 7))
    except subprocess.TimeoutExpired:
        pass
    proc.send_signal(signal.SIGKILL)
    proc.wait()


def _md32000_x(root: Path) -> str:
    out = io.StringIO()
    assert md_run(["--data-dir", str(root), "MD32000[X]"], out, io.StringIO()) == 0
    return re.search(r"= (\S+)", out.getvalue()).group(1)


def _check(mode: str, root: Path) -> None:
    if mode == "program":
        text = NcFileSystem(root / "nc").read("MPF/CRASH.MPF")
        assert text in ("A" * PROGRAM_CHARS + "\nM30\n", "B" * PROGRAM_CHARS + "\nM30\n"), "torn program"
        return
    if mode == "journal":
        entries = EditorJournal(root / "journal").entries()
        assert [e.program for e in entries] == ["/MPF/PART1.MPF"]
        assert entries[0].text in ("A" * PROGRAM_CHARS, "B" * PROGRAM_CHARS), "torn journal entry"
        return
    session = Session.open(root, install_samples=False)
    assert [a.number for a in session.startup_alarms] == [], "a damaged file after the kill"
    if mode == "ncdata":
        data = session.ncdata
        values = {data.r[n] for n in range(40)}
        assert len(values) == 1, f"R parameters from two different saves: {sorted(values)}"
        assert data.settable_frames["G54"].trans["X"] >= 1.0
    else:
        assert _md32000_x(root) in ("5000", "6000")
    leftovers = [p.name for p in root.rglob("*") if ".tmp" in p.name]
    assert leftovers == [], leftovers


def _rounds(mode: str, root: Path, count: int) -> None:
    for round_no in range(count):
        _kill_during_writes(mode, root, round_no)
        _check(mode, root)


@pytest.mark.parametrize("mode", ["program", "ncdata", "md", "journal"])
def test_sigkill_during_writes_leaves_old_or_new_never_torn(mode: str, tmp_path: Path) -> None:
    _rounds(mode, tmp_path, 4)


@pytest.mark.fuzz
@pytest.mark.parametrize("mode", ["program", "ncdata", "md", "journal"])
def test_sigkill_during_writes_many_rounds(mode: str, tmp_path: Path) -> None:
    _rounds(mode, tmp_path, 40)
