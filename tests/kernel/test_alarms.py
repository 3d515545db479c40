"""The alarm server: catalogue, parameters, clear criteria, log, messages, user alarms."""

from __future__ import annotations

from nck import commands as c
from nck.alarms import ACTIVE_LIMIT, AlarmServer
from nck.resources import alarm_catalog
from tests.kernel.helpers import alarm_numbers, auto_start, make_nck, states, until_state


def test_catalogue_has_the_channel_alarms_with_criteria_and_reactions() -> None:
    catalog = alarm_catalog()
    assert catalog[3000].clear == "reset" and "emergency_stop" in catalog[3000].reactions
    assert catalog[10208].clear == "nc_start"
    assert catalog[10203].clear == "cancel"
    assert catalog[1].clear == "power_on"


def test_10203_disables_nc_start() -> None:
    """NC START with unreferenced axes "will have no effect" and raises 10203 (002 L20829-20833);
    the machine datum behind it is MD20700 "NC start disable without reference point" (002 L26423).
    Its reaction is the NC start disable; the next NC START clears it first (CANCEL alarms go with
    NC START), so once the axes are referenced the program starts."""
    definition = alarm_catalog()[10203]
    assert definition.reactions == ("nc_start_disable",)
    assert definition.help_source == "002 L20829-20833"


def test_raise_fills_channel_and_block_parameters() -> None:
    server = AlarmServer()
    entry = server.raise_alarm(10203, ("Z",), now_s=1.5)
    assert entry.params == ("1", "Z")
    assert "Channel 1" in entry.text and "Z" in entry.text
    assert entry.came_s == 1.5
    user = server.raise_alarm(65000, (), now_s=2.0, block="N20")  # a user alarm not in the catalogue
    assert user.params[:2] == ("1", "N20") and "65000" in user.text


def test_same_alarm_is_not_raised_twice() -> None:
    server = AlarmServer()
    server.raise_alarm(10203, ("X",), now_s=0.0)
    server.raise_alarm(10203, ("X",), now_s=1.0)
    assert len(server.active) == 1
    server.raise_alarm(10203, ("Y",), now_s=1.0)
    assert len(server.active) == 2


def test_clear_criteria() -> None:
    """Digest 828d-1 rank 4: clear criteria CANCEL, NC START, RESET, POWER ON (002 L8931-8935).

    Digest 828d-3 rank 25 (NC alarms cleared by RESET, 10208 by NC START, POWER ON alarms survive RESET).
    """
    server = AlarmServer()
    for number in (1, 3000, 10203, 10208):
        server.raise_alarm(number, (), now_s=0.0)
    assert server.clear("cancel", 1.0) == [10203]
    assert server.clear("nc_start", 2.0) == [10208]
    server.raise_alarm(10203, (), now_s=3.0)
    assert sorted(server.clear("reset", 4.0, keep=frozenset({3000}))) == [10203]
    assert [e.number for e in server.active] == [1, 3000]
    assert server.clear("reset", 5.0) == [3000]
    assert [e.number for e in server.active] == [1]  # POWER ON only
    assert server.clear_number(1, 6.0)
    assert server.active == ()


def test_log_is_sequenced_with_come_and_go_times_and_bounded() -> None:
    """Digest 828d-1 rank 4 (alarm log with times)."""
    server = AlarmServer(log_limit=10)
    server.raise_alarm(10203, (), now_s=1.0)
    first = server.last_seq
    server.clear("cancel", 2.5)
    events = server.log_since(first - 1)
    assert [e.kind for e in events] == ["came", "went"]
    assert events[1].entry.went_s == 2.5 and events[1].seq > events[0].seq
    history = server.history()
    assert history[0].came_s == 1.0 and history[0].went_s == 2.5
    for index in range(20):
        server.raise_alarm(61000 + index, (), now_s=3.0)
    assert len(server.log_since(0)) == 10
    assert len(server.active) == ACTIVE_LIMIT == 16  # 002 L8884: at most 16 alarms are kept pending


def test_messages_are_a_separate_list() -> None:
    server = AlarmServer()
    server.set_message("Insert part", 1.0)
    assert server.message == "Insert part" and server.active == ()
    assert server.log_since(0)[-1].kind == "message"


def test_msg_and_setal_from_a_program() -> None:
    nck = make_nck({"P": 'N10 MSG("roughing")\nN20 G1 X5 F600\nN30 SETAL(61002)\nN40 G1 X9\nN50 M30'})
    auto_start(nck, "P")
    nck.tick(0.2)
    assert nck.status().channel.message == "roughing"
    assert until_state(nck, "interrupted", "stopped")
    status = nck.status()
    assert 61002 in alarm_numbers(nck)
    assert status.channel.stop_reason == "alarm"
    assert nck.positions_mcs()["X"] == 5.0  # interpreter stopped before N40
    came = [e for e in nck.alarm_log_since(0) if e.kind == "came"]
    assert came[-1].entry.number == 61002 and came[-1].entry.n == 30
    nck.submit(c.Reset())
    assert alarm_numbers(nck) == [] and nck.status().channel.message == ""


def test_program_alarm_stops_with_its_block_and_location() -> None:
    nck = make_nck({"P": "N10 G1 X5 F600\nN20 ERR\nN30 X50\nN40 M30"})
    auto_start(nck, "P")
    assert until_state(nck, "interrupted", "stopped")
    alarm = nck.status().alarms[0]
    assert (alarm.number, alarm.line, alarm.n) == (12080, 2, 20)
    assert alarm.params[:2] == ("1", "N20")
    assert nck.positions_mcs()["X"] == 5.0
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and result.alarm == 10200


def test_cancel_clears_only_cancel_alarms() -> None:
    nck = make_nck({"P": "N10 M30"}, referenced=False)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    nck.submit(c.CycleStart())
    nck.submit(c.EmergencyStop(True))
    assert sorted(alarm_numbers(nck)) == [3000, 10203]
    nck.submit(c.CancelAlarms())
    assert alarm_numbers(nck) == [3000]


def test_internal_error_becomes_alarm_1_and_is_logged() -> None:
    nck = make_nck({"P": "N10 G1 X5 F600\nN20 M30"})

    def broken(*_args, **_kwargs):
        raise ZeroDivisionError("boom")

    nck._output = broken  # a bug in the kernel
    nck.programs.programs["P"] = "N10 M3 S100\nN20 M30"
    auto_start(nck, "P")
    nck.tick(0.1)
    assert 1 in alarm_numbers(nck)
    assert nck.internal_errors and "ZeroDivisionError" in nck.internal_errors[0]
    assert nck.status().internal_errors >= 1
    assert states(nck)[1:] == ("reset", "aborted")
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and result.alarm == 10200


def test_retained_history_and_external_alarms() -> None:
    from nck.errors import NcAlarmError
    from nck.status import AlarmEntry

    nck = make_nck()
    old = AlarmEntry(seq=0, number=10203, text="old", category="channel", clear="cancel",
                     came_s=1.0, went_s=2.0)
    nck.raise_alarm(NcAlarmError(3000))
    nck.load_alarm_history([old])
    history = nck.alarm_history()
    assert [e.number for e in history] == [10203, 3000]
    assert 3000 in alarm_numbers(nck)
