"""The NC file system: names, create/copy/rename/delete rules, program in use, import/export."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import atomic
from nck.interp.api import ProgramSource
from nck.regular_files import ExportTargetExists
from nck.storage import NcFileSystem, StorageError, split_file_name, validate_name


@pytest.fixture
def fs(tmp_path: Path) -> NcFileSystem:
    return NcFileSystem(tmp_path / "nc")


@pytest.mark.parametrize("name", ["PART1", "part1", "_N", "AB", "L1", "L1234567", "__X_9",
                                  "A" * 24, "CONTOUR_2"])
def test_valid_names(name: str) -> None:
    assert validate_name(name) == name.upper()


@pytest.mark.parametrize("name", ["", "A", "1AB", "A1B", "PART 1", "PÄRT", "PART-1", "A" * 25,
                                  "L12345678", "../ETC", "A.B", "L"])
def test_invalid_names(name: str) -> None:
    with pytest.raises(StorageError) as exc:
        validate_name(name)
    assert exc.value.code == "invalid_name"


@pytest.mark.parametrize("file_name", ["PART1", "PART1.TXT", "PART1.", ".MPF", "1X.MPF"])
def test_file_names_need_a_known_extension_and_valid_stem(file_name: str) -> None:
    with pytest.raises(StorageError):
        split_file_name(file_name)


def test_layout_and_paths(fs: NcFileSystem) -> None:
    assert sorted(p.name for p in fs.root.iterdir()) == ["MPF", "SPF", "WKS"]
    assert fs.canonical("part1.mpf") == "MPF/PART1.MPF"
    assert fs.canonical("l10.spf") == "SPF/L10.SPF"
    assert fs.canonical("wks/shaft.wpd/shaft.mpf") == "WKS/SHAFT.WPD/SHAFT.MPF"
    for bad in ["MPF/X.SPF", "SPF/X.MPF", "WKS/X.MPF", "OTHER/X.MPF", "MPF/../X.MPF",
                "WKS/A.WPD/B.WPD", "WKS/A.WPD/B.MPF/C"]:
        with pytest.raises(StorageError):
            fs.canonical(bad)


def test_create_read_list(fs: NcFileSystem) -> None:
    entry = fs.create("PART1.MPF", "N10 G0 X0\n")
    assert entry.path == "MPF/PART1.MPF" and entry.size_bytes == 10 and entry.kind == "MPF"
    assert fs.read("MPF/PART1.MPF") == "N10 G0 X0\n"
    with pytest.raises(StorageError) as exc:
        fs.create("part1.mpf")
    assert exc.value.code == "exists"
    fs.create("L10.SPF", "M17\n")
    fs.create("ABC.MPF")
    assert [e.name for e in fs.list_directory("MPF")] == ["ABC.MPF", "PART1.MPF"]
    assert [e.name for e in fs.list_directory("SPF")] == ["L10.SPF"]


def test_save_is_atomic(fs: NcFileSystem, monkeypatch: pytest.MonkeyPatch) -> None:
    fs.create("PART1.MPF", "old\n")

    def crash(src: object, dst: object) -> None:
        raise OSError(5, "simulated crash")

    monkeypatch.setattr(atomic.os, "replace", crash)
    with pytest.raises(StorageError) as exc:
        fs.save("PART1.MPF", "new\n")
    assert exc.value.code == "io"
    assert fs.read("PART1.MPF") == "old\n"
    assert [p.name for p in (fs.root / "MPF").iterdir()] == ["PART1.MPF"]


def test_copy_rules(fs: NcFileSystem) -> None:
    fs.create("PART1.MPF", "N10\n")
    assert fs.copy("PART1.MPF", "PART2.MPF").path == "MPF/PART2.MPF"
    assert fs.read("PART2.MPF") == "N10\n"
    with pytest.raises(StorageError) as exc:
        fs.copy("PART1.MPF", "PART2.MPF")
    assert exc.value.code == "exists"
    fs.save("PART1.MPF", "N20\n")
    fs.copy("PART1.MPF", "PART2.MPF", overwrite=True)
    assert fs.read("PART2.MPF") == "N20\n"
    with pytest.raises(StorageError):
        fs.copy("PART1.MPF", "PART1.MPF")
    with pytest.raises(StorageError) as exc:
        fs.copy("NOPE.MPF", "X1.MPF")
    assert exc.value.code == "not_found"
    fs.create_workpiece("SHAFT")
    assert fs.copy("PART1.MPF", "WKS/SHAFT.WPD").path == "WKS/SHAFT.WPD/PART1.MPF"
    assert fs.copy("WKS/SHAFT.WPD", "WKS/SHAFT2.WPD").path == "WKS/SHAFT2.WPD"
    assert [e.name for e in fs.list_directory("WKS/SHAFT2.WPD")] == ["PART1.MPF", "SHAFT.MPF"]


def test_rename_rules(fs: NcFileSystem) -> None:
    fs.create("PART1.MPF", "N10\n")
    fs.create("PART2.MPF")
    assert fs.rename("PART1.MPF", "NEW_NAME").path == "MPF/NEW_NAME.MPF"
    assert not fs.exists("PART1.MPF") and fs.read("NEW_NAME.MPF") == "N10\n"
    with pytest.raises(StorageError) as exc:
        fs.rename("NEW_NAME.MPF", "PART2")
    assert exc.value.code == "exists"
    with pytest.raises(StorageError) as exc:
        fs.rename("NEW_NAME.MPF", "9LIVES")
    assert exc.value.code == "invalid_name"
    with pytest.raises(StorageError):
        fs.rename("NEW_NAME.MPF", "SUB.SPF")  # an SPF does not belong in MPF
    fs.create_workpiece("SHAFT")
    assert fs.rename("WKS/SHAFT.WPD/SHAFT.MPF", "SHAFT.SPF").path == "WKS/SHAFT.WPD/SHAFT.SPF"
    assert fs.rename("WKS/SHAFT.WPD", "AXLE").path == "WKS/AXLE.WPD"


def test_delete_rules(fs: NcFileSystem) -> None:
    fs.create("PART1.MPF")
    fs.delete("PART1.MPF")
    assert not fs.exists("PART1.MPF")
    with pytest.raises(StorageError) as exc:
        fs.delete("PART1.MPF")
    assert exc.value.code == "not_found"
    with pytest.raises(StorageError):
        fs.delete("MPF")
    fs.create_workpiece("SHAFT")
    fs.delete("WKS/SHAFT.WPD")
    assert fs.list_directory("WKS") == []


def test_program_in_use_cannot_be_deleted_renamed_or_saved(fs: NcFileSystem) -> None:
    fs.create("PART1.MPF", "N10\n")
    fs.create_workpiece("SHAFT")
    running = ["PART1.MPF", "WKS/SHAFT.WPD/SHAFT.MPF"]
    fs.in_use_check = lambda: running
    for action in (lambda: fs.delete("MPF/PART1.MPF"), lambda: fs.rename("PART1.MPF", "OTHER"),
                   lambda: fs.save("PART1.MPF", "changed\n"), lambda: fs.delete("WKS/SHAFT.WPD"),
                   lambda: fs.rename("WKS/SHAFT.WPD", "AXLE")):
        with pytest.raises(StorageError) as exc:
            action()
        assert exc.value.code == "in_use"
    assert fs.read("PART1.MPF") == "N10\n" and fs.exists("WKS/SHAFT.WPD")
    opened = fs.open_program("PART1.MPF")
    assert opened.read_only and "in use" in opened.message
    fs.copy("PART1.MPF", "COPY1.MPF")  # copying a program in use is fine
    running.clear()
    fs.rename("PART1.MPF", "OTHER")
    fs.set_in_use(["MPF/OTHER.MPF"])
    fs.in_use_check = lambda: fs._in_use
    with pytest.raises(StorageError):
        fs.delete("OTHER.MPF")


def test_binary_and_non_utf8_open_read_only(fs: NcFileSystem) -> None:
    (fs.root / "MPF" / "BIN.MPF").write_bytes(b"\x00\x01\x02N10")
    (fs.root / "MPF" / "LATIN.MPF").write_bytes("N10 ; Größe".encode("latin-1"))
    for name in ("BIN.MPF", "LATIN.MPF"):
        with pytest.raises(StorageError) as exc:
            fs.read(name)
        assert exc.value.code == "not_text"
        opened = fs.open_program(name)
        assert opened.read_only and "read-only" in opened.message
    assert not fs.open_program(fs.create("OK1.MPF", "N10\n").path).read_only


def test_import_export(fs: NcFileSystem, tmp_path: Path) -> None:
    local = tmp_path / "outside" / "drill_me.mpf"
    local.parent.mkdir()
    local.write_text("N10 G81\n")
    assert fs.import_file(local).path == "MPF/DRILL_ME.MPF"
    assert fs.import_file(local, "SPF").path == "SPF/DRILL_ME.SPF"
    (tmp_path / "outside" / "notes.txt").write_text("N5\n")
    assert fs.import_file(tmp_path / "outside" / "notes.txt").path == "MPF/NOTES.MPF"
    with pytest.raises(StorageError):
        fs.import_file(local)
    with pytest.raises(StorageError):
        fs.import_file(tmp_path / "outside" / "missing.mpf")
    bad = tmp_path / "outside" / "1bad.mpf"
    bad.write_text("x")
    with pytest.raises(StorageError) as exc:
        fs.import_file(bad)
    assert exc.value.code == "invalid_name"
    written = fs.export_file("DRILL_ME.MPF", tmp_path / "outside")
    assert written.name == "DRILL_ME.MPF" and written.read_text() == "N10 G81\n"


def test_program_source_protocol(fs: NcFileSystem) -> None:
    source: ProgramSource = fs
    fs.create("MAIN1.MPF", "N10 L10\n")
    fs.create("L10.SPF", "global sub\n")
    fs.create("CONTOUR.MPF", "as main\n")
    fs.create_workpiece("SHAFT")
    fs.save("WKS/SHAFT.WPD/L10.SPF", "local sub\n")
    assert source.read_program("MAIN1.MPF") == ("MAIN1.MPF", "N10 L10\n")
    assert source.read_program("l10") == ("L10.SPF", "global sub\n")
    assert source.read_program("CONTOUR") == ("CONTOUR.MPF", "as main\n")
    assert source.read_program("MISSING") is None
    assert source.read_program("1/../../etc") is None
    scoped = fs.program_source("WKS/SHAFT.WPD/SHAFT.MPF")
    assert scoped.read_program("L10") == ("L10.SPF", "local sub\n")
    assert scoped.read_program("MAIN1") == ("MAIN1.MPF", "N10 L10\n")


def test_install_samples_once(fs: NcFileSystem, tmp_path: Path) -> None:
    samples = tmp_path / "samples"
    (samples / "basics").mkdir(parents=True)
    (samples / "basics" / "FIRST.MPF").write_text("N10 G0 X0\n")
    (samples / "L100.SPF").write_text("M17\n")
    (samples / "GEAR.WPD").mkdir()
    (samples / "GEAR.WPD" / "GEAR.MPF").write_text("N10\n")
    (samples / "README.md").write_text("not a program")
    (samples / "9BAD.MPF").write_text("bad name")
    installed = fs.install_samples(samples)
    assert sorted(installed) == ["MPF/FIRST.MPF", "SPF/L100.SPF", "WKS/GEAR.WPD",
                                 "WKS/GEAR.WPD/GEAR.MPF"]
    fs.delete("FIRST.MPF")
    assert fs.install_samples(samples) == []  # only on first start
    assert not fs.exists("FIRST.MPF")
    fs.save("L100.SPF", "changed\n")
    fs.install_samples(samples, force=True)
    assert fs.read("L100.SPF") == "changed\n"  # never overwritten


def test_foreign_files_are_not_listed(fs: NcFileSystem) -> None:
    (fs.root / "MPF" / "notes.txt").write_text("x")
    (fs.root / "MPF" / ".PART1.MPF.tmp-1-ab").write_text("x")
    (fs.root / "MPF" / "lower.mpf").write_text("N1\n")
    assert [e.name for e in fs.list_directory("MPF")] == ["LOWER.MPF"]
    assert fs.read("LOWER.MPF") == "N1\n"


def test_every_shipped_training_program_is_installed(tmp_path: Path) -> None:
    from nck.resources import data_path

    shipped = {p.name.upper() for p in data_path("programs").rglob("*")
               if p.suffix.upper() in (".MPF", ".SPF")}
    fs = NcFileSystem(tmp_path / "nc")
    installed = {path.rpartition("/")[2] for path in fs.install_samples(data_path("programs"))}
    assert installed == shipped


@pytest.mark.parametrize("operation", ["rename", "delete"])
def test_a_refused_rename_or_delete_names_the_nc_path_not_the_disk(tmp_path, monkeypatch, operation):
    """The operating system's refusal is said with the program's NC path (as a refused save is),
    never with the folder on the host's disk where the NC memory happens to live."""
    fs = NcFileSystem(tmp_path / "nc")
    (tmp_path / "nc" / "SPF" / "SUB.SPF").write_text("PROC SUB\nRET\n")

    def refused(*args, **kwargs):
        raise PermissionError(13, "Permission denied", str(tmp_path / "nc" / "SPF" / "SUB.SPF"))

    monkeypatch.setattr("os.replace", refused)
    monkeypatch.setattr("pathlib.Path.unlink", refused)
    with pytest.raises(StorageError) as refusal:
        fs.rename("SPF/SUB.SPF", "OTHER") if operation == "rename" else fs.delete("SPF/SUB.SPF")
    assert str(refusal.value) == "SPF/SUB.SPF: permission denied"


