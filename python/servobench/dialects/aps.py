"""The ADLINK APS function library (PCI-8254/8258 manual, seed 004) on the virtual :class:`~servobench.Card`.

Names, argument order and units are the manual's: axis IDs from 0 (``I32 axis_id = 0``, L2608), positions in
pulse, velocities in pulse/s, accelerations in pulse/s^2 (unit factor 1), axis parameters by their PRA_* numbers
(L1746-1762, L2744-2751, L3998-4019). Every function returns an I32 code: ``ERR_NoError`` (0) or a negative
error code of the APS library header ErrorCodeDef.h (the manual names only ERR_NoError; decision V49).
``APS_motion_status`` / ``APS_motion_io_status`` return the status word itself (L3168, L3611); a getter
``APS_get_x(axis, &x)`` returns the tuple ``(rtn, x)``.

A motion command the controller ignores while EMG, ALM or a limit toward the move is active returns
ERR_NoError and changes nothing but the stop code and ASTP, as the manual describes (L3931-4010; V47). A command
refused in this state of the axis (a move during homing, servo on with the alarm latched, position set while
moving) returns ERR_FunctionNotAvailable (-13) and leaves the state unchanged.

This module only translates: the behaviour (moves, status words, safety) is the Card's. Simulation helpers (not
in the manual): :func:`run` (ticks), :func:`Sleep` (ms, as the manual's examples), :func:`wait_until`, :func:`card`.
"""

from __future__ import annotations

import inspect
import math

import numpy as np

from .. import _core
from .._core import AdlinkPtp, ApsServoLaw, BlendMode, CardCommandRefused, MotionCommandRefused
from ..card import Card
from ._aps_constants import *  # noqa: F401,F403  (the header constants: the C++ table's, AX1)
from ._aps_more import _ApsMore
from ._aps_pt import PTA2CA, PTA2CE, PTDWL, PTHCA, PTHCE, PTLINE, PTSTS, _ApsPointTable  # noqa: F401
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401

# The PRA_* ranges, defaults and where each acts are the C++ parameter table's (vendor/adlink/aps_parameters.hpp,
# AV5); the speeds an APS_ptp_all call gives (pulse/s, pulse/s^2, S-factor) are checked against these:
_SPEEDS = {"vs": (0.0, 1e9), "ve": (0.0, 1e9), "acc": (0.0, 1e12), "dec": (0.0, 1e12), "sf": (0.0, 1.0)}
_POS_MAX = 2147483647
# Interpolation Option bits 12-15 (ITP_OPT_*, V114): the field value f is mode f + 1 of L3085-3143.
_BLEND_MODES = (BlendMode.ABORT_BLEND, BlendMode.ABORT_FORCED, BlendMode.ABORT_STOP, BlendMode.BUFFERED,
                BlendMode.BLEND_DECEL, BlendMode.BLEND_DISTANCE, BlendMode.BLEND_PERCENT)
_IGNORED = {"emergency_stop_active", "direction_inhibited", "drive_alarm_active"}  # L3931-4010


