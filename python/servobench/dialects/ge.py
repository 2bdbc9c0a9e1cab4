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
from typing import Any
import threading

from .. import _core, card_io
from .._core import CardCommandRefused, MotionCommandRefused, PathGeometryError
from ..card import Card
from . import _ge_watch

_GE_CRD_SLOT = 4  # the card's group slot of the GE SX crd (machine/card_group_ge.hpp kGeCrdSlot)
from ._ge_watch import TAxis, TWatchBuffer  # noqa: F401 (the manual's watch structures)
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401

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
# Commands whose C form writes through pointers: (rtn, value) in Python.
_READS = frozenset({"GT_ExInpt", "GT_GetLmtSwt", "GT_GetHomeSwt", "GT_GetCmdSts", "GT_EncPos", "GT_CalVel"})


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


# -- [sx-path] the GE path state and the look-ahead module B queue (see GeController's [sx-path] block) --------
class TLookAheadMsg:
    """The Ex commands' message (L5147-5169): mtnNum the CodeNum where an error occurred, num how many commands
    before it were not sent, error 0 none, 1 point equals the previous one, 3 buffer full (re-send), 8 sending
    the motion command failed (here: no InitLookAheadEx / MvXYEx, or a bad argument)."""

    def __init__(self):
        self.mtnNum = 0
        self.num = 0
        self.error = 0

    def __repr__(self):
        return f"TLookAheadMsg(mtnNum={self.mtnNum}, num={self.num}, error={self.error})"


class _GeLookAheadEx:
    """Module B: the GT_InitLookAheadEx parameters (mm, s); active after GT_MvXYEx / GT_MvXYZEx put the card's
    look-ahead window in front of the buffer."""

    def __init__(self, params):
        self.params = params
        self.active = False


