"""Protection levels, passwords and the keyswitch; the protected-datum matrix."""

from __future__ import annotations

import copy
import json

import pytest

from nck.access import (
    AccessControl,
    AccessDenied,
    AccessState,
    Action,
    PasswordError,
    keyswitch_from_bits,
    may,
    required_level,
)
from nck.machine import load_machine
from nck.machine_data import MachineDataStore

_FRESH = AccessState()  # hashing the factory passwords once keeps the tests fast


def fresh_state() -> AccessState:
    return copy.deepcopy(_FRESH)


def control_at(level: int) -> AccessControl:
    """An AccessControl brought to ``level`` the way an operator would."""
    control = AccessControl(fresh_state())
    if level >= 4:
        control.set_keyswitch(7 - level)
    else:
        control.enter_password({1: "SUNRISE", 2: "EVENING", 3: "CUSTOMER"}[level])
    assert control.level == level
    return control


# The configured table: the highest (least privileged) level that may still do it.
EXPECTED_LEVEL = {
    Action.READ_TOOL: 7,
    Action.WRITE_TOOL_GEOMETRY: 4,
    Action.WRITE_TOOL_WEAR: 6,
    Action.WRITE_WORK_OFFSET: 6,
    Action.WRITE_R_PARAMETER: 6,
    Action.CLEAR_R_PARAMETERS: 5,
    Action.WRITE_USER_DATA: 4,
    Action.WRITE_SETTING_DATA: 4,
    Action.WRITE_PROGRAM_CONTROL: 5,
    Action.SELECT_PROGRAM: 6,
    Action.READ_PROGRAM: 7,
    Action.EDIT_PROGRAM: 4,
    Action.PRESET: 5,
}
EXPECTED_MD_LEVEL = {"MD32000[X]": 2, "MD36110[X]": 2, "MD28050": 1, "MD9004": 3,
                     "MD9210": 3, "SD42100": 4, "SD43420[X]": 4, "SD41010": 4}


@pytest.mark.parametrize("level", range(1, 8))
def test_protected_action_matrix(level: int) -> None:
    """Digest 828d-3 rank 3."""
    control = control_at(level)
    for action, highest in EXPECTED_LEVEL.items():
        assert control.may(action) is (level <= highest), (action, level)
        if level <= highest:
            control.require(action)
        else:
            with pytest.raises(AccessDenied) as refused:
                control.require(action)
            assert refused.value.needed_level == highest
            assert f"level {highest}" in str(refused.value)


@pytest.mark.parametrize("level", range(0, 8))
def test_may_function_matrix(level: int) -> None:
    for action, highest in EXPECTED_LEVEL.items():
        assert may(level, action) is (level <= highest)


@pytest.mark.parametrize("level", range(0, 8))
def test_machine_and_setting_data_matrix(level: int) -> None:
    for name, highest in EXPECTED_MD_LEVEL.items():
        store = MachineDataStore(load_machine(), setting_data={})
        value = {"MD9004": 4, "MD9210": 7, "MD28050": 150}.get(name.split("[")[0], 1.0)
        if level <= highest:
            store.write(name, value, level=level)
            assert store.value(name) == value
        else:
            with pytest.raises(AccessDenied) as refused:
                store.write(name, value, level=level)
            assert refused.value.needed_level == highest
            assert store.changes == {} and store.setting_data == {}


@pytest.mark.parametrize("level", range(1, 8))
def test_password_change_matrix(level: int) -> None:
    for target in (1, 2, 3):
        control = control_at(level)
        if level <= target:
            control.change_password(target, "NEWPW")
            assert control.check_password("NEWPW") == target
        else:
            with pytest.raises(AccessDenied):
                control.change_password(target, "NEWPW")
            assert control.check_password("NEWPW") is None


def test_user_class_md_changes_the_matrix() -> None:
    store = MachineDataStore(load_machine())
    control = AccessControl(fresh_state(), user_class=store.user_class)
    control.set_keyswitch(0)
    assert not control.may(Action.WRITE_WORK_OFFSET)
    store.write("MD9210", 7, level=3)
    assert control.may(Action.WRITE_WORK_OFFSET)
    assert required_level(Action.WRITE_WORK_OFFSET, store.user_class) == 7


def test_keyswitch_levels_and_fresh_state() -> None:
    """Digest 828d-1 rank 5 (keyswitch levels, 002 L1319-1380).

    Digest 828d-3 rank 1: positions 0-3 give levels 7-4; bits 1 and 4 together give position 3 (002 L1453-1478).
    """
    control = AccessControl(fresh_state())
    assert control.level == 7
    for position, level in [(0, 7), (1, 6), (2, 5), (3, 4)]:
        control.set_keyswitch(position)
        assert control.level == level
    with pytest.raises(ValueError):
        control.set_keyswitch(4)
    assert keyswitch_from_bits((True, False, False, False)) == 0
    assert keyswitch_from_bits((False, False, True, False)) == 2
    assert keyswitch_from_bits((True, False, False, True)) == 3


