"""Golden: feed, spindle, tool and bad input of the motion builder, through the interpreter."""

from __future__ import annotations

import pytest

from nck import canon
from nck.errors import NcAlarmError
from nck.ncdata import NcData, ToolEdge

from .helpers import approx, lines, mill_data, run


def alarm(text: str, machine: str = "mill3", data: NcData | None = None) -> int:
    with pytest.raises(NcAlarmError) as info:
        run(text, data, machine)
    return info.value.number


@pytest.mark.parametrize(
    ("program", "number"),
    [
        ("N10 G2 X10 Y10 F100\nM30\n", 14040),                        # circle without centre or radius
        ("N10 G2 X40 Y0 CR=10 F100\nM30\n", 14095),                   # CR too small for the chord
        ("N10 G0 X10\nN20 G3 X10 Y0 CR=5 F100\nM30\n", 14040),        # CR with start = end
        ("N10 G3 X10 Y0 I0 J0 F100\nM30\n", 14040),                   # zero radius
        ("N10 G2 X10.5 Y0 I5 J0 F100\nM30\n", 14040),                 # end radius 5.5 vs start 5
        ("N10 CT X10 Y10 F100\nM30\n", 14045),                        # CT with no previous path
        ("N10 CIP X10 Y0 I1=20 J1=0 F100\nM30\n", 14920),             # intermediate beyond the end
        ("N10 G1 X10 CHF=2 F100\nN20 CHF=1\nM30\n", 10882),           # chamfer without motion
        ("N10 S100 M3\nN20 G33 Z-10\nM30\n", 16720),                  # thread without lead
        ("N10 G1 RP=-5 AP=0 F100\nM30\n", 12160),                     # negative polar radius
        ("N10 G4\nM30\n", 12080),                                     # dwell without F or S
        ("N10 G96 S100 LIMS=-1\nM30\n", 14820),
        ("N10 SCALE X2 Y0\nM30\n", 18309),
    ],
)
def test_bad_geometry_is_an_alarm(program: str, number: int) -> None:
    assert alarm(program) == number


def test_g96_without_s_on_a_lathe() -> None:
    assert alarm("N10 G0 X20\nN20 G96 M3\nM30\n", machine="lathe2") == 10900


def test_cip_with_the_intermediate_point_between_is_a_straight_line() -> None:
    r = run(lines("N10 CIP X20 Y0 I1=10 J1=0 F100", "N20 M30"))
    m = r.block(10)[0]
    assert m.center_mcs is None and m.end_mcs == approx({"X": 20.0, "Y": 0.0, "Z": 0.0})


def test_inverse_time_and_axis_feed() -> None:
    """Digest 828d-3 rank 13: G93 F2 -> block time 0.5 min whatever the length."""
    r = run(lines("N10 G93 G1 X30 Y40 F2", "N20 G94 G1 X0 F100", "N30 M30"))
    # G93 F2: the block takes 1/2 min; length 50 mm -> 100 mm/min.
    assert r.block(10)[0].feed_mm_min == pytest.approx(100.0)


def test_m19_spindle_position_and_lims() -> None:
    data = NcData()
    data.setting_data["SD43240"] = 45.0
    r = run(lines("N10 S500 M3", "N20 M19", "N30 LIMS=2000", "N40 M30"), data)
    positioning = [c for c in r.commands if isinstance(c, canon.SpindleCommand) and c.state == "M19"]
    assert positioning[0].position_deg == pytest.approx(45.0)
    # M30 with MD35040 = 0 (default) deletes the direction of rotation (002 L51032-51035).
    assert r.interp.modal.spindle_state == "M5"


def test_tool_change_default_edge_and_d0() -> None:
    """Digest 828d-3 rank 20: M6 activates D1 (MD20270), D0 removes the length.

    Digest programming-840c rank 10 (length acts with the next Z motion; D0 removes it).
    """
    r = run(lines("N10 T1", "N20 M6", "N30 G0 Z0", "N40 D0", "N50 G0 Z0", "N60 M30"), mill_data())
    # M6 activates D1 (MD20270 default); the length 100 acts on Z.
    assert r.end_mcs(30)["Z"] == pytest.approx(100.0)
    assert r.end_mcs(50)["Z"] == pytest.approx(0.0)


