"""The MD/SD catalogue, names, limits and activation (stored vs active values)."""

from __future__ import annotations

import pytest

from nck.access import AccessDenied
from nck.machine import load_machine
from nck.machine_data import (
    DataValueError,
    MachineDataStore,
    UnknownDataError,
    catalog,
    fill_setting_defaults,
    unknown_machine_keys,
)
from nck.resources import data_path

MOTION_MD = [32000, 32300, 32431, 32200, 36100, 36110, 36000, 36010, 32020, 32010, 34000,
             34010, 34020, 34040, 34060, 34070, 34080, 34090, 34100, 34110, 10050, 10070,
             28050, 20150]
ISSUE_SD = [41010, 41110, 42100, 42101, 43400, 43410, 43420, 43430, 43200, 43210, 43220]


def test_catalogue_has_the_data_the_kernel_and_screens_need() -> None:
    cat = catalog()
    for number in MOTION_MD:
        assert cat.get(f"MD{number}") is not None, number
    for number in ISSUE_SD:
        assert cat.get(f"SD{number}") is not None, number
    assert cat.get("MD32000").identifier == "$MA_MAX_AX_VELO"
    assert cat.get("SD42100").identifier == "$SC_DRY_RUN_FEED"
    assert cat.get("SD41010").identifier == "$SN_JOG_VAR_INCR_SIZE"
    assert cat.get("MD9004").identifier == "$MM_DISPLAY_RESOLUTION"
    assert cat.get("MD10070").identifier == "$MN_IPO_SYSCLOCK_TIME_RATIO"
    assert cat.get("MD20150").identifier == "$MC_GCODE_RESET_VALUES"


def test_every_default_is_valid_for_its_own_definition() -> None:
    for d in catalog():
        values = d.default if isinstance(d.default, list) else [d.default]
        if d.array and isinstance(d.default, list):
            assert len(d.default) == d.array, d.key
        for value in values:
            assert d.coerce(value) == value, d.key
        assert 0 <= d.write_level <= 7 and 0 <= d.read_level <= 7


@pytest.mark.parametrize("path", sorted(data_path("machines").glob("*.toml")), ids=lambda p: p.stem)
def test_every_machine_file_key_is_catalogued_and_within_limits(path) -> None:
    machine = load_machine(str(path))
    assert unknown_machine_keys(machine) == []
    store = MachineDataStore(machine)
    for key, value in machine.md.items():
        d = catalog().get(key)
        per_axis = value.items() if isinstance(value, dict) else [(None, value)]
        for _axis, item in per_axis:
            for element in item if isinstance(item, list) else [item]:
                d.coerce(element)
    assert store.active_machine().md == machine.md


def test_names_by_number_and_identifier_are_the_same_datum() -> None:
    store = MachineDataStore(load_machine())
    for a, b in [("MD32000[X]", "$MA_MAX_AX_VELO[X]"), ("SD42100", "$SC_DRY_RUN_FEED"),
                 ("md32000[x]", "32000[X]"), ("MD32200[1,X]", "$MA_POSCTRL_GAIN[1,X]"),
                 ("MD20150[5]", "$MC_GCODE_RESET_VALUES[5]")]:
        assert store.resolve(a) == store.resolve(b)
    assert store.resolve("SD43220[S1]").axis == "SP"
    assert store.resolve("MD32000[X]").text == "MD32000[X]"
    assert store.resolve("MD32000[X]").identifier_text == "$MA_MAX_AX_VELO[X]"


@pytest.mark.parametrize("bad", ["MD99999", "$MA_NO_SUCH", "MD32000[Q]", "MD20150[60]",
                                  "MD32000[1,X]", "R1", "MD32000[[", ""])
def test_unknown_names_are_refused(bad: str) -> None:
    with pytest.raises(UnknownDataError):
        MachineDataStore(load_machine()).resolve(bad)


def test_values_come_from_machine_file_then_default() -> None:
    machine = load_machine()
    store = MachineDataStore(machine)
    assert store.value("MD32000[X]") == machine.md["MD32000"]["X"]
    assert store.value("MD36120[X]") == catalog().get("MD36120").default
    assert set(store.value("MD32000")) == {"X", "Y", "Z", "SP"}


def test_limits_and_types_are_enforced_and_nothing_changes() -> None:
    store = MachineDataStore(load_machine())
    before = store.value("MD32000[X]")
    with pytest.raises(DataValueError):
        store.write("MD32000[X]", -1, level=0)
    with pytest.raises(DataValueError):
        store.write("MD32000[X]", "fast", level=0)
    with pytest.raises(DataValueError):
        store.write("SD42101", 13, level=0)
    with pytest.raises(DataValueError):
        store.write("MD9004", 2.5, level=0)
    assert store.value("MD32000[X]") == before
    assert store.changes == {}


def test_write_level_is_checked_per_datum() -> None:
    store = MachineDataStore(load_machine())
    with pytest.raises(AccessDenied) as refused:
        store.write("MD32000[X]", 5000, level=3)
    assert refused.value.needed_level == 2
    assert store.write("MD32000[X]", 5000, level=2).new == 5000.0


