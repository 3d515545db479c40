"""Inch / metric: what G70, G71, G700 and G710 convert.

The kernel computes in millimetres. The programmed measuring system (G group
13) says in which unit the program writes values; the basic system
(``MD10240 SCALING_SYSTEM_IS_METRIC``) says in which unit the stored data
(tool offsets, settable frames, machine data) are kept.

What each code converts (Function Manual Basic Functions, G2, table "reading
and writing of data in the case of G70/G71 and G700/G710"):

* positions X Y Z, interpolation parameters I J K, CR, RP, thread lead and the
  programmable frame: always in the programmed system (all four codes);
* feeds: G700/G710 in the programmed system; G70/G71 in the basic system;
* settable frames, tool offsets, length-related machine/setting data and
  system variables: G700/G710 in the programmed system; G70/G71 in the basic
  system.

The conversion factor is ``MD10250 SCALING_VALUE_INCH`` (default 25.4).
"""

from __future__ import annotations

from dataclasses import dataclass, field

INCH_MM = 25.4  # MD10250 SCALING_VALUE_INCH / MD31200 SCALING_FACTOR_G70_G71 default
UNIT_CODES = ("G70", "G71", "G700", "G710")


@dataclass(frozen=True, slots=True)
class UnitSystem:
    """The active member of G group 13 with the basic system it works against.

    Attributes:
        code: ``G70``, ``G71``, ``G700`` or ``G710``.
        basic_metric: ``MD10240`` (True = the stored data are in mm).
        inch_mm: millimetres per inch (``MD10250``).
    """

    code: str = "G71"
    basic_metric: bool = True
    inch_mm: float = INCH_MM
    position_mm: float = field(init=False, repr=False, compare=False)
    """Millimetres per programmed length unit (positions, I J K, CR, RP, lead, frames): set
    from ``code`` once (every axis value of every block reads it)."""

    def __post_init__(self) -> None:
        if self.code not in UNIT_CODES:
            raise ValueError(f"not an inch/metric code: {self.code}")
        object.__setattr__(self, "position_mm", self.inch_mm if self.programmed_inch else 1.0)

    @property
    def programmed_inch(self) -> bool:
        """True when the program writes lengths in inch (G70/G700)."""
        return self.code in ("G70", "G700")

    @property
    def converts_feed(self) -> bool:
        """True when F is read in the programmed system (G700/G710)."""
        return self.code in ("G700", "G710")

    @property
    def basic_mm(self) -> float:
        """Millimetres per unit of the basic system."""
        return 1.0 if self.basic_metric else self.inch_mm

    @property
    def feed_mm(self) -> float:
        """Millimetres per length unit of a programmed feed (mm/min, mm/rev)."""
        return self.position_mm if self.converts_feed else self.basic_mm

    @property
    def data_mm(self) -> float:
        """Millimetres per length unit of stored data written or read by the program
        (tool offsets, settable frames, length-related MD/SD/system variables)."""
        return self.position_mm if self.converts_feed else self.basic_mm

    def position_to_mm(self, value: float) -> float:
        """Convert a programmed length into mm."""
        return value * self.position_mm

    def position_from_mm(self, value_mm: float) -> float:
        """Convert mm into the programmed length unit (for WCS display)."""
        return value_mm / self.position_mm

    def feed_to_mm(self, value: float) -> float:
        """Convert a programmed feed (per min or per rev) into mm units."""
        return value * self.feed_mm
