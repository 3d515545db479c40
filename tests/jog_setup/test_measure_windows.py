"""Measure workpiece and Measure tool windows of JOG (issue 22).

Scratching (002 L31279-31290): the tool touches the surface, the window computes the
edge and writes it. Expected values by hand: T1 is an end mill R 5, L 75 (geometry);
the machine position is the tool carrier (MCS Z = tip + 75), the cutter centre in X/Y.
"""

from __future__ import annotations

from nck import commands as cmd
from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst
from tests.jog_setup.kernels import run_in_mda_then_jog
from tests.jog_setup.test_tsm_window import kernel_with_tools

SIZE = (160, 48)


def kernel_with_t1_at(x: float, z: float) -> Nck:
    """T1 D1 loaded, the tool at MCS X ``x``, Z ``z`` (carrier), G500, JOG."""
    nck = kernel_with_tools()
    run_in_mda_then_jog(nck, f"T1 M6 D1\nG0 G53 X{x} Z{z - 75.0}\n")  # G53: no work offset, the tool length stays
    status = nck.status()
    assert status.channel.modal.tool == 1
    assert {a.name: a.position_mcs for a in status.axes}["X"] == x
    assert abs({a.name: a.position_mcs for a in status.axes}["Z"] - z) < 1e-9
    return nck


def wcs(app: HmiApp) -> dict[str, float]:
    """The WCS actual values of the path axes."""
    return {a.name: a.position_wcs for a in app.bridge.status.axes if a.kind != "spindle"}


def info(app: HmiApp, view: str) -> str:
    """The preview line of a window."""
    return str(app.screen.query_one(f"#view-{view}-info").render())


async def edge_zero_from(x_touch: float, approach_keys: list[str]) -> float:
    """Touch at MCS X ``x_touch``, set the edge to X0; return the WCS X of the tool after."""
    app = HmiApp(kernel_with_t1_at(x_touch, 200.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "down", *approach_keys)
        assert "Edge X (MCS) -115.000" in info(app, "measwp"), info(app, "measwp")
        await burst(pilot, "shift+f5")
        return wcs(app)["X"]


async def test_edge_from_both_sides_gives_the_same_zero() -> None:
    """Edge at MCS X −115: touched moving + with the centre at −120 (edge = −120 + 5), or
    moving − with the centre at −110 (edge = −110 − 5). X0 there: the tool then reads −5 and
    +5 in the WCS — the same zero from both sides."""
    assert abs(await edge_zero_from(-120.0, []) - (-5.0)) < 1e-6
    assert abs(await edge_zero_from(-110.0, ["right"]) - 5.0) < 1e-6


async def test_z_surface_sets_z0_at_the_tool_tip() -> None:
    """Carrier at MCS Z 175 with L 75: the tip is on the surface at MCS 100; Z0 there puts
    100 into the PRESET frame's Z (G500); setpoint 12.5 instead: 100 − 12.5 = 87.5.

    The frame is asserted, not the WCS display: in JOG the kernel's display leaves the tool
    length out (it showed Z 175 for the carrier at 175 before the touch), a kernel matter.
    """
    nck = kernel_with_t1_at(0.0, 175.0)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "right", "right")
        assert "Edge Z (MCS) 100.000" in info(app, "measwp")
        await burst(pilot, "shift+f5")
        assert abs(nck.data.setframe.trans["Z"] - 100.0) < 1e-6
        await burst(pilot, "down", "down", "ctrl+a", "ctrl+k", "1", "2", ".", "5", "shift+f5")
        assert abs(nck.data.setframe.trans["Z"] - 87.5) < 1e-6


