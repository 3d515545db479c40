"""Property test: random operator command sequences never break the channel.

Any sequence of mode changes, NC START/STOP, RESET, alarm cancel, JOG keys,
program control switches, E-stop and time never raises, never produces an
internal error, always stays inside the transition table, and RESET always
returns to channel reset / program aborted (unless E-stop is still pressed,
when the state is reset as well but alarm 3000 stays).
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck import commands as c
from nck.channel import is_valid
from tests.kernel.helpers import make_nck

PROGRAMS = {
    "P": "N10 G1 X20 F3000\nN20 M01\nN30 R1=2\nN40 G0 Y5\nN50 M00\nN60 G1 Z-3 F2000\nN70 M30",
    "E": "N10 G1 X5 F3000\nN20 ERR\nN30 M30",
    "S": "N10 SETAL(61000)\nN20 M30",
}

COMMANDS = st.one_of(
    st.sampled_from(["JOG", "MDA", "AUTO"]).map(c.SelectMode),
    st.just(c.CycleStart()),
    st.just(c.CycleStop()),
    st.just(c.Reset()),
    st.just(c.CancelAlarms()),
    st.sampled_from(["P", "E", "S", "NOPE"]).map(c.SelectProgram),
    st.sampled_from([None, "REF", "REPOS", "INC"]).map(c.SelectMachineFunction),
    st.sampled_from([1, 100, 10000, None]).map(c.SelectIncrement),
    st.builds(c.Jog, st.sampled_from(["X", "Y", "Z"]), st.sampled_from([-1, 0, 1])),
    st.builds(c.SetProgramControl, st.just("single_block"), st.sampled_from([None, "SBL1", "SBL2"])),
    st.builds(c.SetProgramControl, st.sampled_from(["m01", "dry_run", "program_test"]), st.booleans()),
    st.builds(c.EmergencyStop, st.booleans()),
    st.sampled_from(["N40", "N60", "Y5", "N99"]).map(c.StartBlockSearch),
    st.just(c.SetMdaProgram("G1 X3 F1000\nM0\nG0 Z1")),
    st.floats(min_value=0.0, max_value=2.0).map(lambda s: ("tick", s)),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(COMMANDS, min_size=1, max_size=40), st.booleans())
def test_random_command_sequences_keep_the_channel_consistent(sequence, referenced) -> None:
    nck = make_nck(PROGRAMS, referenced=referenced)
    for item in sequence:
        if isinstance(item, tuple):
            nck.tick(item[1])
        else:
            result = nck.submit(item)
            assert isinstance(result, (c.Accepted, c.Rejected))
            if isinstance(item, c.Reset):
                status = nck.status()
                assert (status.channel.channel_state, status.channel.program_state) == ("reset", "aborted")
        assert is_valid(nck.situation), nck.situation
        if nck.situation.program == "aborted":
            assert nck.channel.run is None and nck.channel.overlay is None
        assert nck.internal_errors == []
    status = nck.status()
    assert (status.channel.mode, status.channel.channel_state, status.channel.program_state) == (
        nck.situation.mode, nck.situation.channel, nck.situation.program)
    nck.submit(c.EmergencyStop(False))
    assert nck.submit(c.Reset()) == c.Accepted()
    assert (nck.situation.channel, nck.situation.program) == ("reset", "aborted")
    assert 3000 not in [a.number for a in nck.status().alarms]


REAL_PROGRAMS = {
    "P.MPF": "N10 G0 X10 Y5\nN20 M01\nN30 R1=R1+1\nN40 G1 Z-2 F2000\nN50 M00\nN60 G91 X5\nN70 M30",
    "E.MPF": "N10 G1 X5 F3000\nN20 X=\nN30 M30",
}
REAL_COMMANDS = st.one_of(
    COMMANDS,
    st.sampled_from(["P.MPF", "E.MPF"]).map(c.SelectProgram),
    st.sampled_from(["N40", "N60", "X5"]).map(c.StartBlockSearch),
    st.builds(c.SetOverride, st.sampled_from(["feed", "rapid", "spindle"]), st.sampled_from([0, 50, 100, 120, 200])),
    st.builds(c.WriteData, st.sampled_from(["R1", "SD42100", "$AC_REQUIRED_PARTS", "MD1"]), st.sampled_from([0, 3, "x"])),
)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(REAL_COMMANDS, min_size=1, max_size=30))
def test_random_commands_with_the_real_interpreter(sequence) -> None:
    from nck.interp.sources import MemorySource
    from nck.kernel import Nck
    from nck.motion.instant import instant_motion_factory

    nck = Nck(programs=MemorySource(REAL_PROGRAMS), referenced=True, motion_factory=instant_motion_factory)
    for item in sequence:
        if isinstance(item, tuple):
            nck.tick(item[1])
        else:
            assert isinstance(nck.submit(item), (c.Accepted, c.Rejected))
        assert is_valid(nck.situation), nck.situation
        assert nck.internal_errors == []
    nck.status()
    nck.submit(c.EmergencyStop(False))
    nck.submit(c.Reset())
    assert (nck.situation.channel, nck.situation.program) == ("reset", "aborted")
