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
and the APS_pt_* functions as rows of a table: manual name, arguments, the module call, what the manual says.
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field

from .. import _core
from .._core import ApsPtKind as K, ApsPtSpeed as S, ApsPtTransition as T

ERR_DeviceNotInitial = -4
PT_BUFFER_POINTS = 50   # points per table (L3796, L3880)
PT_TABLES = 2           # table IDs 0..1 (L3796, L3858)
MAX_PT_DIM = 6          # APS type_def.h (PTLINE.Pos[6]); the card interpolates 2..6 axes (L2817)
PTB_WORKING, PTB_FULL, PTB_EMPTY = 0x1, 0x2, 0x4  # PTSTS.BitSts bits (the example tests 0x02 = full, L3901)


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
# The APS_pt_* functions (manual §4.10.6, L3794-3911) as rows: manual name -> (arguments after Board_ID, PtbId;
# the ApsPointTables call with (module, board, ptb, *arguments); what the manual says). A row whose first argument
# is ``Prof`` (a struct) or APS_get_pt_status returns ``(rtn, PTSTS)``, the others the code.
_ROWS = {
    "APS_pt_enable": (("Dimension", "AxisArr"), lambda pt, b, p, d, arr: pt.enable(b, p, _f(d), _v(arr)),
                      "``APS_pt_enable(Board_ID, PtbId, Dimension, I32 *AxisArr)`` (L3856): table 0..1 on ``Dimension`` "
                      "(2..6) axes, the first the reference axis; its speeds start as that axis's PRA_VM/ACC/DEC/SF "
                      "(AF6), the mode absolute and buffered. The card has one interpolation group: a second table, or "
                      "a table on axes that are moving, is refused (ERR_FunctionNotAvailable, AF5)."),
    "APS_pt_disable": ((), lambda pt, b, p: pt.disable(b, p),
                       "``APS_pt_disable(Board_ID, PtbId)`` (L3860): ends the table (refused while it moves: stop it "
                       "first); its axes return to single-axis motion."),
    "APS_get_pt_status": ((), lambda pt, b, p: pt.status(b, p),
                          "``APS_get_pt_status(Board_ID, PtbId, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3867, "
                          "L3899-3901)."),
    "APS_pt_start": (("Reserved=0",), lambda pt, b, p, r: pt.start(b, p, 0.0 if r is None else _f(r)),
                     "``APS_pt_start(Board_ID, PtbId)`` (L3874; the example passes a third argument 0, L3910: only 0 "
                     "is accepted): starts executing the points in sequence (L3870-3872); points pushed later run as "
                     "they come."),
    "APS_pt_stop": ((), lambda pt, b, p: pt.stop(b, p),
                    "``APS_pt_stop(Board_ID, PtbId)`` (L3875): the table decelerates to rest along its path at the "
                    "reference axis's PRA_SD_DEC; the points not started are dropped."),
    "APS_pt_set_absolute": ((), lambda pt, b, p: pt.set_relative(b, p, False),
                            "``APS_pt_set_absolute(Board_ID, PtbId)``: the next points are absolute positions (pulse)."),
    "APS_pt_set_relative": ((), lambda pt, b, p: pt.set_relative(b, p, True),
                            "``APS_pt_set_relative(Board_ID, PtbId)``: the next points are relative to the previous end "
                            "point."),
    "APS_pt_set_vm": (("Vm",), lambda pt, b, p, v: pt.set_speed(b, p, S.VM, _f(v)),
                      "``APS_pt_set_vm(Board_ID, PtbId, F64 Vm)``: maximum (vector) speed of the next points, pulse/s, "
                      "0 < Vm <= 1e9."),
    "APS_pt_set_ve": (("Ve",), lambda pt, b, p, v: pt.set_speed(b, p, S.VE, _f(v)),
                      "``APS_pt_set_ve(Board_ID, PtbId, F64 Ve)``: the speed the next points end with, pulse/s (the "
                      "point after starts at it, AF7)."),
    "APS_pt_set_acc": (("Acc",), lambda pt, b, p, v: pt.set_speed(b, p, S.ACC, _f(v)),
                       "``APS_pt_set_acc(Board_ID, PtbId, F64 Acc)``: acceleration of the next points, pulse/s^2 (> 0)."),
    "APS_pt_set_dec": (("Dec",), lambda pt, b, p, v: pt.set_speed(b, p, S.DEC, _f(v)),
                       "``APS_pt_set_dec(Board_ID, PtbId, F64 Dec)``: deceleration of the next points, pulse/s^2 (> 0)."),
    "APS_pt_set_acc_dec": (("AccDec",), lambda pt, b, p, v: pt.set_speed(b, p, S.ACC_DEC, _f(v)),
                           "``APS_pt_set_acc_dec(Board_ID, PtbId, F64 AccDec)``: acceleration and deceleration at once, "
                           "pulse/s^2."),
    "APS_pt_set_s": (("Sf",), lambda pt, b, p, v: pt.set_speed(b, p, S.SF, _f(v)),
                     "``APS_pt_set_s(Board_ID, PtbId, F64 Sf)``: S-factor 0..1 of the next points (L2211-2236)."),
    "APS_pt_set_trans_buffered": ((), lambda pt, b, p: pt.set_transition(b, p, T.BUFFERED),
                                  "``APS_pt_set_trans_buffered(Board_ID, PtbId)``: each next point starts when the one "
                                  "before has ended, with its own speeds (transition mode 4, L3117-3122)."),
    "APS_pt_set_trans_inp": ((), lambda pt, b, p: pt.set_transition(b, p, T.IN_POSITION),
                             "``APS_pt_set_trans_inp(Board_ID, PtbId)``: buffered with an in-position wait between "
                             "points. The card's interpolation has no in-position transition (its modes are "
                             "L3085-3143's seven): ERR_FunctionNotAvailable, the mode unchanged (AF8)."),
    "APS_pt_set_trans_blend_dec": (("Bp",), lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_DEC, _f(v)),
                                   "``APS_pt_set_trans_blend_dec(Board_ID, PtbId, F64 Bp)``: the next point starts when "
                                   "the one before starts decelerating (mode 5, L3124-3129). Mode 5 has no parameter "
                                   "(L3126): Bp must be a finite number >= 0 and does not change the motion (AF9)."),
    "APS_pt_set_trans_blend_dist": (("Bp",), lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_DIST, _f(v)),
                                    "``APS_pt_set_trans_blend_dist(Board_ID, PtbId, F64 Bp)``: the next point starts "
                                    "when the remaining path of the one before is < Bp pulse (> 0; mode 6, "
                                    "L3131-3136)."),
    "APS_pt_set_trans_blend_pctn": (("Bp",), lambda pt, b, p, v: pt.set_transition(b, p, T.BLEND_PCNT, _f(v)),
                                    "``APS_pt_set_trans_blend_pctn(Board_ID, PtbId, F64 Bp)`` (the manual's spelling, "
                                    "L3820; the library's ``_pcnt``): the next point starts when the remaining path of "
                                    "the one before is < Bp % of its length (0 < Bp < 100; mode 7, L3138-3143)."),
    "APS_pt_ext_set_do_ch": (("Channel", "OnOff"), lambda pt, b, p, ch, on: pt.ext_set_do(b, p, _f(ch), _f(on)),
                             "``APS_pt_ext_set_do_ch(Board_ID, PtbId, Channel, OnOff)``: digital output ``Channel`` "
                             "(0..7) goes on (1) or off (0) when the next movement command starts (L3824-3827; read "
                             "with APS_read_d_output)."),
    "APS_pt_ext_set_table_no": (("CtrlNo", "TableNo"),
                                lambda pt, b, p, c, n: pt.ext_set_table(b, p, _f(c), _f(n)),
                                "``APS_pt_ext_set_table_no(Board_ID, PtbId, CtrlNo, TableNo)``: VAO controller "
                                "``CtrlNo`` (0..1) switches to VAO table ``TableNo`` (0..7) when the next movement "
                                "command starts (L3828, L3446)."),
    "APS_pt_line": (("Prof: PTLINE",), _push(K.LINE, dim="Dim", pos="Pos"),
                    "``APS_pt_line(Board_ID, PtbId, PTLINE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3835, "
                    "L3903-3907): a line to ``Prof.Pos`` (pulse; ``Prof.Dim`` = the table's dimension). A full buffer "
                    "(50 points) returns ERR_FunctionNotAvailable (L3880)."),
    "APS_pt_arc2_ca": (("Prof: PTA2CA",), _push(K.ARC2_CA, **_ARC2, angle_deg="Angle"),
                       "``APS_pt_arc2_ca(Board_ID, PtbId, PTA2CA *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a "
                       "2-D arc about ``Prof.Center`` by ``Prof.Angle`` degrees (``Prof.Index`` 0, 1 on a 2-axis "
                       "table, AF10)."),
    "APS_pt_arc2_ce": (("Prof: PTA2CE",), _push(K.ARC2_CE, **_ARC2, pos="End", dir="Dir"),
                       "``APS_pt_arc2_ce(Board_ID, PtbId, PTA2CE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a "
                       "2-D arc about ``Prof.Center`` to ``Prof.End`` (``Prof.Dir`` laps, L2943-2958)."),
    "APS_pt_sprial_ca": (("Prof: PTHCA",), _push(K.SPIRAL_CA, **_HELIX, angle_deg="Angle", delta_h="DeltaH",
                                                   final_r="FinalR"),
                         "``APS_pt_sprial_ca(Board_ID, PtbId, PTHCA *Prof, PTSTS *Status)`` (the manual's spelling, "
                         "L3837) -> ``(rtn, PTSTS)``: a spiral of a 3-axis table (L3001-3035)."),
    "APS_pt_sprial_ce": (("Prof: PTHCE",), _push(K.SPIRAL_CE, **_HELIX, pos="End", dir="Dir"),
                         "``APS_pt_sprial_ce(Board_ID, PtbId, PTHCE *Prof, PTSTS *Status)`` (L3837) -> ``(rtn, PTSTS)``: "
                         "a spiral to ``Prof.End`` (L3037-3063)."),
    "APS_pt_dwell": (("Prof: PTDWL",), _push(K.DWELL, dw_time_ms="DwTime"),
                     "``APS_pt_dwell(Board_ID, PtbId, PTDWL *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3838): the "
                     "table holds its position ``Prof.DwTime`` ms (> 0, whole motion cycles) after the moves before "
                     "it have ended; the next point starts after it."),
}


def _param(text: str) -> inspect.Parameter:
    """``"Name"``, ``"Name=0"`` or ``"Name: TYPE"`` as a parameter (the annotation kept as the text it was)."""
    P = inspect.Parameter
    name, _, default = text.partition("=")
    name, _, ann = name.partition(": ")
    return P(name, P.POSITIONAL_OR_KEYWORD, **({"default": int(default)} if default else {}),
             **({"annotation": ann} if ann else {}))


def _adapter(name: str, args: tuple, call, doc: str):
    """One ApsController method of a _ROWS row: the manual's signature, one call of the C++ point tables."""
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
    """The APS_pt_* functions of :class:`~servobench.dialects.aps.ApsController` (mixed in), made from _ROWS."""


for _name, (_args, _call, _doc) in _ROWS.items():
    setattr(_ApsPointTable, _name, _adapter(_name, _args, _call, _doc))
