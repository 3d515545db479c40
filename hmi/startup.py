"""Building the kernel the HMI runs on: machine, NC data directory, NC file system, samples."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from nck import commands as cmd
from nck.commands import Rejected


def build_nck(machine: str | None = None, data_dir: str | None = None, ephemeral: bool = False,
              program: str | None = None) -> tuple[Any, Callable[[], None] | None]:
    """Build the kernel on the NC data directory; return it and the function run on quit.

    The NC file system (``nck.storage``) lives in ``<data dir>/nc``; the training
    programs of ``data/programs`` are installed into a fresh directory. With
    ``ephemeral`` the kernel works on a temporary copy that is deleted on quit.
    ``program`` (a local file, imported into MPF, or a program name) is selected
    at start; the HMI still starts in JOG (axes must be referenced first).
    """
    from nck.kernel import Nck
    from nck.machine import load_machine
    from nck.paths import open_data_dir
    from nck.resources import data_path
    from nck.storage import NcFileSystem

    config = load_machine(machine)
    root, copy = open_data_dir(data_dir, ephemeral)
    files = NcFileSystem(root / "nc")
    files.install_samples(data_path("programs"))
    nck = Nck(machine=config, programs=files)
    files.in_use_check = lambda: [p for p in [nck.status().channel.selected_program] if p]
    if program:
        name = program
        local = Path(program)
        if local.is_file():
            name = files.import_file(local, overwrite=True).name
        result = nck.submit(cmd.SelectProgram(name))
        if isinstance(result, Rejected):
            raise ValueError(f"program {program}: {result.reason}")

    def on_quit() -> None:
        saver = getattr(nck, "save", None)
        if callable(saver):
            saver()
        if copy is not None:
            copy.cleanup()

    return nck, on_quit
