"""Hostile keys: a monkey sends random panel keys and printable characters across all areas.

The HMI runs on a real kernel over a real NC data directory (every area has its
data). Keys come one at a time, in bursts and as double presses; bursts and
double presses go as terminal bytes through the HMI's terminal parser, in one
read or split into two, as a fast typist, a paste or key auto-repeat delivers
them. After each burst the app must still run, neither the app nor the kernel
may have logged an internal error, and the kernel's status snapshot must be
consistent (known modes and states, finite positions, alarms well formed); no
editor, MDA buffer or input field may hold a character the monkey did not type
into that field (issue 18: a repeated Alt key typed ``^g``), see :class:`TypedLedger`.
"""

from __future__ import annotations

import asyncio
import math
import random
import string
from collections import defaultdict, deque
from pathlib import Path

import pytest
from textual import events

from textual.widgets import Input, TextArea

from hmi.app import make_app
from hmi.key_input import PanelKeyParser
from hmi.keymap import default_keymap
from tests.hmi.conftest import SIZE
from tests.hmi.terminal_bytes import terminal_bytes
from tests.one_key import key_event, send_key

MODES = {"JOG", "MDA", "AUTO"}
CHANNEL_STATES = {"reset", "active", "interrupted"}
PROGRAM_STATES = {"aborted", "running", "stopped", "interrupted", "waiting"}
EXTRA_KEYS = ["enter", "escape", "tab", "shift+tab", "up", "down", "left", "right", "pageup", "pagedown",
              "home", "end", "backspace", "delete", "insert", "space", "ctrl+u", "ctrl+c", "ctrl+v",
              "ctrl+z", "ctrl+s", "ctrl+f"]
PROGRAM = "N10 G90 G0 X10 Y10 Z5\nN20 G1 X30 F2000\nN30 M0\nN40 Y30\nLBL: R1=R1+1\nGOTOB LBL\nM30\n"


def monkey_keys() -> list[str]:
    """Every key of the keymap (quitting excluded), editing keys, and printable characters."""
    keys = [k.strip() for b in default_keymap().bindings if "quit" not in b.id
            for k in b.keys.split(",")]
    keys = [k for k in keys if k and "ctrl+q" not in k]
    printable = [c for c in string.ascii_letters + string.digits + "=+-*/()[].,;:\"'$_ <>"]
    names = {" ": "space"}
    return keys * 3 + EXTRA_KEYS + [names.get(c, c) for c in printable]


def assert_consistent(app) -> None:
    """The app runs, nothing internal failed, the kernel snapshot makes sense."""
    assert app.is_running
    assert app.internal_errors == [], app.internal_errors[0]
    nck = app.bridge.nck
    assert nck.internal_errors == [], nck.internal_errors[0]
    status = nck.status()
    channel = status.channel
    assert channel.mode in MODES
    assert channel.channel_state in CHANNEL_STATES
    assert channel.program_state in PROGRAM_STATES
    for axis in status.axes:
        assert math.isfinite(axis.position_mcs) and math.isfinite(axis.position_wcs), axis
    for alarm in status.alarms:
        assert isinstance(alarm.number, int) and alarm.number > 0 and alarm.text


async def send_terminal_keys(app, pilot, parser: PanelKeyParser, keys: list[str],
                             rng: random.Random) -> None:
    """Send keys as the terminal's bytes in one read, or in two split at a random byte."""
    data = "".join(terminal_bytes(key) or "" for key in keys)
    cut = rng.randrange(len(data) + 1)
    for read in filter(None, (data[:cut], data[cut:])):
        for message in parser.feed(read):
            message.set_sender(app)
            app.post_message(message)
    await pilot.pause(0)


CONTROL_WRITTEN = set(string.ascii_uppercase + string.digits + " .,=-()_;\n")
"""Characters the control itself writes into NC text and fields: block numbers
(renumbering), cycle calls, JOG windows' MDA blocks, a new program's header line,
NC data shown in a value dialog. Everything else (lower-case letters, ``^``,
``+*/[]:"'$<>``) in a field must have been typed into that field by the monkey."""