class _GePathState:
    """What the GE dialect keeps about the SX path (the card's crd holds the motion)."""

    def __init__(self, axes: int):
        self.syn_vel = 0.0          # pulse/ms (SetSynVel; the Mv vel in buffer mode until changed)
        self.syn_acc = 0.0          # pulse/ms^2 (SetSynAcc, immediate mode)
        self.strt_vel = 0.5         # pulse/ms (L1399)
        self.max_vel = 256.0        # pulse/ms (L1405)
        self.stp_acc = 0.0          # pulse/ms^2; 0 = stop at once (V102)
        self.override = 1.0
        self.override_g0 = 1.0
        self.offsets = [0.0] * axes  # GT_MapCnt, pulse
        self.capacity = 4096        # buffered commands (V102)
        self.dirty = True           # rebuild the crd at the next occasion
        self.dim = 0                # crd coordinates (0: up to 4; 3 with look-ahead module B)
        self.buffer = False         # buffer input/execution mode (crd bit 7 = 0)
        self.open = False           # buffer open (crd bit 1 = 0)
        self.mv = False
        self.mv_dim = 4
        self.mv_vel = 0.0
        self.mv_acc = 0.0
        self.mv_pushed = 0          # the Mv line is segment 0 of the generator
        self.started = False        # StrtMtn since StrtList
        self.dcc_vel = None         # SetDccVel for the next segment
        self.io_count = 0           # BufIO since the last motion command (<= 2)
        self.delay_count = 0        # Delay since the last motion command (<= 1)
        self.pending_io = []        # BufIOBit waiting for the next path command
        self.pushed = 0             # path segments buffered since StrtList
        self.ends = []              # end points of the generator's segments, in order
        self.cmd_bit = None         # SX command-error bit of the last path refusal
        self.gpo_seen = 0           # the crd's buffered-output word last merged into the EXO word
        self.la = None              # module A
        self.ex = None              # module B

    def open_list(self):
        self.buffer = self.open = True
        self.mv = self.started = False
        self.mv_pushed = self.pushed = self.io_count = self.delay_count = 0
        self.dcc_vel = None
        self.pending_io = []
        self.ends = []
        if self.ex is not None:
            self.ex.active = False

    def seg_end(self, path):
        i = path.state.segments_done
        if path.busy and i < len(self.ends):
            return self.ends[i]
        return path.tail


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
        self.adc_chn = 8             # GT_SetAdcChn (SX)
        self.shadow = {}             # (axis, register) -> (GE-unit value, per-tick value) for exact read-backs
        self.path = None             # [sx-path] _GePathState, created at the first path command


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
        """The general outputs EXO0..EXO15 as last written by ``GT_ExOpt`` or, on SX, by the path buffer's
        BufIO / BufIOBit when it executed them later (bit n = EXOn)."""
        slot = self._slot
        st = slot.path
        if st is not None and self._card.ge_crd_exists():   # [sx-path] buffered outputs
            gpo = int(self._card.ge_path().state.gpo) & 0xFFFF
            if gpo != st.gpo_seen:
                slot.outputs = (slot.outputs & ~(gpo ^ st.gpo_seen)) | (gpo & (gpo ^ st.gpo_seen))
                st.gpo_seen = gpo
        return slot.outputs

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
        def word():
            path = self._slot.path   # [sx-path] bits 9 and 15 of a path refusal (V100)
            if (self.variant == "SX" and path is not None and path.cmd_bit is not None
                    and self._card.last_fault == "crd_state_error"):
                return 1 << path.cmd_bit
            return _core.ge_command_status(self._card.kernel, self.variant)

        return self._get(word)

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
        return self._read(axis, lambda a: _core.ge_mode_register(self._card.kernel, a))

    # -- 7.4 position, velocity and error feedback --------------------------------------------------------------
    def GT_ZeroPos(self, axis) -> int:
        """Actual = target = profile = 0; at rest only (else rtn 1, cmd bit 11) (L5907-5913)."""
        return self._axis_cmd(axis, lambda a: (self._leave_crd(a), self._card.zero_pos(a)))

    def GT_SetAtlPos(self, axis, pos) -> int:
        """Actual = target = profile = ``pos``, whole pulses -2^30..2^30-1; at rest only (cmd bit 11) (L5457)."""
        return self._axis_cmd(axis, lambda a: (self._leave_crd(a), self._card.set_actual_pos(a, float(pos))),
                              _int_in(pos, _POS_MIN, _POS_MAX), "motion_param_overflow")

    def _leave_crd(self, a):
        """[sx-path] ZeroPos / SetAtlPos on an SX crd axis with the path at rest and no buffer kept: the crd is
        dropped and rebuilt at the new positions by the next path command (Example 7-1 L2190; V112)."""
        if self.variant != "SX" or a >= 4 or not self._card.ge_crd_exists():
            return
        path = self._card.ge_path()
        if path.busy or self._path_state().open or self._resumable(path) or self._card.moving(a):
            return
        self._card.set_mode(a, "t_curve")
        self._path_state().dirty = True

    def GT_GetAtlPos(self, axis):
        """(rtn, actual position, pulse) (L4173); with the encoder off, the profile position (L4180)."""
        def atl(a):
            if not self._slot.enc_on[a]:
                return register32(self._card.profile_pos(a))
            return register32(self._card.actual_pos(a))

        return self._read(axis, atl)

    def GT_GetPrfPos(self, axis):
        """(rtn, profile position, pulse) (L4701)."""
        return self._read(axis, lambda a: register32(self._card.profile_pos(a)))

    def GT_GetAtlErr(self, axis):
        """(rtn, following error profile - actual of the last tick, pulse) (L4144-4171)."""
        return self._read(axis, lambda a: int(round(self._card.following_error(a))))

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
        return self._read(axis, lambda a: _core.ge_axis_status(self._card.kernel, a, self.variant))

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

    # -- [sx-path] path motion, buffer, look-ahead (SX; GE §6 L1393-2040, §12; ge.md §4, §7.9-7.11) ----------
    # The crd is the card's GE group (Card.ge_crd_setup / ge_path, machine/card_group_ge.hpp: X..A = axes 1..4,
    # pulse, ms), built at the first path command and rebuilt at the present positions whenever nothing is
    # buffered (StrtList, an immediate command), so a changed StrtVel/MaxVel/MapCnt takes effect there (V101).
    # This block keeps the GE list bookkeeping; refusals leave the card unchanged and set the SX command-error
    # bit of their cause: 8 path command, 9 buffer state, 15 buffer full, 6 MapCnt (Table 2-4 L324-347; V100).
    def _path_state(self) -> _GePathState:
        slot = self._slot
        if slot.path is None:
            slot.path = _GePathState(len(self._card))
        return slot.path

    def _crd_fault(self, bit: int) -> int:
        """A path refusal: the card records a crd-state fault; GT_GetCmdSts shows `bit` while it is the last."""
        self._card.record_fault(-1, "crd_state_error" if bit != 6 else "axis_state_error")
        self._path_state().cmd_bit = bit
        return RTN_COMMAND_ERROR

    def _fresh(self):
        """The crd's generator, empty, at the present profile positions: cleared, or rebuilt when a setting
        changed or an axis moved outside the path (ZeroPos, AxisOn) (V101)."""
        st = self._path_state()
        st.dim = 0
        if (self._card.ge_crd_exists() and not st.dirty and not self._card.ge_path().lookahead_on
                and self._card.ge_path().coords.dim == min(4, len(self._card))):
            path = self._card.ge_path()
            n = path.coords.dim
            pos = list(path.state.pos)
            if all(abs(pos[k] + st.offsets[k] - self._card.profile_pos(k)) < 0.5 for k in range(n)):
                path.clear()
                return path
        st.dirty = True
        return self._path_generator(rebuild=True)

    def _path_generator(self, rebuild=False):
        """The crd's generator; (re)built at the present positions when asked and nothing is kept."""
        st = self._path_state()
        if not self._card.ge_crd_exists() or (rebuild and st.dirty):
            n = min(st.dim or 4, len(self._card))
            self._card.ge_crd_setup(st.offsets[:n], st.strt_vel, st.max_vel, st.stp_acc, st.capacity, n)
            self.outputs()               # outputs the old crd's buffer wrote stay
            st.dirty = False
            st.mv_pushed = 0
            st.gpo_seen = 0
            path = self._card.ge_path()
            path.set_override(st.override)
            path.set_g0_override(st.override_g0)
        return self._card.ge_path()

    def _path_moving(self, path) -> bool:
        st = self._path_state()
        return (path.busy or (path.running and path.remaining_segments > 0)
                or (st.started and st.open and not path.stopped))

    def _resumable(self, path) -> bool:
        """A stopped buffer that RestoreMtn can resume (breakpoint and unexecuted segments); a stopped immediate
        move keeps none (L1654)."""
        st = self._path_state()
        return st.buffer and st.started and path.breakpoint is not None and path.remaining_segments > 0

    def _geom(self, make):
        """(segment, 0) or (None, return code 2/3/5/7) for a geometry the path layer refuses."""
        try:
            return make(), RTN_SUCCESS
        except PathGeometryError as e:
            return None, e.gt_code  # the SX geometry codes 2/3/5 (Table 2-2 L272-283)
        except ValueError:
            return None, RTN_PARAMETER_ERROR

    def _path_cmd(self, dim, make, g0=False) -> int:
        """A line or arc (pulse, absolute): buffer mode appends it (the Mv dimension fixes the dimension, L5244),
        immediate mode runs it at once at SynVel/SynAcc (L1445-1492)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if st.open:
            if not st.mv or dim > st.mv_dim:
                return self._crd_fault(8)   # no Mv* after StrtList, or a 3-D command after MvXY (L335, L5244)
            path = self._path_generator()
            if path.fifo_space < 1 + len(st.pending_io):
                return self._crd_fault(15)  # buffer full: re-send (L1575-1579, L347)
            seg, rtn = self._geom(lambda: make(list(path.tail)))
            if seg is None:
                return rtn
            vel = st.syn_vel if st.syn_vel > 0 else st.mv_vel
            for do in st.pending_io:
                path.buf_io(0, *do)
            st.pending_io = []
            if st.dcc_vel is not None:
                path.push_segment(seg, vel, st.mv_acc, vel_end=st.dcc_vel, g0=g0)
            else:
                path.push_segment(seg, vel, st.mv_acc, g0=g0, auto_end=not g0)
            st.dcc_vel = None
            st.io_count = st.delay_count = 0
            st.pushed += 1
            st.ends.append(list(seg.end))
            return RTN_SUCCESS
        try:
            path = self._path_generator()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_fault(8)
        if self._path_moving(path):
            return self._crd_fault(8)       # an immediate path command while the path moves (L1492, L335)
        if not (st.syn_vel > 0 and st.syn_acc > 0):
            return self._crd_fault(8)       # no feed set (SetSynVel / SetSynAcc): a bad path parameter
        kept = self._resumable(path)
        if not kept:
            try:
                path = self._fresh()
            except (CardCommandRefused, MotionCommandRefused):
                return self._crd_fault(8)
        start = list(path.state.pos)
        seg, rtn = self._geom(lambda: make(start))
        if seg is None:
            return rtn
        if kept:
            # a stopped buffer waits for RestoreMtn; a line runs at once from where the path stands (L1652, V104)
            if seg.kind != "line":
                return self._crd_fault(8)
            return self._run(lambda: (self._card.group_start(_GE_CRD_SLOT),
                                      path.move_immediate(list(seg.end), st.syn_vel, st.syn_acc)))

        def run_now():
            path.push_segment(seg, st.syn_vel, st.syn_acc, g0=g0, stop_at_end=True)
            st.ends = [list(seg.end)]
            self._card.group_start(_GE_CRD_SLOT)
            path.start()

        rtn = self._run(run_now)
        if rtn == RTN_SUCCESS:
            st.buffer = False   # immediate input mode again (crd bit 7, V103)
            st.started = False
            st.mv_pushed = 0
        return rtn

    def _run(self, fn) -> int:
        try:
            fn()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_fault(8)
        except ValueError:
            return RTN_PARAMETER_ERROR
        return RTN_SUCCESS

    @staticmethod
    def _line_to(dim, pts):
        def make(t):
            end = list(t)
            for k, p in enumerate(pts):
                end[k] = float(p)
            return _core.PathSegment.line(t, end)
        return make

    def _pts_ok(self, *pts) -> bool:
        return all(_real_in(p, _POS_MIN, _POS_MAX) for p in pts)

    def GT_LnXY(self, x, y) -> int:
        """Line to the absolute point (x, y), pulse (L4946); the feed is SetSynVel (L1407). Returns 3 for a zero
        length or overflow (L280)."""
        return self._path_cmd(2, self._line_to(2, (x, y))) if self._pts_ok(x, y) else self._len_overflow()

    def GT_LnXYZ(self, x, y, z) -> int:
        """3-D line, pulse (L4980)."""
        return self._path_cmd(3, self._line_to(3, (x, y, z))) if self._pts_ok(x, y, z) else self._len_overflow()

    def GT_LnXYZA(self, x, y, z, a) -> int:
        """4-D line, pulse (L5010)."""
        return (self._path_cmd(4, self._line_to(4, (x, y, z, a))) if self._pts_ok(x, y, z, a)
                else self._len_overflow())

    def GT_LnXYG0(self, x, y) -> int:
        """Rapid line: a full profile from StrtVel to SynVel and back to rest, scaled by OverrideG0 (L1473-1477,
        L5036)."""
        return self._path_cmd(2, self._line_to(2, (x, y)), g0=True) if self._pts_ok(x, y) else self._len_overflow()

    def GT_LnXYZG0(self, x, y, z) -> int:
        """3-D rapid line (L5075)."""
        return (self._path_cmd(3, self._line_to(3, (x, y, z)), g0=True) if self._pts_ok(x, y, z)
                else self._len_overflow())

    def GT_LnXYZAG0(self, x, y, z, a) -> int:
        """4-D rapid line (L5113; printed as GT_LnXYZG0(x,y,z,a) at L5115, V110)."""
        return (self._path_cmd(4, self._line_to(4, (x, y, z, a)), g0=True) if self._pts_ok(x, y, z, a)
                else self._len_overflow())

    def _len_overflow(self) -> int:
        return 3 if self._card is not None else RTN_COMM_ERROR

    def _arc(self, plane, c1, c2, angle) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if not self._pts_ok(c1, c2):
            return 3
        if not _real_in(angle, -360, 360):
            return RTN_PARAMETER_ERROR
        dim = 2 if plane == "xy" else 3
        return self._path_cmd(dim, lambda t: _core.PathSegment.arc_center_angle(t, plane, (float(c1), float(c2)),
                                                                                float(angle)))

    def GT_ArcXY(self, x_center, y_center, angle) -> int:
        """Arc about the absolute centre by ``angle`` degrees in [-360, 360], + = CCW seen from +Z (L1481-1486,
        L3434-3443); the radius is the distance of the start point (2: radius 0)."""
        return self._arc("xy", x_center, y_center, angle)

    def GT_ArcYZ(self, y_center, z_center, angle) -> int:
        """Arc in the YZ plane, seen from +X (L3519-3527)."""
        return self._arc("yz", y_center, z_center, angle)

    def GT_ArcZX(self, z_center, x_center, angle) -> int:
        """Arc in the ZX plane, seen from +Y (L3593-3601)."""
        return self._arc("zx", z_center, x_center, angle)

    def _arcp(self, plane, e1, e2, r, direction) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if not self._pts_ok(e1, e2, r):
            return 3
        if not _int_in(direction, -1, 1) or int(direction) == 0:
            return RTN_PARAMETER_ERROR
        i, j = {"xy": (0, 1), "yz": (1, 2), "zx": (2, 0)}[plane]
        dim = 2 if plane == "xy" else 3

        def make(t):
            end = list(t)
            end[i], end[j] = float(e1), float(e2)
            return _core.PathSegment.arc_radius(t, end, plane, float(r), int(direction) == 1)

        return self._path_cmd(dim, make)

    def GT_ArcXYP(self, x_end, y_end, r, direction) -> int:
        """Arc to the end point with signed radius: r > 0 the minor arc, r < 0 the major one; direction +1 CCW,
        -1 CW (L3477-3483). 2: radius or chord 0; 5: chord > diameter (L280-282)."""
        return self._arcp("xy", x_end, y_end, r, direction)

    def GT_ArcYZP(self, y_end, z_end, r, direction) -> int:
        """YZ arc by end point and radius (L3555-3561)."""
        return self._arcp("yz", y_end, z_end, r, direction)

    def GT_ArcZXP(self, z_end, x_end, r, direction) -> int:
        """ZX arc by end point and radius (L3628-3636)."""
        return self._arcp("zx", z_end, x_end, r, direction)

    # feed parameters (L1393-1419, §4.3)
    def _feed_value(self, value, hi):
        """4 for a value <= 0 or overflow (synthesised vel/acc, L280)."""
        return _real_in(value, 0, hi) and float(value) > 0

    def GT_SetSynVel(self, vel) -> int:
        """Path feed, pulse/ms, for the following lines and arcs; bufferable (L1407-1409, L5770-5778)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not self._feed_value(vel, _VEL_MAX):
            return 4
        self._path_state().syn_vel = float(vel)
        return RTN_SUCCESS

    def GT_SetSynAcc(self, acc) -> int:
        """Path acceleration of immediate motion, pulse/ms^2; illegal in buffer mode (bit 8, L1411-1413, L335)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if st.open:
            return self._crd_fault(8)
        if not self._feed_value(acc, _ACC_MAX):
            return 4
        st.syn_acc = float(acc)
        return RTN_SUCCESS

    def _setting(self, value, hi, field, zero_ok=False) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if self._card.ge_crd_exists() and self._path_moving(self._card.ge_path()):
            return self._crd_fault(8)  # start/max velocity, stop acceleration: not while the path moves (L335)
        if not _real_in(value, 0, hi) or (float(value) == 0 and not zero_ok):
            return 4
        setattr(st, field, float(value))
        st.dirty = True
        if field == "stp_acc" and self._card.ge_crd_exists():
            self._card.ge_path().set_stop_dec(0, float(value))
        return RTN_SUCCESS

    def GT_SetStrtVel(self, vel) -> int:
        """Start/stop velocity, pulse/ms (default 0.5 = 500 Hz, L1395-1399, L5748-5756); meant for the set-up."""
        return self._setting(vel, _VEL_MAX, "strt_vel", zero_ok=True)

    def GT_SetMaxVel(self, vel) -> int:
        """Feed clamp, pulse/ms (default 256, L1401-1405, L5638-5644)."""
        return self._setting(vel, _VEL_MAX, "max_vel")

    def GT_SetStpAcc(self, acc) -> int:
        """Deceleration of abnormal stops and GT_EStpMtn, pulse/ms^2 (L1415-1419, L5736-5744)."""
        return self._setting(acc, _ACC_MAX, "stp_acc")

    def _override(self, ratio, g0) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if not _real_in(ratio, 0, 2) or float(ratio) == 0:
            return RTN_PARAMETER_ERROR   # a multiplier, (0, 2] (L1952-1958, L5348; V105)
        st = self._path_state()
        if g0:
            st.override_g0 = float(ratio)
        else:
            st.override = float(ratio)
        if self._card.ge_crd_exists():
            path = self._card.ge_path()
            (path.set_g0_override if g0 else path.set_override)(float(ratio))
        return RTN_SUCCESS

    def GT_Override(self, override) -> int:
        """Feed multiplier of all path motion but G0 and Mv, on the running segment and all later ones; the
        result is clamped to MaxVel (L1952-1958, L5342-5352)."""
        return self._override(override, False)

    def GT_OverrideG0(self, override) -> int:
        """Multiplier of G0 lines and the Mv positioning (L5354-5362)."""
        return self._override(override, True)

    def GT_SetDccVel(self, vel) -> int:
        """End velocity, pulse/ms, of the next buffered path segment (L5492-5500, L1679; V106). Buffer only."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.open or not st.mv:
            return self._crd_fault(8)
        if not _real_in(vel, 0, _VEL_MAX):
            return 4
        st.dcc_vel = float(vel)
        return RTN_SUCCESS

    def GT_MapCnt(self, axis, count) -> int:
        """Work-coordinate offset of ``axis``, pulse: axis = coordinate + count (L1960-1971, L5179-5187); refused
        (bit 6) while an axis moves, the buffer is open, or out of range."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(axis, 1, min(4, self.axes)):
            return self._param(-1)
        st = self._path_state()
        moving = any(self._card.moving(a) for a in range(len(self._card)))
        if moving or st.open or not _real_in(count, _POS_MIN, _POS_MAX):
            return self._crd_fault(6)
        st.offsets[int(axis) - 1] = float(count)
        st.dirty = True
        return RTN_SUCCESS

    # buffer management (L1496-1664, Tables 6-3/6-4)
    def GT_StrtList(self) -> int:
        """Opens and clears the buffer (buffer input mode, segment number 0); refused (bit 9) while buffered motion
        has not stopped or the buffer is open (L1549, L5861-5865)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if st.open:
            return self._crd_fault(9)
        if self._card.ge_crd_exists():
            path = self._card.ge_path()
            if path.busy or (st.started and path.running and not path.stopped):
                return self._crd_fault(9)
        try:
            self._fresh()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_fault(9)
        st.open_list()
        return RTN_SUCCESS

    def _mv(self, point, vel, acc) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.open or st.mv:
            return self._crd_fault(8)   # Mv* only right after StrtList, once (L1551, L335)
        if not self._pts_ok(*point):
            return 3
        if not self._feed_value(vel, _VEL_MAX) or not self._feed_value(acc, _ACC_MAX):
            return 4
        path = self._path_generator()
        t = list(path.tail)
        end = list(t)
        for k, p in enumerate(point):
            end[k] = float(p)
        if end != t:
            path.push_segment(_core.PathSegment.line(t, end), float(vel), float(acc), g0=True)
            st.mv_pushed = 1
            st.ends.append(end)
        st.mv, st.mv_dim, st.mv_vel, st.mv_acc = True, len(point), float(vel), float(acc)
        st.syn_vel = float(vel)   # the feed of the later segments until SetSynVel (L1555)
        return RTN_SUCCESS

    def GT_MvXY(self, x, y, vel, acc) -> int:
        """Buffer start point (x, y) pulse, feed vel pulse/ms and acceleration acc pulse/ms^2 of the buffer
        (acceleration fixed); StrtMtn first goes there by a line that ends at rest (L1551-1555, L5232)."""
        return self._mv((x, y), vel, acc)

    def GT_MvXYZ(self, x, y, z, vel, acc) -> int:
        """3-D buffer start point (L5277)."""
        return self._mv((x, y, z), vel, acc)

    def GT_MvXYZA(self, x, y, z, a, vel, acc) -> int:
        """4-D buffer start point (L5291)."""
        return self._mv((x, y, z, a), vel, acc)

    def GT_EndList(self) -> int:
        """Closes the buffer (only while open, else bit 9) (L1559-1571, L4037)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.open:
            return self._crd_fault(9)
        st.open = False
        return RTN_SUCCESS

    def GT_AddList(self) -> int:
        """Reopens a closed buffer; while open: bit 9 (L1559-1571, L3339)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if st.open or not st.buffer or not st.mv:
            return self._crd_fault(9)
        st.open = True
        return RTN_SUCCESS

    def GT_StrtMtn(self) -> int:
        """Runs the buffer: first the Mv line (ends at rest), then the segments; keeps executing while the host
        streams more until EndList (L1640-1646, L5871-5875). Bit 9 while path motion runs."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.buffer or not st.mv:
            return self._crd_fault(9)
        path = self._path_generator()
        if path.busy or st.started:
            return self._crd_fault(9)   # StrtMtn while path motion runs, or to resume (RestoreMtn, L1664)

        def start():
            self._card.group_start(_GE_CRD_SLOT)
            path.start()

        rtn = self._run(start)
        if rtn == RTN_SUCCESS:
            st.started = True
        return rtn

    def _stp(self, abrupt) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not self._card.ge_crd_exists():
            return RTN_SUCCESS
        path = self._card.ge_path()
        try:
            path.stop(abrupt)
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_fault(8)
        if st.buffer:
            st.open = False   # both stops close the buffer; the breakpoint is kept (L1648-1650)
        return RTN_SUCCESS

    def GT_StpMtn(self) -> int:
        """Smooth path stop at the feed acceleration; closes the buffer, keeps the breakpoint (L1648-1654, L5852)."""
        return self._stp(False)

    def GT_EStpMtn(self) -> int:
        """Path stop at StpAcc (SetStpAcc; 0: at once); closes the buffer, keeps the breakpoint (L1648, L4064)."""
        return self._stp(True)

    def GT_RestoreMtn(self) -> int:
        """Resumes a stopped buffer: a line from the present point to the breakpoint ending at the start
        velocity, then the rest (L1656-1664, L5412). Bit 9 unless stopped with unexecuted segments."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.started or not self._card.ge_crd_exists():
            return self._crd_fault(9)
        path = self._card.ge_path()
        if path.busy or not path.stopped or not self._resumable(path):
            return self._crd_fault(9)

        def start():
            self._card.group_start(_GE_CRD_SLOT)
            path.start()

        return self._run(start)

    def _buf_gate(self) -> int | None:
        """-1 in immediate mode (L3754); bit 8 without Mv; None when the buffer takes it."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.open:
            return RTN_COMM_ERROR
        if not st.mv:
            return self._crd_fault(8)
        return None

    def GT_BufIO(self, io_status) -> int:
        """Buffered write of all 16 outputs EXO0..15 between the previous segment's end and the next one's start;
        at most two between motion commands (L3750-3756). -1 in immediate mode."""
        gate = self._buf_gate()
        if gate is not None:
            return gate
        if not _int_in(io_status, 0, 0xFFFF):
            return RTN_PARAMETER_ERROR
        st = self._path_state()
        if st.io_count >= 2:
            return self._crd_fault(8)
        path = self._card.ge_path()
        if path.fifo_space < 1:
            return self._crd_fault(15)
        path.buf_io(0, 0xFFFF, int(io_status))
        st.io_count += 1
        return RTN_SUCCESS

    def GT_BufIOBit(self, io_bit, bit_status) -> int:
        """Buffered write of one output, effective with the next path segment; of two in a row the one nearest
        the path command wins (L3766-3776)."""
        gate = self._buf_gate()
        if gate is not None:
            return gate
        if not _int_in(io_bit, 0, 15) or not _int_in(bit_status, 0, 1):
            return RTN_PARAMETER_ERROR
        self._path_state().pending_io = [(1 << int(io_bit), int(bit_status) << int(io_bit))]
        return RTN_SUCCESS

    def GT_Delay(self, delay_time) -> int:
        """Buffered dwell between two segments, ms (0 < t < 8192; V107); one between motion commands (L3944-3950)."""
        gate = self._buf_gate()
        if gate is not None:
            return gate
        if not _int_in(delay_time, 1, 8191):
            return RTN_PARAMETER_ERROR
        st = self._path_state()
        if st.delay_count >= 1:
            return self._crd_fault(8)
        path = self._card.ge_path()
        if path.fifo_space < 1:
            return self._crd_fault(15)
        path.buf_delay(float(delay_time))
        st.delay_count += 1
        return RTN_SUCCESS

    # feedback (Table 6-15, L1973-2040)
    def GT_GetCrdSts(self):
        """(rtn, path status, 16 bits) (Table 4-5 L951-968): 0 no path motion (1 idle), 1 buffer closed,
        4 segment completed, 7 immediate input mode, 9 an axis fault stopped the path, 13 buffer empty."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        st = self._path_state()
        if not self._card.ge_crd_exists():
            return RTN_SUCCESS, _core.ge_crd_status(buffer_closed=not st.open, immediate_mode=not st.buffer)
        path = self._card.ge_path()
        info = self._card.group_info(_GE_CRD_SLOT)
        return RTN_SUCCESS, _core.ge_crd_status(
            moving=self._path_moving(path), buffer_closed=not st.open, segment_complete=not path.busy,
            immediate_mode=not st.buffer, fault_stopped=info["fault_stopped"],
            buffer_empty=path.fifo_size == 0 and path.window_size == 0)

    def _pnt(self, which):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        if not self._card.ge_crd_exists():
            return RTN_SUCCESS, [float(self._card.profile_pos(a)) - self._path_state().offsets[a]
                                 for a in range(min(3, len(self._card)))]
        path = self._card.ge_path()
        p = which(path)
        return RTN_SUCCESS, None if p is None else [float(v) for v in list(p)[:3]]

    def GT_GetPrfPnt(self):
        """(rtn, [X, Y, Z] profile point, pulse, work coordinates) (L4675-4699; three values, V108)."""
        return self._pnt(lambda p: p.state.pos)

    def GT_GetSegPnt(self):
        """(rtn, [X, Y, Z] end point of the executing segment, pulse) (L4735-4743): the tail when idle."""
        return self._pnt(lambda p: self._path_state().seg_end(p))

    def GT_GetBrkPnt(self):
        """(rtn, [X, Y, Z] breakpoint of the last buffered stop, pulse, or None) (L4233-4241)."""
        return self._pnt(lambda p: p.breakpoint)

    def GT_GetMtnNm(self):
        """(rtn, segment number): Mv = 0, path segments from 1; holds when the buffer runs dry, while stopped,
        after the last segment; StrtList clears it; wraps 32767 -> 1 (L2005-2017, L4578-4586; V109)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        st = self._path_state()
        if not self._card.ge_crd_exists() or not st.buffer:
            return RTN_SUCCESS, 0
        path = self._card.ge_path()
        n = path.state.segments_done - st.mv_pushed + (1 if path.busy and path.state.speed > 0 else 0)
        n = max(0, min(n, st.pushed))
        return RTN_SUCCESS, (n - 1) % 32767 + 1 if n > 0 else 0

    def GT_GetPrfVel(self, *axis):
        """PX ``GT_GetPrfVel(axis)``: (rtn, profile velocity of the axis, pulse/ms) (L4713). SX
        ``GT_GetPrfVel()``: (rtn, path feed velocity, pulse/ms) (L4725-4733)."""
        if self.variant == "PX":
            if len(axis) != 1:
                return RTN_PARAMETER_ERROR, 0
            return self._read(axis[0], lambda a: self._card.profile_vel(a) / self._k)
        if self._card is None:
            return RTN_COMM_ERROR, 0
        if axis:
            return RTN_PARAMETER_ERROR, 0
        return RTN_SUCCESS, self._card.ge_path().state.speed if self._card.ge_crd_exists() else 0.0

    # look-ahead module A (L1666-1727, Table 6-6; API L3370-3394, L3790-3800, L4879-4887)
    def GT_InitLookAhead(self, t, acc_max, acc, vel, n, con) -> int:
        """Module A: corner time t s, acc_max and acc mm/s^2 (acc < acc_max), feed vel mm/s, n segments, con
        pulse/mm (L4879-4887). The path starts at the present profile point (in mm)."""
        if self._card is None:
            return RTN_COMM_ERROR
        try:
            p = _core.GeLookAheadParams(t_s=float(t), acc_max=float(acc_max), acc=float(acc), vel=float(vel),
                                        n=float(n), con=float(con))
            offsets = self._path_state().offsets
            start = [float(self._card.profile_pos(a)) - offsets[a] for a in range(min(3, len(self._card)))]
            self._path_state().la = _core.GeLookAhead(p, [v / float(con) for v in start])
        except (ValueError, TypeError):
            return RTN_PARAMETER_ERROR
        return RTN_SUCCESS

    def GT_AddLookData(self, code, plane_group, r, x, y, z, vel, cx, cy, i, n, flag) -> int:
        """Pushes one segment (mm, mm/s) to module A: code 0 G00, 1 G01, 2 G02 CW, 3 G03 CCW; plane_group 17 XY,
        18 ZX, 19 YZ; i the slot (not used: the module keeps its own order, V111), n the user number, flag: stop
        at its end. 0 accepted, 1 the point equals the previous one (L3370-3394, Table 6-8 L1709-1724)."""
        if self._card is None:
            return RTN_COMM_ERROR
        la = self._path_state().la
        if la is None:
            return self._crd_fault(8)
        try:
            return la.add_look_data(int(code), int(plane_group), float(r), float(x), float(y), float(z), float(vel),
                                    float(cx), float(cy), int(n), bool(flag))
        except (ValueError, TypeError):
            return RTN_PARAMETER_ERROR

    def GT_CalVel(self):
        """(rtn, end velocity mm/s, user number) of the oldest segment not yet returned: rtn 0 more follow, 1 it was
        the last (L3790-3800, L1725). Send the segment with GT_SetDccVel(vel * con / 1000)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0.0, 0
        la = self._path_state().la
        if la is None or la.pending == 0:
            self._crd_fault(8)
            return RTN_COMMAND_ERROR, 0.0, 0
        return tuple(la.cal_vel())

    # look-ahead module B, the Ex family (Tables 6-9..6-12 L1729-1812; L5147-5177): the card's look-ahead window
    # (PathGenerator.init_lookahead, the same planner as module A in pulse and ms) in front of the buffer (V111)
    def GT_InitLookAheadEx(self, T, amax, am, n, con) -> int:
        """Module B: corner time T s, amax and am mm/s^2 (am < amax), n >= 200 look-ahead segments, con pulse/mm
        (L1729-1785, L4889-4895; also GT_InitLookAheadExx, V110)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(n, 200, 32766):
            return RTN_PARAMETER_ERROR
        try:
            p = _core.GeLookAheadParams(t_s=float(T), acc_max=float(amax), acc=float(am), vel=1.0, n=float(n),
                                        con=float(con))
        except (ValueError, TypeError):
            return RTN_PARAMETER_ERROR
        self._path_state().ex = _GeLookAheadEx(p)
        return RTN_SUCCESS

    def GT_InitLookAheadExx(self, T, amax, am, n, con) -> int:
        """The name ch12 and Example 6-4 use for GT_InitLookAheadEx (L1856, L4889; V110)."""
        return vars(GeController)["GT_InitLookAheadEx"].__wrapped__(self, T, amax, am, n, con)

    def _mv_ex(self, point_mm, vel) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        ex = st.ex
        if ex is None:
            return self._crd_fault(8)
        c = ex.params.con
        if not all(_real_in(v, -1e12, 1e12) and _real_in(float(v) * c, _POS_MIN, _POS_MAX) for v in point_mm):
            return 3
        if not _real_in(vel, 0, 1e9) or float(vel) <= 0:
            return 4
        if not st.open or st.mv:
            return self._crd_fault(8)
        st.dim, st.dirty = 3, True   # the look-ahead plans X, Y, Z (L1679): a 3-D crd
        try:
            path = self._path_generator(rebuild=True)
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_fault(8)
        p = ex.params
        path.init_lookahead(_core.LookAheadParams(t_ms=p.t_s * 1000.0, acc_max=p.acc_max * c / 1e6, n=p.n))
        rtn = self._mv([float(v) * c for v in point_mm], float(vel) * c / 1000.0, p.acc * c / 1e6)
        if rtn == RTN_SUCCESS:
            ex.active = True
            st.mv_dim = len(point_mm)
        return rtn

    def GT_MvXYEx(self, x, y, vel) -> int:
        """Module B start point (x, y) mm at vel mm/s; right after StrtList (L1787-1789, L5269; printed as
        GT_MvXYZEx(x,y,vel) at L5271, V110)."""
        return self._mv_ex((x, y), vel)

    def GT_MvXYZEx(self, x, y, z, vel) -> int:
        """Module B 3-D start point, mm, mm/s (L5305)."""
        return self._mv_ex((x, y, z), vel)

    def _ex_gate(self, msg, number):
        """(path, ex) when an Ex command may be buffered now, else (None, rtn) after filling msg."""
        st = self._path_state()
        ex = st.ex
        if ex is None or not ex.active or not st.open or not self._card.ge_crd_exists():
            msg.error, msg.mtnNum, msg.num = 8, int(number), 0
            return None, self._crd_fault(8)
        path = self._card.ge_path()
        if path.window_size >= int(ex.params.n) and path.fifo_space < 1:
            msg.error, msg.mtnNum, msg.num = 3, int(number), path.window_size
            self._crd_fault(15)
            return None, RTN_COMMAND_ERROR
        return path, ex

    def _ex_motion(self, msg, number, F, dcc, make, g0=False) -> int:
        """One Ex motion command (mm, mm/s): into the card's look-ahead window; buffer full: rtn 1, msg.error 3,
        nothing taken (re-send); the same point as before: rtn 1, msg.error 1 (L5147-5169)."""
        if self._card is None:
            return RTN_COMM_ERROR
        msg = msg if msg is not None else TLookAheadMsg()
        if not _int_in(number, -2**31, 2**31 - 1) or not _int_in(dcc, 0, 1):
            return RTN_PARAMETER_ERROR
        if not (_real_in(F, 0, 1e9) and float(F) > 0):
            return 4
        path, ex = self._ex_gate(msg, number)
        if path is None:
            return ex
        c = ex.params.con
        tail = list(path.tail)
        try:
            seg = make([v / c for v in tail], c)
        except ValueError as e:
            msg.error, msg.mtnNum, msg.num = 8, int(number), 0
            if isinstance(e, PathGeometryError):
                return int(_core.ge_geometry_code(e.gt_code))  # a zero-length line is a duplicate point: 1 (L3374)
            return RTN_PARAMETER_ERROR
        if seg is None:
            msg.error, msg.mtnNum, msg.num = 1, int(number), 0   # the point equals the previous one (L3374)
            return RTN_COMMAND_ERROR
        path.push_segment(seg, float(F) * c / 1000.0, ex.params.acc * c / 1e6, g0=g0, stop_at_end=bool(int(dcc)))
        self._path_state().pushed += 1
        self._path_state().ends.append(list(seg.end))
        msg.error, msg.mtnNum, msg.num = 0, int(number), 0
        return RTN_SUCCESS

    def _ex_line(self, pts, F, dccFlag, CodeNum, pMsg, g0) -> int:
        def make(tail_mm, c):
            end = [v * c for v in tail_mm]
            for k, v in enumerate(pts):
                end[k] = float(v) * c
            tail = [v * c for v in tail_mm]
            if all(abs(a - b) < 0.5 for a, b in zip(end, tail)):
                return None
            return _core.PathSegment.line(tail, end)

        return self._ex_motion(pMsg, CodeNum, F, dccFlag, make, g0)

    def GT_LnXYEx(self, x, y, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B G01 line to (x, y) mm at F mm/s; dccFlag 1 stops at its end; CodeNum the user block number;
        pMsg a TLookAheadMsg filled on error (L4972, Table 6-12 L1803-1812)."""
        return self._ex_line((x, y), F, dccFlag, CodeNum, pMsg, False)

    def GT_LnXYZEx(self, x, y, z, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B 3-D G01 line, mm, mm/s (L5067)."""
        return self._ex_line((x, y, z), F, dccFlag, CodeNum, pMsg, False)

    def GT_LnXYG0Ex(self, x, y, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B G00 rapid to (x, y) mm (starts and ends at rest) (L5103)."""
        return self._ex_line((x, y), F, dccFlag, CodeNum, pMsg, True)

    def GT_LnXYZG0Ex(self, x, y, z, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B 3-D G00 rapid, mm (L5139)."""
        return self._ex_line((x, y, z), F, dccFlag, CodeNum, pMsg, True)

    def _ex_arc(self, plane, c1, c2, angle, F, dccFlag, CodeNum, pMsg) -> int:
        def make(tail_mm, c):
            return _core.PathSegment.arc_center_angle([v * c for v in tail_mm], plane,
                                                      (float(c1) * c, float(c2) * c), float(angle))

        if not _real_in(angle, -360, 360):
            return RTN_PARAMETER_ERROR if self._card is not None else RTN_COMM_ERROR
        return self._ex_motion(pMsg, CodeNum, F, dccFlag, make)

    def _ex_arcp(self, plane, e1, e2, r, direction, F, dccFlag, CodeNum, pMsg) -> int:
        i, j = {"xy": (0, 1), "yz": (1, 2), "zx": (2, 0)}[plane]

        def make(tail_mm, c):
            tail = [v * c for v in tail_mm]
            end = list(tail)
            end[i], end[j] = float(e1) * c, float(e2) * c
            return _core.PathSegment.arc_radius(tail, end, plane, float(r) * c, int(direction) == 1)

        if not _int_in(direction, -1, 1) or int(direction) == 0:
            return RTN_PARAMETER_ERROR if self._card is not None else RTN_COMM_ERROR
        return self._ex_motion(pMsg, CodeNum, F, dccFlag, make)

    def GT_ArcXYEx(self, x_center, y_center, angle, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B arc about the centre (mm) by angle degrees (> 0 CCW) (L3468)."""
        return self._ex_arc("xy", x_center, y_center, angle, F, dccFlag, CodeNum, pMsg)

    def GT_ArcYZEx(self, y_center, z_center, angle, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B YZ arc, centre + angle (L3545)."""
        return self._ex_arc("yz", y_center, z_center, angle, F, dccFlag, CodeNum, pMsg)

    def GT_ArcZXEx(self, z_center, x_center, angle, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B ZX arc, centre + angle (L3619; printed GT_ArcZYEx at L3621, V110)."""
        return self._ex_arc("zx", z_center, x_center, angle, F, dccFlag, CodeNum, pMsg)

    def GT_ArcXYPEx(self, x_end, y_end, r, direction, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B arc to the end point (mm), signed radius, direction 1 CCW / -1 CW (L3511)."""
        return self._ex_arcp("xy", x_end, y_end, r, direction, F, dccFlag, CodeNum, pMsg)

    def GT_ArcYZPEx(self, y_end, z_end, r, direction, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B YZ arc by end point and radius (L3583)."""
        return self._ex_arcp("yz", y_end, z_end, r, direction, F, dccFlag, CodeNum, pMsg)

    def GT_ArcZXPEx(self, z_end, x_end, r, direction, F, dccFlag, CodeNum, pMsg=None) -> int:
        """Module B ZX arc by end point and radius (L3658; printed with (y_end, z_end) at L3660, V110)."""
        return self._ex_arcp("zx", z_end, x_end, r, direction, F, dccFlag, CodeNum, pMsg)

    def _ex_plain(self, push) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._path_state()
        if not st.open:
            return RTN_COMM_ERROR      # immediate mode (L3758-3762)
        msg = TLookAheadMsg()
        path, ex = self._ex_gate(msg, 0)
        if path is None:
            return ex
        push(path)
        return RTN_SUCCESS

    def GT_BufIOEx(self, value) -> int:
        """Module B buffered write of the 16 outputs, in order with the Ex motion commands (L3758-3762); -1 in
        immediate mode."""
        if self._card is not None and not _int_in(value, 0, 0xFFFF):
            return RTN_PARAMETER_ERROR
        return self._ex_plain(lambda path: path.buf_io(0, 0xFFFF, int(value)))

    def GT_BufIOBitEx(self, io_bit, bit_status) -> int:
        """Module B buffered write of one output (L3778)."""
        if self._card is not None and (not _int_in(io_bit, 0, 15) or not _int_in(bit_status, 0, 1)):
            return RTN_PARAMETER_ERROR
        return self._ex_plain(lambda path: path.buf_io(0, 1 << int(io_bit), int(bit_status) << int(io_bit)))

    def GT_DelayEx(self, time) -> int:
        """Module B buffered dwell, ms, 0 < t < 8192 (Table 6-10 L1761; V107)."""
        if self._card is not None and not _int_in(time, 1, 8191):
            return RTN_PARAMETER_ERROR
        return self._ex_plain(lambda path: path.buf_delay(float(time)))

    def GT_M30(self, pMsg=None) -> int:
        """Flushes module B: moves the look-ahead window into the card buffer as space allows. 9 while commands
        remain (msg.error 3: the buffer is full; let the card run and call again), 0 when all are in; then
        GT_EndList (L1793-1795, L5171-5177)."""
        if self._card is None:
            return RTN_COMM_ERROR
        msg = pMsg if pMsg is not None else TLookAheadMsg()
        st = self._path_state()
        if st.ex is None or not st.ex.active or not st.open or not self._card.ge_crd_exists():
            msg.error = 8
            return self._crd_fault(8)
        path = self._card.ge_path()
        if path.flush():
            msg.error, msg.num = 0, 0
            return RTN_SUCCESS
        msg.error, msg.num = 3, path.window_size
        return 9

    # -- analog inputs, spindle output, auxiliary encoders (ch10 L2890-3020; card_io) -------------------------------
    def GT_GetAdc(self, channel):
        """(rtn, input voltage of channel 1..8 as 12-bit counts): +10 V = 2047, 0 V = 0, -10 V = -2048 (Table 10-4,
        L2930-2937), sampled at the last conversion: PX 4 kHz, SX 770 Hz x 8 / GT_SetAdcChn's channels (L2939-2943).
        The voltages are the machine's, ``card_io.of(card).adc_volts`` (L4132-4142)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        if not _int_in(channel, 1, 8):
            return self._param(-1), 0
        rate = 4000.0 if self.variant == "PX" else 770.0 * 8 / self._slot.adc_chn
        t = math.floor(self._card.tick * self._card.servo_period_s * rate) / rate
        v = card_io.of(self._card).volts(int(channel) - 1, t)
        return RTN_SUCCESS, max(-2048, min(2047, math.floor(v / 10.0 * 2048)))

    def GT_SetAdcChn(self, channel) -> int:
        """Number of A/D channels converted, 1..8 (SX; default 8, decision GF7): fewer channels, faster sampling,
        one channel 8 x 770 Hz = 6.16 kHz (L5447-5455, L2941-2943)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(channel, 1, 8):
            return self._param(-1)
        self._slot.adc_chn = int(channel)
        return RTN_SUCCESS

    def GT_SetSpindleVel(self, vel) -> int:
        """Spindle speed: the 16-bit spindle DAC, -32768..32767 for -10..+10 V, output from now on (SV,
        L5724-5734); the machine reads ``card_io.of(card).spindle_volts`` (V = vel x 10 / 32768)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(vel, -32768, 32767):
            return self._param(-1)
        card_io.of(self._card).spindle_volts = int(vel) * 10.0 / 32768
        return RTN_SUCCESS

    def GT_CloseSpindle(self) -> int:
        """Spindle output off: 0 V (SV, L3885-3893)."""
        if self._card is None:
            return RTN_COMM_ERROR
        card_io.of(self._card).spindle_volts = 0.0
        return RTN_SUCCESS

    def GT_EncPos(self, encoder):
        """(rtn, position of auxiliary encoder 1 or 2, pulse) (SX, L4002-4023): the machine's
        ``card_io.of(card).aux_encoders`` (whole counts)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        if not _int_in(encoder, 1, 2):
            return self._param(-1), 0
        enc = card_io.of(self._card).aux_encoders[int(encoder) - 1]
        return RTN_SUCCESS, 0 if enc is None else enc.counts(self._card.tick * self._card.servo_period_s)

    # -- not simulated (UNSUPPORTED) -------------------------------------------------------------------------------
    def GT_HandWheel(self, axis, ratio) -> int:
        """Returns 1: not simulated (UNSUPPORTED; SX, L4839-4853)."""
        return self._not_simulated()

    def GT_ExitHWheel(self) -> int:
        """Returns 1: not simulated (UNSUPPORTED; SX, L4086-4092)."""
        return self._not_simulated()

    def GT_Axis(self, num) -> int:
        """Returns 1: not in the GE command set (UNSUPPORTED)."""
        return self._not_simulated()


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
