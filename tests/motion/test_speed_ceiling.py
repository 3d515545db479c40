"""The look-ahead's velocity ceiling kept as segments come and go equals the ceiling counted
over the buffer from scratch.

The contact watch asks for the ceiling at every IPO cycle while the tool is near a solid (a
lathe's tool in the bar: every cycle). It is counted again only when a segment left the buffer
since the last count; a segment appended raised it as it came, and whatever changes a limit
(an override, a new feed) replans the buffer, which counts again.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.machine import load_machine
from nck.motion.params import motion_params
from nck.motion.path import line
from nck.motion.planner import DwellItem, LookAhead, PlannedSegment, plan_segment

PARAMS = motion_params(load_machine("mill3"))
MASK = [True, True, True]

step = st.one_of(
    st.tuples(st.just("append"), st.floats(0.5, 200.0), st.one_of(st.none(), st.floats(1.0, 300.0))),
    st.tuples(st.just("dwell"), st.just(0.0), st.none()),
    st.tuples(st.just("pop"), st.just(0.0), st.none()),
    st.tuples(st.just("override"), st.floats(0.0, 120.0), st.floats(0.0, 100.0)),
    st.tuples(st.just("ask"), st.just(0.0), st.none()),
)


def counted(la: LookAhead) -> float:
    """The reference: the highest limit of the segments buffered now, counted from scratch."""
    return max((la.v_max(item) for item in la.items if isinstance(item, PlannedSegment)), default=0.0)


@settings(max_examples=300)
@given(st.lists(step, max_size=60))
def test_the_kept_ceiling_is_the_counted_one(steps) -> None:
    la = LookAhead(PARAMS)
    x = 0.0
    for kind, a, b in steps:
        if kind == "append":
            start, x = np.array([x, 0.0, 0.0]), x + a
            la.append(plan_segment(PARAMS, line(start, np.array([x, 0.0, 0.0]), MASK), rapid=b is None,
                                   feed_mm_s=b, soft=False, exact_stop=False, window="G601", source=None))
        elif kind == "dwell":
            la.append(DwellItem(1.0, None))
        elif kind == "pop" and la.items:
            la.pop_front()
        elif kind == "override":
            la.feed_pct, la.rapid_pct = a, b
            la.replan_all()
        elif kind == "ask":
            assert la.current_ceiling() == counted(la)
    assert la.current_ceiling() == counted(la)
