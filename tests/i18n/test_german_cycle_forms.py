"""The program editor's cycle forms in German (issue 27): the form's title and the help line of
the parameter under the cursor from data/lang/de/cycles.toml, the word help's cycle title too.

Keys as tests/program_screens/test_cycle_forms.py: Shift+F7 Cycles (drilling keys), Shift+F3
Deep hole drilling; ↓ moves to the next field. Parameter order CYCLE83(RTP, RFP, SDIS, …)
as data/cycles/README.md.
"""

from __future__ import annotations

from pathlib import Path

from hmi.cycle_form_dialog import CycleFormDialog
from hmi.cycle_forms import cycle_forms
from hmi.i18n import set_language
from hmi.word_help import word_help
from tests.burst import burst
from tests.program_screens.conftest import SIZE, data_dir, make_program_app  # noqa: F401 (fixture)


def shown(form: CycleFormDialog, widget_id: str) -> str:
    return str(form.query_one(widget_id).render())


async def test_deep_hole_drilling_form_in_german(data_dir: Path) -> None:
    """Opened in one burst; the help follows the cursor from RTP to SDIS."""
    set_language("de")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3", "down", "shift+f7")
        menu = app.screen.current_menu()
        assert [key.label for key in menu.horizontal[:3]] == ["Bohren", "Fräsen", "Drehen"]
        assert menu.slot("v3").label == "Tiefloch-\nbohren"
        await burst(pilot, "shift+f4")  # Boring: a sub-level of four cycles
        assert app.screen.current_menu().slot("v2").label == "Ausdrehen\nmit Stopp"  # CYCLE87
        await burst(pilot, "f8")  # back to the drilling keys
        assert app.screen.current_menu().find("cycle.CYCLE83") == "v3"
        await burst(pilot, "shift+f3")
        form = app.screen
        assert isinstance(form, CycleFormDialog) and form.form.cycle == "CYCLE83"
        assert shown(form, "#cycle-title") == "CYCLE83 Tieflochbohren (Neu)"
        assert shown(form, "#cycle-keys").startswith("↑/↓ Feld   Enter nächstes Feld")
        assert shown(form, "#cycle-help") == "RTP: Rückzugsebene (absolut)"
        assert "FDEP / FDPR  erste Bohrtiefe" in shown(form, "#cycle-sketch")
        await burst(pilot, "down", "down")
        assert shown(form, "#cycle-help") == "SDIS: Sicherheitsabstand über RFP (ohne Vorzeichen)"


def test_word_help_names_the_cycle_in_german() -> None:
    set_language("de")
    assert word_help("CYCLE83").startswith("CYCLE83: Zyklus Tieflochbohren — CYCLE83(RTP, RFP, SDIS, DP, DPR, ")
    assert word_help("CYCLE81").startswith("CYCLE81: Zyklus Zentrieren — ")
    set_language("en")
    assert word_help("CYCLE83").startswith("CYCLE83: cycle Deep hole drilling — ")


def test_range_and_refusals_in_german() -> None:
    """The ranges of data/cycles/cycles.toml: CYCLE83 SDIS 0 … 99999.999, VARI 0 / 1; CYCLE95 NPP a name."""
    set_language("de")
    forms = cycle_forms()
    sdis, vari = forms["CYCLE83"].params[2], forms["CYCLE83"].params[11]
    assert sdis.refusal("-1") == "SDIS: Wert unter der unteren Grenze 0"
    assert sdis.refusal("x") == "SDIS: 'x' ist keine Zahl"
    assert vari.refusal("2") == "VARI: nur 0 / 1 zulässig"
    assert forms["CYCLE95"].params[0].range_text() == "Programmname"
