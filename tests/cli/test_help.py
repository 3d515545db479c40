"""``nck --help`` names every command the command line has (the shared spec's cli.md lists
check, run, md and version; the project's README adds grade, setup, exercise, class-pack and
archive), and each name it lists answers its own ``--help``."""

from __future__ import annotations

import re

import pytest

from nck.cli import main

COMMANDS = ["check", "run", "grade", "version", "exercise", "class-pack", "md", "setup", "archive"]


def test_the_top_level_help_lists_every_command(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--help"]) == 0
    listed = re.search(r"\{([a-z,-]+)\}", capsys.readouterr().out)
    assert listed is not None and sorted(listed.group(1).split(",")) == sorted(COMMANDS)


@pytest.mark.parametrize("command", [c for c in COMMANDS if c != "version"])
def test_every_listed_command_answers_its_own_help(command: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main([command, "--help"]) == 0
    assert f"nck {command}" in capsys.readouterr().out
