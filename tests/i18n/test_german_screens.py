"""The panel in German shows no English operator text (issue 27): a walk through the main
screens and their softkey levels finds none.

What counts as English: a word of the English texts the panel and its data tables carry
(the catalogue's ``msgid`` texts, alarm texts, machine-data titles, G-group meanings) and
a few English function words, when the German texts (``msgstr``, the overlays in
``data/lang/de``) never use it. Names the control shows as they are (machine-data and
setting-data identifiers, G codes, NC words, the ``nck setup`` field keys) are written in
capitals or with ``_ . $ [`` and are not words here; :data:`ALLOWED` lists the few proper
names and units that read like English words.
"""

from __future__ import annotations

import html
import re
import tomllib
from pathlib import Path
from typing import Any, Iterator

import pytest

from hmi.app import make_app
from nck.resources import alarm_catalog, data_path, read_table
from nck.translations import read_po
from tests.hmi.conftest import SIZE

WORD = re.compile(r"[A-Za-zÄÖÜäöüß]{2,}")
NAME_TOKEN = re.compile(r"[._$\[\]/]")
FUNCTION_WORDS = frozenset(
    "the of and or to with for on off no yes not is are be by at from into this that here there when then "
    "only all every its it has have each per out first next last new none cannot can will".split())
"""English words common in sentences, counted as English even if no catalogue text had them."""

ALLOWED = frozenset({
    "min", "rpm", "deg", "inch",  # units as the control writes them (rev/min, deg)
    "mm", "po", "re", "cf", "so",  # unit; machine-data activation (power on, reset, config, at once)
    "reset",  # the Kanal RESET state and the RESET key, as Operate writes them in German too
    "hidden",  # the instructor's switch by its `nck setup` field name (Setup ▸ Machine set-up)
    "mill", "lathe",  # the machines' names (mill3, lathe2: Diagnostics ▸ More ▸ Version)
})


def _words(text: str) -> set[str]:
    """The words of ``text`` (lower case), leaving out identifiers and words in capitals."""
    found: set[str] = set()
    for token in text.split():
        if NAME_TOKEN.search(token):
            continue
        found |= {word.lower() for word in WORD.findall(token) if not word.isupper()}
    return found


def _strings(node: Any) -> Iterator[str]:
    if isinstance(node, str):
        yield node
    elif isinstance(node, dict):
        for value in node.values():
            yield from _strings(value)
    elif isinstance(node, list):
        for value in node:
            yield from _strings(value)


def english_only_words() -> frozenset[str]:
    """Words of the English texts that no German text uses."""
    catalogue = read_po(data_path("lang", "de", "hmi.po"))
    english: set[str] = set(FUNCTION_WORDS)
    german: set[str] = set()
    for source, translation in catalogue.items():
        english |= _words(source)
        german |= _words(translation)
    for definition in alarm_catalog().values():
        english |= _words(definition.text)
    for path in sorted(data_path("md").glob("*.toml")):
        english |= {word for entry in read_table(path).get("data", []) for word in _words(entry["title"])}
    english |= {word for group in read_table(data_path("gcode", "siemens.toml"))["group"]
                for word in _words(group["meaning"])}
    for path in sorted(Path(data_path("lang", "de")).glob("*.toml")):
        for text in _strings(tomllib.loads(path.read_text(encoding="utf-8"))):
            german |= _words(text)
    return frozenset(english - german - ALLOWED)


def screen_lines(app) -> list[str]:
    """The text of the screen, one string per terminal row (from the SVG export)."""
    svg = app.export_screenshot()
    rows: dict[str, list[str]] = {}
    for y, text in re.findall(r'<text [^>]*?y="([\d.]+)"[^>]*>(.*?)</text>', svg):
        rows.setdefault(y, []).append(html.unescape(re.sub(r"<[^>]+>", "", text)).replace("\xa0", " "))
    return ["".join(parts) for _y, parts in sorted(rows.items(), key=lambda item: float(item[0]))]


WALKS: dict[str, list[list[str]]] = {
    # NC STOP in channel reset: the kernel's refusal on the message line
    "machine_jog": [["alt+m", "alt+j"], ["alt+h"], *[["alt+m", "alt+j", "f10", f"f{n}"] for n in range(1, 9)]],
    "machine_jog_windows": [["alt+m", "alt+j", "f10", f"shift+f{n}"] for n in range(1, 7)],
    "machine_mda": [["alt+m", "alt+d"], ["alt+m", "alt+d", "f10", "f4"]],
    "machine_auto": [["alt+m", "alt+u"], ["alt+m", "alt+u", "f10", "f4"],
                     ["alt+m", "alt+u", "f10", "f8"]],  # simultaneous recording, waiting for NC START
    "parameter": [["alt+o"], *[["alt+o", "f10", f"f{n}"] for n in range(1, 8)]],
    "program": [["alt+p"], ["alt+n"]],
    # the editor on ALARM_DEMO (alarm 10860 in line 5): header, check message, a greyed key at
    # keyswitch 0 (editing needs level 4), next error; at level 4 the cycle level, MCALL, back
    "program_editor": [["alt+n", "f3"], ["shift+f7"], ["shift+f1"], ["alt+t", "alt+t", "alt+t"],
                       ["shift+f7"], ["f1"], ["shift+f7"], ["f8"], ["f5"]],
    "diagnostics": [["alt+a"], *[["alt+a", "f10", f"f{n}"] for n in range(1, 8)],
                    *[["alt+a", "f10", "f8", f"f{n}"] for n in range(1, 5)]],  # More: utilisation … exercises
    "setup": [["alt+s"], *[["alt+s", "f10", f"f{n}"] for n in range(1, 7)], ["alt+s", "f6", "shift+f5"]],
}
"""Per area: the key bursts that show each screen checked (area key, then its softkeys)."""
ENGLISH_UNIT = re.compile(r"\brev/min\b|\bmm/rev\b")
"""Units written with a slash are names to the word check; these are English (German: U/min, mm/U)."""
PROGRAM_COMMENT = re.compile(r";[^▕▎│]*")
"""A comment of the program shown in the editor: the sample programs are commented in English."""


@pytest.fixture(scope="module")
def english() -> frozenset[str]:
    return english_only_words()


def test_the_check_finds_english_and_passes_german(english: frozenset[str]) -> None:
    assert _words("No program open — select a program") & english
    assert not _words("Kein Programm geöffnet  MD32000 MAX_AX_VELO  blank.size_x  G17 X Y Z") & english


@pytest.mark.parametrize("area", list(WALKS))
async def test_german_screens_show_no_english(tmp_path: Path, english: frozenset[str], area: str) -> None:
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    found: dict[str, str] = {}
    try:
        async with app.run_test(size=SIZE) as pilot:
            for keys in WALKS[area]:
                await pilot.press(*keys)
                await pilot.pause()
                await app.workers.wait_for_complete()  # the editor's check, the simulation
                await pilot.pause()
                for line in screen_lines(app):
                    if area == "program_editor":
                        line = PROGRAM_COMMENT.sub("", line)
                    if _words(line) & english or ENGLISH_UNIT.search(line):
                        found.setdefault(line.strip(), " ".join(keys))
    finally:
        app.nc_session.quit()
    assert not found, "English on the German panel:\n" + "\n".join(f"  [{keys}] {line}" for line, keys in found.items())
