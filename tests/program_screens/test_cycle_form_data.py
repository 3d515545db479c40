"""The cycle forms' data (data/cycles/cycles.toml [menus], [forms]): menus, parameter lists,
refusals and call lines.

Ranges from data/cycles/README.md (PGZ): SDIS and DPR unsigned, FRF 0.001 … 1, CYCLE83 VARI 0
(chip breaking) or 1 (swarf removal), NUM a whole number of holes. Grouping as Operate's
program editor (docs/screens_added.md).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hmi.cycle_forms import CallLine, cycle_forms, cycle_menus, is_modal_call_off, modal_call_toggled, read_call

CYCLES_DIR = Path(__file__).resolve().parents[2] / "data" / "cycles"


def test_menus_group_the_cycles_as_operate() -> None:
    """Drilling, Milling, Turning (lathe) hold every cycle that has a form, each once."""
    menus = {menu.menu_id: menu for menu in cycle_menus()}
    assert [m.label for m in cycle_menus()] == ["Drilling", "Milling", "Turning"]
    assert menus["drilling"].cycles() == ["CYCLE81", "CYCLE82", "CYCLE85", "CYCLE83", "CYCLE86", "CYCLE87",
                                          "CYCLE88", "CYCLE89", "CYCLE84", "CYCLE840", "HOLES1", "HOLES2",
                                          "CYCLE801", "CYCLE802"]
    assert [k.label for k in menus["drilling"].keys][-1] == "Modal call\non / off"
    assert {"CYCLE61", "POCKET3", "POCKET4", "CYCLE76", "CYCLE77", "SLOT1", "SLOT2", "LONGHOLE",
            "CYCLE832"} == set(menus["milling"].cycles())
    assert {"CYCLE95", "CYCLE93", "CYCLE97"} <= set(menus["turning"].cycles())
    assert menus["turning"].machine == "lathe"
    every = [c for menu in cycle_menus() for c in menu.cycles()]
    assert sorted(every) == sorted(cycle_forms()) and len(every) == len(set(every))
    assert all(len(menu.keys) <= 8 for menu in cycle_menus())
    assert menus["turning"].cycles()[:2] == ["CYCLE95", "CYCLE93"]


LEFT_OUT = {  # the 828D mode words the cycles accept and do not use (cycles.toml, forms)
    "CYCLE81": ["_GMODE", "_DMODE", "_AMODE"],
    "CYCLE82": ["_GMODE", "_DMODE", "_AMODE"],
    "CYCLE61": ["_LIM", "_GMODE", "_DMODE", "_AMODE"],
}


@pytest.mark.parametrize("cycle", sorted(cycle_forms()))
def test_form_parameters_are_the_cycles_parameters_in_order(cycle: str) -> None:
    """Each form lists every PROC parameter of the cycle's NC program in order (but the unused mode words)."""
    proc = re.search(r"PROC\s+\w+\s*\(([^)]*)\)", (CYCLES_DIR / f"{cycle}.SPF").read_text())
    assert proc is not None
    names = [declaration.split()[-1] for declaration in proc[1].split(",")]
    types = [declaration.split()[0].upper() for declaration in proc[1].split(",")]
    params = cycle_forms()[cycle].params
    assert [p.name for p in params] + LEFT_OUT.get(cycle, []) == names
    for param, kind in zip(params, types):
        assert (param.kind == "name") == kind.startswith("STRING"), param.name
        if kind == "INT":
            assert param.integer or param.choices, f"{param.name} is INT"
    for param in params:  # the default of a new call is a value of the form
        assert param.refusal(param.default) is None, param.name


def test_refusals_name_the_parameter_and_the_reason() -> None:
    """Out of range, not in the list, not a number, not whole: each refused with its reason."""
    params = {p.name: p for p in cycle_forms()["CYCLE83"].params}
    assert params["VARI"].refusal("2") == "VARI: only 0 / 1 permitted"
    assert params["SDIS"].refusal("-0.5") == "SDIS: value below the lower limit 0"
    assert params["FRF"].refusal("1.5") == "FRF: value above the upper limit 1"
    assert params["RTP"].refusal("R1") == "RTP: 'R1' is not a number"
    assert params["FRF"].refusal("0.5") is None and params["VARI"].refusal("1") is None
    assert params["DAM"].refusal("") is None  # empty: not programmed
    num = cycle_forms()["HOLES2"].params[5]
    assert num.refusal("2.5") == "NUM: only whole numbers permitted"
    assert num.refusal("0") == "NUM: value below the lower limit 1"
    npp = cycle_forms()["CYCLE95"].params[0]
    assert npp.refusal("") == "NPP: '' is not a program name (letters, digits, _; 24 at most)"
    assert npp.refusal("1ABC") is not None and npp.refusal("SHAFT_CONTOUR") is None


def test_call_line_round_trip_keeps_what_surrounds_the_call() -> None:
    """Block number, MCALL and comment stay; lower-case names are read; empty places stay empty."""
    found = read_call("N30 mcall cycle82(5, 0, 2, , 3, 1.50) ; spot")
    assert isinstance(found, CallLine) and found.form.cycle == "CYCLE82"
    assert found.texts == ["5", "0", "2", "", "3", "1.50"]
    assert found.with_call(found.form.call_line(found.texts)) == "N30 mcall CYCLE82(5,0,2,,3,1.5) ; spot"
    assert read_call("N10 G1 X10") is None
    assert read_call("L20(1,2)") is None  # a subprogram without a form
    assert read_call("CYCLE81(1,2,3,4,5,6)") == "CYCLE81: more than 5 parameters, the form cannot show the call"
    assert read_call("CYCLE95(NAME,2)") == "NPP = NAME cannot be shown in the form"
    contour = read_call('CYCLE95("A,B",2)')
    assert isinstance(contour, CallLine) and contour.texts[:2] == ["A,B", "2"]
    assert read_call("HOLES2()").texts == cycle_forms()["HOLES2"].defaults()  # type: ignore[union-attr]


def test_modal_call_switch() -> None:
    """MCALL goes before a drilling call and comes off again; positions and milling calls are not switched."""
    assert modal_call_toggled("N50 CYCLE83(10,0,2) ; x") == "N50 MCALL CYCLE83(10,0,2) ; x"
    assert modal_call_toggled("N50 MCALL CYCLE83(10,0,2) ; x") == "N50 CYCLE83(10,0,2) ; x"
    assert modal_call_toggled("HOLES2(0,0,40)") is None
    assert modal_call_toggled("POCKET4(10)") is None
    assert modal_call_toggled("G1 X10") is None
    assert is_modal_call_off("N70 MCALL ; off") and not is_modal_call_off("MCALL CYCLE81()")
