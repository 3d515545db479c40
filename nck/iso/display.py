"""The G-group display in ISO mode: ISO codes derived from the Siemens modal state.

ISO and Siemens mode share one modal state (Table 2-3 of the ISO dialects
manual maps the equivalent groups). :func:`iso_gcodes` shows it in ISO terms:
ISO group number → active ISO code; groups with no Siemens counterpart show
their ISO reset code from ``data/gcode/iso_m.toml`` / ``iso_t.toml``.
"""

from __future__ import annotations

import functools
from typing import Mapping

from nck.alarm_ids import ILLEGAL_ARRAY_INDEX_1
from nck.errors import NcAlarmError
from nck.iso.frames import display_codes
from nck.lang.dialect import InterpreterContext
from nck.lang.values import to_number
from nck.resources import load_toml

ISO_MAIN_GROUPS_M = (1, 2, 3, 5, 6, 7, 8, 14)
"""ISO M groups of the one-line G-functions window: motion, plane, dimension, feed, unit, TRC,
tool length, zero offset."""

_MOTION = {"G0": "G00", "G1": "G01", "G2": "G02", "G3": "G03", "G33": "G33"}
_UNITS = {"G70": "G20", "G700": "G20", "G71": "G21", "G710": "G21"}
_ZERO_OFFSET = {"G54": "G54", "G55": "G55", "G56": "G56", "G57": "G57", "G505": "G58",
                "G506": "G59"}
_EXACT_STOP = {"G60": "G61", "G64": "G64"}
_CUTTING_SPEED = {"G96": ("G95", "G96"), "G961": ("G94", "G96"), "G97": ("G95", "G97"),
                  "G971": ("G94", "G97")}


@functools.cache
def iso_table(dialect: str) -> tuple[dict[int, str], dict[int, str]]:
    """(group → reset code, group → meaning) of ``iso-m`` / ``iso-t``."""
    table = load_toml("gcode", f"{dialect.replace('-', '_')}.toml")
    resets = {int(g["number"]): str(g["reset"]) for g in table["group"] if g.get("reset")}
    meanings = {int(g["number"]): str(g.get("meaning", "")) for g in table["group"]}
    return resets, meanings


def iso_gcodes(siemens: Mapping[int, str], dialect: str = "iso-m") -> dict[int, str]:
    """ISO group → active ISO code for the Siemens modal state ``siemens`` (group → code)."""
    turning = dialect == "iso-t"
    resets, _ = iso_table("iso-t" if turning else "iso-m")
    view = dict(resets)
    plane_group = 16 if turning else 2
    if siemens.get(1) in _MOTION:
        view[1] = _MOTION[siemens[1]]
    if siemens.get(6) in ("G17", "G18", "G19"):
        view[plane_group] = siemens[6]
    if siemens.get(14) in ("G90", "G91"):
        view[3] = siemens[14]
    if siemens.get(15) in ("G94", "G95"):
        view[5] = siemens[15]
    elif siemens.get(15) in _CUTTING_SPEED:  # Siemens group 15 = ISO feed type + G96/G97
        view[5], view[2 if turning else 13] = _CUTTING_SPEED[siemens[15]]
    if siemens.get(13) in _UNITS:
        view[6] = _UNITS[siemens[13]]
    if siemens.get(7) in ("G40", "G41", "G42"):
        view[7] = siemens[7]
    if siemens.get(8) in _ZERO_OFFSET:
        view[14] = _ZERO_OFFSET[siemens[8]]
    if not turning and siemens.get(10) in _EXACT_STOP:
        view[15] = _EXACT_STOP[siemens[10]]
    view[31] = "G291"
    return view


@functools.cache
def iso_members(dialect: str) -> dict[int, tuple[str, ...]]:
    """ISO group → its codes in value order (position + 1 = ``$P_EXTGG`` value)."""
    table = load_toml("gcode", f"{dialect.replace('-', '_')}.toml")
    return {int(g["number"]): tuple(str(c) for c in g.get("members", ())) for g in table["group"]}


def extgg(siemens: Mapping[int, str], dialect: str, group: int, geometry: object = None) -> int:
    """``$P_EXTGG[group]``: the value of the active ISO code of ``group`` (0 = none), in either
    language mode (the modal state is shared)."""
    turning = dialect == "iso-t"
    view = iso_gcodes(siemens, "iso-t" if turning else "iso-m")
    if siemens.get(47) != "G291":
        view[31] = "G290"
    if not turning:
        view.update(display_codes(geometry))
    members = iso_members("iso-t" if turning else "iso-m").get(group, ())
    code = view.get(group)
    return members.index(code) + 1 if code in members else 0


def read_extgg(ctx: InterpreterContext, mode: str, indices: tuple) -> int:
    """System-variable hook: ``$P_EXTGG[n]`` for the interpreter ``ctx`` in language mode ``mode``."""
    if len(indices) != 1:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "$P_EXTGG")
    modal = ctx.modal
    return extgg(modal.gcodes, mode, int(to_number(indices[0], "$P_EXTGG")), modal.geometry)
