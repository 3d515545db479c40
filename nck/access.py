"""Protection levels 0–7, passwords and the keyswitch.

Level 0 has the most rights and level 7 the fewest. A datum or function with
protection level ``n`` may be used when the current level is ``<= n``.

* Passwords give levels 1–3 (defaults ``SUNRISE``, ``EVENING``, ``CUSTOMER``).
  A password has at most 8 characters (shorter ones count as blank-padded) and
  is stored only as a salted PBKDF2-HMAC-SHA256 hash (600,000 iterations, the
  OWASP recommendation of 2023; one check costs about a third of a second).
* Wrong passwords are counted (retained); the door that takes passwords (panel,
  command line) waits :func:`retry_delay_s` before it takes the next one. The
  kernel itself has no clock: it only counts.
* The keyswitch gives levels 4–7: position 3 → level 4 … position 0 → level 7.
  If several positions are reported at once, position 3 wins.
* An entered password overrides the keyswitch until it is deleted; it is part
  of the retained state and survives power off/on.

The level that each protected function needs comes from the HMI machine data
``USER_CLASS_*`` (display MD 92xx, see ``data/md/display.toml``) or, for
functions without such a datum, from ``data/access.toml``.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import Callable, Mapping

from nck.md_catalog import catalog
from nck.refused import Refused, refusal_texts
from nck.resources import load_toml

LEVEL_MOST_RIGHTS = 0
LEVEL_FEWEST_RIGHTS = 7
PASSWORD_LEVELS = (1, 2, 3)
PASSWORD_MAX_CHARS = 8
KEYSWITCH_POSITIONS = (0, 1, 2, 3)
KDF_ITERATIONS = 600_000  # PBKDF2-HMAC-SHA256, OWASP Password Storage Cheat Sheet (2023)
KDF_ITERATIONS_ACCEPTED = range(10_000, 10_000_001)  # read from a file: older trainer files used 20,000
KDF_NAME = "pbkdf2_sha256"
RETRY_DELAY_CAP_S = 60.0
ALARM_PASSWORD_REFUSED = 129300  # data/alarms/access.toml


def retry_delay_s(failed_attempts: int) -> float:
    """How long a door waits after ``failed_attempts`` wrong passwords in a row before the next try.

    1 s after the first, doubling with every further one, at most 60 s (100 tries then take
    well over an hour instead of 1.4 s).
    """
    if failed_attempts <= 0:
        return 0.0
    return min(RETRY_DELAY_CAP_S, 2.0 ** min(failed_attempts - 1, 16))


class Action(enum.Enum):
    """A protected function; the value is its key in ``data/access.toml``."""

    READ_TOOL = "read_tool"
    WRITE_TOOL_GEOMETRY = "write_tool_geometry"
    WRITE_TOOL_WEAR = "write_tool_wear"
    WRITE_TOOL_NAME = "write_tool_name"
    WRITE_TOOL_TYPE = "write_tool_type"
    WRITE_WORK_OFFSET = "write_work_offset"
    WRITE_FINE_OFFSET = "write_fine_offset"
    WRITE_R_PARAMETER = "write_r_parameter"
    CLEAR_R_PARAMETERS = "clear_r_parameters"
    READ_USER_DATA = "read_user_data"
    WRITE_USER_DATA = "write_user_data"
    WRITE_SETTING_DATA = "write_setting_data"
    WRITE_PROGRAM_CONTROL = "write_program_control"
    SELECT_PROGRAM = "select_program"
    READ_PROGRAM = "read_program"
    EDIT_PROGRAM = "edit_program"
    PRESET = "preset"
    OVERSTORE = "overstore"
    TEACH_IN = "teach_in"
    WRITE_MACHINE_SETUP = "write_machine_setup"
    IMPORT_CLASS_PACK = "import_class_pack"


@dataclass(frozen=True, slots=True)
class ActionRule:
    """Where the level of one action comes from: a USER_CLASS MD, else a fixed level."""

    action: Action
    title: str
    md_number: int | None
    level: int


def _load_rules() -> dict[Action, ActionRule]:
    table = load_toml("access.toml")
    rules: dict[Action, ActionRule] = {}
    for key, entry in table["action"].items():
        action = Action(key)
        rules[action] = ActionRule(
            action=action,
            title=entry["title"],
            md_number=entry.get("md"),
            level=int(entry.get("level", LEVEL_FEWEST_RIGHTS)),
        )
    missing = set(Action) - set(rules)
    if missing:
        raise ValueError(f"data/access.toml lacks {sorted(a.value for a in missing)}")
    return rules


_RULES: dict[Action, ActionRule] | None = None


def action_rules() -> dict[Action, ActionRule]:
    """Return the rule of every protected action (read once from ``data/access.toml``)."""
    global _RULES
    if _RULES is None:
        _RULES = _load_rules()
    return _RULES


UserClassLookup = Callable[[int], "int | None"]


def required_level(action: Action, user_class: UserClassLookup | None = None) -> int:
    """Return the protection level ``action`` needs.

    ``user_class(md_number)`` returns the current value of a USER_CLASS machine
    datum (or None to use the catalogue default); without it the defaults apply.
    """
    rule = action_rules()[action]
    if rule.md_number is not None:
        value = user_class(rule.md_number) if user_class is not None else None
        if value is None:
            value = catalog().get_md(rule.md_number).default
        return int(value)
    return rule.level


def may(level: int, action: Action | int, user_class: UserClassLookup | None = None) -> bool:
    """True when a user at ``level`` may perform ``action`` (or use a datum of that level)."""
    needed = action if isinstance(action, int) else required_level(action, user_class)
    return level <= needed


def level_name(level: int) -> str:
    """Return how a level is reached, for messages (``"password EVENING level"`` style)."""
    if level == 0:
        return "level 0 (system)"
    if level in PASSWORD_LEVELS:
        return f"level {level} (password)"
    return f"level {level} (keyswitch position {LEVEL_FEWEST_RIGHTS - level})"


_TOOL_WEAR_PARAMS = range(12, 21)  # $TC_DP12 … $TC_DP20: wear; the rest is geometry


def action_for_write(name: str) -> Action | None:
    """The protected function that writing the datum ``name`` is, or None when unprotected here.

    ``R10`` / ``R[10]`` → write R parameter; ``$TC_DP12…20[t,d]`` → tool wear, other
    ``$TC_DP…`` → tool geometry; ``$TC_TP…`` (tool name/type) → tool type;
    ``$P_UIFR…``, ``$P_CHBFR…``, ``$P_NCBFR…`` or a frame name ``G54``… → work offset.
    Machine and setting data (``MD…``, ``SD…``, ``$M…``, ``$S…``) are checked per datum
    by :class:`nck.machine_data.MachineDataStore`; they return None here.
    """
    upper = name.strip().upper()
    if upper.startswith("$R") or (upper.startswith("R") and (upper[1:2].isdigit() or upper[1:2] == "[")):
        return Action.WRITE_R_PARAMETER
    if upper.startswith("$TC_DP"):
        digits = ""
        for char in upper[6:]:
            if not char.isdigit():
                break
            digits += char
        if digits and int(digits) in _TOOL_WEAR_PARAMS:
            return Action.WRITE_TOOL_WEAR
        return Action.WRITE_TOOL_GEOMETRY
    if upper.startswith("$TC_TP"):
        return Action.WRITE_TOOL_TYPE
    if upper.startswith(("$P_UIFR", "$P_CHBFR", "$P_NCBFR", "$P_BFRAME")):
        return Action.WRITE_WORK_OFFSET
    frame = upper.split("[")[0].split(".")[0]
    if frame in ("G54", "G55", "G56", "G57") or (
        frame.startswith("G5") and frame[1:].isdigit() and 505 <= int(frame[1:]) <= 599
    ):
        return Action.WRITE_WORK_OFFSET
    return None


class AccessError(Refused):
    """A refused protected operation: a refusal of ``data/refusals.toml`` (``str()``: its English text)."""


class AccessDenied(AccessError):
    """The current level does not allow the operation; nothing was changed.

    ``what_key`` names the refusal that says what was refused (``access_action``: an action's
    title, ``md_write``: writing a datum …), filled from ``fields``; ``what`` is its English text.
    The refusal is ``access_denied`` with ``what`` and, for a panel in another language, the
    ``what_key`` and the fields (:func:`hmi.i18n.refusal_text` says ``what`` in its language).
    An action's title is given as ``action`` with the action's key as ``action_id``.
    """

    def __init__(self, what_key: str, needed_level: int, current_level: int, **fields: object) -> None:
        self.what = refusal_texts()[what_key].format(**fields)
        self.needed_level = needed_level
        self.current_level = current_level
        super().__init__("access_denied", what=self.what, needed=needed_level, current=current_level,
                         what_key=what_key, **fields)

    @classmethod
    def of_action(cls, action: Action, needed_level: int, current_level: int, datum: str = "") -> "AccessDenied":
        """``action`` (its title), on the datum ``datum`` when given, is refused."""
        title = action_rules()[action].title
        if datum:
            return cls("access_action_datum", needed_level, current_level, action=title,
                       action_id=action.value, datum=datum)
        return cls("access_action", needed_level, current_level, action=title, action_id=action.value)


ACCESS_LOCKED_TEXT = refusal_texts()["access_locked"]
"""What the panel says when the keyswitch or a password is tried during an exam."""


class AccessLocked(AccessError):
    """The access level is fixed (an exam): keyswitch and passwords are refused."""

    def __init__(self) -> None:
        super().__init__("access_locked")


class PasswordError(AccessError):
    """A password was wrong, too long, empty or already used for another level."""


def normalize_password(password: str) -> str:
    """Return the password as the control compares it: blank-padded to 8 characters.

    Raises PasswordError when it is empty or longer than 8 characters.
    """
    stripped = password.rstrip(" ")
    if not stripped:
        raise PasswordError("password_empty")
    if len(stripped) > PASSWORD_MAX_CHARS:
        raise PasswordError("password_too_long", max=PASSWORD_MAX_CHARS)
    return stripped.ljust(PASSWORD_MAX_CHARS)


@dataclass(frozen=True, slots=True)
class PasswordHash:
    """A salted hash of one password (never the password itself)."""

    salt_hex: str
    hash_hex: str
    iterations: int = KDF_ITERATIONS
    kdf: str = KDF_NAME

    @classmethod
    def create(cls, password: str, iterations: int = KDF_ITERATIONS) -> "PasswordHash":
        """Hash ``password`` with a fresh random salt."""
        import secrets  # noqa: PLC0415 - only when a password is set

        salt = secrets.token_bytes(16).hex()
        return cls(salt, derive(normalize_password(password), salt, iterations), iterations)

    def matches(self, password: str, derived: dict[tuple[str, int], str] | None = None) -> bool:
        """True when ``password`` hashes to this record.

        ``derived`` caches derivations by (salt, iterations) across records that share a salt.
        """
        try:
            candidate = normalize_password(password)
        except PasswordError:
            return False
        import hmac  # noqa: PLC0415 - only when a password is checked

        key = (self.salt_hex, self.iterations)
        cache = derived if derived is not None else {}
        if key not in cache:
            cache[key] = derive(candidate, self.salt_hex, self.iterations)
        return hmac.compare_digest(cache[key], self.hash_hex)

    def to_json(self) -> dict[str, object]:
        """Return the record as JSON-ready data."""
        return {"kdf": self.kdf, "iterations": self.iterations, "salt": self.salt_hex,
                "hash": self.hash_hex}

    @classmethod
    def from_json(cls, data: Mapping[str, object]) -> "PasswordHash":
        """Read a record written by :meth:`to_json` (ValueError when malformed)."""
        if data.get("kdf") != KDF_NAME:
            raise ValueError(f"unknown password hash {data.get('kdf')!r}")
        salt, digest, iterations = data["salt"], data["hash"], data["iterations"]
        if not (isinstance(salt, str) and isinstance(digest, str) and isinstance(iterations, int)):
            raise ValueError("malformed password hash")
        if isinstance(iterations, bool) or iterations not in KDF_ITERATIONS_ACCEPTED:
            raise ValueError(f"password hash iterations {iterations} outside "
                             f"{KDF_ITERATIONS_ACCEPTED.start} … {KDF_ITERATIONS_ACCEPTED.stop - 1}")
        if len(bytes.fromhex(salt)) < 8 or len(bytes.fromhex(digest)) != 32:
            raise ValueError("malformed password hash")
        return cls(salt, digest, iterations)


def derive(normalized_password: str, salt_hex: str, iterations: int) -> str:
    """The PBKDF2-HMAC-SHA256 hash (hex) of a blank-padded password."""
    import hashlib  # noqa: PLC0415 - only when a password is hashed or checked

    return hashlib.pbkdf2_hmac("sha256", normalized_password.encode("utf-8"),
                               bytes.fromhex(salt_hex), iterations).hex()


def default_password_hashes() -> dict[int, PasswordHash]:
    """Hashes of the factory passwords of levels 1–3 (precomputed in ``data/access.toml``)."""
    table = load_toml("access.toml")["factory_passwords"]
    return {level: PasswordHash.from_json({"kdf": table["kdf"], "iterations": table["iterations"],
                                           "salt": table["salt"], "hash": table[str(level)]})
            for level in PASSWORD_LEVELS}


@dataclass
class AccessState:
    """The retained part of access control: keyswitch, password hashes, active password."""

    keyswitch_position: int = 0
    password_level: int | None = None
    password_hashes: dict[int, PasswordHash] = field(default_factory=default_password_hashes)
    failed_attempts: int = 0  # wrong passwords in a row (the doors wait retry_delay_s of it)
    locked: bool = False
    """An exam's fixed access level (issue 26): keyswitch and passwords change nothing until
    the exam's private data directory is left. Set by the exercise set-up, never by a command."""

    def to_json(self) -> dict[str, object]:
        """Return JSON-ready data (hashes only)."""
        return {
            "keyswitch_position": self.keyswitch_position,
            "password_level": self.password_level,
            "passwords": {str(k): v.to_json() for k, v in sorted(self.password_hashes.items())},
            "failed_attempts": self.failed_attempts,
            "locked": self.locked,
        }

    @classmethod
    def from_json(cls, data: Mapping[str, object]) -> "AccessState":
        """Read data written by :meth:`to_json` (ValueError when malformed)."""
        position = data["keyswitch_position"]
        level = data["password_level"]
        passwords = data["passwords"]
        if not isinstance(position, int) or position not in KEYSWITCH_POSITIONS:
            raise ValueError("bad keyswitch position")
        if level is not None and (not isinstance(level, int) or level not in PASSWORD_LEVELS):
            raise ValueError("bad password level")
        if not isinstance(passwords, dict):
            raise ValueError("bad password table")
        if not passwords:  # never silently back to the factory passwords
            raise ValueError("the password table is empty")
        hashes = {}
        for key, record in passwords.items():
            if key not in ("1", "2", "3") or not isinstance(record, dict):
                raise ValueError("bad password entry")
            hashes[int(key)] = PasswordHash.from_json(record)
        failed = data.get("failed_attempts", 0)
        if isinstance(failed, bool) or not isinstance(failed, int) or not 0 <= failed <= 1_000_000:
            raise ValueError("bad count of failed password attempts")
        locked = data.get("locked", False)
        if not isinstance(locked, bool):
            raise ValueError("bad access lock")
        return cls(position, level, hashes, failed, locked)


