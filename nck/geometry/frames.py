"""Frames: translation, fine translation, rotation, scale and mirror of a coordinate system.

A :class:`Frame` holds the components the operator sees (per-axis
translation and fine translation, rotation angles, scale factors, mirror
flags) and maps a point of its own system to the parent system::

    parent = coarse + fine + R · D · point          (geometry axes)
    parent = coarse + fine + d · point              (other axes)

with ``R`` the rotation and ``D``/``d`` the per-axis scale factor, negated for
a mirrored axis. Components are applied in the order of the manual:
translation first, then rotation about the new origin, then scale, then mirror.

Programmable-frame commands (Siemens mode):

* ``TRANS``/``ROT``/``SCALE``/``MIRROR`` replace the whole programmable frame;
* ``ATRANS``/``AROT``/``ASCALE``/``AMIRROR`` are chained onto it, i.e. they act
  in the current (already shifted, rotated, scaled, mirrored) system;
* frame functions ``CTRANS()``, ``CROT()``, ``CSCALE()``, ``CMIRROR()``,
  ``CFINE()`` build a frame from scratch; ``a.chain(b)`` is the ``:`` operator.

Rotations only act on geometry axes. Several axes in one rotation are applied
in the order of ``MD10600 FRAME_ANGLE_INPUT_MODE = 1`` (RPY): about Z, then the
new Y, then the new X. A positive angle turns counter-clockwise looking from
the positive axis towards the origin (right-hand rule), so after ``ROT Z90``
the WCS X axis points along the parent +Y axis.

A chained rotation after a non-uniform scale cannot be written as components
(it would shear); :meth:`Frame.chain` then keeps the scale factors and turns the
rotation as if the scale were uniform. Use :meth:`Frame.to_transform` for the
exact mapping of anything else.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Iterable, Mapping

import numpy as np

from nck.alarm_ids import WRONG_AXIS_TYPE
from nck.errors import NcAlarmError
from nck.geometry.planes import GEOMETRY_AXES_DEFAULT, Plane
from nck.geometry.transform import Transform

# A scale factor of zero would collapse the coordinate system. The manuals give no
# number for it; this project uses 18309 (see data/alarms/geometry.toml).
ALARM_FRAME_SCALE_ZERO = 18309
# Rotation about an axis that is not a geometry axis: "axis is wrong axis type".

Matrix3 = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]
IDENTITY3: Matrix3 = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def as_matrix3(array: np.ndarray) -> Matrix3:
    """The upper-left 3x3 block of ``array`` as a tuple of float rows."""
    rows = [tuple(float(v) for v in array[i]) for i in range(3)]
    return (rows[0], rows[1], rows[2])  # type: ignore[return-value]


def axis_rotation(index: int, angle_deg: float) -> np.ndarray:
    """Right-hand rotation about geometry axis ``index`` (0, 1, 2) by ``angle_deg``."""
    c = math.cos(math.radians(angle_deg))
    s = math.sin(math.radians(angle_deg))
    # Exact values for multiples of 90 degrees keep golden positions free of 1e-17 noise.
    if abs(c) < 1e-15:
        c = 0.0
    if abs(s) < 1e-15:
        s = 0.0
    i, j = (index + 1) % 3, (index + 2) % 3
    m = np.eye(3)
    m[i, i] = c
    m[i, j] = -s
    m[j, i] = s
    m[j, j] = c
    return m


def rpy_matrix(angles_deg: tuple[float, float, float]) -> np.ndarray:
    """Rotation matrix for angles about axes 1, 2, 3 applied in the order 3, 2', 1'' (RPY)."""
    a, b, c = angles_deg
    return axis_rotation(2, c) @ axis_rotation(1, b) @ axis_rotation(0, a)


