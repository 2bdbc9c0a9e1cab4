"""The Googol GUC-ECAT / iDEABOX advanced functions (GUC-ECAT manual seed 002, iDEABOX manual seed 003) on the
virtual :class:`~servobench.Card`: coordinate systems with FIFO0/FIFO1, buffered commands and look-ahead, PVT
tables, the FollowEx cam, and the basic calls their example programs use.

Vendor names and argument order (the ``CardNo`` argument of the iDEABOX ``...Mx`` forms is left out, as in the
GUC-ECAT library); axes/profiles from 1, crd 1..2, fifo 0..1; units pulse, ms, pulse/ms, pulse/ms^2. Every call
returns the manuals' code (GUC Tab 2-1 L165-180, iDEABOX Table 3-1 L333-361): 0 success, 1 command error (the
card refused it in its present state; nothing changed), 7 parameter error, -1 no card open, -6 the card is
already open. A read call returns a tuple ``(rtn, value...)``.

This module only translates: it generates one method per row of the C++ command table (``_core.gts_command_table()``,
``vendor/googol/gts_commands.hpp``: the manual's name, the parameters, the docstring), whose adapter is the C++ runner
``_core.gts_command`` or, for a struct or array argument, a one-line call of its C++ vendor function; the argument
checks and the codes are C++'s, the behaviour (FIFOs, look-ahead, PVT and cam engines, safety) the Card's. The servo
tick is the clock, ms converted with its period. The configuration adapters and ``...Mx`` forms are in
``_gts_config.py``, the GUC motion program (threads on the card) in ``_gts_program.py`` (mixins of
:class:`GtsController`); :data:`UNSUPPORTED` names the calls the simulation cannot carry out.

Quick use (GUC L802-843, the hexagon)::

    import servobench as sb
    from servobench.dialects import gts

    gts.GT_Open(sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=1e-3))
    gts.GT_AxisOn(1); gts.GT_AxisOn(2)
    gts.GT_SetCrdPrm(1, gts.TCrdPrm(dimension=2, profile=[1, 2], synVelMax=500, synAccMax=1))
    gts.GT_LnXY(1, 200000, 0, 100, 0.1)
    gts.GT_CrdStart(1, 0)
    gts.wait_until(lambda: gts.GT_CrdStatus(1)[1] == 0)
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import _core
from ..card import Card
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401
from ._gts_config import (CONFIG_ADAPTERS, FOLLOW_SWITCH_SEGMENT, FOLLOW_SWITCH_TABLE, MC_ARRIVE,  # noqa: F401
                          UNSUPPORTED_CONFIG, GtsConfigMixin, TJogPrmExt, TTrapPrm, _f, _nums, attach_mx_forms)
from ._gt_system import gt_adapter
from ._gts_program import UNSUPPORTED_PROGRAM, GtsProgramMixin, TCompileInfo, TThreadSts, TVarInfo  # noqa: F401

# Return codes (GUC Tab 2-1 L165-180; iDEABOX Table 3-1 L333-361).
RTN_SUCCESS = 0
RTN_COMMAND_ERROR = 1
RTN_LICENSE_ERROR = 2
RTN_PARAMETER_ERROR = 7
RTN_COMM_ERROR = -1
RTN_OPEN_ERROR = -6

# Buffered IO types (GUC L588-597; gts.h MC_ENABLE 10, MC_CLEAR 11, MC_GPO 12).
MC_ENABLE, MC_CLEAR, MC_GPO = 10, 11, 12
# Limit and stop-input types (GUC L253-266, L638-645).
MC_LIMIT_POSITIVE, MC_LIMIT_NEGATIVE, MC_ALARM, MC_HOME, MC_GPI = 0, 1, 2, 3, 4
# FollowEx (iDEABOX L516-542, L7345-7363).
FOLLOW_SEGMENT_NORMAL, FOLLOW_SEGMENT_EVEN, FOLLOW_SEGMENT_STOP, FOLLOW_SEGMENT_CONTINUE = 0, 1, 2, 3
FOLLOW_MASTER_ENCODER, FOLLOW_MASTER_PROFILE, FOLLOW_MASTER_AXIS = 1, 2, 3
FOLLOW_EVENT_START, FOLLOW_EVENT_PASS = 1, 2


@dataclass
class TCrdPrm:
    """TCrdPrm (GUC L371-388, iDEABOX L7113-7164): dimension 1..4; profile[k] = coordinate (1 X .. 4 A, 0 none)
    of profile k+1; synVelMax (0, 32767) pulse/ms; synAccMax (0, 32767) pulse/ms^2; evenTime [0, 32767) ms;
    setOriginFlag 0 (origin = present profile positions) / 1 (origin = originPos, pulse)."""

    dimension: int = 2
    profile: list = field(default_factory=lambda: [0] * 8)
    synVelMax: float = 0.0
    synAccMax: float = 0.0
    evenTime: int = 0
    setOriginFlag: int = 0
    originPos: list = field(default_factory=lambda: [0] * 8)


class GtsController(GtsConfigMixin, GtsProgramMixin, DialectController):
    """One GUC-ECAT / iDEABOX program's view of a :class:`~servobench.Card` (its advanced functions)."""

    def _do(self, fn, *args) -> int:
        return self._googol_do(fn, *args)

    def GT_Open(self, card: Card | None = None, **axis_parts) -> int:
        """Opens the controller: ``card``, else the machine :meth:`use_machine` set (issue 25.2), else a new
        8-axis :class:`~servobench.Card` from ``axis_parts`` (GUC 8 axes, L250). A second open without close
        returns -6 (GUC L176)."""
        if self._card is not None:
            return RTN_OPEN_ERROR
        if card is None and not axis_parts:
            card = self._machine_card()
        self._card = card if card is not None else Card(8, **axis_parts)
        return RTN_SUCCESS

    def GT_Close(self) -> int:
        """Closes the controller."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._close_program()
        self._card = None
        return RTN_SUCCESS

    def GT_Reset(self) -> int:
        """Resets the controller (card reset: no crd, PVT or cam, drives off); the motion-program threads stop
        (the downloaded program stays until power-off, GUC L2245)."""
        if self._card is not None:
            self._close_program()
        return self._do(lambda: self._card.reset())


def _vec(x) -> np.ndarray:
    """A manual's array argument as float64 values; a non-numeric one as no values (count then exceeds it: 7)."""
    try:
        return np.asarray(x, dtype=float).ravel()
    except (TypeError, ValueError):
        return np.empty(0)


