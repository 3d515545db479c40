"""The SINUMERIK-like colour theme: dark blue/grey panels, orange and white highlights."""

from __future__ import annotations

from textual.theme import Theme

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
        "softkey-disabled": "#6c7a88",
        "header-background": "#0f1a24",
        "alarm-red": "#d7262b",
        "alarm-orange": "#f39200",
        "block-current": "#f39200",
    },
)
"""The default (and only) theme of the HMI."""
