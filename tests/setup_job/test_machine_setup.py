"""Issue 22: what is clamped on the machine (blank, reference block, hidden switch) — kept
in the retained data, read and written through the façade at protection level 2 (service)."""

from __future__ import annotations

from pathlib import Path

from nck.access import AccessControl, AccessState
from nck.commands import (Accepted, Box, Cylinder, EnterPassword, MachineSetup, Rejected, SetKeyswitch,
                          WriteMachineSetup)
from nck.kernel import Nck
from nck.machine import load_machine
from nck.persistence import Session
from nck.queries import MachineSetupData, answer
from nck.workpiece import default_machine_setup, setup_from_plain, setup_to_plain

CUSTOM = MachineSetup(blank=Cylinder((10.0, 20.0, -250.0), 80.0, 40.0),
                      reference=Box((100.0, 0.0, -250.0), (120.0, 20.0, -180.0)), hidden=True)


def open_session(path: Path, machine_name: str = "mill3") -> Session:
    return Session.open(path, load_machine(machine_name), install_samples=False)


def test_fresh_data_directory_has_the_default_blank_of_the_mill(tmp_path: Path) -> None:
    setup = open_session(tmp_path).ncdata.machine_setup
    assert setup == default_machine_setup("mill")
    assert isinstance(setup.blank, Box) and setup.blank.top_z_mcs == -220.0
    assert setup.reference is not None and setup.reference.top_z_mcs == -200.0
    assert setup.hidden is False


def test_lathe_starts_with_a_bar_on_the_turning_axis(tmp_path: Path) -> None:
    blank = open_session(tmp_path, "lathe2").ncdata.machine_setup.blank
    assert isinstance(blank, Cylinder) and blank.base_mcs[:2] == (0.0, 0.0)


def test_setup_survives_a_restart_and_an_instructor_removal_too(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.ncdata.machine_setup = CUSTOM
    session.save()
    assert open_session(tmp_path).ncdata.machine_setup == CUSTOM
    session = open_session(tmp_path)
    session.ncdata.machine_setup = MachineSetup()  # nothing clamped: not replaced by the default
    session.save()
    assert open_session(tmp_path).ncdata.machine_setup == MachineSetup()


def test_corrupted_setup_file_is_restored_from_its_backup_with_4065(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.ncdata.machine_setup = CUSTOM
    session.save()
    session.ncdata.machine_setup = MachineSetup(blank=CUSTOM.blank)
    session.save()  # the backup now holds CUSTOM
    (tmp_path / "retained" / "machine_setup.json").write_text('{"format": "sinumerik-trainer/retained", "sec')
    restarted = open_session(tmp_path)
    assert [(a.number, a.params[0]) for a in restarted.startup_alarms] == [(4065, "machine_setup.json")]
    assert restarted.ncdata.machine_setup == CUSTOM


def test_plain_form_round_trips_and_refuses_nonsense() -> None:
    assert setup_from_plain(setup_to_plain(CUSTOM)) == CUSTOM
    for bad in ({"blank": {"shape": "box", "low_mcs": [0, 0, 0], "high_mcs": [1, -1, 1]}},
                {"blank": {"shape": "cylinder", "base_mcs": [0, 0, 0], "diameter_mm": 0, "length_mm": 5}},
                {"blank": {"shape": "cone"}}, {"reference": setup_to_plain(CUSTOM)["blank"]},
                {"hidden": "yes"}, {"blank": {"shape": "box", "low_mcs": [0, 0], "high_mcs": [1, 1, 1]}}):
        try:
            setup_from_plain(bad)
        except (ValueError, KeyError):
            continue
        raise AssertionError(f"accepted {bad}")


def test_facade_reads_and_writes_the_setup_at_level_2() -> None:
    data_kernel = Nck(access=AccessControl(AccessState(keyswitch_position=0)))
    assert answer(data_kernel, MachineSetupData()) == MachineSetup()
    refused = data_kernel.submit(WriteMachineSetup(CUSTOM))  # keyswitch 0 = level 7
    assert isinstance(refused, Rejected)
    assert answer(data_kernel, MachineSetupData()) == MachineSetup()
    assert data_kernel.submit(SetKeyswitch(3)) == Accepted()  # keyswitch 3 = level 4: still too low
    assert isinstance(data_kernel.submit(WriteMachineSetup(CUSTOM)), Rejected)
    assert data_kernel.submit(EnterPassword("CUSTOMER")) == Accepted()  # level 3 (002 L1439-1449)
    assert isinstance(data_kernel.submit(WriteMachineSetup(CUSTOM)), Rejected)  # a trainee may know it
    assert data_kernel.submit(EnterPassword("EVENING")) == Accepted()  # level 2, service
    assert data_kernel.submit(WriteMachineSetup(CUSTOM)) == Accepted()
    assert answer(data_kernel, MachineSetupData()) == CUSTOM
    assert any("set-up" in entry.text for entry in data_kernel.logbook)
