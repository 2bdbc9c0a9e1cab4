"""The Googol GE series programming interface (GE manual, seed 001) on the virtual :class:`~servobench.Card`.

Explicit-axis style as in the GE manual: every per-axis command takes the axis first, numbered from 1
(``GT_SetKp(axis, kp)``, ``GT_GetSts(axis)``). Two card variants (L99-103): ``"PX"`` (point to point, -PV/-PG,
4 or 8 axes, 32-bit axis status) and ``"SX"`` (continuous path, -SV/-SG, 4 axes, 16-bit axis status; the path
commands come with the card's coordinate systems and are not here). Units are the manual's (L991-996): pulse,
pulse/ms, pulse/ms^2, pulse/ms^3, converted to the card's servo tick with the controller's servo period, which
the GE manual never states (decision V86: a constructor argument, default 200 us). Gains are doubles in
[0, 32767] on the GT-lineage law, per servo tick (V87); DAC counts, 32767 = 10 V.

Return codes (Tables 2-1/2-2, L263-283): 0 success; 1 command error (the card ignored it; the reason is in
``GT_GetCmdSts``, PX axis status bit 7 is set); 7 parameter error (out of range, bad axis number); -1
communication error (no card open, no card with that number); -3 command re-entered (a second thread called a
command while one runs). A read command ``GT_GetX(axis, &x)`` returns the tuple ``(rtn, x)``;
``GT_GetCurrentCardNo()`` returns the number itself, as in C. Illegal sequences leave the card's state unchanged.
Commands the simulator does not model return 1 with no command-error bit (card fault ``not_simulated``) and are
listed in docs/card.md; a command of the other variant's set returns 1 (SX: command-error bit 14).

Module-level functions act on the module's default controller (a PX controller; :func:`controller`);
:class:`GeController` holds its own cards. Simulation helpers (not in the manual): :func:`run` (ticks),
:func:`delay` (ms), :func:`wait_until`, :func:`card`, ``set_inputs`` / ``outputs`` (EXI/EXO words) and
``set_probe_time`` (the EXI0 probe edge).
"""

from __future__ import annotations

import functools
import math
import threading

from .. import _core
from .._core import CardCommandRefused, MotionCommandRefused
from ..card import Card
from . import _ge_watch
from ._ge_watch import TAxis, TWatchBuffer  # noqa: F401 (the manual's watch structures)
from ._controller import DialectController, export_functions

# Return codes (Table 2-1 L263-270, Table 2-2 L272-283).
RTN_SUCCESS = 0
RTN_COMMAND_ERROR = 1
RTN_PARAMETER_ERROR = 7
RTN_COMM_ERROR = -1
RTN_REENTERED = -3

_POS_MIN, _POS_MAX = -1073741824, 1073741823   # L991, L5457-5463
_VEL_MAX, _VEL_MIN_JOG = 40957, -40958          # L5780-5786, L1202-1206
_ACC_MAX, _JERK_MAX = 102400, 256000            # L5435-5437, L5518-5520
_GAIN_MAX = 32767                               # L5530-5620
_MAX_CARDS = 16                                 # L4299-4339

# Commands of the PX set only (ch11 Table 11-1 vs 11-2; ch12 "applicable cards"): on an SX card they return 1
# with command-error bit 14 (Table 2-4).
_PX_ONLY = frozenset({
    "GT_PrflT", "GT_PrflS", "GT_PrflV", "GT_SetPos", "GT_GetPos", "GT_SetVel", "GT_GetVel", "GT_SetAcc",
    "GT_GetAcc", "GT_SetMAcc", "GT_GetMAcc", "GT_SetJerk", "GT_GetJerk", "GT_SmthStp", "GT_AbptStp",
    "GT_GetMode", "GT_GetPrfPos", "GT_GetAtlVel", "GT_GetPrfVel", "GT_GetAtlErr", "GT_CloseLp", "GT_OpenLp",
    "GT_SetMtrCmd", "GT_GetMtrCmd", "GT_AuStpOn", "GT_AuStpOff", "GT_IndexSns"})
# Commands of the SX set only: on a PX card they return 1 (Table 2-3 has no bit for it).
_SX_ONLY = frozenset({"GT_EncPos", "GT_HandWheel", "GT_ExitHWheel", "GT_SetAdcChn"})
# Commands whose C form writes through pointers: (rtn, value) in Python.
_READS = frozenset({"GT_ExInpt", "GT_GetLmtSwt", "GT_GetHomeSwt", "GT_GetCmdSts", "GT_EncPos"})


def _int_in(value, lo, hi) -> bool:
    if isinstance(value, bool):
        return False
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


def _real_in(value, lo, hi) -> bool:
    if isinstance(value, bool):
        return False
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and lo <= v <= hi


class _Slot:
    """One open card and what the dialect keeps about it (settings the Card has no register for)."""

    def __init__(self, card: Card, address: int):
        self.card = card
        self.address = address
        self.reset()

    def reset(self):
        n = len(self.card)
        self.lmt_sns = 0             # GT_LmtSns word (L4897-4907)
        self.home_sns = 0            # GT_HomeSns word (L4809-4837)
        self.index_sns = 0           # GT_IndexSns word (L4869-4877)
        self.enc_sns = 0             # GT_EncSns word (L4025-4035)
        self.ctrl_mode = [0] * n     # GT_CtrlMode: 0 analog (default, L3915), 1 pulse
        self.step_pulse = [False] * n  # GT_StepPulse (True) / GT_StepDir (False, default L701)
        self.enc_on = [True] * n     # GT_EncOn (default on an analog axis) / GT_EncOff
        self.inputs = 0              # EXI0..EXI15 (simulated levels, set_inputs)
        self.outputs = 0             # EXO0..EXO15 (GT_ExOpt)
        self.shadow = {}             # (axis, register) -> (GE-unit value, per-tick value) for exact read-backs