def keyswitch_from_bits(bits: tuple[bool, bool, bool, bool]) -> int:
    """Return the keyswitch position from the four position signals (0..3).

    Several signals at once (or none) count as position 3, the position with the
    most rights, as the control does.
    """
    active = [index for index, on in enumerate(bits) if on]
    if len(active) == 1:
        return active[0]
    return 3


class AccessControl:
    """The current access level and the operations that change it.

    Args:
        state: the retained state (mutated in place; persist it after changes).
        user_class: lookup of the current USER_CLASS machine data by number.
    """

    def __init__(self, state: AccessState | None = None,
                 user_class: UserClassLookup | None = None) -> None:
        self.state = state if state is not None else AccessState()
        self.user_class = user_class
        self.log: list[str] = []  # level changes, for the logbook
        self.revision = 0
        """Grows with every change made through this object (keyswitch, passwords, failed
        attempts): whoever shows the access state (the kernel's snapshot) is stale when it moved,
        whichever door (panel, command line, session) made the change."""

    @property
    def keyswitch_level(self) -> int:
        """Level given by the keyswitch alone (position 0 → 7 … position 3 → 4)."""
        return LEVEL_FEWEST_RIGHTS - self.state.keyswitch_position

    @property
    def level(self) -> int:
        """The current level: the password level while one is set, else the keyswitch level."""
        if self.state.password_level is not None:
            return self.state.password_level
        return self.keyswitch_level

    def _refuse_when_locked(self) -> None:
        if self.state.locked:
            raise AccessLocked()

    def _changed(self, before: int | None = None, reason: str = "") -> None:
        """Record a change: :attr:`revision` moves on; a level that is no longer ``before``
        goes into the log with ``reason``."""
        self.revision += 1
        if before is not None and self.level != before:
            self.log.append(f"access level {before} -> {self.level} ({reason})")

    def set_keyswitch(self, position: int) -> None:
        """Turn the keyswitch to ``position`` 0..3 (ValueError otherwise)."""
        if position not in KEYSWITCH_POSITIONS:
            raise ValueError(f"keyswitch position {position} does not exist (0..3)")
        self._refuse_when_locked()
        before = self.level
        self.state.keyswitch_position = position
        self._changed(before, f"keyswitch {position}")

    def check_password(self, password: str) -> int | None:
        """Return the level that ``password`` opens, or None (nothing changes, nothing counted)."""
        derived: dict[tuple[str, int], str] = {}
        for level in PASSWORD_LEVELS:
            record = self.state.password_hashes.get(level)
            if record is not None and record.matches(password, derived):
                return level
        return None

    def try_password(self, password: str) -> int | None:
        """Check a password at a door: a wrong one counts as a failed attempt, a right one
        clears the count (and renews a hash made with fewer iterations than today's)."""
        level = self.check_password(password)
        self._changed()
        if level is None:
            self.state.failed_attempts += 1
            self.log.append(f"password not accepted (failed attempt {self.state.failed_attempts})")
            return None
        self.state.failed_attempts = 0
        if self.state.password_hashes[level].iterations < KDF_ITERATIONS:
            self.state.password_hashes[level] = PasswordHash.create(password)
        return level

    @property
    def retry_delay_s(self) -> float:
        """How long the door waits before it takes the next password (0 after a right one)."""
        return retry_delay_s(self.state.failed_attempts)

    def enter_password(self, password: str) -> int:
        """Set a password: return the new level, or raise PasswordError (level unchanged;
        a wrong password counts as a failed attempt)."""
        self._refuse_when_locked()
        normalize_password(password)
        level = self.try_password(password)
        if level is None:
            raise PasswordError("password_not_accepted")
        before = self.level
        self.state.password_level = level
        self._changed(before, "password set")
        return level

    def delete_password(self) -> None:
        """Delete the active password: back to the keyswitch level."""
        self._refuse_when_locked()
        before = self.level
        self.state.password_level = None
        self._changed(before, "password deleted")

    def change_password(self, level: int, new_password: str) -> None:
        """Give level ``level`` (1..3) a new password.

        Allowed only from that level or one with more rights; the password must
        not already open another level.
        """
        if level not in PASSWORD_LEVELS:
            raise PasswordError("password_levels", level=level)
        self._refuse_when_locked()
        if self.level > level:
            raise AccessDenied("password_change", level, self.level, level=level)
        normalize_password(new_password)
        derived: dict[tuple[str, int], str] = {}
        for other, record in self.state.password_hashes.items():
            if other != level and record.matches(new_password, derived):
                raise PasswordError("password_taken", level=other)
        self.state.password_hashes[level] = PasswordHash.create(new_password)
        self._changed()

    def required(self, action: Action) -> int:
        """Return the level ``action`` needs with the current USER_CLASS data."""
        return required_level(action, self.user_class)

    def may(self, action: Action | int) -> bool:
        """True when the current level allows ``action`` (or a datum of that level)."""
        return may(self.level, action, self.user_class)

    def require_write(self, name: str) -> None:
        """Raise AccessDenied unless the current level may write the datum ``name``
        (see :func:`action_for_write`; names it does not know are not checked here)."""
        action = action_for_write(name)
        if action is not None:
            self.require(action, name)

    def require(self, action: Action | int, datum: str = "") -> None:
        """Raise AccessDenied unless the current level allows ``action`` (on the datum ``datum``)."""
        needed = action if isinstance(action, int) else self.required(action)
        if self.level > needed:
            if isinstance(action, Action):
                raise AccessDenied.of_action(action, needed, self.level, datum)
            raise AccessDenied("access_operation", needed, self.level)
