"""The benchmark corpus (bench/corpus.py): both spellings mean the same tool path (issue 25).

The SINUMERIK spelling runs through ``nck``; the LinuxCNC spelling through LinuxCNC's own
interpreter ``rs274 -g`` when it is installed — an independent implementation, so equal
block end points show the corpus compares like with like (and that nck's arcs, CR= radii,
helices, subprogram calls, loops and drilling cycle end where another control ends them).
Small seeded samples keep the test fast.
"""

from __future__ import annotations

import functools
import shutil

import pytest

from bench.corpus import cam_milling, corpus
from bench.end_points import nck_end_points, rs274_end_points

SAMPLES = {program.name: program for program in corpus(0.01)}
TOLERANCE_MM = 2e-3  # both sides print/compare 3 decimals; R expressions may differ in the last ulp


def test_the_generator_is_seeded_and_writes_exactly_the_blocks_asked_for() -> None:
    first, again = cam_milling(3000, seed=7), cam_milling(3000, seed=7)
    assert first.siemens == again.siemens and first.linuxcnc == again.linuxcnc
    assert cam_milling(3000, seed=8).siemens != first.siemens
    assert len(first.siemens.splitlines()) == 3000 == len(first.linuxcnc.splitlines())


def test_the_cam_program_has_every_shape_of_cam_output() -> None:
    text = cam_milling(5000).siemens
    for shape in (" I", " J", "CR=", "G2 ", "G3 ", "; ", " F", "T2 D1 M6", "N4000 "):
        assert shape in text, shape
    helices = [line for line in text.splitlines() if line.split()[1:2] in (["G2"], ["G3"]) and " Z" in line]
    assert helices


@functools.lru_cache(maxsize=None)
def ours(name: str) -> list[tuple[float, float, float]]:
    return nck_end_points(SAMPLES[name])


@pytest.mark.parametrize("name", sorted(SAMPLES))
def test_nck_interprets_every_sample_to_its_end(name: str) -> None:
    assert len(ours(name)) > 20


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC rs274 not installed")
@pytest.mark.parametrize("name", sorted(SAMPLES))
def test_nck_and_rs274_give_the_same_block_end_points(name: str) -> None:
    theirs = rs274_end_points(SAMPLES[name])
    assert len(ours(name)) == len(theirs)
    worst = max(max(abs(a - b) for a, b in zip(p, q)) for p, q in zip(ours(name), theirs))
    assert worst <= TOLERANCE_MM
