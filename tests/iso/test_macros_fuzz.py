"""Random ISO programs made of calls, returns, macros and tool-offset words: every outcome
is a normal end, an NC alarm or the block budget — never a Python exception."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

WORDS = ["M98 P21", "M98 P30021", "M98 P21 L2", "M98 P22", "M99", "M99 P30", "M99 P-3", "M30",
         "G65 P10 X1. I2 J3 I4", "G65 P10 L2 F5", "G65 P10 L0", "G65 P1.5", "G66 P10 Y2.",
         "G66 P22", "G67", "G05 P21", "G05 P1 M98 P21", "G00 X1.", "G91 G01 X1. F100", "G90",
         "T2 G43 H4 Z0", "G43 H9", "G41 D5 X3.", "G40 X0 Y0", "G49", "G10 L10 P4 R2.",
         "G10 L13 P9 R1.", "G10 L12 P4", "G04 X1000", "G04 P500", "G95 G04 X2", "N30 X2.",
         "G290", "G291", "G65 P12345", "M98", "G65 X1.", "D0", "M6 X1.", "G123 X2.",
         "M101 L2", "G21 X1.", "M6 M101"]

SUBS = {"O0021": "G91 G00 X1.\nM99\n", "O0022": "N1 G00 Y1.\nM99 P30\n",
        "O0010": "G290\nR1=$C_X+$C_I[1]+$C_F R2=R2+1\nG291\nM99\n",
        "M6_MACRO": "M6\nG123\nM99\n", "G123_MACRO": "G290\nR3=$C_G\nG291\nG21 M6 X$C_X\nM99\n",
        "M101_MACRO": "G65 P10 X1.\nM99\n"}
MACRO_MD = {"MD10814": [101, 6], "MD10815": ["M101_MACRO", "M6_MACRO"],
            "MD10816": [123], "MD10817": ["G123_MACRO"]}
SETUP = "G290\n$TC_DP1[2,3]=120 $TC_DP3[2,3]=10\n$TC_DPH[2,3]=4\n$TC_DPH[2,5]=5\nG291\n"


@settings(max_examples=60, deadline=None)
@given(lines=st.lists(st.sampled_from(WORDS), min_size=1, max_size=8),
       md=st.sampled_from([{}, {"MD10884": False}, {"MD20734": 4, "MD22550": 0}, MACRO_MD]))
def test_random_call_programs_raise_only_nc_alarms(lines, md):
    machine = load_machine(None)
    machine.md.update(md)
    text = SETUP + "\n".join(lines) + "\nM30\n"
    result = interpret_only(machine, MemorySource(SUBS), NcData(), "T.MPF", dialect="iso-m",
                            text=text, max_blocks=400)
    assert result.status in ("ended", "alarm", "timeout")
    for alarm in result.alarms:
        assert 10000 <= alarm.number < 70000
