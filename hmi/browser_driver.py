"""The panel in a browser tab (``hmi --serve``): Textual's web driver with the panel's key reader.

textual-serve starts one ``hmi`` per browser tab with Textual's web driver, which
gets the keys as the bytes a terminal would send (the browser's terminal turns
Alt+D into ESC d). Textual's own parser reports such a pair as a printable key
``alt+d`` carrying the character ``d``, which the panel does not run as the MDA
key. :class:`PanelBrowserDriver` reads them with :class:`hmi.key_input.TerminalReader`,
as the terminal driver does: every Alt chord at once and never as text.
"""

from __future__ import annotations

from textual.drivers._byte_stream import ByteStream
from textual.drivers.web_driver import WebDriver

from hmi.key_input import TerminalReader

STDIN_PACKET = "D"
"""Packet type of the bytes typed in the browser (the others are meta packets: size, focus, quit)."""


class InputEnded(Exception):
    """textual-serve said "exit": no more input comes."""


class PanelBrowserDriver(WebDriver):
    """Textual's web driver whose keys go through the panel's key reader."""

    def on_meta(self, packet_type: str, payload: dict[str, object]) -> None:
        """A meta packet from textual-serve; "exit" ends the input thread."""
        if packet_type == "exit":
            raise InputEnded()
        super().on_meta(packet_type, payload)

    def run_input_thread(self) -> None:
        """Read the packets from textual-serve until the app exits; post the keys the reader makes."""
        reader = TerminalReader()
        packets = ByteStream()
        try:
            for data in self._input_reader:
                for packet_type, payload in packets.feed(data) if data else ():
                    if packet_type == STDIN_PACKET:
                        for message in reader.feed(payload):
                            self.process_message(message)
                    else:
                        self._on_meta(packet_type, payload)
                for message in reader.tick():
                    self.process_message(message)
        except InputEnded:
            pass
        finally:
            self._input_reader.close()
