"""Grading a trainee's program against a reference (``nck grade``).

Both programs are run headless (:func:`nck.headless.run_program`) on the same
set-up; :func:`summarize` keeps what a trainer compares of each run and
:func:`grade` compares the two:

- alarms: the alarm numbers raised (with their blocks);
- final position: where the path axes stand at the end (WCS, program units);
- path: the largest distance between the two toolpaths (MCS, mm) — the one-sided
  distances both ways, so a move the trainee left out counts as much as one too
  many — with the block of each program where it occurs;
- tools: the tools changed in, in order;
- machining time: the kernel's simulated time of each run.

Scoring (our choice, the manuals are silent on grading): 100 points, split as
``WEIGHTS``. Alarms, final position and tools score all or nothing; the path
scores in full up to ``tolerance_mm`` and falls linearly to zero at
``PATH_ZERO_MM``; the machining time scores in full within ``TIME_FULL_RATIO`` of
the reference's and falls linearly to zero at ``TIME_ZERO_RATIO``.

The path is sampled (:data:`SAMPLE_STEP_MM`, coarser for very long paths so at most
:data:`MAX_SAMPLES` points are compared); the distance of a point to a polyline
changes by at most the step between two samples, so the deviation found is exact
at segment ends and at most half a step short in between. Arcs are drawn as
polylines whose sagitta stays below :data:`ARC_SAGITTA_MM`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Iterable

import numpy as np

from nck import canon
from nck.geometry.arc_mcs import arc_points_mcs, is_arc

PATH_AXES = ("X", "Y", "Z")
SAMPLE_STEP_MM = 0.05
MAX_SAMPLES = 20_000
ARC_SAGITTA_MM = 0.0005
MAX_ARC_CHORDS = 4000
WEIGHTS = {"alarms": 25.0, "path": 35.0, "position": 10.0, "tools": 15.0, "time": 15.0}
PATH_ZERO_MM = 1.0
TIME_FULL_RATIO = 0.05
TIME_ZERO_RATIO = 0.5
POSITION_TOLERANCE = 0.001
DISTANCES_PER_CHUNK = 2_000_000  # point x segment distances computed at once (memory bound)


@dataclass(frozen=True)
class Polyline:
    """A toolpath as vertices (rows, MCS mm) and, per segment, the block it belongs to."""

    vertices: np.ndarray  # (n + 1, 3)
    blocks: tuple[str, ...]  # n labels

    @property
    def segment_count(self) -> int:
        """Number of segments."""
        return len(self.blocks)


@dataclass(frozen=True)
class RunSummary:
    """What grading compares of one headless run."""

    status: str  # "ended", "alarm" or "timeout" (as HeadlessRun)
    alarms: tuple[tuple[int, str], ...]  # (number, block label)
    position_wcs: dict[str, float]
    tools: tuple[int, ...]
    machining_time_s: float
    path: Polyline


@dataclass(frozen=True)
class PathDeviation:
    """The largest distance between two toolpaths and where it occurs."""

    distance_mm: float
    student_block: str | None
    reference_block: str | None
    point_mcs: dict[str, float] = field(default_factory=dict)
    missing_in: str | None = None  # "student": a reference point far from the trainee's path


@dataclass(frozen=True)
class Check:
    """One compared aspect: its points, whether it matched and what to tell the trainee."""

    name: str
    points: float
    max_points: float
    same: bool
    text: str
    details: tuple[str, ...] = ()
    data: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Grade:
    """The result of :func:`grade`."""

    student: str
    reference: str
    checks: tuple[Check, ...]

    @property
    def score(self) -> int:
        """Points out of 100, rounded."""
        return round(sum(c.points for c in self.checks))

    @property
    def all_same(self) -> bool:
        """True when every check matched."""
        return all(c.same for c in self.checks)


def block_label(source: canon.Source) -> str:
    """``N50`` where the block has a number, else ``line 5``."""
    return f"N{source.n}" if source.n is not None else f"line {source.line}"


def summarize(result: Any, main_file: str) -> RunSummary:
    """The :class:`RunSummary` of a :class:`nck.headless.HeadlessRun` kept with its commands."""
    def label(source: canon.Source) -> str:
        text = block_label(source)
        return text if source.file.upper() == main_file.upper() else f"{source.file} {text}"

    tools: list[int] = []
    motions: list[canon.Motion] = []
    for command in result.commands:
        if isinstance(command, canon.ToolSelect) and command.change and command.tool:
            tools.append(command.tool)
        elif isinstance(command, canon.Motion):
            motions.append(command)
    alarms = tuple((a.number, label(canon.Source(a.file or main_file, a.line or 0, a.n))
                    if a.n is not None or a.line else "-") for a in result.alarms)
    return RunSummary(status=result.status, alarms=alarms,
                      position_wcs=dict(result.position_wcs or {}), tools=tuple(tools),
                      machining_time_s=float(result.machine_time_s), path=toolpath(motions, label))


def toolpath(motions: Iterable[canon.Motion], label: Any = block_label) -> Polyline:
    """The MCS polyline of ``motions`` (arcs drawn as chords), labelled by ``label(source)``."""
    vertices: list[list[float]] = []
    blocks: list[str] = []
    for motion in motions:
        points = _motion_points(motion)
        if not vertices:
            vertices.append(points[0])
        for point in points[1:]:
            vertices.append(point)
            blocks.append(label(motion.source))
    return Polyline(np.array(vertices, dtype=float).reshape(-1, 3), tuple(blocks))


def _motion_points(motion: canon.Motion) -> list[list[float]]:
    def row(point: Any) -> list[float]:
        return [float(point.get(a, motion.end_mcs.get(a, 0.0))) for a in PATH_AXES]

    if is_arc(motion):
        assert motion.center_mcs is not None
        start = np.array(row(motion.start_mcs or motion.end_mcs))
        centre = np.array(row(motion.center_mcs))
        radius = float(np.linalg.norm(start - centre))
        per_turn = math.pi / math.acos(max(-1.0, 1.0 - ARC_SAGITTA_MM / radius)) if radius > ARC_SAGITTA_MM else 4
        count = min(MAX_ARC_CHORDS, max(4, math.ceil(per_turn * (1 + max(motion.turns, 0)))))
        return [row(p) for p in arc_points_mcs(motion, count)]
    return [row(motion.start_mcs or motion.end_mcs), row(motion.end_mcs)]


def path_deviation(student: Polyline, reference: Polyline) -> PathDeviation:
    """The larger of the two one-sided distances between the toolpaths, with its blocks."""
    if not student.segment_count and not reference.segment_count:
        return PathDeviation(0.0, None, None)
    if not student.segment_count or not reference.segment_count:
        return PathDeviation(math.inf, None, None, missing_in="student" if not student.segment_count else "reference")
    away = _farthest(student, reference)
    back = _farthest(reference, student)
    if back[0] > away[0] + 1e-9:
        distance, ref_block, stu_block, point = back
        return PathDeviation(distance, stu_block, ref_block, point, missing_in="student")
    distance, stu_block, ref_block, point = away
    return PathDeviation(distance, stu_block, ref_block, point)


def _samples(path: Polyline) -> tuple[np.ndarray, np.ndarray]:
    """Points along ``path`` (every vertex and points in between) and their segment index.

    A vertex counts to the segment that ends there (the block that programmed it),
    the path's start point to the first segment.
    """
    starts, ends = path.vertices[:-1], path.vertices[1:]
    lengths = np.linalg.norm(ends - starts, axis=1)
    step = max(SAMPLE_STEP_MM, float(lengths.sum()) / MAX_SAMPLES)
    counts = np.maximum(1, np.ceil(lengths / step).astype(int))
    segment = np.repeat(np.arange(len(lengths)), counts)
    offsets = np.arange(len(segment)) - np.repeat(np.cumsum(counts) - counts, counts) + 1
    t = offsets / counts[segment]
    points = starts[segment] + (ends[segment] - starts[segment]) * t[:, None]
    return np.vstack([starts[:1], points]), np.concatenate([[0], segment])


def _farthest(path: Polyline, other: Polyline) -> tuple[float, str, str, dict[str, float]]:
    """The point of ``path`` farthest from ``other``: distance, both blocks, the point."""
    points, segment = _samples(path)
    starts, ends = other.vertices[:-1], other.vertices[1:]
    along = ends - starts
    squared = np.einsum("ij,ij->i", along, along)
    squared[squared == 0.0] = 1.0
    chunk = max(1, DISTANCES_PER_CHUNK // len(starts))
    best = np.empty(len(points))
    nearest = np.empty(len(points), dtype=int)
    for first in range(0, len(points), chunk):
        block = points[first:first + chunk]
        rel = block[:, None, :] - starts[None, :, :]
        t = np.clip(np.einsum("ijk,jk->ij", rel, along) / squared[None, :], 0.0, 1.0)
        gap = rel - t[:, :, None] * along[None, :, :]
        dist = np.sqrt(np.einsum("ijk,ijk->ij", gap, gap))
        nearest[first:first + chunk] = dist.argmin(axis=1)
        best[first:first + chunk] = dist.min(axis=1)
    worst = int(best.argmax())
    point = {a: round(float(points[worst][i]), 4) for i, a in enumerate(PATH_AXES)}
    return float(best[worst]), path.blocks[segment[worst]], other.blocks[nearest[worst]], point


def grade(student_name: str, student: RunSummary, reference_name: str, reference: RunSummary,
          tolerance_mm: float = 0.01) -> Grade:
    """Compare the trainee's run with the reference run."""
    return Grade(student_name, reference_name, (
        _alarms_check(student, reference),
        _path_check(student, reference, tolerance_mm),
        _position_check(student, reference),
        _tools_check(student, reference),
        _time_check(student, reference),
    ))


