"""Named alarm numbers: a name for each SINUMERIK alarm the kernel raises by number.

The catalogue ``data/alarms/*.toml`` owns everything else about an alarm (text,
category, clear criterion, reactions); this module only gives the numbers names,
so code reads ``NcAlarmError(SYNTAX_ERROR, text)`` instead of ``NcAlarmError(12080, text)``.
Each name says what the catalogue text says; ``tests/test_alarm_ids.py`` checks that
every number here has a catalogue entry and that no number has two names.

Packages whose raises use these names: ``nck.lang``, ``nck.geometry`` (besides
the module constants it already had) and the top-level kernel modules; the
rest still use literals, counted by the test so that the number only goes down.
"""

from __future__ import annotations

INTERNAL_ERROR = 1
"""An internal error of the simulation (a bug, or a refusal without an NC alarm of its own)."""


SYNTAX_ERROR = 12080
"""Syntax error in text %3."""

VALUE_RANGE_EXCEEDED = 12160
"""Value range exceeded %3."""

ARRAY_TOO_MANY_DIMENSIONS = 12190
"""Variable %3 of type ARRAY has too many dimensions."""

MEMORY_CAPACITY_REACHED = 12380
"""Variable memory (MD28040, MD18150) or tool offset memory (MD18100) used up."""

IDENTIFIER_TOO_LONG = 12420
"""Identifier %3 too long."""

G_FUNCTION_UNKNOWN = 12470
"""G function %3 is unknown."""

BLOCK_TOO_COMPLEX = 12540
"""Block too long or too complex."""

NAME_NOT_DEFINED = 12550
"""Name %3 not defined or option/function not available."""

VALUE_OUTSIDE_LIMITS = 12560
"""Programmed value %3 is outside the permitted limits."""

PROGRAM_NOT_FOUND = 14011
"""Program %3 does not exist or is not released for processing."""

WRONG_AXIS_TYPE = 14092
"""Axis %3 is the wrong axis type for this instruction."""

TYPE_CONVERSION_IMPOSSIBLE = 14096
"""Type conversion not possible %3."""

CHAMFER_OR_ROUNDING_NEGATIVE = 16500
"""Chamfer or rounding is negative."""

DATA_WRITE_PROTECTED = 17070
"""Data item %3 is write-protected."""

WRONG_CALL_ARGUMENTS = 14020
"""Wrong value or wrong number of parameters in a function or procedure call."""

STOCK_REMOVAL_CONTOUR_ERROR = 10931
"""Error in the stock removal contour (a turning cycle's contour subprogram)."""

VALUE_BELOW_LOWER_LIMIT = 17080
"""Value of %3 below the lower limit."""

VALUE_ABOVE_UPPER_LIMIT = 17090
"""Value of %3 above the upper limit."""

JUMP_TARGET_NOT_FOUND = 14080
"""Jump destination %3 not found."""