class TypedLedger:
    """Which characters each text field may hold.

    A field may hold what the control writes (:data:`CONTROL_WRITTEN`), the text it
    was made with or that was loaded into it (a program opened, the MDA buffer shown),
    what went through the clipboard, and the characters the monkey typed while the app
    handed them to that field. A character counts as typed only when the key the app
    hands on is a character the monkey sent in this step: one the app made up (``^`` of
    a repeated Alt+G, a chord's letter) counts for no field.

    The fields: the MDA editor with the kernel's MDA buffer; the program editors as one
    (the journal restores, find/replace writes what was typed into the find fields);
    each input field on its own.
    """

    def __init__(self, app, monkeypatch: pytest.MonkeyPatch) -> None:
        self.app = app
        self.sent: deque[str] = deque()
        """Characters of the monkey's keys of this step not yet handed to a widget."""
        self.allowed: defaultdict[object, set[str]] = defaultdict(lambda: set(CONTROL_WRITTEN))
        self.typed_into_inputs: set[str] = set()
        handle = app.on_event

        async def on_event(event) -> None:
            if isinstance(event, events.Key) and event.character and event.is_printable:
                self._handed_on(event.character)
            await handle(event)

        app.on_event = on_event
        copy = app.copy_to_clipboard

        def copy_to_clipboard(text: str) -> None:
            self.allowed["clipboard"] |= set(text)
            copy(text)

        app.copy_to_clipboard = copy_to_clipboard
        self._record_texts_put_in(monkeypatch)

    def _record_texts_put_in(self, monkeypatch: pytest.MonkeyPatch) -> None:
        """Texts a field is made with, and those loaded into an editor (not typed)."""
        ledger = self
        input_init, area_init, load_text = Input.__init__, TextArea.__init__, TextArea.load_text

        def new_input(field: Input, value: str | None = None, *args, **kwargs) -> None:
            ledger.allowed[field] |= set(value or "")
            input_init(field, value, *args, **kwargs)

        def new_area(area: TextArea, text: str = "", *args, **kwargs) -> None:
            ledger.allowed[self.key(area, kwargs.get("id"))] |= set(text)
            area_init(area, text, *args, **kwargs)

        def loaded(area: TextArea, text: str) -> None:
            ledger.allowed[self.key(area)] |= set(text)
            load_text(area, text)

        monkeypatch.setattr(Input, "__init__", new_input)
        monkeypatch.setattr(TextArea, "__init__", new_area)
        monkeypatch.setattr(TextArea, "load_text", loaded)

    @staticmethod
    def key(field, field_id: str | None = None) -> object:
        """The ledger entry of ``field``."""
        if isinstance(field, TextArea):
            return "MDA" if (field_id or field.id) == "mda-editor" else "programs"
        return field

    def sending(self, keys: list[str]) -> None:
        """The monkey sends ``keys`` now (one step)."""
        self.sent.clear()
        for key in keys:
            event = key_event(key)
            if event.character and event.is_printable:
                self.sent.append(event.character)

    def _handed_on(self, character: str) -> None:
        if character not in self.sent:
            return  # not the monkey's: counts for no field
        while self.sent.popleft() != character:
            pass  # keys before it that never arrived as text
        field = self.app.focused
        if isinstance(field, (TextArea, Input)):
            self.allowed[self.key(field)].add(character)
            if isinstance(field, Input):
                self.typed_into_inputs.add(character)

    def stray_characters(self) -> list[tuple[str, str]]:
        """Fields on screen and the MDA buffer holding characters nobody typed into them."""
        texts = [(f"TextArea#{a.id}", self.key(a), a.text) for a in self.app.screen.query(TextArea)]
        texts += [(f"Input#{f.id}", f, f.value) for f in self.app.screen.query(Input)]
        texts.append(("MDA buffer", "MDA", self.app.bridge.nck.status().channel.mda_text))
        found = []
        for where, key, text in texts:
            allowed = self.allowed[key] | self.allowed["clipboard"]
            if key == "programs":
                allowed |= self.typed_into_inputs  # find/replace
            stray = set(text) - allowed
            if stray:
                found.append((where, "".join(sorted(stray))))
        return found


