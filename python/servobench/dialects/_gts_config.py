"""The GUC-ECAT system configuration calls (GUC §3.1 L185-300), the iDEABOX velocity filters (§4.5 L3773-3801,
L5450-5495, L7056-7091), the read-backs (GT_GetTrapPrm, GT_GetJogPrm, GT_GetStopDec, GT_GetCrdStopDec), the
EtherCAT / configuration-file calls of the iDEABOX examples (L611, L625) and the iDEABOX ``...Mx`` forms
(``CardNo`` first, L3825), as a mixin of :class:`~servobench.dialects.gts.GtsController`.

Each command is a one-line adapter (``CONFIG_ADAPTERS``) over a C++ vendor function that checks its arguments and
returns the manual's code (``vendor/googol/gts_config.hpp``, ``_core.gts_*``); its row (parameters, docstring) is the
C++ command table's (``gts_commands.hpp``, generated into the controller by ``gts.py``); what the kernel does not
hold (stop decelerations and inputs, the filter windows and their history, the GPI levels and polarity, the jog
smoothing) is the card's GtsCard (``_core.gts_card(card.kernel)``, ``gts_card.hpp``). Units: pulse, ms, pulse/ms,
pulse/ms^2; axes from 1. Decisions GS1-GS18 (docs/decisions.md, Session 10), GT11-GT13 (Session 11), GU1-GU7
(Session 12), GX1-GX2 (Session 13)."""

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


# -- the adapters: the C++ vendor function of each command (gts_config.hpp; the rows, with their parameters and
# docstrings, are the C++ table's, gts_commands.hpp) -------------------------------------------------------------
CONFIG_ADAPTERS = {
    "GT_AlarmOn": lambda k, a: _core.gts_alarm(k, _f(a), True),
    "GT_AlarmOff": lambda k, a: _core.gts_alarm(k, _f(a), False),
    "GT_LmtsOn": lambda k, a, t: _core.gts_limits(k, *_nums(a, t), True),
    "GT_LmtsOff": lambda k, a, t: _core.gts_limits(k, *_nums(a, t), False),
    "GT_LmtSns": lambda k, s: _core.gts_limit_sense(k, _f(s)),
    "GT_EncSns": lambda k, s: _core.gts_enc_sense(k, _f(s)),
    "GT_ProfileScale": lambda k, a, al, be: _core.gts_scale(k, *_nums(a, al, be)),
    "GT_EncScale": lambda k, a, al, be: _core.gts_scale(k, *_nums(a, al, be)),
    "GT_GpiSns": lambda k, s: _core.gts_card(k).set_gpi_sense(_f(s)),
    "GT_GetDi": lambda k, t: tuple(_core.gts_get_di(k, _f(t))),
    "GT_SetAdcFilter": lambda k, a, t: _core.gts_set_adc_filter(k, *_nums(a, t)),
    "GT_SetStopDec": lambda k, p, s, a: _core.gts_card(k).set_stop_dec(*_nums(p, s, a)),
    "GT_GetStopDec": lambda k, p: tuple(_core.gts_get_stop_dec(k, _f(p))),
    "GT_GetCrdStopDec": lambda k, c: tuple(_core.gts_get_crd_stop_dec(k, _f(c))),
    "GT_SetStopIo": lambda k, a, st, it, ix: _core.gts_set_stop_io(k, *_nums(a, st, it, ix)),
    "GT_GetTrapPrm": lambda k, p: _trap_prm(*_core.gts_get_acc(k, _f(p))),
    "GT_GetJogPrm": lambda k, p: _jog_prm(*_core.gts_get_acc(k, _f(p))),
    "GT_SetAxisPrfVelFilter": lambda k, a, e: _core.gts_card(k).set_prf_vel_filter(*_nums(a, e)),
    "GT_GetAxisPrfVelFilter": lambda k, a: tuple(_core.gts_get_vel_filter(k, _f(a), False)),
    "GT_SetAxisEncVelFilter": lambda k, a, e: _core.gts_card(k).set_enc_vel_filter(*_nums(a, e)),
    "GT_GetAxisEncVelFilter": lambda k, a: tuple(_core.gts_get_vel_filter(k, _f(a), True)),
    "GT_GetEncVel": lambda k, a, n: tuple(_core.gts_get_enc_vel(k, _f(a))),
    "GT_IsEcatReady": lambda k: (GOOGOL_SUCCESS, 1),
    "GT_LoadConfig": lambda k, path: GOOGOL_COMMAND_ERROR if isinstance(path, (str, bytes)) and path
    else GOOGOL_PARAMETER_ERROR,
}


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
