"""What a straight line needs of a frame chain that maps every geometry axis on its own.

The path builder's lines on such a frame (:meth:`PathBuilder._separable_line`) compute each
path axis' machine position as ``(wcs · m_ii + t_i) + tool`` (geometry axes) or through the
frame's axial part (other axes). The factors of those formulas change only with the frame
chain and the tool length vector, not from line to line, so they are gathered once per pair
(:func:`line_frame`) instead of being looked up per axis and line.
"""

from __future__ import annotations

from typing import Mapping, NamedTuple

from nck.geometry.transform import Transform


class AxisMapping(NamedTuple):
    """How one path axis' machine position follows from its WCS value."""

    axis: str
    geometry_index: int  # its place among the geometry axes, -1: not a geometry axis
    scale: float  # m_ii of a geometry axis, the axial factor of another axis
    offset: float  # t_i of a geometry axis, the axial offset of another axis
    tool_mm: float  # the tool length vector's component (0 where it has none)


class LineFrame(NamedTuple):
    """The factors of one frame chain and tool length vector for every path axis."""

    axes: tuple[AxisMapping, ...]  # in the order of the machine's path axes
    scales: tuple[float, float, float]  # m_ii per geometry axis (Transform.axis_affine)
    offsets: tuple[float, float, float]  # t_i per geometry axis


def line_frame(transform: Transform, tool: Mapping[str, float], path_axes: tuple[str, ...],
               geo_axes: tuple[str, ...]) -> LineFrame | None:
    """The factors for ``transform`` and ``tool``, or None when the frame couples axes (a
    rotation, shear: :meth:`Transform.axis_affine` is None)."""
    affine = transform.axis_affine()
    if affine is None:
        return None
    scales, offsets = affine
    rows = []
    for axis in path_axes:
        if axis in geo_axes:
            i = geo_axes.index(axis)
            rows.append(AxisMapping(axis, i, scales[i], offsets[i], tool.get(axis, 0.0)))
        else:
            factor, offset = transform.axial.get(axis, (1.0, 0.0))
            rows.append(AxisMapping(axis, -1, factor, offset, tool.get(axis, 0.0)))
    return LineFrame(tuple(rows), scales, offsets)
