"""The benchmark suite of ``make bench``: figures, targets, peers, ratios → bench/results.md.

Every child process is measured on its own (wall time, CPU, peak RSS via
``wait4``). Peers run alternately with ours and the medians are compared, so
machine noise hits both sides alike. Throughput is blocks per wall second of the
whole command (start-up included, as a user experiences it).
"""

from __future__ import annotations

import datetime
import json
import os
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from bench.contour import contour_program
from bench.corpus import CorpusProgram, corpus, write_program
from bench.material import write_material_program
from bench.measure import ChildRun, alternate, environment_note, median, run_child
from bench.peers import ensure_ncgi, ensure_rs274, nck_check_command, nck_run_command
from bench.programs import CAM_BLOCKS, write_cam_program

RESULTS = Path(__file__).with_name("results.md")


@dataclass
class Row:
    """One line of the results table."""

    figure: str
    value: str
    target: str
    peer: str = ""
    ratio: str = ""
    met: str = ""


def _blocks_per_s(runs: list[ChildRun], blocks: int) -> float:
    return blocks / median([r.wall_s for r in runs])


def interpreter_rows(program: Path, repeats: int, notes: list[str]) -> list[Row]:
    """``nck check`` vs ``rs274 -g`` vs nc-gcode-interpreter on the same file, alternating."""
    commands = {"nck": nck_check_command() + [str(program)]}
    rs274, rs_note = ensure_rs274()
    ncgi, ncgi_note = ensure_ncgi()
    if rs274 is not None:
        commands["rs274"] = rs274 + [str(program), os.devnull]
    else:
        notes.append(rs_note)
    if ncgi is not None:
        commands["ncgi"] = ncgi + [str(program)]
    else:
        notes.append(ncgi_note)
    runs = alternate(commands, repeats)
    for name, name_runs in runs.items():
        bad = [r for r in name_runs if r.returncode != 0]
        if bad:
            notes.append(f"{name} exited {bad[0].returncode}: {bad[0].stderr.strip()[-300:]}")
    ours = _blocks_per_s(runs["nck"], CAM_BLOCKS)
    rows = [Row(f"nck check, {CAM_BLOCKS:,} G1 blocks", f"{ours:,.0f} blocks/s",
                "≥ 0.5× rs274, > nc-gcode-interpreter")]
    if "rs274" in runs:
        theirs = _blocks_per_s(runs["rs274"], CAM_BLOCKS)
        ratio = ours / theirs
        rows.append(Row("  vs LinuxCNC rs274 -g", f"{theirs:,.0f} blocks/s", "ratio ≥ 0.5",
                        rs_note, f"{ratio:.3f}×", "yes" if ratio >= 0.5 else "NO"))
    if "ncgi" in runs:
        theirs = _blocks_per_s(runs["ncgi"], CAM_BLOCKS)
        ratio = ours / theirs
        rows.append(Row("  vs nc-gcode-interpreter", f"{theirs:,.0f} blocks/s", "ratio > 1",
                        ncgi_note, f"{ratio:.3f}×", "yes" if ratio > 1.0 else "NO"))
    cpu = median([r.cpu_s for r in runs["nck"]])
    rows.append(Row("  nck check CPU time", f"{cpu:.2f} s", "", "", "", ""))
    return rows


def corpus_rows(folder: Path, scale: float, repeats: int, notes: list[str]) -> list[Row]:
    """Every corpus program: ``nck check`` vs ``rs274 -g`` (LinuxCNC spelling) vs
    nc-gcode-interpreter (SINUMERIK spelling), alternating; blocks/s of the whole command."""
    rs274, rs_note = ensure_rs274()
    ncgi, ncgi_note = ensure_ncgi()
    rows: list[Row] = []
    for program in corpus(scale):
        main, ngc, tools, table = write_program(folder / "corpus", program)
        data_dir = _tool_data_dir(folder, program.machine, tools, notes)
        commands = {"nck": nck_check_command() + [
            "--data-dir", str(data_dir), "--machine", program.machine, "--max-blocks", "50000000", str(main)]}
        if rs274 is not None:  # a private HOME: rs274 keeps its tool table in $HOME/.tool.mmap
            home = folder / "rs274-home"
            home.mkdir(exist_ok=True)
            commands["rs274"] = ["env", f"HOME={home}"] + rs274[:1] + ["-t", str(table)] + rs274[1:] + [
                str(ngc), os.devnull]
        if ncgi is not None:
            commands["ncgi"] = ncgi + [str(main)]
        runs = alternate(commands, repeats)
        rows += _corpus_program_rows(program, runs, rs_note if rs274 else "", ncgi_note, notes)
    if rs274 is None:
        notes.append(rs_note)
    if ncgi is None:
        notes.append(ncgi_note)
    return rows