async def test_tool_length_from_a_surface_of_known_z0() -> None:
    """Carrier at MCS Z 175, G500 with no offset: a surface at Z0 95 (WCS = MCS here) gives
    L = 175 − 95 = 80 into the geometry; then into the wear instead: 80 − 75 = 5."""
    nck = kernel_with_t1_at(0.0, 175.0)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "shift+f4", "down", "down", "ctrl+a", "ctrl+k", "9", "5")
        assert "Length 1 = 80.000" in info(app, "meastool"), info(app, "meastool")
        await burst(pilot, "down", "down", "down", "right", "shift+f5")
        assert nck.data.tools[(1, 1)].get(12) == 5.0
        assert nck.data.tools[(1, 1)].get(3) == 75.0


async def test_tool_length_into_the_geometry() -> None:
    """The same touch written into the geometry: $TC_DP3 = 80, wear untouched."""
    nck = kernel_with_t1_at(0.0, 175.0)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "shift+f4", "down", "down", "ctrl+a", "ctrl+k", "9", "5",
                    "shift+f5")
        assert nck.data.tools[(1, 1)].get(3) == 80.0
        assert nck.data.tools[(1, 1)].get(12) == 0.0


async def test_measure_tool_without_a_tool_says_so() -> None:
    """No tool active: the window says to load one; ⇧F5 writes nothing."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f4", "shift+f5")
        assert "No tool active" in info(app, "meastool")


async def test_tool_length_on_the_reference_block() -> None:
    """A reference block with its top at MCS Z 95 (the fixed-point value) in the machine
    set-up: touched by the tip with the carrier at 175, L = 175 − 95 = 80."""
    nck = kernel_with_t1_at(0.0, 175.0)
    block = cmd.Box(low_mcs=(100.0, 100.0, 0.0), high_mcs=(150.0, 150.0, 95.0))
    assert nck.submit(cmd.WriteMachineSetup(cmd.MachineSetup(reference=block))) == cmd.Accepted()
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "shift+f4", "down", "right")
        assert "surface Z (MCS) 95.000" in info(app, "meastool")
        assert "Length 1 = 80.000" in info(app, "meastool")
        await burst(pilot, "shift+f5")
        assert nck.data.tools[(1, 1)].get(3) == 80.0


async def test_tool_radius_from_an_edge_of_known_x0() -> None:
    """The cutter's centre at MCS X −120.2 touches, moving +, an edge at X0 −115 (G500, no
    offset: MCS = WCS): radius = −115 − (−120.2) = 5.2 into $TC_DP6 (the geometry said 5)."""
    nck = kernel_with_t1_at(-120.2, 200.0)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "shift+f4", "right", "down", "down", "down", "down",
                    "ctrl+a", "ctrl+k", "-", "1", "1", "5")
        assert "Radius = 5.200" in info(app, "meastool"), info(app, "meastool")
        await burst(pilot, "shift+f5")
        assert abs(nck.data.tools[(1, 1)].get(6) - 5.2) < 1e-9
        assert nck.data.tools[(1, 1)].get(15) == 0.0


async def test_tool_radius_that_would_be_negative_is_not_written() -> None:
    """Centre at X 0 'approaching' + an edge at X0 −10: the edge lies behind the tool
    (0 − 10 < 0): the window says so and ⇧F5 writes nothing (the radius stays 5)."""
    nck = kernel_with_t1_at(0.0, 200.0)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "shift+f4", "right", "down", "down", "down", "down",
                    "ctrl+a", "ctrl+k", "-", "1", "0", "shift+f5")
        assert "Radius -10.000: the tool centre is not before the edge" in info(app, "meastool")
        assert nck.data.tools[(1, 1)].get(6) == 5.0


async def test_measure_preview_never_shows_minus_zero() -> None:
    """An edge 0.2 µm below MCS X 0 (centre at −5.0002 + radius 5, touched moving +) reads
    0.000, as every position on the panel does, not −0.000; so do the translation and the
    tool data lines."""
    app = HmiApp(kernel_with_t1_at(-5.0002, 200.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "shift+f3", "down")
        shown = info(app, "measwp")
        assert "Edge X (MCS) 0.000" in shown and "translation 0.000" in shown, shown
        assert "-0.000" not in shown
