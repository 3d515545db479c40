"""The dry run feed table of SD42101 (002 L18155-18178), digest 828d-2 rank 16."""

from __future__ import annotations

import pytest

from nck.motion.dry_run import DryRun


@pytest.mark.parametrize(("mode", "programmed", "expected"), [
    (0, 500.0, 2000.0), (0, 3000.0, 3000.0),  # the larger of F and SD42100 (L18159-18163)
    (1, 500.0, 500.0), (1, 3000.0, 2000.0),  # the smaller (L18165-18167)
    (2, 500.0, 2000.0), (2, 3000.0, 2000.0),  # SD42100 whatever F is (L18169)
    (10, 500.0, 2000.0), (11, 3000.0, 2000.0), (12, 500.0, 2000.0),  # as 0, 1, 2 outside threads
])
def test_dry_run_feed_by_mode(mode: int, programmed: float, expected: float) -> None:
    assert DryRun(2000.0, mode).feed_for("G1", programmed) == expected


@pytest.mark.parametrize("kind", ["G33", "G34", "G35", "G331", "G332", "G63"])
def test_modes_10_to_12_run_threads_and_tapping_as_programmed(kind: str) -> None:
    """L18170-18178: with 10, 11, 12 thread cutting and tapping keep the programmed feed;
    with 0, 1, 2 they take the dry run feed too (L18151-18153 names G33, G34, G35)."""
    for mode in (10, 11, 12):
        assert DryRun(2000.0, mode).feed_for(kind, 500.0) == 500.0
    assert DryRun(2000.0, 2).feed_for(kind, 500.0) == 2000.0


def test_rapid_traverse_is_not_a_dry_run_feed() -> None:
    """L18151-18153: only the feeds of G1, G2, G3, G33 … are replaced; G0 keeps its rapid."""
    assert DryRun(2000.0, 2).feed_for("G0", None) is None
