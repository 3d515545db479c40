"""The plain-block fast path of ``nck check`` is the general interpreter, only faster.

Every program runs twice through :func:`nck.headless.interpret_only`: once on
the general path (``Interpreter.fast_path`` off) and once with runs of plain
blocks planned as batches (:mod:`nck.interp.plain_run`). Status, block count,
machine time (bit for bit), alarms with their line and block number, and the
modal state afterwards must be identical. Block by block (the kernel's and the
editor's way), the fast step of simple motion blocks (:mod:`nck.interp.simple_step`:
G0-G3 with I/J/K or CR=, F, N, comments) must give the same block results — the
same canonical motions, arc centres included, and alarms at the same line — as
the general path.
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Iterator

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bench.corpus import cam_milling
from nck.geometry.path_builder import PathBuilder
from nck.headless import interpret_only
from nck.interp import plain_run, simple_step
from nck.interp import program as program_module
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.lang.plain import is_plain
from nck.lang.parser import parse_block
from nck.machine import load_machine
from nck.ncdata import NcData

MACHINE = load_machine()

BLOCK_BUDGET = 2_000
"""Blocks a random program may run: ``GOTOB START`` after ``START:`` loops for ever without
motion (no machine time passes), so both paths end at this budget instead (found in CI, whose
fixed Hypothesis seed drew such a program)."""


@contextmanager
def _paths(fast: bool) -> Iterator[None]:
    """The fast paths on (``fast``) or the reference: the general block path, with lines and
    circles built as elements (:attr:`PathBuilder.separable_lines` off)."""
    Interpreter.fast_path = fast
    PathBuilder.separable_lines = fast
    try:
        yield
    finally:
        Interpreter.fast_path = True
        PathBuilder.separable_lines = True


def _run(text: str, fast: bool, **limits: Any) -> dict[str, Any]:
    limits.setdefault("max_blocks", BLOCK_BUDGET)
    program_module._RECENT.clear()
    with _paths(fast):
        result = interpret_only(MACHINE, MemorySource(), NcData(), "PLAIN.MPF", text=text,
                                keep_commands=not fast, **limits)
    interp = result.interpreter
    assert interp is not None
    modal = interp.modal
    geo = modal.geometry
    return {
        "status": result.status,
        "blocks": result.blocks,
        "machine_time_s": result.machine_time_s,
        "alarms": [(a.number, a.file, a.line, a.n, a.params) for a in result.alarms],
        "gcodes": dict(modal.gcodes),
        "position_wcs": dict(modal.position_wcs),
        "position_mcs": dict(modal.position_mcs),
        "feed": modal.feed,
        "geometry": None if geo is None else (dict(geo.wcs_mm), geo.tangent),
        "state": (interp.run_state.blocks, interp.run_state.finished,
                  [(f.pc, f.def_open) for f in interp.run_state.frames]),
    }


@pytest.fixture(autouse=True, scope="module")
def batches_of_any_length() -> Any:
    """Runs of every length take the batch path here (by default a run shorter than
    ``MIN_BATCH_LINES`` goes block by block), so the random programs exercise the batches."""
    default = plain_run.MIN_BATCH_LINES
    plain_run.MIN_BATCH_LINES = 1
    yield
    plain_run.MIN_BATCH_LINES = default


def _same(text: str, **limits: Any) -> dict[str, Any]:
    general, fast = _run(text, False, **limits), _run(text, True, **limits)
    assert fast == general, text
    return fast


# ----------------------------------------------------------------------------- programs
def _number(draw: Any, signed: bool) -> str:
    whole = draw(st.integers(0, 2000))
    style = draw(st.sampled_from(["int", "dec", "dec", "dot", "lead", "zero"]))
    text = {"int": f"{whole}", "dec": f"{whole}.{draw(st.integers(0, 999)):03d}", "dot": f"{whole}.",
            "lead": f".{draw(st.integers(0, 99))}", "zero": draw(st.sampled_from(["0", "0.0", "00.000"]))}[style]
    if signed:
        text = draw(st.sampled_from(["", "", "-", "+"])) + text
    return text


@st.composite
def plain_lines(draw: Any) -> str:
    words: list[str] = []
    if draw(st.booleans()):
        words.append(f"N{draw(st.integers(0, 99999))}")
    gwords = []
    if draw(st.integers(0, 3)) == 0:
        gwords.append(draw(st.sampled_from(["G0", "G1", "G00", "G01"])))
    if draw(st.integers(0, 8)) == 0:
        gwords.append(draw(st.sampled_from(["G90", "G91"])))
    words += draw(st.permutations(gwords))
    for axis in "XYZ":
        if draw(st.integers(0, 4)):
            words.append(axis + _number(draw, True))
    if draw(st.integers(0, 12)) == 0:
        words.append("F" + draw(st.sampled_from(["0", "100", "2500.5", ".5", "0.0"])))
    separator = draw(st.sampled_from([" ", " ", "\t", ""]))
    line = separator.join(words)
    if draw(st.integers(0, 15)) == 0:
        line += " ;cut X" + _number(draw, True)
    return line


@st.composite
def simple_lines(draw: Any) -> str:
    """A simple motion line (nck.lang.plain.SIMPLE_LINE): G0-G3, X Y Z, a centre I/J/K or a
    radius CR=, F, N and a comment; now and then in another word order or lower case, which the
    general path reads (both paths must agree either way). Random centres often miss the end
    point (alarm 14040 at that line); a half circle drawn incrementally always meets it."""
    if draw(st.integers(0, 2)) == 0:
        half = draw(st.integers(1, 400)) / 8
        helix = f" Z{_number(draw, True)}" if draw(st.booleans()) else ""
        return f"G91 {draw(st.sampled_from(['G2', 'G3']))} X{2 * half} Y0{helix} I{half} J0"
    words: list[str] = []
    if draw(st.booleans()):
        words.append(f"N{draw(st.integers(0, 9999))}")
    if draw(st.integers(0, 2)):
        words.append(draw(st.sampled_from(["G2", "G3", "G02", "G03", "G1", "G0"])))
    if draw(st.integers(0, 8)) == 0:
        words.append(draw(st.sampled_from(["G90", "G91"])))
    for axis in "XYZ":
        if draw(st.integers(0, 2)):
            words.append(axis + _number(draw, True))
    if draw(st.booleans()):
        for centre in "IJK":
            if draw(st.integers(0, 2)):
                words.append(centre + _number(draw, True))
    elif draw(st.integers(0, 2)):
        words.append("CR=" + _number(draw, True))
    if draw(st.integers(0, 6)) == 0:
        words.append("F" + draw(st.sampled_from(["0", "250", "1500.5"])))
    if draw(st.integers(0, 9)) == 0:
        words = draw(st.permutations(words))
    line = draw(st.sampled_from([" ", " ", ""])).join(words)
    if draw(st.integers(0, 9)) == 0:
        line = line.lower()
    if draw(st.integers(0, 9)) == 0:
        line += " ; arc"
    return line


SETUP = [
    "G90", "G91", "G0", "G1", "F1000", "G1 F200", "G70", "G71", "G700", "G54", "G500",
    "TRANS X10 Y-5.5 Z0.25", "ATRANS Z3", "SCALE X2 Y2", "SCALE X0.5", "MIRROR X0", "ROT Z30",
    "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50.5\nT1 D1 M6", "G17", "G19", "G64", "G60", "G95 F0.1 S100 M3",
    "G94", "G41 G1 X0 Y0 F100", "RNDM=1", "R1=0", "M3 S1000", "G18", "G2 F500", "G3 F500", "G91 G2 F300",
]
MIXED = [
    "R1=R1+1", "G2 X10 Y0 CR=5", "G3 X0 Y10 CR=-7", "G2 X5 Y5 I2.5 J2.5", "G1 X=R1", "CHF=0.5", "G40", "G4 F0.1", "M1", "G17 G1 X1", "MSG(\"HI\")",
    "G1 X1 X2", "G0 G1 X1", "X1..5", "G1 F-1 X1", "g1 x5", "G91 G1 X1", "G90", "M30", "T2", "D0",
    "IF R1>3 GOTOF DONE", "DONE:", "GOTOB START", "START:", "G91 X1", "SUPA G0 Z0", "G53 X5",
]


@st.composite
def programs(draw: Any) -> str:
    lines = draw(st.lists(st.sampled_from(SETUP), max_size=4))
    if draw(st.integers(0, 3)):  # mostly with a feed: a G1/G2/G3 block without one is alarm 10860
        lines.insert(0, "G1 F1000")
    body = draw(st.lists(st.one_of(plain_lines(), plain_lines(), simple_lines(), simple_lines(), simple_lines(),
                                   st.sampled_from(MIXED)),
                         min_size=1, max_size=60))
    lines += body
    if draw(st.booleans()):
        lines.append("M30")
    return "\n".join(lines) + draw(st.sampled_from(["", "\n"]))


# ----------------------------------------------------------------------------- properties
@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_fast_path_gives_the_general_result(text: str) -> None:
    _same(text)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs(), st.integers(1, 80), st.floats(0.0005, 3.0))
def test_fast_path_stops_at_the_same_block_budget_and_time(text: str, blocks: int, timeout: float) -> None:
    _same(text, max_blocks=blocks)
    _same(text, timeout_s=timeout)


def _steps(text: str, fast: bool, lines: bool | None = None, machine: Any = MACHINE,
           data: NcData | None = None) -> tuple[list[Any], list[Any], dict[str, Any]]:
    """Block by block, with the fast step on or off (the lines on a separable frame as
    ``lines`` says, else with the fast step)."""
    program_module._RECENT.clear()
    data = NcData() if data is None else data
    interp = Interpreter(machine, MemorySource(), data)
    interp.fast_path = fast
    interp.builder.path.separable_lines = fast if lines is None else lines
    interp.start_text("PLAIN.MPF", text)
    results: list[Any] = []
    alarms: list[Any] = []
    for _ in range(200):
        if interp.finished:
            break
        try:
            results.append(interp.step())
        except Exception as alarm:  # noqa: BLE001 - NC alarms, compared below
            alarms.append((getattr(alarm, "number", repr(alarm)), getattr(alarm, "line", None)))
            break
    modal = interp.modal
    geo = modal.geometry
    state = {"gcodes": dict(modal.gcodes), "wcs": dict(modal.position_wcs), "mcs": dict(modal.position_mcs),
             "feed": modal.feed, "geo": None if geo is None else (dict(geo.wcs_mm), geo.tangent),
             "blocks": interp.run_state.blocks, "frames": [(f.pc, f.def_open) for f in interp.run_state.frames]}
    return results, alarms, state


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_plain_steps_give_the_general_block_results(text: str) -> None:
    assert _steps(text, True) == _steps(text, False), text


FRAMES = [
    "G54", "G500", "TRANS X10 Y-5.5 Z0.25", "ATRANS Z3", "SCALE X2 Y2", "ASCALE Z0.5", "SCALE X-1",
    "MIRROR X0", "AMIRROR Z0", "TRANS", "ROT Y30", "G70", "G71", "G700", "G710", "G90", "G91", "G0", "G1",
    "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50.5\nT1 D1 M6", "D0", "G9", "G60", "G64", "G641 ADIS=0.5", "SUPA",
    "DIAMON", "DIAM90", "DIAMOF", "G95 F0.2", "G94 F500", "OVR=50", "ACC[X]=50", "G93 F2",
]


@st.composite
def frame_lines(draw: Any, axes: str) -> str:
    """A line block under changing frames, tool offsets, units and modes; axes absolute,
    incremental, ``=AC()``/``=IC()``, sometimes only one axis (the others are kept and
    reported where they stand through the new frame)."""
    if draw(st.integers(0, 2)) == 0:
        return draw(st.sampled_from(FRAMES))
    words = [draw(st.sampled_from(["", "G0", "G1", "N5 G1"]))]
    for axis in axes:
        if draw(st.integers(0, 2)):
            if draw(st.integers(0, 3)):
                words.append(axis + _number(draw, True))
            else:
                words.append(f"{axis}={draw(st.sampled_from(['AC', 'IC']))}({draw(st.integers(-8000, 8000)) / 8})")
    if draw(st.integers(0, 5)) == 0:
        words.append("F" + draw(st.sampled_from(["100", "2500.5"])))
    return " ".join(word for word in words if word)


def _g54_data(shift: float, scale: float, mirror: bool) -> NcData:
    """NC data whose G54 translates X by ``shift`` and Z by -shift/2, scales X and Z, mirrors Z."""
    found = NcData()
    g54 = found.settable_frames["G54"]
    g54.trans.update({"X": shift, "Z": -shift / 2})
    if scale != 1.0:
        g54.scale.update({"X": scale, "Z": scale})
    if mirror:
        g54.mirror.update({"Z": True})
    return found


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(["mill", "lathe2"]).flatmap(
    lambda name: st.tuples(st.just(name), st.lists(frame_lines("XYZ" if name == "mill" else "XZ"),
                                                   min_size=1, max_size=40))),
    st.sampled_from([(0.0, 1.0, False), (-12.5, 1.0, False), (30.25, 2.0, True), (7.0, -1.0, False)]))
def test_lines_on_a_separable_frame_give_the_element_path(program: tuple[str, list[str]],
                                                           offset: tuple[float, float, bool]) -> None:
    """:meth:`PathBuilder._separable_line` against the general path's line element, frame
    mapping and emit (:attr:`PathBuilder.separable_lines` off): every block result (end
    points in WCS and MCS, kept axes reported through the frame, feeds), alarm and the state
    after, block by block, under work offsets with translation, scale and mirroring."""
    machine_name, lines = program
    machine = MACHINE if machine_name == "mill" else load_machine(machine_name)
    text = "G1 F1000\n" + "\n".join(lines) + "\nM30\n"

    assert _steps(text, True, machine=machine, data=_g54_data(*offset)) == \
        _steps(text, False, lines=False, machine=machine, data=_g54_data(*offset)), text


def test_arcs_and_lines_take_the_fast_step(monkeypatch: pytest.MonkeyPatch) -> None:
    """A circle with ``CR=`` and the lines after it take the fast step; M30 does not."""
    taken: list[bool] = []
    original = simple_step.SimpleStep.step

    def spy(self: simple_step.SimpleStep, interp: Interpreter) -> Any:
        found = original(self, interp)
        taken.append(found is not None)
        return found

    monkeypatch.setattr(simple_step.SimpleStep, "step", spy)
    text = "G90 G1 X10 Y0 F1000\nG3 X0 Y10 CR=10\nG1 X-5 Y10\nX-5 Y0\nM30"
    results, alarms, _ = _steps(text, True)
    assert not alarms and len(results) == 5
    assert taken[1:] == [True, True, True, False]  # M30 takes the general path
    assert _steps(text, True) == _steps(text, False)


def test_plain_steps_are_taken_in_a_cam_program(monkeypatch: pytest.MonkeyPatch) -> None:
    taken: list[int] = []
    original = simple_step.SimpleStep.step

    def spy(self: simple_step.SimpleStep, interp: Interpreter) -> Any:
        found = original(self, interp)
        taken.append(found is not None)
        return found

    monkeypatch.setattr(simple_step.SimpleStep, "step", spy)
    results, alarms, _ = _steps(_cam(150), True)
    assert not alarms and len(results) == 152 and sum(taken) >= 148


@settings(max_examples=200, deadline=None)
@given(plain_lines())
def test_a_plain_line_is_valid_for_the_parser(line: str) -> None:
    assert is_plain(line)
    block = parse_block(line, 1)
    assert block.skip_level is None and block.label is None


# ----------------------------------------------------------------------------- examples
def _cam(lines: int, g91: bool = False) -> str:
    body = [f"N{10 * i} G1 X{i * 0.25:.3f} Y{-(i % 7) * 1.5:.3f} Z{(i % 3) - 1}" for i in range(lines)]
    return "\n".join(["G91 G17 G64 F3000" if g91 else "G90 G17 G64 F3000", *body, "M30"]) + "\n"


def test_a_cam_program_runs_in_batches(monkeypatch: pytest.MonkeyPatch) -> None:
    committed: list[int] = []
    original = plain_run.PlainBatch.commit

    def spy(self: plain_run.PlainBatch, count: int) -> None:
        committed.append(count)
        original(self, count)

    monkeypatch.setattr(plain_run.PlainBatch, "commit", spy)
    result = _same(_cam(3000), max_blocks=None)  # no budget: the whole program runs
    assert result["status"] == "ended" and result["blocks"] == 3002
    assert sum(committed) >= 2999  # everything but the header and M30


@pytest.mark.parametrize("g91", [False, True])
def test_cam_program_with_offsets_tool_and_inch(g91: bool) -> None:
    header = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=42.125\nT1 D1 M6\nTRANS X12.5 Y-3 Z100\nG70\n"
    _same(header + _cam(500, g91), max_blocks=400)


def test_alarms_inside_a_run_are_found_at_their_line() -> None:
    text = "G1 X1 F100\nG1 X2\nG1 X3 F0\nG1 X4\n"
    result = _same(text)
    assert [(a[0], a[2]) for a in result["alarms"]] == [(14800, 3)]
    text = "G0 X1\nG0 X2\nG1 X3\n"
    assert [(a[0], a[2]) for a in _same(text)["alarms"]] == [(10860, 3)]


def test_negative_zero_and_number_forms() -> None:
    _same("G1 F100\nX-0 Y-0.0 Z+0\nX5. Y.5 Z-.5\nX-0\nG91 X-0.0\nX1 Y-0\n", max_blocks=6)


def test_the_editor_check_skips_the_parser_for_plain_lines(monkeypatch: pytest.MonkeyPatch) -> None:
    from nck import check

    parsed: list[str] = []
    import nck.lang.parser as parser_module

    original = parser_module.parse_block

    def spy(text: str, line: int = 1) -> Any:
        parsed.append(text)
        return original(text, line)

    monkeypatch.setattr(parser_module, "parse_block", spy)
    monkeypatch.setattr(check, "parse_block", spy)
    check._line_problem.cache_clear()
    alarms = list(check.iter_syntax_alarms("G1 X1 Y2 F100\nN20 G0 Z-5\nX1..5\nR1=2\n"))
    assert [(a.number, a.line) for a in alarms] == [(12080, 3)]
    assert parsed == ["X1..5", "R1=2"]


def test_the_kernel_run_is_the_same_with_plain_steps() -> None:
    """``nck run``'s way (the kernel asks for one block at a time): identical segments and time."""
    from nck.headless import run_on_kernel

    text = "G90 G17 G64 F2000\n" + "\n".join(
        f"G1 X{(i % 40) * 0.5:.3f} Y{(i // 40) * 0.25:.3f} Z{-(i % 5) * 0.1:.2f}" for i in range(300)) + "\nM30\n"
    outcomes = []
    for fast in (False, True):
        program_module._RECENT.clear()
        with _paths(fast):
            result = run_on_kernel(MACHINE, MemorySource(), NcData(), "K.MPF", text=text, timeout_s=120.0)
        outcomes.append((result.status, result.blocks, result.machine_time_s, result.segments))
    assert outcomes[0] == outcomes[1]
    assert outcomes[1][0] == "ended" and len(outcomes[1][3]) == 300


