"""ISO mode as a :class:`~nck.lang.dialect.Dialect`: the front end the interpreter is given.

:class:`IsoDialect` translates ISO texts into Siemens lines (:mod:`nck.iso.loader`) and
answers the interpreter's run-time questions of ISO mode: the ``$C_…`` macro arguments,
the H numbers, ``$P_EXTGG`` and the ``$P_ISOFR_…`` frames, the ISO G groups of the
display, the ``$C_…`` hand-over of G65/G66 calls and the ISO ``M30`` rule.

It also serves Siemens mode (``name == "siemens"``) on a control with the ISO option:
a Siemens text that switches with G291 is translated (into the machine's external language,
:func:`external_dialect`), everything else is Siemens. :func:`dialect_for` builds the dialect
of a language mode for a machine; :func:`language_mode` is the mode the machine data give
after power on and RESET.
"""

from __future__ import annotations

import bisect
import re
from dataclasses import dataclass
from typing import Any, Sequence

from nck.iso import ISO_DIALECTS, display, frames, macros, subprograms, tool_offsets
from nck.iso.loader import iso_lines, wants_iso
from nck.iso.macros import substitution_tables
from nck.iso.switching import start_unit
from nck.iso.words import IsoSettings
from nck.lang.dialect import CallLevel, GuessN, InterpreterContext, Located
from nck.lang.lines import Line

_MACRO_ARGUMENTS = "$C_"
_H_NUMBERS = ("$TC_DPH", "$TC_ISOH_")
_EXTGG = "$P_EXTGG"
_ISO_FRAMES = "$P_ISOFR_"


@dataclass(frozen=True, eq=False)
class IsoDialect:
    """ISO M / ISO T (or Siemens with the G291 switch) with the machine's ISO settings."""

    name: str
    settings: IsoSettings | None = None
    gcode_table: str = "siemens"
    switch_dialect: str = "iso-m"  # Siemens mode: what G291 switches to (the external language)

    @property
    def iso_name(self) -> str:
        """The ISO dialect of this mode: its own, or in Siemens mode the one G291 switches to."""
        return self.name if is_iso(self.name) else self.switch_dialect

    def program_key(self) -> object:
        """Programs are cached per mode (the settings belong to the machine)."""
        return ("iso", self.name, self.switch_dialect)

    def translated_lines(self, name: str, text: str, located: Located, guess_n: GuessN,
                         main: bool) -> list[Line] | None:
        """The translated lines of an ISO text (or a Siemens text switching with G291)."""
        if self.name == "siemens" and "G291" not in text and "g291" not in text:
            return None
        if not wants_iso(text, self.name):
            return None
        return iso_lines(name, text, self.name, self.settings, located, guess_n, main,
                         switch_dialect=self.switch_dialect)

    def gcode_display(self, modal: Any, levels: Sequence[CallLevel]) -> dict[int, str]:
        """ISO codes for the G-group display while ISO mode (G291) is active, else empty."""
        gcodes = modal.gcodes
        if gcodes.get(subprograms.ISO_MODE_GROUP) != "G291":
            return {}
        turning = self.iso_name == "iso-t"
        view = display.iso_gcodes(gcodes, "iso-t" if turning else "iso-m")
        if not turning:  # ISO M frame groups 11/16/17/22 from the geometry state
            view.update(frames.display_codes(modal.geometry))
        view.update(macros.display_codes(levels, modal, turning))  # groups 8 and 12
        return view

    def reads_variable(self, name: str) -> bool:
        """``$C_…``, the H numbers and ``$P_EXTGG``."""
        return name.startswith((_MACRO_ARGUMENTS, *_H_NUMBERS)) or name == _EXTGG

    def read_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...]) -> Any:
        """Value of an ISO system variable."""
        if name.startswith(_MACRO_ARGUMENTS):  # G65/G66 macro arguments
            return macros.read(ctx, name, indices)
        if name.startswith(_H_NUMBERS):
            return tool_offsets.read(ctx, name, indices)
        return display.read_extgg(ctx, self.iso_name, indices)  # active ISO G code per ISO group

    def writes_variable(self, name: str) -> bool:
        """``$C_…``, the H numbers and the ``$P_ISOFR_…`` frame operations."""
        return name.startswith((_MACRO_ARGUMENTS, *_H_NUMBERS, _ISO_FRAMES))

    def write_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...],
                       value: Any) -> None:
        """Write an ISO system variable."""
        if name.startswith(_MACRO_ARGUMENTS):
            macros.write(ctx, name, indices, value)
        elif name.startswith(_H_NUMBERS):
            tool_offsets.write(ctx, name, indices, value)
        else:  # G68/G51/G51.1/G52 frames
            frames.write(ctx, name, indices, value)

    def bind_call(self, caller: CallLevel, callee: CallLevel, call: Any, modal: Any) -> None:
        """``$C_…`` arguments for the called level; a PROC program runs in G290."""
        macros.bind_call(caller, callee, call, modal)

    def after_return(self, modal: Any, level: CallLevel) -> None:
        """Back to G291 after a Siemens-mode (PROC) program called from ISO mode."""
        if level.iso_macro is not None:
            macros.after_return(modal, level)

    def ends_whole_program(self, ctx: InterpreterContext, end_kind: str | None) -> bool:
        """ISO mode: ``M30`` in a subprogram ends the whole program."""
        return subprograms.ends_whole_program(ctx, end_kind)


def is_iso(dialect: str) -> bool:
    """True for the ISO language modes (``iso-m``, ``iso-t``)."""
    return dialect in ISO_DIALECTS


