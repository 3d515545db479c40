"""`nck check` and `nck run` end an endless loop by themselves (issue 19).

The contract (shared spec cli.md "Exit codes": 3 timeout) and `nck --help` document the bounds:
`nck check` interprets at most 200,000 blocks per program (`--max-blocks`), `nck run` stops
after one hour of simulated time (`--timeout`, 0 = no limit).
"""

from __future__ import annotations

from pathlib import Path

import pytest

import nck.cli
from nck.cli import main

LOOP = "N10 LBL: R1=R1+1\nN20 GOTOB LBL\nN30 M30\n"


def _write(tmp_path: Path, name: str, text: str) -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_check_reports_an_endless_loop_instead_of_ok(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    loop = _write(tmp_path, "LOOP.MPF", LOOP)
    assert main(["check", loop, "--max-blocks", "500"]) == 3
    out = capsys.readouterr().out
    assert "LOOP.MPF: not ended after 500 blocks" in out and "ok" not in out.split(":")[1]


def test_check_bound_is_overridable_and_ok_programs_stay_ok(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    counted = _write(tmp_path, "COUNT.MPF", "N10 R1=0\nN20 LBL: R1=R1+1\nN30 IF R1<100 GOTOB LBL\nN40 M30\n")
    assert main(["check", counted, "--max-blocks", "50"]) == 3
    assert main(["check", counted]) == 0  # the default budget is far above 200 blocks
    assert capsys.readouterr().out.splitlines()[-1] == "COUNT.MPF: ok"
    assert main(["check", counted, "--max-blocks", "0"]) == 2


def test_check_default_budget_is_documented_in_help(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "--help"]) == 0
    assert "200000" in capsys.readouterr().out
    assert main(["run", "--help"]) == 0
    assert "default 3600" in capsys.readouterr().out


def test_run_has_a_default_time_limit(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(nck.cli, "DEFAULT_RUN_TIMEOUT_S", 2.0)  # the real default is one hour
    loop = _write(tmp_path, "LOOP.MPF", LOOP)
    assert main(["run", loop]) == 3
    err = capsys.readouterr().err
    assert "did not end within 2 s of simulated time" in err and "--timeout" in err
    assert main(["run", loop, "--timeout", "1"]) == 3
    assert main(["run", loop, "--timeout", "-1"]) == 2
    assert nck.cli._build_parser().parse_args(["run", loop, "--timeout", "0"]).timeout == 0
