"""The Googol GT series programming interface (GT manual, seed 000) on the virtual :class:`~servobench.Card`.

Current-axis style as in the manual: ``GT_Axis(n)`` (n = 1..4) selects the axis the argument-less commands act
on. Units are the manual's, per sample time ST (= the card's servo tick): pulse, pulse/ST, pulse/ST^2, pulse/ST^3;
gains in the GT law's integers; DAC counts (32767 = 10 V). Every command returns the manual's code (Table 2-1,
L393-408): 0 success, 1 command error (the card ignored it; the reason is in ``GT_GetCmdSts``, axis status bit 7
is set), 7 parameter error (out of range), -1 when no card is open. A read command ``GT_GetX(&x)`` returns the
tuple ``(rtn, x)``. Illegal sequences leave the card's state unchanged.

This module only translates: the behaviour (double buffering, status, safety) is the Card's.

Module-level functions act on the card opened last with :func:`GT_Open`; :class:`GtController` holds one card
for programs that drive several. Simulation helpers (not in the manual): :func:`run` (ticks), :func:`delay`
(ms, as the manual's ``delay()``), :func:`wait_until` and :func:`card`.
"""

from __future__ import annotations

import math
from typing import Any

from .. import _core
from .._core import CardCommandRefused, GtHome, MotionCommandRefused, PathGeometryError, PathSegment
from ..card import Card
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401
from ._gt_system import UNSUPPORTED, _GtSystem

# Return codes (Table 2-1, L393-408).
RTN_SUCCESS = 0
RTN_COMMAND_ERROR = 1
RTN_PARAMETER_ERROR = 7
RTN_SYN_PARAM_ERROR = 4  # GT_SetSynVel/SetSynAcc: vector velocity/acceleration zero, negative or too large (L401)
RTN_COMM_ERROR = -1

_POS_MIN, _POS_MAX = -1073741824, 1073741823  # L854


def _int_in(value, lo, hi) -> bool:
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


def _real_in(value, lo, hi, hi_open=False) -> bool:
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and lo <= v and (v < hi if hi_open else v <= hi)


