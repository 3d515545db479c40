"""When plain blocks may take the fast path, and the constants they need.

The modal state is *simple* for plain blocks (:mod:`nck.lang.plain`) when the
motion type is G0/G1, the distance mode G90/G91, the feed type G94, radius
compensation off (G40, nothing buffered), no chamfer or rounding pending or
modal, the settable frame current, and the frame chain maps every geometry
axis on its own (:meth:`~nck.geometry.transform.Transform.axis_affine`). Then a plain block only moves the
programmed point: :mod:`nck.interp.plain_run` computes a run of them as one batch
without the general path.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from nck.errors import NcAlarmError
from nck.geometry.trc_canon import compensating
from nck.interp.host import InterpreterHost
from nck.lang.lines import TextLines

GEOMETRY = ("X", "Y", "Z")


@dataclass
class Setup:
    """The constants of a simple modal state for plain blocks."""

    absolute: bool
    kind: int
    feed: float
    position_mm: float
    feed_mm: float
    diameter: tuple[bool, bool, bool]
    scale: tuple[float, float, float]
    offset: tuple[float, float, float]
    tool: tuple[float, float, float]
    wcs: tuple[float, float, float]
    mcs: dict[str, float]  # the modal MCS position (read only)
    axes: tuple[str, ...]  # the machine's path axes


def plain_frame(interp: InterpreterHost) -> tuple[Any, Any] | None:
    """The running frame and its scanned program lines, when the plain path may run there.

    Only a streamed Siemens program (:class:`TextLines`) without a modal call or
    pending repetitions qualifies; otherwise None (the general path goes on).
    """
    state = interp.run_state
    if state.finished or not state.frames:
        return None
    frame = state.frames[-1]
    lines = frame.program.lines
    if not isinstance(lines, TextLines) or frame.modal_call is not None or frame.repeats:
        return None
    return frame, lines


def simple_state(interp: InterpreterHost) -> bool:
    """True when the modal state lets a motion block go straight to the path geometry: a Siemens
    program, nothing held back or waiting, no chamfer/rounding, no G641 rounding that holds every
    element back, radius compensation off, the settable frame current."""
    if interp.dialect.name != "siemens":
        return False
    geo = interp.modal.geometry
    if geo is None or not geo.loaded or geo.pending is not None or geo.rndm_mm or geo.contour_first is not None \
            or geo.waiting:
        return False
    gcodes = interp.modal.gcodes
    if gcodes.get(10) == "G641" and (geo.adis_mm or geo.adispos_mm):
        return False  # every corner is rounded: the path builder holds each element back
    if gcodes.get(7, "G40") != "G40" or compensating(geo) is not False:
        return False
    return geo.frames.settable_code == gcodes.get(8, "G500")


def simple_setup(interp: InterpreterHost, motion: str | None = None) -> Setup | None:
    """The constants of the batch when the modal state is simple, else None.

    ``motion`` is the G0/G1 the block itself programs: it replaces the modal
    motion of group 1 (a ``G1 X… Y…`` after an arc is plain again).
    """
    path = interp.builder.path
    if not simple_state(interp) or not path.cartesian_xyz():
        return None
    modal = interp.modal
    geo = modal.geometry
    gcodes = modal.gcodes
    if geo.spindle_check_due:
        return None
    kind, distance = motion or gcodes.get(1), gcodes.get(14)
    if kind not in ("G0", "G1") or distance not in ("G90", "G91"):
        return None
    if gcodes.get(15, "G94") != "G94" or geo.feed_type != "G94":
        return None
    if geo.feed_override_pct != 100.0 or geo.accel_pct:
        return None  # OVR and ACC go through the path builder
    affine = geo.frames.transform().axis_affine()
    if affine is None:
        return None
    try:
        tool = path.tool_vector(modal)
    except NcAlarmError:
        return None
    units = path.units(modal)
    if units.feed_mm != geo.feed_unit_mm:
        return None  # F was programmed under another G70/G71/G700/G710: the path builder keeps it
    if gcodes.get(29) == "DIAM90":
        return None  # diameter or radius by G90/G91: the path builder
    diameter_on = gcodes.get(29) == "DIAMON"
    return Setup(
        absolute=distance == "G90",
        kind=1 if kind == "G1" else 0,
        feed=float(modal.feed),
        position_mm=units.position_mm,
        feed_mm=units.feed_mm,
        diameter=tuple(diameter_on and a in path.diameter_axes for a in GEOMETRY),  # type: ignore[arg-type]
        scale=affine[0],
        offset=affine[1],
        tool=(float(tool.get("X", 0.0)), float(tool.get("Y", 0.0)), float(tool.get("Z", 0.0))),
        wcs=(float(geo.wcs_mm.get("X", 0.0)), float(geo.wcs_mm.get("Y", 0.0)), float(geo.wcs_mm.get("Z", 0.0))),
        mcs=modal.position_mcs,
        axes=tuple(path.path_axes),
    )
