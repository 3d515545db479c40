"""The settings for manual mode that measuring in JOG uses: retraction plane, safety distance,
measuring feed (the JOG Settings window; retained in the section ``manual_settings``).

* ``retraction_plane_mm`` — the WCS Z a 3D probe returns to after it measured a Z surface
  (above the workpiece, in the active work offset);
* ``safety_distance_mm`` — how far the probe backs off a surface after it switched, and half
  the longest way it searches: CYCLE START in Measure workpiece moves the probe at most
  2 × the safety distance towards the edge;
* ``measuring_feed_mm_min`` — the feed of that searching move (a probe needs a low, constant
  feed to switch repeatably).

Trainer choice: the manuals here describe neither the panel's manual-mode settings nor the
data they are kept in, so these are the trainer's own retained values, not setting data with
a SINUMERIK number; changing them needs no protection level, like the JOG feed SD41110.
Defaults: retraction plane 50 mm, safety distance 5 mm, measuring feed 300 mm/min.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping

from nck.refused import Refused


@dataclass(frozen=True, slots=True)
class ManualSettings:
    """Retraction plane (WCS Z), safety distance and measuring feed of manual mode."""

    retraction_plane_mm: float = 50.0
    safety_distance_mm: float = 5.0
    measuring_feed_mm_min: float = 300.0


FIELDS = ("retraction_plane_mm", "safety_distance_mm", "measuring_feed_mm_min")
POSITIVE = ("safety_distance_mm", "measuring_feed_mm_min")


class BadSetting(Refused, ValueError):
    """A manual setting that is no number or, for the distance and the feed, not above 0."""


def settings_to_plain(settings: ManualSettings) -> dict[str, float]:
    """The settings as JSON-ready data."""
    return {name: getattr(settings, name) for name in FIELDS}


def settings_from_plain(data: Mapping[str, Any]) -> ManualSettings:
    """The settings of :func:`settings_to_plain`'s form (missing ones at their default);
    :class:`BadSetting` (a ``ValueError``) for a value that is no number or, for the distance
    and the feed, not above 0."""
    values: dict[str, float] = {}
    for name in FIELDS:
        if name not in data:
            continue
        value = data[name]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise BadSetting("manual_setting_not_number", name=name, value=str(value))
        if name in POSITIVE and value <= 0.0:
            raise BadSetting("manual_setting_not_positive", name=name)
        values[name] = float(value)
    return ManualSettings(**values)
