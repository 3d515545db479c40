"""The kernel-side trace recorder and the service values, on the real motion system."""

from __future__ import annotations

import pytest

from nck import commands as cmd
from nck.trace import (
    AxisTrace, TraceError, TraceRecorder, TraceSettings, available_signals, csv_column, trace_csv,
)
from tests.diagnostics.conftest import kernel, kv1_machine, limit_machine


def start(nck, program: str) -> None:
    assert nck.submit(cmd.SelectMode("AUTO")) == cmd.Accepted()
    assert nck.submit(cmd.SelectProgram(program)) == cmd.Accepted()
    assert nck.submit(cmd.CycleStart()) == cmd.Accepted()


def test_following_error_at_f1000_with_kv1_is_one_mm() -> None:
    """Kv = 1 (m/min)/mm, no feedforward: 1 m/min gives 1 mm following error (± 2 %).

    Digest 828d-1 rank 1 (002 L837-842).
    """
    nck = kernel(kv1_machine())
    start(nck, "FEED.MPF")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] < -99.9, 30.0)  # N10 done
    assert nck.run_until(lambda k: k.positions_mcs()["X"] > -90.0, 30.0)  # N20 under way
    nck.tick(0.5)
    x = nck.status().axes[0]
    assert x.velocity == pytest.approx(1000.0, rel=0.01)
    assert x.following_error == pytest.approx(1.0, rel=0.02)
    assert x.extra["kv_calculated"] == pytest.approx(1.0, rel=0.02)


def test_records_one_sample_per_ipo_cycle_for_the_duration() -> None:
    nck = kernel()
    recorder = TraceRecorder(TraceSettings(("X.position", "feed_override"), "now", 0.2), nck.machine)
    recorder.attach(nck)
    nck.tick(1.0)
    assert recorder.state == "done"
    assert recorder.sample_count == round(0.2 / nck.ipo_cycle_s)
    steps = [b - a for a, b in zip(recorder.times_s, recorder.times_s[1:])]
    assert all(s == pytest.approx(nck.ipo_cycle_s) for s in steps)
    assert set(recorder.columns["feed_override"]) == {100.0}
    assert nck.cycle_listeners == []


def test_nc_start_trigger_waits_for_the_program() -> None:
    nck = kernel()
    recorder = TraceRecorder(TraceSettings(("X.position", "X.velocity"), "nc_start", 0.5), nck.machine)
    recorder.attach(nck)
    nck.tick(0.3)
    assert recorder.state == "armed" and recorder.sample_count == 0
    start(nck, "TRACE.MPF")
    nck.tick(0.1)
    assert recorder.state == "recording"
    assert recorder.times_s[0] == pytest.approx(0.3 + nck.ipo_cycle_s)
    assert max(abs(v) for v in recorder.columns["X.velocity"]) > 0.0


def test_settings_are_checked() -> None:
    machine = limit_machine()
    with pytest.raises(TraceError, match="at most 4"):
        TraceRecorder(TraceSettings(("X.position",) * 5), machine)
    with pytest.raises(TraceError, match="unknown"):
        TraceRecorder(TraceSettings(("Q.position",)), machine)
    with pytest.raises(TraceError):
        TraceRecorder(TraceSettings(("X.position",), "later"), machine)
    with pytest.raises(TraceError):
        TraceRecorder(TraceSettings(("X.position",), "now", 0.0), machine)
    assert "SP.speed" in available_signals(machine)
    assert "X.following_error" in available_signals(machine)


def test_trace_of_x_reproduces_the_axis_trace_of_the_run() -> None:
    """The trace of X.position equals the X column of the --trace recorder (same run)."""
    nck = kernel()
    full = AxisTrace(["X", "Y", "Z"])
    full.attach(nck)
    recorder = TraceRecorder(TraceSettings(("X.position",), "nc_start", 30.0), nck.machine)
    recorder.attach(nck)
    start(nck, "TRACE.MPF")
    assert nck.run_until(lambda k: k.situation.channel == "reset", 60.0)
    recorder.detach()
    start_index = full.times_s.index(recorder.times_s[0])
    end = start_index + recorder.sample_count
    assert full.times_s[start_index:end] == recorder.times_s
    assert full.columns["X"][start_index:end] == recorder.columns["X.position"]
    assert min(recorder.columns["X.position"]) == pytest.approx(-50.0, abs=0.05)
    csv_rows = recorder.to_csv().splitlines()
    assert csv_rows[0] == "t_s,X"
    full_rows = full.to_csv().splitlines()
    assert [r.split(",")[:2] for r in full_rows[start_index + 1:end + 1]] == [r.split(",") for r in csv_rows[1:]]


def test_csv_columns_and_format() -> None:
    assert csv_column("X.position") == "X"
    assert csv_column("X.velocity") == "X_velocity_mm_min"
    assert csv_column("feed_override") == "feed_override_pct"
    assert trace_csv([0.004, 0.008], {"X": [1.0, 2.5]}) == "t_s,X\n0.004,1.000000\n0.008,2.500000\n"


def test_logbook_records_access_level_and_machine_data_changes() -> None:
    """Digest 828d-1 rank 5 (level change written to the logbook)."""
    nck = kernel()
    assert nck.submit(cmd.EnterPassword("EVENING")) == cmd.Accepted()
    assert nck.submit(cmd.WriteData("MD32000[X]", 5000)) == cmd.Accepted()
    assert nck.submit(cmd.WriteData("R1", 5)) == cmd.Accepted()  # not a machine datum: not logged
    assert nck.submit(cmd.ActivateMachineData()) == cmd.Accepted()
    assert nck.submit(cmd.DeletePassword()) == cmd.Accepted()
    assert isinstance(nck.submit(cmd.EnterPassword("wrong")), cmd.Rejected)  # a failed attempt (issue 19)
    assert [(e.kind, e.text) for e in nck.logbook] == [
        ("access", "password entered: access level 7 -> 2"),
        ("data", "MD32000[X] = 5000"),
        ("data", "machine data activated (NEW CONFIG)"),
        ("access", "password deleted: access level 2 -> 7"),
        ("access", "password not accepted (failed attempt 1)"),
    ]
    assert all("EVENING" not in e.text for e in nck.logbook)


def test_nc_start_trigger_fires_when_an_alarm_stops_the_program_at_once() -> None:
    nck = kernel()
    recorder = TraceRecorder(TraceSettings(("X.position",), "nc_start", 0.1), nck.machine)
    recorder.attach(nck)
    nck.tick(0.1)
    start(nck, "LIMIT.MPF")  # X20 is beyond the +5 mm limit: 10720 in the first cycles
    nck.tick(0.2)
    assert any(a.number == 10720 for a in nck.status().alarms)
    assert recorder.state == "done" and recorder.sample_count == 25


def test_a_finished_recorder_does_not_hide_the_next_listener() -> None:
    nck = kernel()
    short = TraceRecorder(TraceSettings(("X.position",), "now", 0.004), nck.machine)
    short.attach(nck)
    full = AxisTrace(["X"])
    full.attach(nck)
    nck.tick(0.04)
    assert short.sample_count == 1 and len(full.times_s) == 10
