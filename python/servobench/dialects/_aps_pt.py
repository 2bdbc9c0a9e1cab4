"""The ADLINK point tables (PCI-8254/8258 manual §4.10.6, seed 004 L3794-3911): the APS_pt_* functions of
:class:`~servobench.dialects.aps.ApsController` (mixed in), decisions AF5-AF12.

A point table is a buffered continuous interpolation of a fixed axis array: the dialect translates it onto the
card's ADLINK interpolation group (``Card.aps_interp``, vendor/adlink/adlink_group.hpp), hosted with 50 pending
points (L3796) and flagged as a point table (MTS PTB while it runs, L3656). The moves go in with the table's own
motion parameters (the _all form: the speeds of APS_pt_set_vm/ve/acc/dec/s) and its transition mode
(APS_pt_set_trans_*: the card's modes 4-7 of L3117-3143); the first point holds the group (MF_WAIT) until
APS_pt_start. Instruction commands (APS_pt_ext_set_do_ch / _table_no) ride on the next movement command and take
effect when that move starts. Units: pulse, pulse/s, pulse/s^2, ms (PTDWL.DwTime), degrees (arcs).

The tables, their buffer bookkeeping and the instruction commands are the C++ module's
(cpp/include/servobench/vendor/adlink/aps_point_table.hpp, decisions AW1-AW3); this module holds the manual's structs
and the APS_pt_* functions made from the module's command table (name, arguments, what the manual says) with the
module call of each.
"""

from __future__ import annotations

import ast
import inspect
import math
from dataclasses import dataclass, field

from .. import _core
from .._core import ApsPtKind as K, ApsPtSpeed as S, ApsPtTransition as T
from ._aps_constants import ERR_DeviceNotInitial, MAX_PT_DIM


@dataclass
class PTSTS:
    """Point-table status (APS type_def.h): ``BitSts`` b0 the table moves, b1 its buffer is full (L3901), b2 it
    is empty; ``PntBufFreeSpace`` / ``PntBufUsageSpace`` points (of 50) free / holding a move not yet finished;
    ``RunningCnt`` the moves started since APS_pt_enable."""
    BitSts: int = 0
    PntBufFreeSpace: int = 0
    PntBufUsageSpace: int = 0
    RunningCnt: int = 0


@dataclass
class PTLINE:
    """A point-table line (L3904-3907): ``Dim`` axes (the table's dimension), end point ``Pos`` (pulse; relative
    after APS_pt_set_relative)."""
    Dim: int = 0
    Pos: list = field(default_factory=lambda: [0.0] * MAX_PT_DIM)


@dataclass
class PTA2CA:
    """A 2-D arc about ``Center`` by ``Angle`` degrees (+ CCW) on the table axes ``Index`` (L2978 geometry)."""
    Index: list = field(default_factory=lambda: [0, 1])
    Center: list = field(default_factory=lambda: [0.0, 0.0])
    Angle: float = 0.0


@dataclass
class PTA2CE:
    """A 2-D arc about ``Center`` to ``End``, ``Dir`` extra laps (L2943-2958)."""
    Index: list = field(default_factory=lambda: [0, 1])
    Center: list = field(default_factory=lambda: [0.0, 0.0])
    End: list = field(default_factory=lambda: [0.0, 0.0])
    Dir: int = 0


@dataclass
class PTHCA:
    """A spiral about ``Center``/``Normal`` by ``Angle`` degrees, rising ``DeltaH``, radius to ``FinalR``
    (L3001-3035)."""
    Index: list = field(default_factory=lambda: [0, 1, 2])
    Center: list = field(default_factory=lambda: [0.0, 0.0, 0.0])
    Normal: list = field(default_factory=lambda: [0.0, 0.0, 1.0])
    Angle: float = 0.0
    DeltaH: float = 0.0
    FinalR: float = 0.0


@dataclass
class PTHCE:
    """A spiral about ``Center``/``Normal`` to ``End``, ``Dir`` extra laps (L3037-3063)."""
    Index: list = field(default_factory=lambda: [0, 1, 2])
    Center: list = field(default_factory=lambda: [0.0, 0.0, 0.0])
    Normal: list = field(default_factory=lambda: [0.0, 0.0, 1.0])
    End: list = field(default_factory=lambda: [0.0, 0.0, 0.0])
    Dir: int = 0


@dataclass
class PTDWL:
    """A dwell: the table holds its position ``DwTime`` ms (L3838)."""
    DwTime: float = 0.0


def _f(v) -> float:
    """A vendor argument as a number (NaN when it is none: the module returns ERR_ParametersInvalid for it)."""
    try:
        return float(v)
    except (TypeError, ValueError, OverflowError):
        return math.nan


def _v(v) -> list:
    """A vendor array argument as numbers ([NaN] when it is not a sequence)."""
    try:
        return [_f(x) for x in v]
    except TypeError:
        return [math.nan]


def _push(kind, **fields):
    """The module call of a movement command: the struct's fields (``module keyword -> struct field``)."""
    vec = {"index", "pos", "center", "normal"}
    return lambda pt, b, p, prof: pt.push(b, p, kind, **{k: (_v if k in vec else _f)(getattr(prof, f, None))
                                                          for k, f in fields.items()})


