"""Digest job-planning-variables (manual 004, Job Planning, variables): ranked items through
the interpreter. ``tests/README.md`` lists the items proved elsewhere or not modelled.

Expected values come from the manual lines cited, computed by hand or with ``math``.
"""

from __future__ import annotations

import math

import pytest

from tests.lang.conftest import run_text


def r_after(text: str, subprograms: dict[str, str] | None = None) -> dict[int, float]:
    """R parameters after a run that must end without alarm."""
    result = run_text(text, subprograms)
    assert result.status == "ended", result.alarms
    r = result.interpreter.data.r
    return {n: r[n] for n in range(20)}


def alarm_of(text: str, subprograms: dict[str, str] | None = None) -> int:
    result = run_text(text, subprograms)
    assert result.status == "alarm"
    return result.alarms[0].number


def test_digest_job_planning_rank_01_r_parameter_aliasing_and_indexing() -> None:
    """Digest job-planning-variables rank 1: R10 and R[10] are one element (004 L253-256);
    R[R2] and R[(R1+R2)*R3] address indirectly (004 L310-311): R2 = 5 -> R5; (1+1)*2 -> R4.
    An index beyond MAX_INDEX = MD28050 - 1 (004 L288-291; 100 R parameters here) is 17020."""
    r = r_after("R10=7\nR11=R[10]\nR2=5\nR[R2]=1\nM30\n")
    assert (r[11], r[5]) == (7.0, 1.0)
    r = r_after("R1=1 R2=1 R3=2\nR[(R1+R2)*R3]=5\nM30\n")
    assert r[4] == 5.0
    assert alarm_of("R100=1\nM30\n") == 17020


def test_digest_job_planning_rank_02_number_literals_and_sin_in_degrees() -> None:
    """Digest job-planning-variables rank 2, the manual's example (004 L303-309):
    ``$R4=-0.1EX-5`` is -0.1·10^-5 and ``$R[6]=1.874EX8`` 1.874·10^8, written as main-run R
    parameters (004 L259-266); 8.2EX-3 = 0.0082 (004 L281); SIN(25.3) in degrees. Reading
    R4/R6 gives the same elements (one store)."""
    r = r_after("$R4=-0.1EX-5\n$R[6]=1.874EX8\nR3=8.2EX-3\nR7=SIN(25.3)\nR8=$R4+R6\nM30\n")
    assert r[4] == pytest.approx(-1e-6, rel=1e-12)
    assert r[6] == pytest.approx(1.874e8, rel=1e-12)
    assert r[8] == pytest.approx(1.874e8 - 1e-6, rel=1e-12)
    assert r[3] == pytest.approx(0.0082, rel=1e-12)
    assert r[7] == pytest.approx(math.sin(math.radians(25.3)), rel=1e-12)
    assert r[7] == pytest.approx(0.4273579, abs=5e-8)


def test_digest_job_planning_rank_04_lud_exists_only_in_its_subprogram() -> None:
    """Digest job-planning-variables rank 4: a LUD is created with its subprogram and deleted at
    its end; only that subprogram can access it (004 L390-395): after RET the caller reading
    it gets 12550 (name not defined)."""
    sub = {"SUB1.SPF": "PROC SUB1\nDEF INT LOCALV=3\nR2=LOCALV\nRET\n"}
    assert r_after("SUB1\nM30\n", sub)[2] == 3.0
    assert alarm_of("SUB1\nR1=LOCALV\nM30\n", sub) == 12550


def test_digest_job_planning_rank_05_pud_not_visible_in_subprograms_by_default() -> None:
    """Digest job-planning-variables rank 5: with MD11120 = 0 (default) a PUD of the main program
    is visible only there (004 L509-516): the subprogram reading it gets 12550. The MD11120 = 1
    case is golden program 31 (``tests/golden/31_search_and_md11120``)."""
    sub = {"SUB2.SPF": "PROC SUB2\nR1=MAINV\nRET\n"}
    assert alarm_of("DEF INT MAINV=3\nR2=MAINV\nSUB2\nM30\n", sub) == 12550


def test_digest_job_planning_rank_06_def_syntax_rules() -> None:
    """Digest job-planning-variables rank 6: several variables of one type per DEF, one type per
    DEF (004 L409-411); names of at most 31 characters whose first two characters are letters
    or underscores, no ``$`` (004 L453-456). (Single letters such as A, B, C are address
    letters and cannot be names, so two-letter names stand for the digest's A, B, C.)"""
    r = r_after("DEF INT AA, BB=2, CC\nR1=AA R2=BB R3=CC\nM30\n")
    assert (r[1], r[2], r[3]) == (0.0, 2.0, 0.0)
    assert alarm_of("DEF INT AA REAL BB\nM30\n") == 12080
    assert run_text("DEF INT " + "N" * 31 + "\nM30\n").status == "ended"
    assert alarm_of("DEF INT " + "N" * 32 + "\nM30\n") == 12420
    assert alarm_of("DEF INT $ABC\nM30\n") == 12080
    assert alarm_of("DEF INT 1AB\nM30\n") == 12080
    assert alarm_of("DEF INT A1B\nM30\n") == 12080  # second character a digit
    assert run_text("DEF INT _AB\nM30\n").status == "ended"
    assert alarm_of("R1=1\nDEF INT LATE\nM30\n") == 14500  # definitions first (004 L407-410)


@pytest.mark.parametrize("ending", ["M30", "RESET"])
def test_digest_job_planning_rank_04_pud_is_gone_after_program_end_or_reset(ending: str) -> None:
    """Digest job-planning-variables rank 4: a PUD lives as long as its main program; with
    MD11120 = 1 the subprograms called from it see it (004 L509-516), and after M30 or NC
    RESET it is gone: the same subprogram called from the next program gets 12550 (name not
    defined). Run in one channel of the kernel, programs selected one after the other."""
    import dataclasses

    from nck import commands as c
    from nck.interp.sources import MemorySource
    from nck.kernel import Nck
    from nck.machine import load_machine

    machine = load_machine()
    machine = dataclasses.replace(machine, md={**machine.md, "MD11120": 1})
    first = "DEF INT PU=5\nSUB3\nM0\nM30\n"
    programs = MemorySource({"A.MPF": first, "B.MPF": "SUB3\nM30\n", "SUB3.SPF": "PROC SUB3\nR1=PU\nRET\n"})
    nck = Nck(machine=machine, programs=programs, referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("A.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)  # at M0
    assert nck.status().alarms == ()
    assert nck.data.r[1] == 5.0  # the subprogram read the PUD of its main program
    if ending == "M30":
        assert nck.submit(c.CycleStart()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    else:
        assert nck.submit(c.Reset()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert nck.submit(c.SelectProgram("B.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.program != "running", 10.0)
    assert [a.number for a in nck.status().alarms] == [12550]
