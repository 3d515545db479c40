"""ISO M drilling cycles (group 9: G73, G74, G76, G81–G89) expanded into Siemens blocks.

The cycle runs in its defining block and in every later block with a hole
position until G80 or a group-1 code. Only plane G17 (holes in X/Y, depth in
Z) is supported. The initial plane (tool-axis position at the first cycle
call) is read at run time from ``$P_EP[Z]`` into the local variable
:data:`INITIAL_Z`; the R plane into :data:`R_PLANE_Z`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nck.errors import NcAlarmError
from nck.number_text import trimmed

INITIAL_Z = "ISO_ZINIT"
R_PLANE_Z = "ISO_ZR"
DECLARATION = f"DEF REAL {INITIAL_Z}, {R_PLANE_Z}"
CYCLE_CODES = frozenset({73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 89})
PECK_RETRACT_MM = 1.0  # G73 chip-break retract and G83 re-approach clearance (_ZSFR[1] <= 0)
ALARM_CYCLE_PARAMETER = 61808
ALARM_NO_SPINDLE_DIRECTION = 61102


@dataclass
class CycleState:
    """Modal cycle data kept between blocks (R, Z, Q, P, F of the last call)."""

    code: int | None = None
    params: dict[str, float] = field(default_factory=dict)
    initial_captured: bool = False
    return_to_r: bool = False  # G99


def peck_depths(total_mm: float, step_mm: float) -> list[float]:
    """Cumulative depths below the R plane for a pecking cycle: steps of Q, last the rest."""
    depths: list[float] = []
    depth = 0.0
    while total_mm - depth > step_mm + 1e-9:
        depth += step_mm
        depths.append(depth)
    depths.append(total_mm)
    return depths


def expand(state: CycleState, absolute: bool, hole: list[str], feed: str | None,
           repeat: int) -> list[str]:
    """Siemens blocks for one cycle call at the hole given by ``hole`` words (``X10`` …).

    ``absolute`` is G90 (R and Z absolute) or G91 (R from the initial plane, Z
    from the R plane). Raises 61808 when Z (or Q for G73/G83) is missing; the blocks raise
    61102 when the spindle does not turn (M3/M4) at the call.
    """
    params = state.params
    code = state.code
    if "Z" not in params:
        raise NcAlarmError(ALARM_CYCLE_PARAMETER, "Z")
    if code in (73, 83) and params.get("Q", 0.0) <= 0:
        raise NcAlarmError(ALARM_CYCLE_PARAMETER, "Q")
    # Like the control's shell cycles (000 L5891: 61102 "Spindle direction M03 or M04 missing"),
    # every call checks that the spindle turns before the tool moves.
    blocks: list[str] = ["IF ($P_SDIR<>3) AND ($P_SDIR<>4)", f"SETAL({ALARM_NO_SPINDLE_DIRECTION})", "ENDIF"]
    if not state.initial_captured:
        blocks.append(f"{INITIAL_Z}=$P_EP[Z]")
        state.initial_captured = True
    r_value = params.get("R")
    z_value = params["Z"]
    if absolute:
        r_expr = trimmed(r_value) if r_value is not None else INITIAL_Z
        bottom = trimmed(z_value)
        total = None if r_value is None else r_value - z_value
    else:
        r_expr = f"{INITIAL_Z}+{trimmed(r_value or 0.0)}"
        bottom = f"{R_PLANE_Z}+{trimmed(z_value)}"
        total = -z_value
    feed_word = f" F{feed}" if feed else ""
    retract = f"G0 Z=AC({R_PLANE_Z if state.return_to_r else INITIAL_Z})"
    for _ in range(repeat):
        blocks.append(f"G0 {' '.join(hole)}" if hole else "G0")
        blocks.append(f"{R_PLANE_Z}={r_expr}")
        blocks.append(f"G0 Z=AC({R_PLANE_Z})")
        if code in (73, 83):
            blocks.extend(_pecks(code, params["Q"], total, bottom, feed_word))
        else:
            blocks.append(f"G1 Z=AC({bottom}){feed_word}")
        dwell = params.get("P")
        if dwell and code in (82, 89, 74, 84):
            blocks.append(f"G4 F{trimmed(dwell)}")
        if code in (84, 74):
            blocks.append("M4" if code == 84 else "M3")
            blocks.append(f"G1 Z=AC({R_PLANE_Z})")
            blocks.append("M3" if code == 84 else "M4")
        elif code in (85, 89):
            blocks.append(f"G1 Z=AC({R_PLANE_Z})")
        elif code in (86, 76, 87):
            blocks.append("M5")
        if not (state.return_to_r and code in (84, 74, 85, 89)):
            blocks.append(retract)
        if code in (86, 76, 87):
            blocks.append("M3")
    return blocks


def _pecks(code: int, step: float, total: float | None, bottom: str, feed_word: str) -> list[str]:
    if total is None or total <= 0:
        return [f"G1 Z=AC({bottom}){feed_word}"]
    blocks: list[str] = []
    previous = 0.0
    for depth in peck_depths(total, step):
        if previous > 0:
            if code == 83:
                blocks.append(f"G0 Z=AC({R_PLANE_Z}-{trimmed(max(previous - PECK_RETRACT_MM, 0.0))})")
        target = f"{R_PLANE_Z}-{trimmed(depth)}"
        blocks.append(f"G1 Z=AC({target}){feed_word}")
        if depth < total - 1e-9:
            if code == 83:
                blocks.append(f"G0 Z=AC({R_PLANE_Z})")
            else:
                blocks.append(f"G0 Z=AC({target}+{trimmed(PECK_RETRACT_MM)})")
        previous = depth
    return blocks
