"""``--password`` at the command-line doors (``nck md``, ``nck run``, ``nck check``).

A wrong password counts as a failed attempt in the retained access state, goes into the
alarm log (alarm 129300, as on the panel) and makes the command wait before it ends:
1 s after the first failure, doubling with every further one up to 60 s
(:func:`nck.access.retry_delay_s`). The kernel only counts; the waiting is the door's.
"""

from __future__ import annotations

from typing import Any, Callable

from nck.access import ALARM_PASSWORD_REFUSED, AccessControl, PasswordError, normalize_password
from nck.resources import alarm_text


def level_of_password(access: AccessControl, password: str, session: Any = None,
                      wait_s: Callable[[float], None] | None = None) -> int | None:
    """The level ``password`` opens for this call, or None after the failed-attempt handling.

    ``session`` (a :class:`nck.persistence.Session`) gets the alarm-log entry; the caller
    saves it so that the count survives the command. ``wait_s`` is how the door waits
    (the ``nck`` console script passes ``time.sleep``; None does not wait).
    """
    try:
        normalize_password(password)
    except PasswordError:
        return None
    level = access.try_password(password)
    if level is not None:
        return level
    failed, delay = access.state.failed_attempts, access.retry_delay_s
    if session is not None:
        params = (str(failed), f"{delay:g}")
        session.record_alarms([{
            "seq": 0, "number": ALARM_PASSWORD_REFUSED, "text": alarm_text(ALARM_PASSWORD_REFUSED, params),
            "category": "hmi", "clear": "cancel", "came_s": 0.0, "went_s": 0.0, "params": list(params),
        }])
    if wait_s is not None:
        wait_s(delay)
    return None
