"""The removal model against volumes and depths computed by hand.

Each program runs as AUTO runs it (``nck.simulation.run.simulate``) and the Z-map's removed
volume is compared with the exact volume of the cut, within 1 % at the tested resolution.
Tool data: ``$TC_DP1`` type, ``$TC_DP3`` length 1, ``$TC_DP6`` radius, ``$TC_DP24`` drill tip
angle (002 L62525-62558).
"""

from __future__ import annotations

import math

import pytest

from nck.ncdata import NcData, ToolEdge
from nck.simulation.run import simulate

HEADER = 'N1 WORKPIECE(,"",,"BOX",112,0,-20,-20,0,0,100,100)\nN2 G17 G90 G54\n'


def tools() -> NcData:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 60.0, 6: 5.0})  # end mill D10
    data.tools[(2, 1)] = ToolEdge({1: 200.0, 3: 70.0, 6: 4.0, 24: 118.0})  # twist drill D8, 118°
    data.tools[(3, 1)] = ToolEdge({1: 110.0, 3: 65.0, 6: 5.0})  # ball end mill D10
    return data


def run(body: str, resolution_mm: float = 0.1):
    result = simulate("P.MPF", HEADER + body + "N999 M30\n", data=tools(), resolution_mm=resolution_mm)
    assert result.status == "ended" and result.alarms == []
    return result


def test_slot_of_known_width_depth_and_length() -> None:
    result = run("N10 T1 M6\nN20 D1 S2000 M3\nN30 G0 X20 Y50 Z2\nN40 G1 Z-5 F200\nN50 X80 F600\nN60 G0 Z10\n")
    # A 60 mm straight slot of width 10 (D10) with half-round ends, 5 deep:
    # (60 * 10 + pi * 5^2) * 5 = (600 + 78.540) * 5 = 3392.70 mm³.
    exact = (60.0 * 10.0 + math.pi * 25.0) * 5.0
    assert result.zmap.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    zmap = result.zmap
    assert zmap.height_at(50.0, 50.0) == pytest.approx(-5.0)
    assert zmap.height_at(50.0, 45.05) == pytest.approx(-5.0)  # inside the wall at Y 45
    assert zmap.height_at(50.0, 44.95) == pytest.approx(0.0)  # outside: untouched
    assert zmap.height_at(50.0, 54.95) == pytest.approx(-5.0)
    assert zmap.height_at(50.0, 55.05) == pytest.approx(0.0)
    assert zmap.height_at(85.05, 50.0) == pytest.approx(0.0)  # the end's half circle stops at X 85
    assert result.events == []


def test_pocket() -> None:
    # Pocket X 30..70, Y 35..65 with a D10 end mill: tool centres cover X 35..65, Y 40..60
    # (zigzag at 8 mm steps < 10, then the contour). Removed outline: the 40 x 30 rectangle
    # with its corners rounded by R5: 1200 - (4 - pi) * 25 = 1178.54 mm²; 4 deep: 4714.16 mm³.
    body = ("N10 T1 M6\nN20 D1 S2000 M3\nN30 G0 X35 Y40 Z2\nN40 G1 Z-4 F200\n"
            "N50 X65 F800\nN60 Y48\nN70 X35\nN80 Y56\nN90 X65\nN100 Y60\nN110 X35\nN120 Y40\nN130 G0 Z10\n")
    result = run(body)
    exact = (40.0 * 30.0 - (4.0 - math.pi) * 25.0) * 4.0
    assert result.zmap.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    assert result.zmap.height_at(50.0, 50.0) == pytest.approx(-4.0)
    assert result.zmap.height_at(30.05, 50.0) == pytest.approx(-4.0)
    assert result.zmap.height_at(29.95, 50.0) == pytest.approx(0.0)


def test_drilled_hole_with_point_angle() -> None:
    result = run("N10 T2 M6\nN20 D1 S1000 M3\nN30 G0 X50 Y50 Z2\nN40 G1 Z-10 F100\nN50 G0 Z10\n",
                 resolution_mm=0.05)
    # D8 drill, tip 118°, tip at Z-10: cone height 4 / tan(59°) = 2.4034 mm;
    # cylinder pi * 16 * (10 - 2.4034) = 381.84, cone pi * 16 * 2.4034 / 3 = 40.27: 422.11 mm³.
    cone = 4.0 / math.tan(math.radians(59.0))
    exact = math.pi * 16.0 * (10.0 - cone) + math.pi * 16.0 * cone / 3.0
    assert result.zmap.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    # The cell holding (50, 50) has its centre at (50.025, 50.025), 0.0354 off the axis:
    # the point is 0.0354 / tan(59°) = 0.021 higher there.
    assert result.zmap.height_at(50.0, 50.0) == pytest.approx(-10.0 + 0.0354 / math.tan(math.radians(59.0)), abs=0.002)
    # 2 mm from the axis the point is 2 / tan(59°) = 1.2017 higher.
    assert result.zmap.height_at(52.0, 50.0) == pytest.approx(-10.0 + 2.0 / math.tan(math.radians(59.0)), abs=0.05)


