"""Translate ISO M/T program text into Siemens-mode blocks, line by line.

:func:`translate` returns one :class:`IsoLine` per source line: the Siemens
blocks it stands for (often one, several for fixed cycles, none for comments)
or the alarm the line raises when it is executed. The translation is static
and in line order; it tracks the modal state that changes how words are read
(G90/G91, G94/G95, group 1, the active drilling cycle, G290/G291).

Mapping onto the Siemens machinery: G20/G21 → G700/G710, G02/G03 R → CR=,
G04 X/U/P → G4 F (seconds; G4 S revolutions under G95 with MD 20734 bit 2,
:mod:`nck.iso.dwell`), G43/G44 H and D → the active tool's edge with that
``$TC_DPH`` H number, G10 L10–L13 → its offsets (:mod:`nck.iso.tool_offsets`), G49 → D0,
G52 → programmable coarse offset, G92 → ATRANS so every axis reads its current position,
G92.1 → clears G52 and G92, G10 L2 Pn → ``$P_UIFR[n]`` (G54…G59, G58/G59 = G505/G506),
G68/G69, G51/G50, G51.1/G50.1 → programmable frame, G16/G15 → G110/G111 pole with RP/AP,
SD 42440 = 0 after offset changes (:mod:`nck.iso.frames`); Siemens IF/WHILE/FOR/GOTO/CALL
lines pass unchanged, Siemens-only G codes → 12080, MD 20734 bit 3, MD 20154[5] start unit
(:mod:`nck.iso.switching`),
G53 stays non-modal machine coordinates, G61 → G60, M98 → ``CALL "O<nnnn>" P<count>``,
M99 → M17 (main program: restart), M99 P<n> → RET to N<n> of the caller, M30 in an
ISO subprogram ends the program (:mod:`nck.iso.subprograms`); G65/G66/G67/G05 →
``$C_…`` arguments + CALL / modal call, M/G-code macros of MD 10814–10817
(:mod:`nck.iso.macros`). Decimal point (MD 10884/10886):
pocket-calculator notation by default; in standard notation a value without
a point is counted in increments (IS-B 0.001 mm, IS-C 0.0001 mm).

ISO T (:mod:`nck.iso.turning`): X as a diameter (DIAMON), U/W incremental,
code systems B and A (MD 10881), T<tool><offset> (MD 10888), G10 P tool offsets
of the active tool, G92 S (A: G50 S) → LIMS, G96/G97 → G96/G961/G97/G971, G32/G33
F → lead K, G70–G76 and G77–G79 (A: G90/G92/G94) as NC-inserted blocks.

A ``/n`` in the middle of a block is decided at run time (:mod:`nck.iso.skipping`).

Not modelled (yet): a second mid-block ``/n`` in a block is resolved as if its level were
off; M98 with
8-digit program numbers (MD 20734 bit 6); MD alarm 4150 for a macro on a fixed M;
``$P_ISO_STACK``; G44 applies the length like G43; MD 20380 length modes B/C; a
G10 offset change acts at once (manual: at the next T/H/D); the G-group display
shows G43 for G44 (group 8 follows the active edge); the cycle group (9) in the G-group
display always shows G80;
G68/G51.1 act in the programmable frame, not in channel base frames 1–3; mirroring of
non-geometry axes; polar coordinates in drilling cycles; ``$P_AP``; a Siemens
REPEAT with ISO block numbers.
ISO T not modelled: system C; G34; the G74/G75 relief at the bottom; the ISO
group-1 display of G77–G79; contours with pockets (G71/G72 type II); tool nose radius
compensation inside the cycles; G10 P creating a missing offset; a cycle start
point that is not known from the program text (after G28, M98, Siemens blocks:
61607).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nck.alarm_ids import ADDRESS_PROGRAMMED_TWICE, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.number_text import trimmed
from nck.iso import cycles, subprograms, turning
from nck.iso.lexing import Word, split_words
from nck.iso import dwell as iso_dwell
from nck.iso import macros as iso_macros
from nck.iso import tool_offsets as iso_tools
from nck.iso import frames as iso_frames
from nck.iso import skipping, switching
from nck.iso.words import SIMPLE_G, IsoSettings, g_name, word_value

AXES = ("X", "Y", "Z")


@dataclass
class IsoLine:
    """The Siemens blocks of one ISO source line, or the alarm it raises."""

    number: int
    text: str
    blocks: list[str] = field(default_factory=list)
    error: NcAlarmError | None = None


@dataclass
class _Modal:
    iso: bool = True
    absolute: bool = True
    per_rev: bool = False
    motion: str = "G0"
    turning: bool = False  # ISO T: T<tool><offset>
    main: bool = False  # M99 restarts a main program
    cycle: cycles.CycleState = field(default_factory=cycles.CycleState)
    lathe: object = None  # ISO T: nck.iso.turning.LatheState
    frames: iso_frames.FrameTracker = field(default_factory=iso_frames.FrameTracker)


_SUPPORTED_OTHER = {"G54.1", "G4", "G04", "G10", "G28", "G43", "G44", "G49", "G52", "G80", "G92",
                    "G92.1", "G98", "G99", "G290", "G291", "G15", "G50", "G50.1", "G67",
                    "G69", "G97", "G23", "G13.1"}
_SUPPORTED_OTHER |= {"G68", "G51", "G51.1", "G16"}  # nck.iso.frames


def translate(text: str, dialect: str = "iso-m", settings: IsoSettings | None = None,
              start_in_iso: bool = True, main: bool = False) -> list[IsoLine]:
    """Translate a whole ISO program (see module docstring).

    A ``main`` program started in ISO mode begins with the ISO reset motion
    G00 (the Siemens reset value of group 1 is G1).
    """
    settings = settings or IsoSettings()
    modal = _Modal(iso=start_in_iso, turning=dialect == "iso-t", main=main)
    raw_lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    if raw_lines and raw_lines[-1] == "":
        raw_lines.pop()
    if modal.turning:
        turning.attach(modal, raw_lines, settings)
    out: list[IsoLine] = []
    for number, raw in enumerate(raw_lines, start=1):
        line = IsoLine(number, raw)
        if modal.lathe is not None:
            turning.before_line(modal, number - 1)
        try:
            expanded = skipping.expand(raw, number, modal, lambda text, state: _translate_line(
                text, state, settings)) if modal.iso else None  # mid-block /n at run time
            line.blocks = expanded if expanded is not None else _translate_line(raw, modal, settings)
        except NcAlarmError as alarm:
            if switching.pass_to_siemens(alarm, settings.function_mask):
                line.blocks = [raw]  # MD 20734 bit 3: the Siemens translator gets the block
            else:
                line.error = alarm
        if modal.lathe is not None:
            turning.after_line(modal, line)
        out.append(line)
    if any(cycles.INITIAL_Z in block for line in out for block in line.blocks):
        out.insert(0, IsoLine(1, "", [cycles.DECLARATION]))
    if main and start_in_iso:
        first = 1 if out and out[0].blocks[:1] == [cycles.DECLARATION] else 0
        start = turning.START_BLOCK if dialect == "iso-t" else "G0 G64 G291"  # 000 L5005, L5019
        start = f"{start} {settings.start_unit}".strip()
        out.insert(first, IsoLine(1, "", [start]))  # NC-inserted: G291 may share it
    return out


def _switch_word(raw: str) -> str | None:
    upper = raw.upper()
    for code in ("G291", "G290"):
        if code in upper:
            return code
    return None


def _translate_line(raw: str, modal: _Modal, settings: IsoSettings) -> list[str]:
    if not modal.iso:
        switch = _switch_word(raw)
        if switch == "G291":
            modal.iso = True  # the Siemens block itself selects G291 (group 47)
        return [raw]
    stripped = raw.strip()
    if not stripped or stripped.startswith("%"):
        return []
    if switching.siemens_statement(raw):  # IF/WHILE/GOTOF/CALL … run as Siemens blocks
        return [raw]
    skip, words = split_words(raw)
    if words and words[0].letter == "O":
        words = words[1:]  # program number
    if not words:
        return []
    prefix = "" if skip is None else ("/" if skip == 0 else f"/{skip}")
    if modal.lathe is not None:
        blocks = turning.translate_words(words, modal, settings, translate_block_words)
    else:
        blocks = translate_block_words(words, modal, settings)
    if not modal.iso:
        blocks.append("G290")  # back to Siemens mode after this block
    if words[0].letter == "N":  # NC-inserted blocks carry the ISO block number
        label = f"N{int(words[0].value)}"
        blocks = [b if b.startswith(label + " ") or b == label else f"{label} {b}" for b in blocks]
    if prefix and blocks:
        blocks = [f"{prefix} {block}" for block in blocks]
    return blocks


def translate_block_words(words: list[Word], modal: _Modal, settings: IsoSettings) -> list[str]:
    """The Siemens blocks for the words of one ISO block (``modal`` is updated)."""
    switches = [w for w in words if w.letter == "G" and g_name(w) in ("G290", "G291")]
    if switches and any(w.letter != "N" for w in words if w not in switches) or len(switches) > 1:
        raise NcAlarmError(SYNTAX_ERROR, f"{g_name(switches[0])} not alone in block")  # 003 L393
    macro = iso_macros.macro_block(words, modal, settings, translate_block_words)  # G65/G66/G67/G05
    if macro is not None:
        return macro
    gcodes: list[str] = []
    addresses: dict[str, Word] = {}
    others: list[Word] = []
    for word in words:
        if word.letter == "G":
            gcodes.append(g_name(word))
        elif word.letter in addresses and word.letter not in ("M",):
            raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, word.letter)
        elif word.letter == "M":
            others.append(word)
        else:
            addresses[word.letter] = word
    if "G290" in gcodes:
        modal.iso = False
        gcodes.remove("G290")
    if "G291" in gcodes:
        gcodes.remove("G291")
    if "G94" in gcodes or "G93" in gcodes:
        modal.per_rev = False
    if "G95" in gcodes:
        modal.per_rev = True
    values = {letter: word_value(word, settings, modal) for letter, word in addresses.items()}
    fixed = addresses.get("F")
    if settings.fixed_feedrates and fixed is not None and not fixed.has_point \
            and fixed.value in range(10):
        # 003 L631-652: F0…F9 (no decimal point) take the feed from SD 42160[n] when it is read
        values["F"] = f"=$SC_EXTERN_FIXED_FEEDRATE_F1_F9[{int(fixed.value)}]"  # type: ignore[assignment]
    number = f"N{int(values.pop('N'))} " if "N" in values else ""
    for code in gcodes:
        if code not in SIMPLE_G and code not in _SUPPORTED_OTHER and _cycle_code(code) is None:
            raise switching.unknown_g(code)
        if code == "G93" and modal.turning:  # inverse-time feed is ISO M only (000 L609)
            raise switching.unknown_g(code)  # 12080 for a Siemens-only G code, else 12470
    framing = iso_frames.frame_codes(words, gcodes, values, modal.frames, modal.absolute,
                                     modal.turning)  # G68/G51/G51.1/G16 …
    if framing.done:
        return [number + block for block in framing.blocks] or ([number] if number else [])
    # modal bookkeeping
    for code in gcodes:
        if code in ("G90",):
            modal.absolute = True
        elif code == "G91":
            modal.absolute = False
        elif code in ("G98", "G99"):
            modal.cycle.return_to_r = code == "G99"
    ms = [word for word in others]
    if any(int(w.value) == 98 for w in ms):
        return [number + subprograms.call_block(values)]
    if any(int(w.value) == 99 for w in ms):
        return [number + subprograms.return_block(values, modal.main)]
    if "G54.1" in gcodes or ("G54" in gcodes and "P" in values):
        if "P" not in values:
            raise NcAlarmError(SYNTAX_ERROR, "G54.1")
        slot = int(values.pop("P"))
        if not 1 <= slot <= 48:
            raise NcAlarmError(SYNTAX_ERROR, f"G54 P{slot}")
        gcodes = [c for c in gcodes if c not in ("G54", "G54.1")] + [f"G{506 + slot}"]
    if any(code in ("G4", "G04") for code in gcodes):
        return [number + iso_dwell.block(addresses, settings, modal.per_rev)]
    if "G10" in gcodes:
        tool_data = None if modal.turning else iso_tools.g10_blocks(values, modal.absolute)
        if tool_data is not None:  # ISO M G10 L10–L13: tool offsets by H number
            return [number + block for block in tool_data]
        return [number + block for block in _g10(values)] or ([number] if number else [])
    if "G92.1" in gcodes:
        return iso_frames.trans_blocks(number, {})
    if "G92" in gcodes:
        moved = [a for a in AXES if a in values]
        if not moved:
            return [number] if number else []
        parts = " ".join(f"{a}=$P_EP[{a}]-({trimmed(values[a])})" for a in moved)
        return [number + "ATRANS " + parts, iso_frames.PRESET]
    if "G52" in gcodes:
        return iso_frames.trans_blocks(number, values)
    if "G28" in gcodes:
        moved = [a for a in AXES if a in values]
        blocks = [number + "G0 " + " ".join(f"{a}{trimmed(values[a])}" for a in moved)] if moved else []
        blocks.append("G74 " + " ".join(f"{a}0" for a in (moved or list(AXES))))
        if modal.motion != "G0":
            blocks.append(modal.motion)  # G28 is non-modal: group 1 stays as it was
        return blocks
    siemens_g: list[str] = []
    cycle_code = None
    if "G53" in gcodes and not modal.absolute:
        for axis in AXES:  # incremental values in a G53 block are skipped
            values.pop(axis, None)
    if modal.turning and "T" in values:  # MD 10888 = 2: two tool digits, then the offset
        digits = addresses["T"].text.lstrip("+")
        tool_digits = settings.tool_digits
        if len(digits) > tool_digits:
            values["T"], values["D"] = int(digits[:tool_digits]), int(digits[tool_digits:])
    if not modal.turning:  # ISO M: H/D numbers select edges through $TC_DPH
        iso_tools.address_offsets(gcodes, values)
    for code in gcodes:
        if code.startswith("G5") and code[1:].isdigit() and int(code[1:]) > 500:
            siemens_g.append(code)
        elif code in SIMPLE_G:
            siemens_g.append(SIMPLE_G[code])
            if SIMPLE_G[code] in ("G0", "G1", "G2", "G3"):
                modal.motion = SIMPLE_G[code]
                modal.cycle.code = None
        elif code == "G80":
            modal.cycle.code = None
            siemens_g.append(modal.motion)
        elif _cycle_code(code) is not None:
            cycle_code = _cycle_code(code)
        elif code in ("G43", "G44") and "H" in values:
            values["D"] = values.pop("H")
        elif code == "G49":
            values.setdefault("D", 0)
    if modal.turning and modal.motion == "G1" and cycle_code is None and modal.cycle.code is None:
        _turning_corner_words(values)
    if cycle_code is not None:
        if modal.cycle.code is None:
            modal.cycle.initial_captured = False
            modal.cycle.params = {}
        modal.cycle.code = cycle_code
    if modal.cycle.code is not None and (cycle_code is not None or any(
            a in values for a in ("X", "Y", "Z", "R"))):
        iso_frames.check_cycle(modal.frames, modal.cycle.code)  # 61814 under G16
        return _cycle_block(number, siemens_g, values, modal, settings)
    poles, polar = iso_frames.polar_words(words, values, siemens_g, modal.frames, modal.turning)
    head = framing.head(siemens_g, modal.absolute, any(a in values for a in AXES))  # SD 42440
    block = (_plain_block(number, siemens_g, values, others, modal) + " " + polar).strip()
    return head + poles + ([block] if block else [])


def _turning_corner_words(values: dict[str, float]) -> None:
    """ISO T, in a straight-line block: R is the radius and C, I or K the chamfer inserted
    at the end of the block, without a comma (000 L4875, L4893-4900; C is no axis here); the
    sign means nothing, the next block gives the direction. The last radius written wins
    over a chamfer (000 L4871), as with the comma forms."""
    for letter, marked in (("R", ",R"), ("C", ",C"), ("I", ",C"), ("K", ",C")):
        if letter in values:
            values.setdefault(marked, abs(values.pop(letter)))


def _cycle_code(code: str) -> int | None:
    if code.startswith("G") and code[1:].isdigit() and int(code[1:]) in cycles.CYCLE_CODES:
        return int(code[1:])
    return None


def _plain_block(number: str, siemens_g: list[str], values: dict[str, float],
                 others: list[Word], modal: _Modal) -> str:
    parts = list(siemens_g)
    for letter in ("X", "Y", "Z", "U", "V", "W", "A", "B", "C", "I", "J", "K"):
        if letter in values:
            parts.append(f"{letter}{trimmed(values[letter])}")
    if "R" in values:
        parts.append(f"CR={trimmed(values['R'])}")
    if ",A" in values:  # the angle of a contour definition (000 L4034-4041, L4056-4080)
        parts.append(f"ANG={trimmed(values[',A'])}")
    if ",R" in values:  # a radius and a chamfer together: the radius is inserted (000 L4039)
        parts.append(f"RND={trimmed(values[',R'])}")
    elif ",C" in values:  # the chamfer along the direction of motion, Siemens CHR (000 L5251-5256)
        parts.append(f"CHR={trimmed(values[',C'])}")
    for letter in ("F", "S", "T", "D"):
        if letter in values:
            value = values[letter]
            if isinstance(value, str):  # D=<edge lookup> (nck.iso.tool_offsets)
                parts.append(f"{letter}{value}")
                continue
            parts.append(f"{letter}{trimmed(value) if letter == 'F' else int(value)}")
    for word in others:
        parts.append(f"M{int(word.value)}")
    return (number + " ".join(parts)).rstrip()


def _cycle_block(number: str, siemens_g: list[str], values: dict[str, float], modal: _Modal,
                 settings: IsoSettings) -> list[str]:
    state = modal.cycle
    for letter in ("Z", "R", "Q", "P", "K"):
        if letter in values:
            state.params[letter] = values[letter]
    if "P" in values:
        state.params["P"] = values["P"] / 1000.0  # dwell in ms
    repeat = int(values.get("K", 1))
    feed = (values["F"] if isinstance(values["F"], str) else trimmed(values["F"])) if "F" in values else None
    hole = [f"{a}{trimmed(values[a])}" for a in ("X", "Y") if a in values]
    blocks = cycles.expand(state, modal.absolute, hole, feed, repeat) if repeat > 0 else []
    head = " ".join(siemens_g)
    if head or number:
        blocks.insert(0, (number + head).strip())
    return blocks


def _g10(values: dict[str, float]) -> list[str]:
    mode = int(values.get("L", 0))
    slot = int(values.get("P", 0))
    if mode == 2 and 1 <= slot <= 6:
        return [f"$P_UIFR[{slot}, {a}, TR]={trimmed(values[a])}" for a in AXES if a in values]
    if mode == 20 and slot >= 1:
        return [f"$P_UIFR[{slot + 6}, {a}, TR]={trimmed(values[a])}" for a in AXES if a in values]
    raise NcAlarmError(SYNTAX_ERROR, f"G10 L{mode}")
