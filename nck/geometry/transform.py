"""Affine transforms between coordinate systems of named axes.

A :class:`Transform` maps a point given in a child system (e.g. the WCS) to
its parent (e.g. the BCS). The three geometry axes share a 4x4 homogeneous
matrix (translation, rotation, scale, mirror); every other axis (rotary or
special axis) only has a factor and an offset, because frames may translate,
scale and mirror such axes but never rotate them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from nck.geometry.planes import GEOMETRY_AXES_DEFAULT, Plane

IDENTITY_TOL = 1e-9


def _identity4() -> np.ndarray:
    return np.eye(4)


@dataclass(frozen=True, eq=False)
class Transform:
    """``parent = matrix · child`` for geometry axes, ``factor·child + offset`` for others.

    Attributes:
        geometry_axes: names of geometry axes 1..3 (the order of the matrix rows).
        matrix: 4x4 homogeneous matrix acting on (axis1, axis2, axis3, 1).
        axial: per special axis ``(factor, offset)``; axes not listed map 1:1.
    """

    geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    matrix: np.ndarray = field(default_factory=_identity4)
    axial: Mapping[str, tuple[float, float]] = field(default_factory=dict)

    # --- construction -------------------------------------------------------------------
    @classmethod
    def identity(cls, geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT) -> "Transform":
        """The transform that changes nothing."""
        return cls(geometry_axes=geometry_axes)

    @classmethod
    def translation(
        cls, offsets: Mapping[str, float], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Transform":
        """A pure shift: ``parent = child + offset`` per axis (mm)."""
        matrix = np.eye(4)
        axial: dict[str, tuple[float, float]] = {}
        for axis, value in offsets.items():
            if axis in geometry_axes:
                matrix[geometry_axes.index(axis), 3] += float(value)
            else:
                axial[axis] = (1.0, float(value))
        return cls(geometry_axes=geometry_axes, matrix=matrix, axial=axial)

    # --- use ---------------------------------------------------------------------------
    def axis_affine(self) -> tuple[tuple[float, float, float], tuple[float, float, float]] | None:
        """(scale, offset) per geometry axis when the matrix maps every axis on its own, else None.

        Only exactly diagonal matrices, per axis a scale of ±1 or no offset, and no offset of
        -0.0: then ``matrix @ point`` is ``point_i * m_ii + t_i`` bit for bit, whatever the order
        of the sum (the zero products add nothing, and a fused multiply-add rounds the same).
        Cached (a transform is immutable).
        """
        cached = self.__dict__.get("_axis_affine", False)
        if cached is not False:
            return cached
        matrix = self.matrix
        linear = matrix[:3, :3]
        found: Any = None
        if not (np.count_nonzero(linear - np.diag(np.diag(linear)))
                or np.count_nonzero(matrix[3] - (0.0, 0.0, 0.0, 1.0))):
            scale = (float(matrix[0, 0]), float(matrix[1, 1]), float(matrix[2, 2]))
            offset = (float(matrix[0, 3]), float(matrix[1, 3]), float(matrix[2, 3]))
            negative_zero = [value == 0.0 and math.copysign(1.0, value) < 0.0 for value in offset]
            if all((abs(scale[i]) == 1.0 or offset[i] == 0.0) and not negative_zero[i] for i in range(3)):
                found = (scale, offset)
        self.__dict__["_axis_affine"] = found
        return found

    def apply(self, point: Mapping[str, float]) -> dict[str, float]:
        """Map a point (all geometry axes present, missing ones count as 0) to the parent."""
        first, second, third = self.geometry_axes
        get = point.get
        values = [float(get(first, 0.0)), float(get(second, 0.0)), float(get(third, 0.0))]
        affine = self.axis_affine()
        if affine is not None and math.isfinite(values[0] + values[1] + values[2]):
            scales, offsets = affine  # the matrix product below, without numpy's call overhead
            out = {first: values[0] * scales[0] + offsets[0], second: values[1] * scales[1] + offsets[1],
                   third: values[2] * scales[2] + offsets[2]}
        else:
            mapped = self.matrix @ np.array(values + [1.0])
            out = {axis: float(mapped[i]) for i, axis in enumerate(self.geometry_axes)}
        for axis, value in point.items():
            if axis in out:
                continue
            factor, offset = self.axial.get(axis, (1.0, 0.0))
            out[axis] = factor * float(value) + offset
        return out

    def apply_vector(self, vector: Mapping[str, float]) -> dict[str, float]:
        """Map a direction (no translation) to the parent."""
        geo = np.array([float(vector.get(a, 0.0)) for a in self.geometry_axes])
        mapped = self.matrix[:3, :3] @ geo
        out = {axis: float(mapped[i]) for i, axis in enumerate(self.geometry_axes)}
        for axis, value in vector.items():
            if axis not in out:
                out[axis] = self.axial.get(axis, (1.0, 0.0))[0] * float(value)
        return out

    def apply_geo(self, point: tuple[float, float, float]) -> tuple[float, float, float]:
        """Map a geometry-axis point given as a 3-tuple."""
        mapped = self.matrix @ np.array([point[0], point[1], point[2], 1.0])
        return (float(mapped[0]), float(mapped[1]), float(mapped[2]))

    def apply_geo_vector(self, vector: tuple[float, float, float]) -> tuple[float, float, float]:
        """Map a geometry-axis direction given as a 3-tuple (no translation)."""
        mapped = self.matrix[:3, :3] @ np.array(vector, dtype=float)
        return (float(mapped[0]), float(mapped[1]), float(mapped[2]))

    def __matmul__(self, other: "Transform") -> "Transform":
        """``(self @ other)(p) == self(other(p))``: apply ``other`` first."""
        axial: dict[str, tuple[float, float]] = {}
        for axis in set(self.axial) | set(other.axial):
            f1, o1 = self.axial.get(axis, (1.0, 0.0))
            f2, o2 = other.axial.get(axis, (1.0, 0.0))
            axial[axis] = (f1 * f2, f1 * o2 + o1)
        return Transform(self.geometry_axes, self.matrix @ other.matrix, axial)

    def inverse(self) -> "Transform":
        """The transform back from the parent to the child.

        Raises:
            ValueError: when the transform is singular (a zero scale factor).
        """
        if abs(np.linalg.det(self.matrix[:3, :3])) < 1e-15:
            raise ValueError("singular transform")
        axial = {}
        for axis, (factor, offset) in self.axial.items():
            if factor == 0.0:
                raise ValueError("singular transform")
            axial[axis] = (1.0 / factor, -offset / factor)
        return Transform(self.geometry_axes, np.linalg.inv(self.matrix), axial)

    # --- properties ---------------------------------------------------------------------
    def is_identity(self, tol: float = IDENTITY_TOL) -> bool:
        """True when the transform changes no coordinate by more than ``tol``."""
        if not np.allclose(self.matrix, np.eye(4), atol=tol, rtol=0.0):
            return False
        return all(abs(f - 1.0) <= tol and abs(o) <= tol for f, o in self.axial.values())

    def determinant(self) -> float:
        """Determinant of the geometry part (negative when it mirrors)."""
        return float(np.linalg.det(self.matrix[:3, :3]))

    def reverses_arcs(self, plane: Plane) -> bool:
        """True when a circle programmed in ``plane`` turns the other way in the parent.

        That is the case when the in-plane part of the transform mirrors (an odd
        number of the two plane axes mirrored): G2 then runs as G3 and vice versa.
        """
        a, o, _ = plane.indices
        m = self.matrix
        return float(m[a, a] * m[o, o] - m[a, o] * m[o, a]) < 0.0
