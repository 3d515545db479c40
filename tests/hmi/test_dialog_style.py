"""One dialog style (issue 18): an overlay that keeps the header and the alarm line in view,
cancelled with Escape, and never left pending in an area the operator has left.

Keys are sent as bursts (:func:`tests.burst.burst`).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hmi.area import AreaBase
from hmi.dialog import AreaDialog

from tests.burst import burst
from tests.parameter_setup.conftest import SIZE, trainer

HEADER_LINES = 3
"""State line, alarm line, program line: a dialog never covers them."""

DIALOGS = {
    "reset_po": ("alt+s", "f8"),                       # Setup: Reset (po) question
    "new_program": ("alt+n", "f2"),                    # Program manager: New program name
    "new_tool": ("alt+o", "shift+f1"),                 # Parameter: New tool
    "help": ("alt+m", "f11"),                          # key help
    "select_program": ("alt+m", "alt+u", "f7"),        # AUTO: program selection list
}


@pytest.mark.parametrize("dialog", sorted(DIALOGS))
async def test_dialog_is_an_overlay_below_the_header_and_escape_cancels(tmp_path: Path, dialog: str) -> None:
    """The header stays in view around the dialog; Escape closes it without a result."""
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", *DIALOGS[dialog])
        top = app.screen
        assert isinstance(top, AreaDialog), top
        assert top.styles.background.a < 1  # the area shows through, dimmed
        box = top.children[0]
        assert box.region.y >= HEADER_LINES
        await burst(pilot, "escape")
        assert isinstance(app.screen, AreaBase)


async def test_dialog_is_not_pending_after_leaving_the_area(tmp_path: Path) -> None:
    """Reset (po) opened by accident, then another area: coming back shows no question."""
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+s", "f8", "alt+m", "alt+s")
        assert isinstance(app.screen, AreaBase) and app.current_mode == "setup"
        await burst(pilot, "y")  # a Y now answers nothing
        assert app.bridge.status.channel.channel_state == "reset"