class GtController(_GtSystem, DialectController):
    """A GT program's view of the GT cards of one PC (:class:`~servobench.Card` objects; one current card, chosen
    with GT_SwitchtoCardNo): the current axis and the GT_* commands."""

    def __init__(self):
        super().__init__()
        self._axis = 0          # current axis, 0-based (default axis 1, L754)
        self._lmt_sns = 0       # GT_LmtSns bits (L4217-4231)
        self._index = [0] * 4   # GT_Index per axis (L4190-4196)
        self._slots: list[dict] = []  # the open cards' dialect state, by card number (GT_SwitchtoCardNo)
        self._card_no = 0

    # -- plumbing -------------------------------------------------------------------------------------------
    def _do(self, fn, *args) -> int:
        return self._googol_do(fn, *args)

    def _param_error(self, fault: str) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        self._card.record_fault(self._axis, fault)
        return RTN_PARAMETER_ERROR

    def _get(self, fn):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        return RTN_SUCCESS, fn()

    def _law(self):
        law = self._card.staged(self._axis)["law"]
        return law if isinstance(law, _core.GtServoLaw) else None

    def _set_gain(self, field: str, value, lo=0, hi=32767) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(value, lo, hi):
            return self._param_error("illegal_control_param")
        law = self._law()
        if law is None:  # an axis with the ADLINK law has no GT filter registers
            self._card.record_fault(self._axis, "illegal_control_param")
            return RTN_COMMAND_ERROR
        return self._do(self._card.stage_law, self._axis, law.replace(**{field: float(value)}))

    def _get_gain(self, field: str):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        law = self._law()
        return (RTN_SUCCESS, int(getattr(law, field))) if law is not None else (RTN_COMMAND_ERROR, 0)

    # -- simulation helpers -----------------------------------------------------------------------------------
    def delay(self, ms: float):
        """The manual's ``delay(ms)``: runs the card for ``ms`` milliseconds (rounded to whole ticks)."""
        return self.run_ms(ms)

    # -- 8.1 system -------------------------------------------------------------------------------------------
    def GT_Open(self, card: Card | int | None = None, irq: int = 0, **axis_parts) -> int:
        """Opens the card(s) (PCI form, L4381-4391): ``card``, else the machine :meth:`use_machine` set (one Card
        or the PC's several GT cards, card 0 current, L5134-5140), else a new 4-axis :class:`~servobench.Card`
        built from ``axis_parts``. The GT has 4 axes (L752-756). The ISA Windows form ``GT_Open(PortBase, irq)``
        (Example 3-2, L519-523, L549-553) opens the machine's card whose base-address jumper is ``PortBase``
        (``card_io.of(card).base_address``): 0, or -1 when no card answers there; irq 0 (none) or 10..15."""
        if card is not None and not isinstance(card, Card):
            if not _int_in(card, 0, 0xFFFF) or not (_int_in(irq, 10, 15) or irq == 0):
                return RTN_PARAMETER_ERROR
            return RTN_SUCCESS if self.GT_SetAddr(int(card)) == RTN_SUCCESS else RTN_COMM_ERROR
        cards = [card] if card is not None else (self._machine_cards() if not axis_parts else [])
        self._open_cards(cards or [Card(4, **axis_parts)])
        return RTN_SUCCESS

    def GT_Close(self) -> int:
        """Closes the card(s) (L3051-3061)."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._slots = []
        self._card = None
        return RTN_SUCCESS

    def GT_Reset(self) -> int:
        """Command reset, the HardRst defaults (L4124-4142): registers 0, T-curve, gains 0, limits 32767,
        auto-update/auto-stop off, closed loop, limits on, drives off, events cleared."""
        self._lmt_sns = 0
        self._index = [0] * 4
        st = self._sys_state()
        st.update(enc_sns=0, step_pulse=[False] * 4, adc_chn=8)  # pulse + direction, 8 A/D channels (GF7)
        # the coordinate system back to the HardRst state: SynVel/SynAcc 0 (item 1, L4126), CrdAuStp allowed
        # (item 15, L4140), immediate mode (item 16, L4141); the card's reset drops the mapping (item 17, L4142)
        self.__dict__.pop("_crd_state", None)
        if self._card is not None:
            self._intr_reset()  # all interrupts masked after reset (L2223, L4765-4779; issue 10.3)
        return self._do(lambda: self._card.reset())

    def GT_HardRst(self) -> None:
        """Hardware reset (returns nothing, L4122)."""
        self.GT_Reset()

    def GT_GetSmplTm(self):
        """(rtn, sample time in us) (L4066-4078)."""
        return self._get(lambda: self._card.servo_period_s * 1e6)

    def GT_GetCmdSts(self):
        """(rtn, command status register) (Table 2-2, L455-478)."""
        def word():
            st = getattr(self, "_crd_state", None)
            if st is not None and self._card.last_fault == "crd_state_error":
                return 1 << st["cmd_bit"]  # 12, 13 or 15: which coordinated command failed (V127)
            return _core.gt_command_status(self._card.kernel)

        return self._get(word)

    # -- 8.2 axis selection, enable, output ---------------------------------------------------------------
    def GT_Axis(self, num: int) -> int:
        """Selects the current axis, 1..4 (L2825-2846)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(num, 1, 4):
            return self._param_error("illegal_control_param")
        self._axis = int(num) - 1
        return RTN_SUCCESS

    def GT_AxisOn(self) -> int:
        """Enables the drive; sets motion complete; refused while the drive-alarm bit is set (L2910-2933)."""
        return self._do(lambda: self._card.axis_on(self._axis))

    def GT_AxisOff(self) -> int:
        """Disables the drive (L2884-2908)."""
        return self._do(lambda: self._card.axis_off(self._axis))

    def GT_DrvRst(self) -> int:
        """Pulses the drive reset; only with the drive disabled (L3212-3239)."""
        return self._do(lambda: self._card.drive_reset(self._axis))

    def GT_CtrlMode(self, mode) -> int:
        """Output type: 0 analog (default), 1 pulse (L3189-3210). The simulated output is fixed by the axis's drive
        (a StepperDrive or ServoPositionDrive takes pulses): a mode that does not match it returns 1."""
        if self._card is None:
            return RTN_COMM_ERROR
        if mode not in (0, 1):
            return self._param_error("illegal_control_param")
        pulse = type(self._card.axes[self._axis].drive).__name__ in ("StepperDrive", "ServoPositionDrive")
        if bool(mode) != pulse:
            self._card.record_fault(self._axis, "illegal_control_param")
            return RTN_COMMAND_ERROR
        return RTN_SUCCESS

    def GT_CloseLp(self) -> int:
        """Closed loop (L3063-3087)."""
        return self._do(lambda: self._card.set_closed_loop(self._axis, True))

    def GT_OpenLp(self) -> int:
        """Open loop: the output is GT_SetMtrCmd (L4355-4365)."""
        return self._do(lambda: self._card.set_closed_loop(self._axis, False))

    def GT_SetMtrCmd(self, mcmd) -> int:
        """Open-loop output, DAC counts -32767..32767 (L4958-4970)."""
        if self._card is not None and not _int_in(mcmd, -32767, 32767):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.set_mtr_cmd(self._axis, float(mcmd)))

    def GT_GetMtrCmd(self):
        """(rtn, open-loop output counts) (L3996-4008)."""
        return self._get(lambda: int(self._card.mtr_cmd(self._axis)))

    def GT_LmtSns(self, sense) -> int:
        """Limit polarity for all axes: bit 2(k-1) axis k positive, 2(k-1)+1 negative; 0 = triggers on a high
        level (default), 1 = on a low level (L4215-4248)."""
        if self._card is not None and not _int_in(sense, 0, 0xFFFF):
            return self._param_error("illegal_control_param")

        def apply():
            for k in range(4):
                lim = self._card.limits(k).replace(pos_active_low=bool(int(sense) >> (2 * k) & 1),
                                                   neg_active_low=bool(int(sense) >> (2 * k + 1) & 1))
                self._card.set_limits(k, lim)
            self._lmt_sns = int(sense)

        return self._do(apply)

    def GT_LmtsOn(self) -> int:
        """Limit monitoring on for the current axis (default) (L4262-4272)."""
        return self._do(lambda: self._card.set_limits(self._axis, self._card.limits(self._axis).replace(enabled=True)))

    def GT_LmtsOff(self) -> int:
        """Limit monitoring off for the current axis (L4250-4260)."""
        return self._do(lambda: self._card.set_limits(self._axis, self._card.limits(self._axis).replace(enabled=False)))

    def GT_GetLmtSwt(self):
        """(rtn, limit input levels): bit 2(k-1) axis k positive, 2(k-1)+1 negative; 1 = the switch is hit
        (the input is high with the default normally-closed wiring), whatever LmtSns says (L3915-3938)."""
        def levels():
            w = 0
            for k in range(4):
                lim = self._card.limits(k)
                w |= int(self._card.pos_limit_input(k) != lim.pos_active_low) << (2 * k)
                w |= int(self._card.neg_limit_input(k) != lim.neg_active_low) << (2 * k + 1)
            return w

        return self._get(levels)

    # -- 8.3 servo filter (double-buffered) -----------------------------------------------------------------
    def GT_SetKp(self, kp) -> int:
        """Proportional gain 0..32767 (staged) (L4902-4914)."""
        return self._set_gain("kp", kp)

    def GT_SetKi(self, ki) -> int:
        """Integral gain 0..32767, the term is Ki*SumE/256 (staged) (L4888-4900)."""
        return self._set_gain("ki", ki)

    def GT_SetKd(self, kd) -> int:
        """Derivative gain 0..32767 (staged) (L4874-4886)."""
        return self._set_gain("kd", kd)

    def GT_SetKvff(self, kvff) -> int:
        """Velocity feed-forward 0..32767 on V_target pulse/ST (staged) (L4916-4928)."""
        return self._set_gain("kvff", kvff)

    def GT_SetKaff(self, kaff) -> int:
        """Acceleration feed-forward 0..32767 on A_target pulse/ST^2 (staged) (L4860-4872)."""
        return self._set_gain("kaff", kaff)

    def GT_SetILmt(self, ilmt) -> int:
        """Integral limit 0..32767 on the error sum (staged; 0 clears it) (L4749-4761)."""
        return self._set_gain("ilmt", ilmt)

    def GT_SetMtrLmt(self, mlmt) -> int:
        """Output limit 0..32767 counts (staged) (L4972-4984)."""
        return self._set_gain("mtr_lmt", mlmt)

    def GT_SetMtrBias(self, bias) -> int:
        """Output bias -32768..32767 counts (staged) (L4944-4956)."""
        return self._set_gain("bias", bias, -32768, 32767)

    def GT_GetKp(self):
        """(rtn, staged Kp)."""
        return self._get_gain("kp")

    def GT_GetKi(self):
        """(rtn, staged Ki)."""
        return self._get_gain("ki")

    def GT_GetKd(self):
        """(rtn, staged Kd)."""
        return self._get_gain("kd")

    def GT_GetKvff(self):
        """(rtn, staged Kvff)."""
        return self._get_gain("kvff")

    def GT_GetKaff(self):
        """(rtn, staged Kaff)."""
        return self._get_gain("kaff")

    def GT_GetILmt(self):
        """(rtn, staged integral limit)."""
        return self._get_gain("ilmt")

    def GT_GetMtrLmt(self):
        """(rtn, staged output limit, counts)."""
        return self._get_gain("mtr_lmt")

    def GT_GetMtrBias(self):
        """(rtn, staged bias, counts)."""
        return self._get_gain("bias")

    def GT_SetPosErr(self, perr) -> int:
        """Following-error limit 0..32767 pulse (staged) (L5000-5012)."""
        if self._card is not None and not _int_in(perr, 0, 32767):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.stage_pos_err(self._axis, float(perr)))

    def GT_GetPosErr(self):
        """(rtn, staged following-error limit, pulse)."""
        return self._get(lambda: int(self._card.staged(self._axis)["pos_err"]))

    def GT_GetIntgr(self):
        """(rtn, integral accumulator, pulse*ST, as a short) (L3775-3785)."""
        return self._get(lambda: int(self._card.integral(self._axis)))

    def GT_GetAtlErr(self):
        """(rtn, planned - actual position of the last tick, pulse, as a short) (L3554-3576)."""
        return self._get(lambda: int(max(-32768, min(32767, round(self._card.following_error(self._axis))))))

    def GT_AuStpOn(self) -> int:
        """Auto-stop on following error: stop, motion complete, drive off (mode bit 7) (L2752-2773)."""
        return self._do(lambda: self._card.set_auto_stop(self._axis, True))

    def GT_AuStpOff(self) -> int:
        """Following error only flags bit 4 (default) (L2729-2750)."""
        return self._do(lambda: self._card.set_auto_stop(self._axis, False))

    # -- 8.4 profile / motion ---------------------------------------------------------------------------------
    def GT_PrflT(self) -> int:
        """T-curve mode (L4467-4492); refused while moving (command status bit 6)."""
        return self._do(lambda: self._card.set_mode(self._axis, "t_curve"))

    def GT_PrflS(self) -> int:
        """S-curve mode (L4439-4465)."""
        return self._do(lambda: self._card.set_mode(self._axis, "s_curve"))

    def GT_PrflV(self) -> int:
        """Velocity (jog) mode (L4494-4518)."""
        return self._do(lambda: self._card.set_mode(self._axis, "jog"))

    # -- [modes] electronic gear (GT L1029-1090, L4407-4437) --------------------------------------------------
    def GT_PrflG(self, master) -> int:
        """Electronic gear mode: the current axis follows the profile position of axis ``master`` (1..4) with the
        staged ratio (GT_SetRatio + Update); bit 10 stays set (L1090). Masters 5, 6 (auxiliary encoders) are not
        simulated: 1 (command error). Refused while the axis moves in another mode (bit 6) (L4407-4437)."""
        if self._card is not None and not _int_in(master, 1, 6):
            return self._param_error("illegal_control_param")
        if self._card is not None and int(master) > 4:
            self._card.record_fault(self._axis, "invalid_in_mode")
            return RTN_COMMAND_ERROR
        return self._do(lambda: self._card.set_gear(self._axis, int(master) - 1))

    def GT_SetPos(self, pos) -> int:
        """Target position, whole pulses -2^30..2^30-1 (staged) (L4986-4998)."""
        if self._card is not None and not _int_in(pos, _POS_MIN, _POS_MAX):
            return self._param_error("motion_param_overflow")
        return self._do(lambda: self._card.stage_pos(self._axis, float(pos)))

    def GT_GetPos(self):
        """(rtn, staged target, pulse) (L4024-4036)."""
        return self._get(lambda: register32(self._card.staged(self._axis)["pos"]))

    def GT_SetVel(self, vel) -> int:
        """Velocity, pulse/ST: 0..16384 in T/S mode, -16384..16384 in jog mode (staged) (L5076-5090)."""
        if self._card is not None:
            lo = -16384 if self._card.mode(self._axis) == "jog" else 0
            if not _real_in(vel, lo, 16384):
                return self._param_error("motion_param_overflow")
        return self._do(lambda: self._card.stage_vel(self._axis, float(vel)))

    def GT_GetVel(self):
        """(rtn, staged velocity, pulse/ST)."""
        return self._get(lambda: self._card.staged(self._axis)["vel"])

    def GT_SetAcc(self, acc) -> int:
        """Acceleration, pulse/ST^2, 0..16384, T-curve and jog (staged) (L4571-4583)."""
        if self._card is not None and not _real_in(acc, 0, 16384):
            return self._param_error("motion_param_overflow")
        return self._do(lambda: self._card.stage_acc(self._axis, float(acc)))

    def GT_GetAcc(self):
        """(rtn, staged acceleration, pulse/ST^2)."""
        return self._get(lambda: self._card.staged(self._axis)["acc"])

    def GT_SetMAcc(self, macc) -> int:
        """S-curve maximum acceleration, pulse/ST^2, 0 <= MAcc < 0.5 (staged) (L4930-4942)."""
        if self._card is not None and not _real_in(macc, 0, 0.5, hi_open=True):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.stage_macc(self._axis, float(macc)))

    def GT_GetMAcc(self):
        """(rtn, staged MAcc, pulse/ST^2)."""
        return self._get(lambda: self._card.staged(self._axis)["macc"])

    def GT_SetJerk(self, jerk) -> int:
        """S-curve jerk, pulse/ST^3, 0 <= J < 0.5 (staged) (L4846-4858)."""
        if self._card is not None and not _real_in(jerk, 0, 0.5, hi_open=True):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.stage_jerk(self._axis, float(jerk)))

    def GT_GetJerk(self):
        """(rtn, staged jerk, pulse/ST^3)."""
        return self._get(lambda: self._card.staged(self._axis)["jerk"])

    def GT_SetRatio(self, ratio) -> int:
        """Gear ratio -16384..16384 (staged) (L5014-5026)."""
        if self._card is not None and not _real_in(ratio, -16384, 16384):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.stage_ratio(self._axis, float(ratio)))

    def GT_GetRatio(self):
        """(rtn, staged gear ratio)."""
        return self._get(lambda: self._card.staged(self._axis)["ratio"])

    def GT_SmthStp(self) -> int:
        """Smooth stop at the commanded deceleration (staged: needs Update) (L5092-5102)."""
        return self._do(lambda: self._card.stage_smooth_stop(self._axis))

    def GT_AbptStp(self) -> int:
        """Abrupt stop: profile velocity 0 at once, motion complete (immediate) (L2702-2727)."""
        return self._do(lambda: self._card.abrupt_stop(self._axis))

    def GT_Update(self) -> int:
        """Commits the current axis's staged registers at the next sample (L5184-5194)."""
        return self._do(lambda: self._card.update(1 << self._axis))

    def GT_MltiUpdt(self, mask) -> int:
        """Commits the masked axes (bit k-1 = axis k) in the same sample; mask 0 is an error (cmd bit 2)
        (L4274-4310)."""
        if self._card is not None and not _int_in(mask, 0, 0xFFFF):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.update(int(mask) & 0xF))

    def GT_ZeroPos(self) -> int:
        """Actual = target = profile = 0; at rest only (cmd bit 11) (L5196-5206)."""
        return self._do(lambda: self._card.zero_pos(self._axis))

    def GT_SynchPos(self) -> int:
        """Target = profile = actual (staged: needs Update); an error in jog mode (L5152-5162)."""
        return self._do(lambda: self._card.stage_synch_pos(self._axis))

    def GT_SetAtlPos(self, pos) -> int:
        """Actual = target = profile = pos, whole pulses; at rest only (L4613-4639)."""
        if self._card is not None and not _int_in(pos, _POS_MIN, _POS_MAX):
            return self._param_error("motion_param_overflow")
        return self._do(lambda: self._card.set_actual_pos(self._axis, float(pos)))

    def GT_GetAtlPos(self):
        """(rtn, actual position, pulse) (L3578-3606)."""
        return self._get(lambda: register32(self._card.actual_pos(self._axis)))

    # -- 8.5 breakpoints ----------------------------------------------------------------------------------------
    def GT_SetBrkCn(self, brk) -> int:
        """Breakpoint compare value, whole pulses +-2^30 (staged) (L4717-4731)."""
        if self._card is not None and not _int_in(brk, _POS_MIN, _POS_MAX):
            return self._param_error("motion_param_overflow")
        return self._do(lambda: self._card.stage_brk_cn(self._axis, float(brk)))

    def GT_GetBrkCn(self):
        """(rtn, staged breakpoint value, pulse) (L3624-3638)."""
        return self._get(lambda: int(self._card.staged(self._axis)["brk_cn"]))

    def GT_PosBrk(self) -> int:
        """Arms: actual >= BrkCn (L4393-4405)."""
        return self._do(lambda: self._card.arm_breakpoint(self._axis, "pos"))

    def GT_NegBrk(self) -> int:
        """Arms: actual <= BrkCn (L4341-4353)."""
        return self._do(lambda: self._card.arm_breakpoint(self._axis, "neg"))

    def GT_MtnBrk(self) -> int:
        """Arms: on motion complete (L4312-4339)."""
        return self._do(lambda: self._card.arm_breakpoint(self._axis, "motion"))

    def GT_ExtBrk(self) -> int:
        """Arms: on the home capture (L3443-3470)."""
        return self._do(lambda: self._card.arm_breakpoint(self._axis, "home"))

    def GT_BrkOff(self) -> int:
        """Disarms an untriggered breakpoint (L2935-2956)."""
        return self._do(lambda: self._card.arm_breakpoint(self._axis, "none"))

    def GT_AuUpdtOn(self) -> int:
        """Auto-update at a breakpoint on (mode bit 10) (L2802-2823)."""
        return self._do(lambda: self._card.set_auto_update(self._axis, True))

    def GT_AuUpdtOff(self) -> int:
        """Auto-update off (default) (L2775-2800)."""
        return self._do(lambda: self._card.set_auto_update(self._axis, False))

    # -- 8.6 status and mode ----------------------------------------------------------------------------------
    def GT_GetSts(self):
        """(rtn, axis status register) (Table 4-14, L4080-4104)."""
        return self._get(lambda: _core.gt_axis_status(self._card.kernel, self._axis))

    def GT_ClrSts(self) -> int:
        """Clears status bits 0-7 (bit 4 only once out of error) (L3138-3161)."""
        return self._do(lambda: self._card.clear_events(self._axis, _core.gt_events_to_clear(0)))

    def GT_RstSts(self, mask) -> int:
        """Clears the status bits 0-7 whose mask bit is 0 (L4557-4569)."""
        if self._card is not None and not _int_in(mask, 0, 0xFFFF):
            return self._param_error("illegal_control_param")
        return self._do(lambda: self._card.clear_events(self._axis, _core.gt_events_to_clear(int(mask))))

    def GT_GetMode(self):
        """(rtn, axis mode register) (Table 4-15, L3954-3978)."""
        return self._get(lambda: _core.gt_mode_register(self._card.kernel, self._axis))

    # -- 8.7 capture / homing ---------------------------------------------------------------------------------
    def GT_CaptHome(self) -> int:
        """Arms a one-shot home capture (status bit 14) (L2958-2982)."""
        return self._do(lambda: self._card.arm_capture(self._axis, "home"))

    def GT_CaptIndex(self) -> int:
        """Arms a one-shot index capture (status bit 15) (L2984-3006)."""
        return self._do(lambda: self._card.arm_capture(self._axis, "index"))

    def GT_GetCapt(self):
        """(rtn, captured position, pulse) (L3640-3674)."""
        return self._get(lambda: int(round(self._card.capture_value(self._axis))))

    def GT_Index(self, value=1) -> int:
        """0 home only (default), 1 home + index for GT_Home (L4188-4213)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if value not in (0, 1):
            return self._param_error("illegal_control_param")
        self._index[self._axis] = int(value)
        return RTN_SUCCESS

    def GT_Home(self, pos) -> int:
        """Automatic homing toward ``pos`` (pulse, beyond the home switch) at the staged T-curve Vel and Acc
        (decision V24) (L4152-4168)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(pos, _POS_MIN, _POS_MAX):
            return self._param_error("motion_param_overflow")
        reg = self._card.staged(self._axis)
        if not (reg["vel"] > 0 and reg["acc"] > 0):
            self._card.record_fault(self._axis, "illegal_control_param")
            return RTN_COMMAND_ERROR
        p = GtHome(pos=float(pos), vel=reg["vel"], acc=reg["acc"], index=bool(self._index[self._axis]), zero=False)
        return self._do(lambda: self._card.home(self._axis, p))


    # -- [modes] coordinated motion (GT L1513-2011; gt.md §4, §8.11) -----------------------------------------
    # The coordinate system is the card's GT_MapAxis system (Card.gt_map_axis / gt_path, units per sample time);
    # this block keeps the GT's list bookkeeping (immediate / buffer mode, list open, Mv done, SynVel/SynAcc).
    def _crd(self):
        if not hasattr(self, "_crd_state"):
            self._crd_state = dict(vel=0.0, acc=0.0, buffer=False, open=False, mv=False, started=False,
                                   error=False, au_stp=True, cmd_bit=12, pushed=0, mv_pushed=0, acc_lmt=[0.0] * 4)
        return self._crd_state

    def _crd_refuse(self, bit: int = 12, rtn: int = RTN_COMMAND_ERROR) -> int:
        """A refused coordinated command: the card records a crd-state fault and GT_GetCmdSts shows `bit` (12 a
        command in the wrong state, 13 an Mv* error, 15 buffer full; Table 2-2 L455-478) while it is the last."""
        st = self._crd()
        st.update(error=True, cmd_bit=bit)
        self._card.record_fault(self._axis, "crd_state_error")
        return rtn

    def _crd_do(self, fn, *, mv: bool = False) -> int:
        rtn = self._do(fn)
        st = self._crd()
        st["error"] = rtn != RTN_SUCCESS
        if rtn == RTN_COMMAND_ERROR:
            try:
                path = self._card.gt_path()
            except (CardCommandRefused, MotionCommandRefused):
                path = None
            if path is not None and path.fifo_space <= 0:
                return self._crd_refuse(15)  # buffer full: not accepted, send it again (L477-478)
            if mv:
                return self._crd_refuse(13)
            if self._card.last_fault in ("change_in_motion", "invalid_in_mode"):
                return self._crd_refuse(12)  # a path command refused: bit 12 (L1800)
        return rtn

    def GT_MapAxis(self, axis_num, map_count) -> int:
        """Maps motor axis 1..4: Axis = Cx x + Cy y + Cz z + Ca a + C, map_count = [Cx, Cy, Cz, Ca, C] (L1533-1538);
        the axis enters coordinated mode. Only at rest (1); a map that determines no coordinate returns 6
        (L1528, L1660)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(axis_num, 1, 4) or len(map_count) != 5 or not all(_real_in(c, -1e12, 1e12) for c in map_count):
            return self._param_error("illegal_control_param")
        try:
            self._card.gt_map_axis(int(axis_num), [float(c) for c in map_count])
            self._apply_acc_lmt()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_refuse()
        except PathGeometryError as e:
            return int(_core.gt_geometry_code(e.gt_code))  # a map that determines no coordinate: 6 (L408)
        except ValueError:
            return RTN_PARAMETER_ERROR
        return RTN_SUCCESS

    def GT_SetSynVel(self, vel) -> int:
        """Vector velocity, coordinate units/ST, modal for the later path commands (L1725)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _real_in(vel, 0, 16384) or float(vel) == 0:
            return RTN_SYN_PARAM_ERROR  # zero, negative or beyond bounds: return 4 (Table 2-1 L401)
        self._crd()["vel"] = float(vel)
        return RTN_SUCCESS

    def GT_SetSynAcc(self, acc) -> int:
        """Vector acceleration, coordinate units/ST^2, modal (L1729)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _real_in(acc, 0, 16384) or float(acc) == 0:
            return RTN_SYN_PARAM_ERROR  # zero, negative or beyond bounds: return 4 (Table 2-1 L401)
        self._crd()["acc"] = float(acc)
        return RTN_SUCCESS

    def _path_cmd(self, make_segment) -> int:
        """A line or arc: immediate mode runs it at once (1 while a path moves, L1800); buffer mode appends it."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._crd()
        try:
            path = self._card.gt_path()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_refuse()
        if st["buffer"] and st["open"] and not st["mv"]:
            return self._crd_refuse()  # Mv* must follow StrtList (L1843)
        if not (st["vel"] > 0 and st["acc"] > 0):
            return self._param_error("motion_param_overflow")
        try:
            seg = make_segment(list(path.tail))
        except ValueError as e:
            st["error"] = True
            return int(_core.gt_geometry_code(e.gt_code)) if isinstance(e, PathGeometryError) else RTN_PARAMETER_ERROR
        if st["buffer"] and st["open"]:
            rtn = self._crd_do(lambda: path.push_segment(seg, st["vel"], st["acc"], auto_end=True))
            st["pushed"] += rtn == RTN_SUCCESS
            return rtn
        if st["buffer"] and path.breakpoint is not None:
            # stopped buffer: a path command runs at once as a single line, the buffer waits (L1938, V64)
            if seg.kind != "line" or path.busy:
                return self._crd_refuse()
            return self._crd_do(lambda: (self._card.group_start(2),
                                         path.move_immediate(list(seg.end), st["vel"], st["acc"])))
        if path.busy or path.running or path.fifo_size or path.window_size:
            return self._crd_refuse()  # a second path command before the first finishes (L1800)

        def run_now():
            path.clear()
            path.push_segment(seg, st["vel"], st["acc"], stop_at_end=True)
            self._card.group_start(2)
            path.start()

        rtn = self._crd_do(run_now)
        if rtn == RTN_SUCCESS:
            st.update(buffer=False, started=False)  # immediate (single-segment) mode again (V64)
        return rtn

    def GT_LnXY(self, x, y) -> int:
        """Line to the absolute point (x, y), coordinate units (L1749, L1787)."""
        return self._path_cmd(lambda t: PathSegment.line(t, [float(x), float(y), t[2], t[3]]))

    def GT_LnXYZ(self, x, y, z) -> int:
        """3-D line (L1750)."""
        return self._path_cmd(lambda t: PathSegment.line(t, [float(x), float(y), float(z), t[3]]))

    def GT_LnXYZA(self, x, y, z, a) -> int:
        """4-D line (L1751)."""
        return self._path_cmd(lambda t: PathSegment.line(t, [float(x), float(y), float(z), float(a)]))

    def GT_ArcXY(self, x_center, y_center, angle) -> int:
        """Arc about the centre (absolute) by ``angle`` degrees, positive CCW seen from +Z (L1752, L1793, L1913);
        the radius is the distance of the present point (2: zero radius)."""
        return self._path_cmd(lambda t: PathSegment.arc_center_angle(t, "xy", (float(x_center), float(y_center)),
                                                                     float(angle)))

    def GT_ArcYZ(self, y_center, z_center, angle) -> int:
        """Arc in the YZ plane (L1754)."""
        return self._path_cmd(lambda t: PathSegment.arc_center_angle(t, "yz", (float(y_center), float(z_center)),
                                                                     float(angle)))

    def GT_ArcZX(self, z_center, x_center, angle) -> int:
        """Arc in the ZX plane (L1756)."""
        return self._path_cmd(lambda t: PathSegment.arc_center_angle(t, "zx", (float(z_center), float(x_center)),
                                                                     float(angle)))

    def _arcp(self, plane, e1, e2, r, direction) -> int:
        i, j = {"xy": (0, 1), "yz": (1, 2), "zx": (2, 0)}[plane]
        if self._card is not None and not (_real_in(e1, _POS_MIN, _POS_MAX) and _real_in(e2, _POS_MIN, _POS_MAX)
                                           and _real_in(r, -2.0**31, 2.0**31)):
            return RTN_PARAMETER_ERROR
        if direction not in (1, -1):
            return RTN_PARAMETER_ERROR if self._card is not None else RTN_COMM_ERROR

        def make(t):
            end = list(t)
            end[i], end[j] = float(e1), float(e2)
            return PathSegment.arc_radius(t, end, plane, float(r), int(direction) == 1)

        return self._path_cmd(make)

    def GT_ArcXYP(self, x_end, y_end, r, direction) -> int:
        """Arc in the XY plane to the end point (x_end, y_end) with radius ``r``: r > 0 the arc of at most 180 deg,
        r < 0 the longer one; direction +1 CCW, -1 CW (seen from +Z, L1793). The GT manual names it with "the end
        point and radius" (L1753) and its return code 5, end point or radius wrong (L406), but prints no prototype:
        the GE lineage's (GE L3477-3483) is taken (decision GF8). 2: radius 0; 5: chord longer than the diameter."""
        return self._arcp("xy", x_end, y_end, r, direction)

    def GT_ArcYZP(self, y_end, z_end, r, direction) -> int:
        """Arc in the YZ plane by end point and radius (L1755; as GT_ArcXYP, positive CCW seen from +X)."""
        return self._arcp("yz", y_end, z_end, r, direction)

    def GT_ArcZXP(self, z_end, x_end, r, direction) -> int:
        """Arc in the ZX plane by end point and radius (L1757; as GT_ArcXYP, positive CCW seen from +Y)."""
        return self._arcp("zx", z_end, x_end, r, direction)

    def GT_GetMtnNm(self):
        """(rtn, number of the buffer segment executing, or where the buffer stopped): the Mv* line is 0, the path
        segments since GT_StrtList count from 1; it holds when the buffer runs dry and after the last segment
        (L1971-1985, decision GF9). 0 in immediate mode."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        st = self._crd()
        if not st["buffer"] or not self._card.group_info(2)["set_up"]:
            return RTN_SUCCESS, 0
        path = self._card.gt_path()
        n = path.state.segments_done - st["mv_pushed"] + (1 if path.busy and path.state.speed > 0 else 0)
        n = max(0, min(n, st["pushed"]))
        return RTN_SUCCESS, (n - 1) % 32767 + 1 if n > 0 else 0

    def _apply_acc_lmt(self):
        if self._card.group_info(2)["set_up"]:
            path = self._card.gt_path()
            for k, lim in enumerate(self._crd()["acc_lmt"]):
                if getattr(path.setup, f"axis_acc_{k + 1}") != lim:
                    path.set_axis_acc(k + 1, lim)

    def GT_SetAccLmt(self, acc) -> int:
        """Acceleration limit of the current axis at the joints of a buffered path, pulse/ST^2, 0..16384 (0 = no
        limit, the default): the vector velocity at a joint is lowered until no mapped axis changes its velocity
        by more than its limit (L1956-1966, strategies one and two). "A command for each motor axis" (L1956); the
        manual prints no prototype: one argument on the current axis, like every single-axis command (GF10)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _real_in(acc, 0, 16384):
            return self._param_error("motion_param_overflow")
        self._crd()["acc_lmt"][self._axis] = float(acc)
        return self._do(self._apply_acc_lmt)

    def GT_StrtList(self) -> int:
        """Opens and clears the buffer (buffer mode); refused while the buffer executes (bit 12) (L1841)."""
        if self._card is None:
            return RTN_COMM_ERROR
        try:
            path = self._card.gt_path()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_refuse()
        if path.busy or path.running:
            return self._crd_refuse()
        rtn = self._crd_do(path.clear)
        if rtn == RTN_SUCCESS:
            self._crd().update(buffer=True, open=True, mv=False, started=False, pushed=0, mv_pushed=0)
        return rtn

    def _mv(self, point, vel, acc) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._crd()
        if not st["open"] or st["mv"]:
            return self._crd_refuse(13)  # Mv* must follow StrtList once (L1843): an Mv* error, bit 13 (L476)
        if not _real_in(vel, 0, 16384) or not _real_in(acc, 0, 16384) or float(vel) == 0 or float(acc) == 0:
            return self._crd_refuse(13, RTN_PARAMETER_ERROR)  # bad Mv* parameters: 7 with bit 13
        path = self._card.gt_path()
        t = list(path.tail)
        end = [float(p) for p in point] + t[len(point):]

        def push():
            if end != t:
                path.push_segment(PathSegment.line(t, end), float(vel), float(acc), stop_at_end=True)

        rtn = self._crd_do(push, mv=True)
        if rtn == RTN_SUCCESS:
            st.update(mv=True, vel=float(vel), acc=float(acc), mv_pushed=int(end != t))  # the Mv vel/acc become the defaults (L1845)
        return rtn

    def GT_MvXY(self, x, y, vel, acc) -> int:
        """Buffer start point (x, y) reached by a line at vel/acc that ends at rest; vel/acc become the defaults
        (L1843-1845)."""
        return self._mv((x, y), vel, acc)

    def GT_MvXYZ(self, x, y, z, vel, acc) -> int:
        """3-D start point (L3351)."""
        return self._mv((x, y, z), vel, acc)

    def GT_MvXYZA(self, x, y, z, a, vel, acc) -> int:
        """4-D start point (L1901)."""
        return self._mv((x, y, z, a), vel, acc)

    def GT_EndList(self) -> int:
        """Closes the buffer (only while open) (L1849)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not self._crd()["open"]:
            return self._crd_refuse()
        self._crd()["open"] = False
        return RTN_SUCCESS

    def GT_AddList(self) -> int:
        """Reopens a closed buffer; while open: bit 12 (L1853-1859)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._crd()
        if st["open"] or not st["buffer"]:
            return self._crd_refuse()
        st["open"] = True
        return RTN_SUCCESS

    def GT_StrtMtn(self) -> int:
        """Runs the buffer (needs StrtList + Mv*), or resumes it after a stop, first returning to the stop point
        (L1928, L1940); refused while it executes (bit 12)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._crd()
        if not st["buffer"] or not st["mv"]:
            return self._crd_refuse()
        path = self._card.gt_path()
        if path.busy or (path.running and not path.stopped):
            return self._crd_refuse()

        def start():
            self._card.group_start(2)
            path.start()

        rtn = self._crd_do(start)
        if rtn == RTN_SUCCESS:
            st["started"] = True
        return rtn

    def _stp(self, abrupt) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._crd()
        try:
            path = self._card.gt_path()
        except (CardCommandRefused, MotionCommandRefused):
            return self._crd_refuse()
        rtn = self._crd_do(lambda: path.stop(abrupt))
        if rtn == RTN_SUCCESS:
            st["open"] = False  # both stops close the buffer (L1936)
        return rtn

    def GT_StpMtn(self) -> int:
        """Smooth stop of the coordinated motion; closes the buffer (L1934-1936)."""
        return self._stp(False)

    def GT_EStpMtn(self) -> int:
        """Abrupt stop: vector velocity 0 at once; closes the buffer; the buffer resumes with StrtMtn
        (L3332-3359)."""
        return self._stp(True)

    def GT_CrdAuStpOn(self) -> int:
        """Coordinate status bit 6 on (default): an axis abnormality stops the whole coordinated motion (L2011)."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._crd()["au_stp"] = True
        return RTN_SUCCESS

    def GT_CrdAuStpOff(self) -> int:
        """Coordinate status bit 6 off. The card still stops the whole path on an axis fault (decision V64)."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._crd()["au_stp"] = False
        return RTN_SUCCESS

    def GT_GetBrkPnt(self):
        """(rtn, coordinate point where the buffer was stopped, or None) (L1971)."""
        return self._get(lambda: None if self._card.gt_path().breakpoint is None
                         else [float(v) for v in self._card.gt_path().breakpoint])

    def GT_GetCrdSts(self):
        """(rtn, coordinate status register) (Table 5-6, L1990-2011): 0 finished/none, 1 buffer input finished,
        3 last coordinated command in error, 4 segment completed, 6 auto-stop on, 7 immediate mode, 9 an axis
        fault stopped the motion, 13 buffer empty after the start."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        st = self._crd()
        info = self._card.group_info(2)
        if not info["set_up"]:
            return RTN_SUCCESS, _core.gt_crd_status(last_command_error=st["error"], auto_stop_on=st["au_stp"])
        path = self._card.gt_path()
        empty = path.fifo_size == 0 and path.window_size == 0 and not path.busy
        moving = path.busy or (st["buffer"] and st["started"] and st["open"] and not path.stopped)
        return RTN_SUCCESS, _core.gt_crd_status(
            moving=moving, buffer_closed=not st["open"], last_command_error=st["error"],
            segment_complete=not path.busy, auto_stop_on=st["au_stp"], immediate_mode=not st["buffer"],
            fault_stopped=info["fault_stopped"], buffer_empty=empty, buffer_started=st["started"])
