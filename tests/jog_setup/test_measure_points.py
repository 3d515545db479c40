"""Measure workpiece from several touches: corner, rotated corner, hole, spigot (issue 22).

Manual measuring (002 L31279-31290): the touches are saved as points P1, P2 … (⇧F6), the
window shows the result, ⇧F5 "Set WO" writes it. Under G500 the translation goes into the
system frame for PRESET and scratching $P_SETFR (002 L30600-30612); the rotation of a rotated
corner into the active settable offset G54.

Hand values. 3D probe T1: type 710, length 150 to the ball centre, ball radius 2; end mill
T2: L 100, R 5. The blank is a box X −73.5 … 26.5, Y −41.25 … 38.75, Z −250 … −220 (MCS), so a
corner at X0 = Y0 = 0 gives the translation (−73.5, −41.25); the opposite corner is at
(100, 80) of that WCS. A probe stops at its trigger: the ball centre 2 mm before the face.
"""

from __future__ import annotations

import math

import pytest

from nck import commands as cmd
from nck.kernel import Nck
from nck.ncdata import NcData, ToolEdge
from nck.workpiece import Box, Cylinder, MachineSetup

from hmi.app import HmiApp
from tests.burst import burst
from tests.jog_setup.kernels import run_in_mda_then_jog

SIZE = (160, 48)
BLANK = Box((-73.5, -41.25, -250.0), (26.5, 38.75, -220.0))
SPIGOT = Cylinder((-12.0, 7.5, -250.0), 40.0, 30.0)  # centre X −12 Y 7.5, Ø 40, top Z −220


def kernel(tool: int, blank: Box | Cylinder | None = BLANK) -> Nck:
    """Probe T1 and end mill T2 in the tool list; ``tool`` loaded; the ball/tip at Z −230."""
    data = NcData()
    data.machine_setup = MachineSetup(blank=blank)
    data.tools[(1, 1)] = ToolEdge({1: 710.0, 3: 150.0, 6: 2.0})
    data.tools[(2, 1)] = ToolEdge({1: 120.0, 3: 100.0, 6: 5.0})
    nck = Nck(data=data, referenced=True)
    return run_in_mda_then_jog(nck, f"T{tool} D1 M6\nG0 X-150 Y-100 Z-150\n")


def move_to(app: HmiApp, x: float, y: float, z: float = -230.0) -> None:
    """Traverse the tool (its tip, G500, no offset yet) over the blank to X/Y, then down to Z —
    a short MDA job between two touches, back in JOG after it."""
    run_in_mda_then_jog(app.bridge.nck, f"G0 Z-150\nX{x} Y{y}\nZ{z}\n")
    app.bridge.poll(force=True)


def probe(app: HmiApp, axis: str, direction: int) -> None:
    """JOG the probe along ``axis`` until it switches and the kernel stops the motion."""
    assert app.bridge.submit(cmd.Jog(axis, direction)) == cmd.Accepted()
    app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=10.0)
    app.bridge.submit(cmd.Jog(axis, 0))


def info(app: HmiApp, view: str) -> str:
    """The preview of a window."""
    return str(app.screen.query_one(f"#view-{view}-info").render())


def setframe(nck: Nck) -> tuple[float, float]:
    """The X/Y translation of $P_SETFR."""
    return nck.data.setframe.trans.get("X", 0.0), nck.data.setframe.trans.get("Y", 0.0)


async def touch_and_save(pilot, app: HmiApp, at: tuple[float, float], axis: str, direction: int) -> None:
    """Move the probe to ``at``, probe along ``axis``, save the point (⇧F6)."""
    move_to(app, *at)
    probe(app, axis, direction)
    await pilot.pause()
    await burst(pilot, "shift+f6")


