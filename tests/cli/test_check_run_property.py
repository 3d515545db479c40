"""``nck check`` never says ok for a block the run would refuse (issue 20), on drawn programs.

Hypothesis draws small straight-line programs (no jumps or loops: every program ends) from the
language's motion, plane, frame, tool, spindle, contour-definition and data words, with values
that now and then leave the software limits (MD36110 X = 500 on the default mill) or the
circle's geometry. Each goes through the run (``nck run``'s kernel with motion, a bounded
simulated time) and through ``nck check`` (a block budget) and the editor's check: the three
must name the same first alarm (number and line), or none. The run's answer is the reference.
The one exception: a run that stands for ever in a block without an alarm (a thread or a
revolutional feed with the spindle at rest) never reaches the blocks the check reads on.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck.check import check_text
from nck.headless import check_program, run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from tests.cli.test_check_run_differential import data, first

MACHINE = load_machine(None)
RUN_TIMEOUT_S = 120.0  # simulated: the drawn programs take seconds at their feeds
CHECK_BLOCKS = 200  # block budget of the check (the programs have at most 9 blocks)

coordinate = st.sampled_from([-20, 0, 5, 10, 35, 120, 480, 520, 600])
small = st.sampled_from([0, 1, 2, 5, 10])
angle = st.sampled_from([0, 30, 90, 135, 200, 400])

WORDS = st.one_of(
    st.builds("G0 X{} Y{}".format, coordinate, coordinate),
    st.builds("G1 X{} F{}".format, coordinate, st.sampled_from([0, 500, 20000])),
    st.builds("G1 Y{} Z{}".format, coordinate, coordinate),
    st.builds("G2 X{} Y{} CR={}".format, coordinate, coordinate, st.sampled_from([-30, 5, 40, 400])),
    st.builds("G3 X{} Y{} I{} J{}".format, coordinate, coordinate, small, small),
    st.builds("G1 X{} ANG={}".format, coordinate, angle),
    st.builds("X{} CHF={}".format, coordinate, small),
    st.builds("Y{} RND={}".format, coordinate, small),
    st.sampled_from([
        "G90", "G91", "G17", "G18", "G19", "G40", "G41", "G42", "G500", "G54", "G53 X0",
        "T1 M6 D1", "T5 M6", "D4", "D0", "S1000 M3", "M5", "G95 F0.2", "G94 F1000", "G4 F0.1",
        "G4 S2", "G96 S100 LIMS=2000", "G97", "SPOS=90", "M19", "G58 X10", "G26 X100", "WALIMON",
        "TRANS X10", "ROT RPL=30", "MIRROR X0", "SCALE X2", "R1=5", "R2=R1/0", "$SC_THREAD_START_ANGLE=30",
        "G33 Z-5 K1", "CHF=2", "G93 F2", "OVR=50", "ACC[X]=50", "SETAL(65000)", "G0 X=AC(10)",
    ]),
)
PROGRAMS = st.lists(WORDS, min_size=1, max_size=8).map(
    lambda blocks: "".join(f"N{10 * (k + 1)} {b}\n" for k, b in enumerate(blocks + ["M30"])))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(PROGRAMS)
def test_check_names_the_first_alarm_of_the_run_on_drawn_programs(text: str) -> None:
    run = run_program(MACHINE, MemorySource({}), data(), "P.MPF", text=text, timeout_s=RUN_TIMEOUT_S)
    if run.status == "timeout" and not run.alarms:
        # The run stands in a block (G33 or G95 with the spindle at rest waits without an
        # alarm, 002 L55411-55420): the check, which reads on, may name an alarm of a later
        # block the run never reached.
        return
    reference = first(run.alarms)
    checked = check_program(MACHINE, MemorySource({}), "P.MPF", text, data(), max_blocks=CHECK_BLOCKS)
    assert first(checked) == reference, text
    assert first(check_text("P.MPF", text, machine=MACHINE, data=data())) == reference, text


@pytest.mark.fuzz
@settings(max_examples=2000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(PROGRAMS)
def test_check_names_the_first_alarm_of_the_run_fuzz(text: str) -> None:
    test_check_names_the_first_alarm_of_the_run_on_drawn_programs.hypothesis.inner_test(text)
