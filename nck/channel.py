"""Modes, channel status and program status as an explicit transition table.

Source: Function Manual Basic Functions, K1 (digest part 2 §1.6, §2.2–2.4,
Table 9-3). One mode group with one channel.

* Modes: ``JOG``, ``MDA``, ``AUTO``; power-on mode JOG.
* Channel status: ``reset`` / ``active`` / ``interrupted``.
* Program status: ``aborted`` / ``running`` / ``stopped`` / ``interrupted`` / ``waiting``.

Decisions where the manual is ambiguous (digest §18): an MDA program shows
``running``/``stopped`` like AUTO (the manual's Table 9-3 shows "aborted");
a single-block stop gives channel interrupted / program stopped.

The kernel (:mod:`nck.kernel`) drives this table: :func:`next_state`
returns the situation an event leads to, or None when the event is not
allowed in the current situation. :data:`VALID_SITUATIONS` lists every
(mode, channel, program) combination that can be reached.
"""

from __future__ import annotations

from dataclasses import dataclass

from nck.commands import Rejected
from nck.refusals import refuse

MODES = ("JOG", "MDA", "AUTO")
MACHINE_FUNCTIONS = ("REF", "REPOS", "INC")
INCREMENTS = (1, 10, 100, 1000, 10000)  # in 0.001 mm; None = INC VAR
POWER_ON_MODE = "JOG"

RESET, ACTIVE, INTERRUPTED = "reset", "active", "interrupted"
ABORTED, RUNNING, STOPPED, PROG_INTERRUPTED, WAITING = (
    "aborted", "running", "stopped", "interrupted", "waiting",
)


@dataclass(frozen=True, slots=True)
class ChannelSituation:
    """Mode, channel status and program status at one instant."""

    mode: str = POWER_ON_MODE
    channel: str = RESET
    program: str = ABORTED


# (mode, channel, program) combinations reachable in the simulator (Table 9-3
# situations 4-18, with MDA showing running/stopped, see the module docstring).
VALID_SITUATIONS: frozenset[tuple[str, str, str]] = frozenset({
    # AUTO: reset; running; stopped (NC STOP, M0/M1, single block, alarm);
    # interrupted (back from JOG/MDA, or search target found); waiting.
    ("AUTO", RESET, ABORTED), ("AUTO", ACTIVE, RUNNING), ("AUTO", INTERRUPTED, STOPPED),
    ("AUTO", INTERRUPTED, PROG_INTERRUPTED), ("AUTO", ACTIVE, WAITING),
    # MDA: own program reset/running/stopped; with an interrupted program
    # (AUTO's or its own, after a visit to JOG): interrupted, or running an
    # MDA block over the interrupted AUTO program (situation 16).
    ("MDA", RESET, ABORTED), ("MDA", ACTIVE, RUNNING), ("MDA", INTERRUPTED, STOPPED),
    ("MDA", INTERRUPTED, PROG_INTERRUPTED), ("MDA", ACTIVE, PROG_INTERRUPTED),
    # MDA with the machine functions REF/REPOS: traversing by hand (situations 7, 14).
    ("MDA", ACTIVE, ABORTED), ("MDA", INTERRUPTED, ABORTED),
    # JOG: reset; jogging; a JOG increment stopped with NC STOP (situation 8);
    # a program interrupted; jogging while a program is interrupted.
    ("JOG", RESET, ABORTED), ("JOG", ACTIVE, ABORTED), ("JOG", INTERRUPTED, ABORTED),
    ("JOG", INTERRUPTED, PROG_INTERRUPTED), ("JOG", ACTIVE, PROG_INTERRUPTED),
})

