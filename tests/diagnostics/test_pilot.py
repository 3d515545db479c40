"""Pilot tests of the Diagnostics area on the real kernel and motion system."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as cmd
from nck.cli import main as cli_main
from nck.trace import AxisTrace
from hmi.widgets.header import AreaHeader
from hmi.widgets.plot import TracePlot
from screens.diagnostics import DiagnosticsScreen
from tests.diagnostics.conftest import PROGRAMS, SIZE, app_on, kernel, kv1_machine, power_off, power_on


def body(app, view: str) -> str:
    """The plain text of a view's window."""
    widget = app.screen.query_one(f"#diag-{view}")
    return str(widget.render())


def key_for(app, action: str) -> str:
    """The first key the keymap binds to ``action`` (``reset``, ``alarm_cancel``, ``switch_area('diagnostics')``)."""
    binding = next(b for b in app.keymap.bindings if b.action == action)
    return binding.keys.split(",")[0].strip()


def header_alarm(app) -> str:
    return str(app.screen.query_one(AreaHeader).query_one("#hdr-alarm").render())


async def open_diagnostics(pilot) -> DiagnosticsScreen:
    await pilot.press(key_for(pilot.app, "switch_area('diagnostics')"))
    await pilot.pause()
    screen = pilot.app.screen
    assert isinstance(screen, DiagnosticsScreen)
    return screen


async def advance(pilot, seconds: float) -> None:
    pilot.app.bridge.advance(seconds)
    await pilot.pause()


async def test_software_limit_in_jog_listed_and_cleared_by_itself_then_logged_after_restart(tmp_path: Path) -> None:
    session, nck = power_on(tmp_path)
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        nck.submit(cmd.SelectIncrement(10000))
        for _ in range(2):  # the first step stops at +5 mm, the second one raises 10621
            app.submit(cmd.Jog("X", 1))
            await advance(pilot, 0.05)
            app.submit(cmd.Jog("X", 0))
            await advance(pilot, 4.0)
        await open_diagnostics(pilot)
        assert "10621" in header_alarm(app)
        listed = body(app, "alarms")
        assert "10621" in listed and "axis X stands at software limit switch +" in listed
        assert "channel 1 axis X" in listed
        app.submit(cmd.Jog("X", -1))  # leaving the limit clears it (CLEARHIMSELF)
        await advance(pilot, 0.05)
        app.submit(cmd.Jog("X", 0))
        await advance(pilot, 4.0)
        assert "10621" not in body(app, "alarms")
        assert "No active alarms" in body(app, "alarms")
    power_off(session, nck)

    session, nck = power_on(tmp_path)  # restart on the same data directory
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        await open_diagnostics(pilot)
        await pilot.press("f3")
        await pilot.pause()
        log = body(app, "log")
        assert "PO-" in log and "10621" in log and "software limit switch" in log
        assert "No active alarms" in body(app, "alarms")  # nothing of the alarm handler survives power on


async def test_software_limit_in_auto_cleared_by_reset_and_in_the_log(tmp_path: Path) -> None:
    nck = kernel()
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("LIMIT.MPF"), cmd.CycleStart()):
            assert app.submit(command) == cmd.Accepted()
        await advance(pilot, 1.0)
        screen = await open_diagnostics(pilot)
        assert "10720" in header_alarm(app)
        assert "10720" in body(app, "alarms") and "LIMIT.MPF N10" in body(app, "alarms")
        await pilot.press(key_for(pilot.app, "alarm_cancel"))  # CANCEL does not clear a RESET alarm
        await pilot.pause()
        assert "10720" in body(app, "alarms")
        await pilot.press(key_for(pilot.app, "reset"))
        await pilot.pause()
        assert "10720" not in body(app, "alarms")
        await pilot.press("f3")
        await pilot.pause()
        assert screen.view == "log"
        log = body(app, "log")
        assert "10720" in log and "would pass software limit switch" in log
        # filter by number range, by text, and a range that excludes it
        assert screen.apply_filter("10000-10999 software")
        assert "1 of 1 entries" in body(app, "log")
        assert screen.apply_filter("20000-29999")
        assert "0 of 1 entries" in body(app, "log")
        assert not screen.apply_filter("30000-20000")
        screen.export_dir = tmp_path
        screen.action_clear_filter()
        await pilot.press("shift+f3", "shift+f4")
        await pilot.pause()
        csv_text = (tmp_path / "alarm_log.csv").read_text()
        assert csv_text.splitlines()[0] == "earlier_power_on,come,go,number,clear,text,source"
        assert ",10720,reset," in csv_text
        assert "10720" in (tmp_path / "alarm_log.txt").read_text()


