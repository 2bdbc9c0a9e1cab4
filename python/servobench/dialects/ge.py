"""The Googol GE series programming interface (GE manual, seed 001) on the virtual :class:`~servobench.Card`.

Explicit-axis style as in the GE manual: every per-axis command takes the axis first, numbered from 1
(``GT_SetKp(axis, kp)``, ``GT_GetSts(axis)``). Two card variants (L99-103): ``"PX"`` (point to point, -PV/-PG,
4 or 8 axes, 32-bit axis status) and ``"SX"`` (continuous path, -SV/-SG, 4 axes, 16-bit axis status, the path
commands, buffer and look-ahead modules A and B on the card's GE coordinate system; ``TLookAheadMsg``). Units are the manual's (L991-996): pulse,
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
from typing import TYPE_CHECKING, Any
import threading

from .. import _core, card_io
from .._core import CardCommandRefused, MotionCommandRefused
from ..card import Card
from . import _ge_watch

from ._ge_watch import TAxis, TWatchBuffer  # noqa: F401 (the manual's watch structures)
from ._controller import DialectController, _wrap_vendor_methods, export_functions, register32, wrap32  # noqa: F401

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
    "GT_GetMode", "GT_GetPrfPos", "GT_GetAtlVel", "GT_GetAtlErr", "GT_CloseLp", "GT_OpenLp",
    "GT_SetMtrCmd", "GT_GetMtrCmd", "GT_AuStpOn", "GT_AuStpOff", "GT_IndexSns"})
# Commands of the SX set only: on a PX card they return 1 (Table 2-3 has no bit for it).
_SX_ONLY = frozenset({"GT_EncPos", "GT_HandWheel", "GT_ExitHWheel", "GT_SetAdcChn", "GT_SetSpindleVel",
                      "GT_CloseSpindle",
                      # [sx-path] path motion, buffer and look-ahead (ch11 Table 11-2, GE §6)
                      "GT_LnXY", "GT_LnXYZ", "GT_LnXYZA", "GT_LnXYG0", "GT_LnXYZG0", "GT_LnXYZAG0", "GT_ArcXY",
                      "GT_ArcYZ", "GT_ArcZX", "GT_ArcXYP", "GT_ArcYZP", "GT_ArcZXP", "GT_SetSynVel", "GT_SetSynAcc",
                      "GT_SetStrtVel", "GT_SetMaxVel", "GT_SetStpAcc", "GT_Override", "GT_OverrideG0",
                      "GT_SetDccVel", "GT_MapCnt", "GT_StrtList", "GT_MvXY", "GT_MvXYZ", "GT_MvXYZA", "GT_EndList",
                      "GT_AddList", "GT_StrtMtn", "GT_StpMtn", "GT_EStpMtn", "GT_RestoreMtn", "GT_BufIO",
                      "GT_BufIOBit", "GT_Delay", "GT_GetCrdSts", "GT_GetPrfPnt", "GT_GetSegPnt", "GT_GetBrkPnt",
                      "GT_GetMtnNm", "GT_InitLookAhead", "GT_AddLookData", "GT_CalVel", "GT_InitLookAheadEx",
                      "GT_InitLookAheadExx", "GT_MvXYEx", "GT_MvXYZEx", "GT_LnXYEx", "GT_LnXYZEx", "GT_LnXYG0Ex",
                      "GT_LnXYZG0Ex", "GT_ArcXYEx", "GT_ArcYZEx", "GT_ArcZXEx", "GT_ArcXYPEx", "GT_ArcYZPEx",
                      "GT_ArcZXPEx", "GT_BufIOEx", "GT_BufIOBitEx", "GT_DelayEx", "GT_M30"})
# Commands whose C form writes through pointers: (rtn, value) in Python (also every GT_Get*).
_READS = frozenset({"GT_ExInpt", "GT_GetLmtSwt", "GT_GetHomeSwt", "GT_GetCmdSts", "GT_EncPos", "GT_CalVel"})


def _int_in(value, lo, hi) -> bool:
    v = _num(value)
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


def _real_in(value, lo, hi) -> bool:
    v = _num(value)
    return math.isfinite(v) and lo <= v <= hi


def _num(value) -> float:
    """A manual argument as the double the checks and the C++ vendor modules take: a bool or a non-number is NaN
    (outside every range, so the card answers with the manual's code for a bad value)."""
    if isinstance(value, bool):
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def _nums(*values) -> list[float]:
    return [_num(v) for v in values]


class TLookAheadMsg:
    """The Ex commands' message (L5147-5169): mtnNum the CodeNum where an error occurred, num how many commands
    before it were not sent, error 0 none, 1 point equals the previous one, 3 buffer full (re-send), 8 sending
    the motion command failed (here: no InitLookAheadEx / MvXYEx, or a bad argument). The manual's struct."""

    def __init__(self):
        self.mtnNum, self.num, self.error = 0, 0, 0

    def __repr__(self):
        return f"TLookAheadMsg(mtnNum={self.mtnNum}, num={self.num}, error={self.error})"


class _Slot:
    """One open card: the handle and its ISA address (its GE state is the card's modules, ge_registers/ge_list)."""

    def __init__(self, card: Card, address: int):
        self.card = card
        self.address = address


def _command(name: str, fn):
    """Wraps a GT_* method: variant command set, re-entry (-3), and the GT_HookCommand callback."""
    read = _is_read(name)

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


def _is_read(name: str) -> bool:
    """A command whose C form writes through pointers: it returns (rtn, value...) in Python."""
    return name in _READS or name.startswith("GT_Get") and name != "GT_GetCurrentCardNo"


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

    if TYPE_CHECKING:  # the GT_* methods are made from the rows (_ROWS) after the class statement
        def __getattr__(self, name: str) -> Any: ...

    # -- plumbing: the card handle and the one-line adapters' helpers ----------------------------------------------
    @property
    def _slot(self) -> _Slot | None:
        return self._slots.get(self._current)

    def _sync(self):
        slot = self._slot
        self._card = slot.card if slot is not None else None

    def _regs(self):
        """The card's GE registers module (vendor/googol/ge_registers.hpp)."""
        return _core.ge_registers(self._card.kernel)

    def _ax(self, axis):
        """0-based axis, or None after recording an illegal parameter (bad axis number)."""
        if _int_in(axis, 1, self.axes):
            return int(axis) - 1
        self._card.record_fault(-1, "illegal_control_param")
        return None

    def _do(self, fn, *args) -> int:
        """fn(*args): 1 when the card refuses it (the cause is recorded), 7 for a bad value, else 0."""
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
            return self._param(a, fault)
        return self._do(fn, a)

    def _card_cmd(self, fn, ok=True) -> int:
        """Card command: -1 without a card, 7 for `ok` False (recording an illegal parameter), else fn()."""
        if self._card is None:
            return RTN_COMM_ERROR
        return self._do(fn) if ok else self._param(-1)

    def _refuse(self, a, fault):
        """A command the card ignores in this state: records `fault` (axis bit 7, GT_GetCmdSts) and raises the
        card's refusal (1 through _do; the code is the exception's type, never its text)."""
        self._card.record_fault(a, fault)
        raise CardCommandRefused(f"axis {a + 1}: refused ({fault})")

    def _param(self, a, fault="illegal_control_param") -> int:
        self._card.record_fault(a, fault)
        return RTN_PARAMETER_ERROR

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

    def _ge(self, call):
        """A command of the GE registers module: -1 without a card, else its code."""
        return RTN_COMM_ERROR if self._card is None else call(self._regs())

    def _motion(self, axis, register, value, lo, hi) -> int:
        """GT_SetVel/Acc/MAcc/Jerk: `value` in GE units (pulse/ms^order), staged per tick (on Update)."""
        return self._axis_cmd(axis, lambda a: self._regs().stage_motion(a, register, float(value), self._k),
                              _real_in(value, lo, hi), "motion_param_overflow")

    def _law(self, a):
        return self._card.staged(a)["law"]

    def _set_law(self, axis, field, value, ok) -> int:
        def apply(a):
            if self._regs().refuse_on_pulse_axis(a):  # a servo command on a pulse axis (SX cmd bit 6, L333)
                raise CardCommandRefused(f"axis {a + 1}: a servo-law command on a pulse axis")
            self._card.stage_law(a, self._law(a).replace(fractional_gains=True, **{field: float(value)}))

        return self._axis_cmd(axis, apply, ok)

    def _get_law(self, axis, field, cast=float):
        return self._read(axis, lambda a: cast(getattr(self._law(a), field)))

    def _axis_on(self, a):
        self._card.axis_on(a)
        if not self._card.moving(a):
            self._card.synch_pos_now(a)

    def _alarm(self, a, on):
        if self.variant == "SX" and self._card.servo_on(a):   # SX: illegal with the servo on (cmd bit 3)
            self._refuse(a, "motor_state_while_enabled")
        self._card.set_alarm_enabled(a, on)

    def _loop(self, a, closed):
        if self._card.servo_on(a):
            self._refuse(a, "axis_state_error")
        self._card.set_closed_loop(a, closed)

    def _leave_crd(self, a):
        """[sx-path] ZeroPos / SetAtlPos on an SX crd axis at rest: the crd is rebuilt by the next path command
        (Example 7-1 L2190; V112; GeList::leave_crd)."""
        if self.variant == "SX":
            _core.ge_list(self._card.kernel).leave_crd(a)

    def _atl_pos(self, a):
        on = self._regs().encoder_on(a)
        return register32(self._card.actual_pos(a) if on else self._card.profile_pos(a))

    def _set_vel(self, axis, vel) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        a = self._ax(axis)
        if a is None:
            return RTN_PARAMETER_ERROR
        lo = _VEL_MIN_JOG if self._card.mode(a) == "jog" else 0
        return self._motion(axis, "vel", vel, lo, _VEL_MAX)

    def _adc(self, channel):
        rate = 4000.0 if self.variant == "PX" else 770.0 * 8 / self._regs().adc_channels()
        t = math.floor(self._card.tick * self._card.servo_period_s * rate) / rate
        v = card_io.of(self._card).volts(int(channel) - 1, t)
        return RTN_SUCCESS, max(-2048, min(2047, math.floor(v / 10.0 * 2048)))

    def _aux_encoder(self, encoder):
        enc = card_io.of(self._card).aux_encoders[int(encoder) - 1]
        return RTN_SUCCESS, 0 if enc is None else enc.counts(self._card.tick * self._card.servo_period_s)

    def _sx(self, call, read=False):
        """A command of the card's GE list module (vendor/googol/ge_list.hpp): -1 without a card, else its code."""
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        return call(_core.ge_list(self._card.kernel))

    def _ex(self, pMsg, call) -> int:
        """An Ex command filling ``pMsg`` (a :class:`TLookAheadMsg`, or a scratch one) as the card does."""
        if self._card is None:
            return RTN_COMM_ERROR
        m = pMsg if pMsg is not None else TLookAheadMsg()
        rtn, (m.mtnNum, m.num, m.error) = call(_core.ge_list(self._card.kernel), (m.mtnNum, m.num, m.error))
        return rtn

    # -- simulation helpers -----------------------------------------------------------------------------------
    def delay(self, ms: float):
        """The manual's ``delay(ms)``: runs the card for ``ms`` milliseconds (rounded to whole ticks)."""
        return self.run_ms(ms)

    def set_inputs(self, bits: int):
        """Sets the simulated levels of the general inputs EXI0..EXI15 (bit n = EXIn; 1 = high) that
        ``GT_ExInpt`` reads. (The probe edge of EXI0 for ``GT_CaptProb`` is ``set_probe_time``.)"""
        if not _int_in(bits, 0, 0xFFFF):
            raise ValueError(f"set_inputs.bits = {bits} is outside the allowed range 0..65535 (16 inputs)")
        self._regs().set_inputs(int(bits))

    def outputs(self) -> int:
        """The general outputs EXO0..EXO15 as last written by ``GT_ExOpt`` or, on SX, by the path buffer's
        BufIO / BufIOBit when it executed them later (bit n = EXOn)."""
        return _core.ge_list(self._card.kernel).outputs()

    def set_probe_time(self, t_s: float | None):
        """The simulated probe edge on EXI0 at time ``t_s`` (s, the axes' clock tick * Ts, 0..1e9; None: never)."""
        self._card.set_probe_time(None if t_s is None else float(t_s))

    # -- 7.1 system -------------------------------------------------------------------------------------------
    def GT_Open(self, address=65535, card: Card | None = None, **axis_parts) -> int:
        """Opens the next card (L5313-5321; a second call opens the next one, L4310-4315) and makes it current:
        ``card`` (or a :class:`~servobench.Card` as the first argument), the machine :meth:`use_machine` set, or a
        new one built from ``axis_parts``
        (GE reset defaults: gains 0). ``address``: the ISA base address (e.g. 0x300) or 65535 for PCI, recorded.
        Returns -1 when 16 cards are open."""
        if isinstance(address, Card):
            address, card = 65535, address
        if card is None and not axis_parts:
            card = self._machine_card()  # the machine use_machine set (a program's plain GT_Open(), issue 25.2)
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
        _core.ge_registers(card.kernel).reset()  # the GE registers and path list of a card a program opens
        _core.ge_list(card.kernel).reset()
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
        self._card.reset()   # the card's modules (GE registers, list) reset with it
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

    def GT_GetPrfVel(self, *axis):
        """PX ``GT_GetPrfVel(axis)``: (rtn, profile velocity of the axis, pulse/ms) (L4713). SX
        ``GT_GetPrfVel()``: (rtn, path feed velocity, pulse/ms) (L4725-4733)."""
        if self.variant == "PX":
            if len(axis) != 1:
                return RTN_PARAMETER_ERROR, 0
            return self._read(axis[0], lambda a: self._card.profile_vel(a) / self._k)
        return self._sx(lambda L: (RTN_PARAMETER_ERROR, 0) if axis else (RTN_SUCCESS, L.prf_vel()), read=True)


def _adapter(name: str, params: str, body, doc: str):
    """The GeController method ``name(self, <params>)``: one call of ``body(self, <params>)``, with the row's
    docstring (what it does, units, the manual's lines) and the manual's return (``-> int``, or a tuple for a
    read). The parameter names and defaults are the manual's (programs call them by keyword too)."""
    names = ", ".join(p.split("=")[0].strip() for p in params.split(",") if p.strip())
    sep = ", " if params else ""
    namespace = {"_body": body}
    exec(f"def {name}(self{sep}{params}):\n    return _body(self{sep}{names})\n", namespace)  # noqa: S102
    fn = namespace[name]
    fn.__doc__, fn.__qualname__, fn.__module__ = doc, f"GeController.{name}", __name__
    fn.__annotations__ = {} if _is_read(name) else {"return": "int"}
    return fn


_P = "pMsg=None"  # the Ex commands' last parameter (TLookAheadMsg*)
# The GE commands as rows: (manual name, parameters, adapter, what the manual says: units and lines).
_ROWS = (
    # -- 7.1 system ---------------------------------------------------------------------------------------------
    ("GT_GetCmdSts", "", lambda c: c._get(lambda: _core.ge_command_status(c._card.kernel, c.variant)),
     "(rtn, command-error register): PX Table 2-3 (L301-322), SX Table 2-4 (L324-347); the bit of the last refused "
     "command's cause (decision V90; a path refusal's bit 6/8/9/15, V100)."),
    # -- 7.2 axis configuration ---------------------------------------------------------------------------------
    ("GT_AxisOn", "axis", lambda c, axis: c._axis_cmd(axis, c._axis_on),
     "Servo on; target and profile positions take the actual position (L3716-3720); refused while the "
     "drive-alarm bit is set (PX cmd bit 9, SX bit 3)."),
    ("GT_AxisOff", "axis", lambda c, axis: c._axis_cmd(axis, c._card.axis_off), "Servo off (L3704)."),
    ("GT_DrvRst", "axis", lambda c, axis: c._axis_cmd(axis, c._card.drive_reset),
     "Pulses the drive-reset output; only with the servo off (cmd bit 3) (L3954-3980)."),
    ("GT_AlarmOn", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._alarm(a, True)),
     "Drive-alarm input monitored (default on -XV) (L3408); SX: illegal with the servo on (cmd bit 3)."),
    ("GT_AlarmOff", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._alarm(a, False)),
     "Drive-alarm input ignored (L3396); SX: illegal with the servo on (cmd bit 3)."),
    ("GT_LmtsOn", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_limits(
        a, c._card.limits(a).replace(enabled=True))), "Limit switches stop the axis (default; status bit 11) (L4921)."),
    ("GT_LmtsOff", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_limits(
        a, c._card.limits(a).replace(enabled=False))),
     "Limit switches ignored (still readable by GT_GetLmtSwt) (L4909)."),
    ("GT_LmtSns", "sense", lambda c, sense: c._ge(lambda r: r.set_sense("limit", _num(sense))),
     "Limit polarity, all axes: bit 2k axis k+1 positive, 2k+1 negative; 0 triggers on a high level (default), 1 "
     "on a low level (Table 3-3 L516-520, L4897-4907)."),
    ("GT_HomeSns", "sense", lambda c, sense: c._ge(lambda r: r.set_sense("home", _num(sense))),
     "Home capture edge, bit k = axis k+1: 0 falling (default) = the simulated edge where the axis enters the home "
     "switch; 1 rising: not simulated, returns 1 (L524-534, L4809-4837, V93)."),
    ("GT_IndexSns", "sense", lambda c, sense: c._ge(lambda r: r.set_sense("index", _num(sense))),
     "Index capture edge (PX; bit meaning not given, L4869-4877): 0 accepted, a set bit returns 1 (V93)."),
    ("GT_EncSns", "sense", lambda c, sense: c._ge(lambda r: r.set_sense("encoder", _num(sense))),
     "Encoder count direction, bit k = axis k+1, 1 = reversed (L535-547, L4025-4035). The simulated encoder counts "
     "the drive's positive direction as positive: 0 bits accepted, a set bit returns 1 (V93)."),
    ("GT_EncOn", "axis", lambda c, axis: c._ge(lambda r: r.set_encoder(_num(axis), True)),
     "Encoder input on (default); illegal with the servo on (SX cmd bit 3) (L3992-4000)."),
    ("GT_EncOff", "axis", lambda c, axis: c._ge(lambda r: r.set_encoder(_num(axis), False)),
     "Encoder input off: GT_GetAtlPos reads the profile position (L3982, L4180); illegal with the servo on."),
    ("GT_CtrlMode", "axis, mode", lambda c, axis, mode: c._ge(lambda r: r.set_ctrl_mode(_num(axis), _num(mode))),
     "Output type: 0 analog voltage (default), 1 pulse (L3907-3925); illegal with the servo on (SX cmd bit 6). The "
     "simulated output is the axis's drive (StepperDrive / ServoPositionDrive take pulses): a mode that does not "
     "match it returns 1 (not simulated, V94)."),
    ("GT_StepDir", "axis", lambda c, axis: c._ge(lambda r: r.set_step_form(_num(axis), False)),
     "Pulse + direction output (default) (L5805); only on a pulse axis (SX cmd bit 6). Recorded: the simulated "
     "pulse drive counts the pulses whatever their electrical form (V94)."),
    ("GT_StepPulse", "axis", lambda c, axis: c._ge(lambda r: r.set_step_form(_num(axis), True)),
     "CW/CCW pulse output (L5840); only on a pulse axis (SX cmd bit 6). Recorded (V94)."),
    ("GT_CloseLp", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._loop(a, True)),
     "Closed loop (default; PX status bit 8) (L3875-3883); the servo must be off (else rtn 1)."),
    ("GT_OpenLp", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._loop(a, False)),
     "Open loop: the output is GT_SetMtrCmd (L5325-5340); the servo must be off (else rtn 1)."),
    ("GT_SetMtrCmd", "axis, vol", lambda c, axis, vol: c._axis_cmd(
        axis, lambda a: c._card.set_mtr_cmd(a, float(max(int(vol), -32767))), _int_in(vol, -32768, 32767)),
     "Open-loop output, DAC counts -32768..32767 (-32768 is driven as -32767, V95) (L5664-5686)."),
    ("GT_GetMtrCmd", "axis", lambda c, axis: c._read(axis, lambda a: int(c._card.mtr_cmd(a))),
     "(rtn, open-loop output, counts) (L4600-4606)."),
    ("GT_AuStpOn", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_auto_stop(a, True)),
     "A following error stops the axis abruptly and turns the servo off (mode bit 7) (L3678-3686, L2362)."),
    ("GT_AuStpOff", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_auto_stop(a, False)),
     "A following error only sets status bit 4 (default) (L3666)."),
    # -- 7.3 point-to-point profile (PX) ------------------------------------------------------------------------
    ("GT_PrflT", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_mode(a, "t_curve")),
     "Trapezoid mode (L5376); only at rest (else rtn 1, cmd bit 6)."),
    ("GT_PrflS", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_mode(a, "s_curve")),
     "S-curve mode (L5364); only at rest (cmd bit 6)."),
    ("GT_PrflV", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.set_mode(a, "jog")),
     "Velocity mode (L5388); only at rest (cmd bit 6)."),
    ("GT_SetPos", "axis, pos", lambda c, axis, pos: c._axis_cmd(
        axis, lambda a: c._card.stage_pos(a, float(pos)), _int_in(pos, _POS_MIN, _POS_MAX), "motion_param_overflow"),
     "Target position, whole pulses -2^30..2^30-1 (on Update) (L5700)."),
    ("GT_GetPos", "axis", lambda c, axis: c._read(axis, lambda a: int(c._card.staged(a)["pos"])),
     "(rtn, target position as set, pulse) (L4622)."),
    ("GT_SetVel", "axis, vel", lambda c, axis, vel: c._set_vel(axis, vel),
     "Velocity, pulse/ms: 0..40957 (T, S), -40958..40957 in velocity mode (on Update) (L5780-5786)."),
    ("GT_GetVel", "axis", lambda c, axis: c._read(axis, lambda a: c._regs().read_motion(a, "vel", c._k)),
     "(rtn, velocity as set, pulse/ms) (L4757)."),
    ("GT_SetAcc", "axis, acc", lambda c, axis, acc: c._motion(axis, "acc", acc, 0, _ACC_MAX),
     "Acceleration, pulse/ms^2, 0..102400; used by trapezoid and velocity modes (on Update) (L5435-5437)."),
    ("GT_GetAcc", "axis", lambda c, axis: c._read(axis, lambda a: c._regs().read_motion(a, "acc", c._k)),
     "(rtn, acceleration as set, pulse/ms^2) (L4120)."),
    ("GT_SetMAcc", "axis, macc", lambda c, axis, macc: c._motion(axis, "macc", macc, 0, _ACC_MAX),
     "S-curve maximum acceleration, pulse/ms^2, 0..102400 (on Update) (L5626-5628)."),
    ("GT_GetMAcc", "axis", lambda c, axis: c._read(axis, lambda a: c._regs().read_motion(a, "macc", c._k)),
     "(rtn, S-curve maximum acceleration as set, pulse/ms^2) (L4554)."),
    ("GT_SetJerk", "axis, jerk", lambda c, axis, jerk: c._motion(axis, "jerk", jerk, 0, _JERK_MAX),
     "S-curve jerk, pulse/ms^3, 0..256000 (on Update) (L5518-5520)."),
    ("GT_GetJerk", "axis", lambda c, axis: c._read(axis, lambda a: c._regs().read_motion(a, "jerk", c._k)),
     "(rtn, jerk as set, pulse/ms^3) (L4407)."),
    ("GT_Update", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.update(1 << a)),
     "Makes the axis's Set* parameters (Table 5-6 L1280-1296) effective at the next servo tick (L5895); refused as "
     "a whole when a parameter may not change now (cmd bit 11) or is zero (cmd bit 1)."),
    ("GT_MltiUpdt", "mask", lambda c, mask: c._card_cmd(lambda: c._card.update(int(mask) & ((1 << c.axes) - 1)),
                                                        _int_in(mask, 0, 0xFFFF)),
     "As GT_Update for the axes of ``mask`` (bit 0 = axis 1 ... bit 7 = axis 8), all in the same tick; mask 0 is an "
     "error (cmd bit 2) (L5189-5228)."),
    ("GT_SmthStp", "axis", lambda c, axis: c._axis_cmd(axis, c._card.smooth_stop),
     "Smooth stop at the mode's acceleration, at once (decision V91: immediate, L1310-1312 and Example 7-2; ch12 "
     "L5797 calls it update-effective)."),
    ("GT_AbptStp", "axis", lambda c, axis: c._axis_cmd(axis, c._card.abrupt_stop),
     "Abrupt stop: target and profile velocity 0 at once (L3307-3311, L1317)."),
    ("GT_GetMode", "axis", lambda c, axis: c._read(axis, lambda a: _core.ge_mode_register(c._card.kernel, a)),
     "(rtn, mode register) (Table 4-4 L938-945): bit 7 auto-stop; bits 13..11 000 T, 001 V, 010 S."),
    # -- 7.4 position, velocity and error feedback ---------------------------------------------------------------
    ("GT_ZeroPos", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: (c._leave_crd(a), c._card.zero_pos(a))),
     "Actual = target = profile = 0; at rest only (else rtn 1, cmd bit 11) (L5907-5913)."),
    ("GT_SetAtlPos", "axis, pos", lambda c, axis, pos: c._axis_cmd(
        axis, lambda a: (c._leave_crd(a), c._card.set_actual_pos(a, float(pos))), _int_in(pos, _POS_MIN, _POS_MAX),
        "motion_param_overflow"),
     "Actual = target = profile = ``pos``, whole pulses -2^30..2^30-1; at rest only (cmd bit 11) (L5457)."),
    ("GT_GetAtlPos", "axis", lambda c, axis: c._read(axis, c._atl_pos),
     "(rtn, actual position, pulse) (L4173); with the encoder off, the profile position (L4180)."),
    ("GT_GetPrfPos", "axis", lambda c, axis: c._read(axis, lambda a: register32(c._card.profile_pos(a))),
     "(rtn, profile position, pulse) (L4701)."),
    ("GT_GetAtlErr", "axis", lambda c, axis: c._read(axis, lambda a: int(round(c._card.following_error(a)))),
     "(rtn, following error profile - actual of the last tick, pulse) (L4144-4171)."),
    ("GT_GetAtlVel", "axis", lambda c, axis: c._read(axis, lambda a: c._regs().actual_vel(a)),
     "(rtn, actual velocity, pulse/ms): the encoder shaft's speed now in counts (V96) (L4203)."),
    # -- 7.5 servo parameters (XV; on Update) ---------------------------------------------------------------------
    ("GT_SetKp", "axis, kp", lambda c, axis, kp: c._set_law(axis, "kp", kp, _real_in(kp, 0, _GAIN_MAX)),
     "Proportional gain, double 0..32767 (L5566-5570)."),
    ("GT_SetKi", "axis, ki", lambda c, axis, ki: c._set_law(axis, "ki", ki, _real_in(ki, 0, _GAIN_MAX)),
     "Integral gain, double 0..32767 (term Ki * SumE / 256, V87) (L5554-5558)."),
    ("GT_SetKd", "axis, kd", lambda c, axis, kd: c._set_law(axis, "kd", kd, _real_in(kd, 0, _GAIN_MAX)),
     "Derivative gain, double 0..32767 (L5542-5546)."),
    ("GT_SetKvff", "axis, kvff", lambda c, axis, kvff: c._set_law(axis, "kvff", kvff, _real_in(kvff, 0, _GAIN_MAX)),
     "Velocity feed-forward, double 0..32767, on the profile velocity per tick (V87) (L5614-5618)."),
    ("GT_SetKaff", "axis, kaff", lambda c, axis, kaff: c._set_law(axis, "kaff", kaff, _real_in(kaff, 0, _GAIN_MAX)),
     "Acceleration feed-forward, double 0..32767, on the profile acceleration per tick^2 (V87) (L5530-5534)."),
    ("GT_SetILmt", "axis, ilmt", lambda c, axis, ilmt: c._set_law(axis, "ilmt", ilmt, _int_in(ilmt, 0, 32767)),
     "Integral limit 0..32767 (default 32767; 0 clears the integral) (L5504-5510)."),
    ("GT_SetMtrLmt", "axis, lmt", lambda c, axis, lmt: c._set_law(axis, "mtr_lmt", lmt, _int_in(lmt, 0, 32767)),
     "Output saturation, DAC counts 0..32767 (default 32767 = 10 V) (L5688-5692)."),
    ("GT_SetMtrBias", "axis, bias", lambda c, axis, bias: c._set_law(axis, "bias", bias,
                                                                     _int_in(bias, -32768, 32767)),
     "Zero-drift compensation, DAC counts -32768..32767 (L5648-5652)."),
    ("GT_SetPosErr", "axis, limit", lambda c, axis, limit: c._axis_cmd(
        axis, lambda a: c._card.stage_pos_err(a, float(limit)), _int_in(limit, 0, 32767)),
     "Following-error limit 0..32767 pulse (default 32767) (L5712-5716)."),
    ("GT_GetKp", "axis", lambda c, axis: c._get_law(axis, "kp"), "(rtn, Kp as set) (L4455)."),
    ("GT_GetKi", "axis", lambda c, axis: c._get_law(axis, "ki"), "(rtn, Ki as set) (L4443)."),
    ("GT_GetKd", "axis", lambda c, axis: c._get_law(axis, "kd"), "(rtn, Kd as set) (L4431)."),
    ("GT_GetKvff", "axis", lambda c, axis: c._get_law(axis, "kvff"), "(rtn, Kvff as set) (L4498)."),
    ("GT_GetKaff", "axis", lambda c, axis: c._get_law(axis, "kaff"), "(rtn, Kaff as set) (L4419)."),
    ("GT_GetILmt", "axis", lambda c, axis: c._get_law(axis, "ilmt", int), "(rtn, integral limit as set) (L4383)."),
    ("GT_GetMtrLmt", "axis", lambda c, axis: c._get_law(axis, "mtr_lmt", int),
     "(rtn, output saturation as set, counts) (L4610)."),
    ("GT_GetMtrBias", "axis", lambda c, axis: c._get_law(axis, "bias", int), "(rtn, bias as set, counts) (L4588)."),
    ("GT_GetPosErr", "axis", lambda c, axis: c._read(axis, lambda a: int(c._card.staged(a)["pos_err"])),
     "(rtn, following-error limit as set, pulse) (L4663)."),
    ("GT_GetIntgr", "axis", lambda c, axis: c._read(axis, lambda a: int(max(-32768, min(32767, round(
        c._card.integral(a)))))), "(rtn, error integral, as a short) (L4395-4405)."),
    # -- 7.6 status -----------------------------------------------------------------------------------------------
    ("GT_GetSts", "axis", lambda c, axis: c._read(axis, lambda a: _core.ge_axis_status(c._card.kernel, a, c.variant)),
     "(rtn, axis status): PX 32 bits (Table 4-3 L902-932), SX 16 bits (Table 4-2 L879-900)."),
    ("GT_ClrSts", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.clear_events(
        a, _core.ge_events_to_clear(0))),
     "Clears status bits 0-7 (bit 4 stays while the error persists) (L3895-3899)."),
    ("GT_RstSts", "axis, mask", lambda c, axis, mask: c._axis_cmd(axis, lambda a: c._card.clear_events(
        a, _core.ge_events_to_clear(int(mask))), _int_in(mask, 0, 0xFFFF)),
     "Clears the status bits 0-7 whose mask bit is 0; a 1 keeps the bit (L5423-5431)."),
    # -- 7.7 capture ----------------------------------------------------------------------------------------------
    ("GT_CaptHome", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.arm_capture(a, "home")),
     "Arms a one-shot capture of the actual position on the Home edge (status bit 14; bit 3 on capture); re-arming "
     "before a capture or before GT_ClrSts is refused (cmd bit 5) (L3802-3812, L2334-2336)."),
    ("GT_CaptIndex", "axis", lambda c, axis: c._axis_cmd(axis, lambda a: c._card.arm_capture(a, "index")),
     "Arms a one-shot capture on the encoder index (status bit 15) (L3814-3826)."),
    ("GT_CaptProb", "", lambda c: c._card_cmd(lambda: c._card.arm_probe()),
     "Arms every axis's capture on the probe input EXI0, one shot; bit 3 of all axes on the edge (L3828-3862). PX "
     "and SX (the command is \"for all GT series cards\", V92)."),
    ("GT_GetCapt", "axis", lambda c, axis: c._read(axis, lambda a: int(round(c._card.capture_value(a)))),
     "(rtn, captured actual position, pulse); holds until the next capture (L4243-4251)."),
    # -- 6.6 data watch (dialects/_ge_watch.py on the card's sampler; L2464-2884, decisions V73-V75) -------------
    ("GT_SetWatch", "config, size", lambda c, config, size: _ge_watch.GT_SetWatch(c, config, size),
     "``GT_SetWatch(config[AXIS_NUM], size)``: config[k] the watched signals of axis k+1 (bit 0 profile position, 1 "
     "actual position, 2 profile velocity, 3 actual velocity, 6 control voltage), ``size`` samples per block; 7 "
     "when the block is too large for the watch memory or a reserved bit is set (L2786-2793)."),
    ("GT_StartWatch", "n=0", lambda c, n: _ge_watch.GT_StartWatch(c, n),
     "``GT_StartWatch(n)``: one sample every n+1 control periods (0: every period, L2558-2559, L2880)."),
    ("GT_GetWatch", "buffer", lambda c, buffer: _ge_watch.GT_GetWatch(c, buffer),
     "``GT_GetWatch(&buffer, &available)`` -> ``(rtn, available)``: 1 when a full block of ``size`` samples was "
     "copied into the arrays attached to ``buffer`` (:class:`TWatchBuffer`), oldest block first (L2836-2870)."),
    ("GT_StopWatch", "", lambda c: _ge_watch.GT_StopWatch(c), "``GT_StopWatch()``: stops the watch."),
    # -- 7.8 digital I/O --------------------------------------------------------------------------------------------
    ("GT_ExInpt", "", lambda c: c._get(lambda: c._regs().inputs()),
     "(rtn, EXI0..EXI15 levels, bit n = EXIn) (L4074); the simulated levels of ``set_inputs``."),
    ("GT_ExOpt", "value", lambda c, value: c._card_cmd(lambda: _core.ge_list(c._card.kernel).set_outputs(int(value)),
                                                        _int_in(value, 0, 0xFFFF)),
     "Writes EXO0..EXO15, bit n = EXOn (L4094-4118)."),
    ("GT_GetLmtSwt", "", lambda c: c._get(lambda: c._regs().limit_levels()),
     "(rtn, limit input levels): bit 2k Limit k+ (axis k+1), 2k+1 Limit k-; 1 = high = the switch is hit with the "
     "default normally-closed wiring, whatever LmtSns says (L2448-2456, L4510-4552; as GT V21)."),
    ("GT_GetHomeSwt", "", lambda c: c._get(lambda: c._regs().home_levels()),
     "(rtn, Home input levels): bit k = Home k (axis k+1), 1 = high = the axis is inside its home switch (V97) "
     "(L2458-2460, L4341-4381)."),
    # -- [sx-path] path motion, buffer, look-ahead (SX; GE §6 L1393-2040, §12; ge.md §4, §7.9-7.11): one call each
    # into the card's GE list module (vendor/googol/ge_list.hpp; V100-V112, GV1-GV4), arguments as doubles.
    ("GT_LnXY", "x, y", lambda c, x, y: c._sx(lambda L: L.line(_nums(x, y), False)),
     "Line to the absolute point (x, y), pulse (L4946); the feed is SetSynVel (L1407). Returns 3 for a zero length "
     "or overflow (L280)."),
    ("GT_LnXYZ", "x, y, z", lambda c, *p: c._sx(lambda L: L.line(_nums(*p), False)), "3-D line, pulse (L4980)."),
    ("GT_LnXYZA", "x, y, z, a", lambda c, *p: c._sx(lambda L: L.line(_nums(*p), False)), "4-D line, pulse (L5010)."),
    ("GT_LnXYG0", "x, y", lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)),
     "Rapid line: a full profile from StrtVel to SynVel and back to rest, scaled by OverrideG0 (L1473-1477, L5036)."),
    ("GT_LnXYZG0", "x, y, z", lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)), "3-D rapid line (L5075)."),
    ("GT_LnXYZAG0", "x, y, z, a", lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)),
     "4-D rapid line (L5113; printed as GT_LnXYZG0(x,y,z,a) at L5115, V110)."),
    ("GT_ArcXY", "x_center, y_center, angle", lambda c, *p: c._sx(lambda L: L.arc_center("xy", *_nums(*p))),
     "Arc about the absolute centre by ``angle`` degrees in [-360, 360], + = CCW seen from +Z (L1481-1486, "
     "L3434-3443); the radius is the distance of the start point (2: radius 0)."),
    ("GT_ArcYZ", "y_center, z_center, angle", lambda c, *p: c._sx(lambda L: L.arc_center("yz", *_nums(*p))),
     "Arc in the YZ plane, seen from +X (L3519-3527)."),
    ("GT_ArcZX", "z_center, x_center, angle", lambda c, *p: c._sx(lambda L: L.arc_center("zx", *_nums(*p))),
     "Arc in the ZX plane, seen from +Y (L3593-3601)."),
    ("GT_ArcXYP", "x_end, y_end, r, direction", lambda c, *p: c._sx(lambda L: L.arc_radius("xy", *_nums(*p))),
     "Arc to the end point with signed radius: r > 0 the minor arc, r < 0 the major one; direction +1 CCW, -1 CW "
     "(L3477-3483). 2: radius or chord 0; 5: chord > diameter (L280-282)."),
    ("GT_ArcYZP", "y_end, z_end, r, direction", lambda c, *p: c._sx(lambda L: L.arc_radius("yz", *_nums(*p))),
     "YZ arc by end point and radius (L3555-3561)."),
    ("GT_ArcZXP", "z_end, x_end, r, direction", lambda c, *p: c._sx(lambda L: L.arc_radius("zx", *_nums(*p))),
     "ZX arc by end point and radius (L3628-3636)."),
    ("GT_SetSynVel", "vel", lambda c, vel: c._sx(lambda L: L.set_syn_vel(_num(vel))),
     "Path feed, pulse/ms, for the following lines and arcs; bufferable (L1407-1409, L5770-5778); 4 for <= 0."),
    ("GT_SetSynAcc", "acc", lambda c, acc: c._sx(lambda L: L.set_syn_acc(_num(acc))),
     "Path acceleration of immediate motion, pulse/ms^2; illegal in buffer mode (bit 8, L1411-1413, L335)."),
    ("GT_SetStrtVel", "vel", lambda c, vel: c._sx(lambda L: L.set_strt_vel(_num(vel))),
     "Start/stop velocity, pulse/ms (default 0.5 = 500 Hz, L1395-1399, L5748-5756); meant for the set-up."),
    ("GT_SetMaxVel", "vel", lambda c, vel: c._sx(lambda L: L.set_max_vel(_num(vel))),
     "Feed clamp, pulse/ms (default 256, L1401-1405, L5638-5644)."),
    ("GT_SetStpAcc", "acc", lambda c, acc: c._sx(lambda L: L.set_stp_acc(_num(acc))),
     "Deceleration of abnormal stops and GT_EStpMtn, pulse/ms^2 (L1415-1419, L5736-5744)."),
    ("GT_Override", "override", lambda c, override: c._sx(lambda L: L.set_override(_num(override), False)),
     "Feed multiplier of all path motion but G0 and Mv, on the running segment and all later ones; the result is "
     "clamped to MaxVel (L1952-1958, L5342-5352)."),
    ("GT_OverrideG0", "override", lambda c, override: c._sx(lambda L: L.set_override(_num(override), True)),
     "Multiplier of G0 lines and the Mv positioning (L5354-5362)."),
    ("GT_SetDccVel", "vel", lambda c, vel: c._sx(lambda L: L.set_dcc_vel(_num(vel))),
     "End velocity, pulse/ms, of the next buffered path segment (L5492-5500, L1679; V106). Buffer only."),
    ("GT_MapCnt", "axis, count", lambda c, *p: c._sx(lambda L: L.map_cnt(*_nums(*p))),
     "Work-coordinate offset of ``axis``, pulse: axis = coordinate + count (L1960-1971, L5179-5187); refused (bit "
     "6) while an axis moves, the buffer is open, or out of range."),
    ("GT_StrtList", "", lambda c: c._sx(lambda L: L.strt_list()),
     "Opens and clears the buffer (buffer input mode, segment number 0); refused (bit 9) while buffered motion has "
     "not stopped or the buffer is open (L1549, L5861-5865)."),
    ("GT_MvXY", "x, y, vel, acc", lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
     "Buffer start point (x, y) pulse, feed vel pulse/ms and acceleration acc pulse/ms^2 of the buffer "
     "(acceleration fixed); StrtMtn first goes there by a line that ends at rest (L1551-1555, L5232)."),
    ("GT_MvXYZ", "x, y, z, vel, acc", lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
     "3-D buffer start point (L5277)."),
    ("GT_MvXYZA", "x, y, z, a, vel, acc", lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
     "4-D buffer start point (L5291)."),
    ("GT_EndList", "", lambda c: c._sx(lambda L: L.end_list()),
     "Closes the buffer (only while open, else bit 9) (L1559-1571, L4037)."),
    ("GT_AddList", "", lambda c: c._sx(lambda L: L.add_list()),
     "Reopens a closed buffer; while open: bit 9 (L1559-1571, L3339)."),
    ("GT_StrtMtn", "", lambda c: c._sx(lambda L: L.strt_mtn()),
     "Runs the buffer: first the Mv line (ends at rest), then the segments; keeps executing while the host streams "
     "more until EndList (L1640-1646, L5871-5875). Bit 9 while path motion runs."),
    ("GT_StpMtn", "", lambda c: c._sx(lambda L: L.stp_mtn(False)),
     "Smooth path stop at the feed acceleration; closes the buffer, keeps the breakpoint (L1648-1654, L5852)."),
    ("GT_EStpMtn", "", lambda c: c._sx(lambda L: L.stp_mtn(True)),
     "Path stop at StpAcc (SetStpAcc; 0: at once); closes the buffer, keeps the breakpoint (L1648, L4064)."),
    ("GT_RestoreMtn", "", lambda c: c._sx(lambda L: L.restore_mtn()),
     "Resumes a stopped buffer: a line from the present point to the breakpoint ending at the start velocity, then "
     "the rest (L1656-1664, L5412). Bit 9 unless stopped with unexecuted segments."),
    ("GT_BufIO", "io_status", lambda c, io_status: c._sx(lambda L: L.buf_io(_num(io_status))),
     "Buffered write of all 16 outputs EXO0..15 between the previous segment's end and the next one's start; at "
     "most two between motion commands (L3750-3756). -1 in immediate mode."),
    ("GT_BufIOBit", "io_bit, bit_status", lambda c, *p: c._sx(lambda L: L.buf_io_bit(*_nums(*p))),
     "Buffered write of one output, effective with the next path segment; of two in a row the one nearest the path "
     "command wins (L3766-3776)."),
    ("GT_Delay", "delay_time", lambda c, delay_time: c._sx(lambda L: L.delay(_num(delay_time))),
     "Buffered dwell between two segments, ms (0 < t < 8192; V107); one between motion commands (L3944-3950)."),
    ("GT_GetCrdSts", "", lambda c: c._sx(lambda L: (RTN_SUCCESS, L.crd_status()), read=True),
     "(rtn, path status, 16 bits) (Table 4-5 L951-968): 0 no path motion (1 idle), 1 buffer closed, 4 segment "
     "completed, 7 immediate input mode, 9 an axis fault stopped the path, 13 buffer empty."),
    ("GT_GetPrfPnt", "", lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(0)), read=True),
     "(rtn, [X, Y, Z] profile point, pulse, work coordinates) (L4675-4699; three values, V108)."),
    ("GT_GetSegPnt", "", lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(1)), read=True),
     "(rtn, [X, Y, Z] end point of the executing segment, pulse) (L4735-4743): the tail when idle."),
    ("GT_GetBrkPnt", "", lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(2)), read=True),
     "(rtn, [X, Y, Z] breakpoint of the last buffered stop, pulse, or None) (L4233-4241)."),
    ("GT_GetMtnNm", "", lambda c: c._sx(lambda L: (RTN_SUCCESS, L.mtn_nm()), read=True),
     "(rtn, segment number): Mv = 0, path segments from 1; holds when the buffer runs dry, while stopped, after the "
     "last segment; StrtList clears it; wraps 32767 -> 1 (L2005-2017, L4578-4586; V109)."),
    # look-ahead module A (L1666-1727, Table 6-6; API L3370-3394, L3790-3800, L4879-4887)
    ("GT_InitLookAhead", "t, acc_max, acc, vel, n, con", lambda c, *p: c._sx(lambda L: L.init_look_ahead(*_nums(*p))),
     "Module A: corner time t s, acc_max and acc mm/s^2 (acc < acc_max), feed vel mm/s, n segments, con pulse/mm "
     "(L4879-4887). The path starts at the present profile point (in mm)."),
    ("GT_AddLookData", "code, plane_group, r, x, y, z, vel, cx, cy, i, n, flag",
     lambda c, code, plane_group, r, x, y, z, vel, cx, cy, i, n, flag: c._sx(lambda L: L.add_look_data(
         int(code), int(plane_group), *_nums(r, x, y, z, vel, cx, cy), int(n), bool(flag))),
     "Pushes one segment (mm, mm/s) to module A: code 0 G00, 1 G01, 2 G02 CW, 3 G03 CCW; plane_group 17 XY, 18 ZX, "
     "19 YZ; i the slot (not used: the module keeps its own order, V111), n the user number, flag: stop at its end. "
     "0 accepted, 1 the point equals the previous one (L3370-3394, Table 6-8 L1709-1724)."),
    ("GT_CalVel", "", lambda c: c._sx(lambda L: L.cal_vel()) if c._card is not None else (RTN_COMM_ERROR, 0.0, 0),
     "(rtn, end velocity mm/s, user number) of the oldest segment not yet returned: rtn 0 more follow, 1 it was the "
     "last (L3790-3800, L1725). Send the segment with GT_SetDccVel(vel * con / 1000)."),
    # look-ahead module B, the Ex family (Tables 6-9..6-12 L1729-1812; L5147-5177; V111)
    ("GT_InitLookAheadEx", "T, amax, am, n, con", lambda c, *p: c._sx(lambda L: L.init_look_ahead_ex(*_nums(*p))),
     "Module B: corner time T s, amax and am mm/s^2 (am < amax), n >= 200 look-ahead segments, con pulse/mm "
     "(L1729-1785, L4889-4895; also GT_InitLookAheadExx, V110)."),
    ("GT_InitLookAheadExx", "T, amax, am, n, con", lambda c, *p: c._sx(lambda L: L.init_look_ahead_ex(*_nums(*p))),
     "The name ch12 and Example 6-4 use for GT_InitLookAheadEx (L1856, L4889; V110)."),
    ("GT_MvXYEx", "x, y, vel", lambda c, *p: c._sx(lambda L: L.mv_ex(_nums(*p[:-1]), _num(p[-1]))),
     "Module B start point (x, y) mm at vel mm/s; right after StrtList (L1787-1789, L5269; printed as "
     "GT_MvXYZEx(x,y,vel) at L5271, V110)."),
    ("GT_MvXYZEx", "x, y, z, vel", lambda c, *p: c._sx(lambda L: L.mv_ex(_nums(*p[:-1]), _num(p[-1]))),
     "Module B 3-D start point, mm, mm/s (L5305)."),
    ("GT_LnXYEx", f"x, y, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(
        _nums(*p[:-4]), *_nums(*p[-4:-1]), False, m)),
     "Module B G01 line to (x, y) mm at F mm/s; dccFlag 1 stops at its end; CodeNum the user block number; pMsg a "
     "TLookAheadMsg filled on error (L4972, Table 6-12 L1803-1812)."),
    ("GT_LnXYZEx", f"x, y, z, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(
        _nums(*p[:-4]), *_nums(*p[-4:-1]), False, m)), "Module B 3-D G01 line, mm, mm/s (L5067)."),
    ("GT_LnXYG0Ex", f"x, y, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(
        _nums(*p[:-4]), *_nums(*p[-4:-1]), True, m)),
     "Module B G00 rapid to (x, y) mm (starts and ends at rest) (L5103)."),
    ("GT_LnXYZG0Ex", f"x, y, z, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(
        _nums(*p[:-4]), *_nums(*p[-4:-1]), True, m)), "Module B 3-D G00 rapid, mm (L5139)."),
    ("GT_ArcXYEx", f"x_center, y_center, angle, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_center_ex("xy", *_nums(*p[:-1]), m)),
     "Module B arc about the centre (mm) by angle degrees (> 0 CCW) (L3468)."),
    ("GT_ArcYZEx", f"y_center, z_center, angle, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_center_ex("yz", *_nums(*p[:-1]), m)), "Module B YZ arc, centre + angle (L3545)."),
    ("GT_ArcZXEx", f"z_center, x_center, angle, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_center_ex("zx", *_nums(*p[:-1]), m)),
     "Module B ZX arc, centre + angle (L3619; printed GT_ArcZYEx at L3621, V110)."),
    ("GT_ArcXYPEx", f"x_end, y_end, r, direction, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_radius_ex("xy", *_nums(*p[:-1]), m)),
     "Module B arc to the end point (mm), signed radius, direction 1 CCW / -1 CW (L3511)."),
    ("GT_ArcYZPEx", f"y_end, z_end, r, direction, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_radius_ex("yz", *_nums(*p[:-1]), m)),
     "Module B YZ arc by end point and radius (L3583)."),
    ("GT_ArcZXPEx", f"z_end, x_end, r, direction, F, dccFlag, CodeNum, {_P}", lambda c, *p: c._ex(
        p[-1], lambda L, m: L.arc_radius_ex("zx", *_nums(*p[:-1]), m)),
     "Module B ZX arc by end point and radius (L3658; printed with (y_end, z_end) at L3660, V110)."),
    ("GT_BufIOEx", "value", lambda c, value: c._sx(lambda L: L.buf_io_ex(_num(value))),
     "Module B buffered write of the 16 outputs, in order with the Ex motion commands (L3758-3762); -1 in "
     "immediate mode."),
    ("GT_BufIOBitEx", "io_bit, bit_status", lambda c, *p: c._sx(lambda L: L.buf_io_bit_ex(*_nums(*p))),
     "Module B buffered write of one output (L3778)."),
    ("GT_DelayEx", "time", lambda c, time: c._sx(lambda L: L.delay_ex(_num(time))),
     "Module B buffered dwell, ms, 0 < t < 8192 (Table 6-10 L1761; V107)."),
    ("GT_M30", _P, lambda c, pMsg: c._ex(pMsg, lambda L, m: L.m30(m)),
     "Flushes module B: moves the look-ahead window into the card buffer as space allows. 9 while commands remain "
     "(msg.error 3: the buffer is full; let the card run and call again), 0 when all are in; then GT_EndList "
     "(L1793-1795, L5171-5177)."),
    # -- analog inputs, spindle output, auxiliary encoders (ch10 L2890-3020; card_io) -----------------------------
    ("GT_GetAdc", "channel", lambda c, channel: (RTN_COMM_ERROR, 0) if c._card is None else (
        c._adc(channel) if _int_in(channel, 1, 8) else (c._param(-1), 0)),
     "(rtn, input voltage of channel 1..8 as 12-bit counts): +10 V = 2047, 0 V = 0, -10 V = -2048 (Table 10-4, "
     "L2930-2937), sampled at the last conversion: PX 4 kHz, SX 770 Hz x 8 / GT_SetAdcChn's channels (L2939-2943). "
     "The voltages are the machine's, ``card_io.of(card).adc_volts`` (L4132-4142)."),
    ("GT_SetAdcChn", "channel", lambda c, channel: c._ge(lambda r: r.set_adc_channels(_num(channel))),
     "Number of A/D channels converted, 1..8 (SX; default 8, decision GF7): fewer channels, faster sampling, one "
     "channel 8 x 770 Hz = 6.16 kHz (L5447-5455, L2941-2943)."),
    ("GT_SetSpindleVel", "vel", lambda c, vel: c._card_cmd(lambda: setattr(
        card_io.of(c._card), "spindle_volts", int(vel) * 10.0 / 32768), _int_in(vel, -32768, 32767)),
     "Spindle speed: the 16-bit spindle DAC, -32768..32767 for -10..+10 V, output from now on (SV, L5724-5734); the "
     "machine reads ``card_io.of(card).spindle_volts`` (V = vel x 10 / 32768)."),
    ("GT_CloseSpindle", "", lambda c: c._card_cmd(lambda: setattr(card_io.of(c._card), "spindle_volts", 0.0)),
     "Spindle output off: 0 V (SV, L3885-3893)."),
    ("GT_EncPos", "encoder", lambda c, encoder: (RTN_COMM_ERROR, 0) if c._card is None else (
        c._aux_encoder(encoder) if _int_in(encoder, 1, 2) else (c._param(-1), 0)),
     "(rtn, position of auxiliary encoder 1 or 2, pulse) (SX, L4002-4023): the machine's "
     "``card_io.of(card).aux_encoders`` (whole counts)."),
    # -- not simulated (UNSUPPORTED) --------------------------------------------------------------------------------
    ("GT_HandWheel", "axis, ratio", lambda c, axis, ratio: c._not_simulated(),
     "Returns 1: not simulated (UNSUPPORTED; SX, L4839-4853)."),
    ("GT_ExitHWheel", "", lambda c: c._not_simulated(), "Returns 1: not simulated (UNSUPPORTED; SX, L4086-4092)."),
    ("GT_Axis", "num", lambda c, num: c._not_simulated(), "Returns 1: not in the GE command set (UNSUPPORTED)."),
)
for _row in _ROWS:
    setattr(GeController, _row[0], _adapter(*_row))
