"""Auxiliary-function output timing relative to the motion (digest 828d-1 rank 6, rank 7).

Manual 002: the output behaviour of the predefined functions is MD22080 (table L14480-14540:
M3 index 6, D index 19, T index 21 have bit 5 "before the motion"; S index 17 has bit 6
"during the motion"), of user-defined ones MD22035 (L14920-14927); a function without a defined
behaviour goes out at block end (bit 7, L14633-14636). Implicit exact stop (L4797-4809): an
output before the motion ends the previous block with exact stop; an output after the motion
goes out after the interpolator end of its block. A following block with an output before the
motion makes the axes stop between the blocks (L4955-4956).

Run on the real interpreter and the default planned motion, cycle by cycle.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from nck import canon
from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine
from tests.geometry.golden.helpers import lines, run

FEED_MM_MIN = 3000.0  # 50 mm/s: 0.2 mm per IPO cycle of 4 ms at full speed


def _run_cycles(program: str, md: dict | None = None) -> list[tuple[float, dict[str, str], str]]:
    """(X setpoint, aux outputs, spindle state) after every IPO cycle until the program ends."""
    machine = load_machine()
    if md:
        machine = dataclasses.replace(machine, md={**machine.md, **md})
    nck = Nck(machine=machine, programs=MemorySource({"P.MPF": program}), referenced=True, batch_cycles=1)
    nck.motion.enable_trace()
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    samples = []
    for _ in range(5000):
        nck.step(1)
        status = nck.status()
        _times, rows = nck.motion.trace()
        x = float(rows[-1][0]) if len(rows) else 0.0
        samples.append((x, dict(status.channel.modal.aux), status.channel.modal.spindle_state))
        if nck.situation.channel == "reset":
            break
    assert not nck.alarm_history()
    return samples


def _smallest_step_near(samples: list[tuple[float, dict, str]], x_mm: float) -> float:
    """The smallest setpoint change per cycle while X passes ``x_mm`` ± 1 mm (0 = standstill)."""
    xs = np.array([s[0] for s in samples])
    steps = np.abs(np.diff(xs))
    near = (np.abs(xs[1:] - x_mm) < 1.0) & (np.abs(xs[:-1] - x_mm) < 1.0)
    return float(steps[near].min())


def test_canonical_order_before_during_and_after_the_motion() -> None:
    """Digest 828d-1 rank 6: T, D, M3 (bit 5) go out before the motion, behind an implicit
    exact stop; S (bit 6) with them; M8 and H5 without a defined behaviour after the motion,
    whose block ends at interpolator end (002 L14480-14540, L14633-14636, L4797-4809). The
    cut after M3 first waits for the spindle's set speed range (MD35500, 002 L54530-54536)."""
    r = run(lines("N10 G64 G1 X10 F100 M8 H5 S200 M3 T1 D1", "N20 M30"))
    block = [cmd for cmd in r.commands if cmd.source.n == 10]
    kinds = [type(cmd).__name__ for cmd in block]
    assert kinds == ["ToolSelect", "EdgeSelect", "SpindleCommand", "ExactStop", "Dwell", "Motion",
                     "AuxFunction", "AuxFunction"]
    wait = block[4]
    assert isinstance(wait, canon.Dwell) and wait.wait_spindle and wait.feed_enable
    motion = block[5]
    assert isinstance(motion, canon.Motion) and motion.exact_stop and motion.exact_stop_window == "G603"
    assert [(cmd.address, cmd.value) for cmd in block[6:]] == [("M", 8.0), ("H", 5.0)]


def test_spindle_speed_alone_goes_out_during_the_motion_without_a_stop() -> None:
    """S (MD22080 index 17, bit 6) needs no exact stop: no ExactStop in the block."""
    r = run(lines("N10 G64 G1 X10 F100", "N20 X20 S500", "N30 M30"))
    kinds = [type(cmd).__name__ for cmd in r.commands if cmd.source.n == 20]
    assert kinds == ["SpindleCommand", "Motion"]


def test_m3_in_the_following_block_stops_the_path_between_the_blocks() -> None:
    """Digest 828d-1 rank 7 (002 L4955-4956, L4797-4799): in G64, N20 with M3 (output before
    the motion) makes the axes stop at X10; the spindle starts only once N10 has ended.
    The same contour with S alone in N20 runs through X10 at feed."""
    stopped = _run_cycles("N10 G64 G1 X10 F3000\nN20 X20 M3 S500\nN30 M30\n")
    assert _smallest_step_near(stopped, 10.0) == pytest.approx(0.0, abs=1e-9)
    first_m3 = next(i for i, s in enumerate(stopped) if s[2] == "M3")
    assert stopped[first_m3][0] == pytest.approx(10.0, abs=1e-9)
    # Continuous: at 50 mm/s the setpoint moves 0.2 mm per 4 ms cycle through X10.
    through = _run_cycles("N10 G64 G1 X10 F3000\nN20 X20 S500\nN30 M30\n")
    assert _smallest_step_near(through, 10.0) > 0.1


def test_m8_without_a_defined_behaviour_goes_out_at_block_end() -> None:
    """002 L14633-14636: M8 (no output behaviour defined) after the motion of its block,
    which ends at interpolator end (L4800-4801): the path comes to rest at X10."""
    samples = _run_cycles("N10 G64 G1 X10 F3000 M8\nN20 X20\nN30 M30\n")
    first_m8 = next(i for i, s in enumerate(samples) if s[1].get("M") == "8")
    # The kernel hands it out between two IPO cycles: the cycle before stood at the end point.
    assert samples[first_m8 - 1][0] == pytest.approx(10.0, abs=1e-9)
    assert all(s[0] <= 10.0 + 1e-9 for s in samples[:first_m8])
    assert _smallest_step_near(samples, 10.0) == pytest.approx(0.0, abs=1e-9)


def test_md22035_h121_puts_a_user_m_function_before_the_motion() -> None:
    """002 L15478-15499: M8 defined as user function (MD22010 M, MD22020 0, MD22030 8) with
    MD22035 = 'H121' (bits 0, 5, 8): output before the motion, so M8 is out while X is at 0."""
    md = {"MD22010": ["M"], "MD22020": [0], "MD22030": [8], "MD22035": [0x121]}
    samples = _run_cycles("N10 G64 G1 X10 F3000 M8\nN20 M30\n", md)
    first_move = next(i for i, s in enumerate(samples) if s[0] > 1e-9)
    assert samples[first_move][1].get("M") == "8"
