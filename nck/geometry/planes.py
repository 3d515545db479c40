"""Working planes G17 / G18 / G19.

A plane names which geometry axis is the abscissa, which the ordinate and
which is perpendicular to it (the applicate, also the tool length axis of a
milling tool). The assignment follows the order of the geometry axes, not
their names: with geometry axes (X, Y, Z)

========  =========  ========  =========
code      abscissa   ordinate  applicate
========  =========  ========  =========
``G17``   X          Y         Z
``G18``   Z          X         Y
``G19``   Y          Z         X
========  =========  ========  =========
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

GEOMETRY_AXES_DEFAULT = ("X", "Y", "Z")

# plane code -> (abscissa, ordinate, applicate) as indices of the geometry axes
PLANE_AXIS_INDICES: dict[str, tuple[int, int, int]] = {
    "G17": (0, 1, 2),
    "G18": (2, 0, 1),
    "G19": (1, 2, 0),
}

Vec3 = tuple[float, float, float]

_NORMALS: tuple[Vec3, Vec3, Vec3] = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
"""The unit vector of geometry axis 1, 2, 3 (a plane's normal is its applicate's)."""


@dataclass(frozen=True, slots=True)
class Plane:
    """One working plane over three named geometry axes.

    Attributes:
        code: ``G17``, ``G18`` or ``G19``.
        indices: (abscissa, ordinate, applicate) as indices 0..2 of the geometry axes.
        geometry_axes: names of geometry axes 1..3 of the channel.
    """

    code: str
    indices: tuple[int, int, int]
    geometry_axes: tuple[str, str, str]

    @property
    def abscissa(self) -> str:
        """Name of the first axis of the plane (horizontal axis of the plane)."""
        return self.geometry_axes[self.indices[0]]

    @property
    def ordinate(self) -> str:
        """Name of the second axis of the plane."""
        return self.geometry_axes[self.indices[1]]

    @property
    def applicate(self) -> str:
        """Name of the axis perpendicular to the plane (infeed / tool length axis)."""
        return self.geometry_axes[self.indices[2]]

    @property
    def axes(self) -> tuple[str, str, str]:
        """(abscissa, ordinate, applicate) names."""
        return (self.abscissa, self.ordinate, self.applicate)

    def to_plane(self, point: Sequence[float]) -> Vec3:
        """Reorder a geometry-axis vector (axis 1, 2, 3) into (abscissa, ordinate, applicate)."""
        a, o, p = self.indices
        return (float(point[a]), float(point[o]), float(point[p]))

    def from_plane(self, point: Sequence[float]) -> Vec3:
        """Reorder an (abscissa, ordinate, applicate) vector back into geometry-axis order."""
        out = [0.0, 0.0, 0.0]
        for value, index in zip(point, self.indices):
            out[index] = float(value)
        return (out[0], out[1], out[2])

    def normal(self) -> Vec3:
        """Unit vector of the applicate, in geometry-axis order."""
        return _NORMALS[self.indices[2]]


def plane(code: str, geometry_axes: Sequence[str] = GEOMETRY_AXES_DEFAULT) -> Plane:
    """Return the plane ``G17``/``G18``/``G19`` over the given geometry axes.

    Raises:
        KeyError: for a code that is not a plane selection.
    """
    names = tuple(geometry_axes)
    found = _PLANES.get((code, names))
    if found is None:
        if len(names) != 3:
            raise ValueError("a plane needs exactly three geometry axes")
        found = _PLANES[(code, names)] = Plane(code=code, indices=PLANE_AXIS_INDICES[code],
                                               geometry_axes=names)  # type: ignore[arg-type]
    return found


_PLANES: dict[tuple[str, tuple[str, ...]], Plane] = {}
"""The planes made so far (immutable; every path block asks for its plane)."""
