"""The GUC-ECAT system configuration calls (GUC §3.1 L185-300), the iDEABOX velocity filters (§4.5 L3773-3801,
L5450-5495, L7056-7091), the read-backs (GT_GetTrapPrm, GT_GetJogPrm, GT_GetStopDec, GT_GetCrdStopDec), the
EtherCAT / configuration-file calls of the iDEABOX examples (L611, L625) and the iDEABOX ``...Mx`` forms
(``CardNo`` first, L3825), as a mixin of :class:`~servobench.dialects.gts.GtsController`.

A table: each command is a row over a C++ vendor function that checks its arguments and returns the manual's code
(``vendor/googol/gts_config.hpp``, ``_core.gts_*``); what the kernel does not hold (stop decelerations and inputs,
the filter windows and their history, the GPI levels and polarity, the jog smoothing) is the card's GtsCard
(``_core.gts_card(card.kernel)``, ``gts_card.hpp``). Units: pulse, ms, pulse/ms, pulse/ms^2; axes from 1.
Decisions GS1-GS18 (docs/decisions.md, Session 10), GT11-GT13 (Session 11), GU1-GU7 (Session 12)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import _core
from ._controller import GOOGOL_COMMAND_ERROR, GOOGOL_COMM_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_SUCCESS
from ._gt_system import gt_adapter

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


def _f(v) -> float:
    """A manual argument as the double the C++ vendor functions take: a bool, a non-number or inf is NaN (out of
    every range: C++ returns 7)."""
    try:
        x = float(v)
    except (TypeError, ValueError):
        return math.nan
    return x if math.isfinite(x) else math.nan


def _nums(*values) -> list[float]:
    return [_f(v) for v in values]


def gts_row(name, params, call, doc, read=None):
    """A GTS command whose C++ vendor function (``vendor/googol/gts_commands.hpp``, ``gts_config.hpp``) checks
    its arguments and returns the manual's code: ``call(card kernel, *args)``; -1 without a card (a read: -1 and
    the placeholders ``read``)."""
    def body(self, *args):
        if self._card is None:
            return GOOGOL_COMM_ERROR if read is None else (GOOGOL_COMM_ERROR, *read)
        return call(self._card.kernel, *args)

    return gt_adapter(name, params, body, doc, "int" if read is None else None, "GtsController",
                      "servobench.dialects.gts")


def _trap_prm(rtn, acc, smooth):
    return (rtn, TTrapPrm(acc=acc, dec=acc)) if rtn == GOOGOL_SUCCESS else (rtn, None)


def _jog_prm(rtn, acc, smooth):
    return (rtn, TJogPrmExt(acc=acc, dec=acc, smooth=smooth)) if rtn == GOOGOL_SUCCESS else (rtn, None)


class GtsConfigMixin:
    """System configuration, velocity filters, read-backs and the Mx forms (see the module docstring)."""

    def _gts(self):
        """The open card's GUC/iDEABOX module (its registers: stop decelerations and inputs, filters, GPI...)."""
        return _core.gts_card(self._card.kernel)

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


