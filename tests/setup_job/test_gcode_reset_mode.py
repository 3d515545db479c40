"""MD20152 GCODE_RESET_MODE: a G group whose entry is 1 keeps its code at RESET and program end
(002 L2770-2782: 0 = the reset member of MD20150, 1 = the last one active; L21518-21530: the
reset sequence at program end and at RESET evaluates it). The shipped machines keep group 8
(settable work offset) and 13 (unit), so that T,S,M of JOG can select them (issue 22).

Hand values: G54 holds X −100: the WCS X is the MCS X + 100 while G54 is active."""

from __future__ import annotations

import pytest

from nck import commands as cmd
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import ToolEdge

from tests.jog_setup.kernels import run_in_mda_then_jog


def wcs_x(nck: Nck) -> float:
    return {a.name: a.position_wcs for a in nck.status().axes}["X"]


def g54_kernel(**md: object) -> Nck:
    machine = load_machine("mill3")
    machine.md.update(md)
    nck = Nck(machine=machine, referenced=True)
    nck.data.settable_frame("G54").trans["X"] = -100.0
    return nck


def test_the_shipped_mill_keeps_the_work_offset_and_the_unit_after_the_mda_job() -> None:
    nck = run_in_mda_then_jog(g54_kernel(), "G54 G70\nG0 X1\n")  # X 1 inch = 25.4 mm in G54
    modal = nck.status().channel.modal
    assert (modal.gcodes[8], modal.gcodes[13]) == ("G54", "G70")
    assert wcs_x(nck) == pytest.approx(25.4 + 0.0, abs=1e-6) or wcs_x(nck) == pytest.approx(1.0, abs=1e-6)
    mcs = {a.name: a.position_mcs for a in nck.status().axes}["X"]
    assert mcs == pytest.approx(-100.0 + 25.4, abs=1e-6)
    assert nck.submit(cmd.Reset()) == cmd.Accepted()
    nck.tick(0.1)
    assert nck.status().channel.modal.gcodes[8] == "G54"


def test_mode_0_goes_back_to_the_reset_member() -> None:
    nck = run_in_mda_then_jog(g54_kernel(MD20152=0), "G54 G70\nG0 X1\n")
    modal = nck.status().channel.modal
    assert (modal.gcodes[8], modal.gcodes[13]) == ("G500", "G71")
    assert wcs_x(nck) == pytest.approx(-100.0 + 25.4, abs=1e-6)  # WCS = MCS again


def test_other_groups_still_reset() -> None:
    nck = run_in_mda_then_jog(g54_kernel(), "G54 G91 G1 X1 F1000\n")
    modal = nck.status().channel.modal
    assert (modal.gcodes[8], modal.gcodes[14]) == ("G54", "G90")


def test_jog_display_after_an_mda_tool_change_subtracts_the_new_tools_length() -> None:
    """T1 (L 75) loaded in MDA, G53 Z−50 puts the tip at MCS −50 (carrier 25); back in JOG
    (G54 has no Z) the WCS Z is the MCS Z − 75 = −50 (the JOG display read an interpreter that
    had not seen the tool change: it showed 25)."""
    nck = g54_kernel()
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 75.0, 6: 5.0})
    run_in_mda_then_jog(nck, "G54 T1 M6 D1\nG0 G53 Z-50\n")
    z = {a.name: a for a in nck.status().axes}["Z"]
    assert (z.position_mcs, z.position_wcs) == (pytest.approx(25.0), pytest.approx(-50.0))