# event -> {(channel, program): (channel, program)}; the mode is unchanged
# except for "mode_change", handled by :func:`mode_change_allowed`.
TRANSITIONS: dict[str, dict[tuple[str, str], tuple[str, str]]] = {
    # NC START of a program: from reset, from a stop, or resuming an interrupted one.
    "program_start": {
        (RESET, ABORTED): (ACTIVE, RUNNING),
        (INTERRUPTED, STOPPED): (ACTIVE, RUNNING),
        (INTERRUPTED, PROG_INTERRUPTED): (ACTIVE, RUNNING),
    },
    # NC START in MDA while the AUTO program stays interrupted (situation 10 -> 16).
    "overlay_start": {(INTERRUPTED, PROG_INTERRUPTED): (ACTIVE, PROG_INTERRUPTED)},
    # NC STOP: brake now (situations 13 -> 12, 14 -> 7, 15 -> 8, 16 -> 10, 17 -> 11).
    "nc_stop": {
        (ACTIVE, RUNNING): (INTERRUPTED, STOPPED),
        (ACTIVE, WAITING): (INTERRUPTED, STOPPED),
        (ACTIVE, ABORTED): (INTERRUPTED, ABORTED),
        (ACTIVE, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
    },
    # Stop at a block boundary: M0, M1, single block, alarm with interpreter stop.
    "block_stop": {
        (ACTIVE, RUNNING): (INTERRUPTED, STOPPED),
        (ACTIVE, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
    },
    # M2/M30, end of the MDA blocks.
    "program_end": {
        (ACTIVE, RUNNING): (RESET, ABORTED),
        (ACTIVE, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
    },
    # A direction key (or NC START continuing a stopped increment) in JOG.
    "jog_start": {
        (RESET, ABORTED): (ACTIVE, ABORTED),
        (INTERRUPTED, ABORTED): (ACTIVE, ABORTED),
        (INTERRUPTED, PROG_INTERRUPTED): (ACTIVE, PROG_INTERRUPTED),
    },
    "jog_end": {
        (ACTIVE, ABORTED): (RESET, ABORTED),
        (ACTIVE, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
    },
    # Leaving the mode of a stopped program: it becomes interrupted (12 -> 10/11).
    "leave_program_mode": {(INTERRUPTED, STOPPED): (INTERRUPTED, PROG_INTERRUPTED)},
    # Block search with calculation found its target (cascaded search allowed).
    "search_found": {
        (RESET, ABORTED): (INTERRUPTED, PROG_INTERRUPTED),
        (INTERRUPTED, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
        (INTERRUPTED, STOPPED): (INTERRUPTED, PROG_INTERRUPTED),
    },
    # Emergency stop: programs are interrupted, JOG motion ends.
    "emergency_stop": {
        (ACTIVE, RUNNING): (INTERRUPTED, PROG_INTERRUPTED),
        (ACTIVE, WAITING): (INTERRUPTED, PROG_INTERRUPTED),
        (INTERRUPTED, STOPPED): (INTERRUPTED, PROG_INTERRUPTED),
        (ACTIVE, ABORTED): (RESET, ABORTED),
        (INTERRUPTED, ABORTED): (RESET, ABORTED),
        (ACTIVE, PROG_INTERRUPTED): (INTERRUPTED, PROG_INTERRUPTED),
    },
}


def next_state(situation: ChannelSituation, event: str) -> ChannelSituation | None:
    """Return the situation ``event`` leads to, or None if it is not allowed.

    ``reset`` is allowed in every situation and always gives channel reset /
    program aborted in the same mode.
    """
    if event == "reset":
        return ChannelSituation(situation.mode, RESET, ABORTED)
    table = TRANSITIONS.get(event)
    if table is None:
        raise KeyError(f"unknown channel event {event!r}")
    target = table.get((situation.channel, situation.program))
    if target is None:
        return None
    return ChannelSituation(situation.mode, target[0], target[1])


def mode_change_allowed(
    situation: ChannelSituation, target_mode: str, interrupted_owner: str | None
) -> Rejected | None:
    """Return None if the mode change is allowed, else its refusal.

    ``interrupted_owner`` is the mode (``AUTO``/``MDA``) whose program is
    stopped or interrupted, if any. Rules (digest §1.6): no change while the
    channel is active; an interrupted MDA program cannot go straight to AUTO.
    """
    if target_mode not in MODES:
        return refuse("unknown_mode", mode=repr(target_mode))
    if situation.channel == ACTIVE:
        return refuse("mode_change_refused")
    if target_mode == "AUTO" and interrupted_owner == "MDA":
        return refuse("mda_interrupted")
    return None


def situation_after_mode_change(
    situation: ChannelSituation, target_mode: str, interrupted_owner: str | None
) -> ChannelSituation:
    """The situation after an allowed mode change to ``target_mode``.

    A program stopped in its own mode becomes ``interrupted`` when that mode is
    left and stays interrupted in the other modes (Table 9-3, 12 -> 10/11).
    """
    program = situation.program
    channel = situation.channel
    if program == STOPPED and target_mode != situation.mode:
        program = PROG_INTERRUPTED
    if channel == INTERRUPTED and program == ABORTED:
        # A stopped JOG increment is dropped by leaving JOG.
        channel = RESET
    return ChannelSituation(target_mode, channel, program)


def is_valid(situation: ChannelSituation) -> bool:
    """True if the situation is one of :data:`VALID_SITUATIONS`."""
    return (situation.mode, situation.channel, situation.program) in VALID_SITUATIONS
