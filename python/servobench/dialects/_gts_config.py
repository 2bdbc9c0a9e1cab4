"""The GUC-ECAT system configuration calls (GUC §3.1 L185-300), the iDEABOX velocity filters (§4.5 L3773-3801,
L5450-5495, L7056-7091), the read-backs (GT_GetTrapPrm, GT_GetJogPrm, GT_GetStopDec, GT_GetCrdStopDec), the
EtherCAT / configuration-file calls of the iDEABOX examples (L611, L625) and the iDEABOX ``...Mx`` forms
(``CardNo`` first, L3825), as a mixin of :class:`~servobench.dialects.gts.GtsController`.

Behaviour stays the Card's (alarm enable, limit enable and polarity, stops); what the card does not hold (stop
decelerations, stop inputs, the filter windows, the GPI polarity) is kept here per controller and applied at the
reads and at ``GT_Stop``, through a per-tick hook (:meth:`_tick_hook`) only while something needs it. Units:
pulse, ms, pulse/ms, pulse/ms^2; axes from 1. Decisions GS1-GS18 (docs/decisions.md, Session 10)."""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass

from .._core import CardCommandRefused
from ._controller import GOOGOL_COMMAND_ERROR, GOOGOL_COMM_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_SUCCESS

# Digital input types of GT_GetDi / GT_SetStopIo (GUC L253-266): MC_GPI 4, MC_ARRIVE 5 (GTS-400-PX, L259).
MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI, MC_ARRIVE = 0, 1, 2, 3, 4, 5
# GT_FollowSwitchNowEx methods (iDEABOX L5427-5429).
FOLLOW_SWITCH_SEGMENT, FOLLOW_SWITCH_TABLE = 1, 2
_FILTER_EXP_MAX = 7  # window 2^n, n 0..7 (iDEABOX L3795-3797, L5462)

#: Calls the simulation cannot carry out: defined, return the manual's code, listed with the reason.
UNSUPPORTED_CONFIG = {
    "GT_SetAdcFilter": "the simulated card has no analog inputs to filter (GUC L207, L278-280: GTS-400-PX only); "
                       "returns 1 (command error, GUC Tab 2-1 L165-180)",
    "GT_LoadConfig": "the .cfg file is written by the vendor's configuration tool in a format neither manual gives "
                     "(iDEABOX L625, GUC L188-192); the simulated machine's configuration is the Card it opens "
                     "(use_machine); returns 1 (command error, iDEABOX Table 3-1 L333-361)",
}


@dataclass
class TTrapPrm:
    """TTrapPrm (GUC basic library): acc, dec pulse/ms^2; velStart pulse/ms; smoothTime ms."""
    acc: float = 0.0
    dec: float = 0.0
    velStart: float = 0.0
    smoothTime: int = 0


@dataclass
class TJogPrmExt:
    """TJogPrmExt (iDEABOX Ex 4-1 L598, L726-730): acc, dec pulse/ms^2; smooth 0..1 (the examples set acc)."""
    acc: float = 0.0
    dec: float = 0.0
    smooth: float = 0.0


def _int_in(v, lo, hi) -> bool:
    try:
        x = float(v)
    except (TypeError, ValueError):
        return False
    return math.isfinite(x) and x == int(x) and lo <= x <= hi


def _pos(v, hi=32767.0) -> bool:
    """0 < v <= hi (the manuals' (0, 32767] decelerations, GUC L240-243)."""
    try:
        x = float(v)
    except (TypeError, ValueError):
        return False
    return math.isfinite(x) and 0 < x <= hi


