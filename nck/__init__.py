"""The simulated NCK: a pure, deterministic kernel — and its façade.

Nothing in this package imports a UI library, reads the wall clock or starts a
thread. Time advances only through the kernel's own tick/step calls.

Code outside ``nck/`` (the HMI and its screens) uses the kernel only through this
façade: this module, :mod:`nck.commands` (what a client may ask the kernel to do),
:mod:`nck.status` (the snapshot it publishes) and :mod:`nck.queries` (read-only
questions). Below is everything else of ``nck`` a client may use, re-exported by
job; ``tests/test_architecture.py`` holds the UI to that.

The kernel, its composition root, the NC file system, the servo trace and the panel's
refusals are imported on first use (PEP 562 ``__getattr__``): ``nck check`` and the other
commands that build no kernel start without loading them. Their imports stand below under
``TYPE_CHECKING``, so mypy and ``tests/import_graph`` see every edge of the façade;
``tests/test_facade.py`` holds ``_ON_FIRST_USE`` to the same names.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

__version__ = "0.1.0"

# Numbers as the operator reads them (fixed decimals, never -0.000).
from nck.number_text import fixed as fixed, trimmed as trimmed
# Ending a process on SIGTERM/SIGHUP like a normal exit (the nck command does the same).
from nck.termination import (TERMINATION_SIGNALS as TERMINATION_SIGNALS,
                             exit_on_termination as exit_on_termination)
# Protected functions and the levels they need (data/access.toml).
from nck.access import AccessDenied as AccessDenied, Action as Action, required_level as required_level
# Safe file writes and reads.
from nck.atomic import atomic_write_text as atomic_write_text
from nck.regular_files import ExportTargetExists as ExportTargetExists
from nck.regular_files import read_regular_bytes as read_regular_bytes, write_export as write_export
# A programmed move as the interpreter emits it (what the editor's toolpath draws).
from nck.canon import Motion as Motion
# The ISO dialect's G groups as the G-functions window shows them.
from nck.iso.display import ISO_MAIN_GROUPS_M as ISO_MAIN_GROUPS_M, iso_table as iso_table
from nck.iso.dialect import ProgramLanguage as ProgramLanguage, program_language as program_language
# A refusal a data layer raises (keyed).
from nck.refused import Refused as Refused
# Operator texts in more than one language: gettext catalogues and data-table overlays (data/lang).
from nck.translations import (LANGUAGES as LANGUAGES, SOURCE_LANGUAGE as SOURCE_LANGUAGE,
                              UnknownLanguage as UnknownLanguage, alarm_text_in as alarm_text_in,
                              check_language as check_language, localized as localized,
                              gettext_catalogue as gettext_catalogue, counted_text as counted_text)

if TYPE_CHECKING:
    # Building a kernel: the kernel itself, the one composition root (build_nck) and the kernel on a data directory.
    from nck.kernel import Nck as Nck
    from nck.build import (OpenedData as OpenedData, SessionKernel as SessionKernel, build_nck as build_nck,
                           build_session_kernel as build_session_kernel, open_data_session as open_data_session,
                           programs_in_execution as programs_in_execution)
    # The NC file system (part programs, subprograms, workpieces).
    from nck.storage import (MAX_IMPORT_BYTES as MAX_IMPORT_BYTES, NcFileSystem as NcFileSystem,
                             ProgramEntry as ProgramEntry, StorageError as StorageError)
    # The servo trace (Diagnostics > Service): recorder, its settings and signals.
    from nck.trace import (MAX_SIGNALS as MAX_SIGNALS, TraceError as TraceError, TraceRecorder as TraceRecorder,
                           TraceSettings as TraceSettings, available_signals as available_signals,
                           signal_unit as signal_unit)
    # A refusal by its key in data/refusals.toml (the panel's own refusals of operator commands).
    from nck.refusals import refuse as refuse
    # An operating system's refusal of a file operation as a refusal.
    from nck.os_refusals import os_refusal as os_refusal

_ON_FIRST_USE = {
    "nck.kernel": ("Nck",),
    "nck.build": ("OpenedData", "SessionKernel", "build_nck", "build_session_kernel", "open_data_session",
                  "programs_in_execution"),
    "nck.storage": ("MAX_IMPORT_BYTES", "NcFileSystem", "ProgramEntry", "StorageError"),
    "nck.trace": ("MAX_SIGNALS", "TraceError", "TraceRecorder", "TraceSettings", "available_signals", "signal_unit"),
    "nck.refusals": ("refuse",),
    "nck.os_refusals": ("os_refusal",),
}
"""The façade's names imported on first use, by the module that defines them."""
_HOME_OF = {name: module for module, names in _ON_FIRST_USE.items() for name in names}


def __getattr__(name: str) -> object:
    """Import a name of ``_ON_FIRST_USE`` from its module when it is first asked for (PEP 562)."""
    module = _HOME_OF.get(name)
    if module is None:
        raise AttributeError(f"module 'nck' has no attribute '{name}'")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value
