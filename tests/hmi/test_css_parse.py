"""The panel parses each CSS source once per process (hmi.css_parse), per set of theme variables."""

from __future__ import annotations

from textual.color import Color
from textual.css.stylesheet import Stylesheet

from hmi.css_parse import share_parsed_css

CSS = "Static { color: $accent; }"


def _parsed(variables: dict[str, str]) -> Stylesheet:
    stylesheet = Stylesheet(variables=variables)
    stylesheet.add_source(CSS, ("test_css_parse", ""))
    stylesheet.parse()
    return stylesheet


def test_a_fresh_stylesheet_takes_the_rules_parsed_before() -> None:
    # Textual re-parses in a fresh Stylesheet whenever a screen brings its own CSS
    share_parsed_css()
    first, second = _parsed({"accent": "#ff0000"}), _parsed({"accent": "#ff0000"})
    assert second.rules[0] is first.rules[0]


def test_other_theme_variables_parse_again_with_their_values() -> None:
    share_parsed_css()
    red, blue = _parsed({"accent": "#ff0000"}), _parsed({"accent": "#0000ff"})
    assert red.rules[0] is not blue.rules[0]
    assert red.rules[0].styles.color == Color(255, 0, 0)
    assert blue.rules[0].styles.color == Color(0, 0, 255)


def test_sharing_is_installed_once() -> None:
    share_parsed_css()
    installed = Stylesheet._parse_rules
    share_parsed_css()
    assert Stylesheet._parse_rules is installed
