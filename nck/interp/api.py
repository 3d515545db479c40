"""The contract between the channel (kernel) and the interpreter.

The channel drives the interpreter one block at a time; the interpreter
returns what the block produced. A block that fails raises
:class:`nck.errors.NcAlarmError` and changes no state.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from nck.canon import CanonCommand, Source

BLOCK_COST_S = 0.001
"""Simulated time one interpreted block costs (1 ms), whatever path interpreted it."""


@dataclass(slots=True)
class BlockResult:
    """What one interpreted block produced.

    Immutable by contract, but not a frozen dataclass: a frozen one sets each field through
    ``object.__setattr__`` (~2.1 against ~0.7 us, one result per block; it was never
    hashable, ``extras`` is a dict).

    Attributes:
        source: file, line and block number of the block.
        text: the block's source text (for the block display).
        commands: canonical commands, in output order.
        action_block: True if the block triggers an action (motion, auxiliary
            function, dwell, message, stop point) — single block SBL1 stops after
            these; SBL2 stops after every block.
        finished: True when the main program ended (M2/M30) with this block.
        cost_s: simulated time the interpretation of this block costs (so an
            endless loop without motion still advances time).
        extras: further facts about the block, by key: ``level`` (program level
            after the block), ``skipped`` (skip level active), ``single_block_off``
            (SBLOF), ``display_off`` (DISPLOF), ``preprocessing_stop`` (the block
            read main-run data such as ``$AA_IM``).
    """

    source: Source
    text: str
    commands: tuple[CanonCommand, ...] = ()
    action_block: bool = False
    finished: bool = False
    cost_s: float = 0.0
    extras: dict = field(default_factory=dict)


class ProgramSource(Protocol):
    """Where the interpreter finds programs by name (directory, NC file system, memory)."""

    def read_program(self, name: str) -> tuple[str, str] | None:
        """Return ``(display_name, text)`` for a main/subprogram name, or None if absent.

        ``name`` may carry an extension (``PART1.MPF``) or not (``L123``, ``CONTOUR``,
        looked up as ``.SPF`` then ``.MPF``).
        """


class Interpreter(Protocol):
    """What the channel needs from an interpreter (``nck.interp.interpreter``)."""

    def start(self, program_name: str) -> None:
        """Load the main program ``program_name`` and position before its first block."""

    def start_text(self, name: str, text: str) -> None:
        """Load a program given as text (MDA buffer) under ``name``."""

    def step(self) -> BlockResult:
        """Interpret the next block; raise NcAlarmError on failure (state unchanged)."""

    def reset(self) -> None:
        """Abort the program and restore the reset state of every G group and modal value."""

    def skip_to(self, number: int | None, text: str) -> bool:
        """Place the main program before block ``number`` (or the first block containing
        ``text``) without interpreting anything before it; False if there is none."""

    @property
    def finished(self) -> bool:
        """True when the program has ended or none is loaded."""
