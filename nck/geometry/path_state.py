"""The geometric modal state of a channel, kept inside the interpreter's modal state.

Everything here survives from block to block and is deep-copied with the
modal state before each block (all members are immutable or plain dicts), so
an alarm in a block leaves it untouched.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from nck.geometry.chain import FrameChain
from nck.geometry.frames import Frame
from nck.geometry.polar import PolarState
from nck.geometry.tangents import end_tangent

Vec3 = tuple[float, float, float]


@dataclass
class PendingCorner:
    """A path element held back until the next one is known (CHF/CHR/RND/RNDM, G641).

    Attributes:
        element: the element in the WCS (mm): a line or an arc.
        aid: ``CHF``, ``CHR``, ``RND`` or ``ADIS`` (G641 rounding by distance).
        size_mm: chamfer length / leg, rounding radius or rounding distance, mm.
        context: what is needed to emit it later (kind, source, transform, tool vector …).
    """

    element: Any
    aid: str
    size_mm: float
    context: dict[str, Any]


@dataclass
class GeometryState:
    """Frames, polar data, programmed position and technology values of the path.

    Attributes:
        frames: base, settable and programmable frame.
        polar: pole and modal RP/AP.
        wcs_mm: the programmed end point per axis in the WCS, in mm (degrees for rotary axes).
        end_tangent_known, end_element: the direction of travel at the end of the last path
            element (WCS), or that element while its direction is not computed yet: only CT
            reads it (:attr:`tangent`).
        pending: an element held back for a chamfer/rounding, or None.
        rndm_mm: modal rounding radius (RNDM), 0 = off.
        adis_mm, adispos_mm: G641 rounding distances of feed and G0 blocks (ADIS, ADISPOS).
        feed_type: the member of G group 15 the programmed F belongs to.
        cutting_speed_m_min: G96 constant cutting speed (S under G96).
        lims_rpm: G96 spindle speed limit (LIMS), None = none.
        axis_feeds: positioning-axis feeds FA[axis] (mm/min or deg/min).
        thread_lead_mm: last programmed thread lead.
        feed_unit_mm: millimetres per length unit of the programmed F, fixed when F is
            programmed: a later G70/G71/G700/G710 keeps the feed's physical value until F is
            programmed again (002 L11662-11667).
        feed_override_pct: programmable feed override OVR (002 L56515-56536), 100 after RESET.
        accel_pct: ACC[axis] acceleration factors in percent (002 L7433-7450), axes not at 100;
            reduced to 100 by RESET/M30 (MD32320 bit 0 = 0, the only setting modelled).
        loaded: False after RESET: settable and basic frame are read again from the NC data.
        setframe_active: the system frame for PRESET and scratching (``$P_SETFR``) is part of
            the chain; after RESET as MD24006 bit 0 says, again with G500/G54… (002 L30660-30664).
        contour_first: the first block of a two-line contour definition (``ANG=`` without a
            plane axis) as (angle in degrees, plane code, the block's words), waiting for the
            block that ends the contour; None otherwise.
        waiting: outputs of blocks that wait for a motion held back before them (chamfer,
            rounding, radius compensation look-ahead), in block order; see
            :mod:`nck.interp.waiting_outputs`.
        spindle_check_due: a speed change of the master spindle was programmed (M3, M4, S)
            and no machining block has started since: the next one checks the set speed
            range first (MD35500).
    """

    frames: FrameChain = field(default_factory=FrameChain)
    polar: PolarState = field(default_factory=PolarState)
    wcs_mm: dict[str, float] = field(default_factory=dict)
    end_tangent_known: Vec3 | None = None
    end_element: Any = None
    pending: PendingCorner | None = None
    rndm_mm: float = 0.0
    adis_mm: float = 0.0
    adispos_mm: float = 0.0
    feed_type: str = "G94"
    cutting_speed_m_min: float = 0.0
    lims_rpm: float | None = None
    axis_feeds: dict[str, float] = field(default_factory=dict)
    thread_lead_mm: float | None = None
    feed_unit_mm: float = 1.0
    feed_override_pct: float = 100.0
    accel_pct: dict[str, float] = field(default_factory=dict)
    loaded: bool = False
    setframe_active: bool = True
    contour_first: tuple[float, str, Any] | None = None
    waiting: tuple[Any, ...] = ()
    spindle_check_due: bool = False

    @property
    def tangent(self) -> Vec3 | None:
        """WCS direction of travel at the end of the last path element (for CT), None when
        unknown; computed from the element the first time it is asked for."""
        if self.end_element is not None:
            self.end_tangent_known, self.end_element = end_tangent(self.end_element), None
        return self.end_tangent_known

    @tangent.setter
    def tangent(self, direction: Vec3 | None) -> None:
        self.end_tangent_known, self.end_element = direction, None

    def tangent_at_end_of(self, element: Any) -> None:
        """The last path element is ``element`` (a line or an arc): :attr:`tangent` is its end direction."""
        self.end_tangent_known, self.end_element = None, element

    def __deepcopy__(self, memo: dict) -> "GeometryState":
        """Snapshots before each block: frames, pole and elements are immutable and shared
        (a shallow copy of the fields without ``copy.copy``'s pickling protocol)."""
        new = object.__new__(type(self))
        new.__dict__.update(self.__dict__)
        new.wcs_mm = dict(self.wcs_mm)
        new.axis_feeds = dict(self.axis_feeds)
        new.accel_pct = dict(self.accel_pct)
        if self.pending is not None:
            new.pending = PendingCorner(self.pending.element, self.pending.aid, self.pending.size_mm,
                                        dict(self.pending.context))
        return new

    def reset(self) -> None:
        """RESET / program end: programmable frame, pole, RNDM, ADIS/ADISPOS and held-back element go.

        The settable and basic frames are re-read from the NC data before the next
        block (their G code comes back to its reset member).
        """
        self.frames = self.frames.with_programmable(Frame(geometry_axes=self.frames.geometry_axes))
        self.polar = PolarState()
        self.tangent = None
        self.pending = None
        self.rndm_mm = 0.0
        self.adis_mm = 0.0
        self.adispos_mm = 0.0
        self.lims_rpm = None
        self.feed_override_pct = 100.0
        self.accel_pct = {}
        self.loaded = False
        self.contour_first = None
        self.waiting = ()
        self.spindle_check_due = False