EXTERN_CNC_SYSTEM = {1: "iso-m", 2: "iso-t"}
"""MD10880 $MN_EXTERN_CNC_SYSTEM: the ISO dialect of the external language (000 L433, L470-475)."""
ISO_MODE_AT_RESET = 2
"""MD20150 $MC_GCODE_RESET_VALUES[46] (group 47): 1 G290 Siemens mode, 2 G291 ISO Dialect mode
after power on and RESET (000 L466-475)."""


def external_dialect(machine: Any) -> str:
    """The ISO dialect G291 switches to on ``machine``: MD10880 (1 ISO M, 2 ISO T); when it is
    not set (0) the one of the machine's kind (our choice: a lathe ISO T, a mill ISO M)."""
    md_value = getattr(machine, "md_value", None)
    system = md_value("MD10880", None, 0) if md_value else 0
    if system in EXTERN_CNC_SYSTEM:
        return EXTERN_CNC_SYSTEM[system]
    return "iso-t" if getattr(machine, "kind", "mill") == "lathe" else "iso-m"


def language_mode(machine: Any) -> str:
    """The language mode after power on and RESET (000 L466-475): the external language
    (:func:`external_dialect`) when MD20150[46] selects G291, else ``siemens``."""
    md_value = getattr(machine, "md_value", None)
    values = md_value("MD20150", None, None) if md_value else None
    group_47 = values[46] if isinstance(values, (list, tuple)) and len(values) > 46 else None
    return external_dialect(machine) if group_47 == ISO_MODE_AT_RESET else "siemens"


def dialect_for(name: str | None, machine: Any) -> IsoDialect:
    """The dialect of language mode ``name`` with the machine's ISO machine data; ``None``:
    the machine's mode after power on and RESET (:func:`language_mode`).

    ``siemens`` gives Siemens mode with the G291 switch to the machine's external language
    (no ISO settings, as before: a switching program is translated with the defaults).
    """
    if name is None:
        name = language_mode(machine)
    if not is_iso(name):
        return IsoDialect(name, switch_dialect=external_dialect(machine))
    md_value = getattr(machine, "md_value", None)
    pocket = md_value("MD10884", None, True) if md_value else True
    is_c = md_value("MD10886", None, 0) if md_value else 0
    mask = md_value("MD20734", None, 0) if md_value else 0  # EXTERN_FUNCTION_MASK
    system = md_value("MD10881", None, 0) if md_value else 0
    digits = md_value("MD10888", None, 2) if md_value else 2
    settings = IsoSettings(pocket_calculator=bool(pocket), increment_system_c=bool(is_c),
                           gcode_system=int(system or 0), tool_digits=int(digits or 2),
                           function_mask=int(mask or 0),
                           fixed_feedrates=bool(md_value("MD22920", None, False)) if md_value else False,
                           start_unit=_start_unit(md_value),
                           **substitution_tables(md_value))
    return IsoDialect(name, settings)


def _start_unit(md_value: Any) -> str:
    """MD 20154[5]: the inch/metric code an ISO main program starts with."""
    return start_unit(md_value("MD20154", None, None)) if callable(md_value) else ""


_SWITCH = re.compile(r"(?<![A-Z0-9_.])G29([01])(?![0-9.])", re.IGNORECASE)
_COMMENT = re.compile(r";.*|\([^)]*\)")  # a Siemens comment, an ISO comment


@dataclass(frozen=True)
class ProgramLanguage:
    """The language each line of a program text is read in (for the editor's word help): the
    machine's mode at the start (:func:`language_mode`; a ``PROC`` program is Siemens), then
    every G290 / G291 line switches. A reading of the text, not the interpreter's: a switch in a
    skipped branch counts too."""

    start: str
    iso_dialect: str
    switch_lines: tuple[int, ...] = ()  # 0-based lines with G290 or G291, in order
    switch_to_iso: tuple[bool, ...] = ()

    def dialect_at(self, line: int) -> str:
        """``siemens``, ``iso-m`` or ``iso-t`` for the 0-based ``line`` (its own switch counts)."""
        index = bisect.bisect_right(self.switch_lines, line) - 1
        if index < 0:
            return self.start
        return self.iso_dialect if self.switch_to_iso[index] else "siemens"


def program_language(text: str, machine: Any) -> ProgramLanguage:
    """How the lines of ``text`` are read on ``machine`` (see :class:`ProgramLanguage`)."""
    mode = language_mode(machine)
    iso = external_dialect(machine) if not is_iso(mode) else mode
    start = mode if is_iso(mode) and wants_iso(text, mode) else "siemens"
    lines: list[int] = []
    to_iso: list[bool] = []
    index, counted_to = 0, 0  # the line index of text position counted_to
    for position in _candidates(text):  # (a 200,000-line program: a few ms)
        index += text.count("\n", counted_to, position)
        counted_to = position
        if lines and lines[-1] == index:
            continue  # a second switch in the line: the line was read whole
        begin = text.rfind("\n", 0, position) + 1
        end = text.find("\n", position)
        found = _SWITCH.findall(_COMMENT.sub("", text[begin:end if end >= 0 else len(text)]))
        if found:  # (not inside a comment)
            lines.append(index)
            to_iso.append(found[-1] == "1")
    return ProgramLanguage(start, iso, tuple(lines), tuple(to_iso))


def _candidates(text: str) -> list[int]:
    """The positions of every ``G29`` / ``g29`` in ``text``, in order (str.find: faster than a
    regular expression over the whole text)."""
    found = []
    for word in ("G29", "g29"):
        position = text.find(word)
        while position >= 0:
            found.append(position)
            position = text.find(word, position + 3)
    return sorted(found)

