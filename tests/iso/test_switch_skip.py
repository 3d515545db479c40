"""A skip level ``/n`` in the middle of an ISO block is decided when the block runs (item 4)."""

from __future__ import annotations

from nck.iso.dialect import dialect_for
from nck import canon
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.iso.skipping import mid_block_skip
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.iso.conftest import ends, run_iso


def test_level_active_drops_the_rest_even_if_it_would_not_translate():
    result = run_iso("N5 G00 X100. /3 YY100\nM30\n", skip_levels=frozenset({3}))
    assert result.status == "ended", result.alarms
    assert ends(result) == [(1, {"X": 100.0, "Y": 0.0, "Z": 0.0})]


def test_level_off_runs_the_whole_block_and_its_alarm():
    result = run_iso("N5 G00 X100. /3 YY100\nM30\n")
    assert result.status == "alarm" and result.alarms[0].number == 12080
    assert result.segments == []


def test_level_decides_which_words_run():
    """Digest iso-milling-828d rank 5 (/ and /1 are independent switches)."""
    text = "G00 X10. /2 Y20.\nM30\n"
    assert ends(run_iso(text, skip_levels=frozenset({2})))[0][1] == {"X": 10.0, "Y": 0.0, "Z": 0.0}
    assert ends(run_iso(text))[0][1] == {"X": 10.0, "Y": 20.0, "Z": 0.0}
    assert ends(run_iso(text, skip_levels=frozenset({3})))[0][1]["Y"] == 20.0


def test_bare_slash_is_level_zero():
    text = "G00 X1. / Y1.\nM30\n"
    assert ends(run_iso(text, skip_levels=frozenset({0})))[0][1]["Y"] == 0.0
    assert ends(run_iso(text))[0][1]["Y"] == 1.0


def test_switch_read_at_run_time_in_one_loaded_program():
    interp = Interpreter(load_machine(None), MemorySource(), NcData(), dialect=dialect_for("iso-m", load_machine(None)))
    interp.start_text("T.MPF", "G00 X1. /1 Y1.\nX2. /1 Y2.\nM30\n")
    ends_seen = []
    while not interp.finished:
        for command in interp.step().commands:
            if isinstance(command, canon.Motion):
                ends_seen.append((command.end_wcs["X"], command.end_wcs["Y"]))
                interp.skip_levels = frozenset({1})  # the operator switches /1 on
    assert ends_seen == [(1.0, 1.0), (2.0, 1.0)]


def test_slash_in_a_comment_or_at_the_start_is_not_mid_block():
    assert mid_block_skip("X100. ( /3 ) Y100") is None
    assert mid_block_skip("/2 X1. Y1.") is None
    assert mid_block_skip("N5 X1. /3 Y1.") == (3, "N5 X1. ")


def test_modal_state_follows_the_whole_block():
    text = "G00 X1. /4 G91\nX1.\nM30\n"
    assert [p["X"] for _line, p in ends(run_iso(text))] == [1.0, 2.0]
    assert [p["X"] for _line, p in ends(run_iso(text, skip_levels=frozenset({4})))] == [1.0, 1.0]
