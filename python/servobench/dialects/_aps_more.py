"""More ADLINK functions of :class:`~servobench.dialects.aps.ApsController` (mixed in; issue 25.3, decisions
AF13-AF24): the ``*_multi`` stops and ``APS_vel_all`` (L2566-2584), the position and counter reads (L2056-2099),
the compare timer counter (L3363-3378), the watchdog (L4025-4084), the VAO (velocity -> PWM power) tables
(L3436-3542), the board parameters and the drive control mode (L1498, L1623, L3520-3533), and the digital
outputs the point table and the watchdog write (APS_read_d_output / APS_write_d_output of the APS library).

Units: pulse, pulse/s, pulse/s^2; the watchdog's time-out in 100 ms (L4070); VAO powers in the table's unit
(mode 1: duty in 0.05 %, modes 2-3: Hz; L3489-3495).
"""

from __future__ import annotations

import math

from .. import _core
from ._aps_constants import ERR_DeviceNotInitial, ERR_FunctionNotAvailable, ERR_NoError, ERR_ParametersInvalid
from ._aps_pt import _f


def _num(v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) else None


def _int(v):
    x = _num(v)
    return int(x) if x is not None and x == int(x) else None


class _ApsMore:
    """The functions of this module's docstring (mixed into ApsController)."""

    def _more_init(self):
        self._outs().power_on()  # DO word, board parameters, VAO: vendor/adlink/aps_outputs.hpp (AV9)
        _core.aps_watchdog(self._card.kernel).power_on()  # vendor/adlink/aps_watchdog.hpp (AW5)

    def _outs(self):
        """The card's ADLINK output module (DO0..7, board parameters, VAO tables)."""
        return _core.aps_outputs(self._card.kernel)

    def _more_close(self):
        """The watchdog and the interrupt watch go with the card (their vendor watches end)."""
        _core.aps_watchdog(self._card.kernel).power_on()
        _core.aps_interrupts(self._card.kernel).power_on()

    # -- stops and velocity (L2566-2584) ---------------------------------------------------------------------
    def _multi(self, Dimension, Axis_ID_Array, stop) -> int:
        if self._card is None:
            return ERR_DeviceNotInitial
        d = _int(Dimension)
        try:
            ids = [self._axis(a) for a in list(Axis_ID_Array)[: d or 0]]
        except TypeError:
            return ERR_ParametersInvalid
        if d is None or not 1 <= d <= len(self._card) or len(ids) != d or None in ids:
            return ERR_ParametersInvalid
        rtn = ERR_NoError
        for i in ids:                    # one call: no card time passes between the axes (the same tick)
            r = stop(i)
            rtn = rtn if r == ERR_NoError else r
        return rtn

    def APS_stop_move_multi(self, Dimension, Axis_ID_Array) -> int:
        return self._multi(Dimension, Axis_ID_Array, self.APS_stop_move)

    def APS_emg_stop_multi(self, Dimension, Axis_ID_Array) -> int:
        return self._multi(Dimension, Axis_ID_Array, self.APS_emg_stop)

    def APS_vel_all(self, Axis_ID, Option, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None) -> int:
        i = self._axis(Axis_ID)
        vals = [_num(x) for x in (Vs, Vm, Ve, Acc, Dec, SFac)]
        if i is None or None in vals or Option not in (0, 1) or Wait not in (None, 0):
            return self._bad()
        vs, vm, ve, acc, dec, sf = vals
        if not 0 < vm <= 1e9 or not 0 <= vs <= vm or not 0 <= ve <= 1e9 or not 0 < acc <= 1e12 \
                or not 0 < dec <= 1e12 or not 0 <= sf <= 1:
            return ERR_ParametersInvalid
        self._release_limits(i)
        return self._do(self._card.move_velocity, i, -vm if Option else vm,
                        self._params(i, vs=vs, vm=vm, acc=acc, dec=dec, sf=sf))

    # -- positions and counters (L2056-2099; unit factor 1: coordinates = motor pulses, AF14) -------------------
    def APS_get_command_f(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0.0) if i is None else (ERR_NoError, float(self._card.profile_pos(i)))

    def APS_set_command(self, Axis_ID, Command) -> int:
        i = self._axis(Axis_ID)
        p = _num(Command)
        if i is None or p is None or p != int(p) or abs(p) > 2147483647:
            return self._bad()
        c = self._card
        self._release_modes(i)
        return self._do(c.set_actual_pos, i, float(c.actual_pos(i)) + (p - float(c.profile_pos(i))))

    def APS_get_encoder(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, _reg32(self._card.actual_pos(i)))

    def APS_get_command_counter(self, Axis_ID):
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, _reg32(self._card.profile_pos(i)))

    # -- compare timer (L3363-3378; TIMR_* of APS_set_trigger_param): vendor/adlink/aps_scope.hpp's (AF15) ------
    def APS_get_timer_counter(self, Board_ID, TmrCh):
        if not self._board(Board_ID):
            return self._bad(), 0
        return (ERR_NoError, self._scope().timer_counter()) if _num(TmrCh) == 0 else (ERR_ParametersInvalid, 0)

    def APS_set_timer_counter(self, Board_ID, TmrCh, Cnt) -> int:
        if not self._board(Board_ID):
            return self._bad()
        return self._scope().set_timer_counter(Cnt) if _num(TmrCh) == 0 else ERR_ParametersInvalid

    # -- watchdog (L4025-4084): vendor/adlink/aps_watchdog.hpp's (AW5) -------------------------------------------
    def _watchdog(self, call, *args):
        """``call(module, board, timer, *args)`` on the card's ADLINK watchdog, or ERR_DeviceNotInitial."""
        if self._card is None:
            return ERR_DeviceNotInitial
        return call(_core.aps_watchdog(self._card.kernel), *(_f(a) for a in args))

    def APS_wdt_set_action_event(self, Board_ID, TimerNo, EventByBit) -> int:
        return self._watchdog(lambda w, *a: w.set_action(*a), Board_ID, TimerNo, EventByBit)

    def APS_wdt_get_action_event(self, Board_ID, TimerNo):
        return (ERR_DeviceNotInitial, 0) if self._card is None else self._watchdog(lambda w, *a: w.action(*a), Board_ID,
                                                                                      TimerNo)

    def APS_wdt_start(self, Board_ID, TimerNo, TimeOut) -> int:
        return self._watchdog(lambda w, *a: w.start(*a), Board_ID, TimerNo, TimeOut)

    def APS_wdt_get_timeout_period(self, Board_ID, TimerNo):
        return (ERR_DeviceNotInitial, 0) if self._card is None else self._watchdog(lambda w, *a: w.period(*a), Board_ID,
                                                                                      TimerNo)

    def APS_wdt_reset_counter(self, Board_ID, TimerNo) -> int:
        return self._watchdog(lambda w, *a: w.reset_counter(*a), Board_ID, TimerNo)

    # -- digital outputs, board parameters, VAO: adapters over vendor/adlink/aps_outputs.hpp (AV9) -----------------
    def APS_write_d_output(self, Board_ID, DO_Group, DO_Data) -> int:
        return self._outs().write_do(DO_Group, DO_Data) if self._board(Board_ID) else self._bad()

    def APS_read_d_output(self, Board_ID, DO_Group):
        if not self._board(Board_ID):
            return self._bad(), 0
        _core.aps_point_tables(self._card.kernel).sync()
        return self._outs().read_do(DO_Group)

    def APS_set_board_param(self, Board_ID, BOD_Param_No, BOD_Param) -> int:
        return self._outs().set_board_param(BOD_Param_No, BOD_Param) if self._board(Board_ID) else self._bad()

    def APS_get_board_param(self, Board_ID, BOD_Param_No):
        return self._outs().board_param(BOD_Param_No) if self._board(Board_ID) else (self._bad(), 0)

    def APS_get_eep_curr_drv_ctrl_mode(self, Board_ID):
        if not self._board(Board_ID):
            return self._bad(), 0
        return ERR_NoError, (1 << len(self._card)) - 1

    def APS_set_vao_param(self, Board_ID, Param_No, Param_Val) -> int:
        return self._outs().set_vao_param(Param_No, Param_Val) if self._board(Board_ID) else self._bad()

    def APS_set_vao_table(self, Board_ID, Table_No, MinVelocity, VelInterval, TotalPoints, MappingDataArray) -> int:
        if not self._board(Board_ID):
            return self._bad()
        return self._outs().set_vao_table(Table_No, MinVelocity, VelInterval, TotalPoints, list(MappingDataArray))

    def APS_switch_vao_table(self, Board_ID, Table_No) -> int:
        return self._outs().switch_vao_table(Table_No) if self._board(Board_ID) else self._bad()

    def APS_start_vao(self, Board_ID, Output_Ch, Enable) -> int:
        return self._outs().start_vao(Output_Ch, Enable) if self._board(Board_ID) else self._bad()

    def vao_output(self, ctrl: int) -> dict:
        """Simulation helper (not in the manual): what PWM ``ctrl`` (0..1) outputs now: ``on`` (APS_start_vao,
        not switched off by the watchdog, and its PRB_PWMx_MAP_DO digital output in the enabling state),
        ``table``, ``speed`` (the composite command speed of the table's VAO_TABLE_SRC axes, pulse/s) and
        ``power`` interpolated linearly between the table's points (L3489), held at its first/last point outside
        them, in the output type's unit (``unit``: "0.05 %" or "Hz"); ``power`` is 0 when off."""
        if ctrl not in (0, 1):
            raise ValueError(f"vao_output.ctrl = {ctrl!r} must be 0 or 1 (the VAO controllers)")
        _core.aps_point_tables(self._card.kernel).sync()
        return self._outs().vao_output(ctrl)


def _reg32(v: float) -> int:
    x = int(round(v))
    return ((x + 2**31) % 2**32) - 2**31
