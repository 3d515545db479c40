"""The G-group table of a language mode (``data/gcode/<dialect>.toml``).

Identity lives in the data: which G functions exist, their group, their
position inside the group, the reset default and whether the group is modal.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass

from nck.alarm_ids import G_FUNCTION_UNKNOWN
from nck.errors import NcAlarmError
from nck.resources import load_toml


@dataclass(frozen=True, slots=True)
class GGroup:
    """One G group: number, members in manual order, reset member, modality, meaning."""

    number: int
    members: tuple[str, ...]
    reset: str | None
    modal: bool
    meaning: str
    reset_by_kind: tuple[tuple[str, str], ...] = ()  # machine kind -> reset member (e.g. lathe: G18)

    def position(self, code: str) -> int:
        """1-based position of ``code`` in the group (the value ``$P_GG`` returns)."""
        return self.members.index(code) + 1


@dataclass(frozen=True, slots=True)
class GTable:
    """All G groups of a dialect, with a lookup from code to group."""

    groups: dict[int, GGroup]
    group_of: dict[str, int]

    def lookup(self, code: str) -> GGroup:
        """Return the group of a (normalised) G code; alarm 12470 if unknown."""
        number = self.group_of.get(code)
        if number is None:
            raise NcAlarmError(G_FUNCTION_UNKNOWN, code)
        return self.groups[number]

    def is_gcode(self, name: str) -> bool:
        """True if ``name`` (normalised) is a G function of this dialect."""
        return name in self.group_of

    def reset_state(self, overrides: dict[int, str] | None = None, kind: str = "mill") -> dict[int, str]:
        """The active code of every modal group after RESET.

        ``kind`` is the machine kind (``mill``/``lathe``): groups may name a
        different reset member per kind (``reset_lathe`` in the table);
        ``overrides`` (from MD20150 of the machine) win over both.
        """
        state: dict[int, str] = {}
        for number, group in self.groups.items():
            if not group.modal:
                continue
            member = dict(group.reset_by_kind).get(kind, group.reset)
            if member:
                state[number] = member
        if overrides:
            state.update(overrides)
        return state


_LEADING_ZEROS = re.compile(r"^G0+(\d)")


def normalize(code: str) -> str:
    """Normalise a G code as written: ``G01`` → ``G1``, ``g00`` → ``G0``."""
    code = code.upper()
    return _LEADING_ZEROS.sub(r"G\1", code)


@functools.cache
def gtable(dialect: str = "siemens") -> GTable:
    """Load and cache the G table of ``dialect``."""
    table = load_toml("gcode", f"{dialect}.toml")
    groups: dict[int, GGroup] = {}
    group_of: dict[str, int] = {}
    for entry in table["group"]:
        members = tuple(entry.get("members", ()))
        group = GGroup(
            number=int(entry["number"]),
            members=members,
            reset=entry.get("reset"),
            modal=bool(entry.get("modal", True)),
            meaning=entry.get("meaning", ""),
            reset_by_kind=tuple((key[len("reset_"):], value) for key, value in entry.items()
                                if key.startswith("reset_") and isinstance(value, str)),
        )
        groups[group.number] = group
        for code in members:
            if code:
                group_of[code] = group.number
    return GTable(groups=groups, group_of=group_of)


@functools.cache
def named_gcodes(dialect: str = "siemens") -> frozenset[str]:
    """G functions written as names (``BRISK``, ``CIP``, ``TRANS``…), not ``G<n>``.

    Made once per dialect (from the cached :func:`gtable`): the parser asks it for every name it reads.
    """
    return frozenset(c for c in gtable(dialect).group_of if not re.fullmatch(r"G\d+", c))