async def test_cancel_alarm_acknowledged_by_f12() -> None:
    nck = kernel()
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        nck.raise_alarm(__import__("nck.errors", fromlist=["NcAlarmError"]).NcAlarmError(10763, "N10"))
        await advance(pilot, 0.01)
        await open_diagnostics(pilot)
        assert "10763" in body(app, "alarms") and "✕" in body(app, "alarms")
        await pilot.press("shift+f1")  # the vertical softkey does what F12 does
        await pilot.pause()
        assert "10763" not in body(app, "alarms")


async def test_service_axis_shows_one_mm_following_error_at_f1000_with_kv1() -> None:
    nck = kernel(kv1_machine())
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("FEED.MPF"), cmd.CycleStart()):
            app.submit(command)
        app.bridge.run_until(lambda s: s.axes[0].position_mcs < -99.9, max_s=30.0)
        app.bridge.run_until(lambda s: s.axes[0].position_mcs > -90.0, max_s=30.0)
        await advance(pilot, 0.5)
        screen = await open_diagnostics(pilot)
        await pilot.press("f5")
        await pilot.pause()
        rows = {line[:49].strip(): line[49:].split() for line in body(app, "axis").splitlines()}
        kernel_fe = nck.status().axes[0].following_error
        assert float(rows["Following error"][0]) == pytest.approx(1.0, rel=0.02)
        assert float(rows["Following error"][0]) == pytest.approx(kernel_fe, abs=0.0005)
        assert float(rows["Servo gain factor (calculated)"][0]) == pytest.approx(1.0, rel=0.02)
        assert rows["Controller mode"][:3] == ["0", "position", "control"]
        await pilot.press("shift+f1")  # Axis +
        await pilot.pause()
        assert "Axis Y" in body(app, "axis")
        await pilot.press("f6")
        await pilot.pause()
        assert "Drive of Y" in body(app, "drive") and "Motor temperature" in body(app, "drive")
        assert screen.axis_index == 1