def _tool_data_dir(folder: Path, machine: str, tools: Path, notes: list[str]) -> Path:
    """A data directory of ``machine`` with the corpus tools written once (``nck run`` of an
    empty program with ``--tools``), so the measured checks read tools as rs274 reads its table
    (the password's key derivation would cost every check ~0.5 s)."""
    data_dir = folder / f"data-{machine}"
    if not data_dir.exists():
        empty = folder / "EMPTY.MPF"
        empty.write_text("M30\n")
        done = run_child([sys.executable, "-m", "nck", "run", "--data-dir", str(data_dir), "--machine", machine,
                          "--password", "EVENING", "--tools", str(tools), str(empty)])
        if done.returncode != 0:
            notes.append(f"tool set-up for {machine} exited {done.returncode}: {done.stderr.strip()[-200:]}")
    return data_dir


def _corpus_program_rows(program: CorpusProgram, runs: dict[str, list[ChildRun]], rs_note: str,
                         ncgi_note: str, notes: list[str]) -> list[Row]:
    for name, name_runs in runs.items():
        bad = [r for r in name_runs if r.returncode != 0]
        if bad:
            notes.append(f"{program.name}: {name} exited {bad[0].returncode}: {bad[0].stderr.strip()[-200:]}")
    ours = _blocks_per_s(runs["nck"], program.blocks)
    floor = 1.0 if program.name == "CAM_MILL" else 0.5
    cpu = median([r.cpu_s for r in runs["nck"]])
    rows = [Row(f"nck check, corpus {program.name} ({program.blocks:,} blocks)", f"{ours:,.0f} blocks/s",
                f"≥ {floor}× rs274", "", f"CPU {cpu:.2f} s")]
    if "rs274" in runs and not any(r.returncode for r in runs["rs274"]):
        theirs = _blocks_per_s(runs["rs274"], program.blocks)
        ratio = ours / theirs
        rows.append(Row("  vs LinuxCNC rs274 -g", f"{theirs:,.0f} blocks/s", f"ratio ≥ {floor}", rs_note,
                        f"{ratio:.3f}×", "yes" if ratio >= floor else "NO"))
    if "ncgi" in runs and not any(r.returncode for r in runs["ncgi"]):
        theirs = _blocks_per_s(runs["ncgi"], program.blocks)
        ratio = ours / theirs
        rows.append(Row("  vs nc-gcode-interpreter", f"{theirs:,.0f} blocks/s", "ratio > 1", ncgi_note,
                        f"{ratio:.3f}×", "yes" if ratio > 1.0 else "NO"))
    return rows


def _machine_time(run: ChildRun) -> float:
    try:
        return float(json.loads(run.stdout)["machine_time_s"])
    except (ValueError, KeyError, TypeError):
        return float("nan")


def simulation_rows(folder: Path, program: Path, notes: list[str], big: bool) -> list[Row]:
    """``nck run`` of the 2,000-block G64 contour and of the long program: machine/wall, RSS."""
    data_dir = folder / "data"
    data_dir.mkdir(exist_ok=True)
    contour = folder / "CONTOUR.MPF"
    contour.write_text(contour_program(2000, 40.0))
    rows = []
    runs = [run_child(nck_run_command(data_dir) + [str(contour)]) for _ in range(3)]
    ratio = median([_machine_time(r) / r.wall_s for r in runs])
    rows.append(Row("nck run, 2,000-block G64 contour", f"{ratio:,.0f}× real time",
                    "≥ 300× (aim 1,000×)", "", "", "yes" if ratio >= 300 else "NO"))
    for run in runs[:1]:
        if run.returncode != 0:
            notes.append(f"nck run contour exited {run.returncode}: {run.stderr.strip()[-300:]}")
    if not big:
        notes.append(f"nck run on the {CAM_BLOCKS:,}-block program skipped (BENCH_QUICK)")
        return rows
    run = run_child(nck_run_command(data_dir) + [str(program)], timeout_s=1500.0)
    if run.returncode != 0:
        notes.append(f"nck run {CAM_BLOCKS:,} blocks exited {run.returncode}: {run.stderr.strip()[-300:]}")
    machine = _machine_time(run)
    rows.append(Row(f"nck run, {CAM_BLOCKS:,} G1 blocks", f"{machine / run.wall_s:,.0f}× real time",
                    "≥ 300×", "", f"{machine:,.0f} s machine / {run.wall_s:,.1f} s wall",
                    "yes" if machine / run.wall_s >= 300 else "NO"))
    rows.append(Row(f"peak RSS, nck run {CAM_BLOCKS:,} blocks", f"{run.peak_rss_mb:,.0f} MB",
                    "< 300 MB", "", "", "yes" if run.peak_rss_mb < 300 else "NO"))
    return rows


