"""When an auxiliary function goes out relative to the motion of its block (002 L14480-14636).

Each auxiliary function has an output behaviour: the predefined ones (M0 … M30, M6, M3/M4/M5,
M19, M70, M40 … M45, S, F, D, DL, T) in MD22080 ``AUXFU_PREDEF_SPEC[index]``, user-defined ones
(M8, H5 …) in MD22035 ``AUXFU_ASSIGN_SPEC[n]`` for the entry ``n`` whose type MD22010,
extension MD22020 and value MD22030 match (-1 matches any). Bit 5 puts the output before the
block's traversing motion, bit 6 during it, bit 7 after it (block end); a function without a
defined behaviour goes out at block end (002 L14633-14636).

The channel turns these into motion: an output before the motion ends the previous block with
exact stop first, an output at block end ends the block's own motion at interpolator end, and
a block with outputs but no path motion ends the previous block with exact stop
(002 L4797-4809). The PLC acknowledgement (bits 0, 1, 4) is not modelled: without a PLC cycle
every output is acknowledged at once.
"""

from __future__ import annotations

from typing import Any

from nck.machine import MachineConfig
from nck.machine_data import catalog

BEFORE = "before"
DURING = "during"
AFTER = "after"

BIT_BEFORE = 1 << 5
BIT_DURING = 1 << 6
BIT_AFTER = 1 << 7
UNDEFINED_SPEC = (1 << 0) | BIT_AFTER  # 002 L14633-14636

# Index of MD22080 per predefined function (002 L13903-13960; spindle 1 for every spindle).
GENERAL_M_INDEX = {0: 0, 1: 1, 2: 2, 17: 3, 30: 4, 6: 5}
SPINDLE_M_INDEX = {3: 6, 4: 7, 5: 8, 19: 9, 70: 10, 40: 11, 41: 12, 42: 13, 43: 14, 44: 15, 45: 16}
ADDRESS_INDEX = {"S": 17, "F": 18, "D": 19, "DL": 20, "T": 21}


def _array(machine: MachineConfig, ident: str) -> list[Any]:
    """The elements of an array datum: the machine file's value over the catalogue default."""
    definition = catalog().get(ident)
    assert definition is not None, ident
    size = definition.array or 1
    default = definition.default
    values = list(default) if isinstance(default, list) else [default] * size
    given = machine.md_value(ident)
    if isinstance(given, list):
        values[:len(given)] = given
    elif given is not None:
        values = [given] * size
    return values


def timing_of_spec(spec: int) -> str:
    """``before``/``during``/``after`` of an output-behaviour bit mask (bit 5 first)."""
    if spec & BIT_BEFORE:
        return BEFORE
    if spec & BIT_DURING:
        return DURING
    return AFTER


class AuxOutputTiming:
    """The output timing of the auxiliary functions of one machine (see the module docstring)."""

    def __init__(self, machine: MachineConfig) -> None:
        self.predefined = [int(v or 0) for v in _array(machine, "MD22080")]
        types = _array(machine, "MD22010")
        extensions = _array(machine, "MD22020")
        values = _array(machine, "MD22030")
        specs = _array(machine, "MD22035")
        self.user = [
            (str(t).strip().upper(), int(e or 0), int(v or 0), int(s or 0))
            for t, e, v, s in zip(types, extensions, values, specs) if str(t or "").strip()
        ]

    def spec(self, address: str, extension: int | None, value: float | None) -> int:
        """The output-behaviour bits of the function ``address extension = value``."""
        address = address.upper()
        index: int | None = None
        if address == "M" and value is not None and int(value) == value:
            number = int(value)
            if extension in (None, 0) and number in GENERAL_M_INDEX:
                index = GENERAL_M_INDEX[number]
            elif number in SPINDLE_M_INDEX and number not in GENERAL_M_INDEX:
                index = SPINDLE_M_INDEX[number]
        elif address in ADDRESS_INDEX:
            index = ADDRESS_INDEX[address]
        if index is not None and index < len(self.predefined):
            return self.predefined[index]
        ext = 0 if extension is None else extension
        for kind, user_ext, user_value, user_spec in self.user:
            if kind != address or user_ext not in (-1, ext):
                continue
            if user_value == -1 or (value is not None and user_value == value):
                return user_spec
        return UNDEFINED_SPEC

    def timing(self, address: str, extension: int | None = None, value: float | None = None) -> str:
        """``before``, ``during`` or ``after`` the block's motion."""
        return timing_of_spec(self.spec(address, extension, value))