def _num(value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


class ApsController(DialectController):
    """One APS program's view of a :class:`~servobench.Card`: the APS_* functions with the card's axes 0..n-1."""

    _PARAMETER_ERROR = ERR_ParametersInvalid   # what an APS_* function returns instead of raising (issue 21.2)
    _COMMAND_ERROR = ERR_FunctionNotAvailable

    # -- plumbing ----------------------------------------------------------------------------------------------
    def _axis(self, axis_id):
        """The 0-based axis or None (not initialised / not an axis of the card)."""
        v = _num(axis_id)
        if self._card is None or v is None or v != int(v) or not 0 <= v < len(self._card):
            return None
        return int(v)

    def _bad(self) -> int:
        return ERR_DeviceNotInitial if self._card is None else ERR_ParametersInvalid

    def _do(self, fn, *args) -> int:
        try:
            fn(*args)
        except (CardCommandRefused, MotionCommandRefused):
            fault = self._card.last_fault
            if fault in _IGNORED:
                return ERR_NoError
            return ERR_DistantNotEnough if fault == "distance_too_short" else ERR_FunctionNotAvailable
        except ValueError:
            return ERR_ParametersInvalid
        return ERR_NoError

    def _prm(self):
        """The card's PRA_* parameter table (vendor/adlink/aps_parameters.hpp)."""
        return _core.aps_parameters(self._card.kernel)

    def _params(self, axis: int, **override) -> AdlinkPtp:
        """The axis's PRA_* motion parameters with ``override`` (validated: ValueError)."""
        return self._prm().motion(axis).replace(**override)

    # -- simulation helpers ------------------------------------------------------------------------------------
    def Sleep(self, ms: float):
        """The examples' ``Sleep(ms)``: runs the card ``ms`` milliseconds (rounded to whole servo ticks)."""
        return self.run_ms(ms)

    # -- system --------------------------------------------------------------------------------------------------
    def APS_initial(self, mode: int = 0, card: Card | None = None, **axis_parts):
        if self._card is not None:
            return ERR_DeviceAlreadyInitialed, 0
        if card is None and not axis_parts:
            card = self._machine_card()  # the machine a vendor program runs against (use_machine, issue 25.2)
        if card is None:
            axis_parts.setdefault("law", ApsServoLaw())
            axis_parts.setdefault("servo_period_s", 250e-6)
            card = Card(4, **axis_parts)
        if len(card) not in (4, 8):
            return ERR_ParametersInvalid, 0
        self._card = card
        self._prm().power_on()  # the PRA_* table (AV5)
        self._scope_init()  # sampling, trigger, interrupts (issue 10.3)
        _core.aps_point_tables(card.kernel).power_on()  # point tables (AF5-AF12, AW1)
        self._more_init()   # counters, watchdog, VAO, board parameters (AF13-AF21)
        return ERR_NoError, 1

    def APS_close(self) -> int:
        if self._card is None:
            return ERR_DeviceNotInitial
        self._more_close()  # the watchdog and the interrupt watch go with the card (AW4, AW5)
        self._card = None
        return ERR_NoError

    # -- axis parameters -----------------------------------------------------------------------------------------
    def APS_set_axis_param(self, Axis_ID, AxisPara, Data) -> int:
        v = _num(Data)
        if v is None or v != int(v):
            return self._bad()
        return self.APS_set_axis_param_f(Axis_ID, AxisPara, v)

    def APS_set_axis_param_f(self, Axis_ID, AxisPara, Data) -> int:
        i = self._axis(Axis_ID)
        v = _num(Data)
        return self._bad() if i is None or v is None else self._prm().set(i, AxisPara, v)

    def APS_get_axis_param_f(self, Axis_ID, AxisPara):
        i = self._axis(Axis_ID)
        return (self._bad(), 0.0) if i is None else self._prm().get(i, AxisPara)

    def APS_get_axis_param(self, Axis_ID, AxisPara):
        rtn, v = self.APS_get_axis_param_f(Axis_ID, AxisPara)
        return rtn, int(v)

    # -- servo and motion ------------------------------------------------------------------------------------------
    def APS_set_servo_on(self, Axis_ID, Servo_on) -> int:
        i = self._axis(Axis_ID)
        if i is None or Servo_on not in (0, 1):
            return self._bad()
        if not Servo_on:
            self._stop_modes(i, abrupt=True)  # servo off releases a gear / stops an interpolation (L3325)
        return self._do(self._card.axis_on if Servo_on else self._card.axis_off, i)

    def _release_limits(self, i: int) -> None:
        """Before a single-axis command: an idle group or halted gear hands axis i back, ended limit events clear
        (ADLINK limits are level inputs, V31; vendor/adlink/adlink_group.hpp aps_release_axis)."""
        _core.aps_release_axis(self._card.kernel, i)

    def _ptp(self, i: int, target: float, vm, wait: bool = False, **speeds) -> int:
        if target is None or target != int(target) or abs(target) > _POS_MAX:
            return ERR_ParametersInvalid
        if vm is None or not 0 < vm <= 1e9:
            return ERR_ParametersInvalid
        for k, v in speeds.items():
            lo, hi = _SPEEDS[k]
            if v is None or not lo <= v <= hi:
                return ERR_ParametersInvalid
        try:
            p = self._params(i, pos=target, vm=vm, **speeds)
        except ValueError:
            return ERR_ParametersInvalid
        self._release_limits(i)
        return self._do(self._card.move_ptp_wait if wait else self._card.move_ptp, i, p)

    def APS_relative_move(self, Axis_ID, Distance, Max_Speed) -> int:
        i = self._axis(Axis_ID)
        d = _num(Distance)
        if i is None or d is None:
            return self._bad()
        return self._ptp(i, self._card.profile_pos(i) + d if d == int(d) else None, _num(Max_Speed))

    def APS_absolute_move(self, Axis_ID, Position, Max_Speed) -> int:
        i = self._axis(Axis_ID)
        if i is None:
            return self._bad()
        return self._ptp(i, _num(Position), _num(Max_Speed))

    def _option(self, Axis_ID, Option, Position, Wait):
        """(axis, target, wait) of an APS_ptp-family call, or an error code."""
        i = self._axis(Axis_ID)
        o, pos = _num(Option), _num(Position)
        if i is None or o is None or o != int(o) or pos is None or Wait not in (None, 0):
            return self._bad()
        o = int(o)
        if o & ~(1 | MF_WAIT):
            return ERR_FunctionNotAvailable  # buffer modes (bits 12-15) are not simulated (V32)
        if pos != int(pos) or abs(pos) > _POS_MAX:
            return ERR_ParametersInvalid
        target = self._card.profile_pos(i) + pos if o & 1 else pos
        return i, target, bool(o & MF_WAIT)

    def APS_ptp(self, Axis_ID, Option, Position, Wait=None) -> int:
        r = self._option(Axis_ID, Option, Position, Wait)
        if isinstance(r, int):
            return r
        i, target, wait = r
        return self._ptp(i, target, self._prm().motion(i).vm, wait)

    def APS_ptp_v(self, Axis_ID, Option, Position, Vm, Wait=None) -> int:
        r = self._option(Axis_ID, Option, Position, Wait)
        if isinstance(r, int):
            return r
        i, target, wait = r
        return self._ptp(i, target, _num(Vm), wait)

    def APS_ptp_all(self, Axis_ID, Option, Position, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None) -> int:
        r = self._option(Axis_ID, Option, Position, Wait)
        if isinstance(r, int):
            return r
        i, target, wait = r
        return self._ptp(i, target, _num(Vm), wait, vs=_num(Vs), ve=_num(Ve), acc=_num(Acc), dec=_num(Dec),
                         sf=_num(SFac))

    def APS_move_trigger(self, Dimension, Axis_ID_Array) -> int:
        d = _num(Dimension)
        if self._card is None:
            return ERR_DeviceNotInitial
        try:
            ids = list(Axis_ID_Array)
        except TypeError:
            return ERR_ParametersInvalid
        if d is None or d != int(d) or not 1 <= d <= len(self._card) or len(ids) < d:
            return ERR_ParametersInvalid
        mask = 0
        for a in ids[: int(d)]:
            i = self._axis(a)
            if i is None:
                return ERR_ParametersInvalid
            mask |= 1 << i
        c = self._card
        if c.aps_interp_trigger(mask):  # a waiting interpolation starts with its reference axis (V115)
            mask &= ~sum(1 << a for a in c.aps_interp_info()["array"])
            if mask == 0:
                return ERR_NoError
        return self._do(c.move_trigger, mask)

    def APS_home_move(self, Axis_ID) -> int:
        i = self._axis(Axis_ID)
        if i is None:
            return self._bad()
        try:
            p = self._prm().home(i).replace()  # validated before anything changes
        except ValueError:
            return ERR_ParametersInvalid
        self._release_limits(i)
        return self._do(self._card.home, i, p)

    def APS_jog_on(self, Axis_ID, On) -> int:
        i = self._axis(Axis_ID)
        if i is None or On not in (0, 1):
            return self._bad()
        c = self._card
        if On and not c.jog_on(i):
            if not c.jogging(i):
                try:
                    p = self._prm().jog(i).replace()
                except ValueError:
                    return ERR_ParametersInvalid
                self._release_limits(i)
                rtn = self._do(c.jog, i, p)
                if rtn != ERR_NoError:
                    return rtn
            return self._do(c.set_jog_on, i, True)
        if not On and c.jog_on(i):
            return self._do(c.set_jog_on, i, False)
        return ERR_NoError

    def APS_velocity_move(self, Axis_ID, Max_Speed) -> int:
        i = self._axis(Axis_ID)
        v = _num(Max_Speed)
        if i is None or v is None:
            return self._bad()
        if v == 0 or abs(v) > 1e9:
            return ERR_ParametersInvalid
        self._release_limits(i)
        return self._do(self._card.move_velocity, i, v, self._params(i, vm=abs(v)))

    def APS_vel(self, Axis_ID, Dir, Vel, Wait=None) -> int:
        i = self._axis(Axis_ID)
        v = _num(Vel)
        if i is None or v is None or Dir not in (0, 1) or Wait not in (None, 0) or not 0 < v <= 1e9:
            return self._bad()
        self._release_limits(i)
        return self._do(self._card.move_velocity, i, -v if Dir else v, self._params(i, vm=v))

    def APS_stop_move(self, Axis_ID) -> int:
        i = self._axis(Axis_ID)
        if i is None:
            return self._bad()
        if self._stop_modes(i, abrupt=False):
            return ERR_NoError
        return self._do(self._card.stop_move, i, self._params(i))

    def APS_emg_stop(self, Axis_ID) -> int:
        i = self._axis(Axis_ID)
        if i is None:
            return self._bad()
        if self._stop_modes(i, abrupt=True):
            return ERR_NoError
        return self._do(self._card.abrupt_stop, i)

    # -- interpolation and gear (L2813-3150, L3294-3346; decisions V113-V125) ---------------------------------------
    def _release_modes(self, i: int) -> None:
        """An idle interpolation group holding axis i, or a halted gear, hands it back (V116, V121)."""
        _core.aps_release_modes(self._card.kernel, i)

    def _stop_modes(self, i: int, abrupt: bool) -> bool:
        """A stop of an axis of a moving group stops the group (V117); of a gear slave releases it (V121)."""
        return _core.aps_stop_modes(self._card.kernel, i, abrupt)

    def APS_start_gear(self, Axis_ID, Mode) -> int:
        i = self._axis(Axis_ID)
        if i is None or Mode not in (0, 1, 2):
            return self._bad()
        c = self._card
        if Mode == 0:
            if c.mode(i) != "gear":
                return ERR_NoError
            return self._do(c.set_mode, i, "t_curve")
        if Mode == 2:
            return ERR_FunctionNotAvailable
        master, ratio, rate = self._prm().gear(i)
        if int(master) == i:
            return ERR_ParametersInvalid
        self._release_modes(i)
        return self._do(c.set_gear_ramp, i, int(master), ratio, rate * c.servo_period_s)

    def _interp(self, ids, option, kind, trans, vm=None, speeds=None, **geom) -> int:
        """One interpolation command: validates the axis array and Option, builds the move, hands it to the card
        (Card.aps_interp). ``trans`` is TransPara: the residual distance (mode 6, pulse) or percent (mode 7)."""
        c = self._card
        if c is None:
            return ERR_DeviceNotInitial
        try:
            arr = [self._axis(a) for a in ids]
        except TypeError:
            return ERR_ParametersInvalid
        o = _num(option)
        if None in arr or len(set(arr)) != len(arr) or not 2 <= len(arr) <= 6 or o is None or o != int(o):
            return ERR_ParametersInvalid
        o = int(o)
        field = (o >> 12) & 0xF
        if o & ~(1 | MF_WAIT | 0xF000) or field > 6:
            return ERR_ParametersInvalid
        mode = _BLEND_MODES[field]
        t = _num(trans) if trans is not None else 0.0
        if t is None:
            return ERR_ParametersInvalid
        blend = t if mode in (BlendMode.BLEND_DISTANCE, BlendMode.BLEND_PERCENT) else 0.0
        for k, v in geom.items():
            if k in ("angle_deg", "height", "final_radius", "dir"):
                x = _num(v)
                if x is None or (k == "dir" and (x != int(x) or abs(x) > 32767)):  # I16 Dir
                    return ERR_ParametersInvalid
                geom[k] = int(x) if k == "dir" else x
                continue
            try:
                vals = [_num(x) for x in v]
            except TypeError:
                return ERR_ParametersInvalid
            if None in vals:
                return ERR_ParametersInvalid
            geom[k] = vals
        all_ = None
        if speeds is not None:
            vals = {k: _num(x) for k, x in speeds.items()}
            if None in vals.values():
                return ERR_ParametersInvalid
            try:
                all_ = AdlinkPtp(**vals, sd_dec=self._prm().motion(arr[0]).sd_dec)
            except ValueError:
                return ERR_ParametersInvalid
        v = 0.0 if vm is None else _num(vm)
        if v is None or (vm is not None and not 0 < v <= 1e9):
            return ERR_ParametersInvalid
        for a in arr:
            self._release_limits(a)
        info = c.aps_interp_info()
        if info["set_up"] and not info["busy"]:
            self._release_modes(arr[0])
        try:
            params = [self._params(a) for a in arr]
        except ValueError:
            return ERR_ParametersInvalid
        return self._do(lambda: c.aps_interp(arr, params, kind, relative=bool(o & 1), mode=mode, blend=blend, vm=v,
                                             all=all_, wait=bool(o & MF_WAIT), **geom))

    def APS_line(self, Dimension, Axis_ID_Array, Option, PositionArray, TransPara=0.0, Wait=None) -> int:
        return self._line(Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Wait)

    def _line(self, Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Wait, **speeds) -> int:
        """APS_line / _v / _all: the first Dimension axes and positions, then :meth:`_interp`."""
        d = _num(Dimension)
        if Wait not in (None, 0) or d is None or d != int(d):
            return self._bad()
        try:
            ids, pos = list(Axis_ID_Array)[: int(d)], list(PositionArray)[: int(d)]
        except TypeError:
            return ERR_ParametersInvalid
        if len(ids) != d or len(pos) != d:
            return ERR_ParametersInvalid
        return self._interp(ids, Option, "line", TransPara, target=pos, **speeds)

    def APS_line_v(self, Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Vm, Wait=None) -> int:
        return self._line(Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Wait, vm=Vm)

    def APS_line_all(self, Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Vs, Vm, Ve, Acc, Dec, SFac,
                     Wait=None) -> int:
        return self._line(Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Wait, vm=Vm,
                          speeds=dict(vs=Vs, vm=Vm, ve=Ve, acc=Acc, dec=Dec, sf=SFac))

    def APS_absolute_linear_move(self, Dimension, Axis_ID_Array, Position_Array, Max_Linear_Speed) -> int:
        return self._linear_move(Dimension, Axis_ID_Array, Position_Array, Max_Linear_Speed, 0)

    def APS_relative_linear_move(self, Dimension, Axis_ID_Array, Distance_Array, Max_Linear_Speed) -> int:
        return self._linear_move(Dimension, Axis_ID_Array, Distance_Array, Max_Linear_Speed, 1)

    def _linear_move(self, Dimension, ids, values, speed, option) -> int:
        try:
            vals = [_num(x) for x in values]
        except TypeError:
            return ERR_ParametersInvalid
        if None in vals or any(x != int(x) or abs(x) > _POS_MAX for x in vals):
            return ERR_ParametersInvalid
        s = _num(speed)
        if s is None or s != int(s):
            return ERR_ParametersInvalid
        return self.APS_line_v(Dimension, ids, option, vals, 0.0, s)

    def _arc(self, kind, ids, dim, Option, TransPara, Wait, vm=None, speeds=None, **geom) -> int:
        if Wait not in (None, 0):
            return self._bad()
        try:
            ids = list(ids)
            for k in ("center", "target", "normal"):
                if k in geom:
                    geom[k] = list(geom[k])
                    if len(geom[k]) != (3 if k == "normal" else dim):
                        return ERR_ParametersInvalid
        except TypeError:
            return ERR_ParametersInvalid
        if len(ids) != dim:
            return ERR_ParametersInvalid
        return self._interp(ids, Option, kind, TransPara, vm=vm, speeds=speeds, **geom)

    # -- [/interpolation and gear] ----------------------------------------------------------------------------------

    # -- positions -------------------------------------------------------------------------------------------------
    def APS_get_position(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, register32(self._card.actual_pos(i)))

    def APS_set_position(self, Axis_ID, Position) -> int:
        i = self._axis(Axis_ID)
        p = _num(Position)
        if i is None or p is None or p != int(p) or abs(p) > _POS_MAX:
            return self._bad()
        self._release_modes(i)
        return self._do(self._card.set_actual_pos, i, p)

    def APS_get_command(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, register32(self._card.profile_pos(i)))

    def APS_get_error_position(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, int(round(self._card.following_error(i))))

    # -- status ------------------------------------------------------------------------------------------------------
    def APS_motion_status(self, Axis_ID) -> int:
        i = self._axis(Axis_ID)
        return self._bad() if i is None else int(_core.aps_group_motion_status(self._card.kernel, i))

    def APS_motion_io_status(self, Axis_ID) -> int:
        i = self._axis(Axis_ID)
        return self._bad() if i is None else int(_core.aps_motion_io_status(self._card.kernel, i))

    def APS_get_stop_code(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, int(_core.aps_group_stop_code(self._card.kernel, i)))


# -- sampling, position compare trigger, host interrupts (issue 10 point 3; decisions V71-V85) -------------------
# The sources' signals, units and bits are the C++ module's table (vendor/adlink/aps_scope.cpp, Tables 4-5/4-6).
#: One sample of APS_wait_trigger_sampling (STR_SAMP_DATA_4CH {I32 tick; I32 data[4]}; data F64 here, V78).
STR_SAMP_DATA_4CH = np.dtype([("tick", np.int64), ("data", np.float64, (4,))])


class _ApsScope:
    """The sampling, trigger and interrupt functions of :class:`ApsController` (mixed in)."""

    def _scope_init(self):
        self._scope().power_on()  # sampling, trigger and timer registers: the C++ module's (AV2)
        self._ints().power_on()   # interrupt table and its own watch of the card (AV4, AW4)

    def _scope(self):
        """The card's ADLINK scope module (vendor/adlink/aps_scope.hpp): the sampling/trigger/timer registers."""
        return _core.aps_scope(self._card.kernel)

    def _board(self, Board_ID) -> bool:
        return self._card is not None and _num(Board_ID) == 0

    # -- data sampling (L3544-3665): the registers and the run are vendor/adlink/aps_scope.hpp's ------------------
    def APS_set_sampling_param(self, Board_ID, ParaNum, ParaDat) -> int:
        return self._scope().set_sampling_param(ParaNum, ParaDat) if self._board(Board_ID) else self._bad()

    def APS_get_sampling_param(self, Board_ID, ParaNum):
        return self._scope().sampling_param(ParaNum) if self._board(Board_ID) else (self._bad(), 0)

    def APS_wait_trigger_sampling(self, Board_ID, Length, PreTrgLen, TimeOutMs):
        rtn, data = self.APS_wait_trigger_sampling_async(Board_ID, Length, PreTrgLen, TimeOutMs)
        if rtn != ERR_NoError:
            return rtn, None
        s, c = self._scope(), self._card
        c.run_until(lambda _c: s.sampling_block_ready(), max_ticks=s.sampling_ticks_left(),
                    chunk=max(1, int(round(1e-3 / c.servo_period_s))))
        rtn = s.finish_sampling()
        return rtn, (data if rtn == ERR_NoError else None)

    def APS_wait_trigger_sampling_async(self, Board_ID, Length, PreTrgLen, TimeOutMs):
        if not self._board(Board_ID):
            return self._bad(), None
        rtn = self._scope().start_sampling(Length, PreTrgLen, TimeOutMs)
        return rtn, (self._scope().sampling_buffer() if rtn == ERR_NoError else None)

    def APS_get_sampling_count(self, Board_ID):
        return (ERR_NoError, self._scope().sampling_count()) if self._board(Board_ID) else (self._bad(), 0)

    def APS_stop_wait_sampling(self, Board_ID) -> int:
        if not self._board(Board_ID):
            return self._bad()
        self._scope().stop_sampling()
        return ERR_NoError

    # -- position compare trigger (L3348-3435) ------------------------------------------------------------------
    def _trg_count_ok(self, ch) -> bool:
        v = _num(ch)
        return v is not None and v == int(v) and 0 <= v < (2 if len(self._card) == 4 else 4)

    def APS_set_trigger_param(self, Board_ID, Param_No, Param_Val) -> int:
        return self._scope().set_trigger_param(Param_No, Param_Val) if self._board(Board_ID) else self._bad()

    def APS_get_trigger_param(self, Board_ID, Param_No):
        return self._scope().trigger_param(Param_No) if self._board(Board_ID) else (self._bad(), 0)

    def APS_set_trigger_linear(self, Board_ID, LCmpCh, StartPoint, RepeatTimes, Interval) -> int:
        if not self._board(Board_ID):
            return self._bad()
        ch = _num(LCmpCh)
        if ch not in (0, 1):
            return ERR_ParametersInvalid
        return self._do(self._card.compare_set_linear, int(ch), _num(StartPoint), _num(RepeatTimes), _num(Interval))

    def APS_set_trigger_table(self, Board_ID, TCmpCh, DataArr, ArraySize) -> int:
        if not self._board(Board_ID):
            return self._bad()
        ch, n = _num(TCmpCh), _num(ArraySize)
        try:
            pts = [float(x) for x in DataArr]
        except (TypeError, ValueError):
            return ERR_ParametersInvalid
        if ch not in (0, 1) or n is None or n != int(n) or not 0 <= n <= len(pts):
            return ERR_ParametersInvalid
        return self._do(self._card.compare_set_table, int(ch), pts[:int(n)])

    def APS_set_trigger_manual(self, Board_ID, TrgCh) -> int:
        if not self._board(Board_ID):
            return self._bad()
        if not self._trg_count_ok(TrgCh):
            return ERR_ParametersInvalid
        return self._do(self._card.compare_manual, int(_num(TrgCh)))

    def APS_get_trigger_count(self, Board_ID, TrgCh):
        if not self._board(Board_ID):
            return self._bad(), 0
        if not self._trg_count_ok(TrgCh):
            return ERR_ParametersInvalid, 0
        return ERR_NoError, int(self._card.compare_count(int(_num(TrgCh))))

    def APS_reset_trigger_count(self, Board_ID, TrgCh) -> int:
        if not self._board(Board_ID):
            return self._bad()
        if not self._trg_count_ok(TrgCh):
            return ERR_ParametersInvalid
        return self._do(self._card.compare_reset_count, int(_num(TrgCh)))

    def APS_get_trigger_linear_cmp(self, Board_ID, LCmpCh):
        return self._next_cmp(Board_ID, LCmpCh, 0)

    def APS_get_trigger_table_cmp(self, Board_ID, TCmpCh):
        return self._next_cmp(Board_ID, TCmpCh, 2)

    def _next_cmp(self, Board_ID, ch, base):
        if not self._board(Board_ID):
            return self._bad(), 0
        if _num(ch) not in (0, 1):
            return ERR_ParametersInvalid, 0
        v = self._card.compare_next_point(base + int(_num(ch)))
        return ERR_NoError, (0 if math.isnan(v) else int(v))

    # -- host interrupts (L4090-4330): the table is vendor/adlink/aps_interrupts.hpp's (AV4) ------------------------
    def _ints(self):
        """The card's ADLINK interrupt module (main switch, factors, signaled flags, the wait)."""
        return _core.aps_interrupts(self._card.kernel)

    def APS_int_enable(self, Board_ID, Enable) -> int:
        return self._ints().set_main(Enable) if self._board(Board_ID) else self._bad()

    def APS_set_int_factor(self, Board_ID, Item_No, Factor_No, Enable) -> int:
        if not self._board(Board_ID):
            return self._bad()
        return self._ints().set_factor(Item_No, Factor_No, Enable)  # the module watches the card itself (AW4)

    def APS_get_int_factor(self, Board_ID, Item_No, Factor_No):
        return self._ints().factor_enabled(Item_No, Factor_No) if self._board(Board_ID) else (self._bad(), 0)

    def APS_int_no_to_handle(self, Int_No):
        return int(Int_No)

    def APS_wait_single_int(self, Int_No, Time_Out) -> int:
        return self.APS_wait_multiple_int(1, [Int_No], 1, Time_Out)

    def APS_wait_multiple_int(self, Int_Count, Int_No_Array, Wait_All, Time_Out) -> int:
        if self._card is None:
            return ERR_DeviceNotInitial
        m = self._ints()
        rtn, ticks = m.begin_wait(Int_Count, list(Int_No_Array), Wait_All, Time_Out)
        if rtn != ERR_NoError:
            return rtn
        self._card.run_until_fired(m.wait_done, ticks)
        return ERR_NoError if m.wait_done() else ERR_TimeOut

    def APS_reset_int(self, Int_No) -> int:
        return ERR_DeviceNotInitial if self._card is None else self._ints().set_signaled(Int_No, False)

    def APS_set_int(self, Int_No) -> int:
        return ERR_DeviceNotInitial if self._card is None else self._ints().set_signaled(Int_No, True)


# The arc and spiral commands (L2899-3063; argument lists V113) as rows: manual name -> (Card.aps_interp kind, axes,
# the manual's geometry arguments -> aps_interp keywords, what the manual says). Each row makes three functions with
# the manual's signatures: NAME (PRA speeds), NAME_v (at vector speed Vm, pulse/s), NAME_all (every speed given:
# Vs/Vm/Ve pulse/s, Acc/Dec pulse/s^2, SFac 0..1). Positions in pulse, angles in degrees; Option and TransPara as
# APS_line; ``Wait`` must be None/0.
_ARCS = {
    "APS_arc2_ca": ("arc2_ca", 2, {"CenterArray": "center", "Angle": "angle_deg"},
                    "``APS_arc2_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 Angle, F64 *TransPara, "
                    "ASYNCALL *Wait)`` (L2978): a 2-D arc about the centre by Angle degrees (+ CCW, ``|Angle|`` > 360 "
                    "= laps)."),
    "APS_arc2_ce": ("arc2_ce", 2, {"CenterArray": "center", "EndArray": "target", "Dir": "dir"},
                    "``APS_arc2_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *EndArray, I16 Dir, F64 "
                    "*TransPara, ASYNCALL *Wait)`` (L2981): a 2-D arc to an exact end point, Angle = theta + Dir*360 "
                    "(L2943-2958); exactly 180 deg or 360 deg is ERR_ParametersInvalid (L2930-2933)."),
    "APS_arc3_ca": ("arc3_ca", 3, {"CenterArray": "center", "NormalArray": "normal", "Angle": "angle_deg"},
                    "``APS_arc3_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 Angle, "
                    "F64 *TransPara, ASYNCALL *Wait)`` (L2899): a 3-D arc, right-hand rule about the normal "
                    "(Gram-Schmidt, L2911)."),
    "APS_arc3_ce": ("arc3_ce", 3, {"CenterArray": "center", "EndArray": "target", "Dir": "dir"},
                    "``APS_arc3_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *EndArray, I16 Dir, F64 "
                    "*TransPara, ASYNCALL *Wait)`` (L2900): a 3-D arc to an exact end point (no half or full "
                    "circle)."),
    "APS_sprial_ca": ("spiral_ca", 3, {"CenterArray": "center", "NormalArray": "normal", "Angle": "angle_deg",
                                       "DeltaH": "height", "FinalR": "final_radius"},
                      "``APS_sprial_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 "
                      "Angle, F64 DeltaH, F64 FinalR, F64 *TransPara, ASYNCALL *Wait)`` (the manual's spelling, "
                      "L3047): a conical spiral, rise DeltaH along the normal, radius to FinalR (L3001-3035)."),
    "APS_sprial_ce": ("spiral_ce", 3, {"CenterArray": "center", "NormalArray": "normal", "EndArray": "target",
                                       "Dir": "dir"},
                      "``APS_sprial_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 "
                      "*EndArray, I16 Dir, F64 *TransPara, ASYNCALL *Wait)`` (L3050): a spiral to an exact end point "
                      "(L3037-3063)."),
}
_SPEED_ARGS = {"_v": ("Vm",), "_all": ("Vs", "Vm", "Ve", "Acc", "Dec", "SFac")}


def _arc_function(name: str, suffix: str, kind: str, dim: int, geom: dict, doc: str):
    """One ApsController method of an _ARCS row: the manual's signature, one call of ``_arc``."""
    P = inspect.Parameter
    extra = _SPEED_ARGS.get(suffix, ())
    params = [P(n, P.POSITIONAL_OR_KEYWORD) for n in ("self", "Axis_ID_Array", "Option", *geom)]
    params.append(P("TransPara", P.POSITIONAL_OR_KEYWORD, **({} if suffix else {"default": 0.0})))
    params += [P(n, P.POSITIONAL_OR_KEYWORD) for n in extra] + [P("Wait", P.POSITIONAL_OR_KEYWORD, default=None)]
    sig = inspect.Signature(params, return_annotation="int")

    def method(*args, **kwargs):
        a = sig.bind(*args, **kwargs)
        a.apply_defaults()
        v = a.arguments
        speeds = dict(zip(("vs", "vm", "ve", "acc", "dec", "sf"), (v[k] for k in extra))) if suffix == "_all" else None
        return v["self"]._arc(kind, v["Axis_ID_Array"], dim, v["Option"], v["TransPara"], v["Wait"], vm=v.get("Vm"),
                              speeds=speeds, **{key: v[arg] for arg, key in geom.items()})

    method.__name__ = method.__qualname__ = name + suffix
    method.__signature__ = sig  # type: ignore[attr-defined]
    method.__annotations__ = {"return": "int"}
    method.__doc__ = doc if not suffix else (f":func:`{name}` at vector speed Vm (pulse/s)." if suffix == "_v" else
                                             f":func:`{name}` with every speed given (the PRA values unchanged).")
    return method


for _name, (_kind, _dim, _geom, _doc) in _ARCS.items():
    for _suffix in ("", "_v", "_all"):
        setattr(ApsController, _name + _suffix, _arc_function(_name, _suffix, _kind, _dim, _geom, _doc))

for _mixin in (_ApsScope, _ApsPointTable, _ApsMore):  # the blocks' functions are ApsController methods
    for _name, _fn in list(vars(_mixin).items()):
        if callable(_fn) and not _name.startswith("__"):
            setattr(ApsController, _name, _fn)
for _name, _args, _doc in _core.APS_COMMANDS:  # what each function does: the C++ table's row (AX2)
    getattr(ApsController, _name).__doc__ = _doc

#: Functions the simulation cannot carry out: they return the vendor's error code (issue 25.3).
UNSUPPORTED = {
    "APS_pt_set_trans_inp": "the card's interpolation has no in-position transition (its seven modes, L3085-3143): "
                            "ERR_FunctionNotAvailable, the table keeps its mode (AF8)",
}


_default = ApsController()
APS_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "APS_")