def material_rows(folder: Path, notes: list[str]) -> list[Row]:
    """Issue 24: the 200 × 150 mm plate at 0.2 mm cut by the 200,000-block CAM program
    (8 mm ball end mill): the AUTO run through the kernel, then the sweep through the Z-map."""
    program = write_material_program(folder)
    run = run_child([sys.executable, "-m", "bench.material", str(program)], timeout_s=3600.0)
    if run.returncode != 0:
        notes.append(f"material removal exited {run.returncode}: {run.stderr.strip()[-300:]}")
        return []
    figures = json.loads(run.stdout.strip().splitlines()[-1])
    return [
        Row("material removal, 200×150 plate at 0.2 mm, 200,000 blocks", f"{run.wall_s:,.1f} s",
            "< 10 s", "", f"run {figures['run_s']:,.1f} s + sweep {figures['sweep_s']:,.1f} s "
            f"(CPU {figures['run_cpu_s']:,.1f} + {figures['sweep_cpu_s']:,.1f} s), {figures['chords']:,} chords", "yes" if run.wall_s < 10.0 else "NO"),
        Row("  peak RSS, material removal", f"{run.peak_rss_mb:,.0f} MB", "< 500 MB", "", "",
            "yes" if run.peak_rss_mb < 500.0 else "NO"),
    ]