# -- the table: name, parameters, the C++ vendor function (gts_config.hpp), the manual -----------------------------
_ROWS = [
    *[gts_row(f"GT_Alarm{w}", "axis", (lambda on: lambda k, a: _core.gts_alarm(k, _f(a), on))(on), doc)
      for w, on, doc in (("On", True, "The drive-alarm input of ``axis`` stops it and switches its drive off "
                                      "(default) (GUC L198, L215)."),
                         ("Off", False, "The drive-alarm input of ``axis`` is ignored (GUC L197, L213)."))],
    *[gts_row(f"GT_Lmts{w}", "axis, limitType=-1", (lambda on: lambda k, a, t: _core.gts_limits(k, *_nums(a, t), on))(on),
              doc) for w, on, doc in (
        ("On", True, "Limit switches of ``axis`` stop it (default): limitType MC_LIMIT_POSITIVE 0, MC_LIMIT_NEGATIVE "
                     "1, -1 both (GUC L199, L217-222). One side alone only when the other side is already in that "
                     "state (returns 1 otherwise, nothing changed: the card has one enable per axis, decision GS3)."),
        ("Off", False, "Limit switches of ``axis`` ignored (GUC L200, L223-228); one side alone as in GT_LmtsOn "
                       "(GS3)."))],
    gts_row("GT_LmtSns", "sense", lambda k, s: _core.gts_limit_sense(k, _f(s)),
            "Limit polarity, bit 2k axis k+1 positive, 2k+1 negative: 0 triggers on a high level (normally closed, "
            "default), 1 on a low level (GUC L294-305, Tab 3-4)."),
    gts_row("GT_EncSns", "sense", lambda k, s: _core.gts_enc_sense(k, _f(s)),
            "Encoder count direction, bit k = axis k+1 (bit 8 the auxiliary encoder), 1 = reversed (GUC L284-290, "
            "Tab 3-3). The simulated encoder counts the drive's positive direction as positive: 0 bits are "
            "accepted, a set bit returns 1 (reversing it would turn the closed loop into positive feedback; GS4)."),
    gts_row("GT_ProfileScale", "axis, alpha, beta", lambda k, a, al, be: _core.gts_scale(k, *_nums(a, al, be)),
            "Profile scale alpha/beta, each -32768..32767 (GUC L201, L232-235): 1:1 (alpha = beta) is the "
            "simulated axis; another ratio returns 1 (decision GS5)."),
    gts_row("GT_EncScale", "axis, alpha, beta", lambda k, a, al, be: _core.gts_scale(k, *_nums(a, al, be)),
            "Encoder scale alpha/beta (GUC L202, L236-239): as GT_ProfileScale (GS5)."),
    gts_row("GT_GpiSns", "sense", lambda k, s: _core.gts_card(k).set_gpi_sense(_f(s)),
            "General-input polarity, bit k = GPI k+1: 0 GT_GetDi reads the level, 1 the inverted level (GUC L206, "
            "L267-276)."),
    gts_row("GT_GetDi", "diType", lambda k, t: tuple(_core.gts_get_di(k, _f(t))),
            "(rtn, input word): MC_LIMIT_POSITIVE / MC_LIMIT_NEGATIVE bit k = the limit of axis k+1 triggers, "
            "MC_ALARM bit k = drive alarm of axis k+1, MC_GPI bit k = GPI k+1 after GT_GpiSns (GUC L206, "
            "L267-276). MC_HOME / MC_ARRIVE: 1 (not wired in the simulated machine, decision GS6).", (0,)),
    gts_row("GT_SetAdcFilter", "adc, filterTime", lambda k, a, t: _core.gts_set_adc_filter(k, *_nums(a, t)),
            "ADC input filter, adc 1..8, filterTime 1..50 (GUC L207, L278-280; GTS-400-PX only): the simulated "
            "card has no analog inputs: 1 (UNSUPPORTED); 7 for values out of range."),
    # stop decelerations and stop inputs
    gts_row("GT_SetStopDec", "profile, decSmoothStop, decAbruptStop",
            lambda k, p, s, a: _core.gts_card(k).set_stop_dec(*_nums(p, s, a)),
            "Stop decelerations of ``profile``, (0, 32767] pulse/ms^2 each (GUC L203, L240-243): GT_Stop "
            "decelerates a point-to-point or jog axis at decSmoothStop (smooth) or decAbruptStop (abrupt option "
            "bit) instead of its acc / at once (decision GS7)."),
    gts_row("GT_GetStopDec", "profile", lambda k, p: tuple(_core.gts_get_stop_dec(k, _f(p))),
            "(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 set by GT_SetStopDec; (0, 0) before (GUC L204, "
            "L244-247).", (0.0, 0.0)),
    gts_row("GT_GetCrdStopDec", "crd", lambda k, c: tuple(_core.gts_get_crd_stop_dec(k, _f(c))),
            "(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 of ``crd`` 1..2 set by GT_SetCrdStopDec; (0, 0) before "
            "(GUC L362, L710-712; iDEABOX L5551-5560).", (0.0, 0.0)),
    gts_row("GT_SetStopIo", "axis, stopType, inputType, inputIndex",
            lambda k, a, st, it, ix: _core.gts_set_stop_io(k, *_nums(a, st, it, ix)),
            "Maps an input to a stop of ``axis`` 1..8: stopType 0 emergency / 1 smooth; inputType "
            "MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM (index 1..8), MC_GPI (index 1..16) (GUC L205, "
            "L248-266). While the input is active the axis stops at its GT_SetStopDec decelerations (checked every "
            "tick, decision GS8). MC_HOME / MC_ARRIVE: 1 (not wired, GS6)."),
    # read-backs of the profile parameters
    gts_row("GT_GetTrapPrm", "profile", lambda k, p: _trap_prm(*_core.gts_get_acc(k, _f(p))),
            "(rtn, TTrapPrm): acc = dec = the staged acceleration (pulse/ms^2; one acceleration for both ramps, "
            "decision V61), velStart 0, smoothTime 0 (GUC basic library; the combined-motion example L2900 reads "
            "it).", (None,)),
    gts_row("GT_GetJogPrm", "profile", lambda k, p: _jog_prm(*_core.gts_get_acc(k, _f(p))),
            "(rtn, TJogPrmExt): acc = dec = the staged acceleration pulse/ms^2 (V61), smooth as set (iDEABOX Ex 4-1 "
            "L726).", (None,)),
    # iDEABOX velocity filters (§4.5 L3773-3801)
    gts_row("GT_SetAxisPrfVelFilter", "axis, filterNumExp",
            lambda k, a, e: _core.gts_card(k).set_prf_vel_filter(*_nums(a, e)),
            "Profile-velocity filter of ``axis``: window 2^filterNumExp ticks, filterNumExp 0..7 (iDEABOX L3801, "
            "L7075-7091). GT_GetPrfVel then reads the mean over that window (decision GS9)."),
    gts_row("GT_GetAxisPrfVelFilter", "axis", lambda k, a: tuple(_core.gts_get_vel_filter(k, _f(a), False)),
            "(rtn, filterNumExp) of the profile-velocity filter, 0 by default (iDEABOX L5474-5495).", (0,)),
    gts_row("GT_SetAxisEncVelFilter", "axis, filterNumExp",
            lambda k, a, e: _core.gts_card(k).set_enc_vel_filter(*_nums(a, e)),
            "Encoder-velocity filter of ``axis``: window 2^filterNumExp ticks, 0..7 (iDEABOX L3793-3797, "
            "L7056-7071). GT_GetEncVel then reads the mean over that window (GS9)."),
    gts_row("GT_GetAxisEncVelFilter", "axis", lambda k, a: tuple(_core.gts_get_vel_filter(k, _f(a), True)),
            "(rtn, filterNumExp) of the encoder-velocity filter, 0 by default (iDEABOX L5450-5470).", (0,)),
    gts_row("GT_GetEncVel", "axis, count=1", lambda k, a, n: tuple(_core.gts_get_enc_vel(k, _f(a))),
            "(rtn, encoder velocity, pulse/ms): the actual-position change over the last 2^n ticks / 2^n (n = "
            "GT_SetAxisEncVelFilter, 0 = one tick). The history starts at the first velocity-filter setting or "
            "GT_GetEncVel call (before two samples it reads 0; decision GS9).", (0.0,)),
    # iDEABOX EtherCAT and configuration file
    gts_row("GT_IsEcatReady", "", lambda k: (GOOGOL_SUCCESS, 1),
            "(rtn, status): 1 = the EtherCAT bus is configured and running (iDEABOX Ex 4-1 L611-615). The simulated "
            "bus is up as soon as the card is open (decision GS10).", (0,)),
    gts_row("GT_LoadConfig", "pCfgPath", lambda k, path: GOOGOL_COMMAND_ERROR if isinstance(path, (str, bytes))
            and path else GOOGOL_PARAMETER_ERROR,
            "Loads a configuration file (iDEABOX L625; './GTS800.cfg'): the file's format is not given in the "
            "manuals; the simulated machine's configuration is the Card it opens. Returns 1 (UNSUPPORTED, GS11)."),
]
for _fn in _ROWS:
    setattr(GtsConfigMixin, _fn.__name__, _fn)


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
