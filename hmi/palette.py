"""The command palette's places: every operating area and every softkey of its top level.

The palette (Ctrl+P, ``app.palette`` in ``data/keymap.toml``) offers Textual's
system commands and, through :class:`PlaceProvider`, the places of the panel:
an area (``Machine``, reached with Alt+M) and each softkey of an area's
top softkey level, horizontal and vertical (``Machine ▸ Block search``, reached
with Alt+M, F5), and the softkeys of the levels such a key opens
(``Diagnostics ▸ More ▸ Version``, Alt+A, F8, F2). The softkeys are read from the menus
the area screens show (:meth:`hmi.area.AreaBase.softkey_menu`, and for a level a key opens
the screen method the key names, :attr:`hmi.softkeys.Softkey.submenu`), so the palette never
holds a table of its own. Vertical softkeys depend on the area's view: the palette lists
those of the view the area has now.

Choosing a place runs the app's ``go_to_place`` action: the area key, then the
softkeys as their function keys would press them (refused in the panel's words when
the access level or the state does not allow it).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable, Protocol

from rich.align import Align
from rich.text import Text
from textual.command import CommandList, CommandPalette, DiscoveryHit, Hit, Hits, Provider

from hmi.i18n import _
from hmi.keymap import Keymap
from hmi.softkeys import Softkey, SoftkeyMenu, one_line

PATH_SEPARATOR = " ▸ "
SOFTKEY_PATH_SEPARATOR = "/"
"""Between the softkey ids of a place below the top level (``diag.more/diag.version``)."""
MAX_LEVELS = 3
"""How deep the palette follows softkeys into the levels they open."""


@dataclass(frozen=True, slots=True)
class Place:
    """A place the palette can go to.

    Attributes:
        path: what the operator reads, ``Machine ▸ Block search``.
        keys: the panel keys that lead there, ``Alt+M, F5``.
        area_id: the operating area (mode id).
        softkey_id: the softkey to press there (``""``: the area itself); below the top
            level the ids of the softkeys to press in turn, joined by ``/``.
        english_path: the path in English (the code's labels): a German panel finds a
            place by its English name too (``language`` finds ``Sprache wechseln``).
    """

    path: str
    keys: str
    area_id: str
    softkey_id: str = ""
    english_path: str = ""


class PanelCommandPalette(CommandPalette):
    """Textual's command palette, its "No matches found" line in the panel's language.

    Textual adds that line itself (an option with the palette's no-matches id) and then shows
    the list; when the list is shown, this palette says the line again through the catalogue.
    """

    def watch__list_visible(self, visible: bool) -> None:
        """The list is shown or hidden (Textual's own watcher has run): translate the no-matches line."""
        if not visible:
            return
        command_list = self.query_one(CommandList)
        no_matches = self._NO_MATCHES
        if command_list.option_count == 1 and command_list.get_option_at_index(0).id == no_matches:
            command_list.replace_option_prompt(no_matches, Align.center(Text(_("No matches found"), style="not bold")))


SubLevel = Callable[[Softkey], SoftkeyMenu | None]
"""The softkey level a softkey opens (its :attr:`Softkey.submenu`), None for a key that opens none."""


def label_text(label: str) -> str:
    """A softkey label as a place's path shows it: on one line, without the ``▸`` of a level key."""
    return one_line(label).removesuffix("▸").rstrip()


def area_places(area_id: str, area_label: str, menu: SoftkeyMenu, keymap: Keymap,
                sub_level: SubLevel | None = None) -> list[Place]:
    """The area itself and each softkey of ``menu`` with their keys, and below a key that opens
    a softkey level (``sub_level``) the softkeys of that level (``Diagnostics ▸ More ▸ Version``).

    ``area_label`` and the softkeys' labels are given in English and translated here; each
    place keeps its English path as well.
    """
    area_key = keymap.by_id(f"area.{area_id}").key_display
    places = [Place(label_text(_(area_label)), area_key, area_id, english_path=label_text(area_label))]

    def add_level(level: SoftkeyMenu, parent: Place, depth: int) -> None:
        for prefix, bar in (("h", level.horizontal), ("v", level.vertical)):
            for index, softkey in enumerate(bar, start=1):
                if softkey is None:
                    continue
                ids = parent.softkey_id
                here = Place(parent.path + PATH_SEPARATOR + label_text(_(softkey.label)),
                             f"{parent.keys}, {keymap.by_id(f'softkey.{prefix}{index}').key_display}",
                             area_id, f"{ids}{SOFTKEY_PATH_SEPARATOR}{softkey.id}" if ids else softkey.id,
                             parent.english_path + PATH_SEPARATOR + label_text(softkey.label))
                places.append(here)
                below = sub_level(softkey) if sub_level is not None and depth < MAX_LEVELS else None
                if below is not None:
                    add_level(below, here, depth + 1)

    add_level(menu, places[0], 1)
    return places


class PlaceSource(Protocol):
    """What the provider needs of the app: the places of the panel as they are now."""

    def palette_places(self) -> Iterable[Place]:
        """Every place, areas in panel order, each followed by its softkeys."""
        ...  # pragma: no cover - protocol


class PlaceProvider(Provider):
    """Finds an area or a softkey by (part of) its name; choosing it goes there."""

    _places: list[Place]

    async def startup(self) -> None:
        """Read the places once, as the palette opens (not on every key typed)."""
        source: PlaceSource = self.app  # type: ignore[assignment]
        self._places = list(source.palette_places())

    def _go(self, place: Place):
        async def go() -> None:
            await self.app.run_action(f"go_to_place({place.area_id!r}, {place.softkey_id!r})")
        return go

    async def search(self, query: str) -> Hits:
        """Places whose path (in the panel's language, else in English) matches ``query``
        (fuzzy), best first; the keys as help."""
        matcher = self.matcher(query)
        for place in self._places:
            score = matcher.match(place.path)
            shown = matcher.highlight(place.path)
            if score <= 0 and place.english_path != place.path:
                score = matcher.match(place.english_path)
                shown = Text(place.path)
            if score > 0:
                yield Hit(score, shown, self._go(place), text=place.path, help=place.keys)

    async def discover(self) -> Hits:
        """With nothing typed: the operating areas."""
        for place in self._places:
            if not place.softkey_id:
                yield DiscoveryHit(Text(place.path), self._go(place), text=place.path, help=place.keys)
