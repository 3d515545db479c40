"""Retained NC data: survives restarts, recovers from damaged files, archives."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nck.access import AccessDenied, PasswordError
from nck.machine import load_machine
from nck.ncdata import ToolEdge
from nck.persistence import ArchiveError, SECTIONS, Session
from nck.resources import alarm_text
from nck.status import AlarmEntry


def open_session(path: Path, **kwargs) -> Session:
    return Session.open(path, install_samples=False, **kwargs)


def fill(session: Session) -> None:
    """Change one value in every retained section."""
    data = session.ncdata
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 80.5, 6: 5.0, 12: -0.02})
    data.settable_frame("G54").trans.update({"X": 100.0, "Y": -20.0})
    data.settable_frame("G55").rot["Z"] = 30.0
    data.base_frame.trans["Z"] = 1.5
    data.r[7] = 42.5
    data.gud["_COUNT"] = 3
    session.md.write("SD42100", 1234, level=4)
    session.md.write("SD43420[X]", 250, level=4)
    session.md.write("MD32000[X]", 5000, level=2)
    session.access.set_keyswitch(2)
    session.access.enter_password("CUSTOMER")
    data.part_counters["ACTUAL_PARTS"] = 17
    data.mda_program = "G0 X10\nM30\n"
    session.record_alarms([AlarmEntry(seq=1, number=10720, text="limit", category="axis",
                                      clear="reset", came_s=1.5, params=("X",))])


def check(session: Session) -> None:
    data = session.ncdata
    assert data.tools[(1, 1)].params == {1: 120.0, 3: 80.5, 6: 5.0, 12: -0.02}
    assert data.settable_frames["G54"].trans == {"X": 100.0, "Y": -20.0}
    assert data.settable_frames["G55"].rot == {"Z": 30.0}
    assert data.base_frame.trans == {"Z": 1.5}
    assert data.r[7] == 42.5 and len(data.r) == 100
    assert data.gud == {"_COUNT": 3}
    assert data.setting_data["SD42100"] == 1234.0
    assert data.setting_data["SD43420"]["X"] == 250.0
    assert session.md.active_value("MD32000[X]") == 5000.0
    assert session.access.state.keyswitch_position == 2
    assert session.access.level == 3
    assert data.part_counters == {"ACTUAL_PARTS": 17}
    assert data.mda_program == "G0 X10\nM30\n"
    assert session.alarm_log[-1]["number"] == 10720 and session.alarm_log[-1]["params"] == ["X"]


def test_fresh_directory(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    assert session.startup_alarms == []
    assert sorted(p.stem for p in (tmp_path / "retained").glob("*.json")) == sorted(SECTIONS)
    assert session.access.level == 7  # keyswitch 0
    assert session.access.enter_password("EVENING") == 2
    assert session.ncdata.setting_data["SD42100"] == 5000.0
    assert session.save() == ["access"]
    assert session.save() == []


def test_every_section_survives_a_restart(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    fill(session)
    session.save()
    check(open_session(tmp_path))  # new objects reading the same directory
    check(session.power_on())


def test_passwords_are_stored_only_as_salted_hashes(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.access.enter_password("SUNRISE")
    session.access.change_password(3, "SECRET7")
    session.save()
    session.export_archive(tmp_path / "retained" / "export.json")
    blobs = b"".join(p.read_bytes() for p in tmp_path.rglob("*") if p.is_file())
    for plain in (b"SUNRISE", b"EVENING", b"CUSTOMER", b"SECRET7"):
        assert plain not in blobs
    again = open_session(tmp_path)
    again.access.delete_password()
    assert again.access.enter_password("SECRET7") == 3
    with pytest.raises(PasswordError):
        again.access.enter_password("CUSTOMER")
    # a changed password gets a fresh salt (the factory passwords share one, data/access.toml)
    hashes = again.access.state.password_hashes
    assert hashes[3].salt_hex not in (hashes[1].salt_hex, hashes[2].salt_hex)


def test_password_survives_power_off_on(tmp_path: Path) -> None:
    """Digest 828d-3 rank 2 (level survives POWER OFF/ON)."""
    session = open_session(tmp_path)
    session.access.enter_password("EVENING")
    session = session.power_on()
    assert session.access.level == 2
    session.access.delete_password()
    assert session.power_on().access.level == 7


@pytest.mark.parametrize("damage", ["truncate", "garbage", "empty", "version", "section",
                                    "bad_content", "binary"])
def test_damaged_file_uses_backup_and_loses_nothing_else(tmp_path: Path, damage: str) -> None:
    session = open_session(tmp_path)
    fill(session)
    session.save()
    session.ncdata.tools[(2, 1)] = ToolEdge({1: 200.0, 3: 100.0})  # newer tools file
    session.save()
    tools = tmp_path / "retained" / "tools.json"
    original = tools.read_bytes()
    corrupt = {
        "truncate": original[: len(original) // 2],
        "garbage": b"#!@ not json at all",
        "empty": b"",
        "version": original.replace(b'"format_version": 1', b'"format_version": 99'),
        "section": original.replace(b'"section": "tools"', b'"section": "mda"'),
        "bad_content": original.replace(b'"t": 1', b'"t": "one"'),
        "binary": b"\xff\xfe\x00\x01" * 10,
    }[damage]
    assert corrupt != original
    tools.write_bytes(corrupt)

    restarted = open_session(tmp_path)
    assert [a.number for a in restarted.startup_alarms] == [4065]
    alarm = restarted.startup_alarms[0]
    assert alarm.params[0] == "tools.json" and alarm.params[2] == "tools.json.bad-1"
    assert "tools.json" in alarm_text(alarm.number, alarm.params)
    assert (tmp_path / "retained" / "tools.json.bad-1").read_bytes() == corrupt  # kept aside
    # the backup generation is used: tool 1 is back, the newest change (tool 2) is lost
    assert set(restarted.ncdata.tools) == {(1, 1)}
    # every other section is intact
    restarted.ncdata.tools[(2, 1)] = ToolEdge({1: 200.0, 3: 100.0})
    check(restarted)
    # the file is whole again: the next start raises nothing
    assert open_session(tmp_path).startup_alarms == []


def test_damaged_file_and_backup_give_standard_values_with_alarm(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    fill(session)
    session.save()
    session.ncdata.r[8] = 1.0
    session.save()
    r_file = tmp_path / "retained" / "r_parameters.json"
    r_file.write_text("{")
    (tmp_path / "retained" / "r_parameters.json.bak").write_text("[]")
    restarted = open_session(tmp_path)
    assert [a.number for a in restarted.startup_alarms] == [4060]
    assert restarted.startup_alarms[0].params[0] == "r_parameters.json"
    assert restarted.ncdata.r == [0.0] * 100
    assert (tmp_path / "retained" / "r_parameters.json.bad-1").read_text() == "{"
    assert (tmp_path / "retained" / "r_parameters.json.bak.bad-1").read_text() == "[]"
    assert restarted.ncdata.tools[(1, 1)].params[6] == 5.0  # the rest is intact
    assert open_session(tmp_path).startup_alarms == []  # standard values were written


def test_missing_file_with_backup_is_restored(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    fill(session)
    session.save()
    session.ncdata.mda_program = "M30\n"
    session.save()
    (tmp_path / "retained" / "mda.json").unlink()
    restarted = open_session(tmp_path)
    assert [(a.number, a.params[1]) for a in restarted.startup_alarms] == [(4065, "file missing")]
    assert restarted.ncdata.mda_program == "G0 X10\nM30\n"


def test_bad_files_are_numbered(tmp_path: Path) -> None:
    open_session(tmp_path).save()
    for n in (1, 2):
        (tmp_path / "retained" / "counters.json").write_text("x")
        assert open_session(tmp_path).startup_alarms[0].params[2] == f"counters.json.bad-{n}"


def test_power_on_data_take_effect_only_after_power_on(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.access.enter_password("EVENING")
    result = session.md.write("MD10070", 2, level=session.access.level)
    assert not result.active_now
    session.md.activate("reset")
    assert session.active_machine().md["MD10070"] == 4
    session.save()
    assert open_session(tmp_path).active_machine().md["MD10070"] == 2
    assert session.power_on().active_machine().md["MD10070"] == 2


def test_r_parameter_count_follows_md28050_after_power_on(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.md.write("MD28050", 200, level=1)
    session.ncdata.r[99] = 9.0
    assert len(session.ncdata.r) == 100
    session = session.power_on()
    assert len(session.ncdata.r) == 200 and session.ncdata.r[99] == 9.0


def test_md_changes_are_kept_per_machine(tmp_path: Path) -> None:
    mill = open_session(tmp_path)
    mill.md.write("MD32000[X]", 5000, level=0)
    mill.save()
    lathe = open_session(tmp_path, machine=load_machine("lathe2"))
    assert lathe.md.value("MD32000[X]") == load_machine("lathe2").md["MD32000"]["X"]
    lathe.save()
    assert open_session(tmp_path).md.value("MD32000[X]") == 5000.0


def test_refused_write_changes_nothing_on_disk(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    before = {p.name: p.read_bytes() for p in (tmp_path / "retained").iterdir()}
    with pytest.raises(AccessDenied):
        session.md.write("MD32000[X]", 5000, level=session.access.level)
    assert session.save() == []
    assert {p.name: p.read_bytes() for p in (tmp_path / "retained").iterdir()} == before


def test_alarm_log_is_bounded(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    session.record_alarms({"seq": i, "number": 10000 + i} for i in range(600))
    session.save()
    log = open_session(tmp_path).alarm_log
    assert len(log) == 500 and log[0]["seq"] == 100


def test_archive_round_trip(tmp_path: Path) -> None:
    source = Session.open(tmp_path / "a", install_samples=False)
    fill(source)
    source.files.create("PART1.MPF", "N10 G0 X0\nM30\n")
    source.files.create_workpiece("SHAFT")
    source.files.save("WKS/SHAFT.WPD/L1.SPF", "M17\n")
    (source.files.root / "MPF" / "BIN.MPF").write_bytes(b"\x00\xff")
    archive = source.export_archive(tmp_path / "setup.json")

    target = Session.open(tmp_path / "b", install_samples=False)
    target.files.create("KEEP.MPF", "M30\n")
    imported = target.import_archive(archive, level=1)  # it changes machine data: level 1 (SUNRISE)
    imported.access.state.keyswitch_position = 2  # access is not imported by default
    imported.access.enter_password("CUSTOMER")
    check(imported)
    assert imported.files.read("PART1.MPF") == "N10 G0 X0\nM30\n"
    assert imported.files.read("WKS/SHAFT.WPD/L1.SPF") == "M17\n"
    assert imported.files.read_bytes("BIN.MPF") == b"\x00\xff"
    assert imported.files.read("KEEP.MPF") == "M30\n"

    with_access = Session.open(tmp_path / "c", install_samples=False).import_archive(
        archive, include_access=True, level=1)
    assert with_access.access.level == 3


def test_bad_archive_changes_nothing(tmp_path: Path) -> None:
    session = open_session(tmp_path)
    fill(session)
    session.save()
    good = json.loads(session.export_archive(tmp_path / "good.json").read_text())
    before = {p.name: p.read_bytes() for p in (tmp_path / "retained").iterdir()}
    bad_cases = {
        "garbage.json": "not json",
        "other.json": json.dumps({"format": "something else"}),
        "badsection.json": json.dumps({**good, "sections": {**good["sections"],
                                                            "tools": {"edges": [{"t": "x"}]}}}),
        "badpath.json": json.dumps({**good, "programs": [{"path": "../../etc/passwd", "text": ""}]}),
    }
    for name, text in bad_cases.items():
        (tmp_path / name).write_text(text)
        with pytest.raises(ArchiveError):
            session.import_archive(tmp_path / name)
    with pytest.raises(ArchiveError):
        session.import_archive(tmp_path / "missing.json")
    assert {p.name: p.read_bytes() for p in (tmp_path / "retained").iterdir()} == before


def test_samples_installed_on_first_start(tmp_path: Path) -> None:
    samples = tmp_path / "samples"
    samples.mkdir()
    (samples / "TRAIN1.MPF").write_text("N10 G0 X0\nM30\n")
    session = Session.open(tmp_path / "data", samples=samples)
    assert session.files.read("TRAIN1.MPF") == "N10 G0 X0\nM30\n"
    session.files.delete("TRAIN1.MPF")
    assert not Session.open(tmp_path / "data", samples=samples).files.exists("TRAIN1.MPF")
