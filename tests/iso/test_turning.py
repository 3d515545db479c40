"""ISO dialect T turning cycles on the lathe (lathe2: X diameter, Z): program flow and end points.

Every expected point is worked by hand from the cycle rules in nck/iso/turning_cycles.py
(X values are diameters, as programmed).
"""

from __future__ import annotations

import math

import pytest

from nck import canon
from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.iso.translate import translate
from nck.machine import load_machine
from nck.ncdata import NcData


def run_lathe(text: str, md: dict | None = None) -> HeadlessRun:
    """Run ``text`` as an ISO T main program on the lathe, without time simulation."""
    machine = load_machine("lathe2")
    machine.md.update(md or {})
    return interpret_only(machine, MemorySource({}), NcData(), "TURN.MPF", text=text,
                          max_blocks=20_000, dialect="iso-t")


def points(result: HeadlessRun, line: int | None = None) -> list[tuple[str, float, float]]:
    """(motion, X, Z) of every segment (of source line ``line``), rounded to 1 µm."""
    return [(m.kind, round(m.end_wcs["X"], 3), round(m.end_wcs["Z"], 3))
            for m in result.segments if line is None or m.source.line == line]


def lines_run(result: HeadlessRun) -> list[int]:
    """Source lines that produced motion, in order (repeats collapsed)."""
    out: list[int] = []
    for motion in result.segments:
        if not out or out[-1] != motion.source.line:
            out.append(motion.source.line)
    return out


# ---------------------------------------------------------------- E5: program flow


def test_e5_g70_runs_the_contour_then_continues_after_its_own_block():
    """Digest iso-dialects-840d rank 15 (E5, 000 L3663-3669)."""
    text = ("N10 G70 P20 Q50\nN20 X100. Z50.\nN30 X200.\nN40 Z100.\nN50 X250. Z111.\nN60 M30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    contour = [("G0", 100.0, 50.0), ("G0", 200.0, 50.0), ("G0", 200.0, 100.0),
               ("G0", 250.0, 111.0)]
    assert points(result, 1) == contour  # the finishing pass, carrying the G70 block
    assert {m.source.n for m in result.segments if m.source.line == 1} == {10}
    assert [p for line in (2, 3, 4, 5) for p in points(result, line)] == contour  # then again


E5_G71 = ("N5 G00 X260. Z120.\nN10 G71 P50 Q80 U4. W3. F0.5\nN20 G1 F0.5 G95 S1000\n"
          "N30 X30. Z10.\nN40 M30\nN50 X100. Z50.\nN60 X200.\nN70 Z100.\nN80 X250. Z111.\n"
          "N90 G00 X300.\nN100 M30\n")


def test_e5_g71_skips_the_blocks_before_the_contour_and_continues_after_q():
    """Digest iso-dialects-840d rank 15 (E5, 000 L3686-3695)."""
    result = run_lathe(E5_G71)
    assert result.status == "ended", result.alarms
    assert lines_run(result) == [1, 2, 10]  # start move, cycle (N10), then N90: N20-N80 never run
    assert points(result, 10) == [("G0", 300.0, 120.0)]
    # the cycle ends back at its start point
    assert points(result, 2)[-1] == ("G0", 260.0, 120.0)