# ----------------------------------------------------------------------------- the bench corpus (issue 25)
CORPUS_TOOLS = "".join(f"$TC_DP1[{t},1]=120\n$TC_DP3[{t},1]={60 + 5 * t}\n" for t in range(1, 5))


@pytest.mark.parametrize("min_batch", [1, 16])
def test_fast_path_agrees_on_the_cam_corpus(min_batch: int, monkeypatch: pytest.MonkeyPatch) -> None:
    """CAM output (bench/corpus.py): N numbers, lines with F changes, arcs with I/J and CR=,
    helices, comments, Z steps and tool changes give the general path's result, with batches
    of any length and with the default threshold."""
    monkeypatch.setattr(plain_run, "MIN_BATCH_LINES", min_batch)
    text = CORPUS_TOOLS + cam_milling(1200, seed=3).siemens
    result = _same(text, max_blocks=None)
    assert result["status"] == "ended" and not result["alarms"]


def test_plain_steps_agree_block_by_block_on_the_cam_corpus() -> None:
    text = CORPUS_TOOLS + cam_milling(190, seed=4).siemens
    results, alarms, state = _steps(text, True)
    assert not alarms and len(results) == 190 + 8
    assert (results, alarms, state) == _steps(text, False)


def test_a_line_plan_is_not_taken_to_another_machine() -> None:
    """A loaded program's lines are shared; the precompiled plan of ``G1 X10 Y5`` made on the
    mill (Y an axis) must not run on the lathe (X and Z only: Y is alarm 12550, name not
    defined). Both machines give the general path's result."""
    lathe = load_machine("lathe2")
    text = "G1 F100\nG1 X10 Y5\nM30\n"
    outcomes = []
    for machine in (MACHINE, lathe, MACHINE):
        per_path = []
        for fast in (False, True):
            with _paths(fast):  # the program cache is kept between the runs: the lines (and plans) are shared
                result = interpret_only(machine, MemorySource(), NcData(), "SHARED.MPF", text=text,
                                        keep_commands=True)
            per_path.append((result.status, result.blocks, [(a.number, a.line) for a in result.alarms]))
        assert per_path[0] == per_path[1]
        outcomes.append(per_path[1])
    assert outcomes[0] == outcomes[2] and not outcomes[0][2]
    assert outcomes[1][2] == [(12550, 2)]