def Sleep(ms: float):
    """The examples' ``Sleep(ms)``: runs the open card ``ms`` milliseconds (rounded to whole servo ticks)."""
    return _default.Sleep(ms)


def use_machine(machine) -> None:
    """The simulated machine a vendor program's ``APS_initial`` opens (a Card or a factory; None forgets it):
    :meth:`~servobench.dialects._controller.DialectController.use_machine` of the default controller."""
    _default.use_machine(machine)


def vao_output(ctrl: int) -> dict:
    """Simulation helper: what PWM ``ctrl`` (0..1) of the open card outputs now (:meth:`ApsController.vao_output`)."""
    return _default.vao_output(ctrl)


# The vendor's names (return codes, PRA_* parameter numbers, the other header constants, the APS_* functions) and
# the simulation helpers; numpy and the package internals stay out of ``from ... import *`` and completion.
__all__ = ["ApsController", "APS_FUNCTIONS", "Sleep", "card", "controller", "run", "wait_until", "use_machine",
           "vao_output", "UNSUPPORTED", "PTSTS", "PTLINE", "PTA2CA", "PTA2CE", "PTHCA", "PTHCE", "PTDWL",
           *sorted(n for n in dict(globals()) if n.split("_")[0] in (
               "ERR", "PRA", "MF", "STOP", "STR", "TGR", "TIMR", "TRG", "MTS", "MIO", "PRB", "PRS", "VAO", "WDT",
               "ITP", "SAMP", "PT", "PTB")),
           *APS_FUNCTIONS]
