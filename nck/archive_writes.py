"""An archive import writes NC data through the one write path (:class:`nck.writes.DataWriter`).

An archive replaces whole sections (tools, work offsets, R parameters, GUD,
setting and machine data). Two rules make that the same write as any other door:

* protection: every datum the import changes or removes needs the level
  :meth:`DataWriter.required_level` names for it — the same rule as the panel,
  ``nck md`` and ``nck run --set``; data that stay as they are need nothing;
* validation: every imported value is written by :meth:`DataWriter.write` into
  fresh NC data, so types, limits and names are checked as for any write.
  The fresh NC data are the result: nothing unchecked reaches the retained files.

Names are those of :mod:`nck.writes` (``R5``, ``$TC_DP6[1,1]``,
``$P_UIFR[1,X,TR]``, ``$P_UBFR[X,RT]``, ``GUD:NAME[2]``, ``SD42100``, ``MD32000[X]``).
"""

from __future__ import annotations

import copy
from typing import Any, Iterable

from nck.access import AccessDenied
from nck.machine import MachineConfig
from nck.machine_data import MachineDataStore, catalog
from nck.ncdata import NcData, WorkOffset
from nck.writes import DataWriter, WriteRefused, settable_frame_index

WRITTEN_SECTIONS = ("tools", "work_offsets", "r_parameters", "user_data", "setting_data", "machine_data")
"""The sections an import writes datum by datum (the others carry no protected data)."""
_FRAME_PARTS = {"TR": "trans", "FI": "fine", "RT": "rot", "SC": "scale", "MI": "mirror"}


def _frame_names(prefix: str, offset: WorkOffset) -> dict[str, Any]:
    names: dict[str, Any] = {}
    for comp, part in _FRAME_PARTS.items():
        for axis, value in getattr(offset, part).items():
            names[f"{prefix}{axis},{comp}]"] = float(value) if comp == "MI" else value
    return names


def _catalog_names(values: dict[str, Any]) -> dict[str, Any]:
    """Machine or setting data by write name (``MD32000[X]``, ``MD20150[5]``, ``MD32200[1,X]``)."""
    names: dict[str, Any] = {}
    for key, value in values.items():
        definition = catalog().get(key)
        array = definition.array if definition is not None else 0
        slots = value.items() if isinstance(value, dict) else [(None, value)]
        for axis, item in slots:
            if array and not isinstance(item, list):
                item = [item] * array  # an array stored as one value for every element
            elements = enumerate(item) if isinstance(item, list) else [(None, item)]
            for index, element in elements:
                inside = ",".join(str(p) for p in (index, axis) if p is not None)
                names[f"{key}[{inside}]" if inside else key] = element
    return names


def section_names(section: str, data: NcData, md_changes: dict[str, Any]) -> dict[str, Any]:
    """Every datum of one section of ``data`` by its write name, with its value."""
    if section == "tools":
        return {f"$TC_DP{p}[{t},{d}]": v for (t, d), edge in data.tools.items() for p, v in edge.params.items()}
    if section == "r_parameters":
        return {f"R{i}": v for i, v in enumerate(data.r) if v != 0.0}
    if section == "work_offsets":
        names = _frame_names("$P_UBFR[", data.base_frame)
        for frame, offset in data.settable_frames.items():
            try:
                index = settable_frame_index(frame)
            except ValueError:
                raise WriteRefused("not_a_work_offset", name=frame) from None
            names.update(_frame_names(f"$P_UIFR[{index},", offset))
        return names
    if section == "user_data":
        names = {}
        for name, value in data.gud.items():
            if isinstance(value, list):
                names.update({f"GUD:{name}[{i}]": item for i, item in enumerate(value)})
            else:
                names[f"GUD:{name}"] = value
        return names
    if section == "setting_data":
        return _catalog_names(data.setting_data)
    if section == "machine_data":
        return _catalog_names(md_changes)
    raise ValueError(f"section {section!r} is not written datum by datum")


def write_import(current: NcData, current_md: dict[str, Any], imported: NcData, imported_md: dict[str, Any],
                 sections: Iterable[str], machine: MachineConfig, writer_of: Any) -> tuple[NcData, dict[str, Any]]:
    """Check and write the imported sections; return the NC data and MD changes to keep.

    ``writer_of(data, store)`` builds the :class:`DataWriter` of the importer
    (its access control and level) on the given NC data. Raises AccessDenied
    (a changed or removed datum above the level), WriteRefused or a DataError
    (a value the datum does not take); nothing is changed then.
    """
    sections = [s for s in sections if s in WRITTEN_SECTIONS]
    checker = writer_of(current, MachineDataStore(machine, copy.deepcopy(current_md), current.setting_data))
    result = NcData()
    result.r = [0.0] * len(imported.r)
    result.gud = copy.deepcopy(imported.gud)  # the definitions (names, types, sizes); values written below
    result.gud_access = copy.deepcopy(imported.gud_access)
    result.setting_data = {}
    store = MachineDataStore(machine, {}, result.setting_data)
    validator = DataWriter(result, store, None)  # a bench: values, types and names, no protection
    for section in sections:
        before = section_names(section, current, current_md)
        after = section_names(section, imported, imported_md)
        for name in sorted(set(before) | set(after)):
            if before.get(name) != after.get(name):
                needed = checker.required_level(name)
                if checker.level > needed:
                    raise AccessDenied("import_datum", needed, checker.level, datum=name)
        for name, value in after.items():
            validator.write(name, value)
        if section == "user_data":
            _check_gud_protection(checker, current.gud_access, imported.gud_access)
    return result, store.retained_changes()


def _check_gud_protection(checker: DataWriter, before: dict[str, dict[str, int]],
                          after: dict[str, dict[str, int]]) -> None:
    """The APRP/APWP levels of a GUD are protection data: changing them needs the level of
    writing user data and the rights of every level changed (none may be loosened from below)."""
    for name in set(before) | set(after):
        old, new = before.get(name, {}), after.get(name, {})
        if any(not 0 <= level <= 7 for level in new.values()):
            raise WriteRefused("protection_level_values", name=name)
        if old != new:
            needed = min([checker.required_level(f"GUD:{name}"), *old.values(), *new.values()])
            if checker.level > needed:
                raise AccessDenied("import_protection_levels", needed, checker.level, name=name)


def md_write_level(key: str) -> int:
    """The level a machine datum of another machine needs (by its catalogue entry; 0 when unknown)."""
    definition = catalog().get(key)
    return definition.write_level if definition is not None else 0