del _row
_wrap_vendor_methods(GeController)  # the rows return the vendor's codes as the class's own methods do


#: GE functions the simulation cannot carry out: each returns 1 (a read (1, 0)) (decision GF3).
UNSUPPORTED: dict[str, str] = {
    "GT_HandWheel": "the handwheel drives an axis from the auxiliary encoder input (L2950-2990); the card's gear "
                    "follows another axis's profile only, it has no encoder master",
    "GT_ExitHWheel": "leaves the handwheel mode GT_HandWheel would enter (L4086-4092), which is not simulated",
    "GT_Axis": "every GE command names its axis (Table 11-1/11-2); GT_Axis appears once, in the GT-lineage sample "
               "under GT_CaptProb (L3848), with no prototype in the GE manual",
}


for _name in [n for n in vars(GeController) if n.startswith("GT_") and n != "GT_HookCommand"]:
    setattr(GeController, _name, _command(_name, vars(GeController)[_name]))
del _name

_default = GeController()
GE_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "GT_")


def delay(ms: float):
    """The manual's ``delay(ms)``: runs the open card for ``ms`` milliseconds (rounded to whole ticks)."""
    return _default.delay(ms)



def __getattr__(name: str) -> Any:
    """PEP 562 hook: the module's GT_* functions are made at import by export_functions (they exist as globals, so
    this is never reached for them); it tells a type checker that ``from servobench.dialects.ge import GT_Axis``
    names a module attribute. Any other name: AttributeError."""
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["GeController", "GE_FUNCTIONS", "TLookAheadMsg", "RTN_COMMAND_ERROR", "RTN_COMM_ERROR", "UNSUPPORTED",
           "use_machine",
           "RTN_PARAMETER_ERROR", "RTN_REENTERED", "RTN_SUCCESS", "TAxis", "TWatchBuffer", "card", "controller", "delay",
           "run", "wait_until", *GE_FUNCTIONS]
