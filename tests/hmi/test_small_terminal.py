"""A terminal smaller than the layout shows one clear sentence with the size needed (issue 18),
wrapped in a terminal narrower than it (an 80-column terminal cut it after "please make the").

120×36 is the tested minimum (``test_small_terminal_120x36`` shows the whole
layout at that size); below it, in width or height, the areas give way to one
line that says what is needed, and the layout comes back when the terminal grows.
"""

from __future__ import annotations

import textwrap

import pytest
from nck.kernel import Nck

from hmi.app import MIN_TERMINAL_SIZE, HmiApp


def too_small_shown(app: HmiApp) -> bool:
    """True when the area shows the size sentence, whole, instead of its windows."""
    screen = app.screen
    line = screen.query_one("#too-small")
    sentence = str(line.render())
    wrapped = textwrap.wrap(sentence, line.region.width) if line.region.width else []
    return (line.display and 1 <= len(wrapped) <= line.region.height and sentence.endswith("larger.")
            and not screen.query_one("#header").region.height)


@pytest.mark.parametrize("size", [(119, 36), (120, 35), (80, 24)])
async def test_smaller_than_the_minimum_shows_the_size_needed(size: tuple[int, int]) -> None:
    app = HmiApp(Nck(), realtime=False)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        assert too_small_shown(app)
        text = str(app.screen.query_one("#too-small").render())
        assert f"{MIN_TERMINAL_SIZE[0]} × {MIN_TERMINAL_SIZE[1]}" in text


async def test_minimum_and_growing_show_the_layout() -> None:
    app = HmiApp(Nck(), realtime=False)
    async with app.run_test(size=MIN_TERMINAL_SIZE) as pilot:
        await pilot.pause()
        assert MIN_TERMINAL_SIZE == (120, 36)
        assert not too_small_shown(app)
        await pilot.resize_terminal(100, 30)
        await pilot.pause()
        assert too_small_shown(app)
        await pilot.press("alt+o")  # another area while too small: the same line
        await pilot.pause()
        assert too_small_shown(app)
        await pilot.resize_terminal(160, 48)
        await pilot.pause()
        assert not too_small_shown(app)
