"""What an xterm-like terminal (tmux, TERM=xterm-256color / screen) sends for the panel's keys.

Tests feed these bytes through the HMI's terminal parser, the way keys reach the
app outside tests. Escape is missing on purpose: alone it is only told apart from
an Alt chord by the escape delay, so tests send it as a key event.
"""

from __future__ import annotations

import string

_FUNCTION = {1: "P", 2: "Q", 3: "R", 4: "S"}
_FUNCTION_CODE = {5: 15, 6: 17, 7: 18, 8: 19, 9: 20, 10: 21, 11: 23, 12: 24}
_CURSOR = {"up": "A", "down": "B", "right": "C", "left": "D"}
_EDIT = {"insert": 2, "delete": 3, "pageup": 5, "pagedown": 6}


def _sequences() -> dict[str, str]:
    table = {f"f{n}": f"\x1bO{final}" for n, final in _FUNCTION.items()}
    table |= {f"shift+f{n}": f"\x1b[1;2{final}" for n, final in _FUNCTION.items()}
    table |= {f"f{n}": f"\x1b[{code}~" for n, code in _FUNCTION_CODE.items()}
    table |= {f"shift+f{n}": f"\x1b[{code};2~" for n, code in _FUNCTION_CODE.items() if n <= 8}
    table |= {name: f"\x1b[{final}" for name, final in _CURSOR.items()}
    table |= {f"ctrl+{name}": f"\x1b[1;5{final}" for name, final in _CURSOR.items()}
    table |= {f"alt+{name}": f"\x1b[1;3{final}" for name, final in _CURSOR.items()}  # the handwheel keys
    table |= {name: f"\x1b[{code}~" for name, code in _EDIT.items()}
    table |= {"ctrl+pageup": "\x1b[5;5~", "ctrl+pagedown": "\x1b[6;5~", "home": "\x1b[H",
              "end": "\x1b[F", "enter": "\r", "tab": "\t", "shift+tab": "\x1b[Z",
              "backspace": "\x7f", "space": " "}
    table |= {f"alt+{letter}": f"\x1b{letter}" for letter in string.ascii_lowercase}
    table |= {f"alt+shift+{letter}": f"\x1b{letter.upper()}" for letter in string.ascii_lowercase}
    table |= {f"ctrl+shift+{name}": f"\x1b[1;6{final}" for name, final in _CURSOR.items()}  # browser-safe keys
    table |= {f"ctrl+{letter}": chr(ord(letter) - 96) for letter in "cfpqsuvz"}
    return table


TERMINAL_BYTES: dict[str, str] = _sequences()
"""Key name → the bytes the terminal sends (printable characters stand for themselves)."""


def terminal_bytes(key: str) -> str | None:
    """The terminal's bytes for a key name or one printable character; None for Escape."""
    if len(key) == 1:
        return key
    return TERMINAL_BYTES.get(key)