async def run_monkey(tmp_path: Path, seed: int, bursts: int, burst_keys: int,
                     monkeypatch: pytest.MonkeyPatch) -> int:
    """Send ``bursts`` x ``burst_keys`` random keys; return how many were sent.

    A step sends one key (70 %), a burst of 2 to 8 keys (15 %) or one key pressed two
    to four times, as a double press or key auto-repeat sends it (15 %; with the Alt
    keys of the keymap among the keys, repeated Alt+G, Alt+K); bursts and repeats go
    through the terminal parser.
    """
    program = tmp_path / "MONKEY.MPF"
    program.write_text(PROGRAM)
    app = make_app(data_dir=str(tmp_path / "data"), program=str(program), realtime=False)
    keys = monkey_keys()
    rng = random.Random(seed)
    parser = PanelKeyParser()
    ledger = TypedLedger(app, monkeypatch)
    sent = 0
    async with app.run_test(size=SIZE) as pilot:
        for _ in range(bursts):
            step_keys = 0
            while step_keys < burst_keys:
                key = rng.choice(keys)
                roll = rng.random()
                if roll < 0.7 or terminal_bytes(key) is None:
                    step = [key]
                    ledger.sending(step)
                    await send_key(app, pilot, key)
                else:
                    if roll < 0.85:
                        step = [key] + [k for k in rng.choices(keys, k=rng.randint(1, 7))
                                        if terminal_bytes(k) is not None]
                    else:
                        step = [key] * rng.randint(2, 4)
                    ledger.sending(step)
                    await send_terminal_keys(app, pilot, parser, step, rng)
                step_keys += len(step)
                sent += len(step)
                if rng.random() < 0.2:
                    app.bridge.advance(rng.choice([0.0, 0.05, 0.5]))
            await pilot.pause()
            assert_consistent(app)
            assert ledger.stray_characters() == []
        assert_consistent(app)
    app.nc_session.quit()
    return sent


async def test_monkey_short(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """About 120 keys in three rounds (the long version runs under ``make fuzz``)."""
    assert await run_monkey(tmp_path, 11, bursts=3, burst_keys=40, monkeypatch=monkeypatch) >= 120


@pytest.mark.fuzz
@pytest.mark.parametrize("seed", range(20))
async def test_monkey_long(seed: int, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """20 seeds x about 1,000 keys = 20,000 keys."""
    assert await run_monkey(tmp_path, 1000 + seed, bursts=20, burst_keys=50, monkeypatch=monkeypatch) >= 1000


async def test_help_opened_again_after_an_area_switch(tmp_path: Path) -> None:
    """Found by the monkey: F11, an area key, F11 again raised DuplicateIds('help')."""
    from hmi.help import HelpScreen

    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    keys = {b.id: b.keys.split(",")[0].strip() for b in default_keymap().bindings}
    async with app.run_test(size=SIZE) as pilot:
        for area in ("area.program_manager", "area.machine", "area.diagnostics"):
            await pilot.press(keys["help"])
            await pilot.pause()
            assert isinstance(app.screen, HelpScreen)
            await pilot.press(keys[area])
            await pilot.pause()
            assert not isinstance(app.screen, HelpScreen)
        await pilot.press(keys["help"], keys["area.machine"], keys["help"])
        await pilot.pause()
        assert_consistent(app)
    app.nc_session.quit()


async def test_enter_then_an_area_key_leaves_the_dialog_in_its_area(tmp_path: Path) -> None:
    """Found by the fast monkey: Enter in a dialog, then an area key before the dialog saw
    its Input.Submitted, popped the new area's only screen (ScreenStackError).

    The area key follows the Enter after a varying number of event-loop turns, so that
    it lands before, between and after the steps of the dialog's Enter handling.
    """
    from screens.program_manager import PromptDialog

    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    keys = {b.id: b.keys.split(",")[0].strip() for b in default_keymap().bindings}
    async with app.run_test(size=SIZE) as pilot:
        for turns in range(10):
            await pilot.press(keys["area.program_manager"])
            await pilot.pause()
            results: list[object] = []
            dialog = PromptDialog("Name")
            app.push_screen(dialog, results.append)
            await pilot.pause()
            for key in ("enter", keys["area.diagnostics"]):
                event = key_event(key)
                event.set_sender(app)
                app.post_message(event)
                for _ in range(turns):
                    await asyncio.sleep(0)
            await pilot.pause()
            assert app.current_mode == "diagnostics"
            assert_consistent(app)
            await pilot.press(keys["area.program_manager"])
            await pilot.pause()
            if results:  # the dialog had closed before the area key came
                assert results == [""] and app.screen is not dialog
            else:  # it waited in its area, unanswered, and still works
                assert app.screen is dialog
                await pilot.press("enter")
                await pilot.pause()
                assert results == [""] and app.screen is not dialog
    app.nc_session.quit()
