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


class DialectName(str):
    """A dialect name (``"iso-m"``) that also carries the ISO decimal-point settings.

    It compares and hashes like the plain name, so code that only looks at the
    name is unaffected; the program loader reads :attr:`iso_settings`.
    """

    iso_settings: object = None


def dialect_for(dialect: str, machine: object) -> str:
    """``dialect`` with the machine's MD 10884/10886 attached (ISO modes only)."""
    if not is_iso(dialect):
        return dialect
    from nck.iso.translate import IsoSettings
    md_value = getattr(machine, "md_value", None)
    pocket = md_value("MD10884", None, True) if md_value else True
    is_c = md_value("MD10886", None, 0) if md_value else 0
    named = DialectName(dialect)
    mask = md_value("MD20734", None, 0) if md_value else 0  # EXTERN_FUNCTION_MASK
    system = md_value("MD10881", None, 0) if md_value else 0
    digits = md_value("MD10888", None, 2) if md_value else 2
    named.iso_settings = IsoSettings(pocket_calculator=bool(pocket), increment_system_c=bool(is_c),
                                     gcode_system=int(system or 0), tool_digits=int(digits or 2),
                                     function_mask=int(mask or 0),
                                     fixed_feedrates=bool(md_value("MD22920", None, False)) if md_value else False,
                                     start_unit=_start_unit(md_value),
                                     **_macro_tables(md_value))
    return named


def _macro_tables(md_value: object) -> dict:
    """MD 10814–10817: the M- and G-code macros of ISO mode (nck.iso.macros)."""
    from nck.iso.macros import substitution_tables
    return substitution_tables(md_value)


def _start_unit(md_value: object) -> str:
    """MD 20154[5]: the inch/metric code an ISO main program starts with."""
    from nck.iso.switching import start_unit
    return start_unit(md_value("MD20154", None, None)) if callable(md_value) else ""