def test_g71_settings_block_moves_nothing_and_keeps_depth_and_retract():
    """Digest iso-dialects-840d rank 15."""
    assert translate("N10 G71 U6. R5.", "iso-t")[0].blocks == []
    text = ("G00 X40. Z2.\nG71 U6. R5.\nG71 P10 Q20 F0.2\nN10 G00 X10.\nN20 G01 Z-30.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    assert points(result, 2) == []
    cut = points(result, 3)
    # passes at X = 40 - 2*6 = 28 and 16 (depth 6 in radius), each lifted by 5 at 45 degrees
    assert cut[:8] == [("G0", 28.0, 2.0), ("G1", 28.0, -30.0), ("G0", 38.0, -25.0),
                       ("G0", 38.0, 2.0), ("G0", 16.0, 2.0), ("G1", 16.0, -30.0),
                       ("G0", 26.0, -25.0), ("G0", 26.0, 2.0)]
    # then the contour itself, back to the start point
    assert cut[8:] == [("G0", 10.0, 2.0), ("G1", 10.0, -30.0), ("G0", 40.0, -30.0),
                       ("G0", 40.0, 2.0)]


def test_g71_with_an_arc_cuts_to_the_circle():
    # contour: X20 Z0, G03 to X40 Z-10 with R10 (quarter circle, centre X20 Z-10), Z-30
    text = ("G00 X46. Z2.\nG71 U2. R0.5\nG71 P10 Q30 F0.2\nN10 G00 X20. Z0\n"
            "N20 G03 X40. Z-10. R10.\nN30 G01 Z-30.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    cuts = [p for p in points(result, 3) if p[0] == "G1"]
    # passes at radius 21 (X42: above the contour, cut to its end Z-30) and 19 (X38), which
    # meets the arc (centre X20 Z-10, radius 10) at z = -10 + sqrt(10^2 - 9^2)
    assert cuts[0] == ("G1", 42.0, -30.0)
    assert cuts[1] == ("G1", 38.0, round(-10 + math.sqrt(10 ** 2 - 9 ** 2), 3))
    arc = [m for m in result.segments if m.kind == "G3"]
    assert len(arc) == 1 and round(arc[0].end_wcs["X"], 3) == 40.0


def test_g71_needs_a_known_start_point():
    result = run_lathe("G71 P10 Q20\nN10 G00 X10.\nN20 G01 Z-30.\nM30\n")
    assert result.alarms[0].number == 61607


def test_g72_facing_roughs_along_x_in_z_steps():
    text = ("G00 X50. Z2.\nG72 W1.5 R0.5\nG72 P10 Q20 F0.2\nN10 G00 Z-3.\nN20 G01 X10.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    cut = points(result, 3)
    # Z steps of 1.5 from Z2: Z0.5, Z-1 and Z-2.5 (the next would pass the contour at Z-3);
    # each pass cuts X down to 10 (the face), lifts 0.5 in Z and radius, rapids back to X50
    assert cut[:4] == [("G0", 50.0, 0.5), ("G1", 10.0, 0.5), ("G0", 11.0, 1.0), ("G0", 50.0, 1.0)]
    assert cut[4:8] == [("G0", 50.0, -1.0), ("G1", 10.0, -1.0), ("G0", 11.0, -0.5),
                        ("G0", 50.0, -0.5)]
    assert cut[8:10] == [("G0", 50.0, -2.5), ("G1", 10.0, -2.5)]
    assert cut[12:] == [("G0", 50.0, -3.0), ("G1", 10.0, -3.0), ("G0", 10.0, 2.0),
                       ("G0", 50.0, 2.0)]


def test_g73_pattern_repeat_passes_move_toward_the_contour():
    text = ("G00 X60. Z5.\nG73 U4. W0 R3\nG73 P10 Q20 U0.4 W0 F0.2\nN10 G00 X30. Z2.\n"
            "N20 G01 Z-20.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    cuts = [p for p in points(result, 3) if p[0] == "G1"]
    # relief 4 (radius) in 3 passes: 4, 2, 0, plus the allowance 0.2 (radius)
    assert cuts == [("G1", 38.4, -20.0), ("G1", 34.4, -20.0), ("G1", 30.4, -20.0)]
    assert points(result, 3)[-1] == ("G0", 60.0, 5.0)


def test_g74_peck_drilling_on_the_axis():
    text = "G00 X0 Z5.\nG74 R1.\nG74 Z-10. Q6000 F0.1\nM30\n"
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    assert points(result, 3) == [("G1", 0.0, -1.0), ("G0", 0.0, 0.0), ("G1", 0.0, -7.0),
                                 ("G0", 0.0, -6.0), ("G1", 0.0, -10.0), ("G0", 0.0, 5.0)]


def test_g75_grooving_pecks_in_x_and_steps_in_z():
    text = "G00 X42. Z-10.\nG75 R0.5\nG75 X30. Z-14. P3000 Q4000 F0.05\nM30\n"
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    # pecks of 3 (radius): X36, then X30; two columns: Z-10 and Z-14
    assert points(result, 3) == [
        ("G1", 36.0, -10.0), ("G0", 37.0, -10.0), ("G1", 30.0, -10.0), ("G0", 42.0, -10.0),
        ("G0", 42.0, -14.0), ("G1", 36.0, -14.0), ("G0", 37.0, -14.0), ("G1", 30.0, -14.0),
        ("G0", 42.0, -14.0), ("G0", 42.0, -10.0)]


def test_g76_f_is_the_thread_lead_and_passes_deepen():
    """Digest iso-dialects-840d rank 15."""
    text = ("G00 X24. Z5.\nG76 P010000 Q50 R0\nG76 X18. Z-20. P1000 Q500 F2.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    threads = [m for m in result.segments if m.kind == "G33"]
    assert {m.lead_mm for m in threads} == {2.0}
    # depths 0.5, 0.707107, 0.866025, 1.0 (last rough = height), one finishing pass at 1.0
    xs = [round(m.end_wcs["X"], 3) for m in threads]
    assert xs == [19.0, round(2 * (10 - 0.707107), 3), round(2 * (10 - 0.866025), 3), 18.0, 18.0]
    assert all(round(m.end_wcs["Z"], 3) == -20.0 for m in threads)  # tool angle 0: radial infeed
    assert points(result, 3)[-1] == ("G0", 24.0, 5.0)


def test_g76_tool_angle_moves_the_infeed_along_the_flank():
    text = ("G00 X24. Z5.\nG76 P010060 Q50 R0\nG76 X18. Z-20. P1000 Q1000 F2.\nM30\n")
    result = run_lathe(text)
    threads = [m for m in result.segments if m.kind == "G33"]
    shift = round(-20 + math.tan(math.radians(30)), 3)
    assert [round(m.end_wcs["Z"], 3) for m in threads] == [shift, shift]


def test_g77_single_cycle_is_modal_and_returns_to_its_start():
    text = "G00 X50. Z2.\nG77 X46. Z-20. F0.2\nX42.\nG00 X60.\nM30\n"
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    assert points(result, 2) == [("G0", 46.0, 2.0), ("G1", 46.0, -20.0), ("G1", 50.0, -20.0),
                                 ("G0", 50.0, 2.0)]
    assert points(result, 3) == [("G0", 42.0, 2.0), ("G1", 42.0, -20.0), ("G1", 50.0, -20.0),
                                 ("G0", 50.0, 2.0)]
    assert points(result, 4) == [("G0", 60.0, 2.0)]  # G00 ended the cycle


def test_g78_thread_single_cycle_and_g79_facing():
    assert run_lathe("G00 X30. Z3.\nG78\nM30\n").segments[-1].end_wcs["X"] == 30.0  # no axes
    result = run_lathe("G00 X30. Z3.\nG78 X19. Z-15. F1.5\nX18.5\nM30\n")
    assert result.status == "ended", result.alarms
    threads = [m for m in result.segments if m.kind == "G33"]
    assert [(round(m.end_wcs["X"], 3), m.lead_mm) for m in threads] == [(19.0, 1.5), (18.5, 1.5)]
    result = run_lathe("G00 X60. Z2.\nG79 X20. Z-2. F0.2\nM30\n")
    assert points(result, 2) == [("G0", 60.0, -2.0), ("G1", 20.0, -2.0), ("G1", 20.0, 2.0),
                                 ("G0", 60.0, 2.0)]


def test_code_system_a_uses_g90_g92_g94_cycles_and_g50_g98_g99():
    text = ("G50 S1500\nG98\nG00 X50. Z2.\nG90 X46. Z-20. F200.\nG00 X60.\nG94 X20. Z-1. F100.\n"
            "M30\n")
    result = run_lathe(text, {"MD10881": 1})
    assert result.status == "ended", result.alarms
    assert points(result, 4) == [("G0", 46.0, 2.0), ("G1", 46.0, -20.0), ("G1", 50.0, -20.0),
                                 ("G0", 50.0, 2.0)]
    assert points(result, 6)[1] == ("G1", 20.0, -1.0)
    cut = [m for m in result.segments if m.source.line == 4 and m.kind == "G1"][0]
    assert cut.gcodes[15] == "G94" and cut.feed == 200.0  # G98 = feed per minute in system A


def test_g32_thread_f_is_the_lead_and_u_w_are_incremental():
    result = run_lathe("G00 X20. Z5.\nG32 Z-20. F1.25\nG00 U10.\nW25.\nM30\n")
    assert result.status == "ended", result.alarms
    assert result.segments[1].kind == "G33" and result.segments[1].lead_mm == 1.25
    assert points(result)[2:] == [("G0", 30.0, -20.0), ("G0", 30.0, 5.0)]


def test_g96_with_spindle_limit_from_g92_s():
    result = run_lathe("G92 S2000\nG00 X100. Z5.\nG96 S150 M03\nG01 X20. F0.2\nM30\n")
    assert result.status == "ended", result.alarms
    speeds = [c.speed_rpm for c in result.commands
              if isinstance(c, canon.SpindleCommand) and c.speed_rpm is not None]
    # at X100 (radius 50 mm): 150000 / (2 pi 50) = 477.5 rpm; at X20 limited to 2000
    assert round(speeds[0], 1) == round(150000 / (2 * math.pi * 50), 1)
    assert speeds[-1] == 2000.0
    assert result.segments[-1].gcodes[15] == "G96"


def test_g92_x_z_sets_the_coordinate_system():
    result = run_lathe("G00 X40. Z10.\nG92 X100. Z50.\nG00 X90. Z40.\nM30\n")
    assert result.status == "ended", result.alarms
    last = result.segments[-1]
    assert round(last.end_wcs["X"], 3) == 90.0 and round(last.end_wcs["Z"], 3) == 40.0
    # 10 mm less in diameter = 5 mm in the machine (radius), 10 mm less in Z
    assert round(last.end_mcs["X"], 3) == 15.0 and round(last.end_mcs["Z"], 3) == 0.0


@pytest.mark.parametrize("text, number", [("G00 X20. Z2.\nG76 X18. Z-20. P1000 Q500\nM30\n", 61001),
                                          ("G00 X20. Z2.\nG76 X18. Z-20. P1000 F1.\nM30\n", 61610),
                                          ("G00 X20. Z2.\nG71 P10 Q99\nN10 X1.\nM30\n", 14080)])
def test_cycle_alarms(text, number):
    assert run_lathe(text).alarms[0].number == number


def test_g33_q_is_the_start_angle_and_the_lead_stays_modal():
    lines = translate("G00 X20. Z5.\nG33 Z-20. F1.5 Q180000\nZ-30.\nG01 X30.", "iso-t")
    assert [line.blocks for line in lines][1:] == [["G33 Z-20 K1.5 SF=180"], ["G33 Z-30"],
                                                  ["G1 X30"]]
    result = run_lathe("G00 X20. Z5.\nG33 Z-20. F1.5 Q180000\nZ-30.\nG01 X30. F0.1\nM30\n")
    assert result.status == "ended", result.alarms
    assert [(m.kind, m.lead_mm) for m in result.segments[1:3]] == [("G33", 1.5), ("G33", 1.5)]


def test_system_a_g50_x_z_sets_the_coordinate_system():
    result = run_lathe("G00 X40. Z10.\nG50 X100. Z50.\nG00 X90. Z40.\nM30\n", {"MD10881": 1})
    assert result.status == "ended", result.alarms
    assert (round(result.segments[-1].end_mcs["X"], 3), round(result.segments[-1].end_mcs["Z"], 3)) \
        == (15.0, 0.0)


def test_g96_is_shown_in_iso_t_group_2_with_the_feed_type_in_group_5():
    from nck.iso.display import iso_gcodes
    result = run_lathe("G50 S3000\nG00 X50. Z2.\nG96 S100 M03\nG01 Z-10. F0.2\nG98 G97 S500\n"
                       "G01 Z-20. F100.\nM30\n", {"MD10881": 1})
    assert result.status == "ended", result.alarms
    views = [iso_gcodes(m.gcodes, "iso-t") for m in result.segments]
    assert (views[1][2], views[1][5]) == ("G96", "G95")
    assert (views[2][2], views[2][5]) == ("G97", "G94")


def test_g28_u0_w0_and_incremental_moves_after_it():
    result = run_lathe("G00 X20. Z30.\nG28 U0. W0.\nG00 U10. W-5.\nG00 X40. Z10.\nG28 U10. W0\nM30\n")
    assert result.status == "ended", result.alarms
    assert points(result) == [("G0", 20.0, 30.0), ("G0", 20.0, 30.0), ("G0", 0.0, 0.0),
                              ("G0", 10.0, -5.0), ("G0", 40.0, 10.0), ("G0", 50.0, 10.0),
                              ("G0", 0.0, 0.0)]


def test_g50_is_not_an_iso_t_code_in_system_b():
    result = run_lathe("G50 S2000\nM30\n")
    assert result.alarms[0].number == 12470
    assert translate("G50.3 P0", "iso-t", _system_a())[0].blocks == translate("G92.1", "iso-t")[0].blocks


def _system_a():
    from nck.iso.translate import IsoSettings
    return IsoSettings(gcode_system=1)


def test_face_thread_takes_its_lead_along_x():
    assert translate("G00 X60. Z0\nG32 X20. F2.", "iso-t")[1].blocks == ["G33 X20 I2"]
    assert translate("G00 X60. Z0\nG32 X20. Z-1. F2.", "iso-t")[1].blocks == ["G33 X20 Z-1 I2"]
    assert translate("G00 X20. Z0\nG32 X22. Z-30. F2.", "iso-t")[1].blocks == ["G33 X22 Z-30 K2"]
    result = run_lathe("G00 X60. Z0\nG32 X20. F2.\nM30\n")
    assert result.status == "ended", result.alarms
    assert result.segments[1].kind == "G33" and result.segments[1].lead_mm == 2.0


def test_g04_u_is_a_dwell_time_and_g96_p_raises():
    assert translate("G00 X20. Z5.\nG04 U1.5", "iso-t")[1].blocks == ["G4 F1.5"]
    assert run_lathe("G00 X20. Z5.\nG96 P1 S100\nM30\n").alarms[0].number == 12080


def test_g71_contour_turning_back_along_z_raises():
    text = ("G00 X50. Z2.\nG71 P10 Q30 F0.2\nN10 G00 X20.\nN20 G01 Z-20.\nN30 X30. Z-10.\nM30\n")
    assert run_lathe(text).alarms[0].number == 61812


def test_g71_start_point_inside_the_contour_raises():
    text = ("G00 X30. Z2.\nG71 P10 Q30 F0.2\nN10 G00 X20.\nN20 G01 Z-20.\nN30 X52. Z-30.\nM30\n")
    assert run_lathe(text).alarms[0].number == 61607
    assert run_lathe(text.replace("X30. Z2.", "X52. Z2.")).status == "ended"


def test_after_a_jumped_contour_the_translator_is_back_at_the_cycle_start():
    # the contour ends in G91 somewhere else; the program continues from A in G90
    text = ("G00 X50. Z2.\nG71 P10 Q30 F0.2\nN10 G00 X20.\nN20 G01 Z-20.\nN30 G91 X10. W-5.\n"
            "N40 G00 U10. W3.\nN50 Z10.\nM30\n")
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    assert points(result, 6) == [("G0", 60.0, 5.0)]
    assert points(result, 7) == [("G0", 60.0, 10.0)]


def test_g76_run_out_leaves_the_thread_at_45_degrees():
    # P01 10 00: one finishing pass, run-out 1.0 lead (= 2 mm at F2), tool angle 0
    text = "G00 X24. Z5.\nG76 P011000 Q50 R0\nG76 X18. Z-20. P1000 Q1000 F2.\nM30\n"
    result = run_lathe(text)
    assert result.status == "ended", result.alarms
    threads = [(round(m.end_wcs["X"], 3), round(m.end_wcs["Z"], 3), m.lead_mm)
               for m in result.segments if m.kind == "G33"]
    # one rough pass at the full height, one finishing pass: each G33 to Z-18, then out to Z-20
    assert threads == [(18.0, -18.0, 2.0), (22.0, -20.0, 2.0)] * 2
