"""Golden programs: the values the manuals determine, worked out by hand.

``test_golden.py`` compares each run with its recorded trace; that shows only that nothing
changed. This module asserts, for every golden program, the end points, R values, alarms,
dwell times and states that follow from the manuals (line cited) or, for language features
the shared manuals do not describe, from the language rule named in the comment — never values
copied from a recorded trace.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from nck import canon
from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.golden.trace import case_data

HERE = Path(__file__).parent


class Case:
    """One golden program run through the interpreter, as ``trace.run_case`` runs it."""

    def __init__(self, name: str) -> None:
        folder = HERE / name
        options = {}
        if (folder / "options.toml").is_file():
            options = tomllib.loads((folder / "options.toml").read_text())
        programs = {p.name: p.read_text() for p in folder.iterdir() if p.suffix.lower() in (".spf", ".mpf")}
        self.data = case_data(folder, options)
        self.result: HeadlessRun = interpret_only(
            load_machine(options.get("machine")), MemorySource(programs), self.data, "main.mpf",
            text=programs["main.mpf"], max_blocks=100_000,
            skip_levels=frozenset(options.get("skip_levels", [])))

    def r(self, *numbers: int) -> tuple[float, ...]:
        return tuple(self.data.r[n] for n in numbers)

    @property
    def position(self) -> dict[str, float]:
        return {a: round(v, 6) for a, v in self.result.interpreter.modal.position_wcs.items()}

    def ends(self, file: str = "main.mpf") -> list[tuple[int | None, dict[str, float]]]:
        """(N, WCS end rounded to 1 µm) of every motion of ``file``."""
        return [(m.source.n, {a: round(v, 3) for a, v in m.end_wcs.items()})
                for m in self.result.segments if m.source.file.lower() == file.lower()]

    def ended(self) -> "Case":
        assert self.result.status == "ended", self.result.alarms
        return self


def xyz(x: float, y: float, z: float) -> dict[str, float]:
    return {"X": x, "Y": y, "Z": z}


def assert_spindle_deleted_at_end(case: Case) -> None:
    """MD35040 = 0 (the machines' default): at the program end (M2, M30) the spindle brakes and
    the last programmed S and direction are deleted (002 L51020, L51032-51035)."""
    modal = case.result.interpreter.modal
    assert (modal.spindle_state, modal.spindle_speed_rpm) == ("M5", 0.0)


def test_01_g0_g1_absolute() -> None:
    """G90 end points are the programmed values (001 L1666-1672); F150 is modal for N40."""
    case = Case("01_g0_g1_absolute").ended()
    assert case.ends() == [(10, xyz(0, 0, 50)), (20, xyz(20, 10, 50)), (30, xyz(20, 10, -5)),
                           (40, xyz(60, 30, -5)), (50, xyz(60, 30, 50))]
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind == "G1"]
    assert feeds == [150.0, 150.0]


def test_02_g90_g91_same_point() -> None:
    """From (20, 10) ``G90 X60 Y30`` and ``G91 X40 Y20`` reach (60, 30) (001 L1666-1688)."""
    case = Case("02_g90_g91_same_point").ended()
    ends = dict(case.ends())
    assert ends[20] == ends[40] == xyz(60, 30, 0)


def test_03_ac_ic_words() -> None:
    """AC()/IC() override G90/G91 for one word: X=AC(50) under G91 is 50 and Y5 adds to 15;
    X=IC(-20) under G90 is 50 - 20 = 30, Y=IC(-2) 13; Y=AC(7) is 7 (840D dimension words)."""
    case = Case("03_ac_ic_words").ended()
    assert [e for _n, e in case.ends()] == [xyz(10, 10, 10), xyz(50, 15, 10), xyz(30, 13, 0),
                                            xyz(30, 7, 0)]


def test_04_r_address_arithmetic() -> None:
    """R1 = 9.7, R2 = -2.1: X = 20.3 + 9.7 = 30, Y = 32.9 + 2.1 = 35, Z = 19.7 - 9.7 = 10
    (840C address arithmetic, digest programming-840c §7, 001 Ch.12)."""
    case = Case("04_r_address_arithmetic").ended()
    assert case.position == pytest.approx(xyz(30, 35, 10))


def test_05_operator_priority() -> None:
    """840D priorities (* / before + -, comparisons last): 2 + 3·4 = 14, (2+3)·4 = 20,
    17 DIV 5 = 3, 17 MOD 5 = 2, -2·3 + 1 = -5, (2+3 == 5) = 1, 1|6 = 7, 12&10 = 8, 5^3 = 6,
    7/2 = 3.5, NOT(2>3) = 1, 1 AND 1 = 1, 0 OR 0 = 0, 1 XOR 1 = 0."""
    case = Case("05_operator_priority").ended()
    assert case.r(*range(1, 18)) == (14, 2, 3, 4, 20, 3, 2, -5, 1, 7, 8, 6, 3.5, 1, 1, 0, 0)


def test_06_functions_degrees() -> None:
    """Angles in degrees (004 L307: R7=SIN(25.3)); each value by ``math``: SIN30 = 0.5,
    COS60 = 0.5, TAN45 = 1, ATAN2(1,1) = 45, ASIN(0.5) = 30, ACOS(0) = 90, SQRT16 + 3² = 13,
    TRUNC 2.9 + ROUND 2.5 + ROUND -2.5 = 2 + 3 - 3 = 2, LN(EXP 2) = 2, -3 + 4 = 1,
    BOUND(0,10,12) = 10, ROUNDUP 2.1 = 3."""
    case = Case("06_functions_degrees").ended()
    expected = (0.5, 0.5, 1.0, 45.0, 30.0, 90.0, math.sin(math.radians(25.3)), 13.0, 2.5, 2.0,
                2.0, 1.0, 10.0, 3.0)
    assert case.r(*range(1, 15)) == pytest.approx(expected, abs=1e-9)


def test_07_r_indirect() -> None:
    """R10 and R[10] are one element (004 L253-256); R[R2] with R2 = 5 writes R5;
    R[(1+1)·2] writes R4 (004 L310-311)."""
    case = Case("07_r_indirect").ended()
    assert case.r(10, 11, 5, 4, 1, 2, 3) == (7, 7, 1, 5, 1, 1, 2)


def test_08_number_literals() -> None:
    """1.874EX8, -0.1EX-5, 8.2EX-3 (004 L281, L305-306); 'H1F' = 31 and 'B1011' = 11
    (hexadecimal/binary constants); .5 and -0.25."""
    case = Case("08_number_literals").ended()
    assert case.r(1, 2, 3, 4, 5, 6, 7) == pytest.approx((1.874e8, -1e-6, 0.0082, 31, 11, 0.5, -0.25))


def test_09_def_types() -> None:
    """DEF of every type (004 L412-445): REAL -> INT rounds 2.5 to 3 and -2.5 to -3; any
    non-zero value is TRUE; CHAR "A" is 65; "AB" << "C" << 3 has 4 characters; the AXIS
    variable moves X to 5."""
    case = Case("09_def_types").ended()
    assert case.r(1, 2, 3, 4, 5, 6, 7, 8) == (3, -3, 1.5, 1, 65, 4, 0, 1)
    assert case.position["X"] == pytest.approx(5.0)


def test_10_def_arrays() -> None:
    """Arrays with initial values (missing ones 0), REP and SET: 1+2+3+0 = 6, 12+1 = 13,
    3·7 = 21, LST[2] = 6."""
    assert Case("10_def_arrays").ended().r(1, 2, 3, 4) == (6, 13, 21, 6)


def test_11_def_limits() -> None:
    """LLI/ULI (004 L449-452): the implicit value 0 is moved inside the limits, to 5 and -5;
    10 is inside [0, 10]."""
    assert Case("11_def_limits").ended().r(1, 2, 3) == (5, -5, 10)


def test_12_if_else_nested() -> None:
    """R1 = 3: outer IF and inner IF taken, R2 = 1, R3 = 10; IF R1 < 0 not taken."""
    case = Case("12_if_else_nested").ended()
    assert case.r(2, 3, 4) == (1, 10, 0)
    assert (case.position["X"], case.position["Y"]) == (1.0, 10.0)


def test_13_while_loop() -> None:
    """WHILE (002 L24290-24299): four passes of G91 X2 from X0 end at X8, R1 = 4."""
    case = Case("13_while_loop").ended()
    assert case.r(1) == (4,)
    assert [e["X"] for _n, e in case.ends()][-4:] == [2, 4, 6, 8]


def test_14_for_loop() -> None:
    """FOR (002 L15592-15596): 1+…+10 = 55; 3·2 = 6 inner passes; a start beyond the end runs
    the body not at all."""
    assert Case("14_for_loop").ended().r(1, 2, 3) == (55, 6, 0)


def test_15_loop_and_repeat() -> None:
    """LOOP left by GOTOF when R1 reaches 5 (002 L16125-16151); REPEAT … UNTIL runs until R3
    is 6 (three passes) and at least once even with UNTIL TRUE."""
    assert Case("15_loop_and_repeat").ended().r(1, 2, 3, 4) == (5, 1, 6, 1)


def test_16_goto_targets() -> None:
    """GOTOF/GOTOB to labels and block numbers (002 L1259): R1, R2, R4 skipped; BACK runs three
    times; GOTOC to a missing target continues without alarm, so R7 = 1."""
    assert Case("16_goto_targets").ended().r(1, 2, 3, 4, 5, 6, 7) == (0, 0, 1, 0, 3, 1, 1)


def test_17_goto_string_target() -> None:
    """A jump destination in a STRING variable: to the label, then to block N60."""
    assert Case("17_goto_string_target").ended().r(1, 2, 3, 4) == (0, 1, 0, 1)


def test_18_subprogram_passes_modal() -> None:
    """840C %4011 adapted (001 L8274ff): L230 moves X -11 and back; L240 P2 raises Z by 5 twice
    (60 -> 70) and returns X each pass; modal G91 (member 2 of group 14) and G0 stay after M17."""
    case = Case("18_subprogram_passes_modal").ended()
    assert (case.position["X"], case.position["Z"]) == (52.0, 70.0)
    assert case.r(1, 2) == (2, 1)
    assert_spindle_deleted_at_end(case)


def test_19_proc_value_and_reference() -> None:
    """Parameters by value are copies, VAR by reference (002 L15528): TOTAL = 1 + 5 = 6,
    R2 = 0 + R1 = 10 with R1 unchanged, ARR[2] = 42."""
    assert Case("19_proc_value_and_reference").ended().r(1, 2, 3, 4) == (10, 10, 6, 42)


def test_20_local_variables_and_nesting() -> None:
    """LUD per level (004 L390-395): main CNT = 100, LEVEL1 CNT = 1, LEVEL2 CNT = 1 + 1 = 2;
    $P_STACK counts the main program as level 1 (000 Table 2-6, L2687-2696): LEVEL1 2, LEVEL2 3."""
    assert Case("20_local_variables_and_nesting").ended().r(1, 2, 3, 4, 5) == (100, 1, 2, 3, 2)


def test_21_skip_levels() -> None:
    """Levels 0 ("/" and "/0") and 1 active, 2 not (digest 828d-2 rank 17): N20, N30, N50 and
    N70 are skipped, N40 runs; X ends at 10 from N60."""
    case = Case("21_skip_levels").ended()
    assert case.r(1, 2, 3, 4, 5) == (1, 0, 0, 1, 0)
    assert case.position["X"] == 10.0


def test_22_messages_and_stops() -> None:
    """MSG shows and clears texts; M0 and M1 are stops; STOPRE (002 L1255) stops preprocessing."""
    case = Case("22_messages_and_stops").ended()
    texts = [c.text for c in case.result.commands if isinstance(c, canon.Message)]
    assert texts == ["Start roughing", "Value 2.5 mm", ""]
    stops = [c.kind for c in case.result.commands if isinstance(c, canon.StopPoint)]
    assert stops[:2] == ["M0", "M1"]


def test_23_setal_user_alarm() -> None:
    """SETAL(61000) raises the cycle alarm and stops the run (002 L8894): X1 reached, X2 not."""
    case = Case("23_setal_user_alarm")
    assert case.result.status == "alarm"
    assert case.position["X"] == 1.0
    assert any(isinstance(c, canon.UserAlarm) and c.number == 61000 for c in case.result.commands)


def test_24_tool_spindle_aux() -> None:
    """T3 then M6 changes to T3 (MD22550 = 1 on the mill), D2; S1200 M3; M8 and H5 go out;
    spindle 2 stopped with M2=5 and set to 300; T7 M6; M5 stops spindle 1."""
    case = Case("24_tool_spindle_aux").ended()
    modal = case.result.interpreter.modal
    assert (modal.tool, modal.spindle_state) == (7, "M5")
    assert modal.edge == 1  # T7 M6 without D: the default edge D1 of MD20270 (002 L58120-58126)
    assert_spindle_deleted_at_end(case)  # S1200 is gone after M30, not only the direction
    # Each M6 selects edge 1 of the new tool (MD20270 = 1, 002 L57659-57666); D2 in between.
    edges = [c.edge for c in case.result.commands if isinstance(c, canon.EdgeSelect)]
    assert edges == [1, 2, 1]
    aux = [(c.address, c.value) for c in case.result.commands if isinstance(c, canon.AuxFunction)]
    assert ("M", 8.0) in aux and ("H", 5.0) in aux and ("M", 9.0) in aux


def test_24_without_its_tool_data_stops_at_the_m6() -> None:
    """Without the data set of T3 the mill (MD22550 = 1) stops at the tool change M06 of N20
    with 17191 (002 L58171-58190, L58219)."""
    programs = {"main.mpf": (HERE / "24_tool_spindle_aux" / "main.mpf").read_text()}
    result = interpret_only(load_machine(None), MemorySource(programs), NcData(), "main.mpf",
                            text=programs["main.mpf"], max_blocks=1000)
    assert [(a.number, a.line) for a in result.alarms] == [(17191, 3)]


def test_25_tool_data_variables() -> None:
    """$TC_DP writes create edge T1 D1 (002 L58637): 75.5 + 4 = 79.5; a missing edge reads 0."""
    case = Case("25_tool_data_variables").ended()
    assert case.r(1, 2) == (79.5, 0)
    assert case.data.tools[(1, 1)].params[3] == 75.5


def test_26_system_variables() -> None:
    """$MC_MM_NUM_R_PARAM is MD28050 of the machine; $AA_IM (002 L10814) after X12 Y-3 is
    12 - 3 = 9; $P_EP[Z] = 4; G91 is member 2 of group 14; $P_F = 250; $P_STACK of the main
    program is 1 (000 Table 2-6, L2687-2696)."""
    case = Case("26_system_variables").ended()
    md28050 = load_machine(None).md.get("MD28050", 100)
    assert case.r(1, 2, 3, 4, 5, 6, 7) == (md28050, 9, 4, 2, 250, 0, 1)


def test_27_program_end_resets_modal() -> None:
    """M2 ends the program and the G groups return to their reset members (MD20150, digest
    828d-2 §7), F is deleted."""
    case = Case("27_program_end_resets_modal").ended()
    modal = case.result.interpreter.modal
    assert (modal.gcodes[14], modal.gcodes[15], modal.gcodes[6]) == ("G90", "G94", "G17")
    assert modal.feed == 0.0
    assert_spindle_deleted_at_end(case)  # M2 as M30 (002 L51020)


def test_28_main_blocks_and_comments() -> None:
    """Main blocks ``:10``, comments after ``;`` (also in a MSG string) and lower case words."""
    case = Case("28_main_blocks_and_comments").ended()
    assert [e for _n, e in case.ends()] == [xyz(10, -15, 0), xyz(10, 20, 0), xyz(5, 20, 0),
                                            xyz(5, 20, 5), xyz(0, 0, 5)]


def test_29_end_of_file_without_m30() -> None:
    """The program ends at the end of the file without alarm."""
    case = Case("29_end_of_file_without_m30").ended()
    assert case.position == xyz(1, 2, 3) and case.r(1) == (1,)


def test_30_rectangle_subprogram() -> None:
    """RECT(40, 25, -1) P2: two passes, each 1 mm deeper (Z 2 -> 1 -> 0), each outline back at
    X0 Y0; then Z50."""
    case = Case("30_rectangle_subprogram").ended()
    outline = [e for _n, e in case.ends("RECT.SPF")]
    assert outline[:5] == [xyz(0, 0, 1), xyz(40, 0, 1), xyz(40, 25, 1), xyz(0, 25, 1), xyz(0, 0, 1)]
    assert outline[5:] == [xyz(0, 0, 0), xyz(40, 0, 0), xyz(40, 25, 0), xyz(0, 25, 0), xyz(0, 0, 0)]
    assert case.position == xyz(0, 0, 50)


def test_31_search_and_md11120() -> None:
    """GOTOB to a block number that stands earlier: N100 runs three times, R2 = 3·10."""
    assert Case("31_search_and_md11120").ended().r(1, 2) == (3, 30)


def test_32_string_functions() -> None:
    """TOUPPER("Contour") << "_" << 12 = "CONTOUR_12": 10 characters, "_" at index 7,
    NUMBER("3.25")·2 = 6.5, both comparisons true."""
    assert Case("32_string_functions").ended().r(1, 2, 3, 4, 5) == (10, 0, 7, 6.5, 0)


def test_33_case_and_save() -> None:
    """CASE (002 L23209) jumps to TWO for 2; 20 matches nothing so DEFAULT; SAVE (002 L22796,
    L31141) restores G90 (member 1) at the return, without SAVE G91 (2) stays."""
    assert Case("33_case_and_save").ended().r(2, 3, 4, 5) == (2, 0, 1, 2)


def test_34_section_repeat() -> None:
    """REPEATB / REPEAT (002 L21257-21291): the STEP block three times in all (X6); FIRST..N40
    four times (R1 4, R2 40); AA..BB three times (R4 R5 R6 = 3), N80 once."""
    case = Case("34_section_repeat").ended()
    assert case.position["X"] == 6.0
    assert case.r(1, 2, 3, 4, 5, 6, 7) == (4, 40, 1, 3, 3, 3, 1)


def test_35_gotos_sblof() -> None:
    """GOTOS jumps to the program start (002 L21211-21231) while R1 < 3; SBLOF/SBLON are
    accepted (002 L23099)."""
    case = Case("35_gotos_sblof").ended()
    assert case.r(1) == (3,) and case.position["X"] == 3.0


def test_36_840c_rectangle_l46() -> None:
    """840C "Example: Rectangle" (001 L8099-8140): each L46 call returns to its start point;
    the outline spans R0 + 2·R3 = 76 by R1 + 2·R3 = 46: X from -8 to 60 + 8 = 68, Y from 0 to
    -(8 + 30 + 8) = -46."""
    case = Case("36_840c_rectangle_l46").ended()
    first = [e for n, e in case.ends("L46.SPF")][:10]
    assert (min(e["X"] for e in first), max(e["X"] for e in first)) == pytest.approx((-8.0, 68.0))
    assert min(e["Y"] for e in first) == pytest.approx(-46.0)
    assert first[-1] == xyz(0, 0, 0)
    assert case.position == xyz(100, 50, 0)


def test_37_840c_line_by_line_l34() -> None:
    """840C "Line-by-line milling" (001 L8170ff): each pass moves X by 40+10+10+40+10+10 = 120
    and returns Y; three passes from X-180 end at X180 Y-250."""
    case = Case("37_840c_line_by_line_l34").ended()
    assert (case.position["X"], case.position["Y"]) == (180.0, -250.0)


def test_38_mcall_call_sprint() -> None:
    """MCALL calls HOLE after N30 and N40 only (N50 has no motion, MCALL alone ends it);
    CALL by name runs MARK once; SPRINT formats "holes 2, last X=30.0"."""
    case = Case("38_mcall_call_sprint").ended()
    assert case.r(1, 2) == (2, 1)
    texts = [c.text for c in case.result.commands if isinstance(c, canon.Message)]
    assert texts[-1] == "holes 2, last X=30.0"


def test_39_array_set_rep() -> None:
    """SET/REP fill in row-major order: 1 + 2·10 + 3·100 + 9·1000 = 9321; 1.5 + 1.5 + 4 + 5 = 12."""
    assert Case("39_array_set_rep").ended().r(1, 2) == (9321, 12)


def test_40_drilling_cycles() -> None:
    """CYCLE81 to Z-10 (DP), modal to Z-5 (DPR 5 below RFP 0) at X20 and X30 only, CYCLE82
    to Z-4 with a 0.5 s dwell, CYCLE83 infeeds 5, 3, 2, 2 (FDEP -5, DAM 2) to Z-12; each
    feeds at F100 from the safety plane Z2 and retracts to Z50."""
    case = Case("40_drilling_cycles").ended()
    drills = [round(m.end_wcs["Z"], 3) for m in case.result.segments if m.kind == "G1"]
    assert drills == [-10, -5, -5, -4, -5, -8, -10, -12]
    dwells = [c.seconds for c in case.result.commands if isinstance(c, canon.Dwell) and c.seconds]
    assert dwells == [0.5]
    assert case.position == xyz(50, 10, 50)
    assert case.r(1, 2) == (1, 1)
    assert_spindle_deleted_at_end(case)


def test_41_g641_adis_rounding() -> None:
    """G641 rounds a corner within ADIS of it (002 L5050-5070): the 90° corner at (10, 10)
    between N110 and N120 is replaced by an arc from (11, 10) to (10, 9), 1 mm from the corner
    on each side; the G9 block N80 ends exactly at (20, 0); N90 ends exactly at (20, 10)
    because the M8 block between stops the rounding."""
    case = Case("41_g641_adis_rounding").ended()
    ends = case.ends()
    assert (80, xyz(20, 0, -1)) in ends
    assert (90, xyz(20, 10, -1)) in ends
    n110 = [e for n, e in ends if n == 110]
    assert n110 == [xyz(11, 10, -1), xyz(10, 9, -1)]
    assert case.position == xyz(10, 0, 50)
