"""HMI figures, measured in a process of their own (``python -m bench.hmi_probe SPAWN_EPOCH``).

Prints one JSON object: time from process spawn to the first frame (median
of fresh processes whose bytecode is cached, as at every start after the
first; the figure of this process, spawned by the caller, is reported too), CPU time
per screen refresh while a program runs (status poll to the frame written), keypress-to-repaint latency while it
runs (keys sent with Textual's Pilot, the kernel advancing on the bridge's
real-time clock, latency up to the first frame of the new screen), and the peak
RSS. With ``--program FILE`` that program is
imported into an NC file system, selected in AUTO and opened in the Program
area's editor before the measurements (memory with a large program). With
``--editor FILE`` only the editor is measured: the time its check of the whole
file takes from opening, and the area keys' latency while that check runs. With
``--simulation FILE`` the editor's simulation of that file: its time, and the redraw after a
scrub step or a zoom.
"""

from __future__ import annotations

import asyncio
import json
import resource
import statistics
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable

SHORT_PROGRAM = ("N10 G90 G0 X0 Y0 Z10\n"
                 + "".join(f"N{20 + 10 * k} G1 X{(k * 7) % 100} Y{(k * 3) % 50} F600\n" for k in range(200))
                 + "N9990 M30\n")


def _percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(fraction * (len(ordered) - 1))))]


async def _open_in_editor(app: Any, pilot: Any, path: str) -> Any:
    """Open ``path`` in the Program area's editor (as Program manager → Open does), back to Machine.

    Returns the Program area's screen (its check of the text runs on in a worker thread).
    """
    from hmi.program_files import ProgramFiles

    ProgramFiles.of_app(app).request_open(path)
    await pilot.press("alt+p")
    await pilot.pause()
    opened = getattr(app.screen, "program", None)
    if opened != path:
        raise RuntimeError(f"the editor did not open {path} (shows {opened})")
    editor_screen = app.screen
    await pilot.press("alt+m")
    await pilot.pause()
    return editor_screen


async def _wait_for_check(editor_screen: Any, pilot: Any, limit_s: float = 600.0) -> float:
    """Wait until the editor's check of the whole text is done (its memory counts); seconds waited."""
    started = time.perf_counter()
    while getattr(editor_screen, "_check_running", False) and time.perf_counter() - started < limit_s:
        await pilot.pause(0.5)
    return time.perf_counter() - started


async def _refresh_cpu(app: Any, pilot: Any, nck: Any, refreshes: int = 60) -> tuple[list[float], list[float]]:
    """CPU time of the event-loop thread per status refresh while the program runs.

    For each refresh the kernel advances 50 ms (not counted), then the bridge
    polls the new status and the time runs until the compositor has written
    the frame (``App._display`` wrapped). The second list runs on until Pilot's
    ``pause`` returns (the figure of earlier rounds): it adds Pilot's own work, a
    callback on every widget and the idle detection.
    """
    to_frame: list[float] = []
    with_pilot: list[float] = []
    with recorded_frames(app, time.thread_time) as frames:
        for _ in range(refreshes):
            nck.tick(0.05)
            await pilot.pause()
            frames.clear()
            t0 = time.thread_time()  # the event loop's thread: not the editor's check worker
            app.bridge.poll()
            for _ in range(500):
                if frames:
                    break
                await asyncio.sleep(0.001)
            painted = frames[0][0] if frames else time.thread_time()
            await pilot.pause()
            to_frame.append(painted - t0)
            with_pilot.append(time.thread_time() - t0)
    return to_frame, with_pilot


