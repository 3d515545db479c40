"""Which sample programs a fresh data directory of a machine kind gets (data/sample_programs.toml)."""

from __future__ import annotations

import tomllib
from typing import Callable

from nck.resources import data_path

SAMPLE_PROGRAMS = "sample_programs.toml"


def sample_filter(machine_kind: str) -> Callable[[str], bool]:
    """A test on an upper-case sample file name: the programs listed under ``machine_kind``;
    for a kind without a list (the mill) every program not listed under another kind."""
    with open(data_path(SAMPLE_PROGRAMS), "rb") as handle:
        kinds: dict[str, list[str]] = tomllib.load(handle)["kinds"]
    if machine_kind in kinds:
        own = frozenset(name.upper() for name in kinds[machine_kind])
        return lambda name: name in own
    others = frozenset(name.upper() for names in kinds.values() for name in names)
    return lambda name: name not in others