@st.composite
def circle_lines(draw: Any, axes: str) -> str:
    """A circle block (G2/G3 with ``CR=``, ``AR=``, I/J/K or ``=AC()`` centres, sometimes
    ``TURN=``) or a line, frame, plane, unit or mode change as in :func:`frame_lines`. End points
    stay within a few mm so that most circles are valid; some are not (14040, 14095)."""
    choice = draw(st.integers(0, 5))
    if choice == 0:
        return draw(st.sampled_from(FRAMES + ["G17", "G18", "G19"]))
    if choice == 1:
        return draw(frame_lines(axes))
    words = [draw(st.sampled_from(["G2", "G3", "N7 G2", "G02"]))]
    centre = draw(st.integers(0, 3))
    full_circle = centre >= 2 and draw(st.booleans())  # no end point: valid for any centre but the start
    for axis in axes:
        if not full_circle and (centre < 2 or draw(st.integers(0, 2))):
            words.append(f"{axis}{draw(st.integers(-80, 80)) / 8}")
    if centre == 0:
        words.append("CR=" + draw(st.sampled_from(["40", "-40", "25.5", "-30", "0.5"])))
    elif centre == 1:
        words.append("AR=" + draw(st.sampled_from(["90", "270", "45.5", "180"])))
    else:
        for letter in "IJK":
            if draw(st.integers(0, 3)):
                value = draw(st.integers(-40, 40)) / 8
                words.append(f"{letter}=AC({value})" if centre == 3 else f"{letter}{value}")
    if draw(st.integers(0, 5)) == 0:
        words.append("TURN=" + draw(st.sampled_from(["1", "2"])))
    return " ".join(words)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(["mill", "lathe2"]).flatmap(
    lambda name: st.tuples(st.just(name), st.lists(circle_lines("XYZ" if name == "mill" else "XZ"),
                                                   min_size=1, max_size=40))),
    st.sampled_from([(0.0, 1.0, False), (-12.5, 1.0, False), (30.25, 2.0, True), (7.0, -1.0, False)]))
