"""How the panel writes durations (``hmi.durations``): worked out by hand."""

from __future__ import annotations

import pytest

from hmi.durations import clock, short_clock


@pytest.mark.parametrize(("seconds", "decimals", "text"), [
    (0.0, 0, "00:00:00"), (59.5, 0, "00:01:00"), (3725.456, 0, "01:02:05"), (3725.456, 2, "01:02:05.46"),
    (-3.0, 2, "00:00:00.00"), (90061.0, 0, "25:01:01"),
])
def test_clock(seconds: float, decimals: int, text: str) -> None:
    assert clock(seconds, decimals) == text


@pytest.mark.parametrize(("seconds", "text"), [
    (23.14, "0:23.1"), (125.26, "2:05.3"), (3599.94, "59:59.9"), (3599.96, "1:00:00.0"),
    (60309.2, "16:45:09.2"),  # CAM_MILL's 1005 minutes 9.2 seconds
])
def test_short_clock(seconds: float, text: str) -> None:
    assert short_clock(seconds) == text
