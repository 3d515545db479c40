"""The cycle forms' data (data/cycles/cycles.toml [forms]): refusals and call lines.

Ranges from data/cycles/README.md "Drilling" (PGZ chapter 2): SDIS and DPR unsigned, FRF
0.001 … 1, CYCLE83 VARI 0 (chip breaking) or 1 (swarf removal).
"""

from __future__ import annotations

from hmi.cycle_forms import CallLine, cycle_forms, forms_of_menu, read_call


def test_drilling_menu_holds_cycle81_to_83_in_call_order() -> None:
    """The Drilling softkey lists CYCLE81, CYCLE82, CYCLE83 with the PGZ parameter order."""
    assert [f.cycle for f in forms_of_menu("drilling")] == ["CYCLE81", "CYCLE82", "CYCLE83"]
    assert [p.name for p in cycle_forms()["CYCLE82"].params] == ["RTP", "RFP", "SDIS", "DP", "DPR", "DTB"]
    assert len(cycle_forms()["CYCLE83"].params) == 17


def test_refusals_name_the_parameter_and_the_reason() -> None:
    """Out of range, not in the list, not a number: each refused with its reason; good values pass."""
    params = {p.name: p for p in cycle_forms()["CYCLE83"].params}
    assert params["VARI"].refusal("2") == "VARI: only 0 / 1 permitted"
    assert params["SDIS"].refusal("-0.5") == "SDIS: value below the lower limit 0"
    assert params["FRF"].refusal("1.5") == "FRF: value above the upper limit 1"
    assert params["RTP"].refusal("R1") == "RTP: 'R1' is not a number"
    assert params["FRF"].refusal("0.5") is None and params["VARI"].refusal("1") is None


def test_call_line_round_trip_keeps_what_surrounds_the_call() -> None:
    """Block number, MCALL and comment stay; lower-case names are read; other menus are ignored."""
    found = read_call("N30 mcall cycle82(5,0,2,,3,1.5) ; spot", "drilling")
    assert isinstance(found, CallLine) and found.form.cycle == "CYCLE82"
    assert found.texts == ["5", "0", "2", "-10", "3", "1.5"]
    assert found.with_call(found.form.call_line(found.texts)) == "N30 mcall CYCLE82(5,0,2,-10,3,1.5) ; spot"
    assert read_call("N10 G1 X10", "drilling") is None
    assert read_call("CYCLE81(1,2,3,4,5,6)", "drilling") == (
        "CYCLE81: more than 5 parameters, the form cannot show the call")
