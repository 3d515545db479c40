"""Machine configurations: which axes a machine has and its machine-data values.

A machine is a TOML file in ``data/machines/`` (or any path given by the
user). The embedded default is ``mill3`` (3-axis vertical mill).
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from nck.resources import data_path, data_root, load_toml, read_table
from nck.operator_files import OperatorFileError, load_operator_toml

DEFAULT_MACHINE = "mill3"
USER_CLASS_NUMBERS = range(9200, 9300)  # display MD holding protection levels (0 most rights … 7)


@dataclass(frozen=True, slots=True)
class AxisConfig:
    """One axis or spindle of the machine.

    Attributes:
        name: the channel axis name used in programs (``X``, ``Z``, ``SP``…).
        kind: ``linear``, ``rotary`` or ``spindle``.
        index: 0-based machine axis index (for MD arrays).
        diameter: True for a transverse axis programmed in diameter (lathe X).
    """

    name: str
    kind: str
    index: int
    diameter: bool = False


@dataclass(frozen=True, slots=True)
class MachineConfig:
    """A machine: name, kind (``mill``/``lathe``), axes, and machine-data values.

    ``md`` maps an MD identifier (``"MD32000"``) to a value, or for axis data to
    a dictionary axis name -> value.
    """

    name: str
    title: str
    kind: str
    axes: tuple[AxisConfig, ...]
    md: dict[str, Any] = field(default_factory=dict)
    source: str = ""
    sim: dict[str, Any] = field(default_factory=dict)

    @property
    def path_axes(self) -> tuple[str, ...]:
        """Names of the linear and rotary axes (not spindles), in channel order."""
        return tuple(a.name for a in self.axes if a.kind != "spindle")

    @property
    def spindles(self) -> tuple[str, ...]:
        """Names of the spindles."""
        return tuple(a.name for a in self.axes if a.kind == "spindle")

    def spindle_kept_after_reset(self, name: str) -> bool:
        """MD35040 SPIND_ACTIVE_AFTER_RESET of spindle ``name``: True keeps its S and direction
        at RESET and program end, False (the default) brakes it and deletes them (002
        L51017-51038)."""
        return bool(int(self.md_value("MD35040", name, 0) or 0))

    def axis(self, name: str) -> AxisConfig:
        """Return the axis called ``name`` (KeyError if there is none)."""
        for axis in self.axes:
            if axis.name == name:
                return axis
        raise KeyError(name)

    def md_value(self, ident: str, axis: str | None = None, default: Any = None) -> Any:
        """Return a machine-data value from the machine file, per axis where given."""
        value = self.md.get(ident, default)
        if isinstance(value, dict):
            return value.get(axis, default) if axis is not None else value
        return value

    def md_float(self, ident: str, axis: str | None = None, default: float = 0.0) -> float:
        """Return a numeric machine-data value (per axis where given) as a float."""
        value = self.md_value(ident, axis, default)
        if isinstance(value, (list, tuple)):
            value = value[0] if value else default
        try:
            return float(value)
        except (TypeError, ValueError):
            return float(default)

    def sim_float(self, key: str, axis: str, default: float = 0.0) -> float:
        """Return a value of the simulated mechanics (``[sim]`` table), per axis."""
        value = self.sim.get(key, {})
        if isinstance(value, dict):
            value = value.get(axis, default)
        try:
            return float(value)
        except (TypeError, ValueError):
            return float(default)


class MachineFileError(Exception):
    """The machine file could not be read (a command-line/file problem, not an alarm)."""


def _refuse_loosened_protection(path: Path, md: Any) -> None:
    """A machine file the user passes may tighten protection levels, never loosen them.

    The USER_CLASS data (MD 9200 …) hold the level each function needs; a file of the
    user's own giving a function a level with fewer rights than the product's value would
    let anyone write what the panel and ``nck md`` refuse (and the write would land in NC
    data shared with the product's machines). Such levels are changed in the Setup area or
    with ``nck md`` at the level they need.
    """
    if not isinstance(md, dict):
        return
    defaults = {f"MD{entry['number']}": entry["default"]
                for entry in load_toml("md", "display.toml")["data"]
                if entry["number"] in USER_CLASS_NUMBERS}
    for key, value in md.items():
        if key in defaults and (isinstance(value, bool) or not isinstance(value, int)
                                or not 0 <= value <= defaults[key]):
            raise MachineFileError(
                f"machine file {path}: {key} = {value!r} would lower the protection level "
                f"{defaults[key]} of the product; a machine file may only make it stricter (0 … {defaults[key]})")


def load_machine(name_or_path: str | None = None) -> MachineConfig:
    """Load a machine by name (``data/machines/<name>.toml``) or by file path."""
    name = name_or_path or DEFAULT_MACHINE
    path = Path(name)
    if not (path.suffix == ".toml" and path.is_file()):
        path = data_path("machines", f"{name}.toml")
    if not path.is_file():
        raise MachineFileError(f"machine '{name}' not found")
    try:
        product = path.resolve().is_relative_to(data_root())
        if product:
            table = read_table(path)  # a machine of the product: through its parsed copy
        else:
            try:
                table = load_operator_toml(path)
            except OperatorFileError as exc:
                raise MachineFileError(f"machine file {path} {exc}") from None
            _refuse_loosened_protection(path, table.get("md", {}))
        head = table["machine"]
        axes = tuple(
            AxisConfig(
                name=entry["name"],
                kind=entry.get("kind", "linear"),
                index=index,
                diameter=bool(entry.get("diameter", False)),
            )
            for index, entry in enumerate(table["axis"])
        )
        return MachineConfig(
            name=head["name"],
            title=head.get("title", head["name"]),
            kind=head.get("kind", "mill"),
            axes=axes,
            md=dict(table.get("md", {})),
            source=str(path),
            sim=dict(table.get("sim", {})),
        )
    except (OSError, tomllib.TOMLDecodeError, KeyError, TypeError) as exc:
        raise MachineFileError(f"machine file {path}: {exc}") from exc
