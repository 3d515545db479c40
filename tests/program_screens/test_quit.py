"""Ctrl+Q loses nothing and asks first when something would be lost (issues 18 and 19).

Keys are sent as bursts (:func:`tests.burst.burst`): the text typed right
before Ctrl+Q, with no autosave in between, must be in the journal.
"""

from __future__ import annotations

import signal
from pathlib import Path

import pytest

from hmi.i18n import set_language
from hmi.journal import EditorJournal
from nck import commands as cmd

from tests.burst import burst
from tests.program_screens.conftest import SIZE, make_program_app, settle


async def open_demo_and_type(app, pilot, text: str) -> None:
    """Program manager → open DEMO.MPF in the editor → type ``text`` at the start."""
    await burst(pilot, "alt+n", "f3")
    await settle(pilot)
    assert app.screen.program == "MPF/DEMO.MPF"
    await burst(pilot, *text)


async def test_quit_right_after_typing_keeps_the_text_in_the_journal(data_dir: Path) -> None:
    """Type, Ctrl+Q, Y in one burst: the journal holds every character, the app has ended."""
    app = make_program_app(data_dir)
    journal_dir = None
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "")
        journal_dir = app.screen.files.journal_dir
        await burst(pilot, *"N5G0", "ctrl+q", "y")
        assert app.return_code == 0  # the app has ended
    entries = EditorJournal(journal_dir).entries()
    assert [e.program for e in entries] == ["MPF/DEMO.MPF"]
    assert entries[0].text.startswith("N5G0; pocket outline")
    assert (data_dir / "MPF" / "DEMO.MPF").read_text().startswith("; pocket")  # not saved, kept aside


async def test_quit_with_unsaved_text_asks_and_n_stays(data_dir: Path) -> None:
    """Ctrl+Q with unsaved text asks; N keeps the HMI open with the text in the editor."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "N5")
        await burst(pilot, "ctrl+q")
        assert type(app.screen).__name__ == "ConfirmDialog"
        assert "Unsaved changes in MPF/DEMO.MPF." in str(app.screen.query_one("#confirm-question").render())
        await burst(pilot, "n")
        assert app.is_running and app.screen.editor.text.startswith("N5; pocket")


async def test_quit_with_interrupted_program_asks(data_dir: Path) -> None:
    """A program interrupted by NC STOP: Ctrl+Q asks; Escape cancels."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        nck = app.bridge.nck
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("MPF/DEMO.MPF"), cmd.CycleStart()):
            app.submit(command)
        app.bridge.advance(0.2)
        app.submit(cmd.CycleStop())
        app.bridge.advance(0.1)
        assert nck.status().channel.channel_state == "interrupted"
        await burst(pilot, "ctrl+q")
        assert "is interrupted" in str(app.screen.query_one("#confirm-question").render())
        await burst(pilot, "escape")
        assert app.is_running and type(app.screen).__name__ != "ConfirmDialog"


async def test_the_question_in_german(data_dir: Path) -> None:
    """In German the question and its lines are German (they were English in a German panel)."""
    set_language("de")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "N5")
        await burst(pilot, "ctrl+q")
        question = str(app.screen.query_one("#confirm-question").render())
        assert question.splitlines()[:2] == ["HMI beenden?", "Nicht gespeicherte Änderungen in MPF/DEMO.MPF."]
        assert "Editor-Journal" in question and "Unsaved" not in question
        await burst(pilot, "n")
        assert app.is_running


async def test_termination_with_interrupted_program_quits_without_asking(data_dir: Path) -> None:
    """SIGTERM/SIGHUP (the terminal gone) with a program interrupted: no question nobody can answer.

    Found after ``tmux kill-session``: the HMI asked its Ctrl+Q question and kept running.
    """
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("MPF/DEMO.MPF"), cmd.CycleStart()):
            app.submit(command)
        app.bridge.advance(0.2)
        app.submit(cmd.CycleStop())
        app.bridge.advance(0.1)
        assert app.quit_concerns()
        app.quit_unattended(128 + signal.SIGTERM)
        await pilot.pause()
        assert app.return_code == 128 + signal.SIGTERM  # ended, nothing asked


def refuse_journal_writes(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every journal write fails as on a full disk."""
    def refuse(*args: object, **kwargs: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(EditorJournal, "write", refuse)


async def test_journal_write_failure_at_quit_is_reported_and_the_hmi_stays(
        data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The journal cannot be written at quit: the HMI does not quit and says why."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "N5")
        refuse_journal_writes(monkeypatch)
        await burst(pilot, "ctrl+q", "y")
        assert app.is_running
        line = str(app.screen.query_one("#dialog-line").render())
        # the quit's "Not quit: …" or, when the 3 s autosave ran meanwhile (a loaded machine), its
        # "Journal could not be written: …" — both name the failure; the HMI stayed either way
        assert "the disk is full" in line and "journal" in line.lower()
        assert app.screen.editor.text.startswith("N5; pocket")


async def test_unattended_quit_with_a_journal_write_failure_still_ends_and_says_why(
        data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """SIGTERM or a lost terminal: nobody can answer or read the dialog line, so the HMI
    ends anyway (it cannot stay for nobody) and the failure is written on stderr after it."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "N5")
        refuse_journal_writes(monkeypatch)
        app.quit_unattended(143)
        await pilot.pause()
        assert app.return_code == 143
    assert app.exit_notes == [
        "hmi: unsaved text could not be kept in the journal: [Errno 28] No space left on device"]


async def test_area_key_and_quit_in_one_burst_ask_once(data_dir: Path) -> None:
    """Unsaved text, then Alt+M Ctrl+Q in one burst (found in tmux, issue 18): the quit question
    is the one on top and the only one (it names the unsaved program); the leave-editor question,
    asked after the area change, no longer lands over it so that Y went to the wrong dialog."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_demo_and_type(app, pilot, "N5")
        journal_dir = app.screen.files.journal_dir
        await burst(pilot, "alt+m", "ctrl+q")
        await settle(pilot)
        dialogs = [type(s).__name__ for s in app.screen_stack if type(s).__name__.endswith("Dialog")]
        assert dialogs == ["ConfirmDialog"]
        assert "Unsaved changes in MPF/DEMO.MPF." in str(app.screen.query_one("#confirm-question").render())
        await burst(pilot, "y")
        assert app.return_code == 0
    assert [e.program for e in EditorJournal(journal_dir).entries()] == ["MPF/DEMO.MPF"]
