"""A message belongs to its area and its cause (issue 18).

A refused value in the tool list must not stay on the work offsets view or
appear in another area. Keys are sent as bursts (:func:`tests.burst.burst`).
"""

from __future__ import annotations

from pathlib import Path

from nck import commands as cmd

from tests.burst import burst
from tests.parameter_setup.conftest import SIZE, fill, trainer


def dialog_line(app) -> str:
    """The dialog line of the area on display."""
    return str(app.area_screen.query_one("#dialog-line").render())


async def test_refusal_in_tool_list_leaves_with_its_view_and_stays_in_its_area(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+o")
        app.submit(cmd.WriteData("$TC_DP6[1,1]", float("inf")))  # what the radius cell sends
        await pilot.pause()
        assert "$TC_DP6" in dialog_line(app)
        await burst(pilot, "alt+m")
        assert "$TC_DP6" not in dialog_line(app)  # not the Machine area's message
        await burst(pilot, "alt+o")
        assert "$TC_DP6" in dialog_line(app)  # still the tool list's
        await burst(pilot, "f3")  # work offsets: the cause is not on screen any more
        assert "$TC_DP6" not in dialog_line(app)


async def test_refused_softkey_message_goes_when_the_keyswitch_gives_the_level(tmp_path: Path) -> None:
    """'New tool: needs access level 4' goes once the keyswitch is turned to level 4.

    Seen in tmux: the refusal stayed on the dialog line while the New tool dialog,
    opened at level 4 in the same burst, was already on screen.
    """
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+o", "shift+f1")
        assert "needs access level 4" in dialog_line(app)
        await burst(pilot, "alt+t", "alt+t", "alt+t")
        assert "needs access level" not in dialog_line(app)
