"""A failed file operation is said in the panel's language (issue 27): the NC file system's
refusals (``StorageError``) are keyed, and an operating system's error is said by its kind
(``errno``), never in the C library's English sentence (``strerror``)."""

from __future__ import annotations

import errno
from pathlib import Path

import pytest

from hmi.i18n import error_text
from nck import StorageError, os_refusal
from nck.regular_files import FileTooLarge, NotAFolder, NotARegularFile
from tests.program_screens.conftest import DEMO_PROGRAM, SIZE, make_program_app, nc_files

GERMAN_KINDS = [
    (errno.ENOENT, "/tmp/x/A.MPF: Datei oder Verzeichnis nicht vorhanden"),
    (errno.EACCES, "/tmp/x/A.MPF: keine Berechtigung"),
    (errno.EPERM, "/tmp/x/A.MPF: keine Berechtigung"),
    (errno.ENOSPC, "/tmp/x/A.MPF: der Datenträger ist voll"),
    (errno.EROFS, "/tmp/x/A.MPF: schreibgeschütztes Dateisystem"),
    (errno.EIO, "/tmp/x/A.MPF: die Datei konnte nicht geschrieben werden"),
]


@pytest.mark.parametrize(("number", "german_text"), GERMAN_KINDS)
def test_an_os_error_is_said_by_its_kind_in_german(german: None, number: int, german_text: str) -> None:
    error = OSError(number, "the C library's English", "/tmp/x/A.MPF")
    assert error_text(error) == german_text


def test_an_os_error_keeps_an_english_sentence_of_its_own() -> None:
    """The command line and the logs read ``str()`` of the refusal: English, without strerror."""
    assert str(os_refusal(OSError(errno.ENOSPC, "No space left on device", "/d/A.MPF"))) == "/d/A.MPF: the disk is full"
    assert str(os_refusal(OSError(errno.EIO, "Input/output error"), failed="os_read_failed")) == (
        "the file could not be read")
    assert error_text(OSError(errno.EACCES, "Permission denied", "/d")) == "/d: permission denied"


def test_an_os_error_without_a_path_and_the_files_of_the_wrong_kind(german: None) -> None:
    assert error_text(OSError(errno.ENOSPC, "No space left on device")) == "der Datenträger ist voll"
    assert error_text(OSError(errno.EIO, "x"), failed="os_read_failed") == "die Datei konnte nicht gelesen werden"
    assert error_text(NotARegularFile("/d/link")) == (
        "/d/link: keine reguläre Datei (eine Verknüpfung, Pipe oder ein Gerät)")
    assert error_text(FileTooLarge("/d/big", 50 << 20)) == "/d/big: größer als 50 MB"
    assert error_text(NotAFolder("/d/plain.txt")) == "/d/plain.txt: eine Datei, kein Ordner"


def test_the_nc_file_systems_refusals_are_said_in_german(german: None) -> None:
    assert error_text(StorageError("storage_exists", path="MPF/DEMO.MPF")) == "MPF/DEMO.MPF ist bereits vorhanden"
    assert error_text(StorageError("storage_in_use_deleted", path="MPF/DEMO.MPF")) == (
        "MPF/DEMO.MPF ist in Benutzung und kann nicht gelöscht werden")
    written = StorageError.from_os_error(OSError(errno.EROFS, "Read-only file system"), "/media/A.MPF")
    assert written.code == "io" and str(written) == "/media/A.MPF: read-only file system"
    assert error_text(written) == "/media/A.MPF: schreibgeschütztes Dateisystem"


async def test_export_and_new_say_the_failure_in_german(german: None, tmp_path: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    """Program manager, German panel: an export onto a read-only file system (a write-protected
    stick) and a program name that is not allowed are refused in German (they were English:
    strerror, StorageError)."""
    def read_only(path: Path, data: bytes, *, replace: bool = False) -> None:
        raise OSError(errno.EROFS, "Read-only file system", str(path))

    monkeypatch.setattr("nck.storage.write_export", read_only)
    monkeypatch.chdir(tmp_path)
    data_dir = tmp_path / "nc"
    nc_files(data_dir)
    (data_dir / "MPF" / "DEMO.MPF").write_text(DEMO_PROGRAM)
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n")
        await pilot.pause()
        await pilot.press("shift+f2")  # Export: its prompt's keys in German too
        await pilot.pause()
        assert str(app.screen.query_one("#prompt-keys").render()) == "Enter bestätigen   F10 abbrechen"
        await pilot.press("ctrl+u", *"stick/DEMO.MPF", "enter")
        await pilot.pause()
        line = str(app.screen.query_one("#dialog-line").render())
        assert line.strip() == "Exportieren: stick/DEMO.MPF: schreibgeschütztes Dateisystem"
        await pilot.press("f2", *"1bad", "enter")  # New
        await pilot.pause()
        line = str(app.screen.query_one("#dialog-line").render())
        assert line.strip().startswith("Neu: 1BAD: nur Buchstaben, Ziffern und _")


def test_a_class_pack_the_system_cannot_read_is_said_in_german(german: None, tmp_path: Path) -> None:
    """Import class pack on a German panel, a path with no file: the operating system's refusal
    in German (was "not a readable class pack (No such file or directory)")."""
    from hmi.app import make_app

    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        said = app.import_class_pack(str(tmp_path / "missing.json"))
    finally:
        app.nc_session.quit()
    assert said == f"Klassenpaket nicht importiert: {tmp_path / 'missing.json'}: Datei oder Verzeichnis nicht vorhanden"
