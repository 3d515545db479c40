"""ISO M tool offsets: H/D numbers through ``$TC_DPH``, G43/G44 H, G10 L10–L13.

Each Siemens edge ``T<t> D<d>`` can carry an ISO *H number*
``$TC_DPH[t,d]`` (kept in the edge's parameters under :data:`H_NUMBER_PARAM`,
0 = not linked). An H number may be used once in the whole tool data
(TO unit): writing it a second time raises 17183 with the T and D that
already hold it.

Translation (ISO M, :func:`address_offsets`): ``G43 H4`` / ``G44 H4`` and a
``D`` word select the edge of the tool programmed in the block (else the
active tool) whose ``$TC_DPH`` is that number: ``T2 G43 H4 Z0`` becomes
``T2 D=$TC_ISOH_EDGE[2,4]``. An H or D that no edge of the tool carries raises
12550. While no H number is assigned at all, the number is taken as the edge
number itself (programs written before H numbers were set up keep working).

``G10 L10 P<h> R<v>`` writes the length geometry (``$TC_DP3``), ``L11`` (or
``L1``) the length wear (``$TC_DP12``), ``L12`` the radius geometry
(``$TC_DP6``), ``L13`` the radius wear (``$TC_DP15``) of the edge with H
number h; under G91 the value is added. G10 only overwrites existing offsets:
an unknown H raises 12550. G44 applies the length like G43 (no negative
length compensation); length always acts as Siemens length 1 (mode A on a
G17 milling machine). Not modelled: MD 20380 modes B/C, and a G10 change
acts at once (the manual: at the next T, H or D word).
"""

from __future__ import annotations

from typing import Any

from nck.alarm_ids import DATA_WRITE_PROTECTED, ILLEGAL_ARRAY_INDEX_1, NAME_NOT_DEFINED, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.lang.values import to_number
from nck.number_text import trimmed

H_NUMBER_PARAM = 0  # ToolEdge.params key of $TC_DPH (the $TC_DP numbers are 1 … 25)
ALARM_H_TWICE = 17183
EDGE_VAR = "$TC_ISOH_EDGE"  # internal: [tool, number] → edge D (read only)
DATA_VAR = "$TC_ISOH_DP"  # internal: [h, dp parameter] of the edge with that H number
G10_PARAMS = {10: 3, 11: 12, 1: 12, 12: 6, 13: 15}  # L → $TC_DP<n>
NAMES = ("$TC_DPH", EDGE_VAR, DATA_VAR)


# ============================================================================ translation
def _edge_expression(number: float, tool: float | None) -> Any:
    value = int(number)
    if value == 0:
        return 0
    tool_text = str(int(tool)) if tool is not None else "$P_TOOLNO"
    return f"={EDGE_VAR}[{tool_text},{value}]"


def address_offsets(gcodes: list[str], values: dict[str, Any]) -> None:
    """ISO M: turn ``G43/G44 H`` and ``D`` into an edge looked up by H number (in place)."""
    tool = values.get("T")
    if any(code in ("G43", "G44") for code in gcodes) and "H" in values:
        values["D"] = _edge_expression(values.pop("H"), tool)
    elif "D" in values:
        values["D"] = _edge_expression(values["D"], tool)


def g10_blocks(values: dict[str, float], absolute: bool) -> list[str] | None:
    """``G10 L10…L13 P<h> R<v>``, or None for other G10 forms."""
    mode = int(values.get("L", -1))
    if mode not in G10_PARAMS:
        return None
    if "P" not in values or "R" not in values:
        raise NcAlarmError(SYNTAX_ERROR, f"G10 L{mode}")

    h_number, param = int(values["P"]), G10_PARAMS[mode]
    target = f"{DATA_VAR}[{h_number},{param}]"
    value = trimmed(values["R"])
    return [f"{target}={value}" if absolute else f"{target}={target}+({value})"]


# ============================================================================ interpreter
def _h_numbers(data: Any) -> dict[int, tuple[int, int]]:
    found: dict[int, tuple[int, int]] = {}
    for (tool, edge), edge_data in data.tools.items():
        h_number = int(edge_data.params.get(H_NUMBER_PARAM, 0))
        if h_number:
            found.setdefault(h_number, (tool, edge))
    return found


def _whole(value: Any, name: str) -> int:
    number = to_number(value, name)
    if int(number) != number:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return int(number)


def _pair(name: str, indices: tuple[Any, ...]) -> tuple[int, int]:
    if len(indices) != 2:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return _whole(indices[0], name), _whole(indices[1], name)


def read(ctx: Any, name: str, indices: tuple[Any, ...]) -> Any:
    """``$TC_DPH[t,d]`` and the internal lookups of the translated ISO blocks."""
    first, second = _pair(name, indices)
    if name == "$TC_DPH":
        edge = ctx.data.edge(first, second)
        return int(edge.params.get(H_NUMBER_PARAM, 0)) if edge is not None else 0
    if name == EDGE_VAR:
        return edge_for(ctx.data, first, second)
    tool, edge = _edge_of_h(ctx.data, first)
    return float(ctx.data.edge(tool, edge).get(second))


def edge_for(data: Any, tool: int, number: int) -> int:
    """The edge D of ``tool`` whose H number is ``number`` (12550 if there is none)."""
    if number == 0:
        return 0
    numbers = _h_numbers(data)
    if not numbers:
        return number  # no H numbers assigned: the number is the edge itself
    for (t, edge), edge_data in data.tools.items():
        if t == tool and int(edge_data.params.get(H_NUMBER_PARAM, 0)) == number:
            return edge
    raise NcAlarmError(NAME_NOT_DEFINED, f"H{number}")


def _edge_of_h(data: Any, h_number: int) -> tuple[int, int]:
    found = _h_numbers(data).get(h_number)
    if found is None:
        raise NcAlarmError(NAME_NOT_DEFINED, f"H{h_number}")
    return found


def write(ctx: Any, name: str, indices: tuple[Any, ...], value: Any) -> None:
    """Write ``$TC_DPH[t,d]`` (17183 if another edge holds that H) or a G10 offset."""
    first, second = _pair(name, indices)
    if name == EDGE_VAR:
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)
    if name == DATA_VAR:
        tool, edge = _edge_of_h(ctx.data, first)
        ctx.write_tool(tool, edge, second, float(to_number(value, name)))
        return
    if first < 1 or not 1 <= second <= 12:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    h_number = _whole(value, name)
    if h_number < 0:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    if h_number:
        holder = _h_numbers(ctx.data).get(h_number)
        if holder is not None and holder != (first, second):
            raise NcAlarmError(ALARM_H_TWICE, holder[0], holder[1])
    ctx.write_tool(first, second, H_NUMBER_PARAM, float(h_number))