def rpy_angles(matrix: Matrix3 | np.ndarray) -> tuple[float, float, float]:
    """Angles (about axes 1, 2, 3, degrees) that :func:`rpy_matrix` turns back into ``matrix``.

    Angles are normalised to -180 … 180 (the middle one to -90 … 90).
    """
    m = np.asarray(matrix, dtype=float)
    b = math.degrees(math.asin(max(-1.0, min(1.0, -m[2, 0]))))
    if abs(abs(m[2, 0]) - 1.0) < 1e-12:
        # gimbal lock: only c-a (b=90) or c+a (b=-90) is defined; the control reads it back
        # as the third angle with the first one 0 (crot(x,10,y,90,z,40) → crot(x,0,y,90,z,30), 002 L27986)
        a = 0.0
        c = math.degrees(math.atan2(-m[0, 1], m[1, 1]))
    else:
        a = math.degrees(math.atan2(m[2, 1], m[2, 2]))
        c = math.degrees(math.atan2(m[1, 0], m[0, 0]))

    def clean(v: float) -> float:
        v = round(v, 9)
        return 0.0 if v == 0.0 else (180.0 if v == -180.0 else v)

    return (clean(a), clean(b), clean(c))


@dataclass(frozen=True, eq=False)
class Frame:
    """One frame (base, settable or programmable) as components.

    Attributes:
        geometry_axes: names of geometry axes 1..3.
        trans: coarse translation per axis, mm, in the parent system.
        fine: fine translation per axis, mm, in the parent system.
        rotation: rotation of the geometry axes (3x3, rows = parent axes).
        scale: scale factor per axis (missing = 1).
        mirror: axes that are mirrored.
    """

    geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    trans: Mapping[str, float] = field(default_factory=dict)
    fine: Mapping[str, float] = field(default_factory=dict)
    rotation: Matrix3 = IDENTITY3
    scale: Mapping[str, float] = field(default_factory=dict)
    mirror: frozenset[str] = frozenset()

    # --- constructors (frame functions) ----------------------------------------------------
    @classmethod
    def identity(cls, geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT) -> "Frame":
        """The zero frame (``CTRANS()``)."""
        return cls(geometry_axes=geometry_axes)

    @classmethod
    def ctrans(
        cls, values: Mapping[str, float], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Frame":
        """``CTRANS(axis, value, …)``: a frame that only translates (mm)."""
        return cls(geometry_axes=geometry_axes, trans={a: float(v) for a, v in values.items()})

    @classmethod
    def cfine(
        cls, values: Mapping[str, float], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Frame":
        """``CFINE(axis, value, …)``: a frame with only a fine translation (mm)."""
        return cls(geometry_axes=geometry_axes, fine={a: float(v) for a, v in values.items()})

    @classmethod
    def crot(
        cls, angles_deg: Mapping[str, float], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Frame":
        """``CROT(axis, angle, …)`` / ``ROT X.. Y.. Z..``: rotation about geometry axes (RPY order).

        Raises:
            NcAlarmError: 14092 when an axis is not a geometry axis.
        """
        angles = [0.0, 0.0, 0.0]
        for axis, value in angles_deg.items():
            if axis not in geometry_axes:
                raise NcAlarmError(WRONG_AXIS_TYPE, axis)
            angles[geometry_axes.index(axis)] = float(value)
        matrix = rpy_matrix((angles[0], angles[1], angles[2]))
        return cls(geometry_axes=geometry_axes, rotation=as_matrix3(matrix))

    @classmethod
    def crpl(cls, plane: Plane, angle_deg: float) -> "Frame":
        """``ROT RPL=…`` / ``CRPL``: rotation in the plane, about its applicate (right-hand rule)."""
        matrix = axis_rotation(plane.indices[2], float(angle_deg))
        return cls(geometry_axes=plane.geometry_axes, rotation=as_matrix3(matrix))

    @classmethod
    def cscale(
        cls, factors: Mapping[str, float], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Frame":
        """``CSCALE(axis, factor, …)`` / ``SCALE X.. Y..``.

        Raises:
            NcAlarmError: 18309 for a zero scale factor.
        """
        for axis, value in factors.items():
            if float(value) == 0.0:
                raise NcAlarmError(ALARM_FRAME_SCALE_ZERO, axis)
        return cls(geometry_axes=geometry_axes, scale={a: float(v) for a, v in factors.items()})

    @classmethod
    def cmirror(
        cls, axes: Iterable[str], geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT
    ) -> "Frame":
        """``CMIRROR(axis, …)`` / ``MIRROR X0 Y0``: mirror about the named axes (MD10610 = 0)."""
        return cls(geometry_axes=geometry_axes, mirror=frozenset(axes))

    # --- components ----------------------------------------------------------------------
    def factor(self, axis: str) -> float:
        """Scale factor of an axis, negative when the axis is mirrored."""
        value = float(self.scale.get(axis, 1.0))
        return -value if axis in self.mirror else value

    def offset(self, axis: str) -> float:
        """Total translation (coarse + fine) of an axis, mm."""
        return float(self.trans.get(axis, 0.0)) + float(self.fine.get(axis, 0.0))

    @property
    def rotation_deg(self) -> tuple[float, float, float]:
        """Rotation angles about geometry axes 1, 2, 3 (RPY), as the frame display shows them."""
        return rpy_angles(self.rotation)

    def linear(self) -> np.ndarray:
        """The 3x3 part ``R · D`` acting on the geometry axes."""
        d = np.diag([self.factor(a) for a in self.geometry_axes])
        return np.asarray(self.rotation, dtype=float) @ d

    def axes(self) -> set[str]:
        """Every axis named in a component."""
        return set(self.trans) | set(self.fine) | set(self.scale) | set(self.mirror)

    def is_identity(self, tol: float = 1e-12) -> bool:
        """True when the frame changes nothing."""
        return self.to_transform().is_identity(tol)

    def to_transform(self) -> Transform:
        """The exact mapping of this frame (child → parent)."""
        matrix = np.eye(4)
        matrix[:3, :3] = self.linear()
        for i, axis in enumerate(self.geometry_axes):
            matrix[i, 3] = self.offset(axis)
        axial = {
            axis: (self.factor(axis), self.offset(axis))
            for axis in self.axes()
            if axis not in self.geometry_axes
        }
        return Transform(self.geometry_axes, matrix, axial)

    # --- combination ---------------------------------------------------------------------
    def chain(self, other: "Frame") -> "Frame":
        """``self : other``: ``other`` acts inside the system of ``self``.

        Translations of ``other`` are turned, scaled and mirrored by ``self``;
        scale factors multiply; mirror flags toggle; rotations multiply (the
        rotation of ``other`` is mirrored by the mirror state of ``self``).
        """
        geo = self.geometry_axes
        linear = self.linear()
        trans = dict(self.trans)
        fine = dict(self.fine)
        for source, target in ((other.trans, trans), (other.fine, fine)):
            geo_vec = np.array([float(source.get(a, 0.0)) for a in geo])
            if geo_vec.any():
                turned = linear @ geo_vec
                for i, axis in enumerate(geo):
                    if turned[i] != 0.0 or axis in target:
                        target[axis] = float(target.get(axis, 0.0)) + float(turned[i])
            for axis, value in source.items():
                if axis not in geo:
                    target[axis] = float(target.get(axis, 0.0)) + self.factor(axis) * float(value)
        signs = np.diag([-1.0 if a in self.mirror else 1.0 for a in geo])
        other_rot = signs @ np.asarray(other.rotation, dtype=float) @ signs
        rotation = np.asarray(self.rotation, dtype=float) @ other_rot
        scale = dict(self.scale)
        for axis, value in other.scale.items():
            scale[axis] = float(scale.get(axis, 1.0)) * float(value)
        mirror = self.mirror ^ other.mirror
        return Frame(geo, _clean(trans), _clean(fine), as_matrix3(rotation), scale, mirror)

    # --- programmable-frame commands --------------------------------------------------------
    def atrans(self, values: Mapping[str, float]) -> "Frame":
        """``ATRANS``: additive translation in the current system.

        It is booked into the fine translation (K2 bookkeeping table: ATRANS leaves the
        coarse part alone, so a later ``G58`` that replaces the coarse part keeps it).
        """
        return self.chain(Frame.cfine(values, self.geometry_axes))

    def arot(self, angles_deg: Mapping[str, float]) -> "Frame":
        """``AROT X.. Y.. Z..``: additive rotation about the current axes."""
        return self.chain(Frame.crot(angles_deg, self.geometry_axes))

    def arot_plane(self, plane: Plane, angle_deg: float) -> "Frame":
        """``AROT RPL=…``: additive rotation in the active plane."""
        return self.chain(Frame.crpl(plane, angle_deg))

    def ascale(self, factors: Mapping[str, float]) -> "Frame":
        """``ASCALE``: additive scale in the current system (factors multiply)."""
        return self.chain(Frame.cscale(factors, self.geometry_axes))

    def amirror(self, values: Mapping[str, float], toggle: bool = True) -> "Frame":
        """``AMIRROR``: additive mirroring.

        With ``MD10612 MIRROR_TOGGLE = 1`` (``toggle``, the default) the value is
        ignored and each named axis toggles its mirror state; with 0 the value
        decides: 0 switches mirroring of that axis off, anything else on.
        """
        if toggle:
            return self.chain(Frame.cmirror(values.keys(), self.geometry_axes))
        wanted = {a for a, v in values.items() if float(v) != 0.0}
        unwanted = {a for a, v in values.items() if float(v) == 0.0}
        flips = (wanted - self.mirror) | (unwanted & self.mirror)
        return self.chain(Frame.cmirror(flips, self.geometry_axes))

    def g58(self, values: Mapping[str, float]) -> "Frame":
        """``G58``: replace the coarse translation of the named axes, keep the fine part."""
        trans = dict(self.trans)
        trans.update({a: float(v) for a, v in values.items()})
        return self._replace(trans=trans)

    def g59(self, values: Mapping[str, float]) -> "Frame":
        """``G59``: replace the fine translation of the named axes, keep the coarse part."""
        fine = dict(self.fine)
        fine.update({a: float(v) for a, v in values.items()})
        return self._replace(fine=fine)

    def _replace(self, **changes: object) -> "Frame":
        data: dict[str, object] = dict(
            geometry_axes=self.geometry_axes, trans=self.trans, fine=self.fine,
            rotation=self.rotation, scale=self.scale, mirror=self.mirror,
        )
        data.update(changes)
        return Frame(**data)  # type: ignore[arg-type]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Frame):
            return NotImplemented
        a, b = self.to_transform(), other.to_transform()
        return bool(np.allclose(a.matrix, b.matrix, atol=1e-12)) and _axial_equal(a, b)

    __hash__ = None  # type: ignore[assignment]

    def describe(self) -> dict[str, object]:
        """Components for display (translation, fine, rotation, scale, mirror per axis)."""
        rot = self.rotation_deg
        axes = sorted(self.axes() | set(self.geometry_axes), key=_axis_sort_key(self.geometry_axes))
        return {
            axis: {
                "trans": float(self.trans.get(axis, 0.0)),
                "fine": float(self.fine.get(axis, 0.0)),
                "rot": rot[self.geometry_axes.index(axis)] if axis in self.geometry_axes else 0.0,
                "scale": float(self.scale.get(axis, 1.0)),
                "mirror": axis in self.mirror,
            }
            for axis in axes
        }


def _axis_sort_key(geo: tuple[str, str, str]):
    def key(axis: str) -> tuple[int, str]:
        return (geo.index(axis), "") if axis in geo else (3, axis)

    return key


def _axial_equal(a: Transform, b: Transform) -> bool:
    for axis in set(a.axial) | set(b.axial):
        fa, oa = a.axial.get(axis, (1.0, 0.0))
        fb, ob = b.axial.get(axis, (1.0, 0.0))
        if abs(fa - fb) > 1e-12 or abs(oa - ob) > 1e-12:
            return False
    return True


def _clean(values: dict[str, float]) -> dict[str, float]:
    """Round away floating noise below a nanometre."""
    return {a: (0.0 if abs(v) < 1e-12 else v) for a, v in values.items()}
