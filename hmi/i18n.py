"""The panel's language: which one is shown, and the gettext functions the screens call.

English is the language of the code; :func:`_` returns a text in the language the
operator chose (Setup ▸ Language, ``hmi --lang``), read from the catalogue
``data/lang/<code>/hmi.po`` (:mod:`nck.translations`). Call :func:`_` where a text is
shown, not where a table of texts is defined: module tables (softkey labels, state
names) stay English and are marked with :func:`N_` so the catalogue test finds them;
the softkey bars, the header and the dialogs translate them as they draw.

One language is active for the whole panel at a time (as on the control); the app sets
it at start and when the operator picks another one, and rebuilds its areas then.
"""

from __future__ import annotations

from typing import Any

from nck import (LANGUAGES, SOURCE_LANGUAGE, Refused, alarm_text_in, check_language, counted_text, gettext_catalogue,
                 localized, os_refusal)
from nck.commands import Rejected
from nck.queries import rejected_by
from nck.status import AlarmEntry

__all__ = ["LANGUAGES", "N_", "_", "alarm_text", "data_text", "error_text", "exercise_text", "language", "reason_text",
           "refusal_text", "set_language", "step_text"]

_active = {"code": SOURCE_LANGUAGE}


def language() -> str:
    """The code of the language shown now (``en``, ``de``)."""
    return _active["code"]


def set_language(code: str) -> None:
    """Show texts in language ``code`` from now on (raises ``UnknownLanguage`` for others)."""
    _active["code"] = check_language(code)


def _(message: str) -> str:
    """``message`` (English, as written in the code) in the language shown now."""
    if not message:
        return message
    return gettext_catalogue(_active["code"]).gettext(message)


def N_(message: str) -> str:  # noqa: N802 - the gettext convention
    """Mark ``message`` for the catalogue without translating it (tables defined at import)."""
    return message


def counted(count: int, one: str, many: str) -> str:
    """``one`` for a count of 1, else ``many`` (English texts marked with :func:`N_`, holding
    ``{count}``), in the language shown now, with the count filled in: "(1 entry)", "(3 entries)"
    (:func:`nck.translations.counted_text`)."""
    return counted_text(count, one, many, _)


WORDED_UNITS = (N_("rev/min"), N_("rpm"), N_("mm/rev"), N_("rev/s²"), N_("deg"), N_("deg/min"), N_("bits"))
"""The units with an English word in them (machine data, JOG fields, the speed displays, the
service screens): the tables and displays draw every unit through :func:`_`, these are the ones
the catalogue translates (U/min, Grad, Bit …)."""


STOP_REASON_WORDS = (N_("single block"), N_("alarm"), N_("search target found"))
"""The channel's stop reasons that are words (``nck.status.ChannelStatus.stop_reason``); the
others (NC STOP, M0, M1, an alarm number) read the same in every language."""


def stop_reason_text(reason: str) -> str:
    """Why the channel stands, in the language shown now."""
    return _(reason) if reason in STOP_REASON_WORDS else reason


def data_text(kind: str, key: object, field: str, english: str) -> str:
    """A text of a data table (a kind of ``nck.translations.OVERLAY_TABLES``) in the language shown now."""
    return localized(_active["code"], kind, key, field, english)


def exercise_text(exercise: Any, field: str) -> str:
    """The ``title``, ``level``, ``summary`` or ``waits_for`` (what it needs that is not built
    yet) of a guided exercise (``nck.exercise.Exercise``) in the language shown now."""
    return data_text("exercise", exercise.exercise_id, field, getattr(exercise, field))


def step_text(exercise: Any, index: int, field: str) -> str:
    """The ``text`` or ``hint`` of step ``index`` (from 0) of a guided exercise in the language shown now."""
    return data_text("exercise_step", f"{exercise.exercise_id}.{index + 1}", field,
                     getattr(exercise.steps[index], field))


def reason_text(reason: str) -> str:
    """A sentence of the kernel (``nck.phrase.Phrase``: why an exercise check does not hold, a
    simulation event) in the language shown now; a plain ``str`` as it is."""
    template = getattr(reason, "template", None)
    if template is None:
        return reason
    fields = {name: reason_text(value) if isinstance(value, str) else value
              for name, value in reason.fields.items()}  # type: ignore[attr-defined]
    return _(template).format(**fields)


FRAME_COMPONENT_WORDS = (N_("offset"), N_("fine offset"), N_("rotation"), N_("scale"), N_("mirror"))
"""The words of ``nck.writes.FRAME_COMPONENT_TEXT`` (a frame write's refusal names the component
in them), marked here for the catalogue."""


def refusal_fields_in(code: str, fields: dict[str, str]) -> dict[str, str]:
    """A refusal's placeholder values in language ``code``: an access action's title (``action``,
    with its key ``action_id``) from the ``action`` overlay, the ``what`` of an access refusal
    from the refusal its ``what_key`` names (``nck.access.AccessDenied``), and the ``name`` of a
    frame component's value (``frame_axis`` and the ``component`` word, ``nck.writes``)."""
    if "action_id" in fields:
        fields["action"] = localized(code, "action", fields["action_id"], "title", fields["action"])
    if "what_key" in fields:
        template = localized(code, "refusal", fields["what_key"], "text", "")
        if template:
            fields["what"] = template.format(**fields)
    if "component" in fields and "frame_axis" in fields:
        fields["name"] = f"{fields['frame_axis']} {gettext_catalogue(code).gettext(fields['component'])}"
    return fields


def refusal_text(refusal: Rejected) -> str:
    """Why the kernel refused a command, in the language shown now: a keyed refusal from the
    overlay of ``data/refusals.toml``, one that raised an alarm in the alarm's text, else as given."""
    code = _active["code"]
    if refusal.key:
        template = localized(code, "refusal", refusal.key, "text", "")
        return template.format(**refusal_fields_in(code, dict(refusal.fields))) if template else refusal.reason
    if refusal.alarm is not None and refusal.alarm_params:
        return alarm_text_in(code, refusal.alarm, refusal.alarm_params, refusal.reason)
    return refusal.reason


def alarm_text(entry: AlarmEntry) -> str:
    """The text of a raised alarm (or of its log entry) in the language shown now."""
    return alarm_text_in(_active["code"], entry.number, entry.params, entry.text)


def error_text(error: Exception, *, failed: str = "os_write_failed") -> str:
    """Why a file operation failed, in the language shown now: a keyed refusal (``StorageError``
    and every ``nck.refused.Refused``) in its text, an ``OSError`` by its kind (no such file,
    permission denied, disk full, read-only file system …; ``nck.os_refusals``; any other kind
    says the file could not be written, or read: ``failed="os_read_failed"``), never the
    operating system's English sentence; anything else as ``str()``."""
    if isinstance(error, OSError):
        error = os_refusal(error, failed=failed)
    if isinstance(error, Refused):
        return refusal_text(rejected_by(error))
    return str(error)