def _alarm_text(alarms: tuple[tuple[int, str], ...]) -> str:
    return ", ".join(f"{number} at {block}" for number, block in alarms) or "none"


def _alarms_check(student: RunSummary, reference: RunSummary) -> Check:
    weight = WEIGHTS["alarms"]
    same = sorted(n for n, _ in student.alarms) == sorted(n for n, _ in reference.alarms)
    data = {"student": [{"number": n, "block": b} for n, b in student.alarms],
            "reference": [{"number": n, "block": b} for n, b in reference.alarms]}
    if same:
        return Check("alarms", weight, weight, True, f"same ({_alarm_text(student.alarms)})", data=data)
    return Check("alarms", 0.0, weight, False, "differ",
                 (f"- reference: {_alarm_text(reference.alarms)}", f"+ student:   {_alarm_text(student.alarms)}"),
                 data)


def _path_check(student: RunSummary, reference: RunSummary, tolerance_mm: float) -> Check:
    weight = WEIGHTS["path"]
    found = path_deviation(student.path, reference.path)
    data: dict[str, Any] = {"max_deviation_mm": None if math.isinf(found.distance_mm) else round(found.distance_mm, 4),
                            "student_block": found.student_block, "reference_block": found.reference_block,
                            "at_mcs": found.point_mcs, "tolerance_mm": tolerance_mm}
    if math.isinf(found.distance_mm):
        who = "the student's program" if found.missing_in == "student" else "the reference"
        return Check("path", 0.0, weight, False, f"{who} moves no axis", data=data)
    if found.distance_mm <= tolerance_mm:
        return Check("path", weight, weight, True,
                     f"same within {tolerance_mm:g} mm (largest deviation {found.distance_mm:.3f} mm)", data=data)
    share = max(0.0, 1.0 - (found.distance_mm - tolerance_mm) / (PATH_ZERO_MM - tolerance_mm)) \
        if PATH_ZERO_MM > tolerance_mm else 0.0
    where = " ".join(f"{a}{v:.3f}" for a, v in found.point_mcs.items())
    if found.missing_in == "student":
        detail = (f"reference {found.reference_block} passes MCS {where}, {found.distance_mm:.3f} mm "
                  f"from the student's path (nearest: {found.student_block})")
    else:
        detail = (f"student {found.student_block} passes MCS {where}, {found.distance_mm:.3f} mm "
                  f"from the reference path (nearest: {found.reference_block})")
    return Check("path", weight * share, weight, False,
                 f"largest deviation {found.distance_mm:.3f} mm", (detail,), data)


