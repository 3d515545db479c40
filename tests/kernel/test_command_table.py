"""The kernel's typed command table: every command has one handler, written for that command."""

from __future__ import annotations

import dataclasses
import inspect
import typing

import pytest

from nck import commands as cmd
from nck.command_table import CommandTable
from nck.kernel import COMMANDS, Nck


def command_classes() -> list[type]:
    """Every command class of nck.commands (the dataclasses apart from the two results)."""
    return [value for _, value in inspect.getmembers(cmd, inspect.isclass)
            if value.__module__ == cmd.__name__ and dataclasses.is_dataclass(value)
            and value not in (cmd.Accepted, cmd.Rejected)]


def test_every_command_class_has_a_handler() -> None:
    assert sorted(c.__name__ for c in command_classes()) == sorted(c.__name__ for c in COMMANDS.entries())


@pytest.mark.parametrize("kind", command_classes(), ids=lambda kind: kind.__name__)
def test_each_handler_takes_its_own_command(kind: type) -> None:
    handler = COMMANDS.entries()[kind]
    parameters = list(inspect.signature(handler).parameters)
    assert len(parameters) == 2  # (kernel, command)
    assert typing.get_type_hints(handler)[parameters[1]] is kind


def test_a_command_without_a_handler_is_rejected_by_the_kernel() -> None:
    @dataclasses.dataclass(frozen=True)
    class Unknown:
        pass

    result = Nck().submit(Unknown())
    assert isinstance(result, cmd.Rejected) and result.reason == "unknown command Unknown"


def test_a_command_class_is_registered_once() -> None:
    table: CommandTable[Nck] = CommandTable()
    table.register(cmd.Reset, Nck._reset)
    with pytest.raises(ValueError, match="Reset is already handled"):
        table.register(cmd.Reset, Nck._cycle_stop)  # type: ignore[arg-type]