@pytest.mark.parametrize("touches, approach_keys, setpoint, expected_mcs", [
    # lower-left corner: P1 moving +X (trigger −75.5), P2 moving +Y (trigger −43.25)
    ((((-100.0, -20.0), "X", 1), ((-60.0, -60.0), "Y", 1)), [], (0.0, 0.0), (-73.5, -41.25)),
    # upper-right corner from the other side: −X (trigger 28.5), −Y (trigger 40.75); X0 100, Y0 80
    (((((50.0, 20.0), "X", -1), ((10.0, 60.0), "Y", -1))), ["right", "down", "right"], (100.0, 80.0),
     (26.5, 38.75)),
])
async def test_corner_with_the_probe_from_either_side_gives_the_same_zero(touches, approach_keys, setpoint,
                                                                         expected_mcs) -> None:
    """Both corners give the translation (−73.5, −41.25): the blank's lower-left corner is the zero."""
    app = HmiApp(kernel(1), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f2", *approach_keys)
        for at, axis, direction in touches:
            await touch_and_save(pilot, app, at, axis, direction)
        keys = ["down"] * (2 - (1 if approach_keys else 0))
        await burst(pilot, *keys, "ctrl+a", "ctrl+k", *f"{setpoint[0]:g}", "down", "ctrl+a", "ctrl+k",
                    *f"{setpoint[1]:g}")
        text = info(app, "meascorner")
        assert f"Corner: X (MCS) {expected_mcs[0]:.3f}  Y (MCS) {expected_mcs[1]:.3f}" in text, text
        assert "(probe)" in text
        await burst(pilot, "shift+f5")
        assert setframe(app.bridge.nck) == pytest.approx((-73.5, -41.25), abs=1e-6)
        wcs = {a.name: a.position_wcs for a in app.bridge.status.axes}
        mcs = {a.name: a.position_mcs for a in app.bridge.status.axes}
        assert wcs["X"] == pytest.approx(mcs["X"] + 73.5, abs=1e-6)


async def test_corner_with_a_cutter_scratching_takes_its_radius() -> None:
    """End mill R 5 (no blank in the way: the positions stand for the touches): centre at
    X −78.5 touching the X edge moving +, at Y −46.25 touching the Y edge moving +: corner
    (−73.5, −41.25); the whole burst in one go, X0 = 10 → translation X −83.5."""
    app = HmiApp(kernel(2, blank=None), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f2")
        move_to(app, -78.5, 0.0)
        await pilot.pause()
        await burst(pilot, "shift+f6")
        move_to(app, 0.0, -46.25)
        await pilot.pause()
        await burst(pilot, "shift+f6", "down", "down", "ctrl+a", "ctrl+k", "1", "0", "shift+f5")
        assert setframe(app.bridge.nck) == pytest.approx((-83.5, -41.25), abs=1e-6)


def rotated(x: float, y: float, angle_deg: float) -> tuple[float, float]:
    """(x, y) turned by ``angle_deg`` about the origin."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    return x * c - y * s, x * s + y * c


async def test_rotated_corner_writes_the_angle_and_the_corner() -> None:
    """A block turned by 20° with its corner at MCS (−30, −20) (not in the kernel's set-up: the
    cutter R 5 stands where it would touch). Edge 1 runs along 20°, edge 2 along 110°; the
    cutter centre lies 5 mm outside each edge: P1, P2 on edge 1 at 10 and 40 mm from the
    corner, P3 on edge 2 at 15 mm. Under G54 (empty): ROT Z 20 in G54, and the corner reads
    X0 = Y0 = 0: the WCS of the corner point is 0 after the write (checked through the
    kernel's frames: the WCS of the tool centre over the corner)."""
    nck = kernel(2, blank=None)
    run_in_mda_then_jog(nck, "G54\n")
    corner = (-30.0, -20.0)
    outward1 = rotated(0.0, -5.0, 20.0)    # edge 1's outside (below it)
    outward2 = rotated(-5.0, 0.0, 20.0)    # edge 2's outside (left of it)
    p1, p2 = (rotated(d, 0.0, 20.0) for d in (10.0, 40.0))
    p3 = rotated(0.0, 15.0, 20.0)
    points = [(corner[0] + p[0] + o[0], corner[1] + p[1] + o[1])
              for p, o in ((p1, outward1), (p2, outward1), (p3, outward2))]
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f3", "right", "right", "down", "right", "right")
        # edge 1 approached in +Y (from below), edge 2 in +X (from the left)
        assert app.screen.query_one("#view-measrot-first").value == "+Y"  # type: ignore[attr-defined]
        assert app.screen.query_one("#view-measrot-third").value == "+X"  # type: ignore[attr-defined]
        for x, y in points:
            move_to(app, x, y, -150.0)
            await pilot.pause()
            await burst(pilot, "shift+f6")
        assert "edge 1 at 20.000°" in info(app, "measrot"), info(app, "measrot")
        assert "X (MCS) -30.000  Y (MCS) -20.000" in info(app, "measrot")
        await burst(pilot, "shift+f5")
        g54 = nck.data.settable_frame("G54")
        assert g54.rot["Z"] == pytest.approx(20.0, abs=1e-9)
        # the tool centre over the corner: WCS X = Y = 0
        move_to(app, 0.0, 0.0, 0.0)
        mcs = {a.name: a.position_mcs for a in app.bridge.status.axes}
        assert (mcs["X"], mcs["Y"]) == pytest.approx(corner, abs=1e-6)


async def test_rotated_corner_under_g500_is_refused_with_the_reason() -> None:
    """$P_SETFR holds no rotation: under G500 the dialog line says to select G54 …, nothing written."""
    app = HmiApp(kernel(2, blank=None), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f3")
        for x, y in ((-10.0, -5.0), (20.0, -4.0), (-15.0, 10.0)):
            move_to(app, x, y, -150.0)
            await pilot.pause()
            await burst(pilot, "shift+f6")
        await burst(pilot, "shift+f5")
        await pilot.pause()
        assert "select a work offset" in app.hint
        assert setframe(app.bridge.nck) == (0.0, 0.0)


@pytest.mark.parametrize("angles", [(0.0, 120.0, 240.0), (30.0, 100.0, 200.0, 300.0)])
async def test_hole_from_3_or_4_touches_gives_its_centre(angles) -> None:
    """A hole Ø 50 centred at MCS (−12, 7.5) (touched from inside by the cutter R 5: its centre
    on a circle of radius 20): 3 or 4 touches at any angles give the centre and Ø 50; X0 = 0,
    Y0 = 0 → translation (−12, 7.5)."""
    app = HmiApp(kernel(2, blank=None), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f4")
        for angle in angles:
            dx, dy = rotated(20.0, 0.0, angle)
            move_to(app, -12.0 + dx, 7.5 + dy, -150.0)
            await pilot.pause()
            await burst(pilot, "shift+f6")
        text = info(app, "meascircle")
        assert "Centre of the hole, Ø 50.000" in text, text
        await burst(pilot, "shift+f5")
        assert setframe(app.bridge.nck) == pytest.approx((-12.0, 7.5), abs=1e-6)


async def test_spigot_with_the_probe_from_four_sides() -> None:
    """The Ø 40 spigot centred at MCS (−12, 7.5): the probe switches 2 mm (ball) outside the wall
    moving −X, +X, −Y, +Y towards the centre; centre (−12, 7.5), Ø 40; X0 5 → X translation −17."""
    app = HmiApp(kernel(1, blank=SPIGOT), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f4", "right")
        for at, axis, direction in (((30.0, 7.5), "X", -1), ((-50.0, 7.5), "X", 1),
                                    ((-12.0, 50.0), "Y", -1), ((-12.0, -30.0), "Y", 1)):
            await touch_and_save(pilot, app, at, axis, direction)
        await burst(pilot, "shift+f6")  # a fifth point is refused
        assert "4 points saved" in app.hint
        text = info(app, "meascircle")
        assert "Centre of the spigot, Ø 40.000" in text, text
        assert "X (MCS) -12.000  Y (MCS) 7.500" in text
        await burst(pilot, "down", "ctrl+a", "ctrl+k", "5", "shift+f5")
        assert setframe(app.bridge.nck) == pytest.approx((-17.0, 7.5), abs=1e-6)
        await burst(pilot, "shift+f7")
        assert "Touch and save P1" in info(app, "meascircle")


async def test_probe_that_has_not_switched_saves_no_point() -> None:
    """The probe in the air: ⇧F6 says it has not switched; no point."""
    app = HmiApp(kernel(1), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "shift+f2", "shift+f6")
        assert "has not switched" in app.hint
        assert "Touch and save P1" in info(app, "meascorner")


async def test_edge_with_the_probe_uses_its_trigger_not_where_it_braked() -> None:
    """Edge X: the probe moving +X switches at −75.5 and brakes a little further; the edge is
    −75.5 + 2 = −73.5 → X0 there: translation −73.5. Z surface: the ball centre 2 above the top
    −220 at the trigger: machine Z = −218 + 150 = −68; the surface −220."""
    app = HmiApp(kernel(1), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3")
        move_to(app, -100.0, 0.0)
        probe(app, "X", 1)
        assert app.bridge.status.axes[0].position_mcs > -75.5  # braked past the trigger
        await pilot.pause()
        assert "Edge X (MCS) -73.500" in info(app, "measwp"), info(app, "measwp")
        await burst(pilot, "shift+f5")
        assert setframe(app.bridge.nck)[0] == pytest.approx(-73.5, abs=1e-6)
        move_to(app, 50.0, 0.0, -200.0)  # the WCS X moved by the frame: machine X −23.5
        probe(app, "Z", -1)
        await pilot.pause()
        await burst(pilot, "right", "right")
        assert "Edge Z (MCS) -220.000" in info(app, "measwp"), info(app, "measwp")


async def test_jog_view_shows_the_probe_switching() -> None:
    """The probe moving +X switches at −75.5 (face −73.5, ball 2): the JOG view says so, with
    the trigger position, and that the probe is deflected (it braked inside the overtravel)."""
    app = HmiApp(kernel(1), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        move_to(app, -100.0, 0.0)
        probe(app, "X", 1)
        await pilot.pause()
        text = str(app.screen.query_one("#jog-info").render())
        assert "Last contact: probe switched on the blank at X -75.500  Y 0.000  Z -80.000 (MCS)" in text, text
        assert "probe deflected" in text
