"""ISO M frames (section 9 items 11–13): polar G16/G15, rotation G68/G69, scaling G51/G50,
mirroring G51.1/G50.1, and G52/G92.1 keeping them. Golden programs E3 and E4 rebuilt."""

from __future__ import annotations

import pytest

from nck.iso.dialect import dialect_for
from nck import canon
from nck.headless import interpret_only
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.iso.translate import translate
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.iso.conftest import ends, run_iso


def _xy(result, frame: str = "wcs") -> list[tuple[int, float, float]]:
    return [(line, p["X"], p["Y"]) for line, p in ends(result, frame)]


def _run_with_md(text: str, md: dict, subprograms: dict[str, str] | None = None,
                 setting_data: dict | None = None):
    machine = load_machine(None)
    machine.md.update(md)
    data = NcData()
    data.setting_data.update(setting_data or {})
    return interpret_only(machine, MemorySource(subprograms or {}), data, "TEST.MPF", text=text,
                          max_blocks=10_000, dialect="iso-m")


# ------------------------------------------------------------------ polar coordinates (item 11)
E3 = "N5 G17 G90 X0 Y0\nN10 G16 X100. Y45.\nN15 G91 X100 G90 Y0\nN20 Y90.\nN25 G15\nM30\n"


def test_e3_polar_coordinates_golden():
    """Digest iso-dialects-840d rank 11 (E3, 000 L1429-1435)."""
    result = run_iso(E3)
    assert result.status == "ended", result.alarms
    assert _xy(result) == [(1, 0.0, 0.0), (2, 70.711, 70.711), (3, 170.711, 70.711),
                           (4, 0.0, 184.776)]


def test_g15_ends_polar_mode():
    result = run_iso("G90 G16 X10. Y90.\nG15\nX5. Y5.\nM30\n")
    assert _xy(result) == [(1, 0.0, 10.0), (3, 5.0, 5.0)]


def test_polar_angle_incremental_under_g91_and_radius_absolute():
    result = run_iso("G90 G16 X10. Y0\nG91 X10. Y90.\nM30\n")
    # second block: pole at the current position (10, 0), radius 10, angle 0 + 90
    assert _xy(result) == [(1, 10.0, 0.0), (2, 10.0, 10.0)]


def test_g15_deletes_polar_angle():
    """Digest iso-dialects-840d rank 11."""
    result = run_iso("G90 G16 X10. Y90.\nG15\nG16 X20.\nM30\n")
    assert _xy(result)[-1] == (3, 20.0, 0.0)


def test_polar_in_g18_uses_z_as_radius_and_x_as_angle():
    result = run_iso("G18 G90 G16 Z10. X90.\nM30\n")
    point = ends(result)[0][1]
    assert (point["Z"], point["X"]) == (0.0, 10.0)


def test_polar_block_keeps_other_axes_and_feed():
    result = run_iso("G90 G01 G16 X10. Y0 Z-2. F100\nM30\n")
    assert ends(result)[0][1] == {"X": 10.0, "Y": 0.0, "Z": -2.0}


# ------------------------------------------------------------------ rotation (item 12)
def test_g68_rotates_about_the_programmed_pivot():
    """Digest iso-dialects-840d rank 12 (000 L1272-1316)."""
    result = run_iso("G90 G00 X0 Y0\nG68 X0 Y0 R90.\nG01 X10. Y0 F100\nM30\n")
    assert result.status == "ended", result.alarms
    assert _xy(result, "mcs")[-1] == (3, 0.0, 10.0)
    assert _xy(result)[-1] == (3, 10.0, 0.0)


def test_g68_without_pivot_turns_about_the_current_position():
    """Digest iso-dialects-840d rank 12."""
    result = run_iso("G90 G00 X10. Y0\nG68 R90.\nG01 X20. Y0 F100\nM30\n")
    assert _xy(result, "mcs")[-1] == (3, 10.0, 10.0)