def _command(name: str, fn):
    """Wraps a GT_* method: variant command set, re-entry (-3), and the GT_HookCommand callback."""
    read = name in _READS or name.startswith("GT_Get") and name != "GT_GetCurrentCardNo"

    @functools.wraps(fn)
    def wrapper(self, *args, **kwargs):
        if not self._lock.acquire(blocking=False):
            return (RTN_REENTERED, 0) if read else RTN_REENTERED
        try:
            if self._card is not None and (name in _PX_ONLY and self.variant == "SX" or
                                           name in _SX_ONLY and self.variant == "PX"):
                self._card.record_fault(-1, "not_in_command_set")
                result = (RTN_COMMAND_ERROR, 0) if read else RTN_COMMAND_ERROR
            else:
                result = fn(self, *args, **kwargs)
        finally:
            self._lock.release()
        hook = self._hook
        if hook is not None:
            rtn = result[0] if isinstance(result, tuple) else result
            hook(f"{name}({','.join(str(a) for a in args)})", rtn)
        return result

    return wrapper


class GeController(DialectController):
    """A GE card program's view of one or more :class:`~servobench.Card` (GT_Open opens the next, up to 16).

    variant
        ``"PX"`` (point to point, GE-X00-PV/PG) or ``"SX"`` (continuous path, GE-X00-SV/SG).
    axes
        4 or 8 (PX); 4 (SX). Cards given to :meth:`GT_Open` must have this many axes.
    servo_period_s
        the servo (control sampling) period, s, 48e-6..1966.08e-6, default 200e-6 (decision V86: the GE manual
        states none; the GT-400 lineage's default). Cards given to :meth:`GT_Open` must run at it.
    """

    def __init__(self, variant: str = "PX", axes: int = 4, servo_period_s: float = 200e-6):
        super().__init__()
        if variant not in ("PX", "SX"):
            raise ValueError(f"GeController.variant = {variant!r} must be 'PX' or 'SX' (GE manual L99-103)")
        if not _int_in(axes, 4, 8) or int(axes) not in ((4, 8) if variant == "PX" else (4,)):
            raise ValueError(f"GeController.axes = {axes} must be {'4 or 8' if variant == 'PX' else '4'} for a "
                             f"GE-X00-{variant} card (GE manual L99-103)")
        lo, hi = _core.GtServoLaw.PERIOD_RANGE_S
        if not _real_in(servo_period_s, lo, hi):
            raise ValueError(f"GeController.servo_period_s = {servo_period_s} is outside the allowed range "
                             f"{lo:g}..{hi:g} s (decision V86)")
        self.variant = variant
        self.axes = int(axes)
        self.servo_period_s = float(servo_period_s)
        self._k = self.servo_period_s / 1e-3   # ms per tick: pulse/ms * k = pulse/tick
        self._slots: dict[int, _Slot] = {}
        self._current = 0
        self._hook = None
        self._lock = threading.Lock()

    # -- plumbing -------------------------------------------------------------------------------------------
    @property
    def _slot(self) -> _Slot | None:
        return self._slots.get(self._current)

    def _sync(self):
        slot = self._slot
        self._card = slot.card if slot is not None else None

    def _ax(self, axis):
        """0-based axis, or None after recording an illegal parameter (bad axis number)."""
        if _int_in(axis, 1, self.axes):
            return int(axis) - 1
        self._card.record_fault(-1, "illegal_control_param")
        return None

    def _do(self, fn, *args) -> int:
        try:
            fn(*args)
        except (CardCommandRefused, MotionCommandRefused):
            return RTN_COMMAND_ERROR
        except ValueError:
            return RTN_PARAMETER_ERROR
        return RTN_SUCCESS

    def _axis_cmd(self, axis, fn, ok=True, fault="illegal_control_param") -> int:
        """Per-axis command: -1 without a card, 7 for a bad axis or `ok` False (recording `fault`), else fn(a)."""
        if self._card is None:
            return RTN_COMM_ERROR
        a = self._ax(axis)
        if a is None:
            return RTN_PARAMETER_ERROR
        if not ok:
            self._card.record_fault(a, fault)
            return RTN_PARAMETER_ERROR
        return self._do(fn, a)

    def _fail(self, a, fault, what):
        """Refuses a command the dialect checks itself: records `fault` (axis bit 7, GT_GetCmdSts) and raises."""
        self._card.record_fault(a, fault)
        raise CardCommandRefused(f"axis {a + 1}: {what} [refused: {fault}; return code 1]")

    def _read(self, axis, fn):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        a = self._ax(axis)
        if a is None:
            return RTN_PARAMETER_ERROR, 0
        return RTN_SUCCESS, fn(a)

    def _get(self, fn):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        return RTN_SUCCESS, fn()

    def _not_simulated(self, read=False):
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        self._card.record_fault(-1, "not_simulated")
        return (RTN_COMMAND_ERROR, 0) if read else RTN_COMMAND_ERROR

    def _stage(self, a, register, value, order, stage):
        per_tick = float(value) * self._k ** order
        stage(a, per_tick)
        self._slot.shadow[(a, register)] = (float(value), per_tick)

    def _readback(self, a, register, order):
        per_tick = self._card.staged(a)[register]
        ge, tick = self._slot.shadow.get((a, register), (None, None))
        return ge if tick == per_tick else per_tick / self._k ** order

    def _law(self, a):
        return self._card.staged(a)["law"]

    def _pulse_axis(self, a) -> bool:
        return self._slot.ctrl_mode[a] == 1

    def _set_law(self, axis, field, value, ok) -> int:
        def apply(a):
            if self._pulse_axis(a):  # a servo command on a pulse axis (SX cmd bit 6, L333)
                self._fail(a, "axis_state_error", "pulse axis")
            self._card.stage_law(a, self._law(a).replace(fractional_gains=True, **{field: float(value)}))

        return self._axis_cmd(axis, apply, ok)

    # -- simulation helpers -----------------------------------------------------------------------------------
    def delay(self, ms: float):
        """The manual's ``delay(ms)``: runs the card for ``ms`` milliseconds (rounded to whole ticks)."""
        return self.run_ms(ms)

    def set_inputs(self, bits: int):
        """Sets the simulated levels of the general inputs EXI0..EXI15 (bit n = EXIn; 1 = high) that
        ``GT_ExInpt`` reads. (The probe edge of EXI0 for ``GT_CaptProb`` is ``set_probe_time``.)"""
        if not _int_in(bits, 0, 0xFFFF):
            raise ValueError(f"set_inputs.bits = {bits} is outside the allowed range 0..65535 (16 inputs)")
        self._slot.inputs = int(bits)

    def outputs(self) -> int:
        """The general outputs EXO0..EXO15 as last written by ``GT_ExOpt`` (bit n = EXOn)."""
        return self._slot.outputs

    def set_probe_time(self, t_s: float):
        """The simulated probe edge on EXI0 at time ``t_s`` (s, the axes' clock tick * Ts; NaN: never)."""
        self._card.set_probe_time(float(t_s))

    # -- 7.1 system -------------------------------------------------------------------------------------------
    def GT_Open(self, address=65535, card: Card | None = None, **axis_parts) -> int:
        """Opens the next card (L5313-5321; a second call opens the next one, L4310-4315) and makes it current:
        ``card`` (or a :class:`~servobench.Card` as the first argument), or a new one built from ``axis_parts``
        (GE reset defaults: gains 0). ``address``: the ISA base address (e.g. 0x300) or 65535 for PCI, recorded.
        Returns -1 when 16 cards are open."""
        if isinstance(address, Card):
            address, card = 65535, address
        if not _int_in(address, 0, 0xFFFFFFFF):
            return RTN_PARAMETER_ERROR
        free = [n for n in range(_MAX_CARDS) if n not in self._slots]
        if not free:
            return RTN_COMM_ERROR
        if card is None:
            axis_parts.setdefault("law", _core.GtServoLaw(fractional_gains=True))
            axis_parts.setdefault("servo_period_s", self.servo_period_s)
            card = Card(self.axes, **axis_parts)
        if len(card) != self.axes:
            raise ValueError(f"GT_Open.card has {len(card)} axes; this GE-{self.variant} controller has {self.axes}")
        for a in card.axes:
            if not isinstance(a.law, _core.GtServoLaw):
                raise ValueError("GT_Open.card: a GE card runs the GT-lineage servo law (GtServoLaw), not "
                                 f"{type(a.law).__name__} (decision V87)")
        if not math.isclose(card.servo_period_s, self.servo_period_s, rel_tol=1e-12):
            raise ValueError(f"GT_Open.card.servo_period_s = {card.servo_period_s} differs from the controller's "
                             f"servo_period_s = {self.servo_period_s} (give GeController(servo_period_s=...))")
        n = free[0]
        self._slots[n] = _Slot(card, int(address))
        self._current = n
        self._sync()
        if self.variant == "SX":
            for a in range(self.axes):  # SX: a following error always stops (L2364)
                card.set_auto_stop(a, True)
        return RTN_SUCCESS

    def GT_Close(self) -> int:
        """Closes the current card (L3865); its number stays current until ``GT_SwitchtoCardNo``."""
        if self._card is None:
            return RTN_COMM_ERROR
        del self._slots[self._current]
        self._sync()
        return RTN_SUCCESS

    def GT_Reset(self) -> int:
        """Resets the current card's registers to the defaults (L5400-5408, list L4769-4786): motion and capture
        registers 0, trapezoid mode, gains 0, ILmt/MtrLmt/PosErr 32767, auto-stop off (SX: on), closed loop,
        limits on with high-level polarity, alarm input on, outputs 0, drives off, events cleared."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._card.reset()
        self._slot.reset()
        if self.variant == "SX":
            for a in range(self.axes):
                self._card.set_auto_stop(a, True)
        return RTN_SUCCESS

    def GT_HardRst(self) -> int:
        """Hardware reset (L4769-4786): as ``GT_Reset`` (the DSP program reload is not simulated)."""
        return self.GT_Reset.__wrapped__(self)

    def GT_HookCommand(self, handler) -> int:
        """Hooks ``handler(command: str, error: int)``, called after every GT_* command with its name and
        arguments (``"GT_SetKp(1,10)"``) and its return value (L394-400, L4855-4866); None unhooks. Not a command
        itself (no hook call for it)."""
        if handler is not None and not callable(handler):
            return RTN_PARAMETER_ERROR
        self._hook = handler
        return RTN_SUCCESS

    def GT_GetCurrentCardNo(self) -> int:
        """The current card number 0..15 (returned, not an error code) (L4299-4339)."""
        return self._current

    def GT_SwitchtoCardNo(self, number) -> int:
        """Makes card ``number`` (0..15) current (L5881-5893); -1 if no card with that number is open."""
        if not _int_in(number, 0, _MAX_CARDS - 1):
            return RTN_PARAMETER_ERROR
        if int(number) not in self._slots:
            return RTN_COMM_ERROR
        self._current = int(number)
        self._sync()
        return RTN_SUCCESS

    def GT_GetCmdSts(self):
        """(rtn, command-error register): PX Table 2-3 (L301-322), SX Table 2-4 (L324-347); the bit of the last
        refused command's cause (decision V90)."""
        return self._get(lambda: _core.ge_command_status(self._card._card, self.variant))

    # -- 7.2 axis configuration -------------------------------------------------------------------------------
    def GT_AxisOn(self, axis) -> int:
        """Servo on; target and profile positions take the actual position (L3716-3720); refused while the
        drive-alarm bit is set (PX cmd bit 9, SX bit 3)."""
        def on(a):
            self._card.axis_on(a)
            if not self._card.moving(a):
                self._card.synch_pos_now(a)

        return self._axis_cmd(axis, on)

    def GT_AxisOff(self, axis) -> int:
        """Servo off (L3704)."""
        return self._axis_cmd(axis, lambda a: self._card.axis_off(a))

    def GT_DrvRst(self, axis) -> int:
        """Pulses the drive-reset output; only with the servo off (cmd bit 3) (L3954-3980)."""
        return self._axis_cmd(axis, lambda a: self._card.drive_reset(a))

    def GT_AlarmOn(self, axis) -> int:
        """Drive-alarm input monitored (default on -XV) (L3408); SX: illegal with the servo on (cmd bit 3)."""
        return self._alarm(axis, True)

    def GT_AlarmOff(self, axis) -> int:
        """Drive-alarm input ignored (L3396); SX: illegal with the servo on (cmd bit 3)."""
        return self._alarm(axis, False)

    def _alarm(self, axis, on) -> int:
        def apply(a):
            if self.variant == "SX" and self._card.servo_on(a):
                self._fail(a, "motor_state_while_enabled", "servo on")
            self._card.set_alarm_enabled(a, on)

        return self._axis_cmd(axis, apply)

    def GT_LmtsOn(self, axis) -> int:
        """Limit switches stop the axis (default; status bit 11) (L4921)."""
        return self._axis_cmd(axis, lambda a: self._card.set_limits(a, self._card.limits(a).replace(enabled=True)))

    def GT_LmtsOff(self, axis) -> int:
        """Limit switches ignored (still readable by GT_GetLmtSwt) (L4909)."""
        return self._axis_cmd(axis, lambda a: self._card.set_limits(a, self._card.limits(a).replace(enabled=False)))

    def GT_LmtSns(self, sense) -> int:
        """Limit polarity, all axes: bit 2k axis k+1 positive, 2k+1 negative; 0 triggers on a high level
        (default), 1 on a low level (Table 3-3 L516-520, L4897-4907)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(sense, 0, 0xFFFF):
            return self._param(-1)

        def apply():
            for k in range(self.axes):
                lim = self._card.limits(k).replace(pos_active_low=bool(int(sense) >> (2 * k) & 1),
                                                   neg_active_low=bool(int(sense) >> (2 * k + 1) & 1))
                self._card.set_limits(k, lim)
            self._slot.lmt_sns = int(sense)

        return self._do(apply)

    def _param(self, a, fault="illegal_control_param") -> int:
        self._card.record_fault(a, fault)
        return RTN_PARAMETER_ERROR

    def _sense_word(self, attr, sense) -> int:
        """HomeSns / IndexSns / EncSns: 0 bits are the simulated wiring; a set bit (for a card axis) is not
        simulated (rtn 1, decision V93)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(sense, 0, 0xFFFF):
            return self._param(-1)
        if int(sense) & ((1 << self.axes) - 1):
            return self._not_simulated()
        setattr(self._slot, attr, int(sense))
        return RTN_SUCCESS

    def GT_HomeSns(self, sense) -> int:
        """Home capture edge, bit k = axis k+1: 0 falling (default) = the simulated edge where the axis enters the
        home switch; 1 rising: not simulated, returns 1 (L524-534, L4809-4837, V93)."""
        return self._sense_word("home_sns", sense)

    def GT_IndexSns(self, sense) -> int:
        """Index capture edge (PX; bit meaning not given, L4869-4877): 0 accepted, a set bit returns 1 (V93)."""
        return self._sense_word("index_sns", sense)

    def GT_EncSns(self, sense) -> int:
        """Encoder count direction, bit k = axis k+1, 1 = reversed (L535-547, L4025-4035). The simulated encoder
        counts the drive's positive direction as positive: 0 bits accepted, a set bit returns 1 (V93)."""
        return self._sense_word("enc_sns", sense)

    def GT_EncOn(self, axis) -> int:
        """Encoder input on (default); illegal with the servo on (SX cmd bit 3) (L3992-4000)."""
        return self._enc(axis, True)

    def GT_EncOff(self, axis) -> int:
        """Encoder input off: GT_GetAtlPos reads the profile position (L3982, L4180); illegal with the servo on."""
        return self._enc(axis, False)

    def _enc(self, axis, on) -> int:
        def apply(a):
            if self._card.servo_on(a):
                self._fail(a, "motor_state_while_enabled", "servo on")
            self._slot.enc_on[a] = on

        return self._axis_cmd(axis, apply)

    def GT_CtrlMode(self, axis, mode) -> int:
        """Output type: 0 analog voltage (default), 1 pulse (L3907-3925); illegal with the servo on (SX cmd bit 6).
        The simulated output is the axis's drive (StepperDrive / ServoPositionDrive take pulses): a mode that does
        not match it returns 1 (not simulated, V94)."""
        def apply(a):
            if self._card.servo_on(a):
                self._fail(a, "axis_state_error", "servo on")
            pulse = type(self._card.axes[a].drive).__name__ in ("StepperDrive", "ServoPositionDrive")
            if bool(int(mode)) != pulse:
                self._fail(a, "not_simulated", "drive")
            self._slot.ctrl_mode[a] = int(mode)

        return self._axis_cmd(axis, apply, mode in (0, 1) and not isinstance(mode, bool))

    def GT_StepDir(self, axis) -> int:
        """Pulse + direction output (default) (L5805); only on a pulse axis (SX cmd bit 6). Recorded: the
        simulated pulse drive counts the pulses whatever their electrical form (V94)."""
        return self._step(axis, False)

    def GT_StepPulse(self, axis) -> int:
        """CW/CCW pulse output (L5840); only on a pulse axis (SX cmd bit 6). Recorded (V94)."""
        return self._step(axis, True)

    def _step(self, axis, pulse) -> int:
        def apply(a):
            if not self._pulse_axis(a):
                self._fail(a, "axis_state_error", "analog axis")
            self._slot.step_pulse[a] = pulse

        return self._axis_cmd(axis, apply)

    def GT_CloseLp(self, axis) -> int:
        """Closed loop (default; PX status bit 8) (L3875-3883); the servo must be off (else rtn 1)."""
        return self._loop(axis, True)

    def GT_OpenLp(self, axis) -> int:
        """Open loop: the output is GT_SetMtrCmd (L5325-5340); the servo must be off (else rtn 1)."""
        return self._loop(axis, False)

    def _loop(self, axis, closed) -> int:
        def apply(a):
            if self._card.servo_on(a):
                self._fail(a, "axis_state_error", "servo on")
            self._card.set_closed_loop(a, closed)

        return self._axis_cmd(axis, apply)

    def GT_SetMtrCmd(self, axis, vol) -> int:
        """Open-loop output, DAC counts -32768..32767 (-32768 is driven as -32767, V95) (L5664-5686)."""
        ok = _int_in(vol, -32768, 32767)
        return self._axis_cmd(axis, lambda a: self._card.set_mtr_cmd(a, float(max(int(vol), -32767))), ok)

    def GT_GetMtrCmd(self, axis):
        """(rtn, open-loop output, counts) (L4600-4606)."""
        return self._read(axis, lambda a: int(self._card.mtr_cmd(a)))

    def GT_AuStpOn(self, axis) -> int:
        """A following error stops the axis abruptly and turns the servo off (mode bit 7) (L3678-3686, L2362)."""
        return self._axis_cmd(axis, lambda a: self._card.set_auto_stop(a, True))

    def GT_AuStpOff(self, axis) -> int:
        """A following error only sets status bit 4 (default) (L3666)."""
        return self._axis_cmd(axis, lambda a: self._card.set_auto_stop(a, False))

    # -- 7.3 point-to-point profile (PX) ----------------------------------------------------------------------
    def GT_PrflT(self, axis) -> int:
        """Trapezoid mode (L5376); only at rest (else rtn 1, cmd bit 6)."""
        return self._axis_cmd(axis, lambda a: self._card.set_mode(a, "t_curve"))

    def GT_PrflS(self, axis) -> int:
        """S-curve mode (L5364); only at rest (cmd bit 6)."""
        return self._axis_cmd(axis, lambda a: self._card.set_mode(a, "s_curve"))

    def GT_PrflV(self, axis) -> int:
        """Velocity mode (L5388); only at rest (cmd bit 6)."""
        return self._axis_cmd(axis, lambda a: self._card.set_mode(a, "jog"))

    def GT_SetPos(self, axis, pos) -> int:
        """Target position, whole pulses -2^30..2^30-1 (on Update) (L5700)."""
        return self._axis_cmd(axis, lambda a: self._card.stage_pos(a, float(pos)),
                              _int_in(pos, _POS_MIN, _POS_MAX), "motion_param_overflow")

    def GT_GetPos(self, axis):
        """(rtn, target position as set, pulse) (L4622)."""
        return self._read(axis, lambda a: int(self._card.staged(a)["pos"]))

    def GT_SetVel(self, axis, vel) -> int:
        """Velocity, pulse/ms: 0..40957 (T, S), -40958..40957 in velocity mode (on Update) (L5780-5786)."""
        if self._card is None:
            return RTN_COMM_ERROR
        a = self._ax(axis)
        if a is None:
            return RTN_PARAMETER_ERROR
        lo = _VEL_MIN_JOG if self._card.mode(a) == "jog" else 0
        if not _real_in(vel, lo, _VEL_MAX):
            return self._param(a, "motion_param_overflow")
        return self._do(self._stage, a, "vel", vel, 1, self._card.stage_vel)

    def GT_GetVel(self, axis):
        """(rtn, velocity as set, pulse/ms) (L4757)."""
        return self._read(axis, lambda a: self._readback(a, "vel", 1))

    def GT_SetAcc(self, axis, acc) -> int:
        """Acceleration, pulse/ms^2, 0..102400; used by trapezoid and velocity modes (on Update) (L5435-5437)."""
        return self._axis_cmd(axis, lambda a: self._stage(a, "acc", acc, 2, self._card.stage_acc),
                              _real_in(acc, 0, _ACC_MAX), "motion_param_overflow")

    def GT_GetAcc(self, axis):
        """(rtn, acceleration as set, pulse/ms^2) (L4120)."""
        return self._read(axis, lambda a: self._readback(a, "acc", 2))

    def GT_SetMAcc(self, axis, macc) -> int:
        """S-curve maximum acceleration, pulse/ms^2, 0..102400 (on Update) (L5626-5628)."""
        return self._axis_cmd(axis, lambda a: self._stage(a, "macc", macc, 2, self._card.stage_macc),
                              _real_in(macc, 0, _ACC_MAX), "motion_param_overflow")

    def GT_GetMAcc(self, axis):
        """(rtn, S-curve maximum acceleration as set, pulse/ms^2) (L4554)."""
        return self._read(axis, lambda a: self._readback(a, "macc", 2))

    def GT_SetJerk(self, axis, jerk) -> int:
        """S-curve jerk, pulse/ms^3, 0..256000 (on Update) (L5518-5520)."""
        return self._axis_cmd(axis, lambda a: self._stage(a, "jerk", jerk, 3, self._card.stage_jerk),
                              _real_in(jerk, 0, _JERK_MAX), "motion_param_overflow")

    def GT_GetJerk(self, axis):
        """(rtn, jerk as set, pulse/ms^3) (L4407)."""
        return self._read(axis, lambda a: self._readback(a, "jerk", 3))

    def GT_Update(self, axis) -> int:
        """Makes the axis's Set* parameters (Table 5-6 L1280-1296) effective at the next servo tick (L5895);
        refused as a whole when a parameter may not change now (cmd bit 11) or is zero (cmd bit 1)."""
        return self._axis_cmd(axis, lambda a: self._card.update(1 << a))

    def GT_MltiUpdt(self, mask) -> int:
        """As GT_Update for the axes of ``mask`` (bit 0 = axis 1 ... bit 7 = axis 8), all in the same tick; mask 0
        is an error (cmd bit 2) (L5189-5228)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 0, 0xFFFF):
            return self._param(-1)
        return self._do(self._card.update, int(mask) & ((1 << self.axes) - 1))

    def GT_SmthStp(self, axis) -> int:
        """Smooth stop at the mode's acceleration, at once (decision V91: immediate, L1310-1312 and Example 7-2;
        ch12 L5797 calls it update-effective)."""
        return self._axis_cmd(axis, lambda a: self._card.smooth_stop(a))

    def GT_AbptStp(self, axis) -> int:
        """Abrupt stop: target and profile velocity 0 at once (L3307-3311, L1317)."""
        return self._axis_cmd(axis, lambda a: self._card.abrupt_stop(a))

    def GT_GetMode(self, axis):
        """(rtn, mode register) (Table 4-4 L938-945): bit 7 auto-stop; bits 13..11 000 T, 001 V, 010 S."""
        return self._read(axis, lambda a: _core.ge_mode_register(self._card._card, a))

    # -- 7.4 position, velocity and error feedback --------------------------------------------------------------
    def GT_ZeroPos(self, axis) -> int:
        """Actual = target = profile = 0; at rest only (else rtn 1, cmd bit 11) (L5907-5913)."""
        return self._axis_cmd(axis, lambda a: self._card.zero_pos(a))

    def GT_SetAtlPos(self, axis, pos) -> int:
        """Actual = target = profile = ``pos``, whole pulses -2^30..2^30-1; at rest only (cmd bit 11) (L5457)."""
        return self._axis_cmd(axis, lambda a: self._card.set_actual_pos(a, float(pos)),
                              _int_in(pos, _POS_MIN, _POS_MAX), "motion_param_overflow")

    def GT_GetAtlPos(self, axis):
        """(rtn, actual position, pulse) (L4173); with the encoder off, the profile position (L4180)."""
        def atl(a):
            if not self._slot.enc_on[a]:
                return int(self._card.profile_pos(a))
            return int(round(self._card.actual_pos(a)))

        return self._read(axis, atl)

    def GT_GetPrfPos(self, axis):
        """(rtn, profile position, pulse) (L4701)."""
        return self._read(axis, lambda a: int(self._card.profile_pos(a)))

    def GT_GetAtlErr(self, axis):
        """(rtn, following error profile - actual of the last tick, pulse) (L4144-4171)."""
        return self._read(axis, lambda a: int(round(self._card.following_error(a))))

    def GT_GetPrfVel(self, axis):
        """(rtn, profile velocity, pulse/ms) (L4713)."""
        return self._read(axis, lambda a: self._card.profile_vel(a) / self._k)

    def GT_GetAtlVel(self, axis):
        """(rtn, actual velocity, pulse/ms): the encoder shaft's speed now in counts (V96) (L4203)."""
        def vel(a):
            ax = self._card.axes[a]
            enc = ax.encoder
            speed = ax.load_speed_rad_s if enc.on_load else ax.speed_rad_s
            return speed * enc.counts_per_rev / (2 * math.pi) * 1e-3

        return self._read(axis, vel)

    # -- 7.5 servo parameters (XV; on Update) -------------------------------------------------------------------
    def GT_SetKp(self, axis, kp) -> int:
        """Proportional gain, double 0..32767 (L5566-5570)."""
        return self._set_law(axis, "kp", kp, _real_in(kp, 0, _GAIN_MAX))

    def GT_SetKi(self, axis, ki) -> int:
        """Integral gain, double 0..32767 (term Ki * SumE / 256, V87) (L5554-5558)."""
        return self._set_law(axis, "ki", ki, _real_in(ki, 0, _GAIN_MAX))

    def GT_SetKd(self, axis, kd) -> int:
        """Derivative gain, double 0..32767 (L5542-5546)."""
        return self._set_law(axis, "kd", kd, _real_in(kd, 0, _GAIN_MAX))

    def GT_SetKvff(self, axis, kvff) -> int:
        """Velocity feed-forward, double 0..32767, on the profile velocity per tick (V87) (L5614-5618)."""
        return self._set_law(axis, "kvff", kvff, _real_in(kvff, 0, _GAIN_MAX))

    def GT_SetKaff(self, axis, kaff) -> int:
        """Acceleration feed-forward, double 0..32767, on the profile acceleration per tick^2 (V87) (L5530-5534)."""
        return self._set_law(axis, "kaff", kaff, _real_in(kaff, 0, _GAIN_MAX))

    def GT_SetILmt(self, axis, ilmt) -> int:
        """Integral limit 0..32767 (default 32767; 0 clears the integral) (L5504-5510)."""
        return self._set_law(axis, "ilmt", ilmt, _int_in(ilmt, 0, 32767))

    def GT_SetMtrLmt(self, axis, lmt) -> int:
        """Output saturation, DAC counts 0..32767 (default 32767 = 10 V) (L5688-5692)."""
        return self._set_law(axis, "mtr_lmt", lmt, _int_in(lmt, 0, 32767))

    def GT_SetMtrBias(self, axis, bias) -> int:
        """Zero-drift compensation, DAC counts -32768..32767 (L5648-5652)."""
        return self._set_law(axis, "bias", bias, _int_in(bias, -32768, 32767))

    def GT_SetPosErr(self, axis, limit) -> int:
        """Following-error limit 0..32767 pulse (default 32767) (L5712-5716)."""
        return self._axis_cmd(axis, lambda a: self._card.stage_pos_err(a, float(limit)), _int_in(limit, 0, 32767))

    def _get_law(self, axis, field, cast=float):
        return self._read(axis, lambda a: cast(getattr(self._law(a), field)))

    def GT_GetKp(self, axis):
        """(rtn, Kp as set) (L4455)."""
        return self._get_law(axis, "kp")

    def GT_GetKi(self, axis):
        """(rtn, Ki as set) (L4443)."""
        return self._get_law(axis, "ki")

    def GT_GetKd(self, axis):
        """(rtn, Kd as set) (L4431)."""
        return self._get_law(axis, "kd")

    def GT_GetKvff(self, axis):
        """(rtn, Kvff as set) (L4498)."""
        return self._get_law(axis, "kvff")

    def GT_GetKaff(self, axis):
        """(rtn, Kaff as set) (L4419)."""
        return self._get_law(axis, "kaff")

    def GT_GetILmt(self, axis):
        """(rtn, integral limit as set) (L4383)."""
        return self._get_law(axis, "ilmt", int)

    def GT_GetMtrLmt(self, axis):
        """(rtn, output saturation as set, counts) (L4610)."""
        return self._get_law(axis, "mtr_lmt", int)

    def GT_GetMtrBias(self, axis):
        """(rtn, bias as set, counts) (L4588)."""
        return self._get_law(axis, "bias", int)

    def GT_GetPosErr(self, axis):
        """(rtn, following-error limit as set, pulse) (L4663)."""
        return self._read(axis, lambda a: int(self._card.staged(a)["pos_err"]))

    def GT_GetIntgr(self, axis):
        """(rtn, error integral, as a short) (L4395-4405)."""
        return self._read(axis, lambda a: int(max(-32768, min(32767, round(self._card.integral(a))))))

    # -- 7.6 status -------------------------------------------------------------------------------------------
    def GT_GetSts(self, axis):
        """(rtn, axis status): PX 32 bits (Table 4-3 L902-932), SX 16 bits (Table 4-2 L879-900)."""
        return self._read(axis, lambda a: _core.ge_axis_status(self._card._card, a, self.variant))

    def GT_ClrSts(self, axis) -> int:
        """Clears status bits 0-7 (bit 4 stays while the error persists) (L3895-3899)."""
        return self._axis_cmd(axis, lambda a: self._card.clear_events(a, _core.ge_events_to_clear(0)))

    def GT_RstSts(self, axis, mask) -> int:
        """Clears the status bits 0-7 whose mask bit is 0; a 1 keeps the bit (L5423-5431)."""
        return self._axis_cmd(axis, lambda a: self._card.clear_events(a, _core.ge_events_to_clear(int(mask))),
                              _int_in(mask, 0, 0xFFFF))

    # -- 7.7 capture ------------------------------------------------------------------------------------------
    def GT_CaptHome(self, axis) -> int:
        """Arms a one-shot capture of the actual position on the Home edge (status bit 14; bit 3 on capture);
        re-arming before a capture or before GT_ClrSts is refused (cmd bit 5) (L3802-3812, L2334-2336)."""
        return self._axis_cmd(axis, lambda a: self._card.arm_capture(a, "home"))

    def GT_CaptIndex(self, axis) -> int:
        """Arms a one-shot capture on the encoder index (status bit 15) (L3814-3826)."""
        return self._axis_cmd(axis, lambda a: self._card.arm_capture(a, "index"))

    def GT_CaptProb(self) -> int:
        """Arms every axis's capture on the probe input EXI0, one shot; bit 3 of all axes on the edge
        (L3828-3862). PX and SX (the command is "for all GT series cards", V92)."""
        if self._card is None:
            return RTN_COMM_ERROR
        return self._do(self._card.arm_probe)

    def GT_GetCapt(self, axis):
        """(rtn, captured actual position, pulse); holds until the next capture (L4243-4251)."""
        return self._read(axis, lambda a: int(round(self._card.capture_value(a))))

    # -- 6.6 data watch (dialects/_ge_watch.py on the card's sampler; L2464-2884, decisions V73-V75) --------------
    def GT_SetWatch(self, config, size) -> int:
        """``GT_SetWatch(config[AXIS_NUM], size)``: config[k] the watched signals of axis k+1 (bit 0 profile
        position, 1 actual position, 2 profile velocity, 3 actual velocity, 6 control voltage), ``size`` samples
        per block; 7 when the block is too large for the watch memory or a reserved bit is set (L2786-2793)."""
        return _ge_watch.GT_SetWatch(self, config, size)

    def GT_StartWatch(self, n=0) -> int:
        """``GT_StartWatch(n)``: one sample every n+1 control periods (0: every period, L2558-2559, L2880)."""
        return _ge_watch.GT_StartWatch(self, n)

    def GT_GetWatch(self, buffer):
        """``GT_GetWatch(&buffer, &available)`` -> ``(rtn, available)``: 1 when a full block of ``size`` samples
        was copied into the arrays attached to ``buffer`` (:class:`TWatchBuffer`), oldest block first
        (L2836-2870)."""
        return _ge_watch.GT_GetWatch(self, buffer)

    def GT_StopWatch(self) -> int:
        """``GT_StopWatch()``: stops the watch."""
        return _ge_watch.GT_StopWatch(self)

    # -- 7.8 digital I/O --------------------------------------------------------------------------------------
    def GT_ExInpt(self):
        """(rtn, EXI0..EXI15 levels, bit n = EXIn) (L4074); the simulated levels of ``set_inputs``."""
        return self._get(lambda: self._slot.inputs)

    def GT_ExOpt(self, value) -> int:
        """Writes EXO0..EXO15, bit n = EXOn (L4094-4118)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(value, 0, 0xFFFF):
            return self._param(-1)
        self._slot.outputs = int(value)
        return RTN_SUCCESS

    def GT_GetLmtSwt(self):
        """(rtn, limit input levels): bit 2k Limit k+ (axis k+1), 2k+1 Limit k-; 1 = high = the switch is hit
        with the default normally-closed wiring, whatever LmtSns says (L2448-2456, L4510-4552; as GT V21)."""
        def levels():
            w = 0
            for k in range(self.axes):
                lim = self._card.limits(k)
                w |= int(self._card.pos_limit_input(k) != lim.pos_active_low) << (2 * k)
                w |= int(self._card.neg_limit_input(k) != lim.neg_active_low) << (2 * k + 1)
            return w

        return self._get(levels)

    def GT_GetHomeSwt(self):
        """(rtn, Home input levels): bit k = Home k (axis k+1), 1 = high = the axis is inside its home switch
        (V97) (L2458-2460, L4341-4381)."""
        def levels():
            w = 0
            for k in range(self.axes):
                ax = self._card.axes[k]
                sw, angle = ax.switches, ax.load_angle_rad
                w |= int(sw.home_min_rad <= angle <= sw.home_max_rad) << k
            return w

        return self._get(levels)

    # -- not simulated (documented in docs/card.md) ------------------------------------------------------------
    def GT_GetAdc(self, channel):
        """(1, 0): the analog inputs are not simulated (L4132-4142)."""
        return self._not_simulated(read=True)

    def GT_SetAdcChn(self, channel) -> int:
        """Returns 1: the analog inputs are not simulated (SX, L5447-5455)."""
        return self._not_simulated()

    def GT_SetSpindleVel(self, vel) -> int:
        """Returns 1: the spindle DAC is not simulated (SV, L5724-5734)."""
        return self._not_simulated()

    def GT_CloseSpindle(self) -> int:
        """Returns 1: the spindle DAC is not simulated (SV, L3885-3893)."""
        return self._not_simulated()

    def GT_HandWheel(self, axis, ratio) -> int:
        """Returns 1: the handwheel is not simulated (SX, L4839-4853)."""
        return self._not_simulated()

    def GT_ExitHWheel(self) -> int:
        """Returns 1: the handwheel is not simulated (SX, L4086-4092)."""
        return self._not_simulated()

    def GT_EncPos(self, encoder):
        """(1, 0): the auxiliary encoder is not simulated (SX, L4002-4023)."""
        return self._not_simulated(read=True)


for _name in [n for n in vars(GeController) if n.startswith("GT_") and n != "GT_HookCommand"]:
    setattr(GeController, _name, _command(_name, vars(GeController)[_name]))
del _name

_default = GeController()
GE_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "GT_")


def delay(ms: float):
    """The manual's ``delay(ms)``: runs the open card for ``ms`` milliseconds (rounded to whole ticks)."""
    return _default.delay(ms)


__all__ = ["GeController", "GE_FUNCTIONS", "RTN_COMMAND_ERROR", "RTN_COMM_ERROR", "RTN_PARAMETER_ERROR",
           "RTN_REENTERED", "RTN_SUCCESS", "TAxis", "TWatchBuffer", "card", "controller", "delay", "run", "wait_until",
           *GE_FUNCTIONS]
