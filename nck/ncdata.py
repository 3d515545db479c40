"""Retained NC data shared by interpreter, channel and HMI.

R parameters, tool cutting edges, work offsets (settable frames and base
frame), setting data and global user data. Persistence and protection levels
are applied around this store, not inside it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from nck.manual_settings import ManualSettings
from nck.workpiece import MachineSetup

R_PARAMETER_COUNT = 100  # MD28050 MM_NUM_R_PARAM default
TOOL_EDGE_COUNT = 600  # MD18100 MM_NUM_CUTTING_EDGES_IN_TOA default (data/md/general.toml)


@dataclass
class ToolEdge:
    """One cutting edge ``D`` of tool ``T``: the ``$TC_DP1`` … ``$TC_DP25`` values.

    Index 1 is the tool type, 2 the cutting edge position, 3–5 the lengths 1–3,
    6 the radius, 12–14 length wear, 15 radius wear (numbering of the manual).
    Key 0 holds the ISO H number ``$TC_DPH`` (0 = not linked; nck.iso.tool_offsets).
    """

    params: dict[int, float] = field(default_factory=dict)

    def get(self, index: int) -> float:
        """Return ``$TC_DP<index>`` (0 when never written)."""
        return self.params.get(index, 0.0)

    @property
    def tool_type(self) -> int:
        """Tool type ``$TC_DP1`` (e.g. 120 end mill, 200 twist drill, 500 roughing tool)."""
        return int(self.get(1))


@dataclass
class WorkOffset:
    """A settable frame / base frame as stored in the NC data.

    Translations in mm, rotations in degrees about X/Y/Z, scale factors and
    mirror flags per axis (missing axis = 0 / 0° / 1.0 / not mirrored).
    """

    trans: dict[str, float] = field(default_factory=dict)
    fine: dict[str, float] = field(default_factory=dict)
    rot: dict[str, float] = field(default_factory=dict)
    scale: dict[str, float] = field(default_factory=dict)
    mirror: dict[str, bool] = field(default_factory=dict)


SETTABLE_FRAME_NAMES = ("G54", "G55", "G56", "G57") + tuple(f"G{n}" for n in range(505, 600))


@dataclass
class NcData:
    """All retained data of one channel of the control."""

    r: list[float] = field(default_factory=lambda: [0.0] * R_PARAMETER_COUNT)
    tools: dict[tuple[int, int], ToolEdge] = field(default_factory=dict)
    settable_frames: dict[str, WorkOffset] = field(
        default_factory=lambda: {name: WorkOffset() for name in SETTABLE_FRAME_NAMES[:8]}
    )
    base_frame: WorkOffset = field(default_factory=WorkOffset)
    setting_data: dict[str, Any] = field(default_factory=dict)
    gud: dict[str, Any] = field(default_factory=dict)
    # part-program protection levels of a GUD from its DEF (APRP/APWP): name → {"read": n, "write": n}
    gud_access: dict[str, dict[str, int]] = field(default_factory=dict)
    # Workpiece counters by variable name without prefix (TOTAL_PARTS, REQUIRED_PARTS,
    # ACTUAL_PARTS, SPECIAL_PARTS: the $AC_… values); retained like the rest.
    part_counters: dict[str, int] = field(default_factory=dict)
    # The MDA buffer (kept until deleted, also over power off/on).
    mda_program: str = ""
    # Positions of the machine control panel's override switches in % by switch (feed, rapid,
    # spindle). A switch stays where it was turned, over power off/on, like the keyswitch.
    override_switches: dict[str, float] = field(default_factory=dict)
    # What is clamped on the machine (blank, reference block; nck.workpiece). Empty in a bare
    # NcData; a data directory starts with the default of its machine kind.
    machine_setup: MachineSetup = field(default_factory=MachineSetup)
    # Retraction plane, safety distance and measuring feed of manual mode (nck.manual_settings).
    manual_settings: ManualSettings = field(default_factory=ManualSettings)
    # The system frame for PRESET and scratching, $P_SETFR (002 L30600-30612): translations only.
    setframe: WorkOffset = field(default_factory=WorkOffset)

    def edge(self, tool: int, edge: int) -> ToolEdge | None:
        """Return the cutting edge ``D<edge>`` of tool ``T<tool>``, if it exists."""
        return self.tools.get((tool, edge))

    def has_room_for_edge(self, tool: int, edge: int, edge_count: int) -> bool:
        """True when ``D<edge>`` of ``T<tool>`` exists or the tool offset memory holds fewer than
        ``edge_count`` edges (MD18100: a D number written for the first time stores a new
        data block, 002 L58292-58296)."""
        return (tool, edge) in self.tools or len(self.tools) < edge_count

    def settable_frame(self, name: str) -> WorkOffset:
        """Return the settable frame ``G54`` … ``G599`` (created empty when first used)."""
        if name not in self.settable_frames:
            self.settable_frames[name] = WorkOffset()
        return self.settable_frames[name]
