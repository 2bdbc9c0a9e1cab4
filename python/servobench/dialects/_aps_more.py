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
        """``APS_stop_move_multi(I32 Dimension, I32 *Axis_ID_Array)`` (L2578): :func:`APS_stop_move` on the first
        Dimension axes in the same servo tick (each decelerates at its PRA_SD_DEC)."""
        return self._multi(Dimension, Axis_ID_Array, self.APS_stop_move)

    def APS_emg_stop_multi(self, Dimension, Axis_ID_Array) -> int:
        """``APS_emg_stop_multi(I32 Dimension, I32 *Axis_ID_Array)`` (L2580): :func:`APS_emg_stop` (immediate) on
        the first Dimension axes in the same servo tick."""
        return self._multi(Dimension, Axis_ID_Array, self.APS_emg_stop)

    def APS_vel_all(self, Axis_ID, Option, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None) -> int:
        """``APS_vel_all(Axis_ID, Option, F64 Vs, F64 Vm, F64 Ve, F64 Acc, F64 Dec, F64 SFac, ASYNCALL *Wait)``
        (L2572): a velocity move at ``Vm`` pulse/s (Option 0 positive, 1 negative, as APS_vel, V50) from ``Vs``
        with ``Acc``/``Dec`` pulse/s^2 and S-factor ``SFac``; the axis parameters are not changed. ``Ve`` (the end
        speed of a move that never ends) is checked (0..1e9) and unused (AF13)."""
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
        """``APS_get_command_f(I32 Axis_ID, F64 *Command)`` -> ``(rtn, command position)``, pulse, F64 (L2066)."""
        i = self._axis(Axis_ID)
        return (self._bad(), 0.0) if i is None else (ERR_NoError, float(self._card.profile_pos(i)))

    def APS_set_command(self, Axis_ID, Command) -> int:
        """``APS_set_command(I32 Axis_ID, I32 Command)`` (L2084): sets the command position, at rest only; the
        feedback position moves with it so the following error is kept (closed loop, AF14)."""
        i = self._axis(Axis_ID)
        p = _num(Command)
        if i is None or p is None or p != int(p) or abs(p) > 2147483647:
            return self._bad()
        c = self._card
        self._release_modes(i)
        return self._do(c.set_actual_pos, i, float(c.actual_pos(i)) + (p - float(c.profile_pos(i))))

    def APS_get_encoder(self, Axis_ID):
        """``APS_get_encoder(I32 Axis_ID, I32 *Encoder)`` -> ``(rtn, encoder counter)`` (L2094): the feedback
        counter in motor pulses, 32-bit (= APS_get_position with unit factor 1, AF14)."""
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, _reg32(self._card.actual_pos(i)))

    def APS_get_command_counter(self, Axis_ID):
        """``APS_get_command_counter(I32 Axis_ID, I32 *Counter)`` -> ``(rtn, command counter)`` (L2095): the
        command output in motor pulses, 32-bit (= APS_get_command with unit factor 1, AF14)."""
        i = self._axis(Axis_ID)
        return (self._bad(), 0) if i is None else (ERR_NoError, _reg32(self._card.profile_pos(i)))

    # -- compare timer (L3363-3378; TIMR_* of APS_set_trigger_param): vendor/adlink/aps_scope.hpp's (AF15) ------
    def APS_get_timer_counter(self, Board_ID, TmrCh):
        """``APS_get_timer_counter(I32 Board_ID, I32 TmrCh, I32 *Cnt)`` -> ``(rtn, Cnt)`` (L3376): the compare
        timer (TmrCh 0, the card's one timer): while TIMR_EN, +-1 every TIMR_ITV servo ticks (TIMR_DIR 0 up,
        1 down), wrapping at 32 bits with TIMR_RING_EN, else held at the I32 limits."""
        if not self._board(Board_ID):
            return self._bad(), 0
        return (ERR_NoError, self._scope().timer_counter()) if _num(TmrCh) == 0 else (ERR_ParametersInvalid, 0)

    def APS_set_timer_counter(self, Board_ID, TmrCh, Cnt) -> int:
        """``APS_set_timer_counter(I32 Board_ID, I32 TmrCh, I32 Cnt)`` (L3378): sets the timer counter (I32)."""
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
        """``APS_wdt_set_action_event(board_id, timer_no, EventByBit)`` (L4037, L4071-4074): what the time-out
        does, bit 0 servo off (every axis), bit 1 digital outputs off, bit 2 PWM (VAO) outputs off."""
        return self._watchdog(lambda w, *a: w.set_action(*a), Board_ID, TimerNo, EventByBit)

    def APS_wdt_get_action_event(self, Board_ID, TimerNo):
        """``APS_wdt_get_action_event(board_id, timer_no, &EventByBit)`` -> ``(rtn, EventByBit)`` (L4051)."""
        return (ERR_DeviceNotInitial, 0) if self._card is None else self._watchdog(lambda w, *a: w.action(*a), Board_ID,
                                                                                      TimerNo)

    def APS_wdt_start(self, Board_ID, TimerNo, TimeOut) -> int:
        """``APS_wdt_start(board_id, timer_no, time_out)`` (L4041, L4053): starts the watchdog with a time-out of
        ``time_out`` x 100 ms of card time (10 -> 1 s, L4070); 0 disables it. If the program does not call
        APS_wdt_reset_counter within the time-out, the action event is carried out once (checked every 1 ms of
        card time, AF16) and the watchdog stops."""
        return self._watchdog(lambda w, *a: w.start(*a), Board_ID, TimerNo, TimeOut)

    def APS_wdt_get_timeout_period(self, Board_ID, TimerNo):
        """``APS_wdt_get_timeout_period(board_id, timer_no, &time_out)`` -> ``(rtn, time_out)`` x 100 ms (L4043)."""
        return (ERR_DeviceNotInitial, 0) if self._card is None else self._watchdog(lambda w, *a: w.period(*a), Board_ID,
                                                                                      TimerNo)

    def APS_wdt_reset_counter(self, Board_ID, TimerNo) -> int:
        """``APS_wdt_reset_counter(board_id, timer_no)`` (L4045, L4058): restarts the time-out from now (a
        watchdog that has fired or is off: ERR_FunctionNotAvailable)."""
        return self._watchdog(lambda w, *a: w.reset_counter(*a), Board_ID, TimerNo)

    # -- digital outputs, board parameters, VAO: adapters over vendor/adlink/aps_outputs.hpp (AV9) -----------------
    def APS_write_d_output(self, Board_ID, DO_Group, DO_Data) -> int:
        """``APS_write_d_output(Board_ID, DO_Group, DO_Data)`` (APS library): the digital outputs DO0..7 (group 0)
        as bits."""
        return self._outs().write_do(DO_Group, DO_Data) if self._board(Board_ID) else self._bad()

    def APS_read_d_output(self, Board_ID, DO_Group):
        """``APS_read_d_output(Board_ID, DO_Group, &DO_Data)`` -> ``(rtn, DO0..7 as bits)`` (APS library), with the
        point tables' instruction commands of the moves started so far carried out."""
        if not self._board(Board_ID):
            return self._bad(), 0
        _core.aps_point_tables(self._card.kernel).sync()
        return self._outs().read_do(DO_Group)

    def APS_set_board_param(self, Board_ID, BOD_Param_No, BOD_Param) -> int:
        """``APS_set_board_param(Board_ID, BOD_Param_No, BOD_Param)`` (L3520): PRB_PWMx_MAP_DO (110h-113h): -1 no
        mapping, else bits 0-7 the DO channel and bit 8 the logic (1: DO on enables PWMx, 0: DO on disables it,
        L3530); PRS_EMG_LOGIC (00h, L1623): only 0 (the simulated EMG input is the active state; inverting its
        wiring is not simulated, AF17)."""
        return self._outs().set_board_param(BOD_Param_No, BOD_Param) if self._board(Board_ID) else self._bad()

    def APS_get_board_param(self, Board_ID, BOD_Param_No):
        """``APS_get_board_param(Board_ID, BOD_Param_No, &BOD_Param)`` -> ``(rtn, BOD_Param)`` (APS library)."""
        return self._outs().board_param(BOD_Param_No) if self._board(Board_ID) else (self._bad(), 0)

    def APS_get_eep_curr_drv_ctrl_mode(self, Board_ID):
        """``APS_get_eep_curr_drv_ctrl_mode(Board_ID, &ModeInBit)`` -> ``(rtn, ModeInBit)`` (L1498): bit k = 1:
        axis k is driven by the analog (+-10 V) command, 0: by pulses (L1493-1498). The simulated axes are driven
        by the servo law's voltage: every bit 1 (AF18)."""
        if not self._board(Board_ID):
            return self._bad(), 0
        return ERR_NoError, (1 << len(self._card)) - 1

    def APS_set_vao_param(self, Board_ID, Param_No, Param_Val) -> int:
        """``APS_set_vao_param(Board_ID, Param_No, Param_Val)`` (L3461, L3504-3512) for table N = 0..7:
        VAO_TABLE_OUTPUT_TYPE + 2N (1 PWM duty, 2 frequency at fixed width, 3 frequency at fixed duty),
        VAO_TABLE_INPUT_TYPE + 2N (0 feedback speed: not simulated, ERR_FunctionNotAvailable, AF19; 1 command
        speed; set it to 1 as the manual's examples do, L3537-3539), VAO_TABLE_PWM_Config + N (mode 1: Hz
        3..50e6; 2: ns 20..335544320; 3: duty x 0.05 %, 1..2000),
        VAO_TABLE_SRC + N (axis bits)."""
        return self._outs().set_vao_param(Param_No, Param_Val) if self._board(Board_ID) else self._bad()

    def APS_set_vao_table(self, Board_ID, Table_No, MinVelocity, VelInterval, TotalPoints, MappingDataArray) -> int:
        """``APS_set_vao_table(Board_ID, Table_No, I32 MinVelocity, I32 VelInterval, I32 TotalPoints, I32
        *MappingDataArray)`` (L3540; arguments of the APS library, AF20): table 0..7 of 1..32 points, point k at
        the composite speed MinVelocity + k * VelInterval pulse/s with power MappingDataArray[k] (the output type's
        unit and range, L3489-3495)."""
        if not self._board(Board_ID):
            return self._bad()
        return self._outs().set_vao_table(Table_No, MinVelocity, VelInterval, TotalPoints, list(MappingDataArray))

    def APS_switch_vao_table(self, Board_ID, Table_No) -> int:
        """``APS_switch_vao_table(Board_ID, Table_No)`` (L3540): VAO controller 0 uses table 0..7 from now (the
        library call names no controller; controller 1 switches through APS_pt_ext_set_table_no, AF21)."""
        return self._outs().switch_vao_table(Table_No) if self._board(Board_ID) else self._bad()

    def APS_start_vao(self, Board_ID, Output_Ch, Enable) -> int:
        """``APS_start_vao(Board_ID, Output_Ch, Enable)`` (L3501): turns the PWM output of VAO controller
        ``Output_Ch`` (0..1 = PWM0..1, AF21) on (1) or off (0); its active table must be set
        (ERR_FunctionNotAvailable otherwise)."""
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
