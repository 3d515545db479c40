"""A check or simulation that raises is a bug, not a problem of the program: it reaches the
tests (the app's internal-error report raises under pytest) and is never shown as a Python text
in the panel's words ("Check failed: TypeError(...)" and "simulation failed: TypeError(...)"
were); what a program does wrong stays an alarm on its line."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.check import CheckContext

from tests.program_screens.conftest import SIZE, make_program_app, settle


def _broken_check(*args: object, **kwargs: object) -> None:
    raise TypeError("a bug in the check")


def _broken_simulation(*args: object, **kwargs: object) -> None:
    raise TypeError("a bug in the simulation")


@pytest.mark.parametrize("method, broken, keys, bug", [
    ("iter_check", _broken_check, ("alt+n", "f3"), "a bug in the check"),  # DEMO.MPF opened: its check
    ("simulate", _broken_simulation, ("alt+n", "f3", "f5"), "a bug in the simulation"),  # and Simulation
])
async def test_a_bug_in_the_check_or_simulation_fails_the_test(
        method: str, broken: object, keys: tuple[str, ...], bug: str, data_dir: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(CheckContext, method, broken)
    app = make_program_app(data_dir)
    with pytest.raises(TypeError, match=bug):
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press(*keys)
            await settle(pilot)


async def test_outside_tests_the_bug_is_kept_and_the_editor_carries_on(
        data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(CheckContext, "iter_check", _broken_check)
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        monkeypatch.delenv("PYTEST_CURRENT_TEST")  # as the panel runs for an operator
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        screen = app.screen
        assert screen.AREA_ID == "program"
        message = str(screen.query_one("#prog-message").render())
        assert "Check failed" not in message and "TypeError(" not in message
        assert len(app.internal_errors) == 1 and "a bug in the check" in app.internal_errors[0]
        await pilot.press("ctrl+end", *"N90 G1 X==5")  # the editor still takes keys
        await pilot.pause()
        assert screen.editor.text.endswith("N90 G1 X==5")


async def test_a_faulty_program_is_an_alarm_on_its_line(data_dir: Path) -> None:
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3", "ctrl+end", *"N90 G1 X==5")
        screen = app.screen
        screen.check_now()
        await settle(pilot)
        assert [(m.line, m.number) for m in screen.editor.error_marks.values()] == [(9, 12080)]
        assert app.internal_errors == []


async def test_outside_tests_the_simulation_bug_is_kept_and_said_in_the_panels_words(
        data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(CheckContext, "simulate", _broken_simulation)
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        monkeypatch.delenv("PYTEST_CURRENT_TEST")
        await pilot.press("alt+n", "f3", "f5")
        await settle(pilot)
        screen = app.screen
        notes = [screen.stock.status_text, screen.toolpath.status_text]
        assert notes == ["simulation not possible"] * 2
        assert len(app.internal_errors) == 1 and "a bug in the simulation" in app.internal_errors[0]
        assert app.screen is screen and screen.simulating  # the panel carries on
