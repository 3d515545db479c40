"""The sample DRILL_FLANGE simulates to its drawing (issue 23 done-when: the samples simulate)."""

from __future__ import annotations

import math
from pathlib import Path

from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path
from nck.simulation.run import simulate

SAMPLE = Path(data_path("programs")) / "DRILL_FLANGE.MPF"


def test_flange_simulates_without_event_and_drills_six_holes(tmp_path: Path) -> None:
    """Six holes on the pitch circle of radius 40 at 0°, 60° … (HOLES2(0, 0, 40, 0, 60, 6)),
    drilled by CYCLE83 to DP -18 with the sample tools' 8.5 mm twist drill (no $TC_DP24: the
    simulation's 118° point), then tapped with G331 after an oriented stop: no rapid into material and no cut with
    the spindle stopped (the tapping turns the spindle with the axis, 002 L19681).

    Depth at a distance r from a hole's axis: 18 - r·tan(90° - 118°/2) = 18 - 0.6009 r; the
    nearest 0.5 mm cell centre is at most 0.354 mm off the axis: between 17.787 and 18 deep.
    The flange's middle stays at its top face Z0."""
    mill = load_machine()
    data = Session.open(tmp_path / "data", mill).ncdata
    result = simulate(SAMPLE.name, SAMPLE.read_text(), machine=mill, data=data,
                      programs=DirectorySource(SAMPLE.parent), resolution_mm=0.5)
    assert result.status == "ended" and result.alarms == [] and result.events == []
    shallowest = 18.0 - 0.5 * math.sqrt(0.5) * math.tan(math.radians(31.0))
    for k in range(6):
        angle = math.radians(60.0 * k)
        depth = -result.zmap.height_at(40.0 * math.cos(angle), 40.0 * math.sin(angle))
        assert shallowest - 1e-3 <= depth <= 18.0 + 1e-3
    assert result.zmap.height_at(0.0, 0.0) == 0.0
