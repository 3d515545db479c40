"""JOG INC: every press of + / − traverses one increment, also while the last one still runs.

Keymap contract (shared/spec/keymap.md, Ctrl+Right / Ctrl+Left): "one increment in INC"
per press. Seen in tmux with INC 100: Ctrl+Right Ctrl+Right Ctrl+Left sent at once moved
X by −0.1 mm (a press during a running increment restarted it from where the axis stood,
so the rest of the earlier increment was lost); one at a time they gave +0.1 mm.
Expected values: the sum of the increments, 0.1 mm each (INC 100 x 0.001 mm).
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.kernel import Nck


def jog_presses(directions: list[int]) -> float:
    nck = Nck(referenced=True)
    start = nck.positions_mcs()["X"]
    assert nck.submit(c.SelectIncrement(100)) == c.Accepted()
    for direction in directions:  # all pressed before the axis has finished the first
        assert nck.submit(c.Jog("X", direction)) == c.Accepted()
        nck.tick(0.004)
    for _ in range(200):
        nck.tick(0.05)
    return nck.positions_mcs()["X"] - start


@pytest.mark.parametrize(("directions", "expected_mm"), [
    ([1, 1, 1], 0.3),
    ([1, 1, -1], 0.1),
    ([-1, -1], -0.2),
])
def test_increments_pressed_in_a_burst_add_up(directions: list[int], expected_mm: float) -> None:
    assert jog_presses(directions) == pytest.approx(expected_mm, abs=1e-6)
