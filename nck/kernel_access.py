"""Keyswitch, passwords and protection levels, a part of :class:`nck.kernel.Nck`.

The commands ``SetKeyswitch``, ``EnterPassword``, ``DeletePassword`` and ``ChangePassword``
work on an :class:`nck.access.AccessControl`. The HMI and the CLI on a data directory hand
the kernel the session's access control, which other doors (the command line, an exercise
set-up) change as well; its ``revision`` tells the kernel that its snapshot is stale.

A bare kernel (unit tests) has no access control: it is a commissioning bench without
protection (level 7 shown, every write allowed) until a password or keyswitch command (or a
read of :attr:`Protection.access`) creates one at keyswitch position 0.
"""

from __future__ import annotations

from typing import Callable

from nck import commands as cmd
from nck.access import (ALARM_PASSWORD_REFUSED, LEVEL_FEWEST_RIGHTS, KEYSWITCH_POSITIONS, AccessControl, AccessError,
                        AccessLocked, AccessState, Action)
from nck.alarms import AlarmServer
from nck.commands import Accepted, SubmitResult
from nck.phrase import Phrase
from nck.refusals import refuse, rejected_by
from nck.status import LogbookEntry


class Protection:
    """The kernel's access control (None: unprotected) and the commands that change it."""

    def __init__(self, control: AccessControl | None, logbook: list[LogbookEntry], alarms: AlarmServer,
                 clock: Callable[[], float], raise_number: Callable[..., None]) -> None:
        self.control = control  # None: no protection; created by a keyswitch or password command
        self.logbook = logbook  # refused passwords are written there
        self.alarms = alarms  # alarm 129300 goes when a password is accepted
        self.clock = clock  # the kernel's simulated time
        self.raise_number = raise_number  # raises an alarm by number with its parameters

    # ------------------------------------------------------------------ reading
    @property
    def access(self) -> AccessControl:
        """Keyswitch and passwords (protection levels 0 … 7), created on first use."""
        if self.control is None:
            self.control = AccessControl(AccessState(keyswitch_position=0))
        return self.control

    @property
    def protected(self) -> bool:
        """True when writes are checked against the access level."""
        return self.control is not None

    def level(self) -> int:
        """The current access level (7, the fewest rights, when unprotected)."""
        return self.control.level if self.control is not None else LEVEL_FEWEST_RIGHTS

    def keyswitch_position(self) -> int | None:
        """The keyswitch position 0 … 3; None when unprotected."""
        return self.control.state.keyswitch_position if self.control is not None else None

    def state(self) -> AccessState | None:
        """Keyswitch position and password state; None when unprotected."""
        return self.control.state if self.control is not None else None

    def revision(self) -> int:
        """Grows with every change of the access state, made by the kernel or another door."""
        return self.control.revision if self.control is not None else 0

    def action_level(self, action: Action | str) -> int:
        """The protection level ``action`` (an Action or its name, ``"READ_TOOL"``) needs;
        7 when unprotected. Creates nothing."""
        if isinstance(action, str):
            action = Action[action.strip().upper()]
        return self.control.required(action) if self.control is not None else LEVEL_FEWEST_RIGHTS

    def require(self, action: Action) -> None:
        """Raise AccessDenied unless the current level allows ``action`` (nothing when unprotected)."""
        if self.control is not None:
            self.control.require(action)

    # ----------------------------------------------------------------- commands
    def set_keyswitch(self, command: cmd.SetKeyswitch) -> SubmitResult:
        """Turn the keyswitch to position 0 … 3 (refused while an exam fixes the level)."""
        if command.position not in KEYSWITCH_POSITIONS:
            return refuse("keyswitch_positions")
        try:
            self.access.set_keyswitch(command.position)
        except AccessLocked as error:
            return rejected_by(error)
        return Accepted()

    def enter_password(self, command: cmd.EnterPassword) -> SubmitResult:
        """Set a password; a wrong one is counted, written to the logbook and raises alarm 129300."""
        failed_before = self.access.state.failed_attempts
        try:
            self.access.enter_password(command.password)
        except AccessError as error:
            failed = self.access.state.failed_attempts
            wrong = failed > failed_before  # a wrong password (not a malformed one): logbook and alarm log
            if wrong:
                delay = f"{self.access.retry_delay_s:g}"
                self.logbook.append(LogbookEntry(self.clock(), "access", Phrase(
                    "password not accepted (failed attempt {failed})", failed=failed)))
                self.raise_number(ALARM_PASSWORD_REFUSED, failed, delay)
            return rejected_by(error, alarm=ALARM_PASSWORD_REFUSED if wrong else None)
        # the refusal and its waiting time are over: the alarm goes (the log keeps it)
        self.alarms.clear_number(ALARM_PASSWORD_REFUSED, self.clock())
        return Accepted()

    def delete_password(self, command: cmd.DeletePassword) -> SubmitResult:
        """Delete the active password: back to the keyswitch level."""
        if self.control is not None:
            try:
                self.control.delete_password()
            except AccessLocked as error:
                return rejected_by(error)
        return Accepted()

    def change_password(self, command: cmd.ChangePassword) -> SubmitResult:
        """Give a password level (1 … 3) a new password (from that level or one with more rights)."""
        try:
            self.access.change_password(command.level, command.password)
        except AccessError as error:  # AccessDenied too
            return rejected_by(error)
        return Accepted()


__all__ = ["Protection"]
