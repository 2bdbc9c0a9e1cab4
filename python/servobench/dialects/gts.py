"""The Googol GUC-ECAT / iDEABOX advanced functions (GUC-ECAT manual seed 002, iDEABOX manual seed 003) on the
virtual :class:`~servobench.Card`: coordinate systems with FIFO0/FIFO1, buffered commands and look-ahead, PVT
tables, the FollowEx cam, and the basic calls their example programs use.

Vendor names and argument order (the ``CardNo`` argument of the iDEABOX ``...Mx`` forms is left out, as in the
GUC-ECAT library); axes/profiles from 1, crd 1..2, fifo 0..1; units pulse, ms, pulse/ms, pulse/ms^2. Every call
returns the manuals' code (GUC Tab 2-1 L165-180, iDEABOX Table 3-1 L333-361): 0 success, 1 command error (the
card refused it in its present state; nothing changed), 7 parameter error, -1 no card open, -6 the card is
already open. A read call returns a tuple ``(rtn, value...)``.

This module only translates, as a table of rows: the behaviour (the FIFOs, look-ahead, PVT and cam engines, safety)
is the Card's; the set-up commands are C++ vendor functions that check their arguments and return the code
(``vendor/googol/gts_commands.hpp``). The servo tick is the clock, ms converted with its period. The configuration and
``...Mx`` forms are in ``_gts_config.py``, the GUC motion program (threads on the card) in ``_gts_program.py``
(mixins of :class:`GtsController`); :data:`UNSUPPORTED` names the calls the simulation cannot carry out.

Quick use (GUC L802-843, the hexagon)::

    import servobench as sb
    from servobench.dialects import gts

    gts.GT_Open(sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=1e-3))
    gts.GT_AxisOn(1); gts.GT_AxisOn(2)
    gts.GT_SetCrdPrm(1, gts.TCrdPrm(dimension=2, profile=[1, 2], synVelMax=500, synAccMax=1))
    gts.GT_LnXY(1, 200000, 0, 100, 0.1)
    gts.GT_CrdStart(1, 0)
    gts.wait_until(lambda: gts.GT_CrdStatus(1)[1] == 0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import _core
from .._core import CardCommandRefused, MotionCommandRefused
from ..card import Card
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401
from ._gts_config import (FOLLOW_SWITCH_SEGMENT, FOLLOW_SWITCH_TABLE, MC_ARRIVE, UNSUPPORTED_CONFIG,  # noqa: F401
                          GtsConfigMixin, TJogPrmExt, TTrapPrm, _f, _nums, attach_mx_forms)
from ._gts_config import gts_row as _cpp
from ._gt_system import gt_adapter
from ._gts_program import UNSUPPORTED_PROGRAM, GtsProgramMixin, TCompileInfo, TThreadSts, TVarInfo  # noqa: F401

# Return codes (GUC Tab 2-1 L165-180; iDEABOX Table 3-1 L333-361).
RTN_SUCCESS = 0
RTN_COMMAND_ERROR = 1
RTN_LICENSE_ERROR = 2
RTN_PARAMETER_ERROR = 7
RTN_COMM_ERROR = -1
RTN_OPEN_ERROR = -6

# Buffered IO types (GUC L588-597; gts.h MC_ENABLE 10, MC_CLEAR 11, MC_GPO 12) -> the interpolator's doType.
MC_ENABLE, MC_CLEAR, MC_GPO = 10, 11, 12
_DO_TYPE = {MC_GPO: 0, MC_ENABLE: 1, MC_CLEAR: 2}
# Limit and stop-input types (GUC L253-266, L638-645).
MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI = 0, 1, 2, 3, 4
# FollowEx (iDEABOX L516-542, L7345-7363).
FOLLOW_SEGMENT_NORMAL, FOLLOW_SEGMENT_EVEN, FOLLOW_SEGMENT_STOP, FOLLOW_SEGMENT_CONTINUE = 0, 1, 2, 3
FOLLOW_MASTER_ENCODER, FOLLOW_MASTER_PROFILE, FOLLOW_MASTER_AXIS = 1, 2, 3
FOLLOW_EVENT_START, FOLLOW_EVENT_PASS = 1, 2

_POS_MIN, _POS_MAX = -1073741824, 1073741823  # iDEABOX L3829 (GUC L449: +-1073741823)


def _num(v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) else None


def _int_in(v, lo, hi) -> bool:
    x = _num(v)
    return x is not None and x == int(x) and lo <= x <= hi


def _open_in(v, lo, hi) -> bool:
    """lo < v < hi (the manuals' (0, 32767) ranges)."""
    x = _num(v)
    return x is not None and lo < x < hi


def _half_open(v, lo, hi) -> bool:
    """lo <= v < hi."""
    x = _num(v)
    return x is not None and lo <= x < hi


@dataclass
class TCrdPrm:
    """TCrdPrm (GUC L371-388, iDEABOX L7113-7164): dimension 1..4; profile[k] = coordinate (1 X .. 4 A, 0 none)
    of profile k+1; synVelMax (0, 32767) pulse/ms; synAccMax (0, 32767) pulse/ms^2; evenTime [0, 32767) ms;
    setOriginFlag 0 (origin = present profile positions) / 1 (origin = originPos, pulse)."""

    dimension: int = 2
    profile: list = field(default_factory=lambda: [0] * 8)
    synVelMax: float = 0.0
    synAccMax: float = 0.0
    evenTime: int = 0
    setOriginFlag: int = 0
    originPos: list = field(default_factory=lambda: [0] * 8)


class GtsController(GtsConfigMixin, GtsProgramMixin, DialectController):
    """One GUC-ECAT / iDEABOX program's view of a :class:`~servobench.Card` (its advanced functions)."""

    # -- plumbing -------------------------------------------------------------------------------------------
    def _do(self, fn, *args) -> int:
        return self._googol_do(fn, *args)

    def _get(self, fn, n_out=1):
        if self._card is None:
            return (RTN_COMM_ERROR,) + (0,) * n_out
        try:
            v = fn()
        except (CardCommandRefused, MotionCommandRefused):
            return (RTN_COMMAND_ERROR,) + (0,) * n_out
        except ValueError:
            return (RTN_PARAMETER_ERROR,) + (0,) * n_out
        return (RTN_SUCCESS,) + (v if isinstance(v, tuple) else (v,))

    def _bad(self) -> int:
        return RTN_COMM_ERROR if self._card is None else RTN_PARAMETER_ERROR

    @property
    def _ms(self) -> float:
        """The servo tick in ms (pulse/ms -> pulse/tick factor)."""
        return self._card.servo_period_s * 1e3

    def _fifo(self, crd, fifo):
        return self._card.crd(int(crd)).fifo(int(fifo))

    def _seg_ok(self, vel, acc, vel_end=0.0) -> bool:
        # synVel, synAcc (0, 32767); velEnd [0, 32767) (GUC L449-481, iDEABOX L3845-3852)
        return _open_in(vel, 0, 32767) and _open_in(acc, 0, 32767) and _half_open(vel_end, 0, 32767)

    def _push(self, crd, fifo, push) -> int:
        """Runs a buffered push on (crd, fifo) with the manuals' codes: 7 for a bad geometry or look-ahead on a
        4-D crd (GUC L985, iDEABOX L2012-2014), 1 for a refused state (full FIFO, FIFO1 while FIFO0 moves)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(crd, 1, 2) or not _int_in(fifo, 0, 1):
            return RTN_PARAMETER_ERROR
        rtn = self._gts().check_push(int(crd), int(fifo))  # 1 crd not set up, 7 look-ahead on a 4-D crd
        return rtn or self._do(push, self._fifo(crd, fifo))

    def _outside(self, crd, axis, ok, push, fifo) -> int:
        """A buffered command of an axis outside the crd (GUC L647, L1052-1060): 7 for a bad value or axis or an
        axis of the crd itself, else :meth:`_push`."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not ok or not _int_in(axis, 1, min(8, len(self._card))) \
                or (_int_in(crd, 1, 2) and self._card.group_of(int(axis) - 1) == int(crd) - 1):
            return RTN_PARAMETER_ERROR
        return self._push(crd, fifo, push)

    # -- system and basic axis calls used by the examples ---------------------------------------------------
    def GT_Open(self, card: Card | None = None, **axis_parts) -> int:
        """Opens the controller: ``card``, else the machine :meth:`use_machine` set (issue 25.2), else a new
        8-axis :class:`~servobench.Card` from ``axis_parts`` (GUC 8 axes, L250). A second open without close
        returns -6 (GUC L176)."""
        if self._card is not None:
            return RTN_OPEN_ERROR
        if card is None and not axis_parts:
            card = self._machine_card()
        self._card = card if card is not None else Card(8, **axis_parts)
        return RTN_SUCCESS

    def GT_Close(self) -> int:
        """Closes the controller."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._close_program()
        self._card = None
        return RTN_SUCCESS

    def GT_Reset(self) -> int:
        """Resets the controller (card reset: no crd, PVT or cam, drives off); the motion-program threads stop
        (the downloaded program stays until power-off, GUC L2245)."""
        if self._card is not None:
            self._close_program()
        return self._do(lambda: self._card.reset())


    def _ln(self, crd, end, vel, acc, vel_end, fifo, g0):
        if self._card is None:
            return RTN_COMM_ERROR
        if not all(_int_in(p, _POS_MIN, _POS_MAX) for p in end) or not self._seg_ok(vel, acc, vel_end):
            return RTN_PARAMETER_ERROR
        return self._push(crd, fifo, lambda f: f.line([float(p) for p in end], float(vel), float(acc),
                                                      float(vel_end), g0))

    def _arc(self, crd, plane, p1, p2, shape, circle_dir, vel, acc, vel_end, fifo):
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(p1, _POS_MIN, _POS_MAX) or not _int_in(p2, _POS_MIN, _POS_MAX) \
                or circle_dir not in (0, 1) or not self._seg_ok(vel, acc, vel_end) \
                or any(_num(v) is None for v in shape):
            return RTN_PARAMETER_ERROR
        idx = {"xy": (0, 1), "yz": (1, 2), "zx": (2, 0)}[plane]

        def push(f):
            end = list(f.tail) + [0.0] * (4 - len(f.tail))
            end[idx[0]], end[idx[1]] = float(p1), float(p2)
            end = end[:max(len(f.tail), max(idx) + 1)]
            if len(shape) == 1:
                f.arc_radius(plane, end, float(shape[0]), bool(circle_dir), float(vel), float(acc), float(vel_end))
            else:
                f.arc_center(plane, end, (float(shape[0]), float(shape[1])), bool(circle_dir), float(vel),
                             float(acc), float(vel_end))

        return self._push(crd, fifo, push)

    @staticmethod
    def _arr(x, count):
        a = np.asarray(x, dtype=float)[: int(count)]
        if len(a) != int(count):
            raise ValueError(f"the arrays hold fewer than count = {count} values")
        return a

# -- the table: name, parameters, argument checks (one per parameter, None = unchecked), the call, the manual ----------
# A check is _AX (axis/profile 1..axes), _MASK (1..2^axes-1), ("int", lo, hi), ("open", lo, hi) (lo < v < hi),
# ("oc", lo, hi) (lo < v <= hi), ("num",) (finite) or a tuple of the allowed values; a failed check returns 7 (-1
# without a card); a read row returns its failure placeholders after the code.
_AX, _MASK, _CRD, _FIFO, _NUM = "axis", "mask", ("int", 1, 2), ("int", 0, 1), ("num",)
_I32 = ("int", -2**31, 2**31 - 1)


def _check(self, spec, value, args) -> bool:
    n = len(self._card)
    if callable(spec):
        return spec(n, value, args)
    if spec == _AX:
        return _int_in(value, 1, n)
    if spec == _MASK:
        return _int_in(value, 1, (1 << n) - 1)
    kind = spec[0] if spec and isinstance(spec[0], str) else "in"
    x = _num(value) if kind != "in" else None
    return {"int": lambda: _int_in(value, *spec[1:]), "open": lambda: _open_in(value, *spec[1:]),
            "oc": lambda: x is not None and spec[1] < x <= spec[2], "num": lambda: x is not None,
            "in": lambda: value in spec}[kind]()


def _row(name, params, checks, call, doc, read=None):
    """A GTS method: checks, then ``call(self, card, *args)`` run the Googol way (a command's code, or a read's
    (0, value...)); ``read`` the failure placeholders of a read (None: a command)."""
    def body(self, *args):
        if self._card is None or not all(s is None or _check(self, s, a, args) for s, a in zip(checks, args)):
            code = RTN_COMM_ERROR if self._card is None else RTN_PARAMETER_ERROR
            return code if read is None else (code, *read)
        if read is None:
            return self._do(lambda: call(self, self._card, *args))
        return self._get(lambda: call(self, self._card, *args), len(read))

    return gt_adapter(name, params, body, doc, "int" if read is None else None, "GtsController",
                      "servobench.dialects.gts")


def _raw(name, params, body, doc):
    """A GTS command whose body checks its own arguments (a path or buffered command over _ln / _arc / _push)."""
    return gt_adapter(name, params, body, doc, "int", "GtsController", "servobench.dialects.gts")


def _vec(x) -> np.ndarray:
    """A manual's array argument as float64 values; a non-numeric one as no values (count then exceeds it: 7)."""
    try:
        return np.asarray(x, dtype=float).ravel()
    except (TypeError, ValueError):
        return np.empty(0)


def _crd_args(p) -> list:
    """A TCrdPrm's fields as the C++ call takes them (a missing field as NaN / no values: 7)."""
    return [_f(getattr(p, "dimension", None)), _vec(getattr(p, "profile", ())),
            *(_f(getattr(p, n, None)) for n in ("synVelMax", "synAccMax", "evenTime", "setOriginFlag")),
            _vec(getattr(p, "originPos", ()))]


def _trap(acc, dec, vel_start, smooth_time):
    """(acc, dec, velStart, smoothTime) of scalars or of a TTrapPrm passed as ``acc``; dec None = acc (V61)."""
    if isinstance(acc, TTrapPrm):
        return acc.acc, acc.dec, acc.velStart, acc.smoothTime
    return acc, acc if dec is None else dec, vel_start, smooth_time


def _jog(acc, dec, smooth):
    """(acc, dec, smooth) of scalars or of a TJogPrmExt passed as ``acc`` (its dec 0 = acc)."""
    if isinstance(acc, TJogPrmExt):
        acc, dec, smooth = acc.acc, (acc.dec or None), acc.smooth
    return acc, acc if dec is None else dec, smooth


def _crd_prm(rtn, *fields):
    """GT_GetCrdPrm's (rtn, TCrdPrm); (1, 0) when the crd is not set up, (7 or -1, None) for a bad call."""
    return (rtn, TCrdPrm(*fields)) if rtn == 0 else (rtn, 0 if rtn == RTN_COMMAND_ERROR else None)


def _follow(c, profile, **changes):
    a = int(profile) - 1
    c.follow_configure(a, c.follow(a).setup.replace(**changes))


_COUNT = (lambda n, v, args: _int_in(v, 1, n - int(args[0]) + 1))  # count axes from axis
_SEG = "crd, x, y, synVel, synAcc, velEnd=0, fifo=0"
_ROWS = [
    # profiles, stops, coordinate systems and PVT tables: C++ vendor functions (gts_commands.hpp) check and code
    _cpp("GT_SetTrapPrm", "profile, acc, dec=None, velStart=0, smoothTime=0",
         lambda k, p, acc, dec, vs, st: _core.gts_set_trap_prm(k, *_nums(p, *_trap(acc, dec, vs, st))),
         "TTrapPrm acc (and dec), pulse/ms^2 > 0, as scalars or a :class:`TTrapPrm` as ``acc`` (GUC L2898-2908 "
         "reads it with GT_GetTrapPrm and writes it back). One acceleration for both ramps: dec is taken equal to "
         "acc (decision V61); velStart and smoothTime must be 0."),
    _cpp("GT_SetJogPrm", "profile, acc, dec=None, smooth=0",
         lambda k, p, acc, dec, sm: _core.gts_set_jog_prm(k, *_nums(p, *_jog(acc, dec, sm))),
         "Jog acc (dec taken equal, V61), pulse/ms^2 > 0, smooth 0..1 (recorded, GS17): scalars or a "
         ":class:`TJogPrmExt` as ``acc`` (iDEABOX Ex 4-1 L726-730)."),
    _cpp("GT_Stop", "mask, option=0", lambda k, m, o: _core.gts_stop(k, *_nums(m, o)),
         "Stops the masked axes (bit k = axis k+1) and coordinate systems (bit 12 = crd 1, 13 = crd 2, iDEABOX "
         "L1793); option bit set = abrupt, clear = smooth (at the GT_SetStopDec deceleration, GS7). A stopped crd "
         "keeps its breakpoint (resume with GT_CrdStart)."),
    _cpp("GT_SetCrdPrm", "crd, prm: TCrdPrm", lambda k, crd, p: _core.gts_set_crd_prm(k, _f(crd), *_crd_args(p)),
         "Sets up coordinate system ``crd`` (1..2) from a :class:`TCrdPrm` (GUC L369-388, L736-792; iDEABOX "
         "L7095-7176). 7 for values out of range or a profile mapped twice (L785); 1 while a mapped axis moves or "
         "is in the other crd (L743, L7168-7174)."),
    _cpp("GT_GetCrdPrm", "crd", lambda k, crd: _crd_prm(*_core.gts_get_crd_prm(k, _f(crd))),
         "(rtn, TCrdPrm) of ``crd``; (1, 0) when it is not set up.", (None,)),
    _cpp("GT_InitLookAhead", "crd, fifo, T, accMax, n, pLookAheadBuf=None",
         lambda k, crd, f, t, a, n, buf: _core.gts_init_lookahead(k, *_nums(crd, f, t, a, n)),
         "Look-ahead on a FIFO: corner time T (0, 1000] ms, accMax (0, 32767] pulse/ms^2, window n 0..32766 "
         "segments (0 = off) (GUC L725-732, L908-995; iDEABOX L5848-5879). The buffer argument is not used."),
    _cpp("GT_CrdData", "crd, pCrdData=None, fifo=0",
         lambda k, crd, d, f: _core.gts_crd_data(k, _f(crd), d in (None, 0), _f(f)),
         "With pCrdData None (NULL): moves the look-ahead window into the FIFO; 1 when the FIFO filled first (call "
         "again after GT_CrdSpace) (GUC L975-977; iDEABOX L4465-4498). Raw TCrdData records: not simulated (7)."),
    _cpp("GT_PvtTable", "tableId, count, pTime, pPos, pVel", lambda k, i, n, t, p, v: _core.gts_pvt_table(
        k, _f(i), _f(n), _vec(t), _vec(p), _vec(v)),
         "PVT data, the first ``count`` points (ms, pulse, pulse/ms), replaces table 1..32 (GUC L1169; iDEABOX "
         "L6404)."),
    _cpp("GT_PvtTableEx", "tableId, count, pTime, pPos, pVelBegin, pVelEnd",
         lambda k, i, n, t, p, vb, ve: _core.gts_pvt_table_ex(k, _f(i), _f(n), *map(_vec, (t, p, vb, ve))),
         "PVT-Ex data with a begin and an end velocity per point, pulse/ms (iDEABOX L6446-6472)."),
    _cpp("GT_PvtTableComplete", "tableId, count, pTime, pPos, pA=None, pB=None, pC=None, velBegin=0, velEnd=0",
         lambda k, i, n, t, p, pa, pb, pc, vb, ve: _core.gts_pvt_table_complete(
             k, _f(i), _f(n), _vec(t), _vec(p), _f(vb), _f(ve)),
         "Complete data (t ms, p pulse) with velBegin / velEnd pulse/ms: C2 spline (GUC L1181-1191; iDEABOX "
         "L6585). pA/pB/pC are the manual's work arrays (not used)."),
    _cpp("GT_PvtTablePercent", "tableId, count, pTime, pPos, pPercent, velBegin=0",
         lambda k, i, n, t, p, q, vb: _core.gts_pvt_table_percent(k, _f(i), _f(n), _vec(t), _vec(p), _vec(q), _f(vb)),
         "Percent data: times ms, positions pulse, percent 0..100 (GUC L1436-1457; iDEABOX L6931)."),
    gt_adapter("GT_PvtPercentCalculate", "count, pTime, pPos, pPercent, velBegin=0",
               lambda s, n, t, p, q, vb: tuple(_core.gts_pvt_percent_calculate(_f(n), _vec(t), _vec(p), _vec(q),
                                                                              _f(vb))),
               "(rtn, node velocities pulse/ms) of Percent data, nothing downloaded; (7, None) for bad data (GUC "
               "L1436; iDEABOX L6259).", None, "GtsController", "servobench.dialects.gts"),
    _cpp("GT_PvtTableContinuous", "tableId, count, pPos, pVel, pPercent, pVelMax, pAcc, pDec, timeBegin=0",
         lambda k, i, n, p, v, q, vm, a, d, tb: _core.gts_pvt_table_continuous(
             k, _f(i), _f(n), *map(_vec, (p, v, q, q, vm, a, d)), _f(tb), False),
         "Continuous data (p pulse, v pulse/ms, percent, vMax pulse/ms, acc/dec pulse/ms^2 per point), start at "
         "timeBegin ms (GUC L1475-1504; iDEABOX L6690)."),
    _cpp("GT_PvtTableContinuousEx", "tableId, count, pPos, pVel, pAccPercent, pDecPercent, pVelMax, pAcc, pDec, "
         "timeBegin=0", lambda k, i, n, p, v, qa, qd, vm, a, d, tb: _core.gts_pvt_table_continuous(
             k, _f(i), _f(n), *map(_vec, (p, v, qa, qd, vm, a, d)), _f(tb), True),
         "Continuous-Ex data: as GT_PvtTableContinuous with separate S shares (0..100) for the acceleration and "
         "the deceleration phase of each segment (iDEABOX L6745-6803)."),
    gt_adapter("GT_PvtContinuousCalculate", "count, pPos, pVel, pPercent, pVelMax, pAcc, pDec",
               lambda s, n, p, v, q, vm, a, d: tuple(_core.gts_pvt_continuous_calculate(
                   _f(n), *map(_vec, (p, v, q, vm, a, d)))),
               "(rtn, point times ms, time[0] = 0) of Continuous data; (7, None) for bad data (GUC L1230; iDEABOX "
               "L6222-6251).", None, "GtsController", "servobench.dialects.gts"),
    _row("GT_AxisOn", "axis", (_AX,), lambda s, c, a: c.axis_on(int(a) - 1), "Enables the drive of ``axis`` (1..)."),
    _row("GT_AxisOff", "axis", (_AX,), lambda s, c, a: c.axis_off(int(a) - 1), "Disables the drive of ``axis``."),
    _row("GT_ClrSts", "axis, count=1", (_AX, _COUNT), lambda s, c, a, n: [c.clear_events(k, 0xFFF) for k in
                                                                          range(int(a) - 1, int(a) - 1 + int(n))],
         "Clears the latched status of ``count`` axes from ``axis`` (iDEABOX L629)."),
    _row("GT_ZeroPos", "axis, count=1", (_AX, _COUNT), lambda s, c, a, n: c.zero_pos_range(int(a) - 1, int(n)),
         "Actual (encoder) = target = profile position = 0 on ``count`` axes from ``axis`` (pulse), the mechanism "
         "unmoved (iDEABOX L647/L848; the Googol meaning, GT L5196-5206, GE L5907-5913; decision VF3): at rest "
         "only. 1 with nothing changed if any of the axes moves, runs a sequence, or is in gear or a crd; 7 for a "
         "bad axis or count."),
    _row("GT_GetSts", "axis, count=1", (_AX, None), lambda s, c, a, n: _core.gt_axis_status(c.kernel, int(a) - 1),
         "(rtn, status) of ``axis``: the card's status word (GT layout; bit 10 = 0x400 the profile moves, the only "
         "bit the GUC seed uses, L2643-2645; decision V60).", (0,)),
    _row("GT_GetPrfPos", "profile, count=1", (_AX, None), lambda s, c, p, n: wrap32(c.profile_pos(int(p) - 1)),
         "(rtn, profile position, pulse).", (0.0,)),
    _row("GT_GetPrfVel", "profile, count=1", (_AX, None),
         lambda s, c, p, n: s._gts().filtered_prf_vel(int(p) - 1) if s._gts().prf_vel_filter(int(p) - 1)
         else c.profile_vel(int(p) - 1) / s._ms,
         "(rtn, profile velocity, pulse/ms); with GT_SetAxisPrfVelFilter the mean over the last 2^exp ticks "
         "(iDEABOX L3801; GS9).", (0.0,)),
    _row("GT_GetEncPos", "axis, count=1", (_AX, None), lambda s, c, a, n: wrap32(c.actual_pos(int(a) - 1)),
         "(rtn, encoder (actual) position, pulse).", (0.0,)),
    _row("GT_PrfTrap", "profile", (_AX,), lambda s, c, p: c.set_mode(int(p) - 1, "t_curve"),
         "Point-to-point (trapezoid) mode (refused while moving)."),
    _row("GT_PrfJog", "profile", (_AX,), lambda s, c, p: c.set_mode(int(p) - 1, "jog"), "Jog mode (refused while "
         "moving)."),
    _row("GT_SetVel", "profile, vel", (_AX, _NUM), lambda s, c, p, v: c.stage_vel(int(p) - 1, float(v) * s._ms),
         "Target velocity, pulse/ms (signed in jog mode) (staged)."),
    _row("GT_SetPos", "profile, pos", (_AX, ("int", _POS_MIN, _POS_MAX)),
         lambda s, c, p, x: c.stage_pos(int(p) - 1, float(x)), "Target position, pulse (staged)."),
    _row("GT_Update", "mask", (_MASK,), lambda s, c, m: c.update(int(m)), "Starts the staged motion of the masked "
         "axes (bit k = axis k+1)."),
    # coordinate systems (GUC §4.1 L313-1114, iDEABOX §4.3)
    _raw("GT_LnXY", _SEG, lambda s, crd, x, y, v, a, ve, f: s._ln(crd, (x, y), v, a, ve, f, False),
         "Line to (x, y) absolute, pulse; synVel pulse/ms, synAcc pulse/ms^2, velEnd (ignored under look-ahead) "
         "(GUC L449-481; iDEABOX L5881)."),
    _raw("GT_LnXYZ", "crd, x, y, z, synVel, synAcc, velEnd=0, fifo=0",
         lambda s, crd, x, y, z, v, a, ve, f: s._ln(crd, (x, y, z), v, a, ve, f, False), "3-D line (iDEABOX L5975)."),
    _raw("GT_LnXYZA", "crd, x, y, z, a, synVel, synAcc, velEnd=0, fifo=0",
         lambda s, crd, x, y, z, w, v, a, ve, f: s._ln(crd, (x, y, z, w), v, a, ve, f, False),
         "4-D line (iDEABOX L6026); no look-ahead on a 4-D crd (7)."),
    _raw("GT_LnXYG0", "crd, x, y, synVel, synAcc, fifo=0",
         lambda s, crd, x, y, v, a, f: s._ln(crd, (x, y), v, a, 0, f, True),
         "G0 line: ends at rest even under look-ahead (GUC L322-327, iDEABOX L1594-1606)."),
    _raw("GT_LnXYZG0", "crd, x, y, z, synVel, synAcc, fifo=0",
         lambda s, crd, x, y, z, v, a, f: s._ln(crd, (x, y, z), v, a, 0, f, True), "3-D G0 line."),
    _raw("GT_LnXYZAG0", "crd, x, y, z, a, synVel, synAcc, fifo=0",
         lambda s, crd, x, y, z, w, v, a, f: s._ln(crd, (x, y, z, w), v, a, 0, f, True), "4-D G0 line."),
    *[_raw(f"GT_Arc{pl.upper()}R", f"crd, {u}, {w}, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0",
           (lambda plane: lambda s, crd, p1, p2, r, d, v, a, ve, f: s._arc(crd, plane, p1, p2, (r,), d, v, a, ve,
                                                                             f))(pl),
           f"{pl.upper()} arc to the end point with radius (> 0: <= 180 deg, < 0: > 180 deg), circleDir 0 CW / 1 "
           f"CCW; 7 when no such arc exists (GUC L509-587, L892, L906; iDEABOX L{line}).")
      for pl, u, w, line in (("xy", "x", "y", 3874), ("yz", "y", "z", 4002), ("zx", "z", "x", 4131))],
    *[_raw(f"GT_Arc{pl.upper()}C", f"crd, {u}, {w}, {u}Center, {w}Center, circleDir, synVel, synAcc, velEnd=0, fifo=0",
           (lambda plane: lambda s, crd, p1, p2, c1, c2, d, v, a, ve, f: s._arc(crd, plane, p1, p2, (c1, c2), d, v,
                                                                                  a, ve, f))(pl),
           f"{pl.upper()} arc to the end point about the centre offset from the start; end = start is a full "
           f"circle (GUC L904; iDEABOX L{line}).")
      for pl, u, w, line in (("xy", "x", "y", 3812), ("yz", "y", "z", 3941), ("zx", "z", "x", 4070))],
    _raw("GT_BufIO", "crd, doType, doMask, doValue, fifo=0",
         lambda s, crd, t, m, v, f: s._bad() if t not in _DO_TYPE or not (_int_in(m, 0, 0xFFFF) and _int_in(
             v, 0, 0xFFFF)) else s._push(crd, f, lambda q: q.buf_io(_DO_TYPE[t], int(m), int(v))),
         "Buffered digital output: MC_GPO / MC_ENABLE / MC_CLEAR, bits of doValue where doMask is 1 (GUC "
         "L588-597)."),
    _raw("GT_BufDelay", "crd, delayTime, fifo=0", lambda s, crd, t, f: s._bad() if not _int_in(t, 0, 16383)
         else s._push(crd, f, lambda q: q.buf_delay(float(t))), "Buffered dwell, ms, 0..16383 (GUC L598-602)."),
    _raw("GT_BufDA", "crd, chn, daValue, fifo=0", lambda s, crd, ch, v, f: s._bad() if not (
        _int_in(ch, 1, 8) and _int_in(v, -32768, 32767)) else s._push(crd, f, lambda q: q.buf_da(int(ch), float(v))),
         "Buffered analog output, channel 1..8, -32768..32767 (GUC L603-608)."),
    *[_raw(f"GT_BufLmts{w}", "crd, axis, limitType=-1, fifo=0", (lambda on: lambda s, crd, a, t, f: s._bad() if not (
        _int_in(a, 1, 8) and t in (-1, 0, 1)) else s._push(crd, f, lambda q: q.buf_lmts(int(a), int(t), on)))(on),
           f"Buffered limit {'enable' if on else 'disable'}: limitType 0 positive, 1 negative, -1 both (GUC "
           "L609-624).") for w, on in (("On", True), ("Off", False))],
    _raw("GT_BufSetStopIo", "crd, axis, stopType, inputType, inputIndex, fifo=0",
         lambda s, crd, a, st, it, ix, f: s._bad() if not (_int_in(a, 1, 8) and st in (0, 1) and it in range(5) and
                                                           _int_in(ix, 1, 16 if it == MC_GPI else 8))
         else s._push(crd, f, lambda q: q.buf_set_stop_io(int(a), int(st), int(it), int(ix))),
         "Buffered stop-input mapping: stopType 0 emergency / 1 smooth, inputType 0..4, index 1..8 (GPI 1..16) "
         "(GUC L625-645)."),
    _raw("GT_BufMove", "crd, moveAxis, pos, vel, acc, modal, fifo=0",
         lambda s, crd, a, p, v, ac, m, f: s._outside(crd, a, (_int_in(p, -2**31, 2**31 - 1) and _open_in(v, 0, math.inf)
                                                               and _open_in(ac, 0, math.inf) and m in (0, 1)),
                                                     lambda q: q.buf_move(int(a), float(p), float(v), float(ac),
                                                                          bool(m)), f),
         "Buffered point-to-point move of an axis outside the crd to the absolute ``pos`` (pulse) at vel (pulse/ms) "
         "and acc (pulse/ms^2); modal 1 blocks the FIFO until it ends (GUC L646-656, L1052-1055)."),
    _raw("GT_BufGear", "crd, gearAxis, pos, fifo=0",
         lambda s, crd, a, p, f: s._outside(crd, a, _int_in(p, -2**31, 2**31 - 1),
                                            lambda q: q.buf_gear(int(a), float(p)), f),
         "Buffered follow of the next segment by an axis outside the crd over the relative ``pos`` (pulse) (GUC "
         "L657-661, L1058-1060)."),
    _raw("GT_SetUserSegNum", "crd, segNum, fifo=0", lambda s, crd, n, f: s._bad() if not _int_in(n, -2**31, 2**31 - 1)
         else s._push(crd, f, lambda q: q.set_user_seg_num(int(n))), "Buffered user segment number (GUC L662-665)."),
    _row("GT_GetUserSegNum", "crd, fifo=0", (_CRD, _FIFO), lambda s, c, crd, f: int(s._fifo(crd, f).state.user_seg_num),
         "(rtn, user segment number) (GUC L666-670).", (0,)),
    _row("GT_GetRemainderSegNum", "crd, fifo=0", (_CRD, _FIFO),
         lambda s, c, crd, f: int(s._fifo(crd, f).remaining_segments), "(rtn, segments not finished) (GUC L671-675).",
         (0,)),
    _row("GT_CrdSpace", "crd, fifo=0", (_CRD, _FIFO), lambda s, c, crd, f: int(s._fifo(crd, f).fifo_space),
         "(rtn, free FIFO entries) (GUC L979).", (0,)),
    _row("GT_CrdClear", "crd, fifo=0", (_CRD, _FIFO), lambda s, c, crd, f: s._fifo(crd, f).clear(),
         "Clears a FIFO and its segment count (refused while it moves) (GUC L697-699, L855-857)."),
    _row("GT_CrdStart", "mask, option=0", (("int", 1, 3), ("int", 0, 3)), lambda s, c, m, o: c.crd_start(int(m), int(o)),
         "Starts (or resumes) the masked crds (bit 0 crd 1, bit 1 crd 2) on FIFO0 or, option bit set, FIFO1; 1 when "
         "a crd is not set up, the other FIFO moves, FIFO0 resumes away from its breakpoint (GUC L1005, iDEABOX "
         "L4560) or the e-stop / an alarm is active (GUC L684-690; iDEABOX L4527-4566)."),
    _row("GT_CrdStatus", "crd, fifo=0", (_CRD, _FIFO), lambda s, c, crd, f: tuple(c.crd_status(int(crd), int(f))),
         "(rtn, run, segment): run 1 while the FIFO interpolates, segment = segments completed since the crd was set "
         "up or cleared (GUC L692-700; iDEABOX L4574-4599).", (0, 0)),
    _row("GT_SetOverride", "crd, synVelRatio", (_CRD, ("oc", 0, 1)),
         lambda s, c, crd, r: [c.crd(int(crd)).fifo(k).set_override(float(r)) for k in (0, 1)],
         "Feed override (0, 1] (GUC L701-703; iDEABOX L7419-7441)."),
    _row("GT_SetCrdStopDec", "crd, decSmoothStop, decAbruptStop", (_CRD, ("open", 0, 32767), ("open", 0, 32767)),
         lambda s, c, crd, d1, d2: ([c.crd(int(crd)).fifo(k).set_stop_dec(float(d1), float(d2)) for k in (0, 1)],
                                    s._gts().set_crd_stop_dec(int(crd), float(d1), float(d2))),
         "Path stop decelerations, (0, 32767) pulse/ms^2 each (GUC L704-709; iDEABOX L7182-7201)."),
    _row("GT_GetCrdPos", "crd", (_CRD,), lambda s, c, crd: list(c.crd_pos(int(crd))),
         "(rtn, [dimension] crd coordinates, pulse) (GUC L5499-5519; crd = profile - origin).", ([],)),
    _row("GT_GetCrdVel", "crd", (_CRD,), lambda s, c, crd: float(c.crd_vel(int(crd))),
         "(rtn, path speed, pulse/ms) (iDEABOX L5581-5595).", (0.0,)),
    # PVT (GUC §4.2 L1116-2100, iDEABOX §4.4)
    _row("GT_PrfPvt", "profile", (_AX,), lambda s, c, p: c.set_pvt(int(p) - 1),
         "PVT mode (refused while moving) (GUC L1141; iDEABOX L6201)."),
    _row("GT_PvtTableSelect", "profile, tableId", (_AX, ("int", 1, 32)), lambda s, c, p, t: c.pvt_select(int(p) - 1,
                                                                                                         int(t)),
         "Selects the table (at rest at once, while moving at the end of the pass); 1 on an empty table (GUC L1279, "
         "L1308; iDEABOX L7030-7048)."),
    _row("GT_SetPvtLoop", "profile, loop", (_AX, ("int", 0, 2**31 - 1)),
         lambda s, c, p, n: c.pvt_loop(int(p) - 1, float(n)), "Passes, 0 = infinite (GUC L1150, L1312; iDEABOX L7443)."),
    _row("GT_GetPvtLoop", "profile", (_AX,), lambda s, c, p: tuple(c.pvt_loop_status(int(p) - 1)),
         "(rtn, passes done, loop setting) (GUC L1156-1159; iDEABOX L5765-5779).", (0, 0)),
    _row("GT_PvtStart", "mask", (_MASK,), lambda s, c, m: c.pvt_start(int(m)),
         "Starts the masked axes (bit k = axis k+1) on the same tick; 1 on an empty table or an axis not in PVT mode "
         "(GUC L1279-1310; iDEABOX L6305-6321)."),
    _row("GT_PvtStatus", "profile, count=1", (_AX, None), lambda s, c, p, n: tuple(c.pvt_status(int(p) - 1)),
         "(rtn, table id, PVT time ms) (GUC L1285-1289; iDEABOX L6374-6390).", (0, 0.0)),
    # FollowEx (iDEABOX §2.1 L394-929, API L4612-5448, L7212-7417)
    _row("GT_PrfFollowEx", "profile, dir=0", (_AX, (-1, 0, 1)),
         lambda s, c, p, d: c.set_follow(int(p) - 1, _core.FollowExSetup(dir=float(d)), 1 if int(p) == 1 else 0),
         "FollowEx mode, dir 0 both master directions, 1 positive only, -1 negative only (L6173-6199). The master is "
         "axis 1 (axis 2 for profile 1) until GT_SetFollowMasterEx (decision V62)."),
    _row("GT_SetFollowMasterEx", "profile, masterIndex, masterType=2, masterItem=0", (_AX, _AX, (1, 2, 3), (0, 1)),
         lambda s, c, p, m, t, i: (c.follow_set_master(int(p) - 1, int(m) - 1),
                                   _follow(c, p, master_type=float(t), master_item=float(i))),
         "Master axis and signal: type 1 encoder, 2 profile, 3 axis (item 0 planned / 1 encoder); masterIndex != "
         "profile (L7316-7363)."),
    _row("GT_GetFollowMasterEx", "profile", (_AX,), lambda s, c, p: (
        c.follow_master(int(p) - 1) + 1, int(c.follow(int(p) - 1).setup.master_type),
        int(c.follow(int(p) - 1).setup.master_item)), "(rtn, masterIndex, masterType, masterItem).", (0, 0, 0)),
    _row("GT_SetFollowMemoryEx", "profile, memory", (_AX, (0, 1, 2)), lambda s, c, p, m: _follow(c, p, memory=float(m)),
         "FIFO size: 0 16 segments, 1 512, 2 GT_SetFollowExMaxSegment (before any data, L489-514)."),
    _row("GT_GetFollowMemoryEx", "profile", (_AX,), lambda s, c, p: int(c.follow(int(p) - 1).setup.memory),
         "(rtn, memory).", (0,)),
    _row("GT_SetFollowExMaxSegment", "profile, maxsegment", (_AX, ("int", 1, 2**31 - 1)),
         lambda s, c, p, m: _follow(c, p, max_segment=float(m)), "Dynamic FIFO size, 1..2147483647 (L497-501, L7254)."),
    _row("GT_FollowClearEx", "profile, fifo=0", (_AX, (0, 1)), lambda s, c, p, f: c.follow(int(p) - 1).clear(int(f)),
         "Clears a FIFO (refused while it is in use) (L4612-4619)."),
    _row("GT_FollowDataPercentEx", "profile, masterSegment, slaveSegment, type=0, percent=0, fifo=0",
         (_AX, None, None, (0, 1, 2, 3), None, (0, 1)), lambda s, c, p, m, sl, t, pc, f: c.follow(int(p) - 1)
         .data_percent(float(m), float(sl), int(t), float(pc), int(f)),
         "One segment, cumulative master/slave positions from the follow start (decision M30), type NORMAL / EVEN / "
         "STOP / CONTINUE, percent 0..100; 1 when the FIFO is full (the data is lost, L532-534, L4740)."),
    _row("GT_FollowDataCompleteEx", "profile, fifo, n, pMasterSegment, pSlaveSegment, pA=None, pB=None, pC=None, "
         "velRatioBegin=0.0, velRatioEnd=0.0", (_AX, (0, 1), ("int", 2, 2**31 - 1)),
         lambda s, c, p, f, n, ms, ss, pa, pb, pc, vb, ve: c.follow(int(p) - 1).data_complete(
             s._arr(ms, n), s._arr(ss, n), float(vb), float(ve), int(f)),
         "Complete data: n knots (cumulative), clamped C2 spline with the end ratios (L4644-4677); pA/pB/pC are the "
         "manual's work arrays (not used)."),
    _row("GT_FollowSpaceEx", "profile, fifo=0", (_AX, (0, 1)), lambda s, c, p, f: int(c.follow(int(p) - 1).space(int(f))),
         "(rtn, free segments) (L4796).", (0,)),
    _row("GT_SetFollowEventEx", "profile, event, masterDir=1, pos=0", (_AX, (1, 2), (-1, 1), _I32),
         lambda s, c, p, e, d, x: _follow(c, p, event=float(e), master_dir=float(d), event_pos=float(x)),
         "Start event: 1 START, 2 PASS (the master crosses pos moving in masterDir +-1) (L536-542, L7212-7240)."),
    _row("GT_GetFollowEventEx", "profile", (_AX,), lambda s, c, p: (
        int(c.follow(int(p) - 1).setup.event), int(c.follow(int(p) - 1).setup.master_dir),
        int(c.follow(int(p) - 1).setup.event_pos)), "(rtn, event, masterDir, pos).", (0, 0, 0)),
    _row("GT_SetFollowLoopEx", "profile, loop", (_AX, ("int", -32768, 32767)),
         lambda s, c, p, n: _follow(c, p, loop=float(n)), "Passes; < 1 = infinite (L7287-7302)."),
    _row("GT_GetFollowLoopEx", "profile", (_AX,), lambda s, c, p: int(c.follow(int(p) - 1).loop_count),
         "(rtn, completed passes) (L5649-5661).", (0,)),
    _row("GT_FollowStartEx", "mask, option=0", (_MASK, lambda n, v, a: _int_in(v, 0, (1 << n) - 1)),
         lambda s, c, m, o: c.follow_start(int(m), int(o)),
         "Starts the masked slaves (bit k = axis k+1) on FIFO 0 or, option bit set, FIFO 1 (L4827-4916); 1 for an "
         "axis not in FollowEx mode, already following, or with an empty FIFO."),
    _row("GT_FollowSwitchEx", "mask", (_MASK,), lambda s, c, m: c.follow_switch(int(m)),
         "Switches the masked slaves to their other FIFO at the end of the pass; only while moving, the other FIFO "
         "must hold data (L5196-5293)."),
]
for _fn in _ROWS:
    setattr(GtsController, _fn.__name__, _fn)


attach_mx_forms(GtsController)

#: Calls the simulation cannot carry out: defined, they return the manual's code; name -> reason.
UNSUPPORTED: dict[str, str] = {**UNSUPPORTED_CONFIG, **UNSUPPORTED_PROGRAM}

_default = GtsController()
GTS_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "GT_")


