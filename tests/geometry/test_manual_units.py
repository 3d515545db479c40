"""Inch/metric rules of Function Manual 002 (section G2)."""

from __future__ import annotations

import pytest

from nck.headless import run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def on_kernel(text: str):
    return run_program(load_machine(), MemorySource({}), NcData(), "U.MPF", text=text)


def test_aa_iw_is_read_in_the_basic_system_under_g70() -> None:
    """Digest 828d-1 rank 20 (G70: WCS in inch, basic system metric)."""
    # 002 L11680-11697 and table L11793-11817: length-related system variables are read in
    # the basic system (mm) under G70/G71, in the programmed system under G700/G710.
    text = "N10 G70 G1 X1 F100\nN20 R1=$AA_IW[X]\nN30 G700\nN40 R2=$AA_IW[X]\nN50 M30\n"
    data = NcData()
    result = run_program(load_machine(), MemorySource({}), data, "U.MPF", text=text)
    assert result.status == "ended", result.alarms
    assert data.r[1] == pytest.approx(25.4)
    assert data.r[2] == pytest.approx(1.0)


def test_a_g700_feed_keeps_its_physical_value_after_g710() -> None:
    # 002 L11662-11667: the programmed feed is modal and stays active after G70/G71/G700/G710;
    # to apply in the new context it must be programmed again. F100 under G700 is 2540 mm/min:
    # after G710 the block runs as with F2540; F100 programmed under G710 is 100 mm/min:
    # 25.4 mm take 15.24 s instead of 0.6 s.
    kept = on_kernel("N10 G0 X25.4\nN20 G700 F100\nN30 G710 G1 X0\nN40 M30\n").machine_time_s
    metric = on_kernel("N10 G0 X25.4\nN20 G710 F2540\nN30 G710 G1 X0\nN40 M30\n").machine_time_s
    again = on_kernel("N10 G0 X25.4\nN20 G700 F100\nN30 G710 G1 X0 F100\nN40 M30\n").machine_time_s
    assert kept == pytest.approx(metric, abs=1e-9)
    apart = on_kernel("N10 G0 X25.4\nN20 G700 F100\nN30 G710\nN35 G1 X0\nN40 M30\n").machine_time_s
    assert apart == pytest.approx(metric + 0.002, abs=0.003)  # one block more
    assert again - kept == pytest.approx(15.24 - 0.6, abs=0.1)  # ramps: a few hundredths