async def _key_latencies(app: Any, pilot: Any, presses: int = 40, keys: tuple[str, str] = ("alt+o", "alt+m"),
                         until: Callable[[], bool] | None = None) -> tuple[list[float], list[float]]:
    """Key-to-repaint latencies of area keys while the kernel runs on the bridge's own clock.

    The bridge's timer advances the kernel in real time (as in ``hmi``), so a
    key can arrive while a kernel tick or a status refresh is under way. Each
    latency runs from the moment Pilot hands the key to the driver to the first
    frame the compositor produces for the screen the key opened (recorded by
    wrapping ``App._display``). The Pilot round trip (``press`` + ``pause``) is
    reported too: it adds at least three of Textual's 20 ms idle-detection
    sleeps, so it is no measure of what the operator sees.

    ``keys``: the two area keys pressed in turn (default Parameter and Machine, a full
    area switch); ``until``: no more keys once it returns True (the latency of a key
    counts only if it was still False when the frame came).
    """
    app.bridge.start_realtime()
    with recorded_frames(app) as frames:
        await pilot.pause(0.3)
        latency: list[float] = []
        roundtrip: list[float] = []
        for k in range(presses):
            if until is not None and until():
                break
            key = keys[k % 2]
            await pilot.pause(0.06)  # let a timer tick fall anywhere relative to the key
            frames.clear()
            t0 = time.perf_counter()
            await pilot.press(key)
            await pilot.pause()
            if until is not None and until():
                break
            roundtrip.append(time.perf_counter() - t0)
            target = app.screen
            painted = next((t for t, screen in frames if screen is target), None)
            latency.append(painted - t0 if painted is not None else float("inf"))
    return latency, roundtrip


