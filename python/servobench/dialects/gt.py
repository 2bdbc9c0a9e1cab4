"""The Googol GT series programming interface (GT manual, seed 000) on the virtual :class:`~servobench.Card`.

Current-axis style as in the manual: ``GT_Axis(n)`` (n = 1..4) selects the axis the argument-less commands act
on. Units are the manual's, per sample time ST (= the card's servo tick): pulse, pulse/ST, pulse/ST^2, pulse/ST^3;
gains in the GT law's integers; DAC counts (32767 = 10 V). Every command returns the manual's code (Table 2-1,
L393-408): 0 success, 1 command error (the card ignored it; the reason is in ``GT_GetCmdSts``, axis status bit 7
is set), 7 parameter error (out of range), -1 when no card is open. A read command ``GT_GetX(&x)`` returns the
tuple ``(rtn, x)``. Illegal sequences leave the card's state unchanged.

This module only translates: a table of one-line adapters (name, parameters, the C++ call, the manual's line)
over the card kernel and its GT module (``_core.gt_card(card.kernel)``: the current axis, LmtSns, Index, the
coordinated-motion list, the interrupts; ``vendor/googol/gt_card.hpp``), which hold every register.

Module-level functions act on the card opened last with :func:`GT_Open`; :class:`GtController` holds one card
for programs that drive several. Simulation helpers (not in the manual): :func:`run` (ticks), :func:`delay`
(ms, as the manual's ``delay()``), :func:`wait_until` and :func:`card`.
"""

from __future__ import annotations

from typing import Any

from .. import _core
from .._core import GtHome, GtServoLaw  # noqa: F401  (GtHome: the GT_Home parameters, kept importable)
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401
from ._gt_system import UNSUPPORTED, _GtSystem, gt_adapter

# Return codes (Table 2-1, L393-408).
RTN_SUCCESS = 0
RTN_COMMAND_ERROR = 1
RTN_PARAMETER_ERROR = 7
RTN_SYN_PARAM_ERROR = 4  # GT_SetSynVel/SetSynAcc: vector velocity/acceleration zero, negative or too large (L401)
RTN_COMM_ERROR = -1

_POS = (-1073741824, 1073741823, "int", "motion_param_overflow")  # whole pulses -2^30..2^30-1 (L854)
_GAIN = (0, 32767, "int", "illegal_control_param")
_WORD = (0, 0xFFFF, "int", "illegal_control_param")


class GtController(_GtSystem, DialectController):
    """A GT program's view of the GT cards of one PC (:class:`~servobench.Card` objects; one current card, chosen
    with GT_SwitchtoCardNo): the GT_* commands over each card's GT module (current axis, registers)."""

    def delay(self, ms: float):
        """The manual's ``delay(ms)``: runs the card for ``ms`` milliseconds (rounded to whole ticks)."""
        return self.run_ms(ms)

    @property
    def _axis(self) -> int:
        """The current axis, 0-based (the GT module's register; read-only here: GT_Axis / GT_AxisI set it)."""
        return self._gt().axis

    # -- the adapters' bodies (one per row kind) ---------------------------------------------------------------
    def _on_axis(self, call, *args) -> int:
        """A card command on the current axis: -1 without a card, 1 refused, 7 rejected, else 0."""
        return self._googol_do(call, self._card, self._gt().axis, *args) if self._card is not None else RTN_COMM_ERROR

    def _checked(self, rng, call, value) -> int:
        """`call(card, axis, float(value))` once `value` is in the manual's range `rng` (lo, hi, kind, fault)."""
        if self._card is None:
            return RTN_COMM_ERROR
        rtn = self._gt().check(value, *(rng(self._card, self._gt().axis) if callable(rng) else rng))
        return rtn or self._on_axis(call, float(value))

    def _read(self, call):
        """(rtn, call(card, axis)): a read of the current axis."""
        return (RTN_COMM_ERROR, 0) if self._card is None else (RTN_SUCCESS, call(self._card, self._gt().axis))

    def _module(self, call, *args):
        """A command of the card's GT module: its code (or value), -1 without a card."""
        return RTN_COMM_ERROR if self._card is None else call(self._gt(), *args)

    def _gain(self, field: str, value, lo: int = 0, hi: int = 32767) -> int:
        """A GT law gain, staged: 7 out of lo..hi, 1 on an axis without the GT law (no filter registers)."""
        if self._card is None:
            return RTN_COMM_ERROR
        g, law = self._gt(), self._card.staged(self._gt().axis)["law"]
        rtn = g.check(value, lo, hi)
        if rtn or not isinstance(law, _core.GtServoLaw):
            return rtn or g.refuse("illegal_control_param")
        return self._on_axis(lambda c, i: c.stage_law(i, law.replace(**{field: float(value)})))

    def _gain_of(self, field: str):
        if self._card is None:
            return RTN_COMM_ERROR, 0
        law = self._card.staged(self._gt().axis)["law"]
        return (RTN_SUCCESS, int(getattr(law, field))) if isinstance(law, _core.GtServoLaw) else (RTN_COMMAND_ERROR, 0)