def test_passwords_override_keyswitch_until_deleted() -> None:
    """Digest 828d-1 rank 5: CUSTOMER 3, EVENING 2, SUNRISE 1 (002 L1440-1442).

    Digest 828d-3 rank 2 (002 L1413-1452).
    """
    control = AccessControl(fresh_state())
    control.set_keyswitch(3)
    assert control.enter_password("CUSTOMER") == 3
    control.set_keyswitch(0)
    assert control.level == 3
    assert control.enter_password("SUNRISE") == 1
    control.delete_password()
    assert control.level == 7
    assert control.log[-1].startswith("access level 1 -> 7")


def test_wrong_long_and_padded_passwords() -> None:
    """Digest 828d-1 rank 5 (at most 8 characters, wrong password keeps the level).

    Digest 828d-3 rank 2: case-sensitive, 9 characters refused, level unchanged.
    """
    control = AccessControl(fresh_state())
    with pytest.raises(PasswordError):
        control.enter_password("evening")  # case matters
    with pytest.raises(PasswordError):
        control.enter_password("EVENINGXX")  # 9 characters
    with pytest.raises(PasswordError):
        control.enter_password("   ")
    assert control.level == 7
    assert control.enter_password("EVENING ") == 2  # blank padding is the same password


def test_password_cannot_open_two_levels() -> None:
    control = control_at(1)
    with pytest.raises(PasswordError):
        control.change_password(3, "EVENING")
    with pytest.raises(PasswordError):
        control.change_password(3, "TOOLONGPW")
    with pytest.raises(PasswordError):
        control.change_password(4, "ABC")


def test_state_round_trip_keeps_only_hashes() -> None:
    control = AccessControl(fresh_state())
    control.set_keyswitch(1)
    control.enter_password("EVENING")
    text = json.dumps(control.state.to_json())
    for plain in ("SUNRISE", "EVENING", "CUSTOMER"):
        assert plain not in text
    restored = AccessControl(AccessState.from_json(json.loads(text)))
    assert restored.level == 2
    restored.delete_password()
    assert restored.level == 6
    assert restored.check_password("CUSTOMER") == 3


@pytest.mark.parametrize("bad", [
    {"keyswitch_position": 4, "password_level": None, "passwords": {}},
    {"keyswitch_position": 0, "password_level": 5, "passwords": {}},
    {"keyswitch_position": 0, "password_level": None, "passwords": {"1": {"kdf": "md5"}}},
    {"keyswitch_position": 0},
])
def test_malformed_state_is_refused(bad: dict) -> None:
    with pytest.raises((ValueError, KeyError, TypeError)):
        AccessState.from_json(bad)


@pytest.mark.parametrize("name, action", [
    ("R10", Action.WRITE_R_PARAMETER), ("R[5]", Action.WRITE_R_PARAMETER),
    ("$R3", Action.WRITE_R_PARAMETER),
    ("$TC_DP6[1,1]", Action.WRITE_TOOL_GEOMETRY), ("$TC_DP3[2,1]", Action.WRITE_TOOL_GEOMETRY),
    ("$TC_DP12[1,1]", Action.WRITE_TOOL_WEAR), ("$TC_DP15[1,2]", Action.WRITE_TOOL_WEAR),
    ("$TC_DP21[1,1]", Action.WRITE_TOOL_GEOMETRY), ("$TC_TP2[1]", Action.WRITE_TOOL_TYPE),
    ("$P_UIFR[1,X,TR]", Action.WRITE_WORK_OFFSET), ("G54", Action.WRITE_WORK_OFFSET),
    ("G505.X", Action.WRITE_WORK_OFFSET), ("$P_CHBFR[0,Z,TR]", Action.WRITE_WORK_OFFSET),
    ("MD32000[X]", None), ("SD42100", None), ("RESULT", None), ("G500", None),
])
def test_action_for_write(name: str, action: Action | None) -> None:
    from nck.access import action_for_write

    assert action_for_write(name) is action


def test_require_write_matrix() -> None:
    """Digest 828d-3 rank 3: access needs current level <= required level (002 L1479-1632)."""
    control = control_at(7)
    with pytest.raises(AccessDenied) as refused:
        control.require_write("$P_UIFR[1,X,TR]")
    assert refused.value.needed_level == 6
    control.require_write("MD32000[X]")  # checked by the MD store, not here
    control = control_at(6)
    control.require_write("$P_UIFR[1,X,TR]")
    control.require_write("$TC_DP12[1,1]")
    with pytest.raises(AccessDenied):
        control.require_write("$TC_DP6[1,1]")
    control_at(4).require_write("$TC_DP6[1,1]")


def test_every_change_through_the_access_control_moves_its_revision() -> None:
    # Whoever shows the access state (the kernel's snapshot) knows from the revision that it
    # is stale, whichever door made the change - also one that leaves the level as it was.
    control = AccessControl(fresh_state())
    seen = [control.revision]

    def moved() -> bool:
        seen.append(control.revision)
        return seen[-1] > seen[-2]

    control.set_keyswitch(0)  # the same position: the level stays 7
    assert moved()
    with pytest.raises(PasswordError):
        control.enter_password("WRONG")  # a failed attempt is counted
    assert moved()
    control.enter_password("CUSTOMER")
    assert moved()
    control.change_password(3, "NEWONE")
    assert moved()
    control.delete_password()
    assert moved()
    assert control.level == 7 and not control.may(Action.WRITE_TOOL_GEOMETRY)  # reading changes nothing
    assert not moved()
