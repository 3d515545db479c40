"""Values the operator enters for NC data: read as numbers, refused with a message.

Input fields of the HMI (tool list, wear, work offsets, R variables, user
variables, part counters) and the ``nck`` command line send the typed text in a
``WriteData``. The kernel reads it here. Text that is no number is refused with
an :class:`InvalidValue` that says, in the operator's words, what to enter;
nothing is written then, so the datum keeps its old value.

Accepted notation (our choice, after the NC language's number constants): an
optional sign, digits with an optional decimal point, and an optional exponent
written ``E`` or ``EX`` (``-12.5``, ``.5``, ``1.2EX3``). Python spellings such as
``1_000``, ``inf`` or ``nan`` are not numbers on the panel.
"""

from __future__ import annotations

import math
import re
from typing import Any

from nck.refused import Refused

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:EX?[+-]?\d+)?", re.IGNORECASE)


class InvalidValue(Refused):
    """The operator's entry is not a value the datum can take; ``str()`` says what to enter."""


def number_from_text(value: Any, what: str, *, whole: bool = False) -> float:
    """``value`` (typed text or a number) as a finite number; ``whole``: a whole number.

    Raises:
        InvalidValue: empty text, text that is no number, an infinite or undefined
            number, a fraction where a whole number is needed.
    """
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise InvalidValue("value_enter_number", name=what)
    if isinstance(value, str):
        text = value.strip()
        if not text:
            raise InvalidValue("value_missing", name=what)
        if not _NUMBER.fullmatch(text):
            raise InvalidValue("value_not_a_number", name=what, text=text)
        number = float(re.sub("EX", "E", text, flags=re.IGNORECASE))
    else:
        number = float(value)
    if not math.isfinite(number):
        raise InvalidValue("value_out_of_range", name=what)
    if whole and not number.is_integer():
        raise InvalidValue("value_enter_whole_number", name=what)
    return number
