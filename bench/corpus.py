"""The realistic benchmark corpus: CAM-like milling, turning, subprogram calls, R-parameter
loops and cycle calls, each written twice — in SINUMERIK spelling for ``nck check`` and in
LinuxCNC spelling for ``rs274 -g`` — so the peers interpret the same tool path.

Every program comes from a seeded generator (the same seed gives the same text). Both
spellings describe the same block end points; ``tests/bench/test_corpus.py`` checks that on
small samples (and against ``rs274`` when it is installed).

Spelling differences, chosen once here:

* comments: ``; text`` (SINUMERIK) / ``(text)`` (LinuxCNC);
* arc radius: ``CR=r`` / ``Rr`` (both: positive for at most 180°);
* tool change: ``T3 D1 M6`` / ``T3 M6 G43``; units ``G71`` / ``G21``;
* subprograms: a ``PROC`` in its own ``.SPF`` file / an ``o<n> sub`` in the same file;
* R parameters and labels with ``GOTOB`` / ``#n`` and ``o<n> while``;
* drilling: ``MCALL CYCLE81(RTP, RFP, SDIS, DP)`` / ``G98 G81 … R Z``;
* turning: ``DIAMON`` / ``G7`` (diameter programming), feed per revolution ``G95`` in both.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from pathlib import Path

CAM_CORPUS_BLOCKS = 200_000
"""Lines of the CAM-like milling program of ``make bench``."""

TOOLS_TOML = """\
# Tool table of the benchmark corpus (nck check --tools, see nck/cli_tools.py)
[[edge]]
t = 1
type = 120
length1 = 80
radius = 4
[[edge]]
t = 2
type = 120
length1 = 75
radius = 3
[[edge]]
t = 3
type = 200
length1 = 90
radius = 2.5
[[edge]]
t = 4
type = 120
length1 = 70
radius = 1
"""

LATHE_TOOLS_TOML = """\
# Turning tools of the benchmark corpus (nck check --tools); lengths 0: tool tip = slide
[[edge]]
t = 1
type = 500
position = 3
radius = 0.8
[[edge]]
t = 2
type = 550
position = 3
radius = 0.4
"""

RS274_TOOL_TABLE = """\
T1 P1 Z80 D8 ;end mill
T2 P2 Z75 D6 ;end mill
T3 P3 Z90 D5 ;twist drill
T4 P4 Z70 D2 ;end mill
"""
"""The same tools for ``rs274 -t`` (pocket = tool number; the lathe tools have length 0)."""


@dataclass
class CorpusProgram:
    """One program of the corpus in both spellings.

    Attributes:
        name: file stem (``CAM_MILL``); the main program is ``<name>.MPF`` / ``<name>.ngc``.
        machine: the nck machine (``mill3`` or ``lathe2``).
        siemens: the main program in SINUMERIK spelling.
        linuxcnc: the same program in LinuxCNC spelling.
        blocks: blocks the main program executes (loops and calls unrolled, subprogram bodies
            counted per call), the count behind every blocks/s figure.
        subprograms: SINUMERIK subprogram files (``POCKET.SPF``) and their text.
    """

    name: str
    machine: str
    siemens: str
    linuxcnc: str
    blocks: int
    subprograms: dict[str, str] = field(default_factory=dict)

    @property
    def tools_toml(self) -> str:
        """The tool table this program needs."""
        return LATHE_TOOLS_TOML if self.machine == "lathe2" else TOOLS_TOML


class _Writer:
    """Both spellings, line by line."""

    def __init__(self) -> None:
        self.siemens: list[str] = []
        self.linuxcnc: list[str] = []

    def both(self, text: str) -> None:
        self.siemens.append(text)
        self.linuxcnc.append(text)

    def pair(self, siemens: str, linuxcnc: str) -> None:
        self.siemens.append(siemens)
        self.linuxcnc.append(linuxcnc)

    def comment(self, text: str) -> None:
        self.pair(f"; {text}", f"({text})")

    def texts(self) -> tuple[str, str]:
        return "\n".join(self.siemens) + "\n", "\n".join(self.linuxcnc) + "\n"


def _f(value: float) -> str:
    """A coordinate with 3 decimals, as CAM post-processors write it."""
    return f"{value:.3f}"


# ----------------------------------------------------------------------------- CAM milling
def cam_milling(blocks: int = CAM_CORPUS_BLOCKS, seed: int = 25) -> CorpusProgram:
    """A CAM-like 3-axis milling program of exactly ``blocks`` lines.

    N numbers on every block; ~40 % short lines (some with a new F), ~35 % arcs with I/J,
    ~10 % arcs with CR=, ~4 % helical arcs (Z changes on the arc), ~3 % comment lines; a
    Z step (retract, reposition, plunge) every ~1,500 blocks and a tool change every
    ``blocks/6`` blocks. The path wanders inside ±100 mm in X and Y.
    """
    rng = random.Random(seed)
    out = _Writer()
    out.comment(f"CAM-like milling, {blocks} blocks, seed {seed}")
    out.pair("G17 G90 G64 G71 G54 G94", "G17 G90 G64 G21 G54 G94")
    number = 0
    x = y = 0.0
    z = 5.0
    heading = 0.0
    tool = 0
    tool_every = max(blocks // 6, 50)
    step_every = 1500
    body_end = blocks - 1  # the last line is M30

    def n() -> str:
        nonlocal number
        number += 1
        return f"N{number} "

    def plunge() -> None:
        nonlocal z
        z = -round(rng.uniform(0.5, 6.0), 1)
        out.both(f"{n()}G0 Z5.000")
        out.both(f"{n()}G0 X{_f(x)} Y{_f(y)}")
        out.both(f"{n()}G1 Z{_f(z)} F{rng.choice((200, 300, 400))}")
        out.both(f"{n()}G1 F{rng.choice((1200, 1500, 1800, 2400))}")

    while len(out.siemens) < body_end:
        left = body_end - len(out.siemens)
        if left >= 8 and len(out.siemens) // tool_every >= tool:
            tool = tool % 4 + 1
            out.comment(f"tool {tool}")
            out.both(f"{n()}G0 Z50.000")
            out.pair(f"{n()}T{tool} D1 M6", f"{n()}T{tool} M6 G43")
            out.both(f"{n()}S{rng.choice((6000, 8000, 12000))} M3")
            plunge()
            continue
        if left >= 4 and rng.random() < 1.0 / step_every:
            plunge()
            continue
        if abs(x) > 90.0 or abs(y) > 90.0:
            heading = math.atan2(-y, -x) + rng.uniform(-0.3, 0.3)
        roll = rng.random()
        if roll < 0.03:
            out.comment(f"segment {number}")
        elif roll < 0.45:
            length = rng.uniform(0.2, 3.0)
            heading += rng.uniform(-0.6, 0.6)
            x, y = round(x + length * math.cos(heading), 3), round(y + length * math.sin(heading), 3)
            feed = f" F{rng.choice((900, 1200, 1500, 1800, 2400))}" if rng.random() < 0.15 else ""
            out.both(f"{n()}G1 X{_f(x)} Y{_f(y)}{feed}")
        else:
            ccw = rng.random() < 0.5
            radius = rng.uniform(1.0, 15.0)
            side = 1.0 if ccw else -1.0
            cx = round(x - side * radius * math.sin(heading), 3)
            cy = round(y + side * radius * math.cos(heading), 3)
            radius = math.hypot(x - cx, y - cy)
            start = math.atan2(y - cy, x - cx)
            kind = "G3" if ccw else "G2"
            if roll < 0.83:  # I/J
                sweep = math.radians(rng.uniform(10.0, 120.0))
                end = start + side * sweep
                ex, ey = round(cx + radius * math.cos(end), 3), round(cy + radius * math.sin(end), 3)
                centre = f"I{_f(cx - x)} J{_f(cy - y)}"
                out.both(f"{n()}{kind} X{_f(ex)} Y{_f(ey)} {centre}")
            elif roll < 0.96:  # CR=
                sweep = math.radians(rng.uniform(20.0, 150.0))
                end = start + side * sweep
                ex, ey = round(cx + radius * math.cos(end), 3), round(cy + radius * math.sin(end), 3)
                out.pair(f"{n()}{kind} X{_f(ex)} Y{_f(ey)} CR={_f(radius)}",
                         f"{n()}{kind} X{_f(ex)} Y{_f(ey)} R{_f(radius)}")
            else:  # helix: Z goes down on the arc
                sweep = math.radians(rng.uniform(90.0, 300.0))
                end = start + side * sweep
                ex, ey = round(cx + radius * math.cos(end), 3), round(cy + radius * math.sin(end), 3)
                z = max(round(z - rng.uniform(0.1, 0.8), 3), -30.0)
                out.both(f"{n()}{kind} X{_f(ex)} Y{_f(ey)} Z{_f(z)} I{_f(cx - x)} J{_f(cy - y)}")
            x, y = ex, ey
            heading = end + side * math.pi / 2.0
    out.both(f"{n()}M30")
    siemens, linuxcnc = out.texts()
    return CorpusProgram("CAM_MILL", "mill3", siemens, linuxcnc, blocks)


# ----------------------------------------------------------------------------- turning
def turning(parts: int = 400, seed: int = 25) -> CorpusProgram:
    """A turning program: per part, roughing passes along Z and a finishing contour with
    chamfer-like arcs (CR=), in diameter programming and feed per revolution."""
    rng = random.Random(seed)
    out = _Writer()
    out.comment(f"turning, {parts} parts, seed {seed}")
    out.pair("G18 G90 G71 G54 G95 DIAMON", "G18 G90 G21 G54 G95 G7")
    out.pair("T1 D1", "T1 M6")
    out.both("S1500 M3")
    for part in range(parts):
        stock = rng.choice((40.0, 50.0, 60.0))
        final = stock - rng.choice((8.0, 10.0, 12.0))
        length = rng.choice((30.0, 40.0, 50.0))
        out.comment(f"part {part + 1}: roughing")
        out.pair("T1 D1", "T1 M6")
        out.both(f"G0 X{_f(stock + 2.0)} Z2.000")
        diameter = stock
        while diameter - 2.0 >= final:
            diameter -= 2.0
            out.both(f"G0 X{_f(diameter)}")
            out.both(f"G1 Z{_f(-length)} F0.25")
            out.both(f"G1 X{_f(diameter + 1.0)}")
            out.both("G0 Z2.000")
        out.comment("finishing")
        out.pair("T2 D1", "T2 M6")
        out.both("G0 X0.000 Z2.000")
        out.both("G1 Z0.000 F0.1")
        radius = rng.choice((1.0, 2.0))
        out.both(f"G1 X{_f(final - 2.0 * radius)}")
        out.pair(f"G3 X{_f(final)} Z{_f(-radius)} CR={_f(radius)}",
                 f"G3 X{_f(final)} Z{_f(-radius)} R{_f(radius)}")
        out.both(f"G1 Z{_f(-length + radius)}")
        out.pair(f"G2 X{_f(final + 2.0 * radius)} Z{_f(-length)} CR={_f(radius)}",
                 f"G2 X{_f(final + 2.0 * radius)} Z{_f(-length)} R{_f(radius)}")
        out.both(f"G1 X{_f(stock + 1.0)}")
        out.both(f"G0 X{_f(stock + 2.0)} Z2.000")
    out.both("M30")
    siemens, linuxcnc = out.texts()
    return CorpusProgram("TURNING", "lathe2", siemens, linuxcnc, len(out.siemens))


# ----------------------------------------------------------------------------- subprograms
POCKET_SPF = """\
PROC POCKET(REAL PX, REAL PY, REAL PZ)
; slot with round ends at PX, PY, depth PZ
G0 X=PX Y=PY
G1 Z=PZ F300
G1 X=PX+5 F1200
G3 X=PX+5 Y=PY+10 I0 J5
G1 X=PX
G3 X=PX Y=PY I0 J-5
G0 Z5
RET
"""

POCKET_NGC = """\
o100 sub
(slot with round ends at #1, #2, depth #3)
G0 X#1 Y#2
G1 Z#3 F300
G1 X[#1+5] F1200
G3 X[#1+5] Y[#2+10] I0 J5
G1 X#1
G3 X#1 Y#2 I0 J-5
G0 Z5
o100 endsub
"""

POCKET_BLOCKS = 10  # lines of POCKET.SPF executed per call (PROC … RET)


def subprogram_calls(rows: int = 50, columns: int = 50) -> CorpusProgram:
    """A grid of ``rows × columns`` slots, each one call of the POCKET subprogram with parameters."""
    out = _Writer()
    out.comment(f"subprogram calls, {rows * columns} slots")
    out.pair("G17 G90 G64 G71 G54 G94", "G17 G90 G64 G21 G54 G94")
    out.linuxcnc.extend(POCKET_NGC.splitlines())
    out.pair("T2 D1 M6", "T2 M6 G43")
    out.both("S8000 M3")
    out.both("G0 Z5")
    for row in range(rows):
        for column in range(columns):
            px, py, pz = _f(-95.0 + 3.8 * column), _f(-90.0 + 3.6 * row), _f(-1.0 - (row + column) % 5 * 0.5)
            out.pair(f"POCKET({px}, {py}, {pz})", f"o100 call [{px}] [{py}] [{pz}]")
    out.both("M30")
    siemens, linuxcnc = out.texts()
    blocks = len(out.siemens) + rows * columns * POCKET_BLOCKS
    return CorpusProgram("SUBCALLS", "mill3", siemens, linuxcnc, blocks, {"POCKET.SPF": POCKET_SPF})


# ----------------------------------------------------------------------------- R-parameter loops
def r_parameter_loops(rows: int = 40, points: int = 250) -> CorpusProgram:
    """A zigzag of sine waves: an outer WHILE over the rows, an inner label loop with GOTOB over
    the points; the positions are R-parameter expressions."""
    out = _Writer()
    out.comment(f"R-parameter loops, {rows} rows of {points} points")
    out.pair("G17 G90 G64 G71 G54 G94", "G17 G90 G64 G21 G54 G94")
    out.pair("T1 D1 M6", "T1 M6 G43")
    out.both("S6000 M3")
    out.both("G0 X0 Y0 Z2")
    out.both("G1 Z-1 F400")
    out.pair("R3=0", "#3=0")
    out.pair(f"WHILE R3<{rows}", f"o200 while [#3 LT {rows}]")
    out.pair("R1=0", "#1=0")
    out.pair("LOOP1:", f"o201 while [#1 LT {points}]")
    out.pair("G1 X=R1*0.4 Y=R3*5+SIN(R1*7.2)*2 F1500", "G1 X[#1*0.4] Y[#3*5+SIN[#1*7.2]*2] F1500")
    out.pair("R1=R1+1", "#1=[#1+1]")
    out.pair(f"IF R1<{points} GOTOB LOOP1", "o201 endwhile")
    out.pair("R3=R3+1", "#3=[#3+1]")
    out.pair("ENDWHILE", "o200 endwhile")
    out.both("G0 Z5")
    out.both("M30")
    siemens, linuxcnc = out.texts()
    blocks = 10 + rows * (4 + 4 * points)
    return CorpusProgram("RLOOPS", "mill3", siemens, linuxcnc, blocks)


# ----------------------------------------------------------------------------- cycles
def cycle_calls(rows: int = 40, columns: int = 50) -> CorpusProgram:
    """A hole pattern drilled with a modal CYCLE81 call (``G81`` for rs274)."""
    out = _Writer()
    out.comment(f"drilling cycle, {rows * columns} holes")
    out.pair("G17 G90 G71 G54 G94", "G17 G90 G21 G54 G94")
    out.pair("T3 D1 M6", "T3 M6 G43")
    out.both("S3000 M3 F200")
    out.both("G0 X0 Y0 Z10")
    first = True
    for row in range(rows):
        for column in range(columns):
            position = f"X{_f(-100.0 + 4.0 * column)} Y{_f(-80.0 + 4.0 * row)}"
            if first:
                out.pair("MCALL CYCLE81(10, 0, 2, -5)", "G98")
                out.pair(f"G0 {position}", f"G81 {position} Z-5 R2")
                first = False
            else:
                out.both(position)
    out.pair("MCALL", "G80")
    out.both("G0 Z50")
    out.both("M30")
    siemens, linuxcnc = out.texts()
    return CorpusProgram("CYCLES", "mill3", siemens, linuxcnc, len(out.siemens))


def corpus(scale: float = 1.0) -> list[CorpusProgram]:
    """Every program of the corpus; ``scale`` < 1 makes small samples (tests)."""
    def k(value: int) -> int:
        return max(1, int(value * scale))

    return [
        cam_milling(max(200, k(CAM_CORPUS_BLOCKS))),
        turning(k(400)),
        subprogram_calls(k(50), 50),
        r_parameter_loops(k(40), 250),
        cycle_calls(k(40), 50),
    ]


def write_program(folder: Path, program: CorpusProgram) -> tuple[Path, Path, Path, Path]:
    """Write the program's files into ``folder``: (SINUMERIK main, LinuxCNC file, nck tool table,
    rs274 tool table).

    Subprograms go next to the main program (``nck`` looks there first).
    """
    folder.mkdir(parents=True, exist_ok=True)
    main = folder / f"{program.name}.MPF"
    main.write_text(program.siemens)
    for name, text in program.subprograms.items():
        (folder / name).write_text(text)
    ngc = folder / f"{program.name}.ngc"
    ngc.write_text(program.linuxcnc)
    tools = folder / f"{program.machine}_tools.toml"
    tools.write_text(program.tools_toml)
    table = folder / "rs274.tbl"
    table.write_text(RS274_TOOL_TABLE)
    return main, ngc, tools, table
