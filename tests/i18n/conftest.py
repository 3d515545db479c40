"""Fixtures of the language tests."""

from __future__ import annotations

from typing import Iterator

import pytest

from hmi.i18n import set_language


@pytest.fixture
def german() -> Iterator[None]:
    """The panel's language German for one test, English again afterwards."""
    set_language("de")
    yield
    set_language("en")
