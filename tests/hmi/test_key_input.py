"""Keys reach the HMI as the operator typed them: no key typed as text, none reordered.

The terminal tests feed the bytes an xterm-like terminal (tmux) sends into the
HMI's parser, whole and split into reads the way a burst or an auto-repeat
arrives (reads a few ms apart, well inside the parser's escape delay), and post
what the parser makes of them to the app, as the terminal driver does.
"""

from __future__ import annotations

import os
import string
import threading

from textual import events
from textual.drivers.linux_driver import LinuxDriver

from nck import commands as c

from hmi.app import HmiApp
from hmi.key_input import PanelKeyParser, TerminalReader
from hmi.terminal_driver import PanelTerminalDriver
from hmi.keymap import default_keymap
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck
from tests.hmi.terminal_bytes import terminal_bytes

ALT_G = "\x1bg"  # CYCLE START as the terminal sends it (ESC + letter)
ALT_K = "\x1bk"  # SINGLE BLOCK
ALT_D = "\x1bd"  # MDA
SHIFT_F1 = "\x1b[1;2P"  # VSK1
F1 = "\x1bOP"
UP, HOME = "\x1b[A", "\x1b[H"


def parse(*reads: str) -> list[events.Key]:
    """The keys the HMI's parser reports for these reads (no escape delay between them)."""
    parser = PanelKeyParser()
    return [m for read in reads for m in parser.feed(read) if isinstance(m, events.Key)]


def names(keys: list[events.Key]) -> list[str]:
    return [key.key for key in keys]


def splits(data: str) -> list[tuple[str, ...]]:
    """``data`` whole, and cut into two reads at every position."""
    return [(data,)] + [(data[:i], data[i:]) for i in range(1, len(data))]


def test_repeated_alt_key_is_read_as_alt_keys_however_the_reads_fall() -> None:
    for reads in splits(ALT_G * 3) + [tuple(ALT_G * 3)]:
        keys = parse(*reads)
        assert names(keys) == ["alt+g"] * 3, reads
        assert all(key.character is None for key in keys), reads


def test_alt_key_between_text_keeps_its_place() -> None:
    for reads in splits("G4" + ALT_G + "F1" + ALT_K + ALT_K + "X"):
        assert names(parse(*reads)) == ["G", "4", "alt+g", "F", "1", "alt+k", "alt+k", "X"], reads


def test_sequences_and_plain_keys_still_read_as_before() -> None:
    burst = ALT_D + SHIFT_F1 + F1 + UP + HOME + "a" + "\x1b[1;5C"
    for reads in splits(burst):
        assert names(parse(*reads)) == ["alt+d", "shift+f1", "f1", "up", "home", "a",
                                        "ctrl+right"], reads


def keymap_keys() -> list[str]:
    """Every key of data/keymap.toml; Shift+F3 aside (its bytes read as a cursor report,
    which the app turns back into the key, tests/hmi/test_shift_f3.py)."""
    keys = [k.strip() for b in default_keymap().bindings for k in b.keys.split(",")]
    return [k for k in keys if k != "shift+f3"]


def test_every_keymap_key_in_one_burst_arrives_as_sent() -> None:
    keys = keymap_keys()
    burst = "".join(terminal_bytes(key) for key in keys)
    assert names(parse(burst)) == keys
    doubled = "".join(terminal_bytes(key) * 2 for key in keys)  # every key pressed twice
    assert names(parse(doubled)) == [key for key in keys for _ in range(2)]
    assert all(not key.is_printable for key in parse(doubled))


def test_alt_chord_never_carries_text() -> None:
    """Bound or not, an Alt chord is a command, never a character to type.

    Textual's own table read ESC 1 as ``¡`` and ESC f as Ctrl+Right (JOG +).
    """
    for letter in string.ascii_lowercase + string.digits:
        (key,) = parse("\x1b" + letter)
        assert key.key == f"alt+{letter}" and key.character is None and not key.is_printable
    (key,) = parse("\x1bG")
    assert key.key == "alt+shift+g" and key.character is None
    assert [k.key for k in parse("\x1b-\x1b=")] == ["alt+minus", "alt+equals_sign"]


def test_terminal_driver_reads_through_the_panel_parser(fake_app: HmiApp) -> None:
    assert fake_app.get_driver_class() is PanelTerminalDriver
    assert issubclass(PanelTerminalDriver, LinuxDriver)
    read_end, write_end = os.pipe()
    driver = PanelTerminalDriver.__new__(PanelTerminalDriver)  # only its reader, no terminal set-up
    driver.fileno, driver.exit_event = read_end, threading.Event()
    received: list[str] = []

    def take(message) -> None:
        received.append(message.key)
        if len(received) == 4:
            driver.exit_event.set()

    driver.process_message = take
    os.write(write_end, ALT_G.encode() * 2 + "äx".encode())
    driver.run_input_thread()  # returns once the four keys are through
    os.close(read_end)
    os.close(write_end)
    assert received == ["alt+g", "alt+g", "ä", "x"]


