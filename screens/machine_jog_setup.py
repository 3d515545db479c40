"""The setting-up windows of JOG: T,S,M, Set WO, Position and Settings (issue 22).

The Machine area shows them as views of its lower half (the position window
stays in sight) and reaches them by the vertical softkeys of JOG, as SINUMERIK
Operate does: ``T,S,M`` · ``Set WO`` · ``Meas. workpiece`` · ``Meas. tool`` ·
``Position`` · ``Settings``. :class:`JogWindows` composes the windows, names their
softkeys and does what they ask, through the area's ``submit`` and ``ask`` only.

- T,S,M and Position: CYCLE START runs what the window says as NC blocks
  (:mod:`screens.machine_jog_blocks`), as an MDA job (:class:`hmi.manual_job.ManualJob`).
- Set WO: the actual value of an axis (X=0 … or a value typed) through the kernel's
  ``SetActualValue``: the active settable offset G54… takes the difference, under
  G500 the system frame for PRESET and scratching ``$P_SETFR`` (002 L28667); "Delete
  active WO" is ``DeleteActiveWorkOffset``. Active at once: the WCS display and the
  work offset screens show it with the next snapshot.
- T,S,M selects the work offset (G500, G54 …) and the unit (G71 mm / G70 inch) too: they
  stay active after the job because the shipped machines keep G groups 8 and 13 at RESET
  and program end (MD20152 GCODE_RESET_MODE = 1, 002 L2770-2782).
- Settings: the JOG feed (SD41110) and the variable increment (SD41010) — setting
  data written with ``WriteData`` — and the settings for manual mode that measuring uses
  (``WriteManualSettings``: retraction plane, safety distance, measuring feed).
- Measure workpiece, edge / Z surface, with a 3D probe: CYCLE START searches the surface
  from where the probe stands and backs off (:func:`screens.machine_jog_blocks.probing_blocks`),
  as an MDA job like T,S,M; the touch is the probe's trigger as after jogging.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from rich.text import Text
from textual.app import ComposeResult

from nck import commands as cmd
from nck import fixed, trimmed
from nck.queries import ManualSettingsData, ReadData
from nck.status import NckStatus

from hmi.i18n import N_, _, refusal_text
from hmi.manual_job import ManualJob
from hmi.softkeys import Softkey, view_softkey
from screens.machine_jog_blocks import (
    SPINDLE_FUNCTIONS, UNCHANGED, UNITS, EntryError, TsmEntry, position_blocks, probing_blocks, tsm_blocks,
)
from screens.machine_jog_form import FieldSpec, JogForm
from screens.machine_jog_measure import MEASURE_WINDOWS, MeasureWindows
from screens.machine_jog_touch import active_tool_is_probe

if TYPE_CHECKING:
    from hmi.area import AreaBase

JOG_WINDOWS = ("tsm", "setwo", "position", "settings", *MEASURE_WINDOWS)
"""The views of the setting-up windows (``view-tsm`` …)."""

RUNS_ON_CYCLE_START = ("tsm", "position", "measwp")
"""Windows whose content CYCLE START runs."""


def _ready_in_jog(screen: AreaBase) -> bool:
    status = screen.status
    return (status is not None and status.channel.mode == "JOG"
            and status.channel.channel_state == "reset")


class JogWindows:
    """The setting-up windows of one Machine area screen."""

    def __init__(self, screen: AreaBase) -> None:
        self.screen = screen
        self.job = ManualJob(screen.submit)
        self.measure = MeasureWindows(screen)

    # -- layout ----------------------------------------------------------------------------
    def axes(self) -> tuple[str, ...]:
        """The path axes (not spindles), as the kernel reports them."""
        return tuple(a.name for a in self.screen.hmi.bridge.status.axes if a.kind != "spindle")

    def _work_offsets(self) -> tuple[str, ...]:
        """The settable work offsets the NC data holds, in the order of their numbers (G54 … G57,
        G505 …; the retained data may hold them in any order)."""
        data = self.screen.ask(ReadData()).data
        frames = getattr(data, "settable_frames", None) or {}
        return tuple(sorted(frames, key=lambda name: int(name[1:]))) or ("G54", "G55", "G56", "G57")

    def compose(self) -> ComposeResult:
        """The four windows (each a view of the Machine area's content switcher)."""
        yield JogForm("T, S, M — tool change, spindle, M function", (
            FieldSpec("tool", "T  tool (number or name)"),
            FieldSpec("edge", "D  cutting edge", initial="1"),
            FieldSpec("speed", "Spindle S", N_("rev/min")),
            FieldSpec("spindle", "Spindle M function", choices=SPINDLE_FUNCTIONS),
            FieldSpec("m", "Other M function"),
            FieldSpec("work_offset", "Work offset", choices=(UNCHANGED, "G500", *self._work_offsets())),
            FieldSpec("unit", "Unit of measurement", choices=tuple(UNITS)),
        ), "↑/↓ field   ←/→ choice   CYCLE START (Alt+G) runs it   F10 back", id="view-tsm")
        yield JogForm("Set WO — actual value in the active work offset", tuple(
            FieldSpec(axis, _("{axis}  new actual value (WCS)").format(axis=axis), "mm") for axis in self.axes()
        ), "⇧F1… axis = 0   ⇧F5 Set WO (values typed)   ⇧F6 delete active WO   F10 back", id="view-setwo")
        yield JogForm("Position — traverse one axis to a position (WCS)", (
            FieldSpec("axis", "Axis", choices=self.axes()),
            FieldSpec("target", "Position", "mm"),
            FieldSpec("feed", "Feed F", "mm/min", initial="1000"),
            FieldSpec("rapid", "Traverse", choices=(N_("feed"), N_("rapid"))),
        ), "↑/↓ field   ←/→ choice   CYCLE START (Alt+G) traverses   F10 back", id="view-position")
        yield JogForm("Settings for manual mode", (
            FieldSpec("jog_feed", "JOG feed (SD41110)", "mm/min"),
            FieldSpec("var_incr", "Variable increment (SD41010)", "mm"),
            FieldSpec("retraction", "Retraction plane RP (WCS Z)", "mm"),
            FieldSpec("safety", "Safety distance SC", "mm"),
            FieldSpec("meas_feed", "Measuring feed (3D probe)", "mm/min"),
        ), "↑/↓ field   ⇧F1 save   F10 back", id="view-settings")
        yield from self.measure.compose(self.axes())

    # -- softkeys --------------------------------------------------------------------------
    def vertical_softkeys(self, view: str | None) -> list[Softkey | None]:
        """The vertical softkeys of the JOG main view (``view`` None) or of a window."""
        if view == "setwo":
            keys: list[Softkey | None] = [
                Softkey(f"setwo.{axis.lower()}0", f"{axis}=0", f"jog('set_zero', '{axis}')",
                        enabled=_ready_in_jog) for axis in self.axes()[:3]]
            keys += [None] * (3 - len(keys))
            return keys + [
                Softkey("setwo.all0", "=0\nall axes", "jog('set_zero', '*')", enabled=_ready_in_jog),
                Softkey("setwo.set", "Set\nWO", "jog('set_typed')", enabled=_ready_in_jog),
                Softkey("setwo.delete", "Delete\nactive WO", "jog('delete_active')", enabled=_ready_in_jog),
            ]
        if view in MEASURE_WINDOWS:
            return self.measure.vertical_softkeys(view)
        if view == "settings":
            return [Softkey("settings.save", "Save\nsettings", "jog('save_settings')")]
        if view in RUNS_ON_CYCLE_START:
            return []
        return [
            view_softkey("jog.tsm", "T,S,M", "tsm"),
            view_softkey("jog.setwo", "Set\nWO", "setwo"),
            view_softkey("jog.measure_workpiece", "Meas.\nworkpiece", "measwp"),
            view_softkey("jog.measure_tool", "Meas.\ntool", "meastool"),
            view_softkey("jog.position", "Position", "position"),
            view_softkey("jog.settings", "Settings", "settings"),
        ]

    def run(self, what: str, *args: str) -> None:
        """A softkey of a window: ``set_zero``, ``set_typed``, ``delete_active``, ``save_settings``."""
        actions: dict[str, Callable[..., None]] = {
            "set_zero": self._set_zero, "set_typed": self._set_typed,
            "delete_active": self._delete_active, "save_settings": self._save_settings,
            "measure_set": self._measure_set, "measure_function": self._measure_function,
            "measure_point": self._measure_point, "measure_delete": self._measure_delete,
        }
        action = actions.get(what)
        if action is not None:
            action(*args)

    # -- windows shown -------------------------------------------------------------------------
    def form(self, view: str) -> JogForm:
        """The window of ``view``."""
        return self.screen.query_one(f"#view-{view}", JogForm)

    def opened(self, view: str) -> None:
        """A window was shown: fill in what it shows of the current state."""
        if view == "settings":
            data = self._setting_data()
            form = self.form(view)
            form.set_value("jog_feed", trimmed(data("SD41110"), 3))
            form.set_value("var_incr", trimmed(data("SD41010"), 3))
            manual = self.screen.ask(ManualSettingsData())
            if manual is not None:
                form.set_value("retraction", trimmed(manual.retraction_plane_mm, 3))
                form.set_value("safety", trimmed(manual.safety_distance_mm, 3))
                form.set_value("meas_feed", trimmed(manual.measuring_feed_mm_min, 3))

    def show(self, view: str, status: NckStatus) -> None:
        """Redraw the info line of window ``view`` from ``status``."""
        form = self.form(view)
        form.focus_first()
        modal = status.channel.modal
        if view == "tsm":
            tool = modal.tool_name or (f"T{modal.tool}" if modal.tool else _("no tool"))
            form.show_info(Text(" " + _("Active: {tool} D{edge}   S {speed} rev/min {spindle}   {offset}   {unit}").format(
                tool=tool, edge=modal.edge, speed=trimmed(modal.spindle_speed_rpm, 3), spindle=modal.spindle_state,
                offset=modal.gcodes.get(8, "G500"), unit="inch" if modal.gcodes.get(13) == "G70" else "mm")
                + f"   {self._job_state(status)}"))
        elif view == "setwo":
            form.show_info(self._setwo_info(status))
        elif view in MEASURE_WINDOWS:
            self.measure.show(view, status)
        elif view == "position":
            form.show_info(Text(f" {self._job_state(status)}"))
        elif view == "settings":
            data = self._setting_data()
            manual = self.screen.ask(ManualSettingsData())
            stored = _("Stored: JOG feed {feed} mm/min (0 = MD32020)   variable increment {increment} mm").format(
                feed=trimmed(data("SD41110"), 3), increment=trimmed(data("SD41010"), 3))
            if manual:
                stored += "\n " + _("RP {plane} mm   SC {distance} mm   measuring feed {feed} mm/min").format(
                    plane=trimmed(manual.retraction_plane_mm, 3), distance=trimmed(manual.safety_distance_mm, 3),
                    feed=trimmed(manual.measuring_feed_mm_min, 3))
            form.show_info(Text(f" {stored}"))

    def _job_state(self, status: NckStatus) -> str:
        if self.job.running:
            return _("running as MDA job: {blocks}").format(blocks=self.job.blocks.strip().replace(chr(10), " · "))
        return ""

    def _setwo_info(self, status: NckStatus) -> Text:
        active = status.channel.modal.gcodes.get(8, "G500")
        text = Text()
        text.append(" " + _("Active work offset: {offset}").format(offset=active), style="bold")
        if active == "G500":
            text.append("   " + _("(Set WO writes the system frame for PRESET and scratching)"))
        text.append("\n " + _("Actual values WCS:"))
        for axis in status.axes:
            if axis.kind != "spindle":
                text.append(f"  {axis.name} {fixed(axis.position_wcs)}")
        return text

    # -- CYCLE START -----------------------------------------------------------------------
    def before_cycle_start(self, view: str) -> bool:
        """CYCLE START in the T,S,M or Position window: prepare its blocks as the MDA job.

        False when there is nothing to start (the dialog line says why); True to let
        NC START go to the kernel (the prepared job, or JOG's own NC START elsewhere).
        """
        status = self.screen.status
        if status is None or view not in RUNS_ON_CYCLE_START or self.job.running:
            return True  # NC START continues a stopped job or does what it does in JOG
        if status.channel.mode != "JOG" or status.channel.channel_state != "reset":
            return True
        try:
            blocks = self._blocks(view)
        except EntryError as error:
            self.screen.say(error.text())
            return False
        result = self.job.prepare(blocks, status)
        if isinstance(result, cmd.Rejected):
            self.screen.say(refusal_text(result))
            return False
        self.screen.call_later(self._arm_job)  # the app gives NC START right after this
        return True

    def _arm_job(self) -> None:
        self.job.arm()
        self.job.follow(self.screen.hmi.bridge.status)

    def _blocks(self, view: str) -> str:
        form = self.form(view)
        if view == "tsm":
            return tsm_blocks(TsmEntry(
                tool=form.value("tool"), edge=form.value("edge"), speed_rpm=form.value("speed"),
                spindle=form.value("spindle"), m_function=form.value("m"),
                work_offset=form.value("work_offset"), unit=form.value("unit")))
        if view == "measwp":
            return self._probing_blocks(form)
        return position_blocks(form.value("axis"), form.value("target"), form.value("feed"),
                               form.value("rapid") == "rapid")

    def _probing_blocks(self, form: JogForm) -> str:
        status, manual = self.screen.status, self.screen.ask(ManualSettingsData())
        if status is None or manual is None or not active_tool_is_probe(self.screen.ask, status):
            raise EntryError(N_("CYCLE START measures with a 3D probe (tool type 710); "
                               "with a cutter jog to the surface"))
        return probing_blocks(form.value("axis"), 1 if form.value("approach") == "+" else -1,
                              manual.retraction_plane_mm, manual.safety_distance_mm,
                              manual.measuring_feed_mm_min)

    def keeps_window(self, view: str | None) -> bool:
        """True when the window ``view`` stays over a mode change: while its job runs in MDA
        and when JOG is back (the kernel's newest state decides, not a snapshot still queued)."""
        return view in JOG_WINDOWS and (self.job.running
                                        or self.screen.hmi.bridge.status.channel.mode == "JOG")

    def follow(self, status: NckStatus) -> bool:
        """A new snapshot: end the MDA job once its blocks are done (back to JOG); True if it ended."""
        return self.job.follow(self.screen.hmi.bridge.status)

    # -- Set WO ------------------------------------------------------------------------------
    def _set_zero(self, axis: str) -> None:
        for name in (self.axes()[:3] if axis == "*" else (axis,)):
            if isinstance(self.screen.submit(cmd.SetActualValue(name, 0.0)), cmd.Rejected):
                return

    def _set_typed(self) -> None:
        form = self.form("setwo")
        wanted: dict[str, float] = {}
        for axis in self.axes():
            text = form.value(axis).strip()
            if not text:
                continue
            try:
                wanted[axis] = float(text)
            except ValueError:
                self.screen.say(_("{axis}: enter a number").format(axis=axis))
                return
        if not wanted:
            self.screen.say(_("Set WO: enter the new actual value of an axis"))
            return
        for axis, value in wanted.items():
            if isinstance(self.screen.submit(cmd.SetActualValue(axis, value)), cmd.Rejected):
                return
            form.set_value(axis, "")

    def _measure_set(self) -> None:
        view = getattr(self.screen, "view", None)
        if view in MEASURE_WINDOWS:
            self.measure.set_value(view, self.screen.say)

    def _measure_function(self, view: str) -> None:
        if getattr(self.screen, "view", None) != view:
            self.screen.action_show_view(view)

    def _measure_point(self) -> None:
        self.measure.points.save_point(getattr(self.screen, "view", ""), self.screen.say)

    def _measure_delete(self) -> None:
        self.measure.points.delete_points(getattr(self.screen, "view", ""))

    def _delete_active(self) -> None:
        self.screen.submit(cmd.DeleteActiveWorkOffset())

    # -- Settings --------------------------------------------------------------------------------
    def _setting_data(self) -> Callable[[str], float]:
        machine_data = self.screen.ask(ReadData()).machine_data

        def value(name: str) -> float:
            return float(machine_data.value(name)) if machine_data is not None else 0.0
        return value

    def variable_increment_mm(self) -> float:
        """SD41010 JOG_VAR_INCR_SIZE: the size of INC VAR (0 when the kernel has no setting data)."""
        return self._setting_data()("SD41010")

    def _save_settings(self) -> None:
        form = self.form("settings")
        manual = self.screen.ask(ManualSettingsData())
        try:
            values = {name: self._setting_number(form, key, positive) for key, name, positive in (
                ("retraction", "retraction_plane_mm", False), ("safety", "safety_distance_mm", True),
                ("meas_feed", "measuring_feed_mm_min", True))}
        except EntryError as error:
            self.screen.say(error.text())
            return
        for key, name in (("jog_feed", "SD41110"), ("var_incr", "SD41010")):
            text = form.value(key).strip()
            if text and isinstance(self.screen.submit(cmd.WriteData(name, text)), cmd.Rejected):
                return
        if manual is not None:
            changed = cmd.ManualSettings(**{name: getattr(manual, name) if value is None else value
                                            for name, value in values.items()})
            if isinstance(self.screen.submit(cmd.WriteManualSettings(changed)), cmd.Rejected):
                return
        self.screen.say(_("Settings saved"))

    @staticmethod
    def _setting_number(form: JogForm, key: str, positive: bool) -> float | None:
        """The number typed in ``key`` (None when empty); EntryError when it is none or not > 0."""
        text = form.value(key).strip()
        if not text:
            return None
        label = {"retraction": N_("Retraction plane"), "safety": N_("Safety distance"),
                 "meas_feed": N_("Measuring feed")}[key]
        try:
            value = float(text)
        except ValueError:
            raise EntryError(N_("{field}: enter a number"), field=label) from None
        if positive and not value > 0.0:
            raise EntryError(N_("{field}: enter a value greater than 0"), field=label)
        return value
