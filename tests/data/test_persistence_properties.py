"""Property: whatever retained data hold, a save and a restart give them back unchanged."""

from __future__ import annotations

import tempfile
from pathlib import Path

from hypothesis import given, settings, strategies as st

from nck.ncdata import ToolEdge, WorkOffset
from nck.persistence import Session

finite = st.floats(min_value=-1e9, max_value=1e9, allow_nan=False, allow_infinity=False)
axes = st.sampled_from(["X", "Y", "Z"])
offsets = st.builds(
    WorkOffset,
    trans=st.dictionaries(axes, finite, max_size=3),
    rot=st.dictionaries(axes, finite, max_size=3),
    mirror=st.dictionaries(axes, st.booleans(), max_size=3),
)
tools = st.dictionaries(
    st.tuples(st.integers(1, 32000), st.integers(1, 9)),
    st.builds(ToolEdge, params=st.dictionaries(st.integers(1, 25), finite, max_size=6)),
    max_size=5,
)
plain = st.recursive(
    st.none() | st.booleans() | st.integers(-2**31, 2**31 - 1) | finite | st.text(max_size=10),
    lambda inner: st.lists(inner, max_size=3),
    max_leaves=6,
)


@settings(max_examples=12, deadline=None)
@given(
    tools=tools,
    g54=offsets,
    r=st.dictionaries(st.integers(0, 99), finite, max_size=10),
    gud=st.dictionaries(st.from_regex(r"[A-Z_][A-Z0-9_]{0,10}", fullmatch=True), plain, max_size=4),
    mda=st.text(max_size=40),
    counters=st.dictionaries(st.sampled_from(["TOTAL_PARTS", "ACTUAL_PARTS"]),
                             st.integers(0, 999_999_999)),
)
def test_round_trip(tools, g54, r, gud, mda, counters) -> None:
    with tempfile.TemporaryDirectory() as tmp:  # no fsync here: tests/conftest.py
        session = Session.open(Path(tmp), install_samples=False)
        data = session.ncdata
        data.tools = dict(tools)
        data.settable_frames["G54"] = g54
        for index, value in r.items():
            data.r[index] = value
        data.gud = dict(gud)
        data.mda_program = mda
        data.part_counters = dict(counters)
        session.save()
        again = Session.open(Path(tmp), install_samples=False).ncdata
        assert again.tools == data.tools
        assert again.settable_frames == data.settable_frames
        assert again.r == data.r
        assert again.gud == data.gud
        assert again.mda_program == mda
        assert again.part_counters == data.part_counters
