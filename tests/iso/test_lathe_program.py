"""Golden test: the shipped ISO T lathe program runs on the lathe with hand-worked end points.

``nck run data/examples/iso/ISO_T_SHAFT.MPF --machine lathe2 --dialect iso-t`` (the
issue's last "Done when" line): diameter programming, G96 with a G92 S spindle limit,
G71 roughing + G70 finishing, G76 multi-pass threading.

Worked by hand (X as a diameter; r = X/2):

* G71 from A = X52 Z2, depth 2 (radius), retract 0.5, allowance U0.4 W0.1: the shifted
  contour is X20.4 Z2.1 → Z-19.9 → X30.4 → Z-44.9 → X44.4 Z-54.9 → X52.4. Passes at
  r = 24, 22, 20, 18, 16, 14, 12 (r = 10.2 is the shifted contour start). r = 24 lies above
  the taper end (r 22.2), so it runs to the contour's end Z-54.9; r = 22, 20, 18, 16 meet the
  taper Z = -44.9 - 10 (r - 15.2) / 7; r = 14, 12 meet the shoulder at Z-19.9.
* G76 from A = X24 Z5 to X18.16 Z-18, height 0.92, first cut 0.4, minimum 0.05, allowance
  0.02, one finishing pass, 60°: depths 0.4·√n = 0.4, 0.565685, 0.69282, 0.8, then 0.894427
  would leave less than the minimum to 0.9 = 0.92 - 0.02, so 0.9; then 0.92. Pass X =
  18.16 + 2 (0.92 - depth); the infeed follows the flank: Z moves back by depth · tan 30°.
"""

from __future__ import annotations

import json
import math

import pytest

from nck import canon
from nck.cli import main
from nck.cli_tools import read_tool_table
from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from nck.resources import data_path

PROGRAM = data_path("examples", "iso", "ISO_T_SHAFT.MPF")
TOOLS_PATH = data_path("examples", "iso", "ISO_T_SHAFT_TOOLS.toml")
TOOLS = TOOLS_PATH.read_text()  # shipped beside the program


def _taper_z(r: float) -> float:
    return -44.9 - 10.0 * (r - 15.2) / 7.0


ROUGH_CUTS = [(48.0, -54.9)] + [(2 * r, round(_taper_z(r), 6)) for r in (22, 20, 18, 16)] + [
    (28.0, -19.9), (24.0, -19.9)]
PROFILE = [(20.4, 2.1), (20.4, -19.9), (30.4, -19.9), (30.4, -44.9), (44.4, -54.9),
           (52.4, -54.9), (52.0, -54.9), (52.0, 2.0)]
FINISH = [(20.0, 2.0), (20.0, -20.0), (30.0, -20.0), (30.0, -45.0), (44.0, -55.0),
          (52.0, -55.0), (52.0, -55.0), (52.0, 2.0)]
THREAD_DEPTHS = [0.4, 0.4 * math.sqrt(2), 0.4 * math.sqrt(3), 0.8, 0.9, 0.92]


@pytest.fixture(scope="module")
def segments(tmp_path_factory) -> list[dict]:
    folder = tmp_path_factory.mktemp("lathe")
    tools = folder / "tools.toml"
    tools.write_text(TOOLS)
    out = folder / "segments.jsonl"
    code = main(["run", str(PROGRAM), "--machine", "lathe2", "--dialect", "iso-t", "--ephemeral",
                 "--data-dir", str(folder / "data"), "--tools", str(tools), "--password", "CUSTOMER",
                 "--segments", str(out)])
    assert code == 0
    return [json.loads(line) for line in out.read_text().splitlines()]


def _ends(segments: list[dict], n: int, motion: str | None = None) -> list[tuple[float, float]]:
    return [(round(s["end"]["X"], 3), round(s["end"]["Z"], 3)) for s in segments
            if s["n"] == n and (motion is None or s["motion"] == motion)]


def _rounded(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    return [(round(x, 3), round(z, 3)) for x, z in points]


def test_roughing_passes_end_on_the_shifted_contour(segments):
    assert _ends(segments, 70, "G1")[:7] == _rounded(ROUGH_CUTS)
    # each pass: rapid to depth at Z2, cut, lift 0.5 at 45 degrees, rapid back to Z2
    first = _ends(segments, 70)[:4]
    assert first == [(48.0, 2.0), (48.0, -54.9), (49.0, -54.4), (49.0, 2.0)]
    assert _ends(segments, 70)[-8:] == _rounded(PROFILE)
    assert len(_ends(segments, 70)) == 7 * 4 + 8


def test_finishing_pass_follows_the_contour_and_returns_to_the_start(segments):
    assert _ends(segments, 140) == FINISH
    assert all(s["line"] == 17 for s in segments if s["n"] == 140)  # NC-inserted: G70's line


def test_contour_blocks_themselves_never_run(segments):
    assert not [s for s in segments if s["n"] in (80, 90, 100, 110, 120, 130)]


def test_thread_passes(segments):
    threads = _ends(segments, 200, "G33")
    flank = math.tan(math.radians(30.0))
    expected = [(18.16 + 2 * (0.92 - d), -18.0 + d * flank) for d in THREAD_DEPTHS]
    assert threads == _rounded(expected)
    rapids = _ends(segments, 200, "G0")
    assert rapids[0] == _rounded([(18.16 + 2 * 0.52, 5.0 + 0.4 * flank)])[0]
    assert rapids[-1] == (24.0, 5.0)


def test_diameter_programming_and_tool_offsets_in_machine_coordinates(segments):
    start = next(s for s in segments if s["n"] == 50)
    # X52 diameter = 26 mm radius + length 1 (20) on X; Z2 + length 2 (40)
    assert start["end_mcs"] == {"X": 46.0, "Z": 42.0}
    last = segments[-1]
    assert last["n"] == 210 and last["end"] == {"X": 100.0, "Z": 50.0}
    assert last["end_mcs"] == {"X": 75.0, "Z": 95.0}  # tool 2: 50 + 25, 50 + 45


def test_constant_cutting_speed_is_limited_and_thread_lead_is_f():
    data = NcData()  # the tools of the program (17191 without them, 002 L58219)
    data.tools = {key: ToolEdge(params=dict(p)) for key, p in read_tool_table(TOOLS_PATH).items()}
    result = interpret_only(load_machine("lathe2"), MemorySource({}), data, PROGRAM.name,
                            text=PROGRAM.read_text(), max_blocks=10_000, dialect="iso-t")
    assert result.status == "ended", result.alarms
    speeds = [(c.source.n, c.speed_rpm) for c in result.commands
              if isinstance(c, canon.SpindleCommand) and c.speed_rpm is not None]
    css = [rpm for n, rpm in speeds if n in (40, 50, 70, 140)]
    assert max(css) == 2000.0  # G92 S2000 caps the small diameters
    assert round(min(css), 3) == round(180_000 / (2 * math.pi * 52.4 / 2), 3)  # 180 m/min at X52.4
    assert (200, 800.0) not in speeds and (170, 800.0) in speeds  # G97 S800 for the thread
    threads = [m for m in result.segments if m.kind == "G33"]
    assert len(threads) == 6 and {m.lead_mm for m in threads} == {1.5}
