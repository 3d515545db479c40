"""Why the channel stands (the AUTO status line, the block search window) is said in the panel's
language: the reasons that are words are translated, NC STOP, M0/M1 and alarm numbers read the
same in both (issue 27; Einzelsatz is the control's German for single block, SBL)."""

from __future__ import annotations

from hmi.i18n import STOP_REASON_WORDS, stop_reason_text
from nck.program_control import SEARCH_TARGET_FOUND


def test_the_kernels_worded_reasons_are_the_ones_translated() -> None:
    assert SEARCH_TARGET_FOUND in STOP_REASON_WORDS
    assert {"single block", "alarm"} <= set(STOP_REASON_WORDS)


def test_stop_reasons_in_german(german: None) -> None:
    assert stop_reason_text("single block") == "Einzelsatz"
    assert stop_reason_text("alarm") == "Alarm"
    assert stop_reason_text(SEARCH_TARGET_FOUND) == "Suchziel gefunden"
    for reason in ("NC STOP", "M0", "M1", "10208", ""):
        assert stop_reason_text(reason) == reason


def test_stop_reasons_in_english() -> None:
    assert stop_reason_text("single block") == "single block"