def _probe(name: str, arguments: list[str], notes: list[str], timeout_s: float) -> dict | None:
    """The figures ``bench.hmi_probe ARGUMENTS`` prints (its last line, JSON); None, with a note,
    when it printed none."""
    done = run_child([sys.executable, "-m", "bench.hmi_probe", *arguments], timeout_s=timeout_s)
    try:
        return json.loads(done.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        notes.append(f"HMI {name} probe failed (exit {done.returncode}): {done.stderr.strip()[-300:]}")
        return None


def simulation_view_rows(folder: Path, notes: list[str]) -> list[Row]:
    """Issue 24: the editor's simulation of the material benchmark's plate in the HMI, then the
    redraw after a scrub step (Block ◀ / ▶) and after a zoom, key to frame."""
    program = write_material_program(folder)
    figures = _probe("simulation", ["--simulation", str(program)], notes, timeout_s=3600.0)
    if figures is None:
        return []
    rows = [Row(f"HMI editor: Simulation of {program.stem} ({int(figures['simulation_blocks']):,} blocks), "
                "key to the cut blank", f"{figures['simulation_s']:,.1f} s", "", "", "", "")]
    for label, key in (("scrub step (Block ◀ / ▶)", "scrub_step"), ("zoom (Zoom + / -)", "zoom"),
                       ("zoom to a level not shown before", "zoom_new_level"), ("pan (arrow keys)", "pan")):
        if f"{key}_ms_p95" not in figures:
            continue
        p95 = float(figures[f"{key}_ms_p95"])
        first = f"first step {figures['scrub_first_ms']:.0f} ms" if key == "scrub_step" else ""
        rows.append(Row(f"  redraw after a {label}, key to frame",
                        f"median {figures[f'{key}_ms_median']:.0f} ms, p95 {p95:.0f} ms", "< 30 ms", "", first,
                        "yes" if p95 < 30.0 else "NO"))
    if "material_off_ms" in figures:
        rows.append(Row("  Material off (⇧F3): the whole toolpath drawn, key to frame",
                        f"{figures['material_off_ms']:,.0f} ms", "", "", "", ""))
    if "simulation_key_ms_p95" in figures:
        rows.append(Row("  area keys (Machine / Program) while it is calculated again, key to frame",
                        f"median {figures['simulation_key_ms_median']:.0f} ms, "
                        f"p95 {figures['simulation_key_ms_p95']:.0f} ms", "", "",
                        f"{int(figures['keys_during_simulation'])} keys", ""))
    return rows


def hmi_rows(program: Path | None, notes: list[str], editor_program: Path | None = None) -> list[Row]:
    """HMI start-to-first-frame, refresh CPU, area-switch key latency, RSS with the long program,
    and the editor's whole-file check of ``editor_program`` with the key latency during it."""
    rows: list[Row] = []
    probe = run_child([sys.executable, "-m", "bench.hmi_probe", f"{time.time():.6f}"])
    try:
        hmi = json.loads(probe.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        notes.append(f"HMI probe failed: {probe.stderr.strip()[-400:]}")
        return rows
    rows.append(Row("HMI start to first frame", f"{hmi['first_frame_s'] * 1000:,.0f} ms", "< 1,000 ms",
                    "", "", "yes" if hmi["first_frame_s"] < 1.0 else "NO"))
    rows.append(Row("HMI CPU per refresh (program running)",
                    f"median {hmi['refresh_cpu_ms_median']:.1f} ms, p95 {hmi['refresh_cpu_ms_p95']:.1f} ms",
                    "< 15 ms", "", "", "yes" if hmi["refresh_cpu_ms_median"] < 15 else "NO"))
    rows.append(Row("HMI area switch key to repaint (program running)",
                    f"median {hmi['key_latency_ms_median']:.0f} ms, p95 {hmi['key_latency_ms_p95']:.0f} ms",
                    "p95 < 50 ms", "", "", "yes" if hmi["key_latency_ms_p95"] < 50 else "NO"))
    if program is not None:
        big = run_child([sys.executable, "-m", "bench.hmi_probe", f"{time.time():.6f}",
                         "--program", str(program)], timeout_s=900.0)
        if big.returncode == 0:
            rows.append(Row(f"peak RSS, HMI with {CAM_BLOCKS:,}-block program selected in AUTO",
                            f"{big.peak_rss_mb:,.0f} MB", "< 300 MB", "", "",
                            "yes" if big.peak_rss_mb < 300 else "NO"))
        else:
            notes.append(f"HMI with the long program: exit {big.returncode}: {big.stderr.strip()[-300:]}")
    if editor_program is not None and editor_program.exists():
        rows += _editor_rows(editor_program, notes)
    return rows


def _editor_rows(program: Path, notes: list[str]) -> list[Row]:
    """The Program area's editor opening ``program``: its whole-file check, keys during it."""
    lines = program.read_text().count("\n")
    editor = _probe("editor", ["--editor", str(program)], notes, timeout_s=900.0)
    if editor is None:
        return []
    check_s = float(editor["editor_check_s"])
    finished = editor["editor_check_done"] == "True"
    rows = [Row(f"HMI editor: open and check {program.stem} ({lines:,} lines), whole file",
                f"{check_s:,.1f} s{'' if finished else ' (not finished)'}, editor shown after "
                f"{editor['editor_open_s']:.2f} s", "< 3 s", "", "",
                "yes" if finished and check_s < 3.0 else "NO")]
    keys = int(editor["editor_keys_during_check"])
    if keys:
        p95 = float(editor["editor_key_latency_ms_p95"])
        rows.append(Row("HMI area switch key to repaint during that check",
                        f"median {editor['editor_key_latency_ms_median']:.0f} ms, p95 {p95:.0f} ms ({keys} keys)",
                        "p95 < 50 ms", "", "", "yes" if p95 < 50 else "NO"))
    else:
        notes.append("HMI editor: the check ended before a key could be sent")
    return rows


def format_table(rows: list[Row]) -> str:
    """A Markdown table of the rows."""
    head = "| figure | value | target | peer | ratio / detail | met |\n|---|---|---|---|---|---|\n"
    return head + "".join(f"| {r.figure} | {r.value} | {r.target} | {r.peer} | {r.ratio} | {r.met} |\n"
                          for r in rows)


def run_suite() -> str:
    """Run everything, print the table and write bench/results.md; return the Markdown."""
    quick = bool(os.environ.get("BENCH_QUICK"))
    repeats = int(os.environ.get("BENCH_REPEATS", "1" if quick else "3"))
    notes: list[str] = []
    rows: list[Row] = []
    started = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        program = write_cam_program(folder)
        rows += interpreter_rows(program, repeats, notes)
        print(format_table(rows), flush=True)
        rows += corpus_rows(folder, 0.1 if quick else 1.0, repeats, notes)
        print(format_table(rows), flush=True)
        rows += simulation_rows(folder, program, notes, big=not quick)
        rows += hmi_rows(None if quick else program, notes, folder / "corpus" / "CAM_MILL.MPF")
        if not quick:
            rows += material_rows(folder, notes)
            rows += simulation_view_rows(folder, notes)
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    text = (f"# Benchmark results\n\n{stamp} on {environment_note()}, load average "
            f"{' '.join(f'{v:.2f}' for v in os.getloadavg())} at the end; "
            f"{repeats} alternating run(s) per interpreter, medians; suite took "
            f"{time.perf_counter() - started:,.0f} s.\n\n" + format_table(rows))
    if notes:
        text += "\nNotes:\n\n" + "".join(f"- {n}\n" for n in notes)
    return text
