"""The frame chain from the WCS to the BCS, and settable frames from the NC data.

Order of the chain (Function Manual K2, complete frame), reduced to the parts
this trainer models::

    BCS  <- basic frame  <- settable frame (G500, G54…G57, G505…G599)  <- programmable frame  <- WCS

i.e. ``bcs = base(settable(programmable(wcs)))``. Block-wise suppression:

* ``G53`` suppresses the settable and the programmable frame;
* ``G153`` additionally the basic frame;
* ``SUPA`` like G153 (plus DRF, external zero offset and overlaid motion,
  which this trainer does not model).

``G500`` selects the settable frame called G500 (normally a zero frame).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from nck.geometry.frames import Frame, rpy_matrix, as_matrix3
from nck.geometry.planes import GEOMETRY_AXES_DEFAULT
from nck.geometry.transform import Transform
from nck.ncdata import WorkOffset

SUPPRESSION_CODES = ("G53", "G153", "SUPA")


def frame_from_work_offset(
    offset: WorkOffset,
    geometry_axes: tuple[str, str, str] = GEOMETRY_AXES_DEFAULT,
    data_mm: float = 1.0,
) -> Frame:
    """Turn a stored work offset (``$P_UIFR[n]``, basic frame) into a :class:`Frame`.

    ``data_mm`` converts the stored translations into mm (1.0 for a metric basic
    system). Rotations are angles in degrees about geometry axes 1, 2, 3.
    """
    angles = [0.0, 0.0, 0.0]
    for axis, value in offset.rot.items():
        if axis in geometry_axes:
            angles[geometry_axes.index(axis)] = float(value)
    return Frame(
        geometry_axes=geometry_axes,
        trans={a: float(v) * data_mm for a, v in offset.trans.items()},
        fine={a: float(v) * data_mm for a, v in offset.fine.items()},
        rotation=as_matrix3(rpy_matrix((angles[0], angles[1], angles[2]))),
        scale={a: float(v) for a, v in offset.scale.items() if float(v) != 0.0},
        mirror=frozenset(a for a, flag in offset.mirror.items() if flag),
    )


@dataclass(frozen=True, eq=False)
class FrameChain:
    """The active frames of the channel.

    Attributes:
        base: the complete basic frame (``$P_ACTBFRAME``).
        settable_code: the active member of G group 8 (``G500``, ``G54`` …).
        settable: the active settable frame (``$P_IFRAME``).
        programmable: the programmable frame (``$P_PFRAME``).
    """

    base: Frame = field(default_factory=Frame)
    settable_code: str = "G500"
    settable: Frame = field(default_factory=Frame)
    programmable: Frame = field(default_factory=Frame)

    @property
    def geometry_axes(self) -> tuple[str, str, str]:
        """Names of the geometry axes the frames act on."""
        return self.programmable.geometry_axes

    def with_programmable(self, frame: Frame) -> "FrameChain":
        """Return the chain with a new programmable frame."""
        return replace(self, programmable=frame)

    def with_settable(self, code: str, frame: Frame) -> "FrameChain":
        """Return the chain with another settable frame selected (G500, G54 …)."""
        return replace(self, settable_code=code, settable=frame)

    def with_base(self, frame: Frame) -> "FrameChain":
        """Return the chain with a new basic frame."""
        return replace(self, base=frame)

    def transform(self, suppress: str | None = None) -> Transform:
        """WCS → BCS mapping, with the frames that ``suppress`` (G53/G153/SUPA) leaves out."""
        if suppress is not None and suppress not in SUPPRESSION_CODES:
            raise ValueError(f"not a frame suppression: {suppress}")
        cache: dict = self.__dict__.setdefault("_transforms", {})  # the chain is immutable
        if suppress in cache:
            return cache[suppress]
        result = Transform.identity(self.geometry_axes)
        if suppress not in ("G153", "SUPA"):
            result = result @ self.base.to_transform()
        if suppress is None:
            result = result @ self.settable.to_transform() @ self.programmable.to_transform()
        cache[suppress] = result
        return result

    def settable_zero_transform(self) -> Transform:
        """SZS → BCS mapping (basic and settable frame, no programmable frame)."""
        return self.base.to_transform() @ self.settable.to_transform()