# -- probe capture and interrupts (issue 10 point 3; gt.md §5, §7, §8.9; decisions V71-V85) ---------------------
# Interrupt mask bits (GT_SetIntrMsk / GT_RstIntr, L4534-4555, L4763-4785) in the status-register layout (the
# tables print bit 6 = positive limit, bit 5 = negative; the status register, Table 8-1 and GT_AxisI's sample
# (0x20 = positive limit) have bit 5 = positive: V84) -> the card events that set them.
_INTR_EVENTS = {0: ("motion_complete",), 1: ("drive_alarm",), 2: ("breakpoint",), 3: ("captured",),
                4: ("following_error",), 5: ("pos_limit", "soft_pos_limit"), 6: ("neg_limit", "soft_neg_limit")}
_INTR_DISABLED_AXIS = 0x12  # on a disabled axis only motion error (bit 4) and drive alarm (bit 1) interrupt (L2257)
_INTR_REFIRE_LIMIT = 16     # re-raises at one instant before the request is left pending (an interrupt storm)


class _GtInterrupts:
    """GT_CaptProb and the interrupt commands of :class:`GtController` (mixed in)."""

    def _intr(self) -> dict:
        st = self.__dict__.get("_intr_state")
        if st is None or st["card"] is not self._card:
            st = {"card": self._card, "mode": "event", "msk": [0] * 4, "tm": 0, "isr": None, "pending": False,
                  "axis": 0, "subs": [], "in_isr": False, "recheck": False, "storm": (-1, 0), "sync": None}
            self.__dict__["_intr_state"] = st
        return st

    def _intr_reset(self):
        st = self._intr()
        for sid in st["subs"]:
            self._card.remove_event(sid)
        isr, sync = st["isr"], st["sync"]   # the host's routine and event stay (they are the host's, not the card's)
        self.__dict__.pop("_intr_state", None)
        self._intr().update(isr=isr, sync=sync)

    def _intr_sync(self):
        st, c = self._intr(), self._card
        for sid in st["subs"]:
            c.remove_event(sid)
        st["subs"] = []
        if st["mode"] == "timer":
            if st["tm"] > 0:
                st["subs"].append(c.on_event(self._intr_timer, timer_ticks=st["tm"]))
            return
        for k in range(4):
            names = [e for b, ev in _INTR_EVENTS.items() if st["msk"][k] >> b & 1 for e in ev]
            if names:
                st["subs"].append(c.on_event(lambda _c, _f: self._intr_raise(), axis=k, events=names))

    def _intr_level(self):
        """The lowest axis whose enabled status bits 0-6 are set (L2229), or None."""
        st, c = self._intr(), self._card
        for k in range(4):
            bits = _core.gt_axis_status(c._card, k) & st["msk"][k] & 0x7F
            if not c.servo_on(k):
                bits &= _INTR_DISABLED_AXIS
            if bits:
                return k
        return None

    def _intr_raise(self):
        st = self._intr()
        if st["mode"] != "event" or st["pending"] or st["in_isr"]:
            return
        while True:
            k = self._intr_level()
            if k is None:
                return
            tick, count = st["storm"]
            count = count + 1 if tick == self._card.tick else 1
            st["storm"] = (self._card.tick, count)
            st["pending"], st["axis"] = True, k
            if st["sync"] is not None:
                st["sync"].set()            # the driver's ISR signals the program's event (L2338)
            if st["isr"] is None or count > _INTR_REFIRE_LIMIT:
                return
            st["in_isr"] = True
            try:
                st["isr"]()
            finally:
                st["in_isr"] = False
            if not (st["recheck"] and not st["pending"]):
                st["recheck"] = False
                return
            st["recheck"] = False

    def _intr_timer(self, _card, _fired):
        st = self._intr()
        st["pending"] = True
        if st["sync"] is not None:
            st["sync"].set()
        if st["isr"] is not None and not st["in_isr"]:
            st["in_isr"] = True
            try:
                st["isr"]()
            finally:
                st["in_isr"] = False

    def GT_CaptProb(self) -> int:
        """Arms the probe capture (EXI0) on every axis whose capture register is free (not armed for home/index,
        captured flag clear; V85): the probe latches each one's actual position and sets its status bit 3
        (L3008-3049). Returns 1 (command status bit 8) when no axis could be armed. The probe input is the card's:
        ``card.set_probe_time(t_s)`` or ``card.set_probe_position(axis, pulse)``."""
        if self._card is None:
            return RTN_COMM_ERROR
        c = self._card
        free = [k for k in range(4) if c.capture_armed(k) == "none" and not c.events(k) & 0x8]
        if not free:
            c.record_fault(self._axis, "home_capture_armed")
            return RTN_COMMAND_ERROR
        for k in free:
            c.arm_capture(k, "probe")
        return RTN_SUCCESS

    def GT_HookIsr(self, isr):
        """Hooks the host's interrupt service routine (a Python callable taking no argument; PCI DOS form,
        L4170-4186) and returns the previous one (None at first). The card calls it from :meth:`run` at the tick
        the interrupt is requested; inside it, GT_AxisI / GT_GetIntr / GT_RstIntr serve the request."""
        if isr is not None and not callable(isr):
            raise TypeError("GT_HookIsr: isr must be callable (or None)")
        st = self._intr()
        old, st["isr"] = st["isr"], isr
        return old

    def GT_SetIntSyncEvent(self, hIntEvent) -> int:
        """Windows form of interrupt service (L2334-2410): the driver's ISR sets the program's synchronisation event
        at each interrupt request, and a thread of the program waiting on it (``WaitForSingleObject``) runs.
        ``hIntEvent`` is an object with ``set()`` (a :class:`threading.Event`), or None to release it before
        closing (L2340). 7 for anything else."""
        if self._card is None:
            return RTN_COMM_ERROR
        if hIntEvent is not None and not callable(getattr(hIntEvent, "set", None)):
            return RTN_PARAMETER_ERROR
        self._intr()["sync"] = hIntEvent
        return RTN_SUCCESS

    def GT_UnhookIsr(self, old_isr) -> int:
        """Restores the ISR ``old_isr`` (L5164-5182)."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._intr()["isr"] = old_isr
        return RTN_SUCCESS

    def GT_ClearInt(self, CardNo=0) -> int:
        """Ends the interrupt service on card ``CardNo`` (0; L3089-3122): a timer request is served."""
        if self._card is None:
            return RTN_COMM_ERROR
        if CardNo != 0:
            return RTN_PARAMETER_ERROR
        st = self._intr()
        if st["mode"] == "timer":
            st["pending"] = False
        return RTN_SUCCESS

    def GT_EvntIntr(self) -> int:
        """Event interrupts (the default): axis status bits 0-6 enabled by GT_SetIntrMsk request an interrupt
        (L2219-2223, L3361-3373)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._intr()
        st["mode"], st["pending"] = "event", False
        self._intr_sync()
        return RTN_SUCCESS

    def GT_TmrIntr(self) -> int:
        """Timer interrupts every GT_SetIntrTm x ST (L5054-5074); event interrupts off."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._intr()
        st["mode"], st["pending"] = "timer", False
        self._intr_sync()
        return RTN_SUCCESS

    def GT_SetIntrTm(self, Timer) -> int:
        """Timer-interrupt period in servo periods, 0..32767 (10 x 200 us = 2 ms, L4787-4801); 0: no timer
        interrupt (V84)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(Timer, 0, 32767):
            return self._param_error("illegal_control_param")
        self._intr()["tm"] = int(Timer)
        self._intr_sync()
        return RTN_SUCCESS

    def GT_GetIntrTm(self):
        """(rtn, timer-interrupt period in servo periods) (L3815-3829)."""
        return self._get(lambda: self._intr()["tm"])

    def GT_SetIntrMsk(self, Mask) -> int:
        """Interrupt mask of the current axis: bit k = status bit k may interrupt, bits 0-6 (bits 7-15 unused);
        all masked after reset (L4763-4785). A status bit already set interrupts at once."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(Mask, 0, 0xFFFF):
            return self._param_error("illegal_control_param")
        self._intr()["msk"][self._axis] = int(Mask) & 0x7F
        self._intr_sync()
        self._intr_raise()
        return RTN_SUCCESS

    def GT_GetIntrMsk(self):
        """(rtn, interrupt mask of the current axis) (L3801-3813)."""
        return self._get(lambda: self._intr()["msk"][self._axis])

    def GT_GetIntr(self):
        """(rtn, status register of the interrupting axis; of the current axis when no interrupt is pending)
        (L3787-3799); a timer interrupt reads 0."""
        def status():
            st = self._intr()
            if st["mode"] == "timer":
                return 0
            k = st["axis"] if st["pending"] else self._axis
            return _core.gt_axis_status(self._card.kernel, k)

        return self._get(status)

    def GT_AxisI(self) -> int:
        """Makes the interrupting axis current (the lowest number first, L2229); only with an interrupt pending,
        else command status bit 4 (L2850-2882)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._intr()
        if not st["pending"] or st["mode"] != "event":
            self._card.record_fault(self._axis, "no_interrupt_pending")
            return RTN_COMMAND_ERROR
        self._axis = st["axis"]
        return RTN_SUCCESS

    def GT_RstIntr(self, Mask) -> int:
        """Clears the current axis's status bits 0-7 whose Mask bit is 0 (1 keeps) and ends the request; if an
        enabled condition persists (a limit still pressed) the card requests again at once (Table 8-1,
        L2235-2243; L4534-4555). Only with an interrupt pending, else command status bit 4."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(Mask, 0, 0xFFFF):
            return self._param_error("illegal_control_param")
        st = self._intr()
        if not st["pending"] or st["mode"] != "event":
            self._card.record_fault(self._axis, "no_interrupt_pending")
            return RTN_COMMAND_ERROR
        self._card.clear_events(self._axis, _core.gt_events_to_clear(int(Mask) & 0xFF))
        st["pending"] = False
        if st["in_isr"]:
            st["recheck"] = True
        else:
            self._intr_raise()
        return RTN_SUCCESS


for _name, _fn in list(vars(_GtInterrupts).items()):  # the block's functions are GtController methods
    if callable(_fn) and not _name.startswith("__"):
        setattr(GtController, _name, _fn)


_default = GtController()
GT_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "GT_")


def delay(ms: float):
    """The manual's ``delay(ms)``: runs the open card for ``ms`` milliseconds (rounded to whole ticks)."""
    return _default.delay(ms)


def __getattr__(name: str) -> Any:
    """PEP 562 hook: the module's GT_* functions are made at import by export_functions (they exist as globals, so
    this is never reached for them); it tells a type checker that ``from servobench.dialects.gt import GT_Axis``
    names a module attribute. Any other name: AttributeError."""
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["GtController", "GT_FUNCTIONS", "RTN_COMMAND_ERROR", "RTN_COMM_ERROR", "RTN_PARAMETER_ERROR",
           "RTN_SUCCESS", "UNSUPPORTED", "card", "controller", "delay", "run", "use_machine", "wait_until",
           *GT_FUNCTIONS]
