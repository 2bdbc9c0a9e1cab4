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
_MAX_CARDS = 16                                 # L4299-4339

# The GE commands, described once in C++ (vendor/googol/ge_commands.hpp, decision GW3): (name, parameters, command
# set, read, docstring). A command of the other variant's set returns 1 (SX: command-error bit 14, Table 2-4).
_TABLE = _core.ge_command_table()
_PX_ONLY = frozenset(row[0] for row in _TABLE if row[2] == "PX")
_SX_ONLY = frozenset(row[0] for row in _TABLE if row[2] == "SX")
_READS = frozenset(row[0] for row in _TABLE if row[3])
# The commands C++ runs with their argument checks (vendor/googol/ge_axis_commands.cpp, decision GW1).
_CPP = frozenset(_core.ge_axis_command_names())


def _int_in(value, lo, hi) -> bool:
    v = _num(value)
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


def _num(value) -> float:
    """A manual argument as the double the C++ vendor modules take: a bool or a non-number is NaN (outside every
    range, so the card answers with the manual's code for a bad value)."""
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
        if not lo <= _num(servo_period_s) <= hi:
            raise ValueError(f"GeController.servo_period_s = {servo_period_s} is outside the allowed range "
                             f"{lo:g}..{hi:g} s (decision V86)")
        self.variant = variant
        self.axes = int(axes)
        self.servo_period_s = float(servo_period_s)
        self._slots: dict[int, _Slot] = {}
        self._current = 0
        self._hook = None
        self._lock = threading.Lock()

    if TYPE_CHECKING:  # the GT_* methods are made from the rows (_TABLE) after the class statement
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

    def _cpp(self, name, *args):
        """GE command ``name`` run by C++ with its argument checks (vendor/googol/ge_commands.hpp): its code, or
        (code, value) for a read; -1 without a card."""
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if _is_read(name) else RTN_COMM_ERROR
        return _core.ge_command(self._card.kernel, self.variant, name, _nums(*args))

    def _bad(self, read=False):
        """A card-wide illegal parameter: recorded (GT_GetCmdSts), 7."""
        self._card.record_fault(-1, "illegal_control_param")
        return (RTN_PARAMETER_ERROR, 0) if read else RTN_PARAMETER_ERROR

    def _io(self, ok, fn, read=False):
        """A command on the machine's I/O model (servobench.card_io): -1 without a card, 7 for `ok` False, else fn()."""
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        return fn() if ok else self._bad(read)

    def _not_simulated(self, read=False):
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        self._card.record_fault(-1, "not_simulated")
        return (RTN_COMMAND_ERROR, 0) if read else RTN_COMMAND_ERROR

    def _adc(self, channel):
        rate = 4000.0 if self.variant == "PX" else 770.0 * 8 / self._regs().adc_channels()
        t = math.floor(self._card.tick * self._card.servo_period_s * rate) / rate
        v = card_io.of(self._card).volts(int(channel) - 1, t)
        return RTN_SUCCESS, max(-2048, min(2047, math.floor(v / 10.0 * 2048)))

    def _aux_encoder(self, encoder):
        enc = card_io.of(self._card).aux_encoders[int(encoder) - 1]
        return RTN_SUCCESS, 0 if enc is None else enc.counts(self._card.tick * self._card.servo_period_s)

    def _spindle(self, volts):
        card_io.of(self._card).spindle_volts = volts
        return RTN_SUCCESS

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
            return self._cpp("GT_GetPrfVel", *axis) if len(axis) == 1 else (RTN_PARAMETER_ERROR, 0)
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


