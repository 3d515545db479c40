"""The command palette (issue 27): Ctrl+P, the system commands and the places of the panel."""

from __future__ import annotations

import asyncio

from textual.command import CommandPalette
from textual.widgets import Input

from hmi.app import HmiApp
from hmi.help import HelpScreen
from hmi.i18n import language, set_language
from hmi.keymap import default_keymap
from hmi.palette import PlaceProvider, area_places
from hmi.softkeys import Softkey, SoftkeyMenu
from tests.burst import burst
from tests.hmi.conftest import SIZE


def test_palette_key_is_one_key_of_the_keymap() -> None:
    """Ctrl+P opens the palette; it is bound once, in data/keymap.toml, and nothing else uses it."""
    keymap = default_keymap()
    assert keymap.key_of("app.palette") == "ctrl+p"
    holders = [b.id for b in keymap.bindings if "ctrl+p" in (k.strip() for k in b.keys.split(","))]
    assert holders == ["app.palette"]


def test_places_have_path_and_panel_keys() -> None:
    """A softkey's place reads area ▸ label and its keys are the area key then the slot's key
    (keymap contract: F1…F8 = HSK1…8, Shift+F1…F8 = VSK1…8)."""
    menu = SoftkeyMenu.of([None, Softkey("x.g", "G\nfunctions", "noop")], [Softkey("x.v", "Start\nsearch", "noop")])
    places = area_places("machine", "Machine", menu, default_keymap())
    assert [(p.path, p.keys, p.softkey_id) for p in places] == [
        ("Machine", "Alt+M", ""),
        ("Machine ▸ G functions", "Alt+M, F2", "x.g"),
        ("Machine ▸ Start search", "Alt+M, Shift+F1", "x.v"),
    ]


async def _choose(pilot, text: str) -> None:
    await pilot.press("ctrl+p", *text)
    await pilot.pause()
    await pilot.press("down", "enter")
    await pilot.pause()


async def test_palette_finds_a_softkey_of_another_area(fake_app: HmiApp) -> None:
    """Machine area: Ctrl+P, "wear", choose → Parameter area, tool wear view."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await _choose(pilot, "wear")
        assert not isinstance(fake_app.screen, CommandPalette)
        assert fake_app.current_mode == "parameter"
        assert fake_app.screen.view == "wear"
        await pilot.press("alt+m")  # the palette is gone from every area
        assert fake_app.current_mode == "machine" and len(fake_app.screen_stack) == 1


async def test_palette_finds_an_area(fake_app: HmiApp) -> None:
    """Typing part of an area's name finds the area; choosing it shows the area."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await _choose(pilot, "diag")
        assert fake_app.current_mode == "diagnostics"
        assert isinstance(fake_app.screen, type(fake_app.area_screen))


