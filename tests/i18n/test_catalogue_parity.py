"""Every text of the code exists in every language (issue 27): the gettext catalogues.

The code's texts are found in the source (:mod:`tests.i18n.sources`).
"""

from __future__ import annotations

import re

import pytest

from nck.resources import data_path
from nck.translations import LANGUAGES, SOURCE_LANGUAGE, read_po
from tests.i18n.sources import code_texts, texts_of

OTHER_LANGUAGES = [code for code in LANGUAGES if code != SOURCE_LANGUAGE]
NAMED_FIELD = re.compile(r"\{(\w*)[^}]*\}")


def catalogue(code: str) -> dict[str, str]:
    return read_po(data_path("lang", code, "hmi.po"))


def test_the_source_scan_finds_marked_texts_and_softkey_labels() -> None:
    source = ('_("Shown")\nN_("Table")\nSoftkey("a.b", "Block\\nsearch", "x")\n'
              'view_softkey("a.c", "Overview", "v")\n_(name)\nprint("not a text")\n')
    assert set(texts_of(source)) == {"Shown", "Table", "Block\nsearch", "Overview"}


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_every_code_text_has_a_translation(code: str) -> None:
    translated = catalogue(code)
    missing = {text: where for text, where in code_texts().items() if text not in translated}
    assert not missing, f"untranslated in data/lang/{code}/hmi.po (python -m tests.i18n.sources adds them): {missing}"


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_no_translation_without_a_text_in_the_code(code: str) -> None:
    stale = set(catalogue(code)) - set(code_texts())
    assert not stale, f"data/lang/{code}/hmi.po translates texts no code shows any more: {sorted(stale)}"


@pytest.mark.parametrize("code", OTHER_LANGUAGES)
def test_translations_keep_the_placeholders(code: str) -> None:
    wrong = {english: text for english, text in catalogue(code).items()
             if sorted(NAMED_FIELD.findall(english)) != sorted(NAMED_FIELD.findall(text))}
    assert not wrong


def test_no_module_that_translates_binds_underscore_itself() -> None:
    """A function that assigns ``_`` (``for _ in …``, ``a, _ = …``) makes it local: a call of the
    translate function ``_()`` in it would fail. Modules importing ``_`` from hmi.i18n must not."""
    import ast

    from tests.i18n.sources import PACKAGES, ROOT

    offenders = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            tree = ast.parse(path.read_text(encoding="utf-8"))
            imports_underscore = any(isinstance(node, ast.ImportFrom) and node.module == "hmi.i18n"
                                     and any(alias.name == "_" for alias in node.names) for node in ast.walk(tree))
            if not imports_underscore:
                continue
            offenders += [f"{path.relative_to(ROOT)}:{node.lineno}" for node in ast.walk(tree)
                          if isinstance(node, ast.Name) and node.id == "_" and isinstance(node.ctx, ast.Store)]
    assert not offenders
