"""Workpiece counters and the program runtime timer (K1 "Times/Counter").

* ``$AC_TOTAL_PARTS`` / ``$AC_ACTUAL_PARTS`` / ``$AC_SPECIAL_PARTS`` count per
  ``MD27880 $MC_PART_COUNTER``: bits 4 / 8 / 12 switch each counter on; bits
  5 / 9 / 13 make it count on the M code in ``MD27882[0/1/2]`` instead of
  M2/M30; bits 6 / 10 / 14 stop it counting during program test; bit 0 with
  ``$AC_REQUIRED_PARTS`` > 0 wraps the compared counter (bit 1: SPECIAL,
  else ACTUAL) to 0 when it reaches the target. Mode change and RESET never
  change a counter.
* ``$AC_ACT_PROG_NET_TIME`` counts while a program runs in AUTOMATIC (not
  while stopped), is zeroed when a program starts from channel reset, only
  halted by RESET; a correct end (M2/M30) copies it to
  ``$AC_OLD_PROG_NET_TIME`` and increments ``$AC_OLD_PROG_NET_TIME_COUNT``.

When the machine file gives no MD27880, the kernel uses :data:`DEFAULT_PART_COUNTER`
(TOTAL and ACTUAL count on M2/M30), so the counter display does something
on a fresh trainer.
"""

from __future__ import annotations

from dataclasses import dataclass

DEFAULT_PART_COUNTER = 0x110
_COUNTERS = (("total", 4), ("actual", 8), ("special", 12))


@dataclass
class PartCounters:
    """The four workpiece counters and their configuration."""

    mode_bits: int = DEFAULT_PART_COUNTER
    m_codes: tuple[int, int, int] = (2, 2, 2)  # MD27882[0..2]
    total: int = 0
    actual: int = 0
    special: int = 0
    required: int = 0

    def on_program_end(self, program_test: bool) -> None:
        """Count counters configured to count on M2/M30."""
        for name, bit in _COUNTERS:
            if not self._uses_m_code(bit):
                self._count(name, bit, program_test)

    def on_m_function(self, value: int, program_test: bool) -> None:
        """Count counters configured to count on the M code ``value``."""
        for index, (name, bit) in enumerate(_COUNTERS):
            if self._uses_m_code(bit) and value == self.m_codes[index]:
                self._count(name, bit, program_test)

    def _uses_m_code(self, bit: int) -> bool:
        return bool(self.mode_bits & (1 << (bit + 1)))

    def _count(self, name: str, bit: int, program_test: bool) -> None:
        if not self.mode_bits & (1 << bit):
            return
        if program_test and self.mode_bits & (1 << (bit + 2)):
            return
        setattr(self, name, min(getattr(self, name) + 1, 999_999_999))
        compared = "special" if self.mode_bits & 0b10 else "actual"
        if self.mode_bits & 1 and self.required > 0 and name == compared:
            if getattr(self, name) >= self.required:
                setattr(self, name, 0)


@dataclass
class RuntimeTimer:
    """``$AC_ACT_PROG_NET_TIME`` and its "old" copy and count."""

    act_s: float = 0.0
    old_s: float = 0.0
    old_count: int = 0

    def start_from_reset(self) -> None:
        """A program starts from channel reset in AUTOMATIC."""
        self.act_s = 0.0

    def run(self, dt_s: float) -> None:
        """The program ran ``dt_s`` seconds."""
        self.act_s += dt_s

    def program_end(self) -> None:
        """Correct end (M2/M30): copy to OLD and count."""
        self.old_s = self.act_s
        self.old_count += 1
