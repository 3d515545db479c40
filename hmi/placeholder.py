"""The screen of an operating area that has no module in ``screens/`` yet."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.widgets import Static

from hmi.area import AreaBase
from hmi.softkeys import Softkey, SoftkeyMenu


class PlaceholderBody(Static):
    """The centred note in the content window."""


class PlaceholderScreen(AreaBase):
    """Stands in for an area: the frame works (header, keys), the content says it is missing."""

    def __init__(self, area_id: str, title: str, problem: str = "") -> None:
        super().__init__(id=f"area-{area_id}")
        self.problem = problem
        self.AREA_ID = area_id  # type: ignore[misc]
        self.AREA_TITLE = title  # type: ignore[misc]

    def compose_content(self) -> ComposeResult:
        """A note that the area is not built yet."""
        note = self.problem or "This operating area is not available in this version."
        yield PlaceholderBody(
            f"{self.AREA_TITLE}\n\n{note}\n"
            "Alt+M returns to the Machine area; F9 shows the area menu; F11 lists the keys.",
        )

    def softkey_menu(self) -> SoftkeyMenu:
        """Only the way back to the Machine area."""
        return SoftkeyMenu.of(
            [Softkey("placeholder.machine", "Machine", "app.switch_area('machine')")]
        )
