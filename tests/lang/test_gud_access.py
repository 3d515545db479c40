"""GUD access attributes APRP/APWP (APR/APW) enforced on part-program reads and writes
(issue 20; 004 L415-433: protection level 0 … 7, 0 = most rights)."""

from __future__ import annotations

from nck.errors import NcAlarmError
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

DEFINE = "DEF NCK APRP 7 APWP 3 REAL LIMIT=5\nDEF NCK APR 2 INT SECRET=9\nM30\n"


def _run(text: str, data: NcData, level: int) -> list[int]:
    """Alarm numbers of running ``text`` at protection ``level`` (stops at the first)."""
    interp = Interpreter(load_machine(None), MemorySource({}), data)
    interp.access_level = lambda: level
    interp.start_text("TEST.MPF", text)
    try:
        while not interp.finished:
            interp.step()
    except NcAlarmError as alarm:
        return [alarm.number]
    return []


def _defined() -> NcData:
    data = NcData()
    assert _run(DEFINE, data, 7) == []
    return data


def test_apwp_refuses_a_write_from_a_program_running_with_fewer_rights() -> None:
    """Digest job-planning-variables rank 3."""
    # 004 L429: APWP <level> protects writing from a part program; level 7 (keyswitch 0) > 3.
    data = _defined()
    assert _run("LIMIT=6\nM30\n", data, 7) == [17070]
    assert data.gud["LIMIT"] == 5
    # level 3 (password CUSTOMER) and below may write
    assert _run("LIMIT=6\nM30\n", data, 3) == []
    assert data.gud["LIMIT"] == 6


def test_aprp_allows_reading_at_its_level() -> None:
    """Digest job-planning-variables rank 3 (APRP)."""
    # 004 L428: APRP 7 = everyone may read LIMIT from a part program.
    data = _defined()
    assert _run("R1=LIMIT\nM30\n", data, 7) == []
    assert data.r[1] == 5


def test_apr_protects_reading_and_apw_default_is_free() -> None:
    # 004 L428-433: APR <level> = read protection for part program and OPI.
    data = _defined()
    assert _run("R1=SECRET\nM30\n", data, 7) == [17070]
    assert _run("R1=SECRET\nM30\n", data, 2) == []
    assert data.r[1] == 9
    assert _run("SECRET=1\nM30\n", data, 7) == []  # no write protection given


def test_a_level_outside_0_to_7_is_refused() -> None:
    """Digest job-planning-variables rank 3 (levels 0-7)."""
    # 004 L432: range of values 0 … 7.
    assert _run("DEF NCK APWP 9 REAL X1\nM30\n", NcData(), 7) == [12560]


def test_the_protection_survives_a_restart() -> None:
    # The levels are retained with the GUD values (section "user_data" of the retained data).
    from nck.persistence import RetainedData, parse_section, section_text

    data = _defined()
    assert data.gud_access == {"LIMIT": {"read": 7, "write": 3}, "SECRET": {"read": 2}}
    restored = RetainedData()
    parse_section("user_data", section_text("user_data", RetainedData(ncdata=data)).encode(), restored)
    assert restored.ncdata.gud_access == data.gud_access
    assert _run("LIMIT=6\nM30\n", restored.ncdata, 7) == [17070]