def test_an_export_below_a_file_is_a_failure_not_a_question(tmp_path):
    """Only an export file that is already there asks to be replaced (ExportTargetExists); a file
    where the path needs a folder is a refusal with its reason."""
    fs = NcFileSystem(tmp_path / "nc")
    fs.save("MPF/PART.MPF", "M30\n")
    (tmp_path / "plain.txt").write_text("")
    for below in (tmp_path / "plain.txt" / "PART.MPF", tmp_path / "plain.txt" / "sub" / "PART.MPF"):
        with pytest.raises(StorageError) as refusal:
            fs.export_file("MPF/PART.MPF", below)
        assert not isinstance(refusal.value, FileExistsError)
        assert str(refusal.value) == f"{tmp_path / 'plain.txt'}: a file, not a folder"  # the file in the way
    with pytest.raises(StorageError) as refusal:  # typed as a folder: the file there is in the way
        fs.export_file("MPF/PART.MPF", f"{tmp_path / 'plain.txt'}/")
    assert str(refusal.value) == f"{tmp_path / 'plain.txt'}: a file, not a folder"
    assert (tmp_path / "plain.txt").read_text() == ""
    fs.export_file("MPF/PART.MPF", f"{tmp_path / 'folder'}/")  # a folder typed with its slash is made
    assert (tmp_path / "folder" / "PART.MPF").read_text() == "M30\n"
    fs.export_file("MPF/PART.MPF", tmp_path / "new" / "sub" / "PART.MPF")  # missing folders are made
    assert (tmp_path / "new" / "sub" / "PART.MPF").read_text() == "M30\n"
    (tmp_path / "out.MPF").write_text("")
    with pytest.raises(ExportTargetExists):
        fs.export_file("MPF/PART.MPF", tmp_path / "out.MPF")
