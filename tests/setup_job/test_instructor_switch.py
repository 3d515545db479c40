"""Issue 22: the instructor's switch — moving the blank and hiding its position from the trainee,
from the Setup area (service level) and from ``nck setup``; retained.

Expected values by hand from the shipped mill's blank (nck/workpiece.py): a 100 × 80 × 30 box
from MCS (-50, -40, -250) to (50, 40, -220). Moving its position X to -120 keeps the size, so the
box then spans X -120 … -20.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from nck import cli
from nck.commands import Box, Cylinder, EnterPassword, MachineSetup
from nck.machine import load_machine
from nck.persistence import Session
from nck.setup_fields import SetupFieldError, setup_fields, with_field
from nck.workpiece import default_machine_setup

from hmi.app import make_app
from tests.burst import burst

MILL = default_machine_setup("mill")
SIZE = (160, 48)


def stored_setup(data_dir: Path) -> MachineSetup:
    return Session.open(data_dir, load_machine("mill3"), install_samples=False).ncdata.machine_setup


# --------------------------------------------------------------------------- the fields
def test_moving_the_blank_keeps_its_size_and_each_axis_moves_alone() -> None:
    moved = with_field(with_field(MILL, "blank.x", "-120"), "blank.z", "-260.5")
    assert moved.blank == Box((-120.0, -40.0, -260.5), (-20.0, 40.0, -230.5))
    assert moved.reference == MILL.reference and moved.hidden is False
    assert with_field(moved, "blank.size_y", "50").blank == Box((-120.0, -40.0, -260.5), (-20.0, 10.0, -230.5))


def test_shape_change_fits_the_new_solid_into_the_old_extent() -> None:
    bar = with_field(MILL, "blank.shape", "cylinder").blank
    assert bar == Cylinder((0.0, 0.0, -250.0), 80.0, 30.0)  # centre of the bottom, the smaller side
    assert with_field(with_field(MILL, "blank.shape", "cylinder"), "blank.shape", "box").blank == Box(
        (-40.0, -40.0, -250.0), (40.0, 40.0, -220.0))
    assert with_field(MILL, "reference.shape", "none").reference is None
    assert with_field(MachineSetup(), "blank.shape", "box").blank == MILL.blank


@pytest.mark.parametrize(("name", "text"), [
    ("blank.x", "abc"), ("blank.x", "nan"), ("blank.size_x", "0"), ("blank.diameter", "40"),
    ("blank.shape", "cone"), ("reference.shape", "cylinder"), ("hidden", "maybe"), ("table.x", "1")])
def test_a_field_that_cannot_be_taken_says_why(name: str, text: str) -> None:
    with pytest.raises(SetupFieldError):
        with_field(MILL, name, text)


def test_hidden_switch_and_position_flags() -> None:
    hidden = with_field(MILL, "hidden", "yes")
    assert hidden.hidden is True and with_field(hidden, "hidden", "0").hidden is False
    flags = {field.name: field.position for field in setup_fields(hidden)}
    assert flags["blank.x"] and flags["blank.size_z"] and not flags["blank.shape"] and not flags["reference.x"]


# --------------------------------------------------------------------------- nck setup
def nck_setup(data_dir: Path, *args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    from nck import cli_setup

    code = cli_setup.run(["--data-dir", str(data_dir), *args], out, err)
    return code, out.getvalue(), err.getvalue()


def test_cli_moves_and_hides_the_blank_at_service_level_and_it_is_retained(tmp_path: Path) -> None:
    code, out, err = nck_setup(tmp_path, "blank.x=-120", "hidden=yes")  # keyswitch 0: level 7
    assert code == 1 and "needs protection level 2" in err
    code, out, err = nck_setup(tmp_path, "--password", "CUSTOMER", "blank.x=-120")  # level 3: a trainee's
    assert code == 1 and stored_setup(tmp_path) == MILL
    code, out, err = nck_setup(tmp_path, "--password", "EVENING", "blank.x=-120", "hidden=yes")
    assert code == 0 and out.splitlines() == ["blank.x = -120 mm", "hidden = yes"]
    assert stored_setup(tmp_path) == MachineSetup(Box((-120.0, -40.0, -250.0), (-20.0, 40.0, -220.0)),
                                                  MILL.reference, hidden=True)
    code, out, _ = nck_setup(tmp_path)  # the trainee's level: position and size not shown
    assert code == 0 and "blank.x = (hidden)" in out and "blank.size_x = (hidden)" in out
    assert "-120" not in out and "reference.x = 150 mm" in out and "hidden = yes" in out
    code, out, _ = nck_setup(tmp_path, "--password", "EVENING", "blank.x")
    assert out == "blank.x = -120 mm\n"


def test_cli_refuses_a_bad_field_without_writing_anything(tmp_path: Path) -> None:
    code, _, err = nck_setup(tmp_path, "--password", "EVENING", "blank.x=-120", "blank.size_x=-5")
    assert code == 2 and "greater than 0" in err and "nothing was written" in err
    assert stored_setup(tmp_path) == MILL


def test_nck_dispatches_setup(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["setup", "--data-dir", str(tmp_path), "blank.shape"]) == 0
    assert capsys.readouterr().out == "blank.shape = box\n"


# --------------------------------------------------------------------------- the Setup area
async def until(pilot, condition, rounds: int = 200) -> None:
    """Let the app handle queued keys until ``condition()`` holds (a burst crossing into an area
    is handled in the area's queue after its first build)."""
    for _ in range(rounds):
        if condition():
            return
        await pilot.pause()
    raise AssertionError("the keys were not handled")


def table_text(app) -> str:
    return str(app.screen.query_one("#setup-table").render())


async def test_setup_area_moves_and_hides_the_blank_at_service_level(tmp_path: Path) -> None:
    """F5 Machine set-up; at keyswitch 0 the edit is refused; with EVENING, typing on the
    value of blank.x opens the field (keys in one burst), ⇧F1 hides the blank; retained."""
    app = make_app(data_dir=str(tmp_path), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+s")  # the area is built on its first visit
        await burst(pilot, "f5", "down", "enter")
        await until(pilot, lambda: "needs access level 2" in app.hint)
        assert "Position X (smallest corner)" in table_text(app) and "-50" in table_text(app)
        app.submit(EnterPassword("EVENING"))
        await burst(pilot, "-", "1", "2", "0", "enter", "shift+f1")
        await until(pilot, lambda: stored_kernel_setup(app).hidden)
        assert stored_kernel_setup(app).blank == Box((-120.0, -40.0, -250.0), (-20.0, 40.0, -220.0))
        assert stored_kernel_setup(app).hidden is True
        app.submit(EnterPassword("CUSTOMER"))  # a trainee who knows the user password
        await pilot.pause()
        shown = table_text(app)
        assert "hidden" in shown and "-120" not in shown and "100" not in shown.split("Reference")[0]
    assert stored_setup(tmp_path).blank == Box((-120.0, -40.0, -250.0), (-20.0, 40.0, -220.0))


def stored_kernel_setup(app) -> MachineSetup:
    from nck.queries import MachineSetupData

    return app.bridge.query(MachineSetupData())


@pytest.mark.parametrize(("name", "password"), [("shown", "EVENING"), ("hidden", None)])
def test_setup_area_machine_setup_snapshot(snap_compare, tmp_path: Path, name: str, password: str | None) -> None:
    """The Machine set-up list at service level (position shown) and, with the blank hidden,
    at the trainee's keyswitch level (position and size read "hidden", the fields dimmed)."""
    app = make_app(data_dir=str(tmp_path), realtime=False)

    async def run_before(pilot) -> None:
        from nck.commands import WriteMachineSetup

        app.submit(EnterPassword("EVENING"))
        app.submit(WriteMachineSetup(with_field(MILL, "hidden", "yes" if password is None else "no")))
        if password is None:
            from nck.commands import DeletePassword

            app.submit(DeletePassword())
        await pilot.press("alt+s", "f5")

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)