def test_reads_split_inside_a_character_or_a_sequence() -> None:
    reader = TerminalReader()
    data = (ALT_G + "ä" + SHIFT_F1 + ALT_G).encode()
    keys = [m.key for i in range(len(data)) for m in reader.feed(data[i:i + 1])]  # byte by byte
    assert keys == ["alt+g", "ä", "shift+f1", "alt+g"]


async def feed_terminal(app: HmiApp, pilot, *reads: str) -> None:
    """Post what the parser reads from ``reads`` to the app (as the driver does), then settle."""
    for key in parse(*reads):
        key.set_sender(app)
        app.post_message(key)
    await pilot.pause()


def cycle_starts(fake: FakeNck) -> int:
    return sum(isinstance(command, c.CycleStart) for command in fake.submitted)


async def test_double_cycle_start_types_nothing_into_mda(fake: FakeNck, fake_app: HmiApp) -> None:
    """Issue 18 repro: Alt+D, Shift+F1, ``G4 F1``, Alt+G Alt+G quickly gave ``G4 F1^g``."""
    cases = splits(ALT_G * 2) + [tuple(ALT_G * 2)]
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        await pilot.press(*"G4 F1")
        for reads in cases:
            before = cycle_starts(fake)
            await feed_terminal(fake_app, pilot, *reads)
            assert fake.mda_text == "G4 F1", reads
            assert cycle_starts(fake) == before + 2, reads


async def test_repeated_single_block_types_nothing_into_the_editor(fake: FakeNck,
                                                                  fake_app: HmiApp) -> None:
    """Issue 18: in the editor Alt+K four times at 10-60 ms inserted ``^k`` three to five times."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        editor = fake_app.screen.query_one("#mda-editor")
        await feed_terminal(fake_app, pilot, "N1", ALT_K, ALT_K + ALT_K[0], ALT_K[1:] + ALT_K, "X")
        assert editor.text == "N1X"
        await pilot.press("alt+k", "alt+k", "alt+k", "alt+k")  # the same four keys via Pilot
        assert editor.text == "N1X"


BURST = [*"AAA", "up", *"BBB", "home", *"CCC"]
"""Issue 18: text, a cursor key, text, Home, text, arriving at once (paste, a fast typist)."""


async def post_burst(app: HmiApp, pilot, keys: list[str]) -> None:
    """Post keys to the app all at once, as the driver does with one read, then settle."""
    for name in keys:
        key = events.Key(name, name if len(name) == 1 else None)
        key.set_sender(app)
        app.post_message(key)
    await pilot.pause()


async def test_cursor_keys_in_a_burst_apply_in_order_in_mda(fake: FakeNck,
                                                            fake_app: HmiApp) -> None:
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        await pilot.press(*"N1", "enter", *"N2")
        await post_burst(fake_app, pilot, BURST)
        # AAA at the end of N2; Up to the end of N1 (column 2); BBB; Home; CCC at column 0
        assert fake.mda_text == "CCCN1BBB\nN2AAA"
        await pilot.press("down", "end", "backspace", "backspace", "home", "delete", "X")
        assert fake.mda_text == "CCCN1BBB\nX2A"


async def test_cursor_keys_in_a_burst_apply_in_order_in_the_program_editor(tmp_path) -> None:
    from tests.program_screens.conftest import make_program_app, nc_files

    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "BURST.MPF").write_text("N10 G0 X0\nN20 M30\n")
    app = make_program_app(root)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "enter")
        await pilot.pause()
        editor = app.screen.editor
        await pilot.press("ctrl+end")
        await post_burst(app, pilot, BURST)
        # the last line is empty: AAA there; Up to line 2 column 3; BBB; Home; CCC
        assert editor.text == "N10 G0 X0\nCCCN20BBB M30\nAAA"
        await pilot.press(*BURST)  # the same keys through Pilot, without pauses
        # from line 2 column 3: AAA; Up to line 1 column 6; BBB; Home; CCC
        assert editor.text == "CCCN10 G0BBB X0\nCCCAAAN20BBB M30\nAAA"
        await pilot.press("f2")  # the search field, an Input: Backspace in a burst
        await pilot.pause()
        find = app.screen.query_one("#prog-find")
        assert app.focused is find
        await post_burst(app, pilot, [*"G12", "backspace", "backspace", "3", "left", "left",
                                      "delete", "N"])
        assert find.value == "N3"


async def test_text_typed_right_behind_the_mode_key_goes_into_mda(fake: FakeNck,
                                                                  fake_app: HmiApp) -> None:
    """Issue 18 repro as one burst from JOG: Alt+D, Shift+F1, ``G4 F1``. The MDA editor took
    the focus only after the keys already queued (Textual's ``focus()`` waits its turn at the
    app), so the text went nowhere (found in tmux: the MDA stayed empty)."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await post_burst(fake_app, pilot, ["alt+d", "shift+f1", *"G4 F1"])
        assert fake.mda_text == "G4 F1"
        await post_burst(fake_app, pilot, ["alt+j", "alt+d", "shift+f1", *"X1"])
        assert fake.mda_text == "X1"
        await feed_terminal(fake_app, pilot, "\x1bj" + ALT_D + SHIFT_F1 + "G4 F2" + ALT_G + ALT_G)
        assert fake.mda_text == "G4 F2"