def test_ball_mill_groove_cross_section() -> None:
    result = run("N10 T3 M6\nN20 D1 S3000 M3\nN30 G0 X20 Y50 Z2\nN40 G1 Z-3 F200\nN50 X80 F600\nN60 G0 Z10\n")
    # Ball R5, tip 3 deep: the cross-section is a circular segment of height h = 3:
    # R² acos((R-h)/R) - (R-h) sqrt(2Rh - h²) = 25 acos(0.4) - 2 sqrt(21) = 19.8168 mm²;
    # along 60 mm plus the two half caps at the ends (one cap: pi h² (3R - h) / 3 = 113.097):
    # 60 * 19.8168 + 113.097 = 1302.11 mm³.
    section = 25.0 * math.acos(0.4) - 2.0 * math.sqrt(21.0)
    exact = 60.0 * section + math.pi * 9.0 * 12.0 / 3.0
    assert result.zmap.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    zmap = result.zmap
    assert zmap.height_at(50.0, 50.0) == pytest.approx(-3.0, abs=0.01)
    # The cell centred 3.05 mm aside: the ball's surface is 5 - sqrt(25 - 3.05²) = 1.038 above the tip.
    assert zmap.height_at(50.0, 53.02) == pytest.approx(-3.0 + 5.0 - math.sqrt(25.0 - 3.05 ** 2), abs=0.002)
    # The groove is 2 sqrt(21) = 9.165 wide at the top: Y 45.42 .. 54.58.
    assert zmap.height_at(50.0, 54.5) < 0.0
    assert zmap.height_at(50.0, 54.65) == pytest.approx(0.0)


def test_corner_radius_mill_floor_and_fillet() -> None:
    data = tools()
    data.tools[(4, 1)] = ToolEdge({1: 121.0, 3: 60.0, 6: 5.0, 7: 2.0})  # D10, corner R2
    body = "N10 T4 M6\nN20 D1 S2000 M3\nN30 G0 X20 Y50 Z2\nN40 G1 Z-5 F200\nN50 X80 F600\nN60 G0 Z10\nN999 M30\n"
    result = simulate("P.MPF", HEADER + body, data=data, resolution_mm=0.1)
    zmap = result.zmap
    assert zmap.height_at(50.0, 52.95) == pytest.approx(-5.0)  # flat part: r <= 3
    # At r = 4.05 the fillet (centre at r 3, 2 above the tip) is 2 - sqrt(4 - 1.05²) = 0.298 high.
    assert zmap.height_at(50.0, 54.05) == pytest.approx(-5.0 + 2.0 - math.sqrt(4.0 - 1.05 ** 2), abs=0.01)


def test_events_name_their_blocks() -> None:
    body = ("N10 T1 M6\nN20 D1 S2000 M3\nN30 G0 X20 Y50 Z2\nN40 G0 Z-2\nN50 G1 Z5 F500\n"
            "N60 M5\nN70 G0 X50\nN80 G1 Z-1\nN90 X60\nN100 G0 Z10\n")
    result = run(body, resolution_mm=0.25)
    assert [(e.kind, e.n) for e in result.events] == [
        ("rapid_cut", 40), ("spindle_stopped", 80), ("spindle_stopped", 90)]
    assert result.events[0].depth_mm == pytest.approx(2.0)


def test_machining_time_is_the_runs_and_split_per_tool() -> None:
    body = ("N10 T1 M6\nN20 D1 S2000 M3\nN30 G0 X20 Y50 Z2\nN40 G1 Z-5 F200\nN50 X80 F600\nN60 G0 Z10\n"
            "N70 T2 M6\nN80 D1\nN90 G0 X50 Y20 Z2\nN100 G1 Z-10 F100\nN110 G0 Z10\n")
    result = run(body, resolution_mm=0.5)
    # At least the feed moves' own times: T1 7 mm at 200 mm/min = 2.1 s and 60 mm at 600 = 6 s,
    # T2 12 mm at 100 = 7.2 s; acceleration and rapid moves only add.
    assert result.machine_time_s > 2.1 + 6.0 + 7.2
    assert result.tool_times_s[1] > 2.1 + 6.0
    assert result.tool_times_s[2] > 7.2
    assert sum(result.tool_times_s.values()) == pytest.approx(result.machine_time_s)
