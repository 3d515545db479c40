"""One parse of each CSS source per process, shared by every stylesheet Textual builds.

Textual keeps the rules it parsed in a small cache of each ``Stylesheet``. But every
screen that brings its own CSS (each area's ``CSS_PATH``) makes the app re-parse its
whole stylesheet in a *fresh* ``Stylesheet``, whose cache is empty: the first switch
to each area parsed all the panel's CSS again, ~0.1 s of CPU before the area appeared
(2026-11-28, first switch to an area 300 → 170 ms CPU at load 8 with this module).
A test process, which starts hundreds of panels, parsed it once per panel as well.

:func:`share_parsed_css` keeps the parsed rules of each source in one table for the
process, keyed by the CSS variables (the theme) as well as by Textual's own key, so a
theme change still parses with its new variables. Textual already hands one parse
result to every parse of a stylesheet; sharing it between stylesheets hands the rules
to code that expects them reused. Invalid CSS is not kept: it raises as before.

This replaces ``Stylesheet._parse_rules``, a private method of Textual (pinned in
pyproject.toml: a new version must be checked against it).
"""

from __future__ import annotations

from typing import Any

from textual.css.stylesheet import Stylesheet

_parsed_rules: dict[tuple[Any, ...], Any] = {}
"""Parsed rules by (CSS variables, css, origin, default rules?, tie breaker, scope)."""


def share_parsed_css() -> None:
    """Make every ``Stylesheet`` of the process look its parsed rules up in one table (once)."""
    parse_rules = Stylesheet._parse_rules
    if getattr(parse_rules, "shared", False):
        return

    def shared_parse_rules(self: Stylesheet, css: str, read_from: Any, is_default_rules: bool = False,
                           tie_breaker: int = 0, scope: str = "") -> Any:
        key = (tuple(self._variables.items()), css, read_from, is_default_rules, tie_breaker, scope)
        rules = _parsed_rules.get(key)
        if rules is None:
            rules = parse_rules(self, css, read_from, is_default_rules, tie_breaker, scope)
            _parsed_rules[key] = rules
        return rules

    shared_parse_rules.shared = True  # type: ignore[attr-defined]
    Stylesheet._parse_rules = shared_parse_rules  # type: ignore[method-assign]
