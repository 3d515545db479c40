"""The checks of a guided exercise: a small predicate vocabulary over state and events.

Nothing here runs code from an exercise file: a check is a table ``{kind = ..., ...}``
whose ``kind`` names one of the functions of :data:`CHECK_KINDS`.

:class:`ExerciseProgress` follows a session. It is fed what the panel sees — status
snapshots (reduced by :func:`state_of` to the plain :data:`State` the checks read;
alarms that came and went are the differences of their active alarms), the
operator's commands and keys — and keeps
them as a list of plain events, the *recording*. Replaying a recording
(:func:`replay`) gives the same progress and report, so an instructor can go through
a session at speed without the panel.

Events (dicts, ``t_s`` = simulated control time):
``state`` (a changed :data:`State`), ``command`` (name, accepted, fields),
``alarm_came`` / ``alarm_went`` (number; ``went`` also ``by``: the last command before
it), ``program_started``, ``program_ended`` (a correct end M2/M30: the kernel's
``$AC_OLD_PROG_NET_TIME_COUNT`` went up; with the alarms that came and the single-block
stops made during the run), ``stop`` (reason), ``key``, ``ended`` (the session ended: the
report's time runs to it, also when nothing changed in its last minutes).

Step by step: a step's event checks look only at events after the previous step was
done, so "the program ran to its end" means a run after the preceding step.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Mapping

from nck.phrase import Phrase

State = dict[str, Any]
"""Plain state read by the checks: ``referenced`` (axis → bool), ``mode``, ``program``,
``channel``, ``program_state`` (aborted/running/stopped/interrupted/waiting), ``active_alarms`` (numbers), ``estop``, ``offsets`` ("G54" → axis → mm),
``tools`` ("T,D" → effective length 1 in mm), ``blank`` (low/high MCS corners or None),
``single_block``."""

Verdict = tuple[bool, str]
"""A check's answer: held or not, and what to tell the trainee when not."""


def state_of(status: Any, data: Any) -> State:
    """The :data:`State` of a status snapshot (``nck.status.NckStatus``) and NC data (``NcData``)."""
    channel = status.channel
    offsets = {}
    tools = {}
    blank = None
    if data is not None:
        for name, frame in data.settable_frames.items():
            axes = set(frame.trans) | set(frame.fine)
            offsets[name] = {a: round(frame.trans.get(a, 0.0) + frame.fine.get(a, 0.0), 6) for a in sorted(axes)}
        for (tool, edge), params in data.tools.items():
            tools[f"{tool},{edge}"] = round(params.get(3) + params.get(12), 6)
        solid = data.machine_setup.blank
        low = getattr(solid, "low_mcs", None)
        if low is not None:
            blank = {"low": list(low), "high": list(solid.high_mcs)}
    return {
        "referenced": {a.name: bool(a.referenced) for a in status.axes if a.kind != "spindle"},
        "mode": channel.mode,
        "program": channel.selected_program,
        "channel": channel.channel_state,
        "program_state": channel.program_state,
        "active_alarms": sorted({a.number for a in status.alarms}),
        "estop": bool(status.emergency_stop),
        "offsets": offsets,
        "tools": tools,
        "blank": blank,
        "single_block": channel.program_control.get("single_block"),
    }


class Reason(Phrase):
    """Why a check does not hold: the English sentence (what reports and recordings keep), with
    its ``template`` and ``fields`` so that a panel can say it in another language (the
    template is a text of the panel's catalogue, formatted with ``str.format``)."""


