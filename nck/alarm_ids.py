"""Named alarm numbers: a name for each SINUMERIK alarm the kernel raises by number.

The catalogue ``data/alarms/*.toml`` owns everything else about an alarm (text,
category, clear criterion, reactions); this module only gives the numbers names,
so code reads ``NcAlarmError(SYNTAX_ERROR, text)`` instead of ``NcAlarmError(12080, text)``.
Each name says what the catalogue text says; ``tests/test_alarm_ids.py`` checks that
every number here has a catalogue entry and that no number has two names.

Every package of ``nck`` raises with these names (or with module constants
``ALARM_… = number`` that name catalogue entries); ``tests/test_alarm_ids.py``
fails on a raise written with a bare number.
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

CHAMFER_OR_ROUNDING_WITHOUT_PATH_MOTION = 10882
"""Chamfer or rounding programmed in a block without path motion."""

ADDRESS_PROGRAMMED_TWICE = 12000
"""Address %3 programmed more than once."""

G_GROUP_PROGRAMMED_TWICE = 12060
"""G group %3 programmed more than once."""

OPERATION_DOES_NOT_FIT_TYPE = 12150
"""Operation %3 does not fit the data type."""

NAME_DEFINED_TWICE = 12170
"""Name %3 defined more than once."""

STRING_TOO_LONG = 12210
"""String %3 too long."""

TOO_MANY_INITIAL_VALUES = 12260
"""Too many initial values for %3."""

PARAMETER_NOT_A_VARIABLE = 12320
"""Parameter %3 is not a variable."""

TOO_MANY_CALL_PARAMETERS = 12340
"""Too many parameters in call of %3."""

LABEL_DEFINED_TWICE = 12450
"""Label %3 defined twice."""

CONTROL_STRUCTURES_NOT_NESTED = 12640
"""Control structures not correctly nested."""

CONTROL_STRUCTURES_TOO_DEEP = 12641
"""Control structures nested too deeply."""

SUBPROGRAM_LEVEL_EXCEEDED = 14012
"""Maximum subprogram level exceeded."""

PASS_COUNT_NOT_ALLOWED = 14013
"""Number of subprogram passes not allowed."""

ARITHMETIC_ERROR = 14051
"""Arithmetic error in the part program."""

SKIP_LEVEL_NOT_ALLOWED = 14060
"""Skip level %3 not allowed (only 1 to 9)."""

STRING_NOT_AN_AXIS = 14097
"""String %3 cannot be converted to type AXIS."""

NO_VALID_NUMBER = 14098
"""Conversion error, no valid number in %3."""

STRING_RESULT_TOO_LONG = 14099
"""Result of string operation %3 too long."""

DEFINITION_AFTER_STATEMENT = 14500
"""DEF or PROC not allowed after the first executable statement."""

POSITION_OUTSIDE_MODULO_RANGE = 16830
"""Position outside the modulo range 0 to 360 degrees."""

ILLEGAL_ARRAY_INDEX_1 = 17020
"""Illegal array index 1 %3."""

ILLEGAL_ARRAY_INDEX_2 = 17030
"""Illegal array index 2 %3."""

ILLEGAL_AXIS_INDEX = 17040
"""Illegal axis index %3."""