_ARC2 = {"index": "Index", "center": "Center"}
_HELIX = {"index": "Index", "center": "Center", "normal": "Normal"}
# The APS_pt_* functions (manual §4.10.6, L3794-3911): manual name -> the ApsPointTables call with (module, board,
# ptb, *the arguments after Board_ID/PtbId). Their arguments and what they do are the C++ table's
# (vendor/adlink/aps_point_table.cpp pt_commands, _core.APS_PT_COMMANDS): written once, beside the code (AW7).
_CALLS = {
    "APS_pt_enable": lambda pt, b, p, d, arr: pt.enable(b, p, _f(d), _v(arr)),
    "APS_pt_disable": lambda pt, b, p: pt.disable(b, p),
    "APS_get_pt_status": lambda pt, b, p: pt.status(b, p),
    "APS_pt_start": lambda pt, b, p, r: pt.start(b, p, 0.0 if r is None else _f(r)),
    "APS_pt_stop": lambda pt, b, p: pt.stop(b, p),
    "APS_pt_set_absolute": lambda pt, b, p: pt.set_relative(b, p, False),
    "APS_pt_set_relative": lambda pt, b, p: pt.set_relative(b, p, True),
    "APS_pt_set_vm": lambda pt, b, p, v: pt.set_speed(b, p, S.VM, _f(v)),
    "APS_pt_set_ve": lambda pt, b, p, v: pt.set_speed(b, p, S.VE, _f(v)),
    "APS_pt_set_acc": lambda pt, b, p, v: pt.set_speed(b, p, S.ACC, _f(v)),
    "APS_pt_set_dec": lambda pt, b, p, v: pt.set_speed(b, p, S.DEC, _f(v)),
    "APS_pt_set_acc_dec": lambda pt, b, p, v: pt.set_speed(b, p, S.ACC_DEC, _f(v)),
    "APS_pt_set_s": lambda pt, b, p, v: pt.set_speed(b, p, S.SF, _f(v)),
    "APS_pt_set_trans_buffered": lambda pt, b, p: pt.set_transition(b, p, T.BUFFERED),
    "APS_pt_set_trans_inp": lambda pt, b, p: pt.set_transition(b, p, T.IN_POSITION),
    "APS_pt_set_trans_blend_dec": lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_DEC, _f(v)),
    "APS_pt_set_trans_blend_dist": lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_DIST, _f(v)),
    "APS_pt_set_trans_blend_pctn": lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_PCNT, _f(v)),
    "APS_pt_ext_set_do_ch": lambda pt, b, p, ch, on: pt.ext_set_do(b, p, _f(ch), _f(on)),
    "APS_pt_ext_set_table_no": lambda pt, b, p, c, n: pt.ext_set_table(b, p, _f(c), _f(n)),
    "APS_pt_line": _push(K.LINE, dim="Dim", pos="Pos"),
    "APS_pt_arc2_ca": _push(K.ARC2_CA, **_ARC2, angle_deg="Angle"),
    "APS_pt_arc2_ce": _push(K.ARC2_CE, **_ARC2, pos="End", dir="Dir"),
    "APS_pt_sprial_ca": _push(K.SPIRAL_CA, **_HELIX, angle_deg="Angle", delta_h="DeltaH", final_r="FinalR"),
    "APS_pt_sprial_ce": _push(K.SPIRAL_CE, **_HELIX, pos="End", dir="Dir"),
    "APS_pt_dwell": _push(K.DWELL, dw_time_ms="DwTime"),
}


def _param(text: str) -> inspect.Parameter:
    """``"Name"``, ``"Name=0.0"`` or ``"Name: TYPE"`` as a parameter (the annotation kept as the text it was)."""
    P = inspect.Parameter
    name, _, default = text.partition("=")
    name, _, ann = name.partition(": ")
    return P(name, P.POSITIONAL_OR_KEYWORD, **({"default": ast.literal_eval(default)} if default else {}),
             **({"annotation": ann} if ann else {}))


def _adapter(name: str, args: str, doc: str):
    """One ApsController method of a command of the C++ table: the manual's signature, one call of _CALLS[name]; a
    command whose first argument is ``Prof`` (a struct) or APS_get_pt_status returns ``(rtn, PTSTS)``."""
    args = tuple(a.strip() for a in args.split(",") if a.strip())
    call = _CALLS[name]
    params = [_param(t) for t in ("self", "Board_ID", "PtbId", *args)]
    status = name == "APS_get_pt_status" or (args and args[0].startswith("Prof"))
    sig = inspect.Signature(params, **({} if status else {"return_annotation": "int"}))

    def method(*a, **kw):
        bound = sig.bind(*a, **kw)
        bound.apply_defaults()
        self, b, p, *rest = bound.arguments.values()
        if self._card is None:
            return (ERR_DeviceNotInitial, PTSTS()) if status else ERR_DeviceNotInitial
        r = call(_core.aps_point_tables(self._card.kernel), _f(b), _f(p), *rest)
        return (r[0], PTSTS(*r[1])) if status else r

    method.__name__ = method.__qualname__ = name
    method.__signature__ = sig  # type: ignore[attr-defined]
    method.__annotations__ = {} if status else {"return": "int"}
    method.__doc__ = doc
    return method


class _ApsPointTable:
    """The APS_pt_* functions of :class:`~servobench.dialects.aps.ApsController` (mixed in), made from the table."""


for _name, _args, _doc in _core.APS_PT_COMMANDS:
    setattr(_ApsPointTable, _name, _adapter(_name, _args, _doc))