async def test_palette_in_a_burst(fake_app: HmiApp) -> None:
    """Ctrl+P, the name and the choice in one burst; the keys after it reach the area."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p", *"g fun", "down", "enter", "alt+o")
        await pilot.pause()
        assert fake_app.current_mode == "parameter"
        await pilot.press("alt+m")
        assert fake_app.screen.view == "gfunc"


async def test_keys_behind_a_name_wait_for_its_search(fake_app: HmiApp, monkeypatch) -> None:
    """On a loaded machine the search of the typed name ends after the keys behind it have
    arrived: Down and Enter still choose from its list (no key lost; the guide's key rule).
    The search is made slow here by a provider that yields to the event loop for a while
    before each search, as a busy machine does."""
    searched = PlaceProvider.search

    async def slow_search(self: PlaceProvider, query: str):
        await asyncio.sleep(0.3)  # the other tasks (the keys behind) run meanwhile
        async for hit in searched(self, query):
            yield hit

    monkeypatch.setattr(PlaceProvider, "search", slow_search)
    pressed = asyncio.Event()  # the choice presses its softkey after the next refresh
    press_softkeys = HmiApp._press_softkeys

    def pressing(app: HmiApp, *args) -> None:
        press_softkeys(app, *args)
        pressed.set()

    monkeypatch.setattr(HmiApp, "_press_softkeys", pressing)
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p", *"g fun", "down", "enter")
        await asyncio.wait_for(pressed.wait(), timeout=30.0)
        await pilot.pause()
        assert not isinstance(fake_app.screen, CommandPalette)
        assert fake_app.current_mode == "machine" and fake_app.screen.view == "gfunc"


async def test_keymap_keys_never_type_into_the_palette(fake_app: HmiApp) -> None:
    """A softkey key in the palette neither types nor presses the area's softkey; an area key
    closes the palette and shows the area."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p", "a", "b", "f2", "shift+f1", "ctrl+up")
        palette = fake_app.screen
        assert isinstance(palette, CommandPalette)
        assert palette.query_one(Input).value == "ab"
        await pilot.press("alt+o")
        assert fake_app.current_mode == "parameter" and not isinstance(fake_app.screen, CommandPalette)
        await pilot.press("alt+m")
        assert len(fake_app.screen_stack) == 1 and fake_app.screen.view is None


async def test_escape_closes_the_palette(fake_app: HmiApp) -> None:
    """Escape leaves the palette, with or without a search typed (Textual's own palette binding;
    the panel kept every key that came back up to it, so Escape did nothing)."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p")
        await pilot.press("escape")
        assert not isinstance(fake_app.screen, CommandPalette)
        await burst(pilot, "ctrl+p", *"nothing like this", "escape", "escape")
        await fake_app.workers.wait_for_complete()
        await pilot.pause()
        assert not isinstance(fake_app.screen, CommandPalette) and len(fake_app.screen_stack) == 1


async def test_keys_command_shows_the_help(fake_app: HmiApp) -> None:
    """The system command "Keys" shows the F11 help of the keys in force."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await _choose(pilot, "keys")
        assert isinstance(fake_app.screen, HelpScreen)


async def test_theme_command_offers_the_hmi_themes(fake_app: HmiApp) -> None:
    """Theme lists the dark, light and high-contrast themes only; choosing one applies it."""
    assert set(fake_app.available_themes) == {"sinumerik", "operate-light", "high-contrast"}
    async with fake_app.run_test(size=SIZE) as pilot:
        assert fake_app.theme == "sinumerik"
        await _choose(pilot, "theme")
        assert isinstance(fake_app.screen, CommandPalette)
        await pilot.press(*"contrast")
        await pilot.pause()
        await pilot.press("down", "enter")
        await pilot.pause()
        assert fake_app.theme == "high-contrast"
        assert len(fake_app.screen_stack) == 1


def test_places_of_a_sub_level_have_their_path_and_keys() -> None:
    """A softkey that opens a level lists that level's softkeys below it: area ▸ key ▸ key."""
    more = SoftkeyMenu.of([None, Softkey("x.version", "Version", "noop")])
    menu = SoftkeyMenu.of([Softkey("x.more", "More\n▸", "more", submenu="more_menu")])
    places = area_places("diagnostics", "Diagnostics", menu, default_keymap(),
                         lambda key: more if key.submenu == "more_menu" else None)
    assert [(p.path, p.keys, p.softkey_id) for p in places] == [
        ("Diagnostics", "Alt+A", ""),
        ("Diagnostics ▸ More", "Alt+A, F1", "x.more"),  # the key's own ▸ is the path's
        ("Diagnostics ▸ More ▸ Version", "Alt+A, F1, F2", "x.more/x.version"),
    ]