def _axis_cmd(name, call, doc):
    return gt_adapter(name, "", lambda self: self._on_axis(call), doc)


def _setter(name, param, rng, call, doc):
    return gt_adapter(name, param, lambda self, v: self._checked(rng, call, v), doc)


def _getter(name, call, doc):
    return gt_adapter(name, "", lambda self: self._read(call), doc, returns=None)


def _gt_cmd(name, params, call, doc, returns="int"):
    return gt_adapter(name, params, lambda self, *a: self._module(call, *a), doc, returns=returns)


def _gt_read(name, call, doc):
    return gt_adapter(name, "", lambda self: (RTN_COMM_ERROR, 0) if self._card is None
                      else (RTN_SUCCESS, call(self._gt())), doc, returns=None)


def _gains(field, set_name, param, get_name, doc, lo=0, hi=32767):
    return [gt_adapter(set_name, param, lambda self, v: self._gain(field, v, lo, hi), doc),
            gt_adapter(get_name, "", lambda self: self._gain_of(field), f"(rtn, staged {field}).", returns=None)]


def _vel_range(card, axis):  # GT_SetVel: 0..16384 in T/S mode, -16384..16384 in jog mode (L5076-5090)
    return (-16384 if card.mode(axis) == "jog" else 0), 16384, "real", "motion_param_overflow"


def _ctrl_mode(self, mode) -> int:
    if self._card is None:
        return RTN_COMM_ERROR
    if mode not in (0, 1):
        return self._gt().check(float("nan"), 0, 1)
    pulse = type(self._card.axes[self._gt().axis].drive).__name__ in ("StepperDrive", "ServoPositionDrive")
    return RTN_SUCCESS if bool(mode) == pulse else self._gt().refuse("illegal_control_param")


def _prfl_g(self, master) -> int:
    if self._card is None:
        return RTN_COMM_ERROR
    rtn = self._gt().check(master, 1, 6)
    if rtn or master > 4:  # masters 5, 6 (auxiliary encoders) are not simulated: 1
        return rtn or self._gt().refuse("invalid_in_mode")
    return self._on_axis(lambda c, i: c.set_gear(i, int(master) - 1))


_ARC = {"xy": ("x_center, y_center, angle", "x_end, y_end, r, direction"),
        "yz": ("y_center, z_center, angle", "y_end, z_end, r, direction"),
        "zx": ("z_center, x_center, angle", "z_end, x_end, r, direction")}