def __getattr__(name: str) -> Any:
    """Only for type checkers (PEP 562): the ``GT_*`` functions, ``use_machine`` ... are generated into this module
    by :func:`export_functions`, so mypy cannot list them; a program's ``from servobench.dialects.gts import
    GT_Open`` type-checks through this hook. At run time a missing name is an AttributeError as usual."""
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def set_inputs(bits: int) -> None:
    """The simulated levels of the general inputs GPI 1..16 of the open card (:meth:`GtsController.set_inputs`)."""
    _default.set_inputs(bits)

__all__ = ["GtsController", "GTS_FUNCTIONS", "TCrdPrm", "TTrapPrm", "TJogPrmExt", "TVarInfo", "TThreadSts",
           "TCompileInfo", "UNSUPPORTED", "MC_ARRIVE", "FOLLOW_SWITCH_SEGMENT", "FOLLOW_SWITCH_TABLE", "use_machine",
           "RTN_SUCCESS", "RTN_COMMAND_ERROR", "RTN_LICENSE_ERROR",
           "RTN_PARAMETER_ERROR", "RTN_COMM_ERROR", "RTN_OPEN_ERROR", "MC_ENABLE", "MC_CLEAR", "MC_GPO",
           "MC_LIMIT_POSITIVE", "MC_LIMIT_NEGATIVE", "MC_ALARM", "MC_HOME", "MC_GPI", "FOLLOW_SEGMENT_NORMAL",
           "FOLLOW_SEGMENT_EVEN", "FOLLOW_SEGMENT_STOP", "FOLLOW_SEGMENT_CONTINUE", "FOLLOW_MASTER_ENCODER",
           "FOLLOW_MASTER_PROFILE", "FOLLOW_MASTER_AXIS", "FOLLOW_EVENT_START", "FOLLOW_EVENT_PASS", "card",
           "controller", "run", "wait_until", "set_inputs", *GTS_FUNCTIONS]