def test_second_g68_in_g91_adds_and_g69_clears_both():
    """Digest iso-dialects-840d rank 12."""
    text = ("G90 G00 X0 Y0\nG68 X0 Y0 R30.\nG91 G68 X0 Y0 R60.\nG90 G01 X10. Y0 F100\n"
            "G69\nX10. Y0\nM30\n")
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    mcs = _xy(result, "mcs")
    assert mcs[-2] == (4, 0.0, 10.0)  # 30 + 60 degrees
    assert mcs[-1] == (6, 10.0, 0.0)


def test_g69_may_share_its_block():
    result = run_iso("G68 X0 Y0 R90.\nG69 G01 X10. Y0 F100\nM30\n")
    assert _xy(result, "mcs") == [(2, 10.0, 0.0)]


def test_3d_g68_rotates_about_the_vector_with_pivot_at_zero():
    result = run_iso("G00 X5. Y5.\nG68 I0 J0 K1 R90.\nG01 X10. Y0 F100\nM30\n")
    assert result.status == "ended", result.alarms
    assert _xy(result, "mcs")[-1] == (3, 0.0, 10.0)
    result = run_iso("G68 X0 Y0 Z0 I1 J0 K0 R90.\nG01 X0 Y10. Z0 F100\nM30\n")
    assert ends(result, "mcs")[-1][1] == {"X": 0.0, "Y": 0.0, "Z": 10.0}


def test_3d_g68_with_zero_vector_is_12560():
    """Digest iso-dialects-840d rank 12."""
    result = run_iso("G68 X0 Y0 Z0 I0 J0 K0 R30.\nM30\n")
    assert result.status == "alarm" and result.alarms[0].number == 12560


@pytest.mark.parametrize("text", ["G68 X0 Y0 R90. G01 X1.", "G68 X0 Y0 R90. G01 F100",
                                  "G68 X0 Y0 R90. M3"])
def test_g68_must_be_alone_in_its_block(text):
    """Digest iso-dialects-840d rank 12."""
    result = run_iso(text + "\nM30\n")
    assert result.status == "alarm"
    assert result.alarms[0].number in (12000, 12080)
    if "X1." not in text:
        assert result.alarms[0].number == 12080


def test_g68_r_missing_uses_sd42150():
    result = _run_with_md("G68 X0 Y0\nG01 X10. Y0 F100\nM30\n", {}, setting_data={"SD42150": 90.0})
    assert _xy(result, "mcs")[-1] == (2, 0.0, 10.0)


def test_g52_keeps_the_rotation():
    text = "G68 X0 Y0 R90.\nG52 X5.\nG01 X10. Y0 F100\nG92.1 X0 Y0\nX10. Y0\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    mcs = _xy(result, "mcs")
    assert mcs[0] == (3, 5.0, 10.0)
    assert mcs[1] == (5, 0.0, 10.0)


# ------------------------------------------------------------------ scaling and mirroring (item 13)
E4_MAIN = """O0512 (parts program)
N10 G17 G90 G00 X0 Y0
N30 G90 G01 G94 F6000
N32 M98 P0513
N34 G51 X0. Y0. I-1000 J1000
N36 M98 P0513
N38 G51 X0. Y0. I-1000 J-1000
N40 M98 P0513
N42 G51 X0. Y0. I1000 J-1000
N44 M98 P0513
N46 G50
N50 G00 X0 Y0
N55 G01 X50. Y50.
N60 M30
"""
E4_SUB = "O0513 (subprogram)\nN10 G90 X10. Y10.\nN20 X50.\nN30 Y50.\nN40 X10. Y10.\nN50 M99\n"
E4_MD = {"MD22910": 0, "MD22914": 1, "MD10884": False, "MD10886": 0}


