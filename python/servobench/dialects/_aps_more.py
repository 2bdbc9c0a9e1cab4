"""More ADLINK functions of :class:`~servobench.dialects.aps.ApsController` (mixed in; issue 25.3, decisions
AF13-AF24): the watchdog (L4025-4084), the VAO (velocity -> PWM power) tables
(L3436-3542), the board parameters and the drive control mode (L1498, L1623, L3520-3533), and the digital
outputs the point table and the watchdog write (APS_read_d_output / APS_write_d_output of the APS library).

(The ``*_multi`` stops, ``APS_vel_all``, the position and counter reads and the compare timer counter are rows
of the C++ runner, AY1.)
Units: pulse, pulse/s, pulse/s^2; the watchdog's time-out in 100 ms (L4070); VAO powers in the table's unit
(mode 1: duty in 0.05 %, modes 2-3: Hz; L3489-3495).
"""

from __future__ import annotations

from .. import _core
from ._aps_constants import ERR_DeviceNotInitial, ERR_NoError, ERR_ParametersInvalid
from ._aps_pt import _f


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