def _position_check(student: RunSummary, reference: RunSummary) -> Check:
    weight = WEIGHTS["position"]
    axes = sorted(set(student.position_wcs) | set(reference.position_wcs))
    gaps = {a: student.position_wcs.get(a, 0.0) - reference.position_wcs.get(a, 0.0) for a in axes}
    data = {"student": student.position_wcs, "reference": reference.position_wcs}
    text = " ".join(f"{a}{student.position_wcs.get(a, 0.0):.3f}" for a in axes)
    if all(abs(g) <= POSITION_TOLERANCE for g in gaps.values()):
        return Check("position", weight, weight, True, f"same ({text})", data=data)
    ref_text = " ".join(f"{a}{reference.position_wcs.get(a, 0.0):.3f}" for a in axes)
    return Check("position", 0.0, weight, False, "differ",
                 (f"- reference: {ref_text}", f"+ student:   {text}"), data)


def _tools_check(student: RunSummary, reference: RunSummary) -> Check:
    weight = WEIGHTS["tools"]
    data = {"student": list(student.tools), "reference": list(reference.tools)}

    def names(tools: tuple[int, ...]) -> str:
        return " ".join(f"T{t}" for t in tools) or "none"

    if student.tools == reference.tools:
        return Check("tools", weight, weight, True, f"same ({names(student.tools)})", data=data)
    return Check("tools", 0.0, weight, False, "differ",
                 (f"- reference: {names(reference.tools)}", f"+ student:   {names(student.tools)}"), data)


