"""``nck run --tools FILE``: a tool table in TOML, written into the NC data like ``--set``.

Format (one ``[[edge]]`` table per cutting edge)::

    [[edge]]
    t = 1            # tool number
    d = 1            # cutting edge (D number), default 1
    type = 120       # $TC_DP1 tool type (120 end mill, 200 twist drill, 500 roughing tool …)
    position = 0     # $TC_DP2 cutting edge position (turning tools)
    length1 = 75.5   # $TC_DP3 geometry length 1
    length2 = 0      # $TC_DP4
    length3 = 0      # $TC_DP5
    radius = 4       # $TC_DP6
    dp = { 12 = 0.1, 15 = -0.02 }   # any $TC_DP<n> by number (wear, adapters …)
"""

from __future__ import annotations

from pathlib import Path

from nck.operator_files import OperatorFileError, load_operator_toml


NAMED_PARAMS = {"type": 1, "position": 2, "length1": 3, "length2": 4, "length3": 5, "radius": 6}
MAX_PARAM = 25


class ToolFileError(Exception):
    """The tool table could not be used; ``str()`` says why."""


def read_tool_table(path: Path | str) -> dict[tuple[int, int], dict[int, float]]:
    """Read the tool table: ``{(t, d): {param: value}}`` (the values are written like
    ``--set $TC_DP<param>[t,d]=value``, through the protection and limit checks)."""
    path = Path(path)
    try:
        table = load_operator_toml(path)
    except OperatorFileError as exc:
        raise ToolFileError(f"tool table '{path}' {exc}") from None
    edges = table.get("edge", [])
    if not isinstance(edges, list):
        raise ToolFileError(f"tool table '{path}': [[edge]] tables expected")
    loaded: dict[tuple[int, int], dict[int, float]] = {}
    for number, entry in enumerate(edges, start=1):
        where = f"tool table '{path}', edge {number}"
        if not isinstance(entry, dict):
            raise ToolFileError(f"{where}: a table expected")
        tool, edge = entry.get("t"), entry.get("d", 1)
        if not isinstance(tool, int) or not 1 <= tool <= 99_999_999:
            raise ToolFileError(f"{where}: 't' must be a tool number 1…99999999")
        if not isinstance(edge, int) or not 1 <= edge <= 12:
            raise ToolFileError(f"{where}: 'd' must be an edge number 1…12")
        params: dict[int, float] = {}
        for key, value in entry.items():
            if key in ("t", "d"):
                continue
            if key == "dp":
                if not isinstance(value, dict):
                    raise ToolFileError(f"{where}: 'dp' must be a table {{n = value}}")
                for raw, number_value in value.items():
                    if not raw.isdigit() or not 1 <= int(raw) <= MAX_PARAM:
                        raise ToolFileError(f"{where}: $TC_DP{raw} does not exist")
                    params[int(raw)] = _number(number_value, where, f"dp.{raw}")
            elif key in NAMED_PARAMS:
                params[NAMED_PARAMS[key]] = _number(value, where, key)
            else:
                raise ToolFileError(f"{where}: unknown key '{key}'")
        loaded[(tool, edge)] = params
    return loaded


def _number(value: object, where: str, key: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ToolFileError(f"{where}: '{key}' must be a number")
    return float(value)