def test_e4_scaling_mirrors_the_square_into_each_quadrant():
    """Digest iso-dialects-840d rank 13 (E4, 000 L1192-1219)."""
    result = _run_with_md(E4_MAIN, E4_MD, {"O0513": E4_SUB})
    assert result.status == "ended", result.alarms
    mcs = [(x, y) for _line, x, y in _xy(result, "mcs")]
    squares = [mcs[1 + 4 * k: 5 + 4 * k] for k in range(4)]
    assert squares[0] == [(10.0, 10.0), (50.0, 10.0), (50.0, 50.0), (10.0, 10.0)]
    assert squares[1] == [(-10.0, 10.0), (-50.0, 10.0), (-50.0, 50.0), (-10.0, 10.0)]
    assert squares[2] == [(-10.0, -10.0), (-50.0, -10.0), (-50.0, -50.0), (-10.0, -10.0)]
    assert squares[3] == [(10.0, -10.0), (50.0, -10.0), (50.0, -50.0), (10.0, -10.0)]
    assert mcs[-1] == (50.0, 50.0)  # after G50 the contour is unscaled


def test_axial_scaling_needs_md22914():
    """Digest iso-dialects-840d rank 13."""
    result = _run_with_md("G51 I2000 J500\nG01 X10. Y10. F100\nM30\n", {"MD22914": 0})
    assert _xy(result, "mcs") == [(2, 10.0, 10.0)]
    result = _run_with_md("G51 I2000 J500\nG01 X10. Y10. F100\nM30\n", {"MD22914": 1})
    assert _xy(result, "mcs") == [(2, 20.0, 5.0)]


def test_uniform_scaling_with_p_and_weighting_md22910():
    result = _run_with_md("G51 P1500\nG01 X10. Y-4. Z2. F100\nM30\n", {})
    assert ends(result, "mcs")[0][1] == {"X": 15.0, "Y": -6.0, "Z": 3.0}
    result = _run_with_md("G51 P150000\nG01 X10. F100\nM30\n", {"MD22910": 1})
    assert ends(result, "mcs")[0][1]["X"] == 15.0


def test_negative_p_is_12560():
    result = run_iso("G51 P-1000\nM30\n")
    assert result.alarms[0].number == 12560


def test_g51_1_mirrors_about_a_position():
    """Digest iso-dialects-840d rank 13 (G51.1 X80 then X100 ends at 60)."""
    result = run_iso("G51.1 X80.\nG00 X100.\nM30\n")
    assert _xy(result, "mcs") == [(2, 60.0, 0.0)]


def test_mirrors_are_additive_and_g50_1_cancels_per_axis():
    """Digest iso-dialects-840d rank 13."""
    text = "G51.1 X10.\nG51.1 Y10.\nG00 X0 Y0\nG50.1 X0\nX0 Y0\nG50.1 X0 Y0\nX0 Y0\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert _xy(result, "mcs") == [(3, 20.0, 20.0), (5, 0.0, 20.0), (7, 0.0, 0.0)]


@pytest.mark.parametrize("text", ["G51.1 X80. G00 X100.", "G50.1 X0 F100"])
def test_mirroring_must_be_alone_in_its_block(text):
    result = run_iso(text + "\nM30\n")
    assert result.alarms[0].number in (12000, 12080)


def test_mirroring_in_standard_notation_counts_increments():
    result = _run_with_md("G51.1 X80000\nG00 X100.\nM30\n", {"MD10884": False})
    assert _xy(result, "mcs") == [(2, 60.0, 0.0)]


def _mcs_ends(interp: Interpreter) -> list[dict[str, float]]:
    out = []
    while not interp.finished:
        for command in interp.step().commands:
            if isinstance(command, canon.Motion):
                out.append({a: round(v, 3) for a, v in command.end_mcs.items()})
    return out


def test_reset_clears_g51_1():
    """Digest iso-dialects-840d rank 13 (000 L1270)."""
    interp = Interpreter(load_machine(None), MemorySource(), NcData(), dialect=dialect_for("iso-m", load_machine(None)))
    interp.start_text("A.MPF", "G51.1 X80.\nG00 X100.\nM30\n")
    assert _mcs_ends(interp)[-1]["X"] == 60.0
    interp.start_text("B.MPF", "G00 X100.\nM30\n")
    assert _mcs_ends(interp)[-1]["X"] == 100.0


