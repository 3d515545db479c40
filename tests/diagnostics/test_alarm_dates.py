"""Alarm list and alarm log show the date and time of day (issue 18).

002 L74605-74607: alarms and messages are displayed "with date and time".
The kernel counts seconds since its power on only; the HMI stamps the wall
clock when it reads an entry from the kernel's log, and the retained log keeps
the stamps, so entries of an earlier session keep their date and stay below the
new ones (newest first). The wall clock is replaced by a hand-set one; keys go
as bursts (Alt+D Alt+G on unreferenced axes: 10203, CANCEL; F12 acknowledges).
"""

from __future__ import annotations

from datetime import datetime, timedelta, timezone
from pathlib import Path

from hmi.app import make_app
from tests.burst import burst
from tests.diagnostics.conftest import SIZE

ZONE = timezone(timedelta(hours=1))


class HandClock:
    """A wall clock that shows what the test sets."""

    def __init__(self, now: datetime) -> None:
        self.now = now

    def __call__(self) -> datetime:
        return self.now


def body(app, view: str) -> str:
    return str(app.screen.query_one(f"#diag-{view}").render())


def rows_with(text: str, number: str) -> list[str]:
    """The rows that show ``number``, without the selection marker ▶ of the selected row."""
    return [row.replace("▶", " ", 1) for row in text.splitlines() if number in row]


async def test_dates_in_list_and_log_and_order_across_a_restart(tmp_path: Path) -> None:
    data_dir = str(tmp_path / "data")
    clock = HandClock(datetime(2026, 11, 25, 16, 40, 5, tzinfo=ZONE))
    app = make_app(data_dir=data_dir, realtime=False)
    app.bridge.alarm_times.clock = clock
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+d", "alt+g", "alt+a")
        assert rows_with(body(app, "alarms"), "10203")[0].split()[:2] == ["2026-11-25", "16:40:05"]
        clock.now += timedelta(minutes=1, seconds=30)
        app.bridge.advance(0.1)
        await burst(pilot, "f12")
        assert "10203" not in body(app, "alarms")
        await burst(pilot, "ctrl+q")
    clock = HandClock(datetime(2026, 11, 26, 7, 15, 0, tzinfo=ZONE))
    app = make_app(data_dir=data_dir, realtime=False)
    app.bridge.alarm_times.clock = clock
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+d", "alt+g", "alt+a")
        assert rows_with(body(app, "alarms"), "10203")[0].split()[:2] == ["2026-11-26", "07:15:00"]
        await burst(pilot, "f3")
        newest, earlier = rows_with(body(app, "log"), "10203")
        assert newest.split()[:3] == ["2026-11-26", "07:15:00", "—"]
        assert earlier.split()[:5] == ["PO-", "2026-11-25", "16:40:05", "2026-11-25", "16:41:35"]


async def test_reset_po_keeps_the_dates_of_the_earlier_entries(tmp_path: Path) -> None:
    """Reset (po) restarts the kernel on the retained data: the retained entries keep their dates."""
    clock = HandClock(datetime(2026, 11, 26, 10, 0, 0, tzinfo=ZONE))
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    app.bridge.alarm_times.clock = clock
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+d", "alt+g", "f12")
        clock.now += timedelta(minutes=5)
        assert app.power_on_reset()
        await burst(pilot, "alt+d", "alt+g", "alt+a", "f3")
        newest, earlier = rows_with(body(app, "log"), "10203")
        assert newest.split()[:3] == ["2026-11-26", "10:05:00", "—"]
        assert earlier.split()[:5] == ["PO-", "2026-11-26", "10:00:00", "2026-11-26", "10:00:00"]


async def test_logbook_shows_the_date_and_time_of_each_change(tmp_path: Path) -> None:
    """The logbook's access-level changes carry the date and time of day they were made, as the
    alarm log's entries do (002 L74605-74607), not the time since power on; newest first."""
    clock = HandClock(datetime(2026, 11, 25, 16, 40, 5, tzinfo=ZONE))
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    app.bridge.alarm_times.clock = clock
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t")
        clock.now += timedelta(minutes=2)
        await burst(pilot, "alt+t", "alt+a", "f8", "f3")
        rows = [row for row in body(app, "logbook").splitlines() if row.split()[2:3] == ["access"]]
        assert [row.split()[:2] for row in rows] == [["2026-11-25", "16:42:05"],
                                                    ["2026-11-25", "16:40:05"]]