# -- the table: name, parameters, C++ call, what the manual says (and where) -----------------------------------
_ROWS = [
    gt_adapter("GT_Reset", "", lambda self: self._module(lambda g: g.hard_reset()),
               "Command reset, the HardRst defaults (L4124-4142): registers 0, T-curve, gains 0, limits 32767, "
               "auto-update/auto-stop off, closed loop, limits on, drives off, events cleared, LmtSns/Index 0, the "
               "coordinate system in immediate mode with SynVel/SynAcc 0 and CrdAuStp on, all interrupts masked."),
    gt_adapter("GT_HardRst", "", lambda self: (self.GT_Reset(), None)[1],
               "Hardware reset (returns nothing, L4122).", returns="None"),
    gt_adapter("GT_GetSmplTm", "", lambda self: self._read(lambda c, i: c.servo_period_s * 1e6),
               "(rtn, sample time in us) (L4066-4078).", returns=None),
    _gt_read("GT_GetCmdSts", lambda g: g.command_status(), "(rtn, command status register) (Table 2-2, L455-478)."),
    _gt_cmd("GT_Axis", "num: int", lambda g, n: g.select_axis(n), "Selects the current axis, 1..4 (L2825-2846)."),
    _axis_cmd("GT_AxisOn", lambda c, i: c.axis_on(i),
              "Enables the drive; sets motion complete; refused while the drive-alarm bit is set (L2910-2933)."),
    _axis_cmd("GT_AxisOff", lambda c, i: c.axis_off(i), "Disables the drive (L2884-2908)."),
    _axis_cmd("GT_DrvRst", lambda c, i: c.drive_reset(i), "Pulses the drive reset; only with the drive disabled "
              "(L3212-3239)."),
    gt_adapter("GT_CtrlMode", "mode", _ctrl_mode,
               "Output type: 0 analog (default), 1 pulse (L3189-3210). The simulated output is fixed by the axis's "
               "drive (a StepperDrive or ServoPositionDrive takes pulses): a mode that does not match it returns 1."),
    _axis_cmd("GT_CloseLp", lambda c, i: c.set_closed_loop(i, True), "Closed loop (L3063-3087)."),
    _axis_cmd("GT_OpenLp", lambda c, i: c.set_closed_loop(i, False), "Open loop: the output is GT_SetMtrCmd "
              "(L4355-4365)."),
    _setter("GT_SetMtrCmd", "mcmd", (-32767, 32767, "int", "illegal_control_param"),
            lambda c, i, v: c.set_mtr_cmd(i, v), "Open-loop output, DAC counts -32767..32767 (L4958-4970)."),
    _getter("GT_GetMtrCmd", lambda c, i: int(c.mtr_cmd(i)), "(rtn, open-loop output counts) (L3996-4008)."),
    _gt_cmd("GT_LmtSns", "sense", lambda g, s: g.set_limit_sense(s),
            "Limit polarity for all axes: bit 2(k-1) axis k positive, 2(k-1)+1 negative; 0 = triggers on a high "
            "level (default), 1 = on a low level (L4215-4248)."),
    _axis_cmd("GT_LmtsOn", lambda c, i: c.set_limits(i, c.limits(i).replace(enabled=True)),
              "Limit monitoring on for the current axis (default) (L4262-4272)."),
    _axis_cmd("GT_LmtsOff", lambda c, i: c.set_limits(i, c.limits(i).replace(enabled=False)),
              "Limit monitoring off for the current axis (L4250-4260)."),
    _gt_read("GT_GetLmtSwt", lambda g: g.limit_switches(),
             "(rtn, limit input levels): bit 2(k-1) axis k positive, 2(k-1)+1 negative; 1 = the switch is hit (the "
             "input is high with the default normally-closed wiring), whatever LmtSns says (L3915-3938)."),
    # 8.3 servo filter (double-buffered)
    *_gains("kp", "GT_SetKp", "kp", "GT_GetKp", "Proportional gain 0..32767 (staged) (L4902-4914)."),
    *_gains("ki", "GT_SetKi", "ki", "GT_GetKi", "Integral gain 0..32767, the term is Ki*SumE/256 (staged) "
            "(L4888-4900)."),
    *_gains("kd", "GT_SetKd", "kd", "GT_GetKd", "Derivative gain 0..32767 (staged) (L4874-4886)."),
    *_gains("kvff", "GT_SetKvff", "kvff", "GT_GetKvff", "Velocity feed-forward 0..32767 on V_target pulse/ST "
            "(staged) (L4916-4928)."),
    *_gains("kaff", "GT_SetKaff", "kaff", "GT_GetKaff", "Acceleration feed-forward 0..32767 on A_target "
            "pulse/ST^2 (staged) (L4860-4872)."),
    *_gains("ilmt", "GT_SetILmt", "ilmt", "GT_GetILmt", "Integral limit 0..32767 on the error sum (staged; 0 "
            "clears it) (L4749-4761)."),
    *_gains("mtr_lmt", "GT_SetMtrLmt", "mlmt", "GT_GetMtrLmt", "Output limit 0..32767 counts (staged) "
            "(L4972-4984)."),
    *_gains("bias", "GT_SetMtrBias", "bias", "GT_GetMtrBias", "Output bias -32768..32767 counts (staged) "
            "(L4944-4956).", -32768, 32767),
    _setter("GT_SetPosErr", "perr", _GAIN, lambda c, i, v: c.stage_pos_err(i, v),
            "Following-error limit 0..32767 pulse (staged) (L5000-5012)."),
    _getter("GT_GetPosErr", lambda c, i: int(c.staged(i)["pos_err"]), "(rtn, staged following-error limit, pulse)."),
    _getter("GT_GetIntgr", lambda c, i: int(c.integral(i)), "(rtn, integral accumulator, pulse*ST, as a short) "
            "(L3775-3785)."),
    _getter("GT_GetAtlErr", lambda c, i: int(max(-32768, min(32767, round(c.following_error(i))))),
            "(rtn, planned - actual position of the last tick, pulse, as a short) (L3554-3576)."),
    _axis_cmd("GT_AuStpOn", lambda c, i: c.set_auto_stop(i, True),
              "Auto-stop on following error: stop, motion complete, drive off (mode bit 7) (L2752-2773)."),
    _axis_cmd("GT_AuStpOff", lambda c, i: c.set_auto_stop(i, False), "Following error only flags bit 4 (default) "
              "(L2729-2750)."),
    # 8.4 profile / motion
    _axis_cmd("GT_PrflT", lambda c, i: c.set_mode(i, "t_curve"), "T-curve mode (L4467-4492); refused while moving "
              "(command status bit 6)."),
    _axis_cmd("GT_PrflS", lambda c, i: c.set_mode(i, "s_curve"), "S-curve mode (L4439-4465)."),
    _axis_cmd("GT_PrflV", lambda c, i: c.set_mode(i, "jog"), "Velocity (jog) mode (L4494-4518)."),
    gt_adapter("GT_PrflG", "master", _prfl_g,
               "Electronic gear mode: the current axis follows the profile position of axis ``master`` (1..4) with "
               "the staged ratio (GT_SetRatio + Update); bit 10 stays set (L1090). Masters 5, 6 (auxiliary encoders) "
               "are not simulated: 1 (command error). Refused while the axis moves in another mode (bit 6) "
               "(L4407-4437)."),
    _setter("GT_SetPos", "pos", _POS, lambda c, i, v: c.stage_pos(i, v),
            "Target position, whole pulses -2^30..2^30-1 (staged) (L4986-4998)."),
    _getter("GT_GetPos", lambda c, i: register32(c.staged(i)["pos"]), "(rtn, staged target, pulse) (L4024-4036)."),
    _setter("GT_SetVel", "vel", _vel_range, lambda c, i, v: c.stage_vel(i, v),
            "Velocity, pulse/ST: 0..16384 in T/S mode, -16384..16384 in jog mode (staged) (L5076-5090)."),
    _getter("GT_GetVel", lambda c, i: c.staged(i)["vel"], "(rtn, staged velocity, pulse/ST)."),
    _setter("GT_SetAcc", "acc", (0, 16384, "real", "motion_param_overflow"), lambda c, i, v: c.stage_acc(i, v),
            "Acceleration, pulse/ST^2, 0..16384, T-curve and jog (staged) (L4571-4583)."),
    _getter("GT_GetAcc", lambda c, i: c.staged(i)["acc"], "(rtn, staged acceleration, pulse/ST^2)."),
    _setter("GT_SetMAcc", "macc", (0, 0.5, "real_open", "illegal_control_param"), lambda c, i, v: c.stage_macc(i, v),
            "S-curve maximum acceleration, pulse/ST^2, 0 <= MAcc < 0.5 (staged) (L4930-4942)."),
    _getter("GT_GetMAcc", lambda c, i: c.staged(i)["macc"], "(rtn, staged MAcc, pulse/ST^2)."),
    _setter("GT_SetJerk", "jerk", (0, 0.5, "real_open", "illegal_control_param"), lambda c, i, v: c.stage_jerk(i, v),
            "S-curve jerk, pulse/ST^3, 0 <= J < 0.5 (staged) (L4846-4858)."),
    _getter("GT_GetJerk", lambda c, i: c.staged(i)["jerk"], "(rtn, staged jerk, pulse/ST^3)."),
    _setter("GT_SetRatio", "ratio", (-16384, 16384, "real", "illegal_control_param"),
            lambda c, i, v: c.stage_ratio(i, v), "Gear ratio -16384..16384 (staged) (L5014-5026)."),
    _getter("GT_GetRatio", lambda c, i: c.staged(i)["ratio"], "(rtn, staged gear ratio)."),
    _axis_cmd("GT_SmthStp", lambda c, i: c.stage_smooth_stop(i), "Smooth stop at the commanded deceleration "
              "(staged: needs Update) (L5092-5102)."),
    _axis_cmd("GT_AbptStp", lambda c, i: c.abrupt_stop(i), "Abrupt stop: profile velocity 0 at once, motion "
              "complete (immediate) (L2702-2727)."),
    _axis_cmd("GT_Update", lambda c, i: c.update(1 << i), "Commits the current axis's staged registers at the next "
              "sample (L5184-5194)."),
    _setter("GT_MltiUpdt", "mask", _WORD, lambda c, i, v: c.update(int(v) & 0xF),
            "Commits the masked axes (bit k-1 = axis k) in the same sample; mask 0 is an error (cmd bit 2) "
            "(L4274-4310)."),
    _axis_cmd("GT_ZeroPos", lambda c, i: c.zero_pos(i), "Actual = target = profile = 0; at rest only (cmd bit 11) "
              "(L5196-5206)."),
    _axis_cmd("GT_SynchPos", lambda c, i: c.stage_synch_pos(i), "Target = profile = actual (staged: needs Update); "
              "an error in jog mode (L5152-5162)."),
    _setter("GT_SetAtlPos", "pos", _POS, lambda c, i, v: c.set_actual_pos(i, v),
            "Actual = target = profile = pos, whole pulses; at rest only (L4613-4639)."),
    _getter("GT_GetAtlPos", lambda c, i: register32(c.actual_pos(i)), "(rtn, actual position, pulse) (L3578-3606)."),
    # 8.5 breakpoints
    _setter("GT_SetBrkCn", "brk", _POS, lambda c, i, v: c.stage_brk_cn(i, v),
            "Breakpoint compare value, whole pulses +-2^30 (staged) (L4717-4731)."),
    _getter("GT_GetBrkCn", lambda c, i: int(c.staged(i)["brk_cn"]), "(rtn, staged breakpoint value, pulse) "
            "(L3624-3638)."),
    _axis_cmd("GT_PosBrk", lambda c, i: c.arm_breakpoint(i, "pos"), "Arms: actual >= BrkCn (L4393-4405)."),
    _axis_cmd("GT_NegBrk", lambda c, i: c.arm_breakpoint(i, "neg"), "Arms: actual <= BrkCn (L4341-4353)."),
    _axis_cmd("GT_MtnBrk", lambda c, i: c.arm_breakpoint(i, "motion"), "Arms: on motion complete (L4312-4339)."),
    _axis_cmd("GT_ExtBrk", lambda c, i: c.arm_breakpoint(i, "home"), "Arms: on the home capture (L3443-3470)."),
    _axis_cmd("GT_BrkOff", lambda c, i: c.arm_breakpoint(i, "none"), "Disarms an untriggered breakpoint "
              "(L2935-2956)."),
    _axis_cmd("GT_AuUpdtOn", lambda c, i: c.set_auto_update(i, True), "Auto-update at a breakpoint on (mode bit 10) "
              "(L2802-2823)."),
    _axis_cmd("GT_AuUpdtOff", lambda c, i: c.set_auto_update(i, False), "Auto-update off (default) (L2775-2800)."),
    # 8.6 status and mode
    _getter("GT_GetSts", lambda c, i: _core.gt_axis_status(c.kernel, i), "(rtn, axis status register) (Table 4-14, "
            "L4080-4104)."),
    _axis_cmd("GT_ClrSts", lambda c, i: c.clear_events(i, _core.gt_events_to_clear(0)),
              "Clears status bits 0-7 (bit 4 only once out of error) (L3138-3161)."),
    _setter("GT_RstSts", "mask", _WORD, lambda c, i, v: c.clear_events(i, _core.gt_events_to_clear(int(v))),
            "Clears the status bits 0-7 whose mask bit is 0 (L4557-4569)."),
    _getter("GT_GetMode", lambda c, i: _core.gt_mode_register(c.kernel, i), "(rtn, axis mode register) (Table 4-15, "
            "L3954-3978)."),
    # 8.7 capture / homing
    _axis_cmd("GT_CaptHome", lambda c, i: c.arm_capture(i, "home"), "Arms a one-shot home capture (status bit 14) "
              "(L2958-2982)."),
    _axis_cmd("GT_CaptIndex", lambda c, i: c.arm_capture(i, "index"), "Arms a one-shot index capture (status bit "
              "15) (L2984-3006)."),
    _getter("GT_GetCapt", lambda c, i: int(round(c.capture_value(i))), "(rtn, captured position, pulse) "
            "(L3640-3674)."),
    _gt_cmd("GT_Index", "value=1", lambda g, v: g.set_index(v), "0 home only (default), 1 home + index for GT_Home "
            "(L4188-4213)."),
    _gt_cmd("GT_Home", "pos", lambda g, p: g.home(p), "Automatic homing toward ``pos`` (pulse, beyond the home "
            "switch) at the staged T-curve Vel and Acc (decision V24) (L4152-4168)."),
    # coordinated motion (GT L1513-2011; gt.md §4, §8.11): vendor/googol/gt_crd_list.hpp
    _gt_cmd("GT_MapAxis", "axis_num, map_count", lambda g, a, m: g.map_axis(a, list(m)),
            "Maps motor axis 1..4: Axis = Cx x + Cy y + Cz z + Ca a + C, map_count = [Cx, Cy, Cz, Ca, C] "
            "(L1533-1538); the axis enters coordinated mode. Only at rest (1); a map that determines no coordinate "
            "returns 6 (L1528, L1660)."),
    _gt_cmd("GT_SetSynVel", "vel", lambda g, v: g.set_syn_vel(v), "Vector velocity, coordinate units/ST, modal for "
            "the later path commands (L1725); 4 when zero, negative or beyond 16384 (L401)."),
    _gt_cmd("GT_SetSynAcc", "acc", lambda g, a: g.set_syn_acc(a), "Vector acceleration, coordinate units/ST^2, modal "
            "(L1729); 4 when zero, negative or beyond 16384 (L401)."),
    _gt_cmd("GT_LnXY", "x, y", lambda g, *p: g.line(list(p)), "Line to the absolute point (x, y), coordinate units "
            "(L1749, L1787)."),
    _gt_cmd("GT_LnXYZ", "x, y, z", lambda g, *p: g.line(list(p)), "3-D line (L1750)."),
    _gt_cmd("GT_LnXYZA", "x, y, z, a", lambda g, *p: g.line(list(p)), "4-D line (L1751)."),
    *[_gt_cmd(f"GT_Arc{pl.upper()}", _ARC[pl][0], (lambda plane: lambda g, c1, c2, a:
                                                   g.arc_center_angle(plane, c1, c2, a))(pl),
              f"Arc in the {pl.upper()} plane about the centre (absolute) by ``angle`` degrees, positive CCW seen "
              "from the plane's normal (L1752-1756, L1793, L1913); the radius is the distance of the present point "
              "(2: zero radius).") for pl in _ARC],
    *[_gt_cmd(f"GT_Arc{pl.upper()}P", _ARC[pl][1], (lambda plane: lambda g, e1, e2, r, d:
                                                    g.arc_end_radius(plane, e1, e2, r, d))(pl),
              f"Arc in the {pl.upper()} plane to the end point with radius ``r``: r > 0 the arc of at most 180 deg, "
              "r < 0 the longer one; direction +1 CCW, -1 CW (L1753-1757, L1793). The GT manual names it with its "
              "return code 5 (L406) but prints no prototype: the GE lineage's (GE L3477-3483) is taken (decision "
              "GF8). 2: radius 0; 5: chord longer than the diameter.") for pl in _ARC],
    _gt_read("GT_GetMtnNm", lambda g: g.motion_number(),
             "(rtn, number of the buffer segment executing, or where the buffer stopped): the Mv* line is 0, the "
             "path segments since GT_StrtList count from 1; it holds when the buffer runs dry and after the last "
             "segment (L1971-1985, decision GF9). 0 in immediate mode."),
    _gt_cmd("GT_SetAccLmt", "acc", lambda g, a: g.set_acc_lmt(a),
            "Acceleration limit of the current axis at the joints of a buffered path, pulse/ST^2, 0..16384 (0 = no "
            "limit, the default): the vector velocity at a joint is lowered until no mapped axis changes its "
            "velocity by more than its limit (L1956-1966). The manual prints no prototype: one argument on the "
            "current axis, like every single-axis command (GF10)."),
    _gt_cmd("GT_StrtList", "", lambda g: g.start_list(), "Opens and clears the buffer (buffer mode); refused while "
            "the buffer executes (bit 12) (L1841)."),
    _gt_cmd("GT_MvXY", "x, y, vel, acc", lambda g, x, y, v, a: g.move_start_point([x, y], v, a),
            "Buffer start point (x, y) reached by a line at vel/acc that ends at rest; vel/acc become the defaults "
            "(L1843-1845)."),
    _gt_cmd("GT_MvXYZ", "x, y, z, vel, acc", lambda g, x, y, z, v, a: g.move_start_point([x, y, z], v, a),
            "3-D start point (L3351)."),
    _gt_cmd("GT_MvXYZA", "x, y, z, a, vel, acc", lambda g, x, y, z, a, v, ac: g.move_start_point([x, y, z, a], v, ac),
            "4-D start point (L1901)."),
    _gt_cmd("GT_EndList", "", lambda g: g.end_list(), "Closes the buffer (only while open) (L1849)."),
    _gt_cmd("GT_AddList", "", lambda g: g.add_list(), "Reopens a closed buffer; while open: bit 12 (L1853-1859)."),
    _gt_cmd("GT_StrtMtn", "", lambda g: g.start_motion(), "Runs the buffer (needs StrtList + Mv*), or resumes it "
            "after a stop, first returning to the stop point (L1928, L1940); refused while it executes (bit 12)."),
    _gt_cmd("GT_StpMtn", "", lambda g: g.stop_motion(False), "Smooth stop of the coordinated motion; closes the "
            "buffer (L1934-1936)."),
    _gt_cmd("GT_EStpMtn", "", lambda g: g.stop_motion(True), "Abrupt stop: vector velocity 0 at once; closes the "
            "buffer; the buffer resumes with StrtMtn (L3332-3359)."),
    _gt_cmd("GT_CrdAuStpOn", "", lambda g: g.set_crd_auto_stop(True), "Coordinate status bit 6 on (default): an "
            "axis abnormality stops the whole coordinated motion (L2011)."),
    _gt_cmd("GT_CrdAuStpOff", "", lambda g: g.set_crd_auto_stop(False), "Coordinate status bit 6 off. The card "
            "still stops the whole path on an axis fault (decision V64)."),
    gt_adapter("GT_GetBrkPnt", "", lambda self: (RTN_COMM_ERROR, 0) if self._card is None
               else self._gt().crd_breakpoint(), "(rtn, coordinate point where the buffer was stopped, or None) "
               "(L1971).", returns=None),
    _gt_read("GT_GetCrdSts", lambda g: g.crd_status(),
             "(rtn, coordinate status register) (Table 5-6, L1990-2011): 0 finished/none, 1 buffer input finished, "
             "3 last coordinated command in error, 4 segment completed, 6 auto-stop on, 7 immediate mode, 9 an "
             "axis fault stopped the motion, 13 buffer empty after the start."),
    # probe capture and interrupts (issue 10 point 3; gt.md §5, §7, §8.9; decisions V71-V85): gt_interrupts.hpp
    _gt_cmd("GT_CaptProb", "", lambda g: g.capture_probe(),
            "Arms the probe capture (EXI0) on every axis whose capture register is free (not armed for home/index, "
            "captured flag clear; V85): the probe latches each one's actual position and sets its status bit 3 "
            "(L3008-3049). Returns 1 (command status bit 8) when no axis could be armed. The probe input is the "
            "card's: ``card.set_probe_time(t_s)`` or ``card.set_probe_position(axis, pulse)``."),
    gt_adapter("GT_HookIsr", "isr", lambda self, isr: self._gt().hook_isr(isr) if self._card is not None else None,
               "Hooks the host's interrupt service routine (a Python callable taking no argument; PCI DOS form, "
               "L4170-4186) and returns the previous one (None at first). The card calls it from :meth:`run` at the "
               "tick the interrupt is requested; inside it, GT_AxisI / GT_GetIntr / GT_RstIntr serve the request.",
               returns=None),
    _gt_cmd("GT_SetIntSyncEvent", "hIntEvent", lambda g, ev: g.set_sync_event(ev),
            "Windows form of interrupt service (L2334-2410): the driver's ISR sets the program's synchronisation "
            "event at each interrupt request, and a thread of the program waiting on it (``WaitForSingleObject``) "
            "runs. ``hIntEvent`` is an object with ``set()`` (a :class:`threading.Event`), or None to release it "
            "before closing (L2340). 7 for anything else."),
    _gt_cmd("GT_UnhookIsr", "old_isr", lambda g, isr: (g.hook_isr(isr), RTN_SUCCESS)[1], "Restores the ISR ``old_isr`` "
            "(L5164-5182)."),
    _gt_cmd("GT_ClearInt", "CardNo=0", lambda g, n: g.clear_interrupt(n), "Ends the interrupt service on card "
            "``CardNo`` (0; L3089-3122): a timer request is served."),
    _gt_cmd("GT_EvntIntr", "", lambda g: g.event_interrupts(), "Event interrupts (the default): axis status bits 0-6 "
            "enabled by GT_SetIntrMsk request an interrupt (L2219-2223, L3361-3373)."),
    _gt_cmd("GT_TmrIntr", "", lambda g: g.timer_interrupts(), "Timer interrupts every GT_SetIntrTm x ST "
            "(L5054-5074); event interrupts off."),
    _gt_cmd("GT_SetIntrTm", "Timer", lambda g, t: g.set_interrupt_timer(t), "Timer-interrupt period in servo "
            "periods, 0..32767 (10 x 200 us = 2 ms, L4787-4801); 0: no timer interrupt (V84)."),
    _gt_read("GT_GetIntrTm", lambda g: g.interrupt_timer, "(rtn, timer-interrupt period in servo periods) "
             "(L3815-3829)."),
    _gt_cmd("GT_SetIntrMsk", "Mask", lambda g, m: g.set_interrupt_mask(m),
            "Interrupt mask of the current axis: bit k = status bit k may interrupt, bits 0-6 (bits 7-15 unused); "
            "all masked after reset (L4763-4785). A status bit already set interrupts at once."),
    _gt_read("GT_GetIntrMsk", lambda g: g.interrupt_mask(), "(rtn, interrupt mask of the current axis) "
             "(L3801-3813)."),
    _gt_read("GT_GetIntr", lambda g: g.interrupt_status(), "(rtn, status register of the interrupting axis; of the "
             "current axis when no interrupt is pending) (L3787-3799); a timer interrupt reads 0."),
    _gt_cmd("GT_AxisI", "", lambda g: g.select_interrupting_axis(), "Makes the interrupting axis current (the lowest "
            "number first, L2229); only with an interrupt pending, else command status bit 4 (L2850-2882)."),
    _gt_cmd("GT_RstIntr", "Mask", lambda g, m: g.reset_interrupt(m),
            "Clears the current axis's status bits 0-7 whose Mask bit is 0 (1 keeps) and ends the request; if an "
            "enabled condition persists (a limit still pressed) the card requests again at once (Table 8-1, "
            "L2235-2243; L4534-4555). Only with an interrupt pending, else command status bit 4."),
]
for _fn in [*_ROWS, _GtSystem.GT_Open]:  # GT_Open too: the API reference documents the controller's own methods
    setattr(GtController, _fn.__name__, _fn)

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
