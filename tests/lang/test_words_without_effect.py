"""Words the parser takes must act as the manual says or be refused with an alarm, in the run
and in ``nck check`` alike — never parsed and then dropped (issue 20).

* ``SF=`` is the start point offset of a thread: the thread starts where the spindle's zero
  mark plus SF is crossed (002 L55683-55687, example L55746 ``G33 Z50 K5 SF=180``); its datum
  is SD42000 THREAD_START_ANGLE (002 L26538), used when a thread block has no SF.
* ``SR=`` belongs to "multiple feedrates in one block" (002 L56700-56712): the retraction
  starts on a fast NCK input, which this control does not have (no NCK I/O): refused with
  12550 like ``ST=``.
* ``OVRA[axis]=`` is the override of the positioning feed FA (002 L56523-56527) or of a
  spindle (002 L54153, 004 L484): there are no positioning axes and no programmable spindle
  override here: refused with 12550.
* ``CR=``, ``AR=``, ``TURN=`` describe a circle or helix (G2/G3); ``RPL=`` is the angle of a
  ``ROT``/``AROT`` in the plane (002 L29255). In a block without a circle or without the
  rotation they would change nothing: refused with 12550, the choice the control already made
  for ``ANG=`` in a circle block (tests/geometry/test_contour_angle.py).
* ``I``, ``J``, ``K`` are interpolation parameters: the centre of a circle (001 L3137-3155) or
  the lead of a thread (G33). Under G0/G1 they mean nothing (``G1 X10 I5`` was taken and
  dropped): refused with 12550 as well; the manuals name no alarm for it.
"""

from __future__ import annotations

import pytest

from nck.check import check_text
from tests.lang.conftest import run_text


def first_alarm(text: str) -> tuple[tuple[int, int | None] | None, tuple[int, int | None] | None]:
    run = run_text(text)
    checked = check_text("TEST.MPF", text)
    return ((run.alarms[0].number, run.alarms[0].line) if run.alarms else None,
            (checked[0].number, checked[0].line) if checked else None)


@pytest.mark.parametrize("word", ["CR=5", "AR=90", "TURN=2"])
@pytest.mark.parametrize("motion", ["G1", "G0"])
def test_circle_words_in_a_linear_block_are_refused(word: str, motion: str) -> None:
    text = f"N10 {motion} X10 Y0 F100 {word}\nN20 M30\n"
    assert first_alarm(text) == ((12550, 1), (12550, 1))


@pytest.mark.parametrize("word", ["I5", "J=AC(3)", "K-2"])
@pytest.mark.parametrize("motion", ["G1", "G0"])
def test_interpolation_parameters_in_a_linear_block_are_refused(word: str, motion: str) -> None:
    text = f"N10 G17 G0 X0 Y0\nN20 {motion} X10 F100 {word}\nN30 M30\n"
    assert first_alarm(text) == ((12550, 2), (12550, 2))


def test_interpolation_parameters_still_give_the_centre_and_the_lead() -> None:
    # G2 with I: centre 10 mm along X from the start (001 L3148); G33 with K: the lead.
    result = run_text("N10 G17 G0 X0 Y0\nN20 G2 X20 Y0 I10 J0 F100\nN30 M30\n")
    assert result.status == "ended", result.alarms
    assert result.segments[-1].center_wcs["X"] == pytest.approx(10.0)
    result = run_text("N10 G0 X0 Y0 Z0 S100 M3\nN20 G33 Z-10 K2\nN30 M30\n")
    assert result.status == "ended", result.alarms


def test_circle_words_in_a_circle_block_still_act() -> None:
    # G2 from (0, 0) to (20, 0) with CR=10: a half circle about (10, 0) (002 circle by radius).
    result = run_text("N10 G17 G2 X20 Y0 CR=10 F100\nN20 M30\n")
    assert result.status == "ended", result.alarms
    assert result.segments[-1].center_wcs["X"] == pytest.approx(10.0)


def test_rpl_without_a_rotation_is_refused() -> None:
    assert first_alarm("N10 G1 X10 F100 RPL=30\nN20 M30\n") == ((12550, 1), (12550, 1))


def test_rpl_with_rot_turns_the_plane() -> None:
    # 002 L29255: ROT RPL=-45 turns the coordinate system in the plane by -45°; X10 then ends
    # at (10 cos 45°, -10 sin 45°) in the machine.
    result = run_text("N10 G17 ROT RPL=-45\nN20 G1 X10 Y0 F100\nN30 M30\n")
    assert result.status == "ended", result.alarms
    end = result.segments[-1].end_mcs
    assert (end["X"], end["Y"]) == pytest.approx((7.0710678, -7.0710678))


@pytest.mark.parametrize("text", [
    "N10 G1 X10 F100 SR=3\nN20 M30\n",
    "N10 OVRA[X]=50\nN20 G1 X10 F100\nN30 M30\n",
    "N10 OVRA[S1]=80\nN20 M30\n",
])
def test_functions_without_the_hardware_are_refused(text: str) -> None:
    assert first_alarm(text) == ((12550, 1), (12550, 1))


def test_sf_is_the_start_angle_of_the_thread() -> None:
    # 002 L55746: G33 Z50 K5 SF=180 — the thread starts 180° after the zero mark.
    result = run_text("N10 S100 M3\nN20 G0 X10 Z100\nN30 G33 Z50 K5 SF=180\nN40 M30\n")
    assert result.status == "ended", result.alarms
    thread = result.segments[-1]
    assert thread.kind == "G33"
    assert thread.thread_start_deg == pytest.approx(180.0)


def test_sf_is_kept_in_sd42000_for_the_next_thread() -> None:
    # SD42000 THREAD_START_ANGLE (002 L26538) holds the start angle of a thread without SF.
    text = "N10 S100 M3\nN20 G33 Z-10 K2 SF=90\nN30 G0 Z0\nN40 G33 Z-10 K2\nN50 M30\n"
    result = run_text(text)
    assert result.status == "ended", result.alarms
    threads = [m for m in result.segments if m.kind == "G33"]
    assert [m.thread_start_deg for m in threads] == [90.0, 90.0]
    assert result.interpreter.data.setting_data["SD42000"] == 90.0


def test_sf_outside_0_to_360_degrees_is_refused() -> None:
    # SD42000 holds 0 … 359.999° (the datum's range).
    assert first_alarm("N10 S100 M3\nN20 G33 Z-10 K2 SF=400\nN30 M30\n") == ((12160, 2), (12160, 2))


@pytest.mark.parametrize("word", ["RND=2", "CHF=2", "CHR=2"])
def test_rounding_on_the_last_motion_before_m30_is_not_inserted_without_an_alarm(word: str) -> None:
    """No chamfer or rounding is inserted when no straight line or circle follows in the plane
    (003 L1015-1019, the ISO milling manual's rule for the Siemens and ISO forms alike); the
    manuals name no alarm for it. The block runs to its programmed end point (10, 0) in one
    straight line, and the check, like the run, finds nothing (our reading of the manual,
    issue 20 audit: the word acts as the manual says, it is not dropped against it)."""
    text = f"N10 G17 G0 X0 Y0\nN20 G1 X10 F1000 {word}\nN30 M30\n"
    result = run_text(text)
    assert result.status == "ended", result.alarms
    last = result.segments[-1]
    assert (last.source.n, last.end_wcs["X"], last.end_wcs["Y"]) == (20, pytest.approx(10.0), pytest.approx(0.0))
    assert [m.source.n for m in result.segments].count(20) == 1
    assert first_alarm(text) == (None, None)