# ------------------------------------------------------------------ the vocabulary
def _axes_referenced(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    axes = check.get("axes") or sorted(state["referenced"])
    missing = [a for a in axes if not state["referenced"].get(a)]
    return not missing, Reason("axes not referenced: {axes}", axes=", ".join(missing))


def _mode(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    return state["mode"] == check["is"], Reason("operating mode is {mode}, not {wanted}", mode=state["mode"], wanted=check["is"])


def _program_selected(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    wanted = _stem(check["name"])
    return _stem(state["program"]) == wanted, Reason("{program} is not selected", program=check["name"])


def _no_active_alarm(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    return not state["active_alarms"], Reason("alarms still active: {numbers}",
                                                numbers=", ".join(map(str, state["active_alarms"])))


def _emergency_stop_released(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    return not state["estop"], Reason("EMERGENCY STOP is still active (release it, then RESET)")


def _work_offset(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    frame, axis = check.get("frame", "G54"), check["axis"]
    within = float(check.get("within_mm", 0.01))
    if "blank" in check:  # "low" / "high": that corner of the clamped blank, in the MCS
        if state["blank"] is None:
            return False, Reason("no blank is clamped")
        wanted = state["blank"][check["blank"]]["XYZ".index(axis)] + float(check.get("plus_mm", 0.0))
    else:
        wanted = float(check["value"])
    actual = state["offsets"].get(frame, {}).get(axis, 0.0)
    ok = abs(actual - wanted) <= within + 1e-9
    # The reason names the value entered and the tolerance, never the distance to the true
    # value: the side window shows it live, and "5.000 mm off" would hand a measuring
    # exercise's answer to the trainee.
    return ok, Reason("{frame} {axis} is {actual:.3f} mm: not within {within:g} mm of where it belongs",
                      frame=frame, axis=axis, actual=actual, within=within)


def _tool_length(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    key = f"{check['t']},{check.get('d', 1)}"
    within = float(check.get("within_mm", 0.02))
    if key not in state["tools"]:
        return False, Reason("T{tool} D{edge} has no data", tool=check["t"], edge=check.get("d", 1))
    actual, wanted = state["tools"][key], float(check["value"])
    return abs(actual - wanted) <= within + 1e-9, \
        Reason("T{tool} length is {actual:.3f} mm: not within {within:g} mm of its true length",
               tool=check["t"], actual=actual, within=within)


def _program_state(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    wanted = check["state"]
    return state.get("program_state") == wanted, Reason("the program status is not {state}", state=wanted)


def _single_block(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    return state["single_block"] is not None, Reason("single block is off")


def _program_ended(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    ends = [e for e in events if e["kind"] == "program_ended"
            and ("program" not in check or _stem(e["program"]) == _stem(check["program"]))]
    if check.get("without_alarm", True):
        ends = [e for e in ends if not e["alarms"]]
    least = int(check.get("single_block_stops", 0))
    ends = [e for e in ends if e["single_block_stops"] >= least]
    program = check.get("program")
    if program and least:
        why = Reason("{program} has not run to its end without alarm with at least {least} single-block stops",
                     program=program, least=least)
    elif program:
        why = Reason("{program} has not run to its end without alarm", program=program)
    elif least:
        why = Reason("the program has not run to its end without alarm with at least {least} single-block stops",
                     least=least)
    else:
        why = Reason("the program has not run to its end without alarm")
    return bool(ends), why


def _alarm_came(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    number = int(check["number"])
    return any(e["kind"] == "alarm_came" and e["number"] == number for e in events), Reason("alarm {number} did not come", number=number)


def _alarm_cleared(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    number = int(check["number"])
    keys = check.get("by", [])
    went = [e for e in events if e["kind"] == "alarm_went" and e["number"] == number]
    right = [e for e in went if not keys or e["by"] in keys]
    if right:
        return True, ""
    if went:
        if not went[-1]["by"]:
            return False, Reason("alarm {number} was cleared with nothing, not {keys}", number=number,
                                 keys=" or ".join(keys))
        return False, Reason("alarm {number} was cleared with {key}, not {keys}", number=number,
                             key=went[-1]["by"], keys=" or ".join(keys))
    return False, Reason("alarm {number} was not cleared", number=number)


def _command_used(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    name = check["name"]
    wanted = {k: v for k, v in check.items() if k not in ("kind", "name", "contains")}
    contains = check.get("contains", {})
    for event in events:
        if event["kind"] != "command" or event["name"] != name or not event["accepted"]:
            continue
        fields = event.get("fields", {})
        if all(fields.get(k) == v for k, v in wanted.items()) and all(
                str(v).upper() in str(fields.get(k, "")).upper() for k, v in contains.items()):
            return True, ""
    if wanted or contains:
        return False, Reason("{command} was not used as asked", command=name)
    return False, Reason("{command} was not used", command=name)


def _stopped(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    reason = check["reason"]
    count = sum(1 for e in events if e["kind"] == "stop" and e["reason"] == reason)
    least = int(check.get("at_least", 1))
    return count >= least, Reason("the program stopped {count} time(s) with {reason}, at least {least} asked",
                                 count=count, reason=reason, least=least)


def _no_alarm_came(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    numbers = set(check.get("numbers", []))
    came = [e["number"] for e in events if e["kind"] == "alarm_came" and (not numbers or e["number"] in numbers)]
    return not came, Reason("alarms came: {numbers}", numbers=", ".join(map(str, came)))


CHECK_KINDS: dict[str, Callable[[Mapping[str, Any], State, list[dict]], Verdict]] = {
    "axes_referenced": _axes_referenced,
    "mode": _mode,
    "program_selected": _program_selected,
    "no_active_alarm": _no_active_alarm,
    "emergency_stop_released": _emergency_stop_released,
    "work_offset": _work_offset,
    "tool_length": _tool_length,
    "single_block": _single_block,
    "program_state": _program_state,
    "program_ended": _program_ended,
    "alarm_came": _alarm_came,
    "alarm_cleared": _alarm_cleared,
    "command_used": _command_used,
    "stopped": _stopped,
    "no_alarm_came": _no_alarm_came,
}
"""The check vocabulary: ``kind`` → predicate ``(check, state, events) -> (held, why not)``."""


def _stem(name: Any) -> str:
    text = str(name or "").upper().rpartition("/")[2]
    return text.rsplit(".", 1)[0] if "." in text else text


def evaluate(check: Mapping[str, Any], state: State, events: list[dict]) -> Verdict:
    """One check against the state and the events it may look at."""
    return CHECK_KINDS[check["kind"]](check, state, events)


# ------------------------------------------------------------------ progress
@dataclass
class StepResult:
    """How far one step got: done at ``done_s`` (None: not done) and, if not, why."""

    done_s: float | None = None
    why_not: list[str] = field(default_factory=list)


class ExerciseProgress:
    """Follows one session of an exercise (see the module docstring).

    ``steps`` are the exercise's steps (``text``, ``hint``, ``checks``); ``finals`` the
    checks made once at the end over the whole session.
    """

    def __init__(self, steps: Iterable[Any], finals: Iterable[Mapping[str, Any]] = ()) -> None:
        self.steps = list(steps)
        self.finals = list(finals)
        self.events: list[dict[str, Any]] = []
        self.results = [StepResult() for _ in self.steps]
        self.current = 0
        self.state: State | None = None
        self.started_s: float | None = None
        self.now_s = 0.0
        self._step_from = 0  # index of the first event the current step may look at
        self._last_command = ""
        self._run: dict[str, Any] | None = None
        self._ends_seen: int | None = None
        self._stop_reason = ""

    @property
    def finished(self) -> bool:
        """True when every step is done."""
        return self.current >= len(self.steps)

    # -- what the panel feeds in -------------------------------------------------------
    def observe_status(self, status: Any, data: Any) -> None:
        """A new snapshot: derive the run events, record a changed state, check the step."""
        self.now_s = float(status.time_s)
        if self.started_s is None:
            self.started_s = self.now_s
        channel = status.channel
        if self._ends_seen is not None and channel.program_runtime_count > self._ends_seen:
            run = self._run or {"program": channel.selected_program, "alarms": [], "single_block_stops": 0}
            self._add("program_ended", program=run["program"], alarms=run["alarms"],
                      single_block_stops=run["single_block_stops"])
            self._run = None
        self._ends_seen = channel.program_runtime_count
        state = state_of(status, data)
        if self.state is None or state["channel"] != self.state["channel"]:
            if state["channel"] == "active" and state["mode"] in ("AUTO", "MDA") and (
                    self.state is None or self.state["channel"] == "reset"):
                self._run = {"program": state["program"], "alarms": [], "single_block_stops": 0}
                self._add("program_started", program=state["program"], mode=state["mode"])
            elif state["channel"] == "reset":
                self._run = None
        before = set(self.state["active_alarms"]) if self.state is not None else set()
        for number in sorted(set(state["active_alarms"]) - before):
            self._add("alarm_came", number=number)
        for number in sorted(before - set(state["active_alarms"])):
            self._add("alarm_went", number=number, by=self._last_command)
        if channel.stop_reason != self._stop_reason:
            self._stop_reason = channel.stop_reason
            if channel.stop_reason:
                self._add("stop", reason=channel.stop_reason)
        if state != self.state:
            self.state = state
            self._add("state", state=state)
        self._check()

    def observe_command(self, command: Any, accepted: bool) -> None:
        """An operator command sent to the kernel and whether it was taken."""
        name = type(command).__name__
        fields = {k: _plain(getattr(command, k)) for k in getattr(command, "__dataclass_fields__", {})}
        self._last_command = name
        self._add("command", name=name, accepted=bool(accepted), fields=fields)
        self._check()

    def observe_key(self, key: str) -> None:
        """A key the operator pressed (recorded for the instructor's replay)."""
        self._add("key", key=key)

    def observe_end(self, time_s: float) -> None:
        """The session ends at control time ``time_s`` (the time of the last snapshot that
        changed may lie minutes before it)."""
        self.now_s = float(time_s)
        if self.started_s is None:
            self.started_s = self.now_s
        self._add("ended")
        self._check()

    # -- replay ---------------------------------------------------------------------------
    def replay_event(self, event: Mapping[str, Any]) -> None:
        """Feed one recorded event again (see :func:`replay`)."""
        self.now_s = float(event["t_s"])
        if self.started_s is None:
            self.started_s = self.now_s
        fields = {k: v for k, v in event.items() if k not in ("kind", "t_s")}
        if event["kind"] == "state":
            self.state = dict(event["state"])
        elif event["kind"] == "command":
            self._last_command = event["name"]
        self._add(event["kind"], **fields)
        if event["kind"] != "key":
            self._check()

    # -- checking ---------------------------------------------------------------------------
    def _add(self, kind: str, **fields: Any) -> None:
        event = {"kind": kind, "t_s": round(self.now_s, 4), **fields}
        if self._run is not None:
            if kind == "alarm_came":
                self._run["alarms"].append(fields["number"])
            elif kind == "stop" and fields["reason"] == "single block":
                self._run["single_block_stops"] += 1
        self.events.append(event)

    def _check(self) -> None:
        while not self.finished and self.state is not None:
            verdicts = [evaluate(c, self.state, self.events[self._step_from:]) for c in self.steps[self.current].checks]
            result = self.results[self.current]
            result.why_not = [why for ok, why in verdicts if not ok]
            if result.why_not:
                return
            result.done_s = self.now_s
            self.current += 1
            self._step_from = len(self.events)
            self._add("step_done", step=self.current)

    # -- the report -----------------------------------------------------------------------------
    def report(self, title: str = "") -> dict[str, Any]:
        """The scored report: steps done (when), why the others are not, the final checks."""
        state = self.state or {}
        finals = []
        for check in self.finals:
            ok, why = evaluate(check, state, self.events) if state else (False, Reason("nothing happened"))
            finals.append({"check": check["kind"], "passed": ok, "why_not": "" if ok else why})
        start = self.started_s or 0.0
        steps = [{"step": i + 1, "text": getattr(s, "text", ""), "done": r.done_s is not None,
                  "done_after_s": None if r.done_s is None else round(r.done_s - start, 1),
                  "why_not": [] if r.done_s is not None else (r.why_not or [Reason("not reached")])}
                 for i, (s, r) in enumerate(zip(self.steps, self.results))]
        points = sum(1 for s in steps if s["done"]) + sum(1 for f in finals if f["passed"])
        total = len(steps) + len(finals)
        return {"title": title, "score": round(100 * points / total) if total else 0,
                "time_s": round(self.now_s - start, 1), "steps": steps, "final_checks": finals,
                "keys": sum(1 for e in self.events if e["kind"] == "key")}


def report_text(report: Mapping[str, Any], say: Callable[[str], str] = str) -> str:
    """The report as the trainee and the instructor read it. Each sentence is a :class:`Phrase`
    that ``say`` words (a panel passes its translation, which says the reasons' phrases in its
    language too; the default keeps the English); ``report`` may hold a panel's texts of the
    title and the steps."""
    lines = [say(Phrase("Exercise: {title}", title=report["title"])),
             say(Phrase("Score: {score}/100   time: {seconds} s   keys: {keys}", score=report["score"],
                        seconds=f"{report['time_s']:.1f}", keys=report["keys"])), ""]
    for step in report["steps"]:
        if step["done"]:
            lines.append(f"[x] {step['step']}. {step['text']}  "
                         + say(Phrase("(done after {seconds} s)", seconds=f"{step['done_after_s']:.1f}")))
        else:
            lines.append(f"[ ] {step['step']}. {step['text']}")
            lines.extend("      " + say(Phrase("not done: {why}", why=why)) for why in step["why_not"])
    for final in report["final_checks"]:
        mark = "[x]" if final["passed"] else "[ ]"
        lines.append(f"{mark} " + say(Phrase("at the end: {check}", check=final["check"]))
                     + ("" if final["passed"] else f" — {say(final['why_not'])}"))
    return "\n".join(lines) + "\n"


def replay(steps: Iterable[Any], finals: Iterable[Mapping[str, Any]], events: Iterable[Mapping[str, Any]]
           ) -> ExerciseProgress:
    """The progress of a recorded session, fed again event by event (derived events are
    taken as recorded, not derived twice)."""
    progress = ExerciseProgress(steps, finals)
    for event in events:
        if event["kind"] != "step_done":
            progress.replay_event(event)
    return progress


def _plain(value: Any) -> Any:
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    if isinstance(value, (frozenset, set)):
        return sorted(_plain(v) for v in value)
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, Mapping):
        return {str(k): _plain(v) for k, v in value.items()}
    return str(value)
