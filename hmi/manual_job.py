"""A job of the JOG screens (T,S,M, Position, Set WO activation) run by the kernel as MDA blocks.

On the panel, CYCLE START in a JOG window (T,S,M, Position) runs what the window
says as NC blocks; the control does it as an MDA job while the operator stays in
JOG. The kernel runs blocks only in MDA and AUTOMATIC, so the job switches to
MDA, puts its blocks into the MDA buffer, lets CYCLE START run them, and when
the channel is back in reset (the blocks ended, an alarm or RESET ended them)
puts the operator's MDA blocks back and returns to JOG. Our choice where the
manuals are silent: the header shows MDA while the job runs, which tells the
trainee what the control does.

Only commands of :mod:`nck.commands` are sent (through the bridge's ``submit``).
"""

from __future__ import annotations

from typing import Any, Callable

from nck import commands as cmd, refuse
from nck.status import NckStatus

Submit = Callable[[Any], cmd.SubmitResult]


class ManualJob:
    """Runs one set of blocks at a time as an MDA job and returns to JOG afterwards."""

    def __init__(self, submit: Submit) -> None:
        self._submit = submit
        self._saved_mda_text: str | None = None
        self._armed = False
        self.blocks = ""
        """The blocks of the running job ("" when none runs)."""

    @property
    def running(self) -> bool:
        """True from :meth:`prepare` until the job was ended and JOG is back."""
        return self._saved_mda_text is not None

    def prepare(self, blocks: str, status: NckStatus) -> cmd.SubmitResult:
        """Switch to MDA with ``blocks`` in the buffer, for the CYCLE START that follows.

        Refused (nothing changed) unless the channel is in JOG and reset.
        """
        channel = status.channel
        if self.running:
            return refuse("jog_job_running")
        if channel.mode != "JOG" or channel.channel_state != "reset":
            return refuse("jog_job_needs_reset")
        self._saved_mda_text = channel.mda_text  # running from here: the screens see the job
        self._armed = False
        self.blocks = blocks
        result = self._submit(cmd.SelectMode("MDA"))
        if isinstance(result, cmd.Rejected):
            self._saved_mda_text, self.blocks = None, ""
            return result
        self._submit(cmd.SetMdaProgram(blocks))
        return cmd.Accepted()

    def arm(self) -> None:
        """CYCLE START was given (taken or refused): from now on a channel in reset ends the job."""
        self._armed = True

    def follow(self, status: NckStatus) -> bool:
        """Look at the newest snapshot: once the job's channel is in reset, end the job.

        Before :meth:`arm` the job is only being prepared and nothing happens.
        Returns True when the job ended now (MDA buffer restored, JOG selected).
        """
        if not self.running or not self._armed:
            return False
        channel = status.channel
        if channel.mode == "MDA" and channel.channel_state != "reset":
            return False
        if channel.mode != "MDA" and channel.interrupted_program == "MDA":
            return False  # the operator left the stopped job for a while; it may go on
        back_to_jog = channel.mode == "MDA"  # else the operator chose a mode himself
        saved, self._saved_mda_text = self._saved_mda_text, None
        self.blocks = ""
        self._submit(cmd.SetMdaProgram(saved or ""))
        if back_to_jog:
            self._submit(cmd.SelectMode("JOG"))
        return True