class GtsConfigMixin:
    """System configuration, velocity filters, read-backs and the Mx forms (see the module docstring)."""

    # -- per-controller state the card does not hold ------------------------------------------------------------
    def _cfg(self) -> dict:
        st = self.__dict__.get("_cfg_state")
        if st is None or st["card"] is not self._card:
            st = self.__dict__["_cfg_state"] = {
                "card": self._card, "gpi": 0, "gpi_sns": 0, "stop_dec": {}, "crd_stop_dec": {}, "stop_io": {},
                "prf_exp": {}, "enc_exp": {}, "hist": None, "hooks": {}, "sid": None, "jog": {}, "trap": {}}
        return st

    def _tick_hook(self, name: str, fn) -> None:
        """Registers ``fn(card)`` to run after every servo tick (``None`` removes it); one card timer event
        (:meth:`~servobench.Card.on_event`, ``timer_ticks=1``) carries all hooks while any is set."""
        st = self._cfg()
        hooks = st["hooks"]
        if fn is None:
            hooks.pop(name, None)
        else:
            hooks[name] = fn
        card = self._card
        if hooks and st["sid"] is None:
            st["sid"] = card.on_event(lambda c, _ev: [h(c) for h in list(hooks.values())], timer_ticks=1)
        elif not hooks and st["sid"] is not None:
            card.remove_event(st["sid"])
            st["sid"] = None

    def _ok_axis(self, axis) -> bool:
        return self._card is not None and _int_in(axis, 1, len(self._card))

    def _code(self) -> int:
        return GOOGOL_COMM_ERROR if self._card is None else GOOGOL_PARAMETER_ERROR

    # -- simulation helper (not a vendor call) -------------------------------------------------------------------
    def set_inputs(self, bits: int) -> None:
        """Sets the simulated electrical levels of the general inputs GPI 1..16 (bit k = GPI k+1, 1 = high)
        that ``GT_GetDi(MC_GPI)`` and a ``GT_SetStopIo`` on ``MC_GPI`` read (the machine's wiring; default all
        low)."""
        if isinstance(bits, bool) or not _int_in(bits, 0, 0xFFFF):
            raise ValueError(f"set_inputs.bits = {bits!r} is outside the allowed range 0..0xFFFF (GPI 1..16)")
        if self._card is None:
            raise RuntimeError("set_inputs: no card is open (GT_Open first)")
        self._cfg()["gpi"] = int(bits)

    # -- GUC §3.1 system configuration ---------------------------------------------------------------------------
    def GT_AlarmOn(self, axis) -> int:
        """The drive-alarm input of ``axis`` stops it and switches its drive off (default) (GUC L198, L215)."""
        if not self._ok_axis(axis):
            return self._code()
        return self._do(self._card.set_alarm_enabled, int(axis) - 1, True)

    def GT_AlarmOff(self, axis) -> int:
        """The drive-alarm input of ``axis`` is ignored (GUC L197, L213)."""
        if not self._ok_axis(axis):
            return self._code()
        return self._do(self._card.set_alarm_enabled, int(axis) - 1, False)

    def _lmts(self, axis, limitType, on: bool) -> int:
        if not self._ok_axis(axis) or limitType not in (-1, MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE):
            return self._code()
        a = int(axis) - 1
        lim = self._card.limits(a)
        if limitType != -1 and lim.enabled != on:
            # the card has one limit-enable flag per axis: one side alone cannot differ from the other (GS3)
            return GOOGOL_COMMAND_ERROR
        return self._do(self._card.set_limits, a, lim.replace(enabled=on))

    def GT_LmtsOn(self, axis, limitType=-1) -> int:
        """Limit switches of ``axis`` stop it (default): limitType MC_LIMIT_POSITIVE 0, MC_LIMIT_NEGATIVE 1, -1
        both (GUC L199, L217-222). One side alone only when the other side is already in that state (returns 1
        otherwise, nothing changed: the card has one enable per axis, decision GS3)."""
        return self._lmts(axis, limitType, True)

    def GT_LmtsOff(self, axis, limitType=-1) -> int:
        """Limit switches of ``axis`` ignored (GUC L200, L223-228); one side alone as in GT_LmtsOn (GS3)."""
        return self._lmts(axis, limitType, False)

    def GT_LmtSns(self, sense) -> int:
        """Limit polarity, bit 2k axis k+1 positive, 2k+1 negative: 0 triggers on a high level (normally closed,
        default), 1 on a low level (GUC L294-305, Tab 3-4)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(sense, 0, 0xFFFF):
            return GOOGOL_PARAMETER_ERROR

        def apply():
            for k in range(min(8, len(self._card))):
                lim = self._card.limits(k).replace(pos_active_low=bool(int(sense) >> (2 * k) & 1),
                                                   neg_active_low=bool(int(sense) >> (2 * k + 1) & 1))
                self._card.set_limits(k, lim)

        return self._do(apply)

    def GT_EncSns(self, sense) -> int:
        """Encoder count direction, bit k = axis k+1 (bit 8 the auxiliary encoder), 1 = reversed (GUC L284-290,
        Tab 3-3). The simulated encoder counts the drive's positive direction as positive: 0 bits are accepted,
        a set bit returns 1 (reversing it would turn the closed loop into positive feedback; decision GS4)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(sense, 0, 0x1FF):
            return GOOGOL_PARAMETER_ERROR
        return GOOGOL_COMMAND_ERROR if int(sense) else GOOGOL_SUCCESS

    def _scale(self, axis, alpha, beta) -> int:
        if not self._ok_axis(axis) or not _int_in(alpha, -32768, 32767) or not _int_in(beta, -32768, 32767) \
                or beta == 0:
            return self._code()
        # the simulated axis counts one pulse per profile / encoder unit: alpha = beta (1:1) only (GS5)
        return GOOGOL_SUCCESS if alpha == beta else GOOGOL_COMMAND_ERROR

    def GT_ProfileScale(self, axis, alpha, beta) -> int:
        """Profile scale alpha/beta, each -32768..32767 (GUC L201, L232-235): 1:1 (alpha = beta) is the simulated
        axis; another ratio returns 1 (decision GS5)."""
        return self._scale(axis, alpha, beta)

    def GT_EncScale(self, axis, alpha, beta) -> int:
        """Encoder scale alpha/beta (GUC L202, L236-239): as GT_ProfileScale (GS5)."""
        return self._scale(axis, alpha, beta)

    def GT_GpiSns(self, sense) -> int:
        """General-input polarity, bit k = GPI k+1: 0 GT_GetDi reads the level, 1 the inverted level (GUC L206,
        L267-276)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(sense, 0, 0xFFFF):
            return GOOGOL_PARAMETER_ERROR
        self._cfg()["gpi_sns"] = int(sense)
        return GOOGOL_SUCCESS

    def _di_word(self, diType) -> int:
        c = self._card
        n = min(8, len(c))
        if diType == MC_GPI:
            st = self._cfg()
            return st["gpi"] ^ st["gpi_sns"]
        if diType == MC_LIMIT_POSITIVE:  # 1 = the limit triggers (its polarity applied, GT_LmtSns)
            return sum(int(c.pos_limit_input(k)) << k for k in range(n))
        if diType == MC_LIMIT_NEGATIVE:
            return sum(int(c.neg_limit_input(k)) << k for k in range(n))
        if diType == MC_ALARM:  # the latched drive-alarm event (status bit 1)
            return sum(int(c.events(k) >> 1 & 1) << k for k in range(n))
        raise CardCommandRefused("MC_HOME / MC_ARRIVE inputs are not wired in the simulated machine")

    def GT_GetDi(self, diType):
        """(rtn, input word): MC_LIMIT_POSITIVE / MC_LIMIT_NEGATIVE bit k = the limit of axis k+1 triggers,
        MC_ALARM bit k = drive alarm of axis k+1, MC_GPI bit k = GPI k+1 after GT_GpiSns (GUC L206, L267-276).
        MC_HOME / MC_ARRIVE: 1 (not wired in the simulated machine, decision GS6)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR, 0
        if diType not in (MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI, MC_ARRIVE):
            return GOOGOL_PARAMETER_ERROR, 0
        return self._get(lambda: int(self._di_word(diType)))

    def GT_SetAdcFilter(self, adc, filterTime) -> int:
        """ADC input filter, adc 1..8, filterTime 1..50 (GUC L207, L278-280; GTS-400-PX only): the simulated card
        has no analog inputs: 1 (UNSUPPORTED); 7 for values out of range."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(adc, 1, 8) or not _int_in(filterTime, 1, 50):
            return GOOGOL_PARAMETER_ERROR
        return GOOGOL_COMMAND_ERROR

    # -- stop decelerations and stop inputs ----------------------------------------------------------------------
    def GT_SetStopDec(self, profile, decSmoothStop, decAbruptStop) -> int:
        """Stop decelerations of ``profile``, (0, 32767] pulse/ms^2 each (GUC L203, L240-243): GT_Stop
        decelerates a point-to-point or jog axis at decSmoothStop (smooth) or decAbruptStop (abrupt option bit)
        instead of its acc / at once (decision GS7)."""
        if not self._ok_axis(profile):
            return self._code()
        if not _pos(decSmoothStop) or not _pos(decAbruptStop):
            return GOOGOL_PARAMETER_ERROR
        self._cfg()["stop_dec"][int(profile)] = (float(decSmoothStop), float(decAbruptStop))
        return GOOGOL_SUCCESS

    def GT_GetStopDec(self, profile):
        """(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 set by GT_SetStopDec; (0, 0) before (GUC L204,
        L244-247)."""
        if not self._ok_axis(profile):
            return self._code(), 0.0, 0.0
        return (GOOGOL_SUCCESS,) + self._cfg()["stop_dec"].get(int(profile), (0.0, 0.0))

    def GT_GetCrdStopDec(self, crd):
        """(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 of ``crd`` 1..2 set by GT_SetCrdStopDec; (0, 0) before
        (GUC L362, L710-712; iDEABOX L5551-5560)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._code(), 0.0, 0.0
        return (GOOGOL_SUCCESS,) + self._cfg()["crd_stop_dec"].get(int(crd), (0.0, 0.0))

    def _stop_axis(self, a: int, abrupt: bool) -> None:
        """GT_Stop of one point-to-point / jog axis: at its GT_SetStopDec deceleration when set, else the card's
        smooth stop (the move's acc) or abrupt stop (at once)."""
        dec = self._cfg()["stop_dec"].get(a + 1)
        if dec is None or not self._card.moving(a):
            if abrupt:
                self._card.abrupt_stop(a)
            else:
                self._card.stage_smooth_stop(a)
                self._card.update(1 << a)
            return
        acc = self._card.staged(a)["acc"]
        self._card.stage_acc(a, dec[1 if abrupt else 0] * self._ms ** 2)
        self._card.stage_smooth_stop(a)
        self._card.update(1 << a)
        if acc > 0:  # the move's acc again for the next move (staged, committed by its update)
            self._card.stage_acc(a, acc)

    def _stop_io_hook(self, card) -> None:
        st = self._cfg()
        for axis, (stop_type, in_type, index) in list(st["stop_io"].items()):
            a = axis - 1
            try:
                active = self._di_word(in_type) >> (index - 1) & 1
            except CardCommandRefused:
                continue
            if active and (card.moving(a) or card.mode(a) not in ("t_curve", "jog")):
                if card.mode(a) in ("t_curve", "s_curve", "jog") and card.group_of(a) < 0:
                    self._stop_axis(a, stop_type == 0)
                elif card.group_of(a) < 0:
                    card.abrupt_stop(a)

    def GT_SetStopIo(self, axis, stopType, inputType, inputIndex) -> int:
        """Maps an input to a stop of ``axis`` 1..8: stopType 0 emergency / 1 smooth; inputType MC_LIMIT_POSITIVE,
        MC_LIMIT_NEGATIVE, MC_ALARM (index 1..8), MC_GPI (index 1..16) (GUC L205, L248-266). While the input is
        active the axis stops at its GT_SetStopDec decelerations (checked every tick, decision GS8). MC_HOME /
        MC_ARRIVE: 1 (not wired, GS6)."""
        if not self._ok_axis(axis) or not _int_in(axis, 1, 8):
            return self._code()
        hi = 16 if inputType == MC_GPI else 8
        if stopType not in (0, 1) or inputType not in (0, 1, 2, 3, 4, 5) or not _int_in(inputIndex, 1, hi):
            return GOOGOL_PARAMETER_ERROR
        if inputType in (MC_HOME, MC_ARRIVE):
            return GOOGOL_COMMAND_ERROR
        st = self._cfg()
        st["stop_io"][int(axis)] = (int(stopType), int(inputType), int(inputIndex))
        self._tick_hook("stop_io", self._stop_io_hook)
        return GOOGOL_SUCCESS

    # -- read-backs of the profile parameters ------------------------------------------------------------------
    def GT_GetTrapPrm(self, profile):
        """(rtn, TTrapPrm): acc = dec = the staged acceleration (pulse/ms^2; one acceleration for both ramps,
        decision V61), velStart 0, smoothTime 0 (GUC basic library; the combined-motion example L2900 reads it)."""
        if not self._ok_axis(profile):
            return self._code(), None
        a = int(profile) - 1
        return self._get(lambda: TTrapPrm(acc=self._card.staged(a)["acc"] / self._ms ** 2,
                                          dec=self._card.staged(a)["acc"] / self._ms ** 2))

    def GT_GetJogPrm(self, profile):
        """(rtn, TJogPrmExt): acc = dec = the staged acceleration pulse/ms^2 (V61), smooth as set (iDEABOX Ex 4-1
        L726)."""
        if not self._ok_axis(profile):
            return self._code(), None
        a = int(profile) - 1
        smooth = self._cfg()["jog"].get(int(profile), 0.0)
        acc = self._card.staged(a)["acc"] / self._ms ** 2
        return GOOGOL_SUCCESS, TJogPrmExt(acc=acc, dec=acc, smooth=smooth)

    # -- iDEABOX velocity filters (§4.5 L3773-3801) ---------------------------------------------------------------
    def _hist_hook(self, card) -> None:
        h = self._cfg()["hist"]
        h.append(tuple((card.profile_vel(k), card.actual_pos(k)) for k in range(len(card))))

    def _history(self):
        st = self._cfg()
        if st["hist"] is None:
            st["hist"] = deque(maxlen=(1 << _FILTER_EXP_MAX) + 1)
            self._hist_hook(self._card)
            self._tick_hook("vel_history", self._hist_hook)
        return st["hist"]

    def _filtered_vel(self, a: int, which: int, exp: int) -> float:
        """pulse/ms: the mean velocity over the last 2^exp ticks (the moving-average window, L3795-3797), over the
        ticks recorded so far while the history is shorter. which 0: the profile velocity (the mean of its
        per-tick values); 1: the encoder velocity (actual-position change over the window / its ticks)."""
        h = self._history()
        if which == 0:
            n = min(1 << exp, len(h))
            return sum(h[-1 - k][a][0] for k in range(n)) / (n * self._ms) if n else 0.0
        n = min(1 << exp, len(h) - 1)
        if n <= 0:
            return 0.0
        return (h[-1][a][1] - h[-1 - n][a][1]) / (n * self._ms)

    def _set_filter(self, key, axis, exp) -> int:
        if not self._ok_axis(axis) or not _int_in(exp, 0, _FILTER_EXP_MAX):
            return self._code()
        self._cfg()[key][int(axis)] = int(exp)
        self._history()
        return GOOGOL_SUCCESS

    def GT_SetAxisPrfVelFilter(self, axis, filterNumExp) -> int:
        """Profile-velocity filter of ``axis``: window 2^filterNumExp ticks, filterNumExp 0..7 (iDEABOX L3801,
        L7075-7091). GT_GetPrfVel then reads the mean over that window (decision GS9)."""
        return self._set_filter("prf_exp", axis, filterNumExp)

    def GT_GetAxisPrfVelFilter(self, axis):
        """(rtn, filterNumExp) of the profile-velocity filter, 0 by default (iDEABOX L5474-5495)."""
        if not self._ok_axis(axis):
            return self._code(), 0
        return GOOGOL_SUCCESS, self._cfg()["prf_exp"].get(int(axis), 0)

    def GT_SetAxisEncVelFilter(self, axis, filterNumExp) -> int:
        """Encoder-velocity filter of ``axis``: window 2^filterNumExp ticks, 0..7 (iDEABOX L3793-3797,
        L7056-7071). GT_GetEncVel then reads the mean over that window (GS9)."""
        return self._set_filter("enc_exp", axis, filterNumExp)

    def GT_GetAxisEncVelFilter(self, axis):
        """(rtn, filterNumExp) of the encoder-velocity filter, 0 by default (iDEABOX L5450-5470)."""
        if not self._ok_axis(axis):
            return self._code(), 0
        return GOOGOL_SUCCESS, self._cfg()["enc_exp"].get(int(axis), 0)

    def GT_GetEncVel(self, axis, count=1):
        """(rtn, encoder velocity, pulse/ms): the actual-position change over the last 2^n ticks / 2^n
        (n = GT_SetAxisEncVelFilter, 0 = one tick). The history starts at the first velocity-filter setting or
        GT_GetEncVel call (before two samples it reads 0; decision GS9)."""
        if not self._ok_axis(axis):
            return self._code(), 0.0
        a = int(axis) - 1
        return self._get(lambda: self._filtered_vel(a, 1, self._cfg()["enc_exp"].get(a + 1, 0)))

    # -- iDEABOX EtherCAT and configuration file ------------------------------------------------------------------
    def GT_IsEcatReady(self):
        """(rtn, status): 1 = the EtherCAT bus is configured and running (iDEABOX Ex 4-1 L611-615). The simulated
        bus is up as soon as the card is open (decision GS10)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR, 0
        return GOOGOL_SUCCESS, 1

    def GT_LoadConfig(self, pCfgPath) -> int:
        """Loads a configuration file (iDEABOX L625; './GTS800.cfg'): the file's format is not given in the
        manuals; the simulated machine's configuration is the Card it opens. Returns 1 (UNSUPPORTED, GS11)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not isinstance(pCfgPath, (str, bytes)) or not pCfgPath:
            return GOOGOL_PARAMETER_ERROR
        return GOOGOL_COMMAND_ERROR


# The iDEABOX ``...Mx`` forms (CardNo first; "axes 1-16 are card 1, 17-32 card 2", L3825): the plain form with
# the masks of card CardNo (bit k = axis 16 (CardNo - 1) + k + 1). Mx form -> (plain form, mask arguments after
# CardNo, manual line of its prototype). One simulated card: CardNo 1 .. ceil(axes / 16), else 7 (decision GS12).
_MX_FORMS = {
    "GT_UpdateMx": ("GT_Update", 1, 736), "GT_StopMx": ("GT_Stop", 2, 1793), "GT_PvtStartMx": ("GT_PvtStart", 1, 6340),
    "GT_FollowStartExMx": ("GT_FollowStartEx", 2, 5013), "GT_FollowSwitchExMx": ("GT_FollowSwitchEx", 1, 5304),
    "GT_PvtTableMx": ("GT_PvtTable", 0, 6542), "GT_PvtTableExMx": ("GT_PvtTableEx", 0, 6495),
    "GT_PvtTableCompleteMx": ("GT_PvtTableComplete", 0, 6639),
    "GT_PvtTablePercentMx": ("GT_PvtTablePercent", 0, 6982),
    "GT_PvtTableContinuousMx": ("GT_PvtTableContinuous", 0, 6875),
    "GT_PvtTableContinuousExMx": ("GT_PvtTableContinuousEx", 0, 6811),
}


def _mx_form(name, plain, n_masks, line):
    def mx(self, CardNo, *args, **kwargs) -> int:
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(CardNo, 1, max(1, -(-len(self._card) // 16))):
            return GOOGOL_PARAMETER_ERROR
        shift = 16 * (int(CardNo) - 1)
        args = list(args)
        for k in range(min(n_masks, len(args))):
            if not _int_in(args[k], 0, 0xFFFFFFFF):
                return GOOGOL_PARAMETER_ERROR
            args[k] = int(args[k]) << shift
        return getattr(self, plain)(*args, **kwargs)

    mx.__name__ = mx.__qualname__ = name
    shifted = ", its masks shifted by 16 (CardNo - 1)" if n_masks else ""
    mx.__doc__ = (f"{plain} of card ``CardNo`` (iDEABOX L{line}; CardNo first, L3825: card 1 = axes 1-16){shifted}. "
                  f"Arguments after CardNo as {plain}; returns its code, 7 for a CardNo out of range.")
    return mx


def attach_mx_forms(cls) -> None:
    """Adds the Mx forms of :data:`_MX_FORMS` to the controller class ``cls``."""
    for name, (plain, n, line) in _MX_FORMS.items():
        setattr(cls, name, _mx_form(name, plain, n, line))
