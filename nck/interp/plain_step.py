"""One plain block, block by block: the fast path of :meth:`Interpreter.step`.

A plain block (:mod:`nck.lang.plain`) under a simple modal state
(:mod:`nck.interp.plain_setup`) gives the :class:`BlockResult` and the
canonical :class:`~nck.canon.Motion` of the general path — the same values,
computed with the same floating-point operations — without the parser, the
per-block snapshot or the motion builder. Anything else (and any block that
would raise an alarm) returns None, and the general path interprets it.
"""

from __future__ import annotations

from nck import canon
from nck.geometry.contour_aids import LineElement
from nck.geometry.path_builder import end_tangent, round_position
from nck.interp.api import BLOCK_COST_S, BlockResult
from nck.interp.host import InterpreterHost
from nck.interp.plain_setup import GEOMETRY, Setup, plain_frame, simple_setup
from nck.lang.plain import G_CODES, PLAIN_LINE, axis_value, feed_value


def step_plain(interp: InterpreterHost) -> BlockResult | None:
    """Interpret the next block if it is plain and the state simple (else None: the general path).

    Gives exactly the general path's :class:`BlockResult` (the same canonical
    motion) and state, without parser, snapshot or motion builder.
    """
    found = plain_frame(interp)
    if found is None:
        return None
    frame, lines = found
    state, program = interp.run_state, frame.program
    index = frame.pc
    if program.plain_run_end(index) <= index:
        return None
    raw = lines.raw(index)
    line_match = PLAIN_LINE.fullmatch(raw)
    if line_match is None:
        return None
    number, motion_a, distance_a, distance_b, motion_b, x, y, z, f = line_match.groups()
    motion = motion_a or motion_b
    setup = simple_setup(interp, None if motion is None else G_CODES[motion])
    if setup is None:
        return None
    distance = distance_a or distance_b
    if distance is not None and (distance == "G91") == setup.absolute:
        return None  # a change of G90/G91: the general path
    feed = setup.feed
    if f is not None:
        feed = feed_value(f)
        if feed <= 0.0:
            return None  # alarm 14800
    kind = setup.kind if motion is None else (1 if G_CODES[motion] == "G1" else 0)
    texts = (x, y, z)
    moving = x is not None or y is not None or z is not None
    if moving and kind == 1 and feed <= 0.0:
        return None  # alarm 10860
    modal = interp.modal
    source = canon.Source(program.name, index + 1, int(number) if number is not None else None)
    if motion is not None or distance is not None or f is not None or moving:
        frame.def_open = False
    if motion is not None:
        modal.gcodes[1] = "G1" if kind else "G0"
    if distance is not None:
        modal.gcodes[14] = distance
    modal.feed = feed
    commands: tuple[canon.CanonCommand, ...] = ()
    if moving:
        commands = (_move(interp, setup, source, kind, texts),)
    frame.pc = index + 1
    interp.skip_run = None
    return BlockResult(
        source=source, text=raw, commands=commands, action_block=bool(commands), finished=False,
        cost_s=BLOCK_COST_S,
        extras={"level": len(state.frames), "preprocessing_stop": False,
                "single_block_off": frame.single_block_off, "display_off": frame.display_off},
    )


def _move(interp: InterpreterHost, setup: Setup, source: canon.Source, kind: int,
          texts: tuple[str | None, str | None, str | None]) -> canon.Motion:
    """The motion of one plain block; updates the modal state like the path builder."""
    modal = interp.modal
    geo = modal.geometry
    start = geo.wcs_mm
    end = dict(start)
    for axis in GEOMETRY:
        end.setdefault(axis, 0.0)
    machine_geo: dict[str, float] = {}
    for i, axis in enumerate(GEOMETRY):
        text = texts[i]
        if text is None:
            continue
        value_mm = axis_value(text) * setup.position_mm
        if setup.diameter[i]:
            value_mm = value_mm / 2.0
        end[axis] = value_mm if setup.absolute else end.get(axis, 0.0) + value_mm
        machine_geo[axis] = round_position((end[axis] * setup.scale[i] + setup.offset[i]) + setup.tool[i])
    start_mcs = dict(modal.position_mcs)
    end_mcs = {axis: machine_geo[axis] if axis in machine_geo else round_position(start_mcs.get(axis, 0.0))
               for axis in setup.axes}
    geo.wcs_mm = end
    geo.tangent = end_tangent(LineElement(
        (float(start.get("X", 0.0)), float(start.get("Y", 0.0)), float(start.get("Z", 0.0))),
        (float(end["X"]), float(end["Y"]), float(end["Z"]))))
    path = interp.builder.path
    modal.position_wcs = path.wcs_display(end, modal)
    modal.position_mcs = dict(end_mcs)
    gcodes = modal.gcodes
    shared = path.shared_gcodes(gcodes)
    rapid = kind == 0
    return canon.Motion(
        kind="G1" if kind else "G0", source=source, plane=gcodes.get(6, "G17"),
        end_wcs=_reported_wcs(interp, setup, texts, end, end_mcs), end_mcs=end_mcs, start_mcs=start_mcs,
        feed=None if rapid else modal.feed,
        feed_mm_min=None if rapid else modal.feed * setup.feed_mm,
        exact_stop=gcodes.get(10, "G60") == "G60", exact_stop_window=gcodes.get(12, "G601"),
        gcodes=shared,
    )


def _reported_wcs(interp: InterpreterHost, setup: Setup, texts: tuple[str | None, str | None, str | None],
                  end_mm: dict[str, float], end_mcs: dict[str, float]) -> dict[str, float]:
    """The block's WCS end as reported: an axis it does not program stands where it is, seen
    through the active frame (the path builder's ``_report_actual``)."""
    reported = end_mm
    for i, axis in enumerate(GEOMETRY):
        if texts[i] is None and axis in end_mcs:
            actual_mm = (end_mcs[axis] - setup.tool[i] - setup.offset[i]) / setup.scale[i]
            if abs(actual_mm - end_mm[axis]) > 1e-6:
                if reported is end_mm:
                    reported = dict(end_mm)
                reported[axis] = actual_mm
    if reported is end_mm:
        return dict(interp.modal.position_wcs)
    return interp.builder.path.wcs_display(reported, interp.modal)