def test_tool_length_follows_the_plane_and_wear() -> None:
    """Digest 828d-3 rank 21 (plane mapping of L1/L2 with wear).

    Digest programming-840c rank 6 (G18 length on Y, G19 on X).
    """
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0, 4: 20.0, 12: -0.5})
    r = run(lines("N10 T1 M6 D1", "N20 G17 G0 X0 Y0 Z0", "N30 G18 X0 Y0 Z0", "N40 G19 X0 Y0 Z0",
                  "N50 M30"), data)
    # L1 = 100 - 0.5 wear = 99.5, L2 = 20. G17: L1->Z, L2->Y. G18: L1->Y, L2->X. G19: L1->X, L2->Z.
    assert r.end_mcs(20) == approx({"X": 0.0, "Y": 20.0, "Z": 99.5})
    assert r.end_mcs(30) == approx({"X": 20.0, "Y": 99.5, "Z": 0.0})
    assert r.end_mcs(40) == approx({"X": 99.5, "Y": 0.0, "Z": 20.0})


def test_writing_tc_dp_creates_the_edge_used_by_d() -> None:
    r = run(lines("N10 $TC_DP1[3,2]=120", "N20 $TC_DP3[3,2]=55", "N30 T3 M6 D2", "N40 G0 Z1",
                  "N50 M30"))
    assert r.end_mcs(40)["Z"] == pytest.approx(56.0)


def test_reset_clears_the_programmable_frame_and_the_pole() -> None:
    r = run(lines("N10 TRANS X10", "N20 G111 X5 Y5", "N30 M30"))
    geo = r.interp.modal.geometry
    assert geo.frames.programmable.is_identity()
    assert geo.polar.pole is None


def test_aux_function_limits_per_block() -> None:
    run(lines("N10 M7 M8 M9 M10 M11 H1 H2 H3", "N20 M30"))  # 5 M + 3 H = 8: allowed
    assert alarm(lines("N10 M7 M8 M9 M10 M11 M12", "N20 M30")) == 12010  # 6 M
    assert alarm(lines("N10 H1 H2 H3 H4", "N20 M30")) == 12010
    assert alarm(lines("N10 M7 M8 M9 M10 M11 H1 H2 H3 S100 F100 D1", "N20 M30")) == 12010  # 11 in all


def test_aux_output_order() -> None:
    """T, D and the spindle function go out before the block's motion: the predefined
    functions tool selection (index 21), edge selection (19) and M3 (6) have bit 5 "output
    prior to motion" set by default (002 L14504, L14517, L14519, L14590-14592); the previous
    block ends with exact stop first (002 L4797-4799).

    User functions without a defined output behaviour (M8, H5) go out at block end, after the
    motion (002 L14633-14636; bit 7, L14596-14598). The earlier version of this test froze
    them before the motion; the timing on the real motion: ``tests/motion/test_aux_output_timing.py``.
    """
    r = run(lines("N10 G1 X10 F100 M8 H5 S200 M3 T1 D1", "N20 M30"))
    kinds = [type(c).__name__ for c in r.commands if c.source.n == 10]
    # the cut after M3 first waits for the spindle's set speed range (MD35500, 002 L54530-54536)
    assert kinds == ["ToolSelect", "EdgeSelect", "SpindleCommand", "ExactStop", "Dwell", "Motion",
                     "AuxFunction", "AuxFunction"]
    aux = [(c.address, c.value) for c in r.commands if c.source.n == 10 and isinstance(c, canon.AuxFunction)]
    assert aux == [("M", 8.0), ("H", 5.0)]


def test_g25_g26_write_the_working_area_limits() -> None:
    """Digest programming-840c rank 19."""
    data = NcData()
    run(lines("N10 G25 X-100 Y-50", "N20 G26 X200 Z10", "N30 G70 G26 Y1", "N40 M30"), data)
    assert data.setting_data["SD43430"] == {"X": -100.0, "Y": -50.0}
    assert data.setting_data["SD43420"] == pytest.approx({"X": 200.0, "Z": 10.0, "Y": 25.4})
