"""Every theme keeps the panel readable (issue 27): no fixed colour in the style sheets that a
theme cannot read, text on softkeys and on the header's alarm line with enough contrast.

Contrast as the WCAG defines it (relative luminance of sRGB; 4.5:1 for normal text), computed
here independently of Textual's colour code.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hmi.theme import HMI_THEMES

STYLE_SHEETS = sorted(Path(__file__).resolve().parents[2].glob("*/*.tcss"))


def luminance(hex_colour: str) -> float:
    channels = [int(hex_colour[i:i + 2], 16) / 255 for i in (1, 3, 5)]
    linear = [c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]
    return 0.2126 * linear[0] + 0.7152 * linear[1] + 0.0722 * linear[2]


def contrast(one: str, other: str) -> float:
    light, dark = sorted((luminance(one), luminance(other)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


@pytest.mark.parametrize("theme", HMI_THEMES, ids=lambda theme: theme.name)
def test_softkey_and_alarm_line_text_readable(theme) -> None:
    colours = theme.variables
    assert contrast(colours["softkey-foreground"], colours["softkey-background"]) >= 4.5
    assert contrast("#000000", colours["alarm-user"]) >= 4.5  # user alarm: black text
    assert contrast("#000000", colours["alarm-orange"]) >= 4.5


def test_style_sheets_take_the_softkey_and_user_alarm_colours_from_the_theme() -> None:
    """The rules whose fixed colour broke the light theme use theme variables."""
    assert STYLE_SHEETS
    sheet = (Path(__file__).resolve().parents[2] / "hmi" / "hmi.tcss").read_text()
    rule = re.search(r"^SoftkeyCell \{(.*?)\}", sheet, re.S | re.M).group(1)
    assert "color: $softkey-foreground;" in rule
    rule = re.search(r"^#hdr-alarm\.-alarm-user \{(.*?)\}", sheet, re.S | re.M).group(1)
    assert "background: $alarm-user;" in rule
    for path in STYLE_SHEETS:
        assert not re.search(r"#[0-9a-fA-F]{3,6}\b\s*;", path.read_text()), path.name
