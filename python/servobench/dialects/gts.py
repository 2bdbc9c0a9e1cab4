"""The Googol GUC-ECAT / iDEABOX advanced functions (GUC-ECAT manual seed 002, iDEABOX manual seed 003) on the
virtual :class:`~servobench.Card`: coordinate systems with FIFO0/FIFO1, buffered commands and look-ahead, PVT
tables, the FollowEx cam, and the basic calls their example programs use.

Vendor names and argument order (the ``CardNo`` argument of the iDEABOX ``...Mx`` forms is left out, as in the
GUC-ECAT library); axes/profiles from 1, crd 1..2, fifo 0..1; units pulse, ms, pulse/ms, pulse/ms^2. Every call
returns the manuals' code (GUC Tab 2-1 L165-180, iDEABOX Table 3-1 L333-361): 0 success, 1 command error (the
card refused it in its present state; nothing changed), 7 parameter error, -1 no card open, -6 the card is
already open. A read call returns a tuple ``(rtn, value...)``.

This module only translates: the behaviour (the FIFOs, look-ahead, PVT and cam engines, safety) is the Card's
(``Card.set_crd_prm``, ``Card.crd``, ``Card.set_pvt``, ``Card.set_follow``, ...). The card's servo tick is the
controller's clock; times in ms are converted with its servo period. The system configuration, velocity filters, read-backs and
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
from .._core import CardCommandRefused, LookAheadParams, MotionCommandRefused
from ..card import Card
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401
from ._gts_config import (FOLLOW_SWITCH_SEGMENT, FOLLOW_SWITCH_TABLE, MC_ARRIVE, UNSUPPORTED_CONFIG,  # noqa: F401
                          GtsConfigMixin, TJogPrmExt, TTrapPrm, attach_mx_forms)
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
_CRD_STOP_BIT = 12  # GT_Stop / GT_StopMx mask and option bit 12 = crd 1, 13 = crd 2 (iDEABOX Ex 4-6 L1793)


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

    def _axis_ok(self, axis) -> bool:
        return self._card is not None and _int_in(axis, 1, len(self._card))

    def _bad(self) -> int:
        return RTN_COMM_ERROR if self._card is None else RTN_PARAMETER_ERROR

    @property
    def _ms(self) -> float:
        """The servo tick in ms (pulse/ms -> pulse/tick factor)."""
        return self._card.servo_period_s * 1e3

    def _fifo(self, crd, fifo):
        return self._card.crd(int(crd)).fifo(int(fifo))

    def _crd_args_ok(self, crd, fifo) -> bool:
        return _int_in(crd, 1, 2) and _int_in(fifo, 0, 1)

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

    def GT_AxisOn(self, axis) -> int:
        """Enables the drive of ``axis`` (1..)."""
        if not self._axis_ok(axis):
            return self._bad()
        return self._do(self._card.axis_on, int(axis) - 1)

    def GT_AxisOff(self, axis) -> int:
        """Disables the drive of ``axis``."""
        if not self._axis_ok(axis):
            return self._bad()
        return self._do(self._card.axis_off, int(axis) - 1)

    def GT_ClrSts(self, axis, count=1) -> int:
        """Clears the latched status of ``count`` axes from ``axis`` (iDEABOX L629)."""
        if not self._axis_ok(axis) or not _int_in(count, 1, len(self._card) - int(axis) + 1):
            return self._bad()
        return self._do(lambda: [self._card.clear_events(a, 0xFFF) for a in range(int(axis) - 1, int(axis) - 1 + int(count))])

    def GT_ZeroPos(self, axis, count=1) -> int:
        """Actual (encoder) = target = profile position = 0 on ``count`` axes from ``axis`` (pulse), the mechanism
        unmoved. iDEABOX L647/L848 only call it (``GT_ZeroPos(axis, 1)``); the meaning is the Googol one (GT
        L5196-5206, GE L5907-5913; decision VF3): at rest only. Returns 0; 1 with nothing changed if any of the
        axes moves, runs a sequence, or is in gear or a coordinate system; 7 for a bad axis or count."""
        if not self._axis_ok(axis) or not _int_in(count, 1, len(self._card) - int(axis) + 1):
            return self._bad()
        return self._do(self._card.zero_pos_range, int(axis) - 1, int(count))

    def GT_GetSts(self, axis, count=1):
        """(rtn, status) of ``axis``: the card's status word (GT layout; bit 10 = 0x400 the profile moves, the
        only bit the GUC seed uses, L2643-2645; decision V60)."""
        if not self._axis_ok(axis):
            return self._bad(), 0
        return self._get(lambda: _core.gt_axis_status(self._card.kernel, int(axis) - 1))

    def GT_GetPrfPos(self, profile, count=1):
        """(rtn, profile position, pulse)."""
        if not self._axis_ok(profile):
            return self._bad(), 0.0
        return self._get(lambda: wrap32(self._card.profile_pos(int(profile) - 1)))

    def GT_GetPrfVel(self, profile, count=1):
        """(rtn, profile velocity, pulse/ms)."""
        if not self._axis_ok(profile):
            return self._bad(), 0.0
        if self._gts().prf_vel_filter(int(profile) - 1):  # the mean over the last 2^exp ticks (L3801; GS9)
            return self._get(lambda: self._gts().filtered_prf_vel(int(profile) - 1))
        return self._get(lambda: self._card.profile_vel(int(profile) - 1) / self._ms)

    def GT_GetEncPos(self, axis, count=1):
        """(rtn, encoder (actual) position, pulse)."""
        if not self._axis_ok(axis):
            return self._bad(), 0.0
        return self._get(lambda: wrap32(self._card.actual_pos(int(axis) - 1)))

    def GT_PrfTrap(self, profile) -> int:
        """Point-to-point (trapezoid) mode (refused while moving)."""
        if not self._axis_ok(profile):
            return self._bad()
        return self._do(self._card.set_mode, int(profile) - 1, "t_curve")

    def GT_SetTrapPrm(self, profile, acc, dec=None, velStart=0, smoothTime=0) -> int:
        """TTrapPrm acc (and dec), pulse/ms^2 > 0, as scalars or a :class:`TTrapPrm` as ``acc`` (GUC L2898-2908
        reads it with GT_GetTrapPrm, changes acc/dec and writes it back). The card's T-curve has one acceleration
        for both ramps: dec is taken equal to acc (decision V61); velStart and smoothTime must be 0."""
        if isinstance(acc, TTrapPrm):
            acc, dec, velStart, smoothTime = acc.acc, acc.dec, acc.velStart, acc.smoothTime
        if not self._axis_ok(profile):
            return self._bad()
        if not _open_in(acc, 0, math.inf) or (dec is not None and not _open_in(dec, 0, math.inf)) \
                or velStart != 0 or smoothTime != 0:
            return RTN_PARAMETER_ERROR
        return self._do(self._card.stage_acc, int(profile) - 1, float(acc) * self._ms ** 2)

    def GT_PrfJog(self, profile) -> int:
        """Jog mode (refused while moving)."""
        if not self._axis_ok(profile):
            return self._bad()
        return self._do(self._card.set_mode, int(profile) - 1, "jog")

    def GT_SetJogPrm(self, profile, acc, dec=None, smooth=0) -> int:
        """Jog acc (dec taken equal, V61), pulse/ms^2 > 0, smooth 0..1 (recorded, GS17): scalars or a
        :class:`TJogPrmExt` as ``acc`` (iDEABOX Ex 4-1 L726-730 passes the struct)."""
        if isinstance(acc, TJogPrmExt):
            acc, dec, smooth = acc.acc, (acc.dec or None), acc.smooth
        if not self._axis_ok(profile):
            return self._bad()
        if _num(smooth) is None or not 0 <= float(smooth) <= 1:
            return RTN_PARAMETER_ERROR
        rtn = self.GT_SetTrapPrm(profile, acc, dec)
        if rtn == RTN_SUCCESS:
            self._gts().set_jog_smooth(int(profile) - 1, float(smooth))
        return rtn

    def GT_SetVel(self, profile, vel) -> int:
        """Target velocity, pulse/ms (signed in jog mode) (staged)."""
        if not self._axis_ok(profile) or _num(vel) is None:
            return self._bad()
        return self._do(self._card.stage_vel, int(profile) - 1, float(vel) * self._ms)

    def GT_SetPos(self, profile, pos) -> int:
        """Target position, pulse (staged)."""
        if not self._axis_ok(profile) or not _int_in(pos, _POS_MIN, _POS_MAX):
            return self._bad()
        return self._do(self._card.stage_pos, int(profile) - 1, float(pos))

    def GT_Update(self, mask) -> int:
        """Starts the staged motion of the masked axes (bit k = axis k+1)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 1, (1 << len(self._card)) - 1):
            return RTN_PARAMETER_ERROR
        return self._do(self._card.update, int(mask))

    def GT_Stop(self, mask, option=0) -> int:
        """Stops the masked axes (bit k = axis k+1) and coordinate systems (bit 12 = crd 1, 13 = crd 2, iDEABOX
        L1793); option bit set = abrupt, clear = smooth. A stopped crd keeps its breakpoint (resume with
        GT_CrdStart)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 0, 0xFFFFFFFF) or not _int_in(option, 0, 0xFFFFFFFF):
            return RTN_PARAMETER_ERROR
        mask, option = int(mask), int(option)

        def stop():
            for c in (1, 2):
                bit = 1 << (_CRD_STOP_BIT + c - 1)
                if mask & bit and self._card.group_info(c - 1)["set_up"]:
                    self._card.crd_stop(c, bool(option & bit))
            for a in range(len(self._card)):
                if not mask & (1 << a):
                    continue
                if self._card.mode(a) not in ("t_curve", "s_curve", "jog"):
                    if self._card.group_of(a) < 0:
                        self._card.abrupt_stop(a)
                elif option & (1 << a) or self._card.moving(a):
                    self._gts().stop_axis(a, bool(option & (1 << a)))  # GT_SetStopDec decelerations (GS7)

        return self._do(stop)

    # -- coordinate systems (GUC §4.1 L313-1114, iDEABOX §4.3) ----------------------------------------------
    def GT_SetCrdPrm(self, crd, prm: TCrdPrm) -> int:
        """Sets up coordinate system ``crd`` (1..2) (GUC L369-388, L736-792; iDEABOX L7095-7176). 7 for values out
        of range or a profile mapped twice (L785); 1 while a mapped axis moves or is in the other crd (L743,
        L7168-7174)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(crd, 1, 2) or not _int_in(prm.dimension, 1, 4) or len(prm.profile) > 8 \
                or not all(_int_in(p, 0, 4) for p in prm.profile) or not _open_in(prm.synVelMax, 0, 32767) \
                or not _open_in(prm.synAccMax, 0, 32767) or not _half_open(prm.evenTime, 0, 32767) \
                or not _int_in(prm.evenTime, 0, 32766) or prm.setOriginFlag not in (0, 1) \
                or not all(_int_in(p, -2**31, 2**31 - 1) for p in prm.originPos):
            return RTN_PARAMETER_ERROR
        used = [p for p in prm.profile if p]
        if len(used) != len(set(used)) or any(p > prm.dimension for p in used) or len(used) != prm.dimension:
            return RTN_PARAMETER_ERROR
        if any(k >= len(self._card) for k, p in enumerate(prm.profile) if p):
            return RTN_PARAMETER_ERROR
        rtn = self._do(lambda: self._card.set_crd_prm(
            int(crd), dimension=int(prm.dimension), profile=[float(p) for p in prm.profile],
            syn_vel_max=float(prm.synVelMax), syn_acc_max=float(prm.synAccMax), even_time_ms=float(prm.evenTime),
            set_origin=bool(prm.setOriginFlag), origin_pos=[float(p) for p in prm.originPos]))
        if rtn == RTN_SUCCESS:
            self._gts().drop_lookahead(int(crd))
        return rtn

    def GT_GetCrdPrm(self, crd):
        """(rtn, TCrdPrm) of ``crd``."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._bad(), None

        def get():
            if not self._card.group_info(int(crd) - 1)["set_up"]:
                raise CardCommandRefused("crd not set up")
            d = self._card.crd_prm(int(crd))
            return TCrdPrm(dimension=d["dimension"], profile=list(d["profile"]), synVelMax=d["syn_vel_max"],
                           synAccMax=d["syn_acc_max"], evenTime=int(d["even_time_ms"]),
                           setOriginFlag=int(d["set_origin"]), originPos=list(d["origin_pos"]))

        return self._get(get)

    def _ln(self, crd, end, vel, acc, vel_end, fifo, g0):
        if self._card is None:
            return RTN_COMM_ERROR
        if not all(_int_in(p, _POS_MIN, _POS_MAX) for p in end) or not self._seg_ok(vel, acc, vel_end):
            return RTN_PARAMETER_ERROR
        return self._push(crd, fifo, lambda f: f.line([float(p) for p in end], float(vel), float(acc),
                                                      float(vel_end), g0))

    def GT_LnXY(self, crd, x, y, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """Line to (x, y) absolute, pulse; synVel pulse/ms, synAcc pulse/ms^2, velEnd (ignored under look-ahead)
        (GUC L449-481; iDEABOX L5881)."""
        return self._ln(crd, (x, y), synVel, synAcc, velEnd, fifo, False)

    def GT_LnXYZ(self, crd, x, y, z, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """3-D line (iDEABOX L5975)."""
        return self._ln(crd, (x, y, z), synVel, synAcc, velEnd, fifo, False)

    def GT_LnXYZA(self, crd, x, y, z, a, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """4-D line (iDEABOX L6026); no look-ahead on a 4-D crd (7)."""
        return self._ln(crd, (x, y, z, a), synVel, synAcc, velEnd, fifo, False)

    def GT_LnXYG0(self, crd, x, y, synVel, synAcc, fifo=0) -> int:
        """G0 line: ends at rest even under look-ahead (GUC L322-327, iDEABOX L1594-1606)."""
        return self._ln(crd, (x, y), synVel, synAcc, 0, fifo, True)

    def GT_LnXYZG0(self, crd, x, y, z, synVel, synAcc, fifo=0) -> int:
        """3-D G0 line."""
        return self._ln(crd, (x, y, z), synVel, synAcc, 0, fifo, True)

    def GT_LnXYZAG0(self, crd, x, y, z, a, synVel, synAcc, fifo=0) -> int:
        """4-D G0 line."""
        return self._ln(crd, (x, y, z, a), synVel, synAcc, 0, fifo, True)

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

    def GT_ArcXYR(self, crd, x, y, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """XY arc to (x, y) with radius (> 0: <= 180 deg, < 0: > 180 deg), circleDir 0 CW / 1 CCW; 7 when no such
        arc exists (GUC L509-587, L892, L906; iDEABOX L3874)."""
        return self._arc(crd, "xy", x, y, (radius,), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_ArcXYC(self, crd, x, y, xCenter, yCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """XY arc to (x, y) about the centre offset (xCenter, yCenter) from the start; end = start is a full
        circle (GUC L904; iDEABOX L3812)."""
        return self._arc(crd, "xy", x, y, (xCenter, yCenter), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_ArcYZR(self, crd, y, z, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """YZ arc, radius form (iDEABOX L4002)."""
        return self._arc(crd, "yz", y, z, (radius,), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_ArcYZC(self, crd, y, z, yCenter, zCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """YZ arc, centre form (iDEABOX L3941)."""
        return self._arc(crd, "yz", y, z, (yCenter, zCenter), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_ArcZXR(self, crd, z, x, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """ZX arc, radius form (iDEABOX L4131)."""
        return self._arc(crd, "zx", z, x, (radius,), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_ArcZXC(self, crd, z, x, zCenter, xCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0) -> int:
        """ZX arc, centre form (iDEABOX L4070)."""
        return self._arc(crd, "zx", z, x, (zCenter, xCenter), circleDir, synVel, synAcc, velEnd, fifo)

    def GT_BufIO(self, crd, doType, doMask, doValue, fifo=0) -> int:
        """Buffered digital output: MC_GPO / MC_ENABLE / MC_CLEAR, bits of doValue where doMask is 1 (GUC
        L588-597)."""
        if doType not in _DO_TYPE or not _int_in(doMask, 0, 0xFFFF) or not _int_in(doValue, 0, 0xFFFF):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_io(_DO_TYPE[doType], int(doMask), int(doValue)))

    def GT_BufDelay(self, crd, delayTime, fifo=0) -> int:
        """Buffered dwell, ms, 0..16383 (GUC L598-602)."""
        if not _int_in(delayTime, 0, 16383):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_delay(float(delayTime)))

    def GT_BufDA(self, crd, chn, daValue, fifo=0) -> int:
        """Buffered analog output, channel 1..8, -32768..32767 (GUC L603-608)."""
        if not _int_in(chn, 1, 8) or not _int_in(daValue, -32768, 32767):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_da(int(chn), float(daValue)))

    def GT_BufLmtsOn(self, crd, axis, limitType=-1, fifo=0) -> int:
        """Buffered limit enable: limitType 0 positive, 1 negative, -1 both (GUC L609-624)."""
        if not _int_in(axis, 1, 8) or limitType not in (-1, 0, 1):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_lmts(int(axis), int(limitType), True))

    def GT_BufLmtsOff(self, crd, axis, limitType=-1, fifo=0) -> int:
        """Buffered limit disable."""
        if not _int_in(axis, 1, 8) or limitType not in (-1, 0, 1):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_lmts(int(axis), int(limitType), False))

    def GT_BufSetStopIo(self, crd, axis, stopType, inputType, inputIndex, fifo=0) -> int:
        """Buffered stop-input mapping: stopType 0 emergency / 1 smooth, inputType 0..4, index 1..8 (GPI 1..16)
        (GUC L625-645)."""
        hi = 16 if inputType == MC_GPI else 8
        if not _int_in(axis, 1, 8) or stopType not in (0, 1) or inputType not in (0, 1, 2, 3, 4) \
                or not _int_in(inputIndex, 1, hi):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.buf_set_stop_io(int(axis), int(stopType), int(inputType),
                                                                 int(inputIndex)))

    def GT_BufMove(self, crd, moveAxis, pos, vel, acc, modal, fifo=0) -> int:
        """Buffered point-to-point move of an axis outside the crd to the absolute ``pos`` (pulse) at vel
        (pulse/ms) and acc (pulse/ms^2); modal 1 blocks the FIFO until it ends (GUC L646-656, L1052-1055)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(moveAxis, 1, min(8, len(self._card))) or not _int_in(pos, -2**31, 2**31 - 1) \
                or not _open_in(vel, 0, math.inf) or not _open_in(acc, 0, math.inf) or modal not in (0, 1):
            return RTN_PARAMETER_ERROR
        if _int_in(crd, 1, 2) and self._card.group_of(int(moveAxis) - 1) == int(crd) - 1:
            return RTN_PARAMETER_ERROR  # not a crd axis (GUC L647)
        return self._push(crd, fifo, lambda f: f.buf_move(int(moveAxis), float(pos), float(vel), float(acc),
                                                          bool(modal)))

    def GT_BufGear(self, crd, gearAxis, pos, fifo=0) -> int:
        """Buffered follow of the next segment by an axis outside the crd over the relative ``pos`` (pulse)
        (GUC L657-661, L1058-1060)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(gearAxis, 1, min(8, len(self._card))) or not _int_in(pos, -2**31, 2**31 - 1):
            return RTN_PARAMETER_ERROR
        if _int_in(crd, 1, 2) and self._card.group_of(int(gearAxis) - 1) == int(crd) - 1:
            return RTN_PARAMETER_ERROR
        return self._push(crd, fifo, lambda f: f.buf_gear(int(gearAxis), float(pos)))

    def GT_SetUserSegNum(self, crd, segNum, fifo=0) -> int:
        """Buffered user segment number (GUC L662-665)."""
        if not _int_in(segNum, -2**31, 2**31 - 1):
            return self._bad()
        return self._push(crd, fifo, lambda f: f.set_user_seg_num(int(segNum)))

    def _fifo_get(self, crd, fifo, fn):
        if self._card is None or not self._crd_args_ok(crd, fifo):
            return self._bad(), 0
        return self._get(lambda: fn(self._fifo(crd, fifo)))

    def GT_GetUserSegNum(self, crd, fifo=0):
        """(rtn, user segment number) (GUC L666-670)."""
        return self._fifo_get(crd, fifo, lambda f: int(f.state.user_seg_num))

    def GT_GetRemainderSegNum(self, crd, fifo=0):
        """(rtn, segments not finished) (GUC L671-675)."""
        return self._fifo_get(crd, fifo, lambda f: int(f.remaining_segments))

    def GT_CrdSpace(self, crd, fifo=0):
        """(rtn, free FIFO entries) (GUC L979)."""
        return self._fifo_get(crd, fifo, lambda f: int(f.fifo_space))

    def GT_CrdClear(self, crd, fifo=0) -> int:
        """Clears a FIFO and its segment count (refused while it moves) (GUC L697-699, L855-857)."""
        if self._card is None or not self._crd_args_ok(crd, fifo):
            return self._bad()
        return self._do(lambda: self._fifo(crd, fifo).clear())

    def GT_InitLookAhead(self, crd, fifo, T, accMax, n, pLookAheadBuf=None) -> int:
        """Look-ahead on a FIFO: corner time T (ms), accMax (pulse/ms^2), window n segments (0 = off) (GUC
        L725-732, L908-995; iDEABOX L5848-5879). The buffer argument is accepted and not used."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not self._crd_args_ok(crd, fifo) or not _open_in(T, 0, 1000.0001) or not _open_in(accMax, 0, 32767.0001) \
                or not _int_in(n, 0, 32766):
            return RTN_PARAMETER_ERROR
        rtn = self._do(lambda: self._fifo(crd, fifo).init_lookahead(
            LookAheadParams(t_ms=float(T), acc_max=float(accMax), n=float(n))))
        if rtn == RTN_SUCCESS:
            self._gts().set_lookahead(int(crd), int(fifo), int(n))
        return rtn

    def GT_CrdData(self, crd, pCrdData=None, fifo=0) -> int:
        """With pCrdData None (NULL): moves the look-ahead window into the FIFO; 1 when the FIFO filled first
        (call again after GT_CrdSpace) (GUC L975-977; iDEABOX L4465-4498). Raw TCrdData records: not
        simulated (7)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if pCrdData not in (None, 0) or not self._crd_args_ok(crd, fifo):
            return RTN_PARAMETER_ERROR
        try:
            ok = self._fifo(crd, fifo).flush()
        except (CardCommandRefused, MotionCommandRefused):
            return RTN_COMMAND_ERROR
        return RTN_SUCCESS if ok else RTN_COMMAND_ERROR

    def GT_CrdStart(self, mask, option=0) -> int:
        """Starts (or resumes) the masked crds (bit 0 crd 1, bit 1 crd 2) on FIFO0 or, option bit set, FIFO1;
        1 when a crd is not set up, the other FIFO moves, FIFO0 resumes away from its breakpoint (GUC L1005,
        iDEABOX L4560) or the e-stop / an alarm is active (GUC L684-690; iDEABOX L4527-4566)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 1, 3) or not _int_in(option, 0, 3):
            return RTN_PARAMETER_ERROR
        return self._do(self._card.crd_start, int(mask), int(option))

    def GT_CrdStatus(self, crd, fifo=0):
        """(rtn, run, segment): run 1 while the FIFO interpolates, segment = segments completed since the crd was
        set up or cleared (GUC L692-700; iDEABOX L4574-4599)."""
        if self._card is None or not self._crd_args_ok(crd, fifo):
            return self._bad(), 0, 0
        return self._get(lambda: tuple(self._card.crd_status(int(crd), int(fifo))), 2)

    def GT_SetOverride(self, crd, synVelRatio) -> int:
        """Feed override (0, 1] (GUC L701-703; iDEABOX L7419-7441)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._bad()
        x = _num(synVelRatio)
        if x is None or not 0 < x <= 1:
            return RTN_PARAMETER_ERROR

        def set_():
            pair = self._card.crd(int(crd))
            pair.fifo(0).set_override(x)
            pair.fifo(1).set_override(x)

        return self._do(set_)

    def GT_SetCrdStopDec(self, crd, decSmoothStop, decAbruptStop) -> int:
        """Path stop decelerations, (0, 32767) pulse/ms^2 each (GUC L704-709; iDEABOX L7182-7201)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._bad()
        if not _open_in(decSmoothStop, 0, 32767) or not _open_in(decAbruptStop, 0, 32767):
            return RTN_PARAMETER_ERROR

        def set_():
            pair = self._card.crd(int(crd))
            for k in (0, 1):
                pair.fifo(k).set_stop_dec(float(decSmoothStop), float(decAbruptStop))
            self._gts().set_crd_stop_dec(int(crd), float(decSmoothStop), float(decAbruptStop))

        return self._do(set_)

    def GT_GetCrdPos(self, crd):
        """(rtn, [dimension] crd coordinates, pulse) (GUC L5499-5519; crd = profile - origin)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._bad(), []
        return self._get(lambda: list(self._card.crd_pos(int(crd))))

    def GT_GetCrdVel(self, crd):
        """(rtn, path speed, pulse/ms) (iDEABOX L5581-5595)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._bad(), 0.0
        return self._get(lambda: float(self._card.crd_vel(int(crd))))

    # -- PVT (GUC §4.2 L1116-2100, iDEABOX §4.4) ------------------------------------------------------------
    def _table(self, tableId, build) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(tableId, 1, 32):
            return RTN_PARAMETER_ERROR
        try:
            curve = build()
        except ValueError:
            return RTN_PARAMETER_ERROR
        return self._do(self._card.pvt_download, int(tableId), curve)

    @staticmethod
    def _arr(x, count):
        a = np.asarray(x, dtype=float)[: int(count)]
        if len(a) != int(count):
            raise ValueError(f"the arrays hold fewer than count = {count} values")
        return a

    def GT_PrfPvt(self, profile) -> int:
        """PVT mode (refused while moving) (GUC L1141; iDEABOX L6201)."""
        if not self._axis_ok(profile):
            return self._bad()
        return self._do(self._card.set_pvt, int(profile) - 1)

    def GT_PvtTable(self, tableId, count, pTime, pPos, pVel) -> int:
        """PVT data (ms, pulse, pulse/ms), replaces the table (GUC L1169; iDEABOX L6404)."""
        return self._table(tableId, lambda: _core.pvt_table(time_ms=self._arr(pTime, count), pos=self._arr(pPos, count),
                                                            vel=self._arr(pVel, count)))

    def GT_PvtTableEx(self, tableId, count, pTime, pPos, pVelBegin, pVelEnd) -> int:
        """PVT-Ex data with a begin and an end velocity per point (iDEABOX L6446-6472)."""
        return self._table(tableId, lambda: _core.pvt_table_ex(time_ms=self._arr(pTime, count), pos=self._arr(pPos, count),
                                                               vel_begin=self._arr(pVelBegin, count), vel_end=self._arr(pVelEnd, count)))

    def GT_PvtTableComplete(self, tableId, count, pTime, pPos, pA=None, pB=None, pC=None, velBegin=0, velEnd=0) -> int:
        """Complete data (t, p) with velBegin / velEnd: C2 spline (GUC L1181-1191; iDEABOX L6585). pA/pB/pC are
        the manual's work arrays (not used)."""
        return self._table(tableId, lambda: _core.pvt_table_complete(time_ms=self._arr(pTime, count), pos=self._arr(pPos, count),
                                                                     vel_begin=float(velBegin), vel_end=float(velEnd)))

    def GT_PvtTablePercent(self, tableId, count, pTime, pPos, pPercent, velBegin=0) -> int:
        """Percent data (GUC L1436-1457; iDEABOX L6931)."""
        return self._table(tableId, lambda: _core.pvt_table_percent(time_ms=self._arr(pTime, count), pos=self._arr(pPos, count),
                                                                    percent=self._arr(pPercent, count), vel_begin=float(velBegin)))

    def GT_PvtPercentCalculate(self, count, pTime, pPos, pPercent, velBegin=0):
        """(rtn, node velocities) of Percent data (nothing downloaded) (GUC L1436; iDEABOX L6259)."""
        try:
            return RTN_SUCCESS, np.asarray(_core.pvt_percent_calculate(time_ms=self._arr(pTime, count), pos=self._arr(pPos, count),
                                                                       percent=self._arr(pPercent, count), vel_begin=float(velBegin)))
        except ValueError:
            return RTN_PARAMETER_ERROR, None

    def GT_PvtTableContinuous(self, tableId, count, pPos, pVel, pPercent, pVelMax, pAcc, pDec, timeBegin=0) -> int:
        """Continuous data (p, v, percent, vMax, acc, dec per point), start at timeBegin ms (GUC L1475-1504;
        iDEABOX L6690)."""
        a = self._arr
        return self._table(tableId, lambda: _core.pvt_table_continuous(
            pos=a(pPos, count), vel=a(pVel, count), percent=a(pPercent, count), vel_max=a(pVelMax, count),
            acc=a(pAcc, count), dec=a(pDec, count), time_begin_ms=float(timeBegin)))

    def GT_PvtTableContinuousEx(self, tableId, count, pPos, pVel, pAccPercent, pDecPercent, pVelMax, pAcc, pDec,
                                timeBegin=0) -> int:
        """Continuous-Ex data: as GT_PvtTableContinuous with separate S shares (0..100) for the acceleration and
        the deceleration phase of each segment (iDEABOX L6745-6803)."""
        a = self._arr
        return self._table(tableId, lambda: _core.pvt_table_continuous_ex(
            pos=a(pPos, count), vel=a(pVel, count), acc_percent=a(pAccPercent, count),
            dec_percent=a(pDecPercent, count), vel_max=a(pVelMax, count), acc=a(pAcc, count), dec=a(pDec, count),
            time_begin_ms=float(timeBegin)))

    def GT_PvtContinuousCalculate(self, count, pPos, pVel, pPercent, pVelMax, pAcc, pDec):
        """(rtn, point times ms, time[0] = 0) of Continuous data (GUC L1230; iDEABOX L6222-6251)."""
        a = self._arr
        try:
            return RTN_SUCCESS, np.asarray(_core.pvt_continuous_calculate(
                pos=a(pPos, count), vel=a(pVel, count), percent=a(pPercent, count), vel_max=a(pVelMax, count),
                acc=a(pAcc, count), dec=a(pDec, count)))
        except ValueError:
            return RTN_PARAMETER_ERROR, None

    def GT_PvtTableSelect(self, profile, tableId) -> int:
        """Selects the table (at rest at once, while moving at the end of the pass); 1 on an empty table (GUC
        L1279, L1308; iDEABOX L7030-7048)."""
        if not self._axis_ok(profile) or not _int_in(tableId, 1, 32):
            return self._bad()
        return self._do(self._card.pvt_select, int(profile) - 1, int(tableId))

    def GT_SetPvtLoop(self, profile, loop) -> int:
        """Passes, 0 = infinite (GUC L1150, L1312; iDEABOX L7443)."""
        if not self._axis_ok(profile) or not _int_in(loop, 0, 2**31 - 1):
            return self._bad()
        return self._do(self._card.pvt_loop, int(profile) - 1, float(loop))

    def GT_GetPvtLoop(self, profile):
        """(rtn, passes done, loop setting) (GUC L1156-1159; iDEABOX L5765-5779)."""
        if not self._axis_ok(profile):
            return self._bad(), 0, 0
        return self._get(lambda: tuple(self._card.pvt_loop_status(int(profile) - 1)), 2)

    def GT_PvtStart(self, mask) -> int:
        """Starts the masked axes (bit k = axis k+1) on the same tick; 1 on an empty table or an axis not in PVT
        mode (GUC L1279-1310; iDEABOX L6305-6321)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 1, (1 << len(self._card)) - 1):
            return RTN_PARAMETER_ERROR
        return self._do(self._card.pvt_start, int(mask))

    def GT_PvtStatus(self, profile, count=1):
        """(rtn, table id, PVT time ms) (GUC L1285-1289; iDEABOX L6374-6390)."""
        if not self._axis_ok(profile):
            return self._bad(), 0, 0.0
        return self._get(lambda: tuple(self._card.pvt_status(int(profile) - 1)), 2)

    # -- FollowEx (iDEABOX §2.1 L394-929, API L4612-5448, L7212-7417) --------------------------------------
    def _setup(self, profile, **changes) -> int:
        a = int(profile) - 1
        return self._do(lambda: self._card.follow_configure(a, self._card.follow(a).setup.replace(**changes)))

    def GT_PrfFollowEx(self, profile, dir=0) -> int:
        """FollowEx mode, dir 0 both master directions, 1 positive only, -1 negative only (L6173-6199). The master
        is axis 1 (axis 2 for profile 1) until GT_SetFollowMasterEx (decision V62)."""
        if not self._axis_ok(profile) or dir not in (-1, 0, 1):
            return self._bad()
        a = int(profile) - 1
        return self._do(self._card.set_follow, a, _core.FollowExSetup(dir=float(dir)), 1 if a == 0 else 0)

    def GT_SetFollowMasterEx(self, profile, masterIndex, masterType=FOLLOW_MASTER_PROFILE, masterItem=0) -> int:
        """Master axis and signal: type 1 encoder, 2 profile, 3 axis (item 0 planned / 1 encoder); masterIndex !=
        profile (L7316-7363)."""
        if not self._axis_ok(profile) or not self._axis_ok(masterIndex) or masterType not in (1, 2, 3) \
                or masterItem not in (0, 1):
            return self._bad()
        rtn = self._do(self._card.follow_set_master, int(profile) - 1, int(masterIndex) - 1)
        return rtn if rtn else self._setup(profile, master_type=float(masterType), master_item=float(masterItem))

    def GT_GetFollowMasterEx(self, profile):
        """(rtn, masterIndex, masterType, masterItem)."""
        if not self._axis_ok(profile):
            return self._bad(), 0, 0, 0

        def get():
            a = int(profile) - 1
            s = self._card.follow(a).setup
            return self._card.follow_master(a) + 1, int(s.master_type), int(s.master_item)

        return self._get(get, 3)

    def GT_SetFollowMemoryEx(self, profile, memory) -> int:
        """FIFO size: 0 16 segments, 1 512, 2 GT_SetFollowExMaxSegment (before any data, L489-514)."""
        if not self._axis_ok(profile) or memory not in (0, 1, 2):
            return self._bad()
        return self._setup(profile, memory=float(memory))

    def GT_GetFollowMemoryEx(self, profile):
        """(rtn, memory)."""
        if not self._axis_ok(profile):
            return self._bad(), 0
        return self._get(lambda: int(self._card.follow(int(profile) - 1).setup.memory))

    def GT_SetFollowExMaxSegment(self, profile, maxsegment) -> int:
        """Dynamic FIFO size, 1..2147483647 (L497-501, L7254)."""
        if not self._axis_ok(profile) or not _int_in(maxsegment, 1, 2**31 - 1):
            return self._bad()
        return self._setup(profile, max_segment=float(maxsegment))

    def GT_FollowClearEx(self, profile, fifo=0) -> int:
        """Clears a FIFO (refused while it is in use) (L4612-4619)."""
        if not self._axis_ok(profile) or fifo not in (0, 1):
            return self._bad()
        return self._do(lambda: self._card.follow(int(profile) - 1).clear(int(fifo)))

    def GT_FollowDataPercentEx(self, profile, masterSegment, slaveSegment, type=FOLLOW_SEGMENT_NORMAL, percent=0,
                               fifo=0) -> int:
        """One segment, cumulative master/slave positions from the follow start (decision M30), type NORMAL /
        EVEN / STOP / CONTINUE, percent 0..100; 1 when the FIFO is full (the data is lost, L532-534, L4740)."""
        if not self._axis_ok(profile) or type not in (0, 1, 2, 3) or fifo not in (0, 1):
            return self._bad()
        return self._do(lambda: self._card.follow(int(profile) - 1).data_percent(
            float(masterSegment), float(slaveSegment), int(type), float(percent), int(fifo)))

    def GT_FollowDataCompleteEx(self, profile, fifo, n, pMasterSegment, pSlaveSegment, pA=None, pB=None, pC=None,
                                velRatioBegin=0.0, velRatioEnd=0.0) -> int:
        """Complete data: n knots (cumulative), clamped C2 spline with the end ratios (L4644-4677); pA/pB/pC are
        the manual's work arrays (not used)."""
        if not self._axis_ok(profile) or fifo not in (0, 1) or not _int_in(n, 2, 2**31 - 1):
            return self._bad()
        return self._do(lambda: self._card.follow(int(profile) - 1).data_complete(
            self._arr(pMasterSegment, n), self._arr(pSlaveSegment, n), float(velRatioBegin), float(velRatioEnd),
            int(fifo)))

    def GT_FollowSpaceEx(self, profile, fifo=0):
        """(rtn, free segments) (L4796)."""
        if not self._axis_ok(profile) or fifo not in (0, 1):
            return self._bad(), 0
        return self._get(lambda: int(self._card.follow(int(profile) - 1).space(int(fifo))))

    def GT_SetFollowEventEx(self, profile, event, masterDir=1, pos=0) -> int:
        """Start event: 1 START, 2 PASS (the master crosses pos moving in masterDir +-1) (L536-542, L7212-7240)."""
        if not self._axis_ok(profile) or event not in (1, 2) or masterDir not in (-1, 1) \
                or not _int_in(pos, -2**31, 2**31 - 1):
            return self._bad()
        return self._setup(profile, event=float(event), master_dir=float(masterDir), event_pos=float(pos))

    def GT_GetFollowEventEx(self, profile):
        """(rtn, event, masterDir, pos)."""
        if not self._axis_ok(profile):
            return self._bad(), 0, 0, 0

        def get():
            s = self._card.follow(int(profile) - 1).setup
            return int(s.event), int(s.master_dir), int(s.event_pos)

        return self._get(get, 3)

    def GT_SetFollowLoopEx(self, profile, loop) -> int:
        """Passes; < 1 = infinite (L7287-7302)."""
        if not self._axis_ok(profile) or not _int_in(loop, -32768, 32767):
            return self._bad()
        return self._setup(profile, loop=float(loop))

    def GT_GetFollowLoopEx(self, profile):
        """(rtn, completed passes) (L5649-5661)."""
        if not self._axis_ok(profile):
            return self._bad(), 0
        return self._get(lambda: int(self._card.follow(int(profile) - 1).loop_count))

    def GT_FollowStartEx(self, mask, option=0) -> int:
        """Starts the masked slaves (bit k = axis k+1) on FIFO 0 or, option bit set, FIFO 1 (L4827-4916); 1 for an
        axis not in FollowEx mode, already following, or with an empty FIFO."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 1, (1 << len(self._card)) - 1) or not _int_in(option, 0, (1 << len(self._card)) - 1):
            return RTN_PARAMETER_ERROR
        return self._do(self._card.follow_start, int(mask), int(option))

    def GT_FollowSwitchEx(self, mask) -> int:
        """Switches the masked slaves to their other FIFO at the end of the pass; only while moving, the other FIFO
        must hold data (L5196-5293)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(mask, 1, (1 << len(self._card)) - 1):
            return RTN_PARAMETER_ERROR
        return self._do(self._card.follow_switch, int(mask))


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