# The rows of the C++ table (name, parameters, set, read, doc) whose adapter is not the C++ command runner.
_PY = {  # the commands whose adapter is Python's: the SX list (one call into GeList), the machine's I/O, the watch
    "GT_SetWatch": lambda c, config, size: _ge_watch.GT_SetWatch(c, config, size),
    "GT_StartWatch": lambda c, n: _ge_watch.GT_StartWatch(c, n),
    "GT_GetWatch": lambda c, buffer: _ge_watch.GT_GetWatch(c, buffer),
    "GT_StopWatch": lambda c: _ge_watch.GT_StopWatch(c),
    "GT_LnXY": lambda c, x, y: c._sx(lambda L: L.line(_nums(x, y), False)),
    "GT_LnXYZ": lambda c, *p: c._sx(lambda L: L.line(_nums(*p), False)),
    "GT_LnXYZA": lambda c, *p: c._sx(lambda L: L.line(_nums(*p), False)),
    "GT_LnXYG0": lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)),
    "GT_LnXYZG0": lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)),
    "GT_LnXYZAG0": lambda c, *p: c._sx(lambda L: L.line(_nums(*p), True)),
    "GT_ArcXY": lambda c, *p: c._sx(lambda L: L.arc_center("xy", *_nums(*p))),
    "GT_ArcYZ": lambda c, *p: c._sx(lambda L: L.arc_center("yz", *_nums(*p))),
    "GT_ArcZX": lambda c, *p: c._sx(lambda L: L.arc_center("zx", *_nums(*p))),
    "GT_ArcXYP": lambda c, *p: c._sx(lambda L: L.arc_radius("xy", *_nums(*p))),
    "GT_ArcYZP": lambda c, *p: c._sx(lambda L: L.arc_radius("yz", *_nums(*p))),
    "GT_ArcZXP": lambda c, *p: c._sx(lambda L: L.arc_radius("zx", *_nums(*p))),
    "GT_SetSynVel": lambda c, vel: c._sx(lambda L: L.set_syn_vel(_num(vel))),
    "GT_SetSynAcc": lambda c, acc: c._sx(lambda L: L.set_syn_acc(_num(acc))),
    "GT_SetStrtVel": lambda c, vel: c._sx(lambda L: L.set_strt_vel(_num(vel))),
    "GT_SetMaxVel": lambda c, vel: c._sx(lambda L: L.set_max_vel(_num(vel))),
    "GT_SetStpAcc": lambda c, acc: c._sx(lambda L: L.set_stp_acc(_num(acc))),
    "GT_Override": lambda c, override: c._sx(lambda L: L.set_override(_num(override), False)),
    "GT_OverrideG0": lambda c, override: c._sx(lambda L: L.set_override(_num(override), True)),
    "GT_SetDccVel": lambda c, vel: c._sx(lambda L: L.set_dcc_vel(_num(vel))),
    "GT_MapCnt": lambda c, *p: c._sx(lambda L: L.map_cnt(*_nums(*p))),
    "GT_StrtList": lambda c: c._sx(lambda L: L.strt_list()),
    "GT_MvXY": lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
    "GT_MvXYZ": lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
    "GT_MvXYZA": lambda c, *p: c._sx(lambda L: L.mv(_nums(*p[:-2]), *_nums(*p[-2:]))),
    "GT_EndList": lambda c: c._sx(lambda L: L.end_list()),
    "GT_AddList": lambda c: c._sx(lambda L: L.add_list()),
    "GT_StrtMtn": lambda c: c._sx(lambda L: L.strt_mtn()),
    "GT_StpMtn": lambda c: c._sx(lambda L: L.stp_mtn(False)),
    "GT_EStpMtn": lambda c: c._sx(lambda L: L.stp_mtn(True)),
    "GT_RestoreMtn": lambda c: c._sx(lambda L: L.restore_mtn()),
    "GT_BufIO": lambda c, io_status: c._sx(lambda L: L.buf_io(_num(io_status))),
    "GT_BufIOBit": lambda c, *p: c._sx(lambda L: L.buf_io_bit(*_nums(*p))),
    "GT_Delay": lambda c, delay_time: c._sx(lambda L: L.delay(_num(delay_time))),
    "GT_GetCrdSts": lambda c: c._sx(lambda L: (RTN_SUCCESS, L.crd_status()), read=True),
    "GT_GetPrfPnt": lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(0)), read=True),
    "GT_GetSegPnt": lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(1)), read=True),
    "GT_GetBrkPnt": lambda c: c._sx(lambda L: (RTN_SUCCESS, L.point(2)), read=True),
    "GT_GetMtnNm": lambda c: c._sx(lambda L: (RTN_SUCCESS, L.mtn_nm()), read=True),
    "GT_InitLookAhead": lambda c, *p: c._sx(lambda L: L.init_look_ahead(*_nums(*p))),
    "GT_AddLookData": lambda c, code, plane_group, r, x, y, z, vel, cx, cy, i, n, flag: c._sx(
        lambda L: L.add_look_data(int(code), int(plane_group), *_nums(r, x, y, z, vel, cx, cy), int(n), bool(flag))),
    "GT_CalVel": lambda c: c._sx(lambda L: L.cal_vel()) if c._card is not None else (RTN_COMM_ERROR, 0.0, 0),
    "GT_InitLookAheadEx": lambda c, *p: c._sx(lambda L: L.init_look_ahead_ex(*_nums(*p))),
    "GT_InitLookAheadExx": lambda c, *p: c._sx(lambda L: L.init_look_ahead_ex(*_nums(*p))),
    "GT_MvXYEx": lambda c, *p: c._sx(lambda L: L.mv_ex(_nums(*p[:-1]), _num(p[-1]))),
    "GT_MvXYZEx": lambda c, *p: c._sx(lambda L: L.mv_ex(_nums(*p[:-1]), _num(p[-1]))),
    "GT_LnXYEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(_nums(*p[:-4]), *_nums(*p[-4:-1]), False, m)),
    "GT_LnXYZEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(_nums(*p[:-4]), *_nums(*p[-4:-1]), False, m)),
    "GT_LnXYG0Ex": lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(_nums(*p[:-4]), *_nums(*p[-4:-1]), True, m)),
    "GT_LnXYZG0Ex": lambda c, *p: c._ex(p[-1], lambda L, m: L.line_ex(_nums(*p[:-4]), *_nums(*p[-4:-1]), True, m)),
    "GT_ArcXYEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_center_ex("xy", *_nums(*p[:-1]), m)),
    "GT_ArcYZEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_center_ex("yz", *_nums(*p[:-1]), m)),
    "GT_ArcZXEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_center_ex("zx", *_nums(*p[:-1]), m)),
    "GT_ArcXYPEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_radius_ex("xy", *_nums(*p[:-1]), m)),
    "GT_ArcYZPEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_radius_ex("yz", *_nums(*p[:-1]), m)),
    "GT_ArcZXPEx": lambda c, *p: c._ex(p[-1], lambda L, m: L.arc_radius_ex("zx", *_nums(*p[:-1]), m)),
    "GT_BufIOEx": lambda c, value: c._sx(lambda L: L.buf_io_ex(_num(value))),
    "GT_BufIOBitEx": lambda c, *p: c._sx(lambda L: L.buf_io_bit_ex(*_nums(*p))),
    "GT_DelayEx": lambda c, time: c._sx(lambda L: L.delay_ex(_num(time))),
    "GT_M30": lambda c, pMsg: c._ex(pMsg, lambda L, m: L.m30(m)),
    "GT_GetAdc": lambda c, channel: c._io(_int_in(channel, 1, 8), lambda: c._adc(channel), read=True),
    "GT_SetSpindleVel": lambda c, vel: c._io(_int_in(vel, -32768, 32767), lambda: c._spindle(int(vel) * 10.0 / 32768)),
    "GT_CloseSpindle": lambda c: c._io(True, lambda: c._spindle(0.0)),
    "GT_EncPos": lambda c, encoder: c._io(_int_in(encoder, 1, 2), lambda: c._aux_encoder(encoder), read=True),
    "GT_HandWheel": lambda c, axis, ratio: c._not_simulated(),
    "GT_ExitHWheel": lambda c: c._not_simulated(),
    "GT_Axis": lambda c, num: c._not_simulated(),
}
for _name, _params, _set, _read, _doc in _TABLE:  # the generator: one method per row of the C++ table
    setattr(GeController, _name, _adapter(_name, _params, _PY.get(_name, lambda c, *p, _n=_name: c._cpp(_n, *p)), _doc))
assert {row[0] for row in _TABLE} <= set(_PY) | _CPP, "each GE row has an adapter"
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