def _crd_args(p) -> list:
    """A TCrdPrm's fields as the C++ call takes them (a missing field as NaN / no values: 7)."""
    return [_f(getattr(p, "dimension", None)), _vec(getattr(p, "profile", ())),
            *(_f(getattr(p, n, None)) for n in ("synVelMax", "synAccMax", "evenTime", "setOriginFlag")),
            _vec(getattr(p, "originPos", ()))]


def _trap(acc, dec, vel_start, smooth_time):
    """(acc, dec, velStart, smoothTime) of scalars or of a TTrapPrm passed as ``acc``; dec None = acc (V61)."""
    if isinstance(acc, TTrapPrm):
        return acc.acc, acc.dec, acc.velStart, acc.smoothTime
    return acc, acc if dec is None else dec, vel_start, smooth_time


def _jog(acc, dec, smooth):
    """(acc, dec, smooth) of scalars or of a TJogPrmExt passed as ``acc`` (its dec 0 = acc)."""
    if isinstance(acc, TJogPrmExt):
        acc, dec, smooth = acc.acc, (acc.dec or None), acc.smooth
    return acc, acc if dec is None else dec, smooth


def _crd_prm(rtn, *fields):
    """GT_GetCrdPrm's (rtn, TCrdPrm); (1, 0) when the crd is not set up, (7 or -1, None) for a bad call."""
    return (rtn, TCrdPrm(*fields)) if rtn == 0 else (rtn, 0 if rtn == RTN_COMMAND_ERROR else None)


# -- the adapters whose arguments are structs or arrays: one call of the C++ vendor function (gts_commands.hpp) --------
_ADAPTERS = {
    **CONFIG_ADAPTERS,
    "GT_SetTrapPrm": lambda k, p, acc, dec, vs, st: _core.gts_set_trap_prm(k, *_nums(p, *_trap(acc, dec, vs, st))),
    "GT_SetJogPrm": lambda k, p, acc, dec, sm: _core.gts_set_jog_prm(k, *_nums(p, *_jog(acc, dec, sm))),
    "GT_Stop": lambda k, m, o: _core.gts_stop(k, *_nums(m, o)),
    "GT_SetCrdPrm": lambda k, crd, p: _core.gts_set_crd_prm(k, _f(crd), *_crd_args(p)),
    "GT_GetCrdPrm": lambda k, crd: _crd_prm(*_core.gts_get_crd_prm(k, _f(crd))),
    "GT_InitLookAhead": lambda k, crd, f, t, a, n, buf: _core.gts_init_lookahead(k, *_nums(crd, f, t, a, n)),
    "GT_CrdData": lambda k, crd, d, f: _core.gts_crd_data(k, _f(crd), d in (None, 0), _f(f)),
    "GT_PvtTable": lambda k, i, n, t, p, v: _core.gts_pvt_table(k, _f(i), _f(n), _vec(t), _vec(p), _vec(v)),
    "GT_PvtTableEx": lambda k, i, n, t, p, vb, ve: _core.gts_pvt_table_ex(k, _f(i), _f(n), *map(_vec, (t, p, vb, ve))),
    "GT_PvtTableComplete": lambda k, i, n, t, p, pa, pb, pc, vb, ve: _core.gts_pvt_table_complete(
        k, _f(i), _f(n), _vec(t), _vec(p), _f(vb), _f(ve)),
    "GT_PvtTablePercent": lambda k, i, n, t, p, q, vb: _core.gts_pvt_table_percent(
        k, _f(i), _f(n), _vec(t), _vec(p), _vec(q), _f(vb)),
    "GT_PvtTableContinuous": lambda k, i, n, p, v, q, vm, a, d, tb: _core.gts_pvt_table_continuous(
        k, _f(i), _f(n), *map(_vec, (p, v, q, q, vm, a, d)), _f(tb), False),
    "GT_PvtTableContinuousEx": lambda k, i, n, p, v, qa, qd, vm, a, d, tb: _core.gts_pvt_table_continuous(
        k, _f(i), _f(n), *map(_vec, (p, v, qa, qd, vm, a, d)), _f(tb), True),
    "GT_FollowDataCompleteEx": lambda k, p, f, n, ms, ss, pa, pb, pc, vb, ve: _core.gts_follow_data_complete(
        k, *_nums(p, f, n), _vec(ms), _vec(ss), *_nums(vb, ve)),
}
# The two PVT calculations need no card: they compute, nothing is downloaded.
_HOST = {
    "GT_PvtPercentCalculate": lambda n, t, p, q, vb: tuple(_core.gts_pvt_percent_calculate(
        _f(n), _vec(t), _vec(p), _vec(q), _f(vb))),
    "GT_PvtContinuousCalculate": lambda n, p, v, q, vm, a, d: tuple(_core.gts_pvt_continuous_calculate(
        _f(n), *map(_vec, (p, v, q, vm, a, d)))),
}


