"""The pure parts of the Diagnostics views: alarm rows, filter, export, service rows, plot."""

from __future__ import annotations

import csv
import io

import pytest
from hypothesis import given, settings, strategies as st

from nck.persistence import ALARM_LOG_LIMIT, Session, alarm_entry_from_dict
from nck.status import AlarmEntry
from hmi.alarm_times import AlarmTimes
from hmi import utilisation
from hmi.bridge import NckBridge
from hmi.utilisation import UtilisationMeter
from hmi.widgets.plot import format_value, render_curves, value_range
from tests.diagnostics.conftest import kernel
from screens.diagnostics_alarms import (
    LogFilter, alarm_list_rows, clock_text, log_as_csv, log_rows, parse_filter, source_text,
)


def entry(seq: int, number: int, text: str = "text", **kwargs) -> AlarmEntry:
    values = dict(category="axis", clear="reset", came_s=float(seq))
    values.update(kwargs)
    return AlarmEntry(seq=seq, number=number, text=text, **values)


def test_clock_text() -> None:
    assert clock_text(0.0) == "00:00:00.00"
    assert clock_text(3725.456) == "01:02:05.46"
    assert clock_text(None) == ""


def test_alarm_list_newest_first_and_sources() -> None:
    rows = alarm_list_rows([entry(1, 10720, file="P.MPF", n=10), entry(3, 10621, params=("1", "X", "+")),
                            entry(2, 3000, category="nck")])
    assert [r.number for r in rows] == [10621, 3000, 10720]
    assert source_text(rows[0]) == "channel 1 axis X"
    assert source_text(rows[1]) == "NCK"
    assert source_text(rows[2]) == "P.MPF N10"


@pytest.mark.parametrize("typed, expected", [
    ("", LogFilter()),
    ("10720", LogFilter(10720, 10720, "")),
    ("10000-19999", LogFilter(10000, 19999, "")),
    ("-20000", LogFilter(None, 20000, "")),
    ("20000-", LogFilter(20000, None, "")),
    ("10000-19999 limit switch", LogFilter(10000, 19999, "limit switch")),
    ("limit", LogFilter(None, None, "limit")),
    ("G17-plane", LogFilter(None, None, "G17-plane")),
])
def test_parse_filter(typed: str, expected: LogFilter) -> None:
    assert parse_filter(typed) == expected


def test_reversed_range_is_refused() -> None:
    with pytest.raises(ValueError):
        parse_filter("30000-20000")


@settings(max_examples=60, deadline=None)
@given(numbers=st.lists(st.integers(1, 99999), max_size=30), low=st.integers(1, 99999), span=st.integers(0, 50000))
def test_filter_keeps_exactly_the_range(numbers: list[int], low: int, span: int) -> None:
    history = [entry(i + 1, n) for i, n in enumerate(numbers)]
    rows = log_rows(history, parse_filter(f"{low}-{low + span}"))
    assert [r.number for r in rows] == [n for n in reversed(numbers) if low <= n <= low + span]


def test_log_rows_skip_messages_and_csv_export() -> None:
    history = [entry(1, 10720, went_s=2.5), entry(2, 0, category="message"), entry(-1, 3000, clear="reset")]
    rows = log_rows(history)
    assert [r.number for r in rows] == [3000, 10720]
    times = AlarmTimes()
    times.restart({-1: {"came_at": "2026-11-25T23:59:58+00:00"},
                   1: {"came_at": "2026-11-26T00:00:01+00:00", "went_at": "2026-11-26T00:00:02+00:00"}})
    table = list(csv.reader(io.StringIO(log_as_csv(rows, times))))
    assert table[1][:4] == ["1", "2026-11-25 23:59:58", "", "3000"]  # retained from an earlier power on
    assert table[2][:5] == ["0", "2026-11-26 00:00:01", "2026-11-26 00:00:02", "10720", "reset"]


def test_retained_alarm_log_is_bounded_oldest_dropped(tmp_path) -> None:
    session = Session.open(tmp_path, install_samples=False)
    session.record_alarms(entry(i + 1, 10000 + i) for i in range(ALARM_LOG_LIMIT + 20))
    session.save()
    again = Session.open(tmp_path, install_samples=False)
    kept = [alarm_entry_from_dict(d) for d in again.alarm_log]
    assert len(kept) == ALARM_LOG_LIMIT
    assert kept[0].number == 10020 and kept[-1].number == 10000 + ALARM_LOG_LIMIT + 19


def test_utilisation_meter_divides_by_the_cycles_run(monkeypatch) -> None:
    readings = iter([0.0, 0.010, 1.0, 1.004])
    monkeypatch.setattr(utilisation, "CLOCK", lambda: next(readings))
    counts = {"cycles": 0, "blocks": 0}

    def tick(dt_s: float) -> None:
        counts["cycles"] += round(dt_s / 0.004)
        counts["blocks"] += 5

    meter = UtilisationMeter()
    for dt_s in (0.04, 0.016):  # 10 cycles in 10 ms, 4 cycles in 4 ms
        meter.measure(lambda: tick(dt_s), lambda: (counts["cycles"], counts["blocks"]))
    figures = meter.figures(0.004)
    assert figures["cycle_compute_us"] == pytest.approx(1000.0)
    assert figures["ipo_load_pct"] == pytest.approx(25.0)
    assert figures["blocks_per_s"] == pytest.approx(10 / 0.014)


def test_the_bridge_measures_each_ipo_cycle_once() -> None:
    # Nck.tick runs its cycles through Nck.step: timing both counted every cycle twice.
    nck = kernel()
    bridge = NckBridge(nck, realtime=False)
    for _ in range(10):
        bridge.advance(0.04)
    cycles = 10 * round(0.04 / nck.ipo_cycle_s)
    assert nck.cycles_done == cycles
    assert bridge.utilisation.figures(nck.ipo_cycle_s)["cycles_measured"] == cycles


def test_plot_helpers() -> None:
    assert value_range([2.0, 2.0]) == pytest.approx((1.9, 2.1))
    assert format_value(12345.678) == "12345.7" and format_value(-0.01234) == "-0.0123"
    text = render_curves([0.0, 1.0, 2.0], [[0.0, 1.0, 0.0]], 20, 4, cursor=1).plain
    lines = text.splitlines()
    assert len(lines) == 4 and all(len(line) == 20 for line in lines)
    assert any(ch not in " │" for ch in text)


def test_service_drive_rows_name_the_sinamics_signals() -> None:
    """An 828D / 840D sl drives SINAMICS (issue 18): no SIMODRIVE 611D terminal in the rows.

    The enables are the SINAMICS sequence-control words (r0898 control, r0899 status);
    the shared manuals describe only the 611D screen, so these names are our choice.
    """
    from nck.kernel import Nck
    from screens.diagnostics_service import drive_rows

    status = Nck().status()
    names = [name for name, _value, _unit in drive_rows(status, status.axes[0])]
    assert not [name for name in names if "terminal" in name.lower()], names
    shown = dict((name, value) for name, value, _unit in drive_rows(status, status.axes[0]))
    assert shown["Pulses enabled (r0899.11)"] == "yes"
    assert shown["Operation enabled (r0899.2)"] == "yes"
    assert shown["ON / OFF1 (r0898.0)"] == "yes"