def test_setting_data_need_the_write_setting_data_level() -> None:
    data: dict = {}
    store = MachineDataStore(load_machine(), setting_data=data)
    with pytest.raises(AccessDenied):
        store.write("SD42100", 1000, level=5)
    result = store.write("$SC_DRY_RUN_FEED", "1000", level=4)
    assert result.active_now and result.takes_effect == "immediately"
    assert data["SD42100"] == 1000.0
    store.write("SD43420[X]", 100, level=4)
    assert data["SD43420"] == {"X": 100.0}


def test_user_class_cannot_grant_more_rights_than_own_level() -> None:
    store = MachineDataStore(load_machine())
    with pytest.raises(AccessDenied):
        store.write("MD9210", 2, level=3)
    store.write("MD9210", 3, level=3)
    assert store.user_class(9210) == 3


def test_power_on_data_wait_for_power_on() -> None:
    store = MachineDataStore(load_machine())
    result = store.write("MD10070", 2, level=2)
    assert not result.active_now and "POWER ON" in result.takes_effect
    assert store.value("MD10070") == 2 and store.active_value("MD10070") == 4
    store.activate("reset")
    store.activate("new_config")
    assert store.active_value("MD10070") == 4
    assert store.active_machine().md["MD10070"] == 4
    assert store.activate("power_on") == ["MD10070"]
    assert store.active_machine().md["MD10070"] == 2
    # a restart: a new store from the retained changes has everything active
    restarted = MachineDataStore(load_machine(), store.retained_changes())
    assert restarted.active_value("MD10070") == 2


def test_reset_data_at_reset_and_immediate_data_at_once() -> None:
    store = MachineDataStore(load_machine())
    store.write("MD36110[X]", 300, level=2)  # re
    store.write("MD32200[0,X]", 3.0, level=2)  # so
    store.write("MD32000[X]", 5000, level=2)  # cf
    assert store.active_value("MD32200[0,X]") == 3.0
    assert store.active_value("MD36110[X]") == 500.0
    assert store.pending() == ["MD32000", "MD36110"]
    assert store.activate("reset") == ["MD32000", "MD36110"]
    assert store.active_value("MD36110[X]") == 300.0
    md = store.active_machine().md
    assert md["MD32000"] == {"X": 5000.0, "Y": 30000.0, "Z": 24000.0, "SP": 8000.0}
    assert md["MD32200"]["X"][0] == 3.0 and md["MD32200"]["Y"] == 2.0


def test_new_config_activates_cf_but_not_po() -> None:
    store = MachineDataStore(load_machine())
    store.write("MD32000[Y]", 6000, level=2)
    store.write("MD28050", 200, level=1)
    assert store.activate("new_config") == ["MD32000"]
    assert store.active_value("MD28050") == 100


def test_array_element_write_keeps_other_elements() -> None:
    store = MachineDataStore(load_machine())
    store.write("MD20150[5]", 2, level=2)
    assert store.value("MD20150[5]") == 2
    assert store.value("MD20150[4]") == 0
    assert len(store.value("MD20150")) == 60


def test_fill_setting_defaults_keeps_existing_values() -> None:
    machine = load_machine()
    data = {"SD42100": 777.0, "SD43420": {"X": 5.0}}
    fill_setting_defaults(data, machine)
    assert data["SD42100"] == 777.0
    assert data["SD43420"]["X"] == 5.0 and data["SD43420"]["Y"] == 1e8
    assert data["SD42101"] == 0


def test_number_of_identifier() -> None:
    from nck.machine_data import number_of

    assert number_of("MAX_AX_VELO") == 32000
    assert number_of("$MA_MAX_AX_VELO") == 32000
    assert number_of("$SC_DRY_RUN_FEED") == 42100
    assert number_of("NO_SUCH_DATUM") is None


def test_rows_for_the_setup_lists() -> None:
    store = MachineDataStore(load_machine(), setting_data={})
    axis_rows = store.rows("md", "axis", axis="Y")
    row = next(r for r in axis_rows if r.ref.definition.number == 32000)
    assert (row.ref.text, row.value_text, row.unit, row.activation, row.write_level) == (
        "MD32000[Y]", "30000", "mm/min", "cf", 2)
    assert all(r.ref.definition.scope == "axis" for r in axis_rows)
    store.write("MD32000[Y]", 1000, level=2)
    assert next(r for r in store.rows("md", "axis", axis="Y") if r.ref.definition.number == 32000).pending
    assert [r.ref.text for r in store.rows("md", search="DRYRUN")] == ["MD10704"]
    assert [r.ref.text for r in store.rows("sd", search="DRY_RUN_FEED_MODE")] == ["SD42101"]
    assert "MD20154" not in [r.ref.text for r in store.rows("md", "channel", level=7)]
    assert {r.ref.definition.scope for r in store.rows("sd")} == {"general", "channel", "axis"}
    assert store.rows("sd", "channel")[0].write_level == 4  # USER_CLASS_WRITE_SEA
