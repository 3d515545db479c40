"""The ``nck`` command line as the contract (``spec/cli.md``) describes it."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from nck.cli import main


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_run_json_final_state(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "PART1.MPF", "N10 G0 X10 Y5\nN20 G1 Z-1 F100\nN30 T1 M6 D1 S1000 M3\nN40 R1=5\nN50 M30\n")
    # T1 needs its data set (17191 otherwise, 002 L58219): an end mill without length
    assert main(["run", str(prog), "--json", "--set", "$TC_DP1[1,1]=120", "--password", "CUSTOMER"]) == 0
    state = json.loads(capsys.readouterr().out)
    assert state["alarms"] == []
    assert state["position"]["wcs"] == {"X": 10.0, "Y": 5.0, "Z": -1.0}
    assert state["position"]["mcs"] == {"X": 10.0, "Y": 5.0, "Z": -1.0}
    assert state["gcodes"]["14"] == "G90" and state["gcodes"]["6"] == "G17"
    assert state["tool"] == {"T": 1, "D": 1}
    # M30 with MD35040 = 0 (default) deletes the last S and direction (002 L51032-51035).
    assert state["spindle"] == {"S": 0.0, "state": "M5"}
    assert state["r"] == {"1": 5.0}
    assert state["blocks"] == 5
    assert state["channel"] == "reset" and state["program"] == "aborted"
    # 10 mm... only Z moves at F100: 1 mm -> 0.6 s, plus rapid and block costs
    assert 0.6 < state["machine_time_s"] < 1.0


def test_run_segments_file(tmp_path: Path) -> None:
    prog = write(tmp_path, "PART1.MPF", "N10 G0 X10\nN20 G1 Y5 F200\nM30\n")
    out = tmp_path / "seg.jsonl"
    assert main(["run", str(prog), "--segments", str(out)]) == 0
    lines = [json.loads(line) for line in out.read_text().splitlines()]
    assert lines[0] == {"file": "PART1.MPF", "line": 1, "n": 10, "motion": "G0", "plane": "G17",
                        "end": {"X": 10.0, "Y": 0.0, "Z": 0.0}, "end_mcs": {"X": 10.0, "Y": 0.0, "Z": 0.0},
                        "center": None, "feed": None}
    assert lines[1]["motion"] == "G1" and lines[1]["feed"] == 200.0 and lines[1]["n"] == 20


def test_run_segments_to_stdout(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "A.MPF", "G0 X1\nG0 X2\n")
    assert main(["run", str(prog), "--segments", "-"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [json.loads(x)["end"]["X"] for x in out] == [1.0, 2.0]


def test_alarm_goes_to_stderr_with_exit_1(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "PART1.MPF", "N10 G0 X1\nN170 X==\nM30\n")
    assert main(["run", str(prog), "--json"]) == 1
    captured = capsys.readouterr()
    assert captured.err.startswith("ALARM 12080 PART1.MPF:2 N170 ")
    state = json.loads(captured.out)
    assert state["alarms"][0]["number"] == 12080
    assert state["alarms"][0]["line"] == 2 and state["alarms"][0]["n"] == 170


def test_timeout_exit_3(tmp_path: Path) -> None:
    prog = write(tmp_path, "LOOP.MPF", "LBL: R1=R1+1\nGOTOB LBL\n")
    assert main(["run", str(prog), "--timeout", "2"]) == 3


def test_set_r_parameter_and_tool_edge(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "P.MPF", "G0 X=R1\nR2=$TC_DP6[1,1]\nM30\n")
    assert main(["run", str(prog), "--json", "--set", "R1=5", "--set", "$TC_DP6[1,1]=4",
                 "--password", "CUSTOMER"]) == 0
    state = json.loads(capsys.readouterr().out)
    assert state["position"]["wcs"]["X"] == 5.0
    assert state["r"] == {"1": 5.0, "2": 4.0}


def test_set_machine_data(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "P.MPF", "R1=$MC_MM_NUM_R_PARAM\nM30\n")
    assert main(["run", str(prog), "--json", "--set", "$MC_MM_NUM_R_PARAM=200",
                 "--password", "SUNRISE"]) == 0
    assert json.loads(capsys.readouterr().out)["r"] == {"1": 200}


def test_subprogram_in_same_directory(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(tmp_path, "CONTOUR.SPF", "PROC CONTOUR(REAL DX)\nG91 G1 X=DX F100\nG90\nM17\n")
    prog = write(tmp_path, "MAIN.MPF", "CONTOUR(3) P2\nM30\n")
    assert main(["run", str(prog), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["position"]["wcs"]["X"] == 6.0


def test_check_ok_and_problems(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    good = write(tmp_path, "GOOD.MPF", "G1 X1 F100\nM30\n")
    bad = write(tmp_path, "BAD.MPF", "N10 X==\nN20 G1234\nN30 IF R1\n")
    assert main(["check", str(good)]) == 0
    capsys.readouterr()
    assert main(["check", str(good), str(bad)]) == 1
    err = capsys.readouterr().err.splitlines()
    assert [line.split()[1] for line in err] == ["12080", "12470", "12640"]
    assert err[1].startswith("ALARM 12470 BAD.MPF:2 N20 ")


def test_command_line_problems_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", str(tmp_path / "missing.mpf")]) == 2
    assert "not found" in capsys.readouterr().err
    assert main(["check", str(tmp_path)]) == 2
    assert f"'{tmp_path}' is a folder, not a program file" in capsys.readouterr().err
    assert main(["run"]) == 2
    assert main(["frobnicate"]) == 2
    prog = write(tmp_path, "P.MPF", "M30\n")
    assert main(["run", str(prog), "--machine", "no_such_machine"]) == 2
    assert main(["run", str(prog), "--set", "garbage"]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_binary_file_is_checked_without_traceback(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = tmp_path / "BIN.MPF"
    prog.write_bytes(bytes(range(256)) * 4)
    assert main(["check", str(prog)]) == 1
    assert "Traceback" not in capsys.readouterr().err


def test_python_dash_m_nck_version() -> None:
    done = subprocess.run([sys.executable, "-m", "nck", "version"], capture_output=True, text=True, check=False)
    assert done.returncode == 0 and done.stdout.startswith("nck ")


def test_tool_table_is_loaded(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    tools = write(tmp_path, "tools.toml", "[[edge]]\nt = 3\nd = 2\ntype = 120\nlength1 = 80\nradius = 5\ndp = { 12 = 0.25 }\n")
    prog = write(tmp_path, "P.MPF", "R1=$TC_DP3[3,2]+$TC_DP12[3,2] R2=$TC_DP6[3,2]\nM30\n")
    assert main(["run", str(prog), "--json", "--tools", str(tools), "--password", "CUSTOMER"]) == 0
    assert json.loads(capsys.readouterr().out)["r"] == {"1": 80.25, "2": 5.0}
    bad = write(tmp_path, "bad.toml", "[[edge]]\nt = 0\n")
    assert main(["run", str(prog), "--tools", str(bad)]) == 2


def test_data_dir_keeps_retained_data_unless_ephemeral(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "COUNT.MPF", "R7=R7+1\nM30\n")
    data_dir = tmp_path / "ncdata"

    def r7(*extra: str) -> float:
        assert main(["run", str(prog), "--json", "--data-dir", str(data_dir), *extra]) == 0
        return json.loads(capsys.readouterr().out)["r"]["7"]

    assert r7() == 1.0
    assert r7() == 2.0
    assert r7("--ephemeral") == 3.0
    assert r7() == 3.0  # the ephemeral run wrote nothing back


def test_subprograms_found_in_the_nc_file_system(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data_dir = tmp_path / "ncdata"
    prog = write(tmp_path, "MAIN.MPF", "HELPER\nM30\n")
    assert main(["run", str(prog), "--data-dir", str(data_dir)]) == 1  # not there yet: 12550
    capsys.readouterr()
    (data_dir / "nc" / "SPF" / "HELPER.SPF").write_text("R3=3\nM17\n")
    assert main(["run", str(prog), "--json", "--data-dir", str(data_dir)]) == 0
    assert json.loads(capsys.readouterr().out)["r"]["3"] == 3.0


def test_set_setting_and_axis_machine_data(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "SD.MPF", "R1=$SC_DRY_RUN_FEED R2=$MA_MAX_AX_VELO[Y]\nM30\n")
    assert main(["run", str(prog), "--json", "--set", "SD42100=1234", "--set", "$MA_MAX_AX_VELO[Y]=5000",
                 "--password", "SUNRISE"]) == 0
    assert json.loads(capsys.readouterr().out)["r"] == {"1": 1234.0, "2": 5000.0}
    assert main(["run", str(prog), "--set", "$MC_NO_SUCH_DATUM=1", "--password", "SUNRISE"]) == 2


def test_check_finds_jumps_without_destination_on_paths_not_taken(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    prog = write(tmp_path, "J.MPF", "R1=1\nIF R1==0 GOTOF NOWHERE\nGOTOB LATER\nLATER: GOTOC GONE\nM30\n")
    assert main(["check", str(prog)]) == 1
    err = capsys.readouterr().err.splitlines()
    assert [(line.split()[1], line.split()[2]) for line in err] == [("14080", "J.MPF:2"), ("14080", "J.MPF:3")]
    ok = write(tmp_path, "S.MPF", 'DEF STRING[8] DEST="END"\nGOTOF DEST\nEND: M30\n')
    assert main(["check", str(ok)]) == 0


def test_run_reads_the_user_data_dir_but_never_writes_it(tmp_path, monkeypatch) -> None:
    # Without --data-dir, `nck run` uses the user's NC data on a temporary copy: R5 retained
    # there is read, and the program's own write of R5 is not saved back.
    import json
    import subprocess
    import sys

    user_dir = tmp_path / "user-ncdata"
    program = tmp_path / "R.MPF"
    program.write_text("R1=R5*2\nR5=R5+1\nM30\n")
    monkeypatch.setenv("NCK_DATA_DIR", str(user_dir))

    def run(*extra: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "nck", "run", str(program), "--json", *extra],
                              capture_output=True, text=True, check=False)

    setup = run("--data-dir", str(user_dir), "--set", "R5=7", "--password", "CUSTOMER")  # explicit: R5 = 8 is saved
    assert setup.returncode == 0, setup.stderr
    for _ in range(2):
        result = run()
        assert result.returncode == 0, result.stderr
        assert json.loads(result.stdout)["r"]["1"] == 16.0  # 18 on the second run if written back
