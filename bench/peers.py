"""Peer interpreters measured side by side with ``nck check``.

* LinuxCNC's stand-alone interpreter ``rs274 -g`` (Debian package
  ``linuxcnc-uspace``); installed with apt-get when absent and we are root,
  else skipped with a note.
* ``nc-gcode-interpreter`` from PyPI (Rust, Sinumerik-flavoured); installed
  into the running venv with pip when absent, else skipped with a note.
"""

from __future__ import annotations

import importlib.util
import os
import shutil
import subprocess
import sys
from pathlib import Path

RS274_PACKAGE = "linuxcnc-uspace"
NCGI_PACKAGE = "nc-gcode-interpreter"


def ensure_rs274() -> tuple[list[str] | None, str]:
    """The rs274 command prefix (``[path, "-g"]``) or None, and a note."""
    found = shutil.which("rs274")
    if found is None and os.geteuid() == 0 and shutil.which("apt-get"):
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        subprocess.run(["apt-get", "update", "-qq"], env=env, capture_output=True)
        subprocess.run(["apt-get", "install", "-y", "-qq", RS274_PACKAGE], env=env, capture_output=True)
        found = shutil.which("rs274")
    if found is None:
        return None, f"rs274 not available (install the Debian package {RS274_PACKAGE})"
    return [found, "-g"], "rs274 -g"


def ensure_ncgi() -> tuple[list[str] | None, str]:
    """A command that runs nc-gcode-interpreter on a file (appended), or None, and a note."""
    if importlib.util.find_spec("nc_gcode_interpreter") is None:
        subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", NCGI_PACKAGE],
                       capture_output=True)
        importlib.invalidate_caches()
    if importlib.util.find_spec("nc_gcode_interpreter") is None:
        return None, f"{NCGI_PACKAGE} not installable here"
    script = ("import sys, nc_gcode_interpreter as m\n"
              "with open(sys.argv[1]) as f:\n"
              "    frame, _ = m.nc_to_dataframe(f)\n"
              "print(frame.height)\n")
    return [sys.executable, "-c", script], f"{NCGI_PACKAGE} (nc_to_dataframe)"


def nck_check_command() -> list[str]:
    """``nck check`` run with this interpreter (file appended)."""
    return [sys.executable, "-m", "nck", "check"]


def nck_run_command(data_dir: Path) -> list[str]:
    """``nck run --json`` on a private data directory (file appended)."""
    return [sys.executable, "-m", "nck", "run", "--json", "--data-dir", str(data_dir)]