def test_siemens_mode_sees_the_shared_mirror_frame():
    text = "G51.1 X80.\nG290\nG0 X100\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert _xy(result, "mcs") == [(3, 60.0, 0.0)]


def test_translation_of_frame_blocks():
    lines = translate("N10 G68 X1. Y2. R30.\nN20 G69 G01 X1.\nN30 G51.1 X5.\nG16 X10. Y30.")
    sync = "$P_ISOFR_SYNC=0"
    assert lines[0].blocks == ["N10 $P_ISOFR_ROT[19, 1, 2, 0, 0, 0, 0]=30", f"N10 {sync}"]
    assert lines[1].blocks == ["N20 $P_ISOFR_ROTOFF=0", f"N20 {sync}", "N20 G1 X1"]
    assert lines[2].blocks == ["N30 $P_ISOFR_MIRROR[X]=5", f"N30 {sync}"]
    assert lines[3].blocks == ["$P_ISOFR_POLARON=0", "G111 X0 Y0", "RP=AC(10) AP=AC(30)"]


# ------------------------------------------------------------------ SD 42440 (offset change in G91)
@pytest.mark.parametrize("change", ["G10 L2 P2 X5. Y5. Z1.\nG55", "G52 X5. Y5. Z1.",
                                    "G10 L2 P2 X5. Y5. Z1.\nG55 G91 X1.\nG90 X-4."])
def test_sd42440_0_offset_change_not_travelled_in_g91(change):
    text = f"G0 X0 Y0 Z20.\n{change}\nG91 G1 X1. F100\nM30\n"
    result = _run_with_md(text, {}, setting_data={"SD42440": False})
    assert result.status == "ended", result.alarms
    twice = "G91 X1." in change
    assert ends(result)[-1][1] == {"X": -3.0 if twice else -4.0, "Y": -5.0, "Z": 19.0}
    assert ends(result, "mcs")[-1][1] == {"X": 2.0 if twice else 1.0, "Y": 0.0,
                                          "Z": 20.0}


def test_sd42440_1_keeps_the_programmed_point():
    text = "G0 X0 Y0 Z20.\nG52 X5. Y5. Z1.\nG91 G1 X1. F100\nM30\n"
    result = _run_with_md(text, {}, setting_data={"SD42440": True})
    # X: the increment from the programmed point 0 (the G52 shift is travelled, 002 L26937-26942);
    # Y and Z are not programmed and stay in the machine (0, 20): in the G52 system -5 and 19.
    assert ends(result)[-1][1] == {"X": 1.0, "Y": -5.0, "Z": 19.0}
    assert ends(result, "mcs")[-1][1] == {"X": 6.0, "Y": 0.0, "Z": 20.0}


def test_g58_g59_select_settable_offsets_5_and_6():
    text = "G10 L2 P5 X7.\nG10 L2 P6 X9.\nG58\nG0 X0\nG59\nX0\nM30\n"
    result = run_iso(text)
    assert [p["X"] for _line, p in ends(result, "mcs")] == [7.0, 9.0]


def test_inch_program_selects_offsets_stored_in_mm():
    """A settable offset is kept in the basic system (mm); G20 must not convert it twice."""
    text = "G20\nG10 L2 P2 X1.\nG55\nG0 X0\nM30\n"
    result = run_iso(text)
    assert ends(result, "mcs")[0][1]["X"] == 25.4


def test_g15_deletes_pole_radius_and_angle_at_run_time():
    """Even a Siemens polar move after G15 starts from a fresh pole (the origin), RP 0, AP 0."""
    text = "G90 G16 X10. Y90.\nG15\nG290\nG0 RP=5\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert _xy(result)[-1] == (4, 5.0, 0.0)


