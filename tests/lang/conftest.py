"""Shared helpers for the language tests: run program text through the interpreter."""

from __future__ import annotations

import pytest

from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def run_text(text: str, subprograms: dict[str, str] | None = None, data: NcData | None = None,
             timeout_s: float | None = 60.0, machine: str | None = None) -> HeadlessRun:
    """Run ``text`` as TEST.MPF with optional subprograms; returns the HeadlessRun."""
    source = MemorySource(subprograms or {})
    return interpret_only(load_machine(machine), source, data or NcData(), "TEST.MPF", text=text,
                          timeout_s=timeout_s, max_blocks=100_000)


@pytest.fixture
def run():
    """The run_text helper as a fixture."""
    return run_text
