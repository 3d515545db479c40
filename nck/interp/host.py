"""The interpreter as its block execution and fast path see it.

:class:`InterpreterHost` lists what :mod:`nck.interp.block_run` (one general block) and
the fast paths (:mod:`nck.interp.plain_setup`, :mod:`~nck.interp.plain_run`,
:mod:`~nck.interp.simple_step`) use of :class:`~nck.interp.interpreter.Interpreter`. They
are typed against it, so they need not import the interpreter module, which imports them:
the arrows run one way, from the interpreter down to its parts.

:class:`RunState` is everything the interpreter changes while it runs (copied before each
block so that a failing block can be undone).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from nck.interp.api import ProgramSource
from nck.interp.call_stack import Binding, Frame, VariableHost
from nck.interp.modal import ModalState
from nck.interp.motion_builder import MotionBuilder
from nck.interp.sysvars import SysContext
from nck.lang.dialect import Dialect
from nck.lang.gcodes import GTable
from nck.machine import MachineConfig
from nck.ncdata import NcData


@dataclass
class RunState:
    """Everything the interpreter changes; copied before each block."""

    modal: ModalState
    frames: list[Frame] = field(default_factory=list)
    finished: bool = True
    blocks: int = 0
    message: str = ""


class InterpreterHost(VariableHost, SysContext, Protocol):
    """What a block run and the fast path use of the interpreter (see the module docstring).

    ``run_state``, ``skip_run``, ``end_program`` and ``return_from`` are the interpreter's own
    state and steps: public so that its parts in this package may be typed against them,
    not for use outside ``nck.interp``.
    """

    machine: MachineConfig
    programs: ProgramSource
    data: NcData
    dialect: Dialect
    table: GTable
    builder: MotionBuilder
    run_state: RunState
    skip_run: tuple[int, bool] | None

    @property
    def modal(self) -> ModalState:
        """The live modal state."""

    def lookup(self, name: str) -> Binding | None:
        """The binding of a variable name at the current level (None: not a variable)."""

    def read_cycle(self, name: str) -> tuple[str, str] | None:
        """``(name, text)`` of a standard cycle program, None if there is none."""

    def end_program(self, kind: str) -> None:
        """End the whole program (M2/M30)."""

    def return_from(self, frame: Frame) -> None:
        """Subprogram end: repeat while passes are left, else back to the caller."""
