"""The exam profile's fixed access level (issue 26): a lock the trainee cannot lift.

An exam's set-up (``exam = true``, data/exercises/13_exam_setup.toml: keyswitch 1, that is
level 6) locks the retained access state of its private data directory: the keyswitch,
entering, deleting and changing passwords are refused with the panel's words and change
nothing; a wrong password is not even counted. A practice exercise has no lock.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as cmd
from nck.access import ACCESS_LOCKED_TEXT, AccessControl, AccessLocked, AccessState
from nck.exercise import load_exercises
from nck.exercise_setup import prepare_data_dir
from nck.kernel import Nck
from nck.persistence import Session

EXERCISES = {e.exercise_id: e for e in load_exercises()}


def kernel_on(exercise_id: str, directory: Path) -> Nck:
    prepare_data_dir(EXERCISES[exercise_id], directory)
    return Nck(**Session.open(directory).kernel_arguments())


def test_an_exam_fixes_the_access_level(tmp_path: Path) -> None:
    assert EXERCISES["13_exam_setup"].exam
    nck = kernel_on("13_exam_setup", tmp_path)
    assert nck.status().access_level == 6  # keyswitch position 1 → level 6
    for command in (cmd.SetKeyswitch(3), cmd.SetKeyswitch(0), cmd.EnterPassword("EVENING"),
                    cmd.EnterPassword("WRONG"), cmd.DeletePassword(), cmd.ChangePassword(3, "NEWPASS")):
        result = nck.submit(command)
        assert isinstance(result, cmd.Rejected) and result.reason == ACCESS_LOCKED_TEXT, command
        assert nck.status().access_level == 6
    assert nck.access.state.failed_attempts == 0  # refused before the password was looked at


def test_the_lock_is_retained_with_the_data_directory(tmp_path: Path) -> None:
    prepare_data_dir(EXERCISES["13_exam_setup"], tmp_path)
    assert Session.open(tmp_path).retained.access.locked  # a restart (power on) does not lift it


def test_a_practice_exercise_has_no_lock(tmp_path: Path) -> None:
    nck = kernel_on("01_power_on_reference", tmp_path)
    assert isinstance(nck.submit(cmd.SetKeyswitch(3)), cmd.Accepted)
    assert nck.status().access_level == 4


def test_access_state_keeps_the_lock_and_reads_files_without_it() -> None:
    locked = AccessState(keyswitch_position=1, locked=True)
    assert AccessState.from_json(locked.to_json()).locked
    older = locked.to_json()
    del older["locked"]  # a data directory written before the exam profile existed
    assert not AccessState.from_json(older).locked
    with pytest.raises(ValueError):
        AccessState.from_json({**locked.to_json(), "locked": "yes"})
    access = AccessControl(locked)
    with pytest.raises(AccessLocked):
        access.set_keyswitch(3)
    assert access.level == 6
