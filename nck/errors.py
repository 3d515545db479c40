"""Exceptions that cross layer boundaries inside the kernel.

A user-caused problem is always an :class:`NcAlarmError` carrying a SINUMERIK
alarm number. Anything else that escapes is a genuine bug.
"""

from __future__ import annotations

from typing import Any


class NcAlarmError(Exception):
    """A condition that the control reports as a numbered NC alarm.

    Raised by the pure layers (lexer, parser, interpreter, geometry, planner);
    caught at the block boundary, where the alarm server applies its reaction.

    Args:
        number: SINUMERIK alarm number (the contract; text lives in ``data/alarms``).
        params: values for the ``%1``, ``%2`` … placeholders of the alarm text,
            *after* the channel and block parameters that the raiser fills in.
        file: program file name the alarm refers to, if any.
        line: 1-based source line, if any.
        n: block number (``N…``) of the block, if any.
    """

    def __init__(
        self,
        number: int,
        *params: object,
        file: str | None = None,
        line: int | None = None,
        n: int | None = None,
    ) -> None:
        self.number = int(number)
        self.params = tuple(str(p) for p in params)
        self.file = file
        self.line = line
        self.n = n
        super().__init__(f"alarm {self.number} {' '.join(self.params)}".rstrip())

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickled with its number, parameters and location (a simulation computed in another
        process hands its alarms back this way)."""
        return (type(self), (self.number, *self.params), self.__dict__)

    def located(self, file: str | None, line: int | None, n: int | None) -> "NcAlarmError":
        """Fill in the source location where it is still unknown; returns self."""
        if self.file is None:
            self.file = file
        if self.line is None:
            self.line = line
        if self.n is None:
            self.n = n
        return self