async def test_palette_goes_to_a_softkey_of_a_sub_level(fake_app: HmiApp) -> None:
    """Ctrl+P "logbook" in a burst: Diagnostics ▸ More ▸ Logbook is found and shown (Alt+A, F8, F3)."""
    async with fake_app.run_test(size=SIZE) as pilot:
        paths = [place.path for place in fake_app.palette_places()]
        assert "Diagnostics ▸ More ▸ Logbook" in paths
        assert any(path.startswith("Program ▸ Edit ▸ ") for path in paths)
        assert any(path.startswith("Program ▸ Search ▸ ") for path in paths)
        assert "Machine ▸ Block search" in paths
        await pilot.press("ctrl+p", *"logbook", "down", "enter")
        await pilot.pause()
        await pilot.pause()
        assert fake_app.current_mode == "diagnostics"
        assert fake_app.screen.view == "logbook"


async def test_area_key_right_behind_the_choice_in_one_burst(fake_app: HmiApp) -> None:
    """The palette runs the chosen place after Enter (Textual: call_later); an area key typed
    right behind Enter in the same read of the terminal comes after it: the operator's last
    key decides where the panel stands (the guide's key rule: no key reordered)."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p", *"diagn")
        await pilot.pause()
        await burst(pilot, "down", "enter", "alt+o")
        await pilot.pause()
        assert not isinstance(fake_app.screen, CommandPalette)
        assert fake_app.current_mode == "parameter"


async def test_palette_texts_in_german(fake_app: HmiApp) -> None:
    """In German the palette's search field and its system commands speak German (Textual's
    own English texts are replaced where it takes them: the placeholder, the commands)."""
    set_language("de")
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p")
        await pilot.pause()
        assert fake_app.screen.query_one(Input).placeholder == "Befehle suchen…"
        names = [command.title for command in fake_app.get_system_commands(fake_app.screen)]
        assert names == ["Farbschema", "Tasten", "Bildschirmfoto", "Beenden"]
        await pilot.press(*"farbschema")
        await pilot.pause()
        await fake_app.workers.wait_for_complete()
        await pilot.press("down", "enter")
        await pilot.pause()
        assert fake_app.screen.query_one(Input).placeholder == "Farbschemata suchen…"


async def test_palette_finds_the_language_and_theme_selection(fake_app: HmiApp) -> None:
    """The language softkeys (Setup ▸ Password ▸ Change language ▸ Deutsch: F6, Shift+F5, then
    the language's vertical key) and the theme softkeys are places of the palette, with the
    keys that reach them; choosing "Deutsch" switches the panel to German."""
    async with fake_app.run_test(size=SIZE) as pilot:
        places = {place.path: place.keys for place in fake_app.palette_places()}
        assert places["Setup ▸ Password ▸ Change language"] == "Alt+S, F6, Shift+F5"
        assert places["Setup ▸ Password ▸ Change language ▸ Deutsch"] == "Alt+S, F6, Shift+F5, Shift+F2"
        assert places["Setup ▸ Password ▸ Change theme ▸ High contrast"] == "Alt+S, F6, Shift+F6, Shift+F3"
        await pilot.press("ctrl+p", *"deutsch")
        await pilot.pause()
        await fake_app.workers.wait_for_complete()
        await pilot.press("down", "enter")
        for _ in range(4):
            await pilot.pause()
        assert fake_app.current_mode == "setup"
        assert language() == "de"


async def test_german_palette_finds_places_by_german_and_english_names(fake_app: HmiApp) -> None:
    """In German "Sprache" and "language" both find Setup ▸ Kennwort ▸ Sprache wechseln; the
    hit shows the German path."""
    set_language("de")
    async with fake_app.run_test(size=SIZE) as pilot:
        places = [place for place in fake_app.palette_places()
                  if place.path == "Inbetriebnahme ▸ Kennwort ▸ Sprache wechseln"]
        assert len(places) == 1
        provider = PlaceProvider(fake_app.screen)
        await provider.startup()
        for query in ("Sprache", "language", "English"):
            found = [str(hit.text) async for hit in provider.search(query)]
            assert any(path.startswith("Inbetriebnahme ▸ Kennwort ▸ Sprache wechseln") for path in found), query
