"""The bridge: advances the kernel by elapsed time, posts snapshots on a new seq (and once a
second of control time), reports refusals."""

from __future__ import annotations

from nck import commands as c

from hmi.bridge import MAX_CATCH_UP_S, NckBridge
from hmi.messages import CommandRejected, NckStatusChanged
from tests.hmi.fake_nck import FakeNck


class Inbox:
    """Stands in for the app: collects posted messages."""

    def __init__(self) -> None:
        self.messages: list[object] = []

    def post_message(self, message: object) -> bool:
        self.messages.append(message)
        return True

    def of(self, kind: type) -> list[object]:
        return [m for m in self.messages if isinstance(m, kind)]


def make(clock: list[float]) -> tuple[FakeNck, NckBridge, Inbox]:
    fake = FakeNck(referenced=True)
    bridge = NckBridge(fake, realtime=False, clock=lambda: clock[0])
    inbox = Inbox()
    bridge.attach(inbox)  # type: ignore[arg-type]
    return fake, bridge, inbox


def test_timer_advances_by_elapsed_time_with_catch_up_limit() -> None:
    """Each timer tick advances the kernel by the wall time since the last one, at most MAX_CATCH_UP_S."""
    clock = [10.0]
    fake, bridge, _ = make(clock)
    clock[0] = 10.05
    bridge._on_timer()
    assert abs(fake.time_s - 0.05) < 1e-9
    clock[0] = 20.0  # a long stall
    bridge._on_timer()
    assert abs(fake.time_s - (0.05 + MAX_CATCH_UP_S)) < 1e-9


def test_status_posted_only_when_seq_changes() -> None:
    """No new snapshot message while nothing changes; one per change."""
    clock = [0.0]
    fake, bridge, inbox = make(clock)
    first = len(inbox.of(NckStatusChanged))
    for _ in range(5):
        bridge.advance(0.05)  # idle kernel: seq unchanged
    assert len(inbox.of(NckStatusChanged)) == first
    bridge.submit(c.SetOverride("feed", 50))
    assert len(inbox.of(NckStatusChanged)) == first + 1
    assert inbox.of(NckStatusChanged)[-1].status.channel.overrides["feed"] == 50


def test_an_unchanged_snapshot_is_shown_once_a_second() -> None:
    """An idle machine's snapshot does not change; it is still posted once a second of control
    time, for the views whose figures it does not carry (System utilisation)."""
    clock = [0.0]
    fake, bridge, inbox = make(clock)
    first = len(inbox.of(NckStatusChanged))
    for _ in range(int(2.0 / 0.05) + 1):  # two seconds of idle ticks, and one more
        bridge.advance(0.05)
    assert len(inbox.of(NckStatusChanged)) == first + 2


def test_refusal_is_posted_with_reason() -> None:
    """A Rejected answer becomes a CommandRejected message carrying the reason and alarm."""
    clock = [0.0]
    fake, bridge, inbox = make(clock)
    fake.referenced["X"] = False
    fake.submit(c.SelectMode("MDA"))
    fake.submit(c.SetMdaProgram("G0 X1"))
    result = bridge.submit(c.CycleStart())
    assert isinstance(result, c.Rejected)
    rejected = inbox.of(CommandRejected)
    assert rejected and rejected[-1].refusal.alarm == 10203 and "referenced" in rejected[-1].refusal.reason
