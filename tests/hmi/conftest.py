"""Fixtures of the HMI tests: a fake kernel, an app without the wall-clock timer."""

from __future__ import annotations

import pytest

from hmi.app import HmiApp
from tests.hmi.fake_nck import FakeNck

SIZE = (160, 48)


@pytest.fixture
def fake() -> FakeNck:
    """A fresh fake kernel (axes unreferenced, JOG)."""
    return FakeNck()


@pytest.fixture
def fake_app(fake: FakeNck) -> HmiApp:
    """The HMI on the fake kernel; the test advances time itself."""
    return HmiApp(fake, realtime=False)
