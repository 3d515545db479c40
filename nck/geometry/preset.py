"""Set WO / PRESET arithmetic: which translation makes a point read a wanted WCS value.

The frame chain maps ``bcs = T_set + B(S(P(wcs)))`` (``$P_SETFR``, basic, settable and
programmable frame; 002 L28330-28345). Changing the translation of the settable frame by
``Δ`` moves every WCS position by ``-(R_S·P)⁻¹·Δ``; changing ``$P_SETFR`` by ``Δ`` moves it
by ``-(B·S·P)⁻¹·Δ`` (linear parts only). So the WCS error ``e = wcs_now − wanted`` is
removed by ``Δ = L·e`` with ``L`` the linear part of the frames from the target inwards.
Without rotations ``Δ = e`` on the axis set.
"""

from __future__ import annotations

from typing import Mapping

from nck.geometry.chain import FrameChain

TARGET_SETTABLE = "settable"
TARGET_SETFRAME = "setframe"


def translation_change(chain: FrameChain, target: str, wcs_error: Mapping[str, float]) -> dict[str, float]:
    """The change of the ``target`` frame's translation (mm, per axis) that removes ``wcs_error``.

    ``target`` is :data:`TARGET_SETTABLE` or :data:`TARGET_SETFRAME`; ``wcs_error`` holds
    ``wcs_now − wanted`` of the axes being set (mm).
    """
    if target == TARGET_SETFRAME:
        inner = chain.transform()
    elif target == TARGET_SETTABLE:
        inner = chain.settable.to_transform() @ chain.programmable.to_transform()
    else:
        raise ValueError(f"unknown target {target!r}")
    change = inner.apply_vector({axis: float(value) for axis, value in wcs_error.items()})
    return {axis: value for axis, value in change.items() if abs(value) > 1e-12}


def wcs_of_point(chain: FrameChain, point_bcs: Mapping[str, float]) -> dict[str, float]:
    """The WCS position of a workpiece point (no tool offset) under the whole chain."""
    return chain.transform().inverse().apply(dict(point_bcs))
