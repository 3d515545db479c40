"""The HMI's colour themes: the dark SINUMERIK-like default, an Operate-like light one, and a
high-contrast one for projectors (chosen with the palette's Theme command).

Each theme sets Textual's base colours and the HMI's own variables (``$softkey-background``,
``$softkey-foreground``, ``$alarm-user`` …: the style sheets use no fixed colour that one of the
themes could not read);
colours written into widgets' Rich styles (tool path, block display) stay as they are.
"""

from __future__ import annotations

from textual.theme import Theme

from hmi.i18n import N_

SINUMERIK_THEME = Theme(
    name="sinumerik",
    primary="#f39200",  # orange: active softkeys, focus, the selected block
    secondary="#5b7a99",
    accent="#f39200",
    foreground="#e8edf2",
    background="#16222e",  # dark blue-grey desk
    surface="#1f3042",  # window panels
    panel="#2b4157",  # softkeys, headers of windows
    warning="#f39200",
    error="#d7262b",
    success="#3fa34d",
    dark=True,
    variables={
        "softkey-background": "#3a5673",
        "softkey-foreground": "#ffffff",
        "alarm-user": "#c9a227",
        "softkey-disabled": "#6c7a88",
        "header-background": "#0f1a24",
        "alarm-red": "#d7262b",
        "alarm-orange": "#f39200",
        "block-current": "#f39200",
    },
)
"""The default theme of the HMI."""

OPERATE_LIGHT_THEME = Theme(
    name="operate-light",
    primary="#d46f00",  # orange, darkened to read on grey
    secondary="#2f5f8a",
    accent="#d46f00",
    foreground="#1b1f23",
    background="#d9dee3",  # light grey desk, as Operate's newer screens
    surface="#eef1f4",
    panel="#b7c3cf",
    warning="#b35c00",
    error="#c0161b",
    success="#2e7d32",
    dark=False,
    variables={
        "softkey-background": "#a9b8c7",
        "softkey-foreground": "#111820",
        "alarm-user": "#e0b400",
        "softkey-disabled": "#7d8894",
        "header-background": "#2f5f8a",
        "alarm-red": "#c0161b",
        "alarm-orange": "#c46a00",  # black text on it: contrast 5.4 (4.45 with #b35c00)
        "block-current": "#d46f00",
    },
)
"""Light grey panels with dark text, for bright rooms."""

HIGH_CONTRAST_THEME = Theme(
    name="high-contrast",
    primary="#ffff00",
    secondary="#00ffff",
    accent="#ffff00",
    foreground="#ffffff",
    background="#000000",
    surface="#000000",
    panel="#1c1c1c",
    warning="#ffff00",
    error="#ff3030",
    success="#00ff00",
    dark=True,
    variables={
        "softkey-background": "#303030",
        "softkey-foreground": "#ffffff",
        "alarm-user": "#ffd700",
        "softkey-disabled": "#8a8a8a",
        "header-background": "#000000",
        "alarm-red": "#ff3030",
        "alarm-orange": "#ffff00",
        "block-current": "#ffff00",
    },
)
"""White on black with yellow highlights, for projectors."""

HMI_THEMES: tuple[Theme, ...] = (SINUMERIK_THEME, OPERATE_LIGHT_THEME, HIGH_CONTRAST_THEME)
"""The themes offered by the palette's Theme command, the default first."""

THEME_LABELS: dict[str, str] = {
    SINUMERIK_THEME.name: N_("Dark\n(default)"),
    OPERATE_LIGHT_THEME.name: N_("Light"),
    HIGH_CONTRAST_THEME.name: N_("High\ncontrast"),
}
"""The softkey labels of the themes in Setup ▸ Password ▸ Change theme."""
