"""The trace view's settings and recorder handling (Diagnostics area).

Holds the four signal slots, the trigger and the duration the operator chose,
starts a :class:`nck.trace.TraceRecorder` (hooked to the kernel by the bridge) and exports its CSV.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from rich.text import Text

from nck import MAX_SIGNALS, TraceRecorder, TraceSettings, available_signals, signal_unit, write_export

from hmi.i18n import N_, _

DURATIONS_S = (1.0, 2.0, 5.0, 10.0, 20.0, 60.0)
TRIGGER_NAMES = {"now": N_("start now"), "nc_start": N_("on NC START")}
TRACE_STATES = (N_("idle"), N_("armed"), N_("recording"), N_("done"))
"""The recorder's states as the settings line shows them (translated where shown)."""


class TraceSession:
    """Signal slots, trigger, duration and the recorder of the last start."""

    def __init__(self, machine: Any) -> None:
        self.signals = available_signals(machine)
        first = next((s for s in self.signals if s.endswith(".position")), None)
        self.slots: list[str | None] = [first, None, None, None][:MAX_SIGNALS]
        self.slot = 0
        self.trigger = "now"
        self.duration_s = 5.0
        self.recorder: TraceRecorder | None = None
        self.machine = machine

    @property
    def chosen(self) -> tuple[str, ...]:
        """The signals in the slots (empty slots skipped)."""
        return tuple(s for s in self.slots if s)

    def next_slot(self) -> None:
        """Edit the next of the four slots."""
        self.slot = (self.slot + 1) % MAX_SIGNALS

    def next_signal(self) -> None:
        """Put the next signal (or none) into the slot being edited."""
        current = self.slots[self.slot]
        taken = {s for i, s in enumerate(self.slots) if s and i != self.slot}
        choices: list[str | None] = [None, *(s for s in self.signals if s not in taken)]
        index = choices.index(current) if current in choices else 0
        self.slots[self.slot] = choices[(index + 1) % len(choices)]

    def set_signal(self, slot: int, signal: str | None) -> None:
        """Put ``signal`` into ``slot`` (0…3); raises ValueError for an unknown signal."""
        if signal is not None and signal not in self.signals:
            raise ValueError(f"unknown trace signal {signal}")
        self.slots[slot] = signal

    def toggle_trigger(self) -> None:
        """Start now ↔ on NC START."""
        self.trigger = "nc_start" if self.trigger == "now" else "now"

    def next_duration(self) -> None:
        """The next duration of :data:`DURATIONS_S`."""
        later = [d for d in DURATIONS_S if d > self.duration_s + 1e-9]
        self.duration_s = later[0] if later else DURATIONS_S[0]

    @property
    def running(self) -> bool:
        """True while the recorder waits for its trigger or records."""
        return self.recorder is not None and self.recorder.state in ("armed", "recording")

    def start(self, attach: Callable[[TraceRecorder], None]) -> TraceRecorder:
        """Start a new recording, hooked to the kernel by ``attach`` (a running one is stopped first)."""
        self.stop()
        self.recorder = TraceRecorder(TraceSettings(self.chosen, self.trigger, self.duration_s), self.machine)
        attach(self.recorder)
        return self.recorder

    def stop(self) -> None:
        """Stop recording; the samples stay."""
        if self.recorder is not None:
            self.recorder.detach()

    def export(self, directory: Path, replace: bool = False) -> Path:
        """Write the samples as ``trace.csv`` into ``directory``; return the path.

        An existing ``trace.csv`` is replaced only with ``replace`` (else
        :class:`nck.ExportTargetExists`); a link or pipe of that name is refused
        (:func:`nck.regular_files.write_export`).
        """
        if self.recorder is None or not self.recorder.sample_count:
            raise ValueError("nothing recorded yet")
        path = Path(directory) / "trace.csv"
        write_export(path, self.recorder.to_csv().encode("utf-8"), replace=replace)
        return path

    def settings_text(self) -> Text:
        """The settings line(s) above the plot."""
        text = Text(no_wrap=True, end="")
        for index, signal in enumerate(self.slots):
            marker = "▸" if index == self.slot else " "
            name = f"{signal} [{signal_unit(signal)}]" if signal else "—"
            text.append(f" {marker}{index + 1}: ", style="bold" if index == self.slot else None)
            text.append(f"{name:<28}", style="reverse" if index == self.slot else None)
        state = self.recorder.state if self.recorder is not None else "idle"
        samples = self.recorder.sample_count if self.recorder is not None else 0
        text.append("\n " + _("Trigger: {trigger}   Duration: {duration} s   State: {state}   Samples: {samples} "
                               "(one per IPO cycle)").format(trigger=_(TRIGGER_NAMES[self.trigger]),
                                                             duration=f"{self.duration_s:g}", state=_(state),
                                                             samples=samples))
        return text
