"""Run part programs under a fixed address-space budget and report how each one ended.

``python -m tests.reliability.memory_probe BUDGET_MB`` reads a JSON list of program texts on
stdin, limits the process with ``RLIMIT_AS`` before it imports the kernel, then runs every
program three times — through the editor's background check (:func:`nck.check.check_text`, stopped
after 20,000 blocks as the editor stops it when the text changes), through ``nck check``'s
:func:`nck.headless.check_outcome` (20,000 blocks) and headless through the kernel
(:func:`nck.headless.run_program`, 1 s of simulated time, every command handed on as
``nck run --segments`` takes them) — and prints one
JSON line per program: the alarm numbers and the run's status, or ``error`` with the exception
(a MemoryError or any other exception is a failure of the test that started the probe).
"""

from __future__ import annotations

import itertools
import json
import resource
import sys
import traceback


CHECK_BLOCKS = 20_000


def main() -> int:
    budget = int(sys.argv[1]) * 2**20
    resource.setrlimit(resource.RLIMIT_AS, (budget, budget))
    from nck.check import check_text
    from nck.headless import check_outcome, run_program
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData

    machine = load_machine()
    for index, text in enumerate(json.load(sys.stdin)):
        try:
            polls = itertools.count()
            checked = [a.number for a in check_text("FUZZ.MPF", text,
                                                    should_stop=lambda: next(polls) > CHECK_BLOCKS)]
            cli_check = check_outcome(machine, MemorySource({}), "FUZZ.MPF", text, max_blocks=CHECK_BLOCKS)
            run = run_program(machine, MemorySource({}), NcData(), "FUZZ.MPF", text=text, timeout_s=1.0,
                              keep_commands=False, on_command=lambda _command: None)
            line = {"index": index, "check": checked, "cli_check": [a.number for a in cli_check.alarms],
                    "status": run.status,
                    "alarms": [a.number for a in run.alarms]}
        except BaseException as exc:  # noqa: BLE001 - reported to the test, which fails on it
            line = {"index": index, "error": f"{type(exc).__name__}: {exc}"[:300],
                    "trace": traceback.format_exc()[-2000:]}
        print(json.dumps(line), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
