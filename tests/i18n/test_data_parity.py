"""Every text of the data tables exists in every language (issue 27).

The English texts are the entries of ``data/alarms`` (text and the help's explanation and
remedy), ``data/md``, ``data/keymap.toml`` and ``data/gcode`` (the Siemens and ISO G groups, the
G functions' meanings (Siemens and ISO), and the editor's word help of ``words.toml``), ``data/cycles/cycles.toml``
(the editor's cycle forms: each form's title, each parameter's help line and each sketch) and the guided exercises
of ``data/exercises`` (title, level, summary, every step's text and hint), the kernel's refusals of
``data/refusals.toml`` and the protected functions' titles of ``data/access.toml``; the translations are the
overlays ``data/lang/<code>/*.toml``.
"""

from __future__ import annotations

import re

import pytest

from nck.exercise import load_exercises
from nck.refusals import refusal_texts
from nck.resources import alarm_catalog, data_path, read_table
from nck.translations import LANGUAGES, SOURCE_LANGUAGE, overlay

OTHER_LANGUAGES = [code for code in LANGUAGES if code != SOURCE_LANGUAGE]
ALARM_PARAMETER = re.compile(r"%\d")


def base_entries() -> dict[str, dict[str, dict[str, str]]]:
    """kind -> key -> field -> English text, of every translated data table."""
    alarms = {str(number): {"text": d.text, "explanation": d.explanation, "remedy": d.remedy}
              for number, d in alarm_catalog().items()}
    md: dict[str, dict[str, str]] = {}
    for path in sorted(data_path("md").glob("*.toml")):
        for entry in read_table(path).get("data", []):
            md[str(entry["number"])] = {"title": entry["title"]}
    groups = {str(group["number"]): {"meaning": group["meaning"]}
              for group in read_table(data_path("gcode", "siemens.toml"))["group"]}
    keys = {str(key["id"]): {"label": key["label"]} for key in read_table(data_path("keymap.toml"))["key"]}
    codes = {name: {"meaning": meaning} for group in read_table(data_path("gcode", "siemens.toml"))["group"]
             for name, meaning in group.get("codes", {}).items()}
    entries = {"alarm": alarms, "md": md, "group": groups, "key": keys, "code": codes}
    for dialect in ("iso_m", "iso_t"):
        entries[f"{dialect}_group"] = {str(group["number"]): {"meaning": group["meaning"]}
                                       for group in read_table(data_path("gcode", f"{dialect}.toml"))["group"]}
        entries[f"{dialect}_code"] = {name: {"meaning": meaning}
                                      for group in read_table(data_path("gcode", f"{dialect}.toml"))["group"]
                                      for name, meaning in group.get("codes", {}).items()}
    words = read_table(data_path("gcode", "words.toml"))
    for kind, section in (("m_function", "m_functions"), ("system_variable", "system_variables"),
                          ("system_variable_prefix", "system_variable_prefixes")):
        entries[kind] = {name: {"meaning": meaning} for name, meaning in words[section].items()}
    forms = read_table(data_path("cycles", "cycles.toml"))["forms"]
    entries["cycle_form"] = {name: {"title": form["title"], "key": form["key"]} for name, form in forms.items()}
    menus = read_table(data_path("cycles", "cycles.toml"))["menus"]
    entries["cycle_menu"] = {name: {"label": menu["label"]} for name, menu in menus.items()}
    entries["cycle_menu_key"] = {f"{name}.{index}": {"label": key["label"]}
                                 for name, menu in menus.items() for index, key in enumerate(menu["keys"])}
    entries["cycle_param"] = {f"{name}.{param['name']}": {"help": param["help"]}
                              for name, form in forms.items() for param in form["params"]}
    sketches = read_table(data_path("cycles", "cycles.toml"))["sketches"]
    entries["cycle_sketch"] = {name: {"text": text} for name, text in sketches.items()}
    exercises = load_exercises()
    entries["exercise"] = {e.exercise_id: {"title": e.title, **{name: getattr(e, name) for name in ("level", "summary", "waits_for") if getattr(e, name)}}
                           for e in exercises}
    entries["exercise_step"] = {f"{e.exercise_id}.{number}": {"text": step.text, **({"hint": step.hint} if step.hint else {})}
                                for e in exercises for number, step in enumerate(e.steps, 1)}
    entries["refusal"] = {key: {"text": text} for key, text in refusal_texts().items()}
    actions = read_table(data_path("access.toml"))["action"]
    entries["action"] = {key: {"title": entry["title"]} for key, entry in actions.items()}
    return entries


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_every_data_text_has_a_translation_and_no_more(code: str) -> None:
    for kind, entries in base_entries().items():
        translated = overlay(code, kind)
        missing = [f"{key}.{field}" for key, fields in entries.items() for field in fields
                   if not translated.get(key, {}).get(field)]
        assert not missing, f"{kind}: no {code} text for {missing}"
        stale = sorted(set(translated) - set(entries))
        assert not stale, f"{kind}: {code} texts for entries that do not exist: {stale}"
        extra = [f"{key}.{field}" for key, fields in translated.items() for field in fields
                 if field not in entries.get(key, {})]
        assert not extra, f"{kind}: {code} fields the English entry lacks: {extra}"


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_alarm_translations_keep_the_parameters(code: str) -> None:
    for number, fields in overlay(code, "alarm").items():
        english = alarm_catalog()[int(number)].text
        assert sorted(ALARM_PARAMETER.findall(fields["text"])) == sorted(ALARM_PARAMETER.findall(english)), number


PLACEHOLDER = re.compile(r"\{(\w+)\}")


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_refusal_translations_keep_the_placeholders(code: str) -> None:
    for key, fields in overlay(code, "refusal").items():
        assert sorted(PLACEHOLDER.findall(fields["text"])) == sorted(PLACEHOLDER.findall(refusal_texts()[key])), key


PARAMETER_NAME = re.compile(r"(?<![A-Za-z0-9_])_?[A-Z][A-Z0-9_]*[0-9A-Z](?![A-Za-z0-9_])")


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_cycle_sketches_keep_the_parameter_names(code: str) -> None:
    """The form marks the parameter under the cursor where its name stands in the sketch."""
    english = read_table(data_path("cycles", "cycles.toml"))["sketches"]
    for name, fields in overlay(code, "cycle_sketch").items():
        assert sorted(set(PARAMETER_NAME.findall(fields["text"]))) == sorted(set(PARAMETER_NAME.findall(english[name]))), name