def _views(text: str) -> dict[int, dict[int, str]]:
    interp = Interpreter(load_machine(None), MemorySource(), NcData(), dialect=dialect_for("iso-m", load_machine(None)))
    interp.start_text("T.MPF", text)
    views = {}
    while not interp.finished:
        line = interp.step().source.line
        views[line] = dict(interp.modal_view().iso_gcodes)
    return views


def test_g_group_display_shows_active_iso_frames():
    text = "G68 X0 Y0 R30.\nG51 P2000\nG51.1 X5.\nG16 X10. Y0\nG15 G69\nG50 X0\nG50.1 X0\nM30\n"
    views = _views(text)
    assert views[1][16] == "G68" and views[1][11] == "G50"
    assert views[2][11] == "G51"
    assert views[3][22] == "G51.1"
    assert views[4][17] == "G16"
    assert views[5][17] == "G15" and views[5][16] == "G69" and views[5][11] == "G51"
    assert views[7] [22] == "G50.1" and views[7][11] == "G50"


@pytest.mark.parametrize("code", ["G68", "G51 P2000", "G51.1 X1.", "G16 X1. Z0"])
def test_iso_t_has_no_milling_frames(code):
    line = translate(code, "iso-t")[0]
    assert line.error is not None and line.error.number == 12470


def test_drilling_cycle_under_g16_is_61814():
    result = run_iso("G16 G81 X10. Y45. Z-5. R2. F100\nG80\nM30\n")
    assert result.status == "alarm" and result.alarms[0].number == 61814
    result = run_iso("M3 S1000\nG16 X10. Y45.\nG15\nG81 X10. Y45. Z-5. R2. F100\nG80\nM30\n")
    assert result.status == "ended", result.alarms


@pytest.mark.parametrize("sd42440", [True, False])
def test_axes_not_programmed_after_an_offset_change_report_their_actual_position(sd42440):
    # G55 = (5, 7, -3) written by G10 L2 P2; after G54 (zero) G0 X10 Y10 Z20 a G55 block with
    # only X moves X alone: Y and Z stay at machine 10 and 20, which in the G55 system is
    # 10 - 7 = 3 and 20 + 3 = 23 — that is what the actual value display shows (issue 20).
    # SD 42440 only decides whether an incremental move travels the change (002 L26937-26942).
    text = "G10 L2 P2 X5. Y7. Z-3.\nG54 G00 X10. Y10. Z20.\nG55\nG00 X5.\nM30\n"
    result = _run_with_md(text, {}, setting_data={"SD42440": sd42440})
    assert ends(result)[-1][1] == {"X": 5.0, "Y": 3.0, "Z": 23.0}
    assert ends(result, "mcs")[-1][1] == {"X": 10.0, "Y": 10.0, "Z": 20.0}


def test_axes_not_programmed_after_a_frame_change_in_siemens_mode():
    # The same in Siemens mode, with the plain block path: $P_UIFR[2] = G55 (5, 7, -3).
    text = ("$P_UIFR[2]=CTRANS(X,5,Y,7,Z,-3)\nG54 G0 X10 Y10 Z20\nG55\nG0 X5\n"
            "G1 Y2 F100\nG91 G1 Z1\nM30\n")
    result = run_iso(text, dialect="siemens")
    assert ends(result)[1:] == [
        (4, {"X": 5.0, "Y": 3.0, "Z": 23.0}),
        (5, {"X": 5.0, "Y": 2.0, "Z": 23.0}),
        # SD 42440 = 1 (default): the increment starts from the programmed Z 20 and the
        # offset change is travelled: WCS 21, machine 21 - 3 = 18 (002 L26937-26942).
        (6, {"X": 5.0, "Y": 2.0, "Z": 21.0}),
    ]
    assert ends(result, "mcs")[-1][1] == {"X": 10.0, "Y": 9.0, "Z": 18.0}