def _method(name, params, fail, doc):
    """The method of one row of the C++ table: -1 without a card (a read: -1 and its placeholders ``fail``), else
    its adapter, the C++ runner ``_core.gts_command`` unless ``_ADAPTERS`` / ``_HOST`` has one (a failing read of
    the runner: its code and the placeholders)."""
    fail = ast.literal_eval(fail) if fail else None
    call = _ADAPTERS.get(name, lambda k, *a: _core.gts_command(k, name, _nums(*a)))

    def body(self, *args):
        if name in _HOST:
            return _HOST[name](*args)
        if self._card is None:
            return RTN_COMM_ERROR if fail is None else (RTN_COMM_ERROR, *fail)
        r = call(self._card.kernel, *args)
        return r if fail is None or isinstance(r, tuple) else (r, *fail)

    return gt_adapter(name, params, body, doc, "int" if fail is None else None, "GtsController",
                      "servobench.dialects.gts")


_TABLE = _core.gts_command_table()
for _name, _params, _fail, _doc in _TABLE:  # the generator: one method per row of the C++ table
    setattr(GtsController, _name, _method(_name, _params, _fail, _doc))
assert {row[0] for row in _TABLE} <= set(_ADAPTERS) | set(_HOST) | set(_core.gts_command_names())


attach_mx_forms(GtsController)

#: Calls the simulation cannot carry out: defined, they return the manual's code; name -> reason.
UNSUPPORTED: dict[str, str] = {**UNSUPPORTED_CONFIG, **UNSUPPORTED_PROGRAM}

_default = GtsController()
GTS_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "GT_")


def __getattr__(name: str) -> Any:
    """Only for type checkers (PEP 562): the ``GT_*`` functions, ``use_machine`` ... are generated into this module
    by :func:`export_functions`, so mypy cannot list them; a program's ``from servobench.dialects.gts import
    GT_Open`` type-checks through this hook. At run time a missing name is an AttributeError as usual."""
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def set_inputs(bits: int) -> None:
    """The simulated levels of the general inputs GPI 1..16 of the open card (:meth:`GtsController.set_inputs`)."""
    _default.set_inputs(bits)

__all__ = ["GtsController", "GTS_FUNCTIONS", "TCrdPrm", "TTrapPrm", "TJogPrmExt", "TVarInfo", "TThreadSts",
           "TCompileInfo", "UNSUPPORTED", "MC_ARRIVE", "FOLLOW_SWITCH_SEGMENT", "FOLLOW_SWITCH_TABLE", "use_machine",
           "RTN_SUCCESS", "RTN_COMMAND_ERROR", "RTN_LICENSE_ERROR",
           "RTN_PARAMETER_ERROR", "RTN_COMM_ERROR", "RTN_OPEN_ERROR", "MC_ENABLE", "MC_CLEAR", "MC_GPO",
           "MC_LIMIT_POSITIVE", "MC_LIMIT_NEGATIVE", "MC_ALARM", "MC_HOME", "MC_GPI", "FOLLOW_SEGMENT_NORMAL",
           "FOLLOW_SEGMENT_EVEN", "FOLLOW_SEGMENT_STOP", "FOLLOW_SEGMENT_CONTINUE", "FOLLOW_MASTER_ENCODER",
           "FOLLOW_MASTER_PROFILE", "FOLLOW_MASTER_AXIS", "FOLLOW_EVENT_START", "FOLLOW_EVENT_PASS", "card",
           "controller", "run", "wait_until", "set_inputs", *GTS_FUNCTIONS]
