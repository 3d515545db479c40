"""Simultaneous recording: the cut of the program running in AUTO, as far as it has executed.

The kernel feeds every block its interpreter hands over (with the block the motion is
executing now); the commands are released as execution passes them, exactly as the
headless run releases them (:class:`nck.headless.ExecutedCommands`), and recorded as chords
(:class:`nck.simulation.run.PathRecorder`). :meth:`LiveRecording.snapshot` sweeps the chords
recorded since the last snapshot into the blank and answers a :class:`Simulation` of the
cut so far — the same model and view as the editor's simulation, growing while the program
runs, block by block in single block.

Our choices (the manuals describe the HMI function, not its model): the recording starts
with each program start in AUTO (from RESET) and holds at most :data:`MAX_CHORDS` chords
(a program looping for ever stops being recorded, the view says so); the blank is chosen
as the editor's simulation chooses it (``WORKPIECE`` of the main program, the clamped blank,
else a box around what was cut so far, refitted — and cut again — when the path leaves it).
"""

from __future__ import annotations

from typing import Any

from nck import canon
from nck.headless import ExecutedCommands, HeadlessRun
from nck.machine import MachineConfig
from nck.ncdata import NcData
from nck.simulation.blank import Blank
from nck.simulation.run import (
    AUTO_CHORD_RESOLUTION_MM,
    PathRecorder,
    SimEvent,
    Simulation,
    choose_blank,
    material_model,
    sweep_path,
)
from nck.simulation.turning import TurnProfile
from nck.simulation.zmap import ZMap

MAX_CHORDS = 2_000_000
"""At most this many chords are recorded per program run (about 100 MB of path)."""


class LiveRecording:
    """The cut of one AUTO program run so far (see the module docstring)."""

    def __init__(self, machine: MachineConfig, data: NcData, program: str, text: str,
                 tool: int = 0, edge: int = 1) -> None:
        self.machine = machine
        self.data = data
        self.program = program
        self.text = text
        self.turning = machine.kind == "lathe"
        self.recorder = PathRecorder(data, chord_tol_mm=AUTO_CHORD_RESOLUTION_MM / 8.0, turning=self.turning,
                                     main=program)
        self.recorder.tool, self.recorder.selected, self.recorder.edge = tool, tool, edge
        self.full = False
        self._chords = 0
        self._executed = ExecutedCommands(HeadlessRun(status="running"), self._record, keep_commands=False)
        self._model: ZMap | TurnProfile | None = None
        self._swept = 0
        self._events: list[SimEvent] = []
        self.blocks = 0

    def _record(self, command: canon.CanonCommand) -> None:
        if self.full:
            return
        self.recorder(command)
        if isinstance(command, canon.Motion):
            self._chords += self.recorder.counts[-1] if self.recorder.counts else 0
            self.full = self._chords >= MAX_CHORDS

    def interpreted(self, block: Any, executing: canon.Source | None) -> None:
        """A block from the interpreter; ``executing``: the block the motion runs now."""
        self.blocks += 1
        self.recorder.block(block)
        self._executed.interpreted(getattr(block, "commands", ()), executing)

    def snapshot(self, executing: canon.Source | None, ended: bool, time_s: float = 0.0) -> Simulation:
        """The cut as far as the machine has executed (``ended``: the run is over, all of it);
        status ``running``, ``ended`` or ``full`` (:data:`MAX_CHORDS` reached: the rest of the run is
        not recorded)."""
        if ended:
            self._executed.finish(None, {}, {})
        else:
            self._executed.interpreted((), executing)
        path = self.recorder.toolpath()
        blank = self._blank(path)
        if self._model is None or self._model.blank != blank:
            self._model = material_model(blank, None, self.turning)
            self._swept = 0
            self._events = []
        self._events.extend(sweep_path(self._model, path, first=self._swept))
        self._swept = len(path.starts)
        status = "full" if self.full else "ended" if ended else "running"
        return Simulation(blank, self._model, path, list(self._events), [], status, time_s, {}, self.blocks)

    def _blank(self, path: Any) -> Blank:
        if self._model is not None and self._model.blank.kind != "path":
            return self._model.blank
        blank = choose_blank(self.text, self.data.machine_setup, self.recorder.mcs_minus_wcs, path, self.turning)
        if blank.kind == "path" and self._model is not None and _inside(self._model.blank, blank):
            return self._model.blank  # the path still fits the box it had: keep cutting it
        return blank


def _inside(outer: Blank, inner: Blank) -> bool:
    """True when ``inner``'s extents lie within ``outer``'s."""
    pairs = ((outer.x_mm, inner.x_mm), (outer.y_mm, inner.y_mm), (outer.z_mm, inner.z_mm))
    return all(o[0] <= i[0] + 1e-9 and i[1] <= o[1] + 1e-9 for o, i in pairs)