async def measure(spawn_epoch: float, program: Path | None) -> dict[str, float | str]:
    """Run the HMI under Textual's Pilot and collect the figures."""
    from nck import commands as c
    from nck import build_nck
    from nck.machine import load_machine
    from nck.ncdata import NcData

    from hmi.app import HmiApp
    from hmi.programs import DirectoryPrograms

    folder = Path(tempfile.mkdtemp())
    name = "BENCH.MPF"
    programs: Any
    if program is not None:  # in the NC file system, so that the editor can open it too
        from nck.storage import NcFileSystem

        programs = NcFileSystem(folder / "nc")
        name = programs.import_file(program).path.rpartition("/")[2]
    else:
        (folder / name).write_text(SHORT_PROGRAM)
        programs = DirectoryPrograms([folder])
    nck = build_nck(load_machine(), NcData(), programs, referenced=True)
    app = HmiApp(nck, realtime=False)
    app.freeze_gc_at_start = True  # as ``hmi`` (hmi.app.main) does
    first_frame: list[float] = []
    out: dict[str, float | str] = {}
    async with app.run_test(size=(160, 48)) as pilot:
        app.call_after_refresh(lambda: first_frame.append(time.time()))
        await pilot.pause()
        await pilot.pause()
        nck.submit(c.SetKeyswitch(1))
        nck.submit(c.SelectMode("AUTO"))
        nck.submit(c.SelectProgram(name))
        nck.submit(c.CycleStart())
        await pilot.pause()
        editor_screen = None
        if program is not None:
            editor_screen = await _open_in_editor(app, pilot, f"MPF/{name}")
        refresh_cpu, refresh_cpu_with_pilot = await _refresh_cpu(app, pilot, nck)
        latency, roundtrip = await _key_latencies(app, pilot)
        if editor_screen is not None:
            out["editor_check_wait_s"] = await _wait_for_check(editor_screen, pilot)
            out["editor_check_done"] = str(not getattr(editor_screen, "_check_running", False))
        out["program_state"] = str(app.bridge.status.channel.program_state)
    out["first_frame_s"] = first_frame[0] - spawn_epoch if first_frame else float("nan")
    out["refresh_cpu_ms_median"] = statistics.median(refresh_cpu) * 1000.0
    out["refresh_cpu_ms_p95"] = _percentile(refresh_cpu, 0.95) * 1000.0
    out["refresh_cpu_with_pilot_ms_median"] = statistics.median(refresh_cpu_with_pilot) * 1000.0
    out["key_latency_ms_median"] = statistics.median(latency) * 1000.0
    out["key_latency_ms_p95"] = _percentile(latency, 0.95) * 1000.0
    out["key_pilot_roundtrip_ms_median"] = statistics.median(roundtrip) * 1000.0
    out["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return out


@contextmanager
def recorded_frames(app: Any, clock: Callable[[], float] = time.perf_counter) -> Iterator[list[tuple[float, object]]]:
    """(time by ``clock``, screen) of every frame the compositor writes inside the block
    (``App._display`` wrapped, and given back at the end)."""
    frames: list[tuple[float, object]] = []
    display = app._display

    def recording_display(screen: object, renderable: object) -> None:
        display(screen, renderable)
        if renderable is not None and not app._batch_count:
            frames.append((clock(), screen))

    app._display = recording_display
    try:
        yield frames
    finally:
        app._display = display


def _send_key(app: Any, key: str) -> float:
    """Hand ``key`` to the app as its terminal driver does; the time it was sent (perf_counter)."""
    from textual import events

    event = events.Key(key, None)
    event.set_sender(app)
    sent = time.perf_counter()
    app._driver.send_message(event)
    return sent


async def _key_to_frame(app: Any, key: str, frames: list[tuple[float, object]], limit_s: float = 30.0) -> float:
    """Send an area key as the terminal driver does and wait for the first frame of the screen it
    opens; seconds from the key to that frame.

    Pilot's ``press`` cannot be used while a worker thread is busy: it waits until the whole
    process is idle, so it would wait for the editor's check to end.
    """
    before = app.screen
    frames.clear()
    sent = _send_key(app, key)
    while time.perf_counter() - sent < limit_s:
        await asyncio.sleep(0.002)
        target = app.screen
        if target is not before:
            painted = next((t for t, screen in frames if screen is target), None)
            if painted is not None:
                return painted - sent
    return float("inf")


async def measure_editor(program: Path, presses: int = 400) -> dict[str, float | str]:
    """Open ``program`` in the Program area's editor and measure its whole-file check.

    ``editor_check_s`` runs from the Program key that opens the file to the moment the
    editor's check worker hands over its last alarms (what the operator waits for before
    every fault of the file is marked); ``editor_open_s`` up to the first frame of the
    opened editor. From that frame on, Machine and Program are pressed in turn, and the
    key-to-repaint latencies of the keys answered while the check runs are reported.
    """
    from nck import build_nck
    from nck.machine import load_machine
    from nck.ncdata import NcData
    from nck.storage import NcFileSystem

    from hmi.app import HmiApp
    from hmi.program_files import ProgramFiles
    from screens.program_runs import CheckAndSimulation

    programs = NcFileSystem(Path(tempfile.mkdtemp()) / "nc")
    name = programs.import_file(program).path.rpartition("/")[2]
    app = HmiApp(build_nck(load_machine(), NcData(), programs, referenced=True), realtime=False)
    app.freeze_gc_at_start = True
    finished: list[float] = []
    apply_marks = CheckAndSimulation._apply_marks

    def recording_apply_marks(screen: Any, generation: int, marks: list[Any], done: bool) -> None:
        apply_marks(screen, generation, marks, done)
        if done and not screen._check_running:
            finished.append(time.perf_counter())

    CheckAndSimulation._apply_marks = recording_apply_marks  # type: ignore[method-assign,assignment]
    out: dict[str, float | str] = {}
    async with app.run_test(size=(160, 48)) as pilot:
        await pilot.pause()
        await pilot.pause()
        ProgramFiles.of_app(app).request_open(f"MPF/{name}")
        with recorded_frames(app) as frames:
            started = time.perf_counter()
            out["editor_open_s"] = await _key_to_frame(app, "alt+p", frames)
            latency: list[float] = []
            for k in range(presses):
                if finished:
                    break
                await asyncio.sleep(0.06)
                latency.append(await _key_to_frame(app, ("alt+m", "alt+p")[k % 2], frames))
            limit = time.perf_counter() + 600.0
            while not finished and time.perf_counter() < limit:
                await pilot.pause(0.1)
            out["editor_check_done"] = str(bool(finished))
            out["editor_check_s"] = (finished[0] if finished else time.perf_counter()) - started
    out["editor_keys_during_check"] = float(len(latency))
    if latency:
        out["editor_key_latency_ms_median"] = statistics.median(latency) * 1000.0
        out["editor_key_latency_ms_p95"] = _percentile(latency, 0.95) * 1000.0
    out["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return out


async def _key_to_redraw(app: Any, key: str, widget: Any, ready: Callable[[], bool],
                         frames: list[tuple[float, object]], limit_s: float = 120.0) -> float:
    """Send ``key`` as the terminal driver does; seconds until the first frame written after
    ``widget`` rendered with ``ready()`` true (the new picture: a scrub step's blank, a zoom)."""
    rendered: list[float] = []
    render = widget.render

    def recording_render() -> Any:
        text = render()
        if ready():
            rendered.append(time.perf_counter())
        return text

    widget.render = recording_render
    try:
        frames.clear()
        sent = _send_key(app, key)
        while time.perf_counter() - sent < limit_s:
            await asyncio.sleep(0.001)
            if rendered:
                painted = next((t for t, _ in frames if t >= rendered[0]), None)
                if painted is not None:
                    return painted - sent
        return float("inf")
    finally:
        del widget.render


async def _keys_while_recalculating(app: Any, screen: Any, frames: list[tuple[float, object]],
                                    limit_s: float = 1800.0) -> list[float]:
    """Recalculate (F7) the editor's simulation and, while it computes, press Machine and Program
    in turn (as :func:`measure_editor` does during its check); each key's seconds to its frame."""
    latency: list[float] = []
    _send_key(app, "f7")
    started = time.perf_counter()
    while screen._material is not None and time.perf_counter() - started < limit_s:
        await asyncio.sleep(0.002)  # the key is taken: the shown simulation is dropped
    k = 0
    while (screen._material is None or k % 2) and time.perf_counter() - started < limit_s:
        await asyncio.sleep(0.06)
        latency.append(await _key_to_frame(app, ("alt+m", "alt+p")[k % 2], frames))
        k += 1
    return latency


NEW_ZOOM_LEVELS = 8
"""Zoom + presses to levels the material view has not shown yet (``zoom_new_level``)."""


async def measure_simulation(program: Path, presses: int = 20) -> dict[str, float | str]:
    """Open ``program`` in the editor, simulate it (Simulation softkey) and measure what the
    operator waits for: the whole simulation (key to the cut blank shown), then the redraw after
    a scrub step (Block ◀ / Block ▶, the blank re-cut to that block in a worker thread) and
    after a zoom (Zoom + / Zoom -), key to frame, ``presses`` of each kind, a zoom to a level not
    shown before (``NEW_ZOOM_LEVELS`` of them) and a pan (arrow keys on the view, ``presses``);
    then the area keys' latency while the simulation is calculated again (Recalculate).

    The tool is the material benchmark's (T1 D1: ball end mill, 8 mm).
    """
    from nck import build_nck
    from nck.machine import load_machine
    from nck.ncdata import NcData, ToolEdge
    from nck.storage import NcFileSystem

    from hmi.app import HmiApp
    from hmi.program_files import ProgramFiles

    programs = NcFileSystem(Path(tempfile.mkdtemp()) / "nc")
    name = programs.import_file(program).path.rpartition("/")[2]
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 110.0, 3: 80.0, 6: 4.0})
    app = HmiApp(build_nck(load_machine(), data, programs, referenced=True), realtime=False)
    app.freeze_gc_at_start = True
    out: dict[str, float | str] = {}
    async with app.run_test(size=(160, 48)) as pilot:
        await pilot.pause()
        ProgramFiles.of_app(app).request_open(f"MPF/{name}")
        await pilot.press("alt+p")
        screen = app.screen
        out["editor_check_wait_s"] = await _wait_for_check(screen, pilot)
        with recorded_frames(app) as frames:
            stock = screen.stock
            out["simulation_s"] = await _key_to_redraw(app, "f5", stock, lambda: screen._material is not None,
                                                       frames, limit_s=1800.0)
            simulation = screen._material
            out["simulation_blocks"] = float(simulation.blocks if simulation is not None else 0)
            steps: list[float] = []
            zooms: list[float] = []
            for k in range(presses):
                shown = stock.picture
                steps.append(await _key_to_redraw(app, ("shift+f6", "shift+f7")[k % 2 if k else 0], stock,
                                                  lambda: stock.picture is not shown, frames))
                await pilot.pause()
            for k in range(presses):
                zoom = stock.zoom
                zooms.append(await _key_to_redraw(app, ("f4", "f5")[k % 2], stock,
                                                  lambda: stock.zoom != zoom, frames))
                await pilot.pause()
            # The zooms above go back and forth between two levels, whose overlay the view keeps;
            # levels not seen before and pans (a new viewport each) work the overlay out anew.
            new_levels: list[float] = []
            for k in range(NEW_ZOOM_LEVELS + 1):
                zoom = stock.zoom
                moment = await _key_to_redraw(app, "f4", stock, lambda: stock.zoom != zoom, frames)
                if k:  # the first goes to the level seen above
                    new_levels.append(moment)
                await pilot.pause()
            stock.action_fit()
            await pilot.pause()
            pans: list[float] = []
            for k in range(presses):
                port = stock.viewport(stock.size.width, 2 * (stock.size.height - 1))
                pans.append(await _key_to_redraw(app, ("right", "down")[k % 2], stock,
                                                 lambda: stock.viewport(stock.size.width,
                                                                        2 * (stock.size.height - 1)) != port, frames))
                await pilot.pause()
            # Material off: the toolpath alone, drawn for the first time from the whole path.
            material_off = await _key_to_redraw(app, "shift+f3", screen.toolpath,
                                                lambda: not screen.sim_material, frames)
            await pilot.pause()
            await pilot.press("shift+f3")
            await pilot.pause()
            keys = await _keys_while_recalculating(app, screen, frames)
    out["keys_during_simulation"] = float(len(keys))
    if keys:
        out["simulation_key_ms_median"] = statistics.median(keys) * 1000.0
        out["simulation_key_ms_p95"] = _percentile(keys, 0.95) * 1000.0
    out["material_off_ms"] = material_off * 1000.0
    out["scrub_first_ms"] = steps[0] * 1000.0  # the first step back from the end of the simulation
    for label, figures in (("scrub_step", steps), ("zoom", zooms), ("zoom_new_level", new_levels), ("pan", pans)):
        out[f"{label}_ms_median"] = statistics.median(figures) * 1000.0
        out[f"{label}_ms_p95"] = _percentile(figures, 0.95) * 1000.0
    out["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return out


async def first_frame_only(spawn_epoch: float) -> dict[str, float | str]:
    """Start the HMI (as :func:`measure` does) and return the time from spawn to its first frame."""
    from nck import build_nck
    from nck.machine import load_machine
    from nck.ncdata import NcData

    from hmi.app import HmiApp
    from hmi.programs import DirectoryPrograms

    folder = Path(tempfile.mkdtemp())
    (folder / "BENCH.MPF").write_text(SHORT_PROGRAM)
    app = HmiApp(build_nck(load_machine(), NcData(), DirectoryPrograms([folder]), referenced=True), realtime=False)
    first_frame: list[float] = []
    async with app.run_test(size=(160, 48)) as pilot:
        app.call_after_refresh(lambda: first_frame.append(time.time()))
        await pilot.pause()
    return {"first_frame_s": first_frame[0] - spawn_epoch if first_frame else float("nan")}


def first_frames(starts: int = 3) -> float:
    """Median spawn-to-first-frame of ``starts`` fresh processes with their bytecode cached.

    A throw-away start first compiles every module into a private cache
    (``PYTHONPYCACHEPREFIX``: nothing lands in the tree, and an environment with
    ``PYTHONDONTWRITEBYTECODE`` does not force a compile at every start); the
    measured starts then find it, as every start of ``hmi`` after the first does.
    """
    import os
    import subprocess

    figures: list[float] = []
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, PYTHONPYCACHEPREFIX=cache)
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        for _ in range(starts + 1):
            spawn = time.time()
            done = subprocess.run([sys.executable, "-m", "bench.hmi_probe", "--first-frame", f"{spawn:.6f}"],
                                  env=env, capture_output=True, text=True, check=False)
            try:
                figures.append(float(json.loads(done.stdout.strip().splitlines()[-1])["first_frame_s"]))
            except (ValueError, IndexError, KeyError):
                figures.append(float("nan"))
    return statistics.median(figures[1:])


def main(argv: list[str]) -> int:
    """Entry point: ``SPAWN_EPOCH [--program FILE]`` (``--first-frame SPAWN_EPOCH``: that figure only;
    ``--editor FILE``: the editor's whole-file check of FILE and the keys during it;
    ``--simulation FILE``: the editor's simulation of FILE, scrub steps and zooms)."""
    if argv and argv[0] == "--first-frame":
        print(json.dumps(asyncio.run(first_frame_only(float(argv[1])))))
        return 0
    if argv and argv[0] == "--editor":
        print(json.dumps(asyncio.run(measure_editor(Path(argv[1])))))
        return 0
    if argv and argv[0] == "--simulation":
        print(json.dumps(asyncio.run(measure_simulation(Path(argv[1])))))
        return 0
    spawn = float(argv[0]) if argv else time.time()
    program = Path(argv[argv.index("--program") + 1]) if "--program" in argv else None
    out = asyncio.run(measure(spawn, program))
    if program is None:
        out["first_frame_this_process_s"] = out["first_frame_s"]
        out["first_frame_s"] = first_frames()
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
