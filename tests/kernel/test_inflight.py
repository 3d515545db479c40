"""nck.inflight.InFlight keeps the pushed items' blocks as a queue of (file, line).

Expected values come from a plain model: a list of (file, line) tuples, the oldest dropped up to
the first entry of the executing block (what ProgramRun did with a deque of tuples before).
"""

from __future__ import annotations

import random

from nck.canon import Source
from nck.inflight import InFlight


def test_find_and_drop_follow_a_list_of_file_line_pairs() -> None:
    rng = random.Random(7)
    files = ["MAIN.MPF", "SUB.SPF", "/N_L_CYC_SPF"]
    queue, model = InFlight(), []
    for _ in range(20_000):
        source = Source(rng.choice(files), rng.randint(0, 40), None)
        action = rng.random()
        if action < 0.6:
            queue.append(source)
            model.append((source.file, source.line))
        elif action < 0.98:
            key = (source.file, source.line)
            expected = model.index(key) if key in model else None
            assert queue.find(source) == expected
            if expected is not None:
                queue.drop(expected)
                del model[:expected]
        else:
            queue.clear()
            model.clear()
        assert len(queue) == len(model)


def test_drop_beyond_the_end_empties_and_lines_of_other_files_do_not_match() -> None:
    queue = InFlight()
    for line in (5, 6, 5):
        queue.append(Source("MAIN.MPF", line))
    assert queue.find(Source("SUB.SPF", 5)) is None
    assert queue.find(Source("MAIN.MPF", 6)) == 1
    queue.drop(1)
    assert queue.find(Source("MAIN.MPF", 5)) == 1  # the later run of line 5
    queue.drop(10)
    assert len(queue) == 0 and queue.find(Source("MAIN.MPF", 5)) is None