async def test_trace_of_x_on_the_screen_reproduces_nck_run_trace(tmp_path: Path) -> None:
    nck = kernel()
    full = AxisTrace(["X", "Y", "Z"])
    full.attach(nck)
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_diagnostics(pilot)
        await pilot.press("f7")
        await pilot.pause()
        await pilot.press("shift+f3", "shift+f4", "shift+f4", "shift+f4")  # on NC START, 10 s
        await pilot.press("shift+f5")
        await pilot.pause()
        assert screen.trace.recorder.state == "armed"
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("TRACE.MPF"), cmd.CycleStart()):
            app.submit(command)
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30.0)
        await advance(pilot, 0.01)
        recorder = screen.trace.recorder
        assert recorder.sample_count > 100
        plot = screen.query_one(TracePlot)
        assert len(plot.times) == recorder.sample_count
        await pilot.press("shift+f8")
        await pilot.pause()
        assert plot.cursor > 0 and plot.readout().startswith(f"t = {recorder.times_s[plot.cursor]:.3f} s")
        before = plot.cursor
        await pilot.press("right", "right", "left")
        assert plot.cursor == before + max(1, recorder.sample_count // 100)
        screen.export_dir = tmp_path
        await pilot.press("shift+f6")
        await pilot.pause()
    exported = (tmp_path / "trace.csv").read_text().splitlines()
    # the same program through the headless command line: nck run --trace
    program = tmp_path / "TRACE.MPF"
    program.write_text(PROGRAMS["TRACE.MPF"])
    assert cli_main(["run", str(program), "--trace", str(tmp_path / "cli.csv")]) == 0
    cli_rows = (tmp_path / "cli.csv").read_text().splitlines()
    assert cli_rows[0].split(",")[:2] == exported[0].split(",")
    compared = min(len(cli_rows), len(exported))
    assert compared > 0.9 * len(cli_rows)
    for ours, theirs in zip(exported[1:compared], cli_rows[1:compared]):
        t_ours, x_ours = (float(v) for v in ours.split(","))
        t_theirs, x_theirs = (float(v) for v in theirs.split(",")[:2])
        assert t_ours == pytest.approx(t_theirs, abs=1e-9) and x_ours == pytest.approx(x_theirs, abs=1e-6)
    reference = full.to_csv().splitlines()
    first = reference.index(next(r for r in reference if r.startswith(exported[1].split(",")[0] + ",")))
    assert exported[0] == "t_s,X"
    assert exported[1:] == [",".join(r.split(",")[:2]) for r in reference[first:first + len(exported) - 1]]


async def test_every_view_renders_and_softkeys_switch(tmp_path: Path) -> None:
    nck = kernel()
    app = app_on(nck)
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_diagnostics(pilot)
        for key, view in (("f2", "messages"), ("f3", "log"), ("f4", "overview"), ("f5", "axis"),
                          ("f6", "drive"), ("f7", "trace")):
            await pilot.press(key)
            await pilot.pause()
            assert screen.view == view
        await pilot.press("f8", "f1")
        await pilot.pause()
        assert screen.view == "utilisation"
        await advance(pilot, 1.0)  # the figures are redrawn once a second of control time
        assert "IPO cycle load" in body(app, "utilisation")
        assert "250" in body(app, "utilisation")  # 1 s = 250 IPO cycles of 4 ms
        app.submit(cmd.SetKeyswitch(3))
        await pilot.press("f3")
        await pilot.pause()
        logbook = body(app, "logbook")
        assert "keyswitch position 3: access level 7 -> 4" in logbook
        assert "Current access level: 4" in logbook
        await pilot.press("f2")
        await pilot.pause()
        assert "mill" in body(app, "version").lower()
        await pilot.press("f10", "f10")
        await pilot.pause()
        assert screen.view == "alarms"


async def test_alarm_log_survives_a_restart_of_the_app_on_its_data_dir(tmp_path: Path) -> None:
    """``hmi --data-dir``: a 10720 in AUTO is in the log after quitting and starting again."""
    from hmi.app import make_app

    program = tmp_path / "OVER.MPF"
    program.write_text("N10 G90 G1 X600 F2000\nN20 M30\n")  # X's plus limit is 500 mm
    data_dir = tmp_path / "data"
    app = make_app(data_dir=str(data_dir), program=str(program), realtime=False)
    nck = app.bridge.nck
    for axis in nck.machine.path_axes:
        nck.motion.set_referenced(axis, True)
    async with app.run_test(size=SIZE) as pilot:
        app.submit(cmd.SelectMode("AUTO"))
        app.submit(cmd.CycleStart())
        await advance(pilot, 0.5)
        await open_diagnostics(pilot)
        assert "10720" in header_alarm(app) and "10720" in body(app, "alarms")
        await pilot.press(key_for(app, "reset"))
        await pilot.pause()
        assert "No active alarms" in body(app, "alarms")
        await pilot.press(key_for(app, "quit_hmi"))
    app = make_app(data_dir=str(data_dir), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await open_diagnostics(pilot)
        assert "No active alarms" in body(app, "alarms")
        await pilot.press("f3")
        await pilot.pause()
        log = body(app, "log")
        line = next(row for row in log.splitlines() if "10720" in row).replace("▶", " ", 1)
        assert line.split()[0] == "PO-" and "would pass software limit switch" in line
        assert line.split()[2] != "—"  # it went (RESET) before the restart
