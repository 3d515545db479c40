"""A typed table from command class to the kernel function that carries it out.

``Nck.submit`` looks the handler up by the command's class. Each entry is checked by
mypy when it is registered: ``register(cmd.Reset, Nck._reset)`` only type-checks when
the handler takes a ``cmd.Reset``, so a command cannot reach a handler written for
another one (the table used to name handlers by method-name strings). A command carried out
by a part of the kernel is registered with the part it goes to:
``register_part(cmd.Jog, lambda nck: nck.manual, ManualControl.jog)``.
"""

from __future__ import annotations

from typing import Any, Callable, Generic, TypeVar

from nck.commands import SubmitResult

K = TypeVar("K")
"""The kernel type the handlers are methods of."""
C = TypeVar("C")
"""One command class."""
P = TypeVar("P")
"""A part of the kernel that carries out commands."""


class CommandTable(Generic[K]):
    """Command class -> handler ``(kernel, command) -> SubmitResult``."""

    def __init__(self) -> None:
        self._handlers: dict[type, Callable[[K, Any], SubmitResult]] = {}
        self._methods: dict[type, Callable[[Any, Any], SubmitResult]] = {}

    def register(self, kind: type[C], handler: Callable[[K, C], SubmitResult]) -> None:
        """Let ``handler`` carry out commands of class ``kind`` (exactly that class, not subclasses)."""
        self._add(kind, handler, handler)

    def register_part(self, kind: type[C], part: Callable[[K], P], handler: Callable[[P, C], SubmitResult]) -> None:
        """Let ``handler``, a method of the kernel's part ``part(kernel)``, carry out commands of class ``kind``."""
        self._add(kind, lambda kernel, command: handler(part(kernel), command), handler)

    def _add(self, kind: type, call: Callable[[K, Any], SubmitResult], method: Callable[[Any, Any], SubmitResult]) -> None:
        if kind in self._handlers:
            raise ValueError(f"{kind.__name__} is already handled by {self._methods[kind].__qualname__}")
        self._handlers[kind] = call
        self._methods[kind] = method

    def handler(self, kind: type) -> Callable[[K, Any], SubmitResult] | None:
        """What carries out commands of class ``kind``, called ``(kernel, command)``; None when
        no handler is registered."""
        return self._handlers.get(kind)

    def entries(self) -> dict[type, Callable[[Any, Any], SubmitResult]]:
        """Every registered command class and the method that carries it out: the kernel's
        ``(kernel, command)`` or its part's ``(part, command)`` (a copy)."""
        return dict(self._methods)
