"""What an operating area may ask of the app: the :class:`AreaHost` protocol.

Areas (``hmi.area.AreaBase`` and the screens) see the app only through this
protocol, so the area layer does not import the app module: the app imports the
areas, never the other way round.
"""

from __future__ import annotations

from typing import Any, Callable, Protocol

from nck.commands import SubmitResult
from nck.status import NckStatus

from hmi.bridge import NckBridge
from hmi.keymap import Keymap
from hmi.program_lines import ProgramLines


class AreaHost(Protocol):
    """The app as an area sees it."""

    bridge: NckBridge
    """The one door to the kernel: ``query`` for reading, ``submit`` for commands."""
    latest_status: NckStatus | None
    hint: str
    single_block_type: str
    rapid_overlay: bool
    exercise_side: str
    """The exercise side window's text ("" while no exercise runs)."""
    keymap: Keymap
    """The key table (``data/keymap.toml``)."""

    @property
    def selected_axis(self) -> str | None:
        """The axis the + / − keys traverse (None when none can be)."""

    def submit(self, command: Any) -> SubmitResult:
        """Send an operator command through the bridge."""

    def set_hint(self, text: str) -> None:
        """Write ``text`` on the dialog line of the current area."""

    def exercise_key(self, key: str) -> None:
        """Record ``key`` in the running exercise (nothing while none runs)."""

    def start_exercise(self, exercise: Any) -> str:
        """Run the panel on ``exercise``'s private set-up; return what to tell the trainee."""

    def end_exercise(self) -> str:
        """End the exercise: report written, the trainee's own data back; return what to say."""

    def exercise_list(self) -> list[Any]:
        """The exercises to choose from: shipped and imported with class packs."""

    def import_class_pack(self, path: str) -> str:
        """Import the class pack ``path`` into the trainee's data directory; return what to say."""

    def select_language(self, code: str) -> str:
        """Show the operator texts in language ``code``; return what to say ("" when nothing)."""

    def power_on_reset(self) -> bool:
        """Reset (po): restart the kernel on the NC data; False without a data directory."""

    def program_names(self) -> list[str]:
        """The part programs the kernel can select."""

    def program_text(self, name: str) -> ProgramLines | None:
        """The lines of a part program, or None."""

    def show_alarm_help(self, number: int, text: str = "") -> None:
        """Open the help of alarm ``number`` (``text``: as displayed, with its values)."""

    def push_screen(self, screen: Any, callback: Callable[[Any], object] | None = None) -> Any:
        """Open ``screen`` (a dialog) over the current area."""
