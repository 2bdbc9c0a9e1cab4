"""The GUC-ECAT system configuration calls (GUC §3.1 L185-300), the iDEABOX velocity filters (§4.5 L3773-3801,
L5450-5495, L7056-7091), the read-backs (GT_GetTrapPrm, GT_GetJogPrm, GT_GetStopDec, GT_GetCrdStopDec), the
EtherCAT / configuration-file calls of the iDEABOX examples (L611, L625) and the iDEABOX ``...Mx`` forms
(``CardNo`` first, L3825), as a mixin of :class:`~servobench.dialects.gts.GtsController`.

Behaviour stays the Card's (alarm enable, limit enable and polarity, stops); what the kernel does not hold (stop
decelerations, stop inputs, the filter windows and their history, the GPI levels and polarity, the jog smoothing)
is the card's GUC/iDEABOX module (``_core.gts_card(card.kernel)``, ``vendor/googol/gts_card.hpp``), which checks
the stop inputs and records the velocity history at the end of every tick. Units: pulse, ms, pulse/ms,
pulse/ms^2; axes from 1. Decisions GS1-GS18 (docs/decisions.md, Session 10), GT11-GT13 (Session 11)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import _core
from ._controller import GOOGOL_COMMAND_ERROR, GOOGOL_COMM_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_SUCCESS

# Digital input types of GT_GetDi / GT_SetStopIo (GUC L253-266): MC_GPI 4, MC_ARRIVE 5 (GTS-400-PX, L259).
MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI, MC_ARRIVE = 0, 1, 2, 3, 4, 5
# GT_FollowSwitchNowEx methods (iDEABOX L5427-5429).
FOLLOW_SWITCH_SEGMENT, FOLLOW_SWITCH_TABLE = 1, 2

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


class GtsConfigMixin:
    """System configuration, velocity filters, read-backs and the Mx forms (see the module docstring)."""

    def _gts(self):
        """The open card's GUC/iDEABOX module (its registers: stop decelerations and inputs, filters, GPI...)."""
        return _core.gts_card(self._card.kernel)

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
        self._gts().set_inputs(int(bits))

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
        return self._gts().set_gpi_sense(sense)

    def GT_GetDi(self, diType):
        """(rtn, input word): MC_LIMIT_POSITIVE / MC_LIMIT_NEGATIVE bit k = the limit of axis k+1 triggers,
        MC_ALARM bit k = drive alarm of axis k+1, MC_GPI bit k = GPI k+1 after GT_GpiSns (GUC L206, L267-276).
        MC_HOME / MC_ARRIVE: 1 (not wired in the simulated machine, decision GS6)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR, 0
        if diType not in (MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI, MC_ARRIVE):
            return GOOGOL_PARAMETER_ERROR, 0
        word = self._gts().input_word(diType)
        return (GOOGOL_COMMAND_ERROR, 0) if word is None else (GOOGOL_SUCCESS, word)

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
        return self._gts().set_stop_dec(profile, decSmoothStop, decAbruptStop)

    def GT_GetStopDec(self, profile):
        """(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 set by GT_SetStopDec; (0, 0) before (GUC L204,
        L244-247)."""
        if not self._ok_axis(profile):
            return self._code(), 0.0, 0.0
        return (GOOGOL_SUCCESS,) + tuple(self._gts().stop_dec(int(profile) - 1))

    def GT_GetCrdStopDec(self, crd):
        """(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 of ``crd`` 1..2 set by GT_SetCrdStopDec; (0, 0) before
        (GUC L362, L710-712; iDEABOX L5551-5560)."""
        if self._card is None or not _int_in(crd, 1, 2):
            return self._code(), 0.0, 0.0
        return (GOOGOL_SUCCESS,) + tuple(self._gts().crd_stop_dec(int(crd)))

    def GT_SetStopIo(self, axis, stopType, inputType, inputIndex) -> int:
        """Maps an input to a stop of ``axis`` 1..8: stopType 0 emergency / 1 smooth; inputType MC_LIMIT_POSITIVE,
        MC_LIMIT_NEGATIVE, MC_ALARM (index 1..8), MC_GPI (index 1..16) (GUC L205, L248-266). While the input is
        active the axis stops at its GT_SetStopDec decelerations (checked every tick, decision GS8). MC_HOME /
        MC_ARRIVE: 1 (not wired, GS6)."""
        if not self._ok_axis(axis) or not _int_in(axis, 1, 8):
            return self._code()
        return self._gts().set_stop_io(axis, stopType, inputType, inputIndex)

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
        smooth = self._gts().jog_smooth(a)
        acc = self._card.staged(a)["acc"] / self._ms ** 2
        return GOOGOL_SUCCESS, TJogPrmExt(acc=acc, dec=acc, smooth=smooth)

    # -- iDEABOX velocity filters (§4.5 L3773-3801) ---------------------------------------------------------------
    def GT_SetAxisPrfVelFilter(self, axis, filterNumExp) -> int:
        """Profile-velocity filter of ``axis``: window 2^filterNumExp ticks, filterNumExp 0..7 (iDEABOX L3801,
        L7075-7091). GT_GetPrfVel then reads the mean over that window (decision GS9)."""
        return self._gts().set_prf_vel_filter(axis, filterNumExp) if self._ok_axis(axis) else self._code()

    def GT_GetAxisPrfVelFilter(self, axis):
        """(rtn, filterNumExp) of the profile-velocity filter, 0 by default (iDEABOX L5474-5495)."""
        if not self._ok_axis(axis):
            return self._code(), 0
        return GOOGOL_SUCCESS, self._gts().prf_vel_filter(int(axis) - 1)

    def GT_SetAxisEncVelFilter(self, axis, filterNumExp) -> int:
        """Encoder-velocity filter of ``axis``: window 2^filterNumExp ticks, 0..7 (iDEABOX L3793-3797,
        L7056-7071). GT_GetEncVel then reads the mean over that window (GS9)."""
        return self._gts().set_enc_vel_filter(axis, filterNumExp) if self._ok_axis(axis) else self._code()

    def GT_GetAxisEncVelFilter(self, axis):
        """(rtn, filterNumExp) of the encoder-velocity filter, 0 by default (iDEABOX L5450-5470)."""
        if not self._ok_axis(axis):
            return self._code(), 0
        return GOOGOL_SUCCESS, self._gts().enc_vel_filter(int(axis) - 1)

    def GT_GetEncVel(self, axis, count=1):
        """(rtn, encoder velocity, pulse/ms): the actual-position change over the last 2^n ticks / 2^n
        (n = GT_SetAxisEncVelFilter, 0 = one tick). The history starts at the first velocity-filter setting or
        GT_GetEncVel call (before two samples it reads 0; decision GS9)."""
        if not self._ok_axis(axis):
            return self._code(), 0.0
        a = int(axis) - 1
        return self._get(lambda: self._gts().filtered_enc_vel(a))

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
