"""ISO M drilling cycles (section 9 item 6) and subprograms M98/M99 (item 7)."""

from __future__ import annotations

import pytest

from nck.iso.cycles import peck_depths
from tests.iso.conftest import ends, run_iso

HEAD = "G0 X0 Y0 Z50. M3 S1000\n"  # the spindle turns: a drilling cycle without M3/M4 is 61102


def _z_path(result):
    return [(line, point["X"], point["Y"], point["Z"]) for line, point in ends(result)]


def test_g81_g99_drills_in_its_block_and_next_block_uses_new_r():
    """Digest iso-dialects-840d rank 6 (000 L3408-3625)."""
    text = HEAD + "G17 G90 G99 G81 X10. Y20. Z-15. R5. F1000\nX50. Y30. R10.\nG80\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    path = _z_path(result)[1:]
    assert path == [
        (2, 10.0, 20.0, 50.0), (2, 10.0, 20.0, 5.0), (2, 10.0, 20.0, -15.0), (2, 10.0, 20.0, 5.0),
        (3, 50.0, 30.0, 5.0), (3, 50.0, 30.0, 10.0), (3, 50.0, 30.0, -15.0), (3, 50.0, 30.0, 10.0),
    ]
    kinds = [m.kind for m in result.segments[1:5]]
    assert kinds == ["G0", "G0", "G1", "G0"]
    assert result.segments[3].feed == 1000.0


def test_g98_returns_to_initial_plane():
    """Digest iso-dialects-840d rank 6."""
    text = HEAD + "G17 G90 G98 G81 X10. Y20. Z-15. R5. F1000\nX50. Y30. R10.\nG80\nM30\n"
    path = _z_path(run_iso(text))
    assert path[4][3] == 50.0 and path[-1][3] == 50.0


def test_cycle_block_without_position_and_k0_do_not_drill():
    """Digest iso-dialects-840d rank 6."""
    text = HEAD + "G99 G81 X10. Y20. Z-15. R5. F1000\nF500\nX30. K0\nG80\nM30\n"
    path = _z_path(run_iso(text))
    assert all(line in (1, 2) for line, *_ in path)


def test_g80_and_g00_cancel_the_cycle():
    """Digest iso-dialects-840d rank 6."""
    for cancel in ("G80", "G00"):
        text = HEAD + f"G99 G81 X10. Y20. Z-15. R5. F1000\n{cancel}\nX30.\nM30\n"
        path = _z_path(run_iso(text))
        assert path[-1] == (4, 30.0, 20.0, 5.0)


def test_missing_z_is_61808():
    """Digest iso-dialects-840d rank 6."""
    result = run_iso(HEAD + "G81 X10. Y20. R5. F1000\nM30\n")
    assert result.alarms[0].number == 61808


@pytest.mark.parametrize("code", ["G83", "G73"])
@pytest.mark.parametrize("q_word", ["", "Q0"])
def test_peck_without_q_is_61808(code, q_word):
    """Digest iso-dialects-840d rank 6."""
    result = run_iso(HEAD + f"{code} X10. Y20. Z-15. R5. {q_word} F1000\nM30\n")
    assert result.alarms[0].number == 61808


def test_g83_pecks_back_to_r_plane():
    result = run_iso(HEAD + "G99 G83 X0 Y0 Z-10. R2. Q5. F100\nG80\nM30\n")
    assert result.status == "ended", result.alarms
    feeds = [round(m.end_wcs["Z"], 3) for m in result.segments if m.kind == "G1"]
    assert feeds == [-3.0, -8.0, -10.0]
    rapids = [round(m.end_wcs["Z"], 3) for m in result.segments[2:] if m.kind == "G0"]
    assert 2.0 in rapids and rapids[-1] == 2.0


def test_g73_retracts_a_little():
    result = run_iso(HEAD + "G99 G73 X0 Y0 Z-10. R2. Q5. F100\nG80\nM30\n")
    zs = [round(m.end_wcs["Z"], 3) for m in result.segments[2:]]
    assert zs == [2.0, -3.0, -2.0, -8.0, -7.0, -10.0, 2.0]


def test_peck_depths_cover_the_total():
    assert peck_depths(12.0, 5.0) == [5.0, 10.0, 12.0]
    assert peck_depths(4.0, 5.0) == [4.0]


def test_g82_dwells_and_g85_feeds_out():
    result = run_iso(HEAD + "G99 G82 X0 Y0 Z-5. R1. P500 F100\nG85 X5.\nG80\nM30\n")
    assert result.status == "ended", result.alarms
    g85 = [m for m in result.segments if m.source.line == 3]
    assert [m.kind for m in g85] == ["G0", "G0", "G1", "G1"]


def test_g91_cycle_r_from_initial_z_from_r():
    result = run_iso(HEAD + "G91 G99 G81 X10. Y0 Z-20. R-40. F100\nG80\nM30\n")
    zs = [round(m.end_wcs["Z"], 3) for m in result.segments[1:]]
    assert zs == [50.0, 10.0, -10.0, 10.0]


def test_inserted_moves_carry_cycle_block_number():
    result = run_iso(HEAD + "N40 G81 X10. Y20. Z-15. R5. F1000\nM30\n")
    assert {m.source.n for m in result.segments[1:]} == {40}


def test_m98_repeat_count_in_p():
    sub = "O0021\nG91 G01 X1. F100\nM99\n"
    result = run_iso("M98 P30021\nM30\n", {"O0021": sub})
    assert result.status == "ended", result.alarms
    assert [e[1]["X"] for e in ends(result)] == [1.0, 2.0, 3.0]


def test_m98_with_l_count():
    sub = "G91 G01 X1. F100\nM99\n"
    result = run_iso("M98 P55 L4\nM30\n", {"O0055": sub})
    assert len(result.segments) == 4


def test_m98_l_takes_precedence_over_count_digits():
    sub = "G91 G01 X1. F100\nM99\n"
    result = run_iso("M98 P30077 L2\nM30\n", {"O0077": sub})
    assert result.status == "ended", result.alarms
    assert len(result.segments) == 2



@pytest.mark.parametrize("code", ["G81 X10. Y20. Z-15. R5.", "G84 X10. Y20. Z-15. R5.",
                                  "G86 X10. Y20. Z-15. R5.", "G83 X10. Y20. Z-15. R5. Q5."])
@pytest.mark.parametrize("spindle", ["", "M5", "M3 S1000\nM5"])
def test_a_drilling_cycle_without_spindle_direction_is_61102(code, spindle):
    """000 L5891: 61102 "No spindle direction programmed" (spindle direction M03 or M04 missing)
    in the shell cycles of G81 … G89: the cycle stops before any motion of the hole."""
    result = run_iso(f"G0 X0 Y0 Z50.\n{spindle}\nG90 G99 {code} F1000\nG80\nM30\n".replace("\n\n", "\n"))
    assert result.status == "alarm" and [a.number for a in result.alarms] == [61102]
    assert all(point["Z"] == 50.0 for _, point in ends(result))  # not one move towards the hole


@pytest.mark.parametrize("spindle", ["M3 S1000", "M4 S500"])
def test_a_drilling_cycle_with_the_spindle_turning_runs(spindle):
    result = run_iso(f"G0 X0 Y0 Z50. {spindle}\nG90 G99 G81 X10. Y20. Z-15. R5. F1000\nG80\nM30\n")
    assert result.status == "ended", result.alarms