def test_circles_on_a_separable_frame_give_the_element_path(program: tuple[str, list[str]],
                                                             offset: tuple[float, float, bool]) -> None:
    """:meth:`PathBuilder._separable_arc` against the general path's arc element, contour aids
    and emit (:attr:`PathBuilder.separable_lines` off): every block result (end points and
    centres in WCS and MCS, the turning axis, kept axes reported through the frame, feeds),
    alarm and the state after, block by block, in every plane under work offsets with
    translation, scale and mirroring, with and without the fast step."""
    machine_name, lines = program
    machine = MACHINE if machine_name == "mill" else load_machine(machine_name)
    text = "G1 F1000\n" + "\n".join(lines) + "\nM30\n"

    reference = _steps(text, False, lines=False, machine=machine, data=_g54_data(*offset))
    assert _steps(text, True, machine=machine, data=_g54_data(*offset)) == reference, text
    assert _steps(text, False, lines=True, machine=machine, data=_g54_data(*offset)) == reference, text


@pytest.mark.parametrize("text", [
    "G0 X1 Y2 Z3 F1000\nG54\nG2 X5 Y2 CR=10\nG3 X1 Y2 I-2 J0\nTRANS Z0.25\nG2 X1 Y2 I2 J0 TURN=1\nM30\n",
    "G0 X1 Y2 Z3 F1000\nG18\nATRANS Y3\nG2 X5 Z3 CR=-10\nAMIRROR X0\nG3 X1 Z3 AR=90\nG19 G2 Y4 Z1 CR=8\nM30\n",
    "G0 X1 Y2 Z3 F1000\n$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50.5\nT1 D1 M6\nG2 X3 Y2 I=AC(2) J=AC(2)\nG91 G3 X-2 Y0 Z1 CR=1\nM30\n",
])
def test_circles_after_a_frame_or_tool_change_give_the_element_path(text: str) -> None:
    """Circles whose applicate (or another axis) is not programmed after a frame or tool
    change: the kept axes stay where they stand in the MCS, the centre's applicate too."""
    def data() -> NcData:
        found = NcData()
        found.settable_frames["G54"].trans.update({"X": -12.5, "Y": 4.0, "Z": 6.25})
        return found

    reference = _steps(text, False, lines=False, data=data())
    assert not reference[1], reference[1]
    assert _steps(text, True, data=data()) == reference
    assert _steps(text, False, lines=True, data=data()) == reference
