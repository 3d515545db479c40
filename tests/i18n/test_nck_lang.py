"""``nck check|run --lang de`` prints the alarm texts in German (issue 27); English by default."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.cli import main

NO_FEED = "N10 G1 X10\nN20 M30\n"  # G1 without F: alarm 10860 in block N10


@pytest.mark.parametrize("command", ["check", "run"])
def test_alarm_text_in_german(command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = tmp_path / "NOFEED.MPF"
    program.write_text(NO_FEED)
    assert main([command, "--lang", "de", str(program)]) == 1
    assert "ALARM 10860 NOFEED.MPF:1 N10 Kanal 1 Satz N10: kein Vorschub programmiert" in capsys.readouterr().err


def test_english_without_lang(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = tmp_path / "NOFEED.MPF"
    program.write_text(NO_FEED)
    assert main(["check", str(program)]) == 1
    assert "N10 Channel 1 block N10: no feedrate programmed" in capsys.readouterr().err


def test_unknown_language_is_a_usage_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = tmp_path / "NOFEED.MPF"
    program.write_text(NO_FEED)
    assert main(["check", "--lang", "fr", str(program)]) == 2
    assert "--lang" in capsys.readouterr().err
