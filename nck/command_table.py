"""A typed table from command class to the kernel function that carries it out.

``Nck.submit`` looks the handler up by the command's class. Each entry is checked by
mypy when it is registered: ``register(cmd.Reset, Nck._reset)`` only type-checks when
the handler takes a ``cmd.Reset``, so a command cannot reach a handler written for
another one (the table used to name handlers by method-name strings).
"""

from __future__ import annotations

from typing import Any, Callable, Generic, TypeVar

from nck.commands import SubmitResult

K = TypeVar("K")
"""The kernel type the handlers are methods of."""
C = TypeVar("C")
"""One command class."""


class CommandTable(Generic[K]):
    """Command class -> handler ``(kernel, command) -> SubmitResult``."""

    def __init__(self) -> None:
        self._handlers: dict[type, Callable[[K, Any], SubmitResult]] = {}

    def register(self, kind: type[C], handler: Callable[[K, C], SubmitResult]) -> None:
        """Let ``handler`` carry out commands of class ``kind`` (exactly that class, not subclasses)."""
        if kind in self._handlers:
            raise ValueError(f"{kind.__name__} is already handled by {self._handlers[kind].__qualname__}")
        self._handlers[kind] = handler

    def handler(self, kind: type) -> Callable[[K, Any], SubmitResult] | None:
        """The handler of commands of class ``kind``; None when no handler is registered."""
        return self._handlers.get(kind)

    def entries(self) -> dict[type, Callable[[K, Any], SubmitResult]]:
        """Every registered command class and its handler (a copy)."""
        return dict(self._handlers)
