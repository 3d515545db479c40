"""Part-program writes of setting data (``$SN_…``, ``$SC_…``, ``$SA_…[axis]``).

A part program may write a setting datum when the protection level active while it runs
permits it (the datum's own write level, ``protect`` in the catalogue) and the datum takes
effect immediately (004 L245-249; the manual's own examples
write ``$SC_WEAR_SIGN``, 002 L62080-62106). The write goes through the machine-data store's
one write path (:meth:`nck.machine_data.MachineDataStore.write`: level, type and limits);
here its refusals become NC alarms:

* level too low, or a datum that does not take effect at once → 17070 (write-protected);
* value below / above the datum's limits → 17080 / 17090; a value of the wrong type → 12150.

Machine data (``$MN_``/``$MC_``/``$MA_``) stay read-only for part programs: the kernel takes
them from the machine configuration, which a running program cannot change (17070).
The write is journaled: a block that fails later leaves the datum as it was.
"""

from __future__ import annotations

import copy
from typing import Any, Callable

from nck.access import LEVEL_MOST_RIGHTS
from nck.alarm_ids import (
    DATA_WRITE_PROTECTED, ILLEGAL_ARRAY_INDEX_1, NAME_NOT_DEFINED, OPERATION_DOES_NOT_FIT_TYPE,
    VALUE_ABOVE_UPPER_LIMIT, VALUE_BELOW_LOWER_LIMIT,
)
from nck.errors import NcAlarmError
from nck.machine_data import DataValueError, MachineDataStore, UnknownDataError

ALARM_BELOW_LIMIT = VALUE_BELOW_LOWER_LIMIT
ALARM_ABOVE_LIMIT = VALUE_ABOVE_UPPER_LIMIT


def write_setting_data(interp: Any, name: str, indices: tuple[Any, ...], value: Any,
                       journal: Callable[[Callable[[], None]], None]) -> None:
    """Write setting datum ``name`` (``$SC_WEAR_SIGN``; ``indices`` as programmed) at the
    interpreter's current protection level; ``journal`` receives the undo of the write."""
    store = MachineDataStore(interp.machine, {}, interp.data.setting_data)
    text = name + (f"[{','.join(_index_text(i) for i in indices)}]" if indices else "")
    try:
        ref = store.resolve(text)
    except UnknownDataError:  # a known name with a bad index or axis is 17020
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1 if store.catalog.get(name) else NAME_NOT_DEFINED, name) from None
    definition = ref.definition
    if definition.kind != "sd" or definition.activation != "so":
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if definition.min is not None and value < definition.min:
            raise NcAlarmError(ALARM_BELOW_LIMIT, name)
        if definition.max is not None and value > definition.max:
            raise NcAlarmError(ALARM_ABOVE_LIMIT, name)
    if interp.access_level() > definition.write_level:
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)
    key = definition.key
    had, old = key in interp.data.setting_data, copy.deepcopy(interp.data.setting_data.get(key))
    try:
        # The datum's own level was checked above; the panel's user class for its setting-data
        # screen (MD9215) guards the operator's door, not the NCK's part-program door.
        store.write(ref, value, level=LEVEL_MOST_RIGHTS)
    except DataValueError:
        raise NcAlarmError(OPERATION_DOES_NOT_FIT_TYPE, name) from None
    setting_data = interp.data.setting_data

    def undo() -> None:
        if had:
            setting_data[key] = old
        else:
            setting_data.pop(key, None)

    journal(undo)


def _index_text(index: Any) -> str:
    """An evaluated index as the catalogue spells it: ``2.0`` → ``2``, an axis name as is."""
    if isinstance(index, float) and index.is_integer():
        return str(int(index))
    return str(index)
