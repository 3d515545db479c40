"""ISO dialect mode (ISO M milling / ISO T turning, G291) in front of the Siemens interpreter.

An ISO program is translated line by line into Siemens-mode blocks before it is
parsed (:mod:`nck.iso.translate`). Each ISO line becomes zero or more Siemens
blocks that all carry the ISO line's number, so alarms, the block display and
the motion segments of NC-inserted moves (fixed cycles) point at the ISO block.
The interpreter reaches ISO mode only through :class:`nck.iso.dialect.IsoDialect`.
"""

from __future__ import annotations

ISO_DIALECTS = ("iso-m", "iso-t")
"""The ISO language modes."""
