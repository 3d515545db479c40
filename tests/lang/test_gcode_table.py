"""The G-group table in data/gcode/siemens.toml is complete and consistent."""

from __future__ import annotations

import tomllib

from nck.lang.gcodes import gtable, normalize
from nck.resources import data_path


def test_groups_1_to_16_are_present() -> None:
    assert set(range(1, 17)) <= set(gtable().groups)


def test_every_code_belongs_to_exactly_one_group() -> None:
    table = tomllib.loads(data_path("gcode", "siemens.toml").read_text())
    seen: dict[str, int] = {}
    for group in table["group"]:
        for code in group.get("members", []):
            if code:
                assert code not in seen, f"{code} in groups {seen[code]} and {group['number']}"
                seen[code] = group["number"]


def test_reset_members_belong_to_their_modal_group() -> None:
    for group in gtable().groups.values():
        if group.modal and group.members:
            assert group.reset in group.members, group.number
        for _, member in group.reset_by_kind:
            assert member in group.members
        if not group.modal:
            assert group.reset is None


def test_manual_reset_state_of_a_mill() -> None:
    state = gtable().reset_state()
    assert {g: state[g] for g in (1, 6, 7, 8, 10, 12, 13, 14, 15)} == {
        1: "G1", 6: "G17", 7: "G40", 8: "G500", 10: "G60", 12: "G601", 13: "G71", 14: "G90", 15: "G94",
    }
    assert gtable().reset_state(kind="lathe")[6] == "G18"


def test_positions_follow_the_manual_numbering() -> None:
    table = gtable()
    assert table.lookup("G0").position("G0") == 1
    assert table.lookup("G91").position("G91") == 2
    assert table.lookup("G55").position("G55") == 3
    assert table.lookup("G505").position("G505") == 6
    assert table.lookup("G599").position("G599") == 100
    assert table.lookup("G96").position("G96") == 4


def test_leading_zeros_are_normalised() -> None:
    assert normalize("G01") == "G1" and normalize("g00") == "G0" and normalize("G90") == "G90"
    assert normalize("G505") == "G505"
