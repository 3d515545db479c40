"""Fuzzing the whole kernel: every input ends with an alarm, a normal end or the time budget.

Four kinds of hostile input go through :func:`tests.reliability.harness.run_hostile`
(AUTOMATIC, NC START, simulated time up to a budget, wall-clock guard): random
text, mutations of the golden programs, grammatical programs from the
language's own token set, random binary. A few hundred cases run in the
default suite; the ``fuzz`` marker (``make fuzz``) runs tens of thousands.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.lang.test_fuzz import TOKENS, programs
from tests.reliability.harness import golden_programs, run_hostile

GOLDEN = golden_programs()
GOLDEN_NAMES = sorted(GOLDEN)
FUZZ_BUDGET_S = 3.0  # simulated seconds per case: endless loops end here (like --timeout 3)

SHORT = settings(max_examples=100, deadline=None, suppress_health_check=list(HealthCheck), database=None)


def _long(count: int) -> settings:
    return settings(max_examples=count, deadline=None, suppress_health_check=list(HealthCheck),
                    database=None)


# ------------------------------------------------------------------------------------ strategies
random_text = st.text(max_size=400)
random_binary = st.binary(max_size=400).map(lambda raw: raw.decode("latin-1"))
token_programs = st.lists(st.sampled_from(TOKENS), max_size=80).map(" ".join)
structured_programs = st.lists(programs, max_size=5).map(
    lambda parts: "\n".join(["DEF INT CNT", "DEF REAL VALS[3]", *(l for p in parts for l in p), "M30"]))
grammatical = st.one_of(token_programs, structured_programs)

edit = st.tuples(st.sampled_from(["insert", "delete", "replace"]), st.floats(0.0, 1.0),
                 st.sampled_from(list("XYZGRMFST0123456789=()[]+-*/;:\"'$ \n,.<>E") + ["\x00", "\xff", "É"]))


@st.composite
def golden_mutations(draw: st.DrawFn) -> str:
    """A golden program with a few characters inserted, deleted or replaced."""
    text = GOLDEN[draw(st.sampled_from(GOLDEN_NAMES))]
    for kind, where, char in draw(st.lists(edit, min_size=1, max_size=6)):
        at = min(int(where * len(text)), max(len(text) - 1, 0))
        if kind == "insert":
            text = text[:at] + char + text[at:]
        elif kind == "delete":
            text = text[:at] + text[at + 1:]
        else:
            text = text[:at] + char + text[at + 1:]
    return text


def _run(text: str) -> None:
    run_hostile(text, sim_budget_s=FUZZ_BUDGET_S)


# ----------------------------------------------------------------------------- default (short)
@SHORT
@given(random_text)
def test_random_text_through_kernel(text: str) -> None:
    _run(text)


@SHORT
@given(random_binary)
def test_random_binary_through_kernel(text: str) -> None:
    _run(text)


@SHORT
@given(golden_mutations())
def test_golden_mutations_through_kernel(text: str) -> None:
    _run(text)


@SHORT
@given(grammatical)
def test_grammatical_programs_through_kernel(text: str) -> None:
    _run(text)


def test_every_golden_program_runs_cleanly_through_the_harness() -> None:
    """The unmutated golden programs: the harness itself finds no fault in good programs."""
    statuses = {name: run_hostile(text, sim_budget_s=FUZZ_BUDGET_S).status for name, text in GOLDEN.items()}
    assert statuses["23_setal_user_alarm"] == "alarm"
    assert statuses["05_operator_priority"] == "ended"


# ----------------------------------------------------------------------------------- make fuzz
@pytest.mark.fuzz
@_long(25_000)
@given(random_text)
def test_random_text_through_kernel_long(text: str) -> None:
    _run(text)


@pytest.mark.fuzz
@_long(15_000)
@given(random_binary)
def test_random_binary_through_kernel_long(text: str) -> None:
    _run(text)


@pytest.mark.fuzz
@_long(30_000)
@given(golden_mutations())
def test_golden_mutations_through_kernel_long(text: str) -> None:
    _run(text)


@pytest.mark.fuzz
@_long(30_000)
@given(grammatical)
def test_grammatical_programs_through_kernel_long(text: str) -> None:
    _run(text)
