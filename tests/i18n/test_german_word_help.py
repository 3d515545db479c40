"""The editor's word help and the G functions screen in German (issue 27).

One table for both: the codes' meanings of data/gcode/siemens.toml and the groups' meanings,
German from data/lang/de/gcode.toml; the M functions and system variables of
data/gcode/words.toml, German from data/lang/de/words.toml; the ISO dialects' G groups from
data/gcode/iso_m.toml / iso_t.toml, German from the same gcode.toml. Groups as in
tests/program_screens/test_word_help.py (G1 group 1 modal, G4 group 2 non-modal, G91 group 14),
which also walks the editor's message line in German.
"""

from __future__ import annotations

from rich.console import Console

from hmi.i18n import set_language
from hmi.widgets.gfunctions import all_groups_table, iso_group_meanings
from hmi.word_help import word_help


def shown(table) -> str:
    console = Console(width=160, record=True)
    console.print(table)
    return console.export_text()


def test_word_help_in_german() -> None:
    set_language("de")
    assert word_help("G01") == "G1: Gerade mit dem Vorschub F — Gruppe 1 (modale Bewegungsbefehle), modal"
    assert word_help("G4").endswith("Gruppe 2 (nicht modale Bewegungen, Verweilzeit), nicht modal (nur dieser Satz)")
    assert word_help("G91").startswith("G91: Kettenmaßangabe (inkrementell) — Gruppe 14")
    assert word_help("G335") == "G335: Gruppe 1 (modale Bewegungsbefehle), modal"  # no meaning: the group only
    assert word_help("M30") == "M30: Programmende, wie M2"
    assert word_help("m03") == "M3: Spindel ein, Rechtslauf"
    assert word_help("$AA_IM") == "$AA_IM: Istposition einer Achse im Maschinenkoordinatensystem"
    assert "kanalspezifisches Maschinendatum" in word_help("$MC_AXCONF_GEOAX_NAME_TAB")
    assert word_help("CYCLE81").startswith("CYCLE81: Zyklus ")
    assert word_help("CYCLE81").endswith(" — CYCLE81(RTP, RFP, SDIS, DP, DPR)")
    set_language("en")
    assert word_help("G01") == "G1: straight line at the feedrate F — group 1 (modal motion commands), modal"


def test_g_functions_screen_in_german() -> None:
    """Siemens: the active code's meaning (or the group's); ISO M and T: the ISO groups' meanings,
    or with the dialect named the active ISO codes' meanings."""
    set_language("de")
    siemens = shown(all_groups_table({1: "G1", 8: "G505", 14: "G91"}))
    assert "Gerade mit dem Vorschub F" in siemens and "Kettenmaßangabe (inkrementell)" in siemens
    assert "einstellbare Nullpunktverschiebung 5" in siemens
    assert "Ebenenanwahl" in siemens  # group 6 has no active code here: the group's meaning
    assert "straight line" not in siemens
    milling = shown(all_groups_table({1: "G01", 2: "G17"}, iso_group_meanings("iso-m")))
    assert "Bewegung" in milling and "Fräserradiuskorrektur" in milling and "Sprachmodus" in milling
    turning = shown(all_groups_table({1: "G01"}, iso_group_meanings("iso-t")))
    assert "Bewegung und Drehzyklen" in turning and "Schneidenradiuskorrektur" in turning
    turning = shown(all_groups_table({1: "G01", 7: "G40"}, iso_group_meanings("iso-t"), "iso-t"))
    assert "Gerade mit Vorschub" in turning and "Schneidenradiuskorrektur aus" in turning

