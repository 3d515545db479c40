"""ISO dialect mode (ISO M milling / ISO T turning, G291) on top of the Siemens interpreter.

An ISO program is translated line by line into Siemens-mode blocks before it is
parsed (:mod:`nck.iso.translate`). Each ISO line becomes zero or more Siemens
blocks that all carry the ISO line's number, so alarms, the block display and
the motion segments of NC-inserted moves (fixed cycles) point at the ISO block.
"""

from __future__ import annotations

ISO_DIALECTS = ("iso-m", "iso-t")


def is_iso(dialect: str) -> bool:
    """True for the ISO language modes (``iso-m``, ``iso-t``)."""
    return dialect in ISO_DIALECTS
