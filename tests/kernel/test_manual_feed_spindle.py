"""Feed, rapid and spindle behaviour of Function Manual 002 on the real interpreter and motion.

Each test cites the manual lines its expected values come from.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory


def make(programs: dict[str, str], **kwargs) -> Nck:
    return Nck(programs=MemorySource(programs), referenced=True, **kwargs)


def run_time_s(nck: Nck, program: str) -> float:
    """AUTO, select, NC START; the simulated time until the channel is back in reset."""
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram(program)) == c.Accepted()
    start = nck.time_s
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 120.0)
    return nck.time_s - start


def test_feed_override_reaches_200_percent() -> None:
    """Digest 828d-3 rank 9 (200 %)."""
    # 002 L56312-56313: an override between 0 and 200 % for the path feed; feeds are multiplied.
    # 100 mm at F1000 takes 6 s at 100 % and 3 s at 200 % (ramps add a little to both).
    programs = {"P.MPF": "N10 G1 X100 F1000\nN20 M30"}
    plain = run_time_s(make(programs), "P.MPF")
    fast = make(programs)
    assert fast.submit(c.SetOverride("feed", 200)) == c.Accepted()
    assert run_time_s(fast, "P.MPF") == pytest.approx(plain / 2, rel=0.03)
    assert isinstance(fast.submit(c.SetOverride("feed", 201)), c.Rejected)


def test_spindle_override_accepts_0_to_200_percent() -> None:
    # 002 L56318-56319: the spindle override can be between 0 and 200 %.
    nck = make({})
    assert nck.submit(c.SetOverride("spindle", 200)) == c.Accepted()
    assert nck.submit(c.SetOverride("spindle", 0)) == c.Accepted()
    assert isinstance(nck.submit(c.SetOverride("spindle", 201)), c.Rejected)


def test_rapid_override_by_the_feed_switch_is_limited_to_100_percent() -> None:
    """Digest 828d-3 rank 9 (rapid override clamped to 100 %)."""
    # 002 L56314-56315 and L56369-56370: rapid override 0 … 100 %; when the feed switch acts
    # as rapid override, feed overrides above 100 % count as 100 % for rapid traverse.
    # The instant motion stand-in moves G0 at exactly rapid × override (no axis limit to hide it).
    programs = {"P.MPF": "N10 G0 X300\nN20 M30"}
    plain = run_time_s(make(programs, motion_factory=instant_motion_factory), "P.MPF")
    nck = make(programs, motion_factory=instant_motion_factory)
    nck.submit(c.SetProgramControl("rapid_override", True))
    nck.submit(c.SetOverride("feed", 200))
    assert run_time_s(nck, "P.MPF") == pytest.approx(plain, rel=0.01)
    assert isinstance(nck.submit(c.SetOverride("rapid", 101)), c.Rejected)


# ----------------------------------------------------------------------------- G95 and G4 S
RPM_1000_UP = "N10 G95 S1000 M3\nN15 G4 F2\n"  # the dwell lets the spindle reach its speed


def test_revolutional_feed_follows_the_spindle_override() -> None:
    """Digest 828d-3 rank 11."""
    # 002 L55411-55420: the G95 path velocity comes from the actual spindle speed, V = F × n.
    # F0.1 mm/rev at 1000 rpm: 100 mm/min, 10 mm in 6 s; spindle override 50 %: 500 rpm,
    # 50 mm/min, 12 s (002 L56318: the spindle override acts on the speed).
    programs = {"P.MPF": RPM_1000_UP + "N20 G1 X10 F0.1\nN30 M30"}
    plain = run_time_s(make(programs), "P.MPF")
    slow = make(programs)
    slow.submit(c.SetOverride("spindle", 50))
    assert run_time_s(slow, "P.MPF") - plain == pytest.approx(6.0, abs=0.1)


def test_spindle_override_during_a_revolutional_feed_block_changes_its_feed() -> None:
    programs = {"P.MPF": RPM_1000_UP + "N20 G1 X10 F0.1\nN30 M30"}
    nck = make(programs)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 5.0, 20.0)  # half way at 100 mm/min
    start = nck.time_s
    nck.submit(c.SetOverride("spindle", 200))  # 2000 rpm: 200 mm/min, the last 5 mm in 1.5 s
    assert nck.run_until(lambda k: k.situation.channel == "reset", 20.0)
    assert nck.time_s - start == pytest.approx(1.5, abs=0.1)


def test_dwell_in_spindle_revolutions_waits_for_the_revolutions() -> None:
    """Digest programming-840c rank 18 (G4 S in revolutions takes revolutions/speed, 001 L6402-6419)."""
    # 001 L6402-6419 and 002 L53952: G4 S… dwells for spindle revolutions; S50 at 1000 rpm is 3 s.
    base = {"P.MPF": RPM_1000_UP + "N30 M30"}
    dwell = {"P.MPF": RPM_1000_UP + "N20 G4 S50\nN30 M30"}
    assert run_time_s(make(dwell), "P.MPF") - run_time_s(make(base), "P.MPF") == pytest.approx(3.0, abs=0.05)


def test_dwell_in_revolutions_on_a_spindle_started_in_the_block_before() -> None:
    # The revolutions are counted when the dwell starts, not when it is interpreted:
    # S50 right after M3 S1000 lasts 3 s plus half the ramp (16.7 rev/s are reached with
    # the acceleration MD35200 of the spindle, during which it turns only half as far).
    nck = make({})
    ramp_s = (1000 / 60) / machine_datum(nck, "MD35200")
    base = {"P.MPF": "N10 S1000 M3\nN30 M30"}
    dwell = {"P.MPF": "N10 S1000 M3\nN20 G4 S50\nN30 M30"}
    assert run_time_s(make(dwell), "P.MPF") - run_time_s(make(base), "P.MPF") == pytest.approx(
        3.0 + ramp_s / 2, abs=0.05)


def test_iso_g04_under_g95_counts_revolutions_with_md20734_bit_2() -> None:
    # 000 L1148-1160: MD20734 bit 2 = 1 and G95 active: G04 X… is in spindle revolutions;
    # "G95 G04 X1000" (standard notation) = 1000 × 0.001 = 1 revolution. X5. = 5 revolutions
    # at 600 rpm = 0.5 s; with bit 2 = 0 the same block dwells 5 s.
    from nck.headless import run_program
    from nck.machine import load_machine
    from nck.ncdata import NcData

    text = "G95 S600 M3\nG04 X2.\nG04 X5.\nM30\n"
    base_text = "G95 S600 M3\nG04 X2.\nM30\n"
    times = {}
    for mask in (0, 4):
        machine = load_machine()
        machine.md["MD20734"] = mask
        for name, body in (("dwell", text), ("base", base_text)):
            result = run_program(machine, MemorySource({}), NcData(), "ISO.MPF", text=body, dialect="iso-m")
            assert result.status == "ended", result.alarms
            times[mask, name] = result.machine_time_s
    assert times[4, "dwell"] - times[4, "base"] == pytest.approx(0.5, abs=0.05)
    assert times[0, "dwell"] - times[0, "base"] == pytest.approx(5.0, abs=0.05)


# ----------------------------------------------------------------------------- G25/G26, SD43235
def spindle_rpm(nck: Nck) -> float:
    return nck.motion.spindles["SP"].state.actual_rpm


def test_g26_limits_the_spindle_speed_and_the_revolutional_feed() -> None:
    """Digest 828d-3 rank 15 (G26 S clamps the setpoint)."""
    # 002 L54101-54107 and L55616-55618: G26 S… sets the maximum speed (SD43220), which
    # cannot be exceeded: S1000 turns at 500 rpm; F0.1 mm/rev then gives 50 mm/min (12 s for 10 mm).
    programs = {"P.MPF": "N5 G26 S500\n" + RPM_1000_UP + "N20 G1 X10 F0.1\nN30 M30",
                "Q.MPF": RPM_1000_UP + "N20 G1 X10 F0.1\nN30 M30"}
    limited = make(programs)
    assert run_time_s(limited, "P.MPF") - run_time_s(make(programs), "Q.MPF") == pytest.approx(6.0, abs=0.1)
    assert limited.data.setting_data["SD43220"] == {"SP": 500.0}


def test_g25_raises_the_spindle_speed_to_the_minimum() -> None:
    """Digest 828d-3 rank 15 (lower limit)."""
    # 002 L55624-55630: the speed may not fall below G25 / SD43210.
    nck = make({"P.MPF": "N5 G25 S300\nN10 S100 M3\nN20 G4 F2\nN30 M0\nN40 M30"})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.channel != "active", 10.0)
    assert spindle_rpm(nck) == pytest.approx(300.0)


def test_operator_speed_limit_sd43235_acts_at_once() -> None:
    """Digest 828d-3 rank 15 (SD43235 at once)."""
    # 002 L54713-54718: the operator's maximum speed SD43235 acts immediately on the setpoint.
    nck = make({"P.MPF": "N10 S1000 M3\nN20 G4 F10\nN30 M30"})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    nck.tick(2.0)
    assert spindle_rpm(nck) == pytest.approx(1000.0)
    nck.data.setting_data["SD43235"] = {"SP": 800.0}
    nck.tick(2.0)
    assert spindle_rpm(nck) == pytest.approx(800.0)


def test_sd43235_is_10000_rpm_as_delivered() -> None:
    # 002 L54720: as standard setting SD43235 limits the speed to 10,000 rpm.
    from nck.machine_data import catalog

    assert catalog().get("SD43235").default == 10000.0


# ----------------------------------------------------------------------------- SPOS, M19, WAITS
def machine_datum(nck: Nck, key: str) -> float:
    """The spindle's machine datum, or the catalogue's default when the machine has none."""
    from nck.machine_data import catalog

    return float(nck.machine.md_value(key, "SP", catalog().get(key).default))


def positioning_s(nck: Nck, degrees: float, speed_rpm: float | None = None) -> float:
    """Hand formula: a move of ``degrees`` from standstill at MD35300 (or ``speed_rpm``) with
    MD35210 (trapezoid)."""
    speed = (speed_rpm or machine_datum(nck, "MD35300")) * 6.0  # rpm -> deg/s
    accel = machine_datum(nck, "MD35210") * 360.0  # rev/s² -> deg/s²
    if degrees >= speed * speed / accel:
        return degrees / speed + speed / accel
    return 2.0 * (degrees / accel) ** 0.5


def spindle_angle(nck: Nck) -> float:
    return nck.motion.spindles["SP"].state.angle_deg


@pytest.mark.parametrize(("word", "travel", "end"), [
    ("SPOS=90", 90.0, 90.0),
    ("SPOS=DC(270)", 90.0, 270.0),  # 002 L51141-51144: the shortest way (-90°)
    ("SPOS=AC(270)", 90.0, 270.0),  # standstill: direction from the distance to go
    ("SPOS=ACP(270)", 270.0, 270.0),  # 002 L51149-51152: from the positive direction
    ("SPOS=ACN(90)", 270.0, 90.0),
])
def test_spos_takes_its_positioning_time(word: str, travel: float, end: float) -> None:
    """Digest 828d-3 rank 17 (DC shortest way, ACP positive direction)."""
    # 002 L51117-51165: SPOS positions the spindle; the block stays active until it is there.
    base = make({"P.MPF": "N20 M30"})
    nck = make({"P.MPF": f"N10 {word}\nN20 M30"})
    assert run_time_s(nck, "P.MPF") - run_time_s(base, "P.MPF") == pytest.approx(
        positioning_s(nck, travel), abs=0.01)
    assert spindle_angle(nck) == pytest.approx(end)


@pytest.mark.parametrize("rate_deg_min", [3600.0, 36000.0])
def test_fa_of_the_spindle_is_its_positioning_speed(rate_deg_min: float) -> None:
    """Digest 828d-3 rank 17: FA[S1] sets the positioning speed in degrees/min, FA[S1]=0 gives
    MD35300 back (002 L51375-51385, L54149-54151). 3600 deg/min = 10 rpm, 36000 = 100 rpm:
    the 180° move takes the trapezoid time at that speed (timed cycle by cycle). Before,
    FA[S1] was refused (12550)."""
    base = make({"P.MPF": "N20 M30"}, batch_cycles=1)
    nck = make({"P.MPF": f"N10 FA[S1]={rate_deg_min:g} SPOS=180\nN20 M30"}, batch_cycles=1)
    assert run_time_s(nck, "P.MPF") - run_time_s(base, "P.MPF") == pytest.approx(
        positioning_s(nck, 180.0, rate_deg_min / 360.0), abs=0.01)
    assert spindle_angle(nck) == pytest.approx(180.0)
    back = make({"P.MPF": f"N10 FA[S1]={rate_deg_min:g}\nN15 FA[S1]=0 SPOS=180\nN20 M30"}, batch_cycles=1)
    base = make({"P.MPF": f"N10 FA[S1]={rate_deg_min:g}\nN20 M30"}, batch_cycles=1)
    assert run_time_s(back, "P.MPF") - run_time_s(base, "P.MPF") == pytest.approx(
        positioning_s(back, 180.0), abs=0.01)


def test_fa_of_a_path_axis_is_refused_without_positioning_axes() -> None:
    """FA[X] is the feed of a positioning axis (POS/POSA, 002 L8737, L11159); without
    positioning axes (POS is refused) it was stored and never used: now 12550."""
    nck = make({"P.MPF": "N10 FA[X]=500\nN20 M30"})
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.program != "running", 60.0)
    assert [a.number for a in nck.status().alarms] == [12550]


def test_spos_ic_is_relative_to_the_last_programmed_position() -> None:
    """Digest 828d-3 rank 17 (IC)."""
    # 002 L51132-51135: SPOS=IC(…) in relation to the last programmed position.
    nck = make({"P.MPF": "N10 SPOS=100\nN20 SPOS=IC(30)\nN30 M30"})
    run_time_s(nck, "P.MPF")
    assert spindle_angle(nck) == pytest.approx(130.0)


def test_m19_reads_the_position_of_its_spindle_from_sd43240() -> None:
    """Digest 828d-3 rank 17 (M19 to SD43240)."""
    # 002 L51159-51165: M19 reads the position from SD43240 $SA_M19_SPOS[<n>]; on a data
    # directory it is kept per spindle.
    nck = make({"P.MPF": "N10 M19\nN20 M30"})
    nck.data.setting_data["SD43240"] = {"SP": 45.0}
    assert run_time_s(nck, "P.MPF") == pytest.approx(positioning_s(nck, 45.0) + run_time_s(
        make({"P.MPF": "N20 M30"}), "P.MPF"), abs=0.01)
    assert spindle_angle(nck) == pytest.approx(45.0)
    assert nck.status().alarms == ()


def test_waits_holds_the_next_block_until_the_spindle_is_at_speed() -> None:
    """Digest 828d-3 rank 17 (WAITS)."""
    # 002 L51302-51335: with WAITS the next block waits until the spindle is in its set
    # speed range (MD35150 = 0.1: 900 rpm of S1000); without it, and with MD35500 = 0 (the
    # cut does not wait for the speed itself, 002 L51282-51285), the axis starts at once.
    # S1000 needs (1000/60)/MD35200 s to full speed, 90 % of that into the range.
    from nck.machine import load_machine

    machine = load_machine()
    machine.md["MD35500"] = {"SP": 0}
    ramp_s = (1000 / 60) / machine_datum(make({}), "MD35200")
    plain = run_time_s(make({"P.MPF": "N10 S1000 M3\nN30 G1 X10 F600\nN40 M30"}, machine=machine), "P.MPF")
    waiting = run_time_s(make({"P.MPF": "N10 S1000 M3\nN20 WAITS\nN30 G1 X10 F600\nN40 M30"},
                              machine=machine), "P.MPF")
    assert waiting - plain == pytest.approx(0.9 * ramp_s, abs=0.01)


def test_check_agrees_with_the_run_on_spindle_positioning_words() -> None:
    from nck.headless import check_program
    from nck.machine import load_machine

    def numbers(text: str) -> list[int]:
        return [a.number for a in check_program(load_machine(), MemorySource({}), "C.MPF", text)]

    assert numbers("N10 SPOS=DC(45)\nN20 SPOS=ACN(10)\nN30 WAITS\nN40 M19\nM30\n") == []
    assert numbers("N10 SPOS=400\nM30\n") == [16830]  # absolute positions are 0 … 359.999°


# ----------------------------------------------------------------------------- OVR, ACC
def test_programmable_feed_override_multiplies_with_the_panel() -> None:
    """Digest 828d-3 rank 10."""
    # 002 L56515-56536: OVR= 0 … 200 % changes the path feed; the active override is the
    # product with the panel's. 100 mm at F1000: 6 s; OVR=50: 12 s; OVR=200 at 50 % panel: 6 s.
    plain = run_time_s(make({"P.MPF": "N10 G1 X100 F1000\nN20 M30"}), "P.MPF")
    slow = run_time_s(make({"P.MPF": "N5 OVR=50\nN10 G1 X100 F1000\nN20 M30"}), "P.MPF")
    assert slow - plain == pytest.approx(6.0, abs=0.05)
    both = make({"P.MPF": "N5 OVR=200\nN10 G1 X100 F1000\nN20 M30"})
    both.submit(c.SetOverride("feed", 50))
    assert run_time_s(both, "P.MPF") == pytest.approx(plain, abs=0.05)


def test_ovr_is_100_percent_again_after_reset() -> None:
    """Digest 828d-3 rank 10 (100 % after RESET)."""
    # 002 L56533-56536: 100 % after RESET (MD22410 not set).
    nck = make({"P.MPF": "N5 OVR=50\nN10 G1 X10 F600\nN20 M30", "Q.MPF": "N10 G1 X0 F600\nN20 M30"})
    first = run_time_s(nck, "P.MPF")
    assert run_time_s(nck, "Q.MPF") == pytest.approx(first - 1.0, abs=0.05)  # 1 s at F600, 2 s at 50 %


def travel_s(nck: Nck, program: str, target_x: float) -> float:
    """Time the X setpoint needs from leaving its place to reaching ``target_x`` (cycle by cycle)."""
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram(program))
    start_x = nck.positions_mcs()["X"]
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: abs(k.positions_mcs()["X"] - start_x) > 1e-9, 5.0)
    start = nck.time_s
    assert nck.run_until(lambda k: abs(k.positions_mcs()["X"] - target_x) < 1e-9, 5.0)
    travel = nck.time_s - start
    assert nck.run_until(lambda k: k.situation.channel == "reset", 5.0)
    return travel


def test_acc_scales_the_axis_acceleration_until_reset() -> None:
    """Digest 828d-1 rank 8 (ACC[X] until RESET)."""
    # 002 L7433-7450: ACC[axis] = 0 < factor ≤ 200 % of the maximum acceleration, modal;
    # reduced to 100 % by RESET/M30 (MD32320 bit 0 = 0). X10 at F30000 never reaches the
    # feed with MD32300 = 2.5 m/s²: t = 2·√(s/a), 0.253 s at 25 % (a = 625 mm/s²), 0.126 s at 100 %.
    nck = make({"P.MPF": "N5 ACC[X]=25\nN10 G1 X10 F30000\nN20 M30",
                "Q.MPF": "N10 G1 X0 F30000\nN20 M30"}, batch_cycles=1)
    amax = float(nck.machine.md_value("MD32300", "X", None)) * 1000.0
    assert travel_s(nck, "P.MPF", 10.0) == pytest.approx(2.0 * (10.0 / (0.25 * amax)) ** 0.5, abs=0.008)
    assert travel_s(nck, "Q.MPF", 0.0) == pytest.approx(2.0 * (10.0 / amax) ** 0.5, abs=0.008)


@pytest.mark.parametrize(("text", "number"), [
    ("N10 ACC[X]=0\nM30\n", 12160), ("N10 ACC[X]=201\nM30\n", 12160),
    ("N10 OVR=201\nM30\n", 12160), ("N10 ACC[Q]=50\nM30\n", 12550),
])
def test_acc_and_ovr_out_of_range_are_refused_by_run_and_check(text: str, number: int) -> None:
    from nck.headless import check_program, run_program
    from nck.machine import load_machine
    from nck.ncdata import NcData

    machine = load_machine()
    assert [a.number for a in check_program(machine, MemorySource({}), "C.MPF", text)] == [number]
    run = run_program(machine, MemorySource({}), NcData(), "C.MPF", text=text)
    assert [a.number for a in run.alarms] == [number]
