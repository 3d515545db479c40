"""One composition root: ``build_nck`` wires the kernel of the HMI, the command line and
headless runs (issue 21), and nothing else in the product builds a kernel its own way."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import nck.build
import nck.headless
from nck import commands as cmd
from nck.access import AccessControl, AccessState
from nck.build import build_nck, build_session_kernel
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from nck.persistence import Session

ROOT = Path(__file__).resolve().parents[2]


def test_build_nck_wires_machine_data_programs_and_access() -> None:
    machine, data = load_machine("lathe2"), NcData()
    access = AccessControl(AccessState(keyswitch_position=3))  # keyswitch 3: level 4
    nck = build_nck(machine, data, MemorySource({"PART1.MPF": "G0 X10\nM30\n"}), access=access)
    assert nck.machine is machine and nck.data is data and nck.access is access
    status = nck.status()
    assert status.machine_name == machine.name and status.access_level == access.level == 4
    assert isinstance(nck.submit(cmd.SelectMode("AUTO")), cmd.Accepted)
    assert isinstance(nck.submit(cmd.SelectProgram("PART1.MPF")), cmd.Accepted)
    assert isinstance(nck.submit(cmd.SelectProgram("OTHER.MPF")), cmd.Rejected)


@pytest.mark.parametrize("dialect", ["siemens", "iso-m"])
def test_build_nck_interprets_the_dialect_it_is_given(dialect: str) -> None:
    created = []
    nck = build_nck(load_machine(), NcData(), MemorySource(), dialect=dialect, referenced=True,
                    on_interpreter=created.append)
    for command in (cmd.SelectMode("MDA"), cmd.SetMdaProgram("G0 X1"), cmd.CycleStart()):
        assert isinstance(nck.submit(command), cmd.Accepted)
    assert created and {interp.dialect.name for interp in created} == {dialect}


def test_headless_runs_build_their_kernel_with_build_nck(monkeypatch) -> None:
    built = []

    def spy(*args, **kwargs):
        kernel = build_nck(*args, **kwargs)
        built.append(kwargs)
        return kernel

    monkeypatch.setattr(nck.build, "build_nck", spy)  # headless imports it when it runs (start-up)
    result = nck.headless.run_program(load_machine(), MemorySource(), NcData(), "P.MPF",
                                      text="G0 X5\nM30\n", timeout_s=5.0, dialect="siemens")
    assert result.status == "ended" and len(built) == 1 and built[0]["referenced"] is True


def test_the_hmi_kernel_on_a_data_directory_is_built_with_build_nck(monkeypatch, tmp_path: Path) -> None:
    built = []

    def spy(*args, **kwargs):
        built.append(kwargs)
        return build_nck(*args, **kwargs)

    monkeypatch.setattr(nck.build, "build_nck", spy)
    session = Session.open(tmp_path, load_machine(), install_samples=False)
    kernel = build_session_kernel(session).nck
    assert len(built) == 1 and built[0]["data"] is session.ncdata and built[0]["access"] is session.access
    assert kernel.data is session.ncdata


def test_no_client_constructs_the_kernel_itself() -> None:
    # The product (nck/, hmi/, screens/, bench/) builds kernels only in nck/build.py; the
    # unit tests may build a bare Nck(...).
    found = []
    for package in ("nck", "hmi", "screens", "bench"):
        for path in sorted((ROOT / package).rglob("*.py")):
            if path == ROOT / "nck" / "build.py":
                continue
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
                if re.search(r"(?<![\w.])Nck\(", line) and not line.lstrip().startswith(("#", "class ")):
                    found.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()}")
    assert found == []