def _time_check(student: RunSummary, reference: RunSummary) -> Check:
    weight = WEIGHTS["time"]
    mine, theirs = student.machining_time_s, reference.machining_time_s
    ratio = abs(mine - theirs) / theirs if theirs > 0 else (0.0 if mine == theirs else math.inf)
    data = {"student_s": round(mine, 3), "reference_s": round(theirs, 3)}
    change = f"{(mine - theirs) / theirs * 100:+.1f} %" if theirs > 0 else "reference takes no time"
    text = f"{mine:.2f} s, reference {theirs:.2f} s ({change})"
    if ratio <= TIME_FULL_RATIO:
        return Check("time", weight, weight, True, text, data=data)
    share = max(0.0, 1.0 - (ratio - TIME_FULL_RATIO) / (TIME_ZERO_RATIO - TIME_FULL_RATIO))
    return Check("time", weight * share, weight, False, text, data=data)


CHECK_TITLES = {"alarms": "alarms", "path": "path", "position": "final position",
                "tools": "tools used", "time": "machining time"}


def grade_text(result: Grade) -> str:
    """The readable report: score, one line per check, the differences under it."""
    lines = [f"{result.student} against {result.reference}: score {result.score}/100"]
    for check in result.checks:
        mark = "=" if check.same else "≠"
        lines.append(f"{mark} {CHECK_TITLES[check.name]:<15} {check.text}  [{check.points:.1f}/{check.max_points:g}]")
        lines.extend(f"    {detail}" for detail in check.details)
    return "\n".join(lines)


def grade_json(result: Grade) -> dict[str, Any]:
    """The ``--json`` report."""
    return {
        "student": result.student, "reference": result.reference, "score": result.score,
        "same": result.all_same,
        "checks": {c.name: {"same": c.same, "points": round(c.points, 2), "max_points": c.max_points,
                            "text": c.text, "details": list(c.details), **c.data} for c in result.checks},
    }
