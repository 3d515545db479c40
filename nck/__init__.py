"""The simulated NCK: a pure, deterministic kernel — and its façade.

Nothing in this package imports a UI library, reads the wall clock or starts a
thread. Time advances only through the kernel's own tick/step calls.

Code outside ``nck/`` (the HMI and its screens) uses the kernel only through this
façade: this module, :mod:`nck.commands` (what a client may ask the kernel to do),
:mod:`nck.status` (the snapshot it publishes) and :mod:`nck.queries` (read-only
questions). Below is everything else of ``nck`` a client may use, re-exported by
job; ``tests/test_architecture.py`` holds the UI to that.
"""

from __future__ import annotations

__version__ = "0.1.0"

# Building a kernel: the kernel itself, the one composition root (build_nck) and the kernel on a data directory.
from nck.kernel import Nck as Nck
from nck.build import (OpenedData as OpenedData, SessionKernel as SessionKernel, build_nck as build_nck,
                       build_session_kernel as build_session_kernel, open_data_session as open_data_session,
                       programs_in_execution as programs_in_execution)
# Numbers as the operator reads them (fixed decimals, never -0.000).
from nck.number_text import fixed as fixed, trimmed as trimmed
# Ending a process on SIGTERM/SIGHUP like a normal exit (the nck command does the same).
from nck.termination import (TERMINATION_SIGNALS as TERMINATION_SIGNALS,
                             exit_on_termination as exit_on_termination)
# Protected functions and the levels they need (data/access.toml).
from nck.access import AccessDenied as AccessDenied, Action as Action, required_level as required_level
# The NC file system (part programs, subprograms, workpieces) and safe file writes and reads.
from nck.storage import (MAX_IMPORT_BYTES as MAX_IMPORT_BYTES, NcFileSystem as NcFileSystem,
                         ProgramEntry as ProgramEntry, StorageError as StorageError)
from nck.atomic import atomic_write_text as atomic_write_text
from nck.regular_files import ExportTargetExists as ExportTargetExists
from nck.regular_files import read_regular_bytes as read_regular_bytes, write_export as write_export
# The servo trace (Diagnostics > Service): recorder, its settings and signals.
from nck.trace import (MAX_SIGNALS as MAX_SIGNALS, TraceError as TraceError, TraceRecorder as TraceRecorder,
                       TraceSettings as TraceSettings, available_signals as available_signals,
                       signal_unit as signal_unit)
# A programmed move as the interpreter emits it (what the editor's toolpath draws).
from nck.canon import Motion as Motion
# The ISO dialect's G groups as the G-functions window shows them.
from nck.iso.display import ISO_MAIN_GROUPS_M as ISO_MAIN_GROUPS_M, iso_table as iso_table
# A refusal by its key in data/refusals.toml (the panel's own refusals of operator commands).
from nck.refusals import refuse as refuse
# A refusal a data layer raises (keyed), and an operating system's refusal of a file operation as one.
from nck.refused import Refused as Refused
from nck.os_refusals import os_refusal as os_refusal
# Operator texts in more than one language: gettext catalogues and data-table overlays (data/lang).
from nck.translations import (LANGUAGES as LANGUAGES, SOURCE_LANGUAGE as SOURCE_LANGUAGE,
                              UnknownLanguage as UnknownLanguage, alarm_text_in as alarm_text_in,
                              check_language as check_language, localized as localized,
                              gettext_catalogue as gettext_catalogue)
