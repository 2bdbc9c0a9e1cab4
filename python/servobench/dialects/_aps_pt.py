"""The ADLINK point tables (PCI-8254/8258 manual §4.10.6, seed 004 L3794-3911): the APS_pt_* functions of
:class:`~servobench.dialects.aps.ApsController` (mixed in), decisions AF5-AF12.

A point table is a buffered continuous interpolation of a fixed axis array: the dialect translates it onto the
card's ADLINK interpolation group (``Card.aps_interp``, vendor/adlink/adlink_group.hpp), hosted with 50 pending
points (L3796) and flagged as a point table (MTS PTB while it runs, L3656). The moves go in with the table's own
motion parameters (the _all form: the speeds of APS_pt_set_vm/ve/acc/dec/s) and its transition mode
(APS_pt_set_trans_*: the card's modes 4-7 of L3117-3143); the first point holds the group (MF_WAIT) until
APS_pt_start. Instruction commands (APS_pt_ext_set_do_ch / _table_no) ride on the next movement command and take
effect when that move starts. Units: pulse, pulse/s, pulse/s^2, ms (PTDWL.DwTime), degrees (arcs).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .._core import AdlinkPtp, BlendMode, CardCommandRefused, MotionCommandRefused

ERR_NoError, ERR_DeviceNotInitial, ERR_ParametersInvalid, ERR_FunctionNotAvailable = 0, -4, -10, -13
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


def _num(v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) else None


def _floats(values, n):
    """The first n values as floats, or None."""
    try:
        out = [_num(x) for x in list(values)[:n]]
    except TypeError:
        return None
    return out if len(out) == n and None not in out else None


class _Table:
    """What the program memory keeps for one point table (L3808-3811): its axes and the parameters the next
    movement commands use."""

    def __init__(self, axes, params):
        self.axes = axes
        self.relative = False
        self.vm, self.ve = params.vm, 0.0
        self.acc, self.dec, self.sf = params.acc, params.dec, params.sf
        self.mode, self.blend = BlendMode.BUFFERED, 0.0
        self.last_ve = 0.0         # the VE the previous move ends with: the next one starts at it (AF7)
        self.ext: list = []        # instruction commands waiting for the next movement command
        self.started = False       # APS_pt_start given
        self.base = 0              # moves started in the groups hosted before the present one
        self.pushed = 0            # moves pushed into the present group
        self.actions: dict = {}    # move index (in the present group) -> instruction commands
        self.applied = 0           # moves whose instruction commands were carried out


class _ApsPointTable:
    """The APS_pt_* functions of :class:`~servobench.dialects.aps.ApsController` (mixed in)."""

    def _pt_init(self):
        self._pt: dict[int, _Table] = {}

    def _pt_get(self, Board_ID, PtbId):
        """(table id, _Table) of an enabled table, or an error code."""
        if self._card is None:
            return ERR_DeviceNotInitial
        if _num(Board_ID) != 0 or _num(PtbId) not in (0, 1):
            return ERR_ParametersInvalid
        t = self._pt.get(int(PtbId))
        return ERR_FunctionNotAvailable if t is None else (int(PtbId), t)

    def _pt_group(self, t: _Table):
        """The card's interpolation group info when it is this table's, else None."""
        info = self._card.aps_interp_info()
        if info["set_up"] and info["point_table"] and list(info["array"]) == t.axes:
            return info
        return None

    def _pt_sync(self, t: _Table):
        """Carries out the instruction commands of the moves that have started (they take effect with their
        move, L3824-3829)."""
        info = self._pt_group(t)
        started = 0 if info is None else int(info["moves_done"]) + int(info["running"])
        while t.applied < started:
            for kind, a, b in t.actions.pop(t.applied, ()):
                if kind == "do":
                    self._outs().set_do_bit(a, bool(b))
                else:
                    self._outs().select_vao(a, b)
            t.applied += 1
        return info, started

    def APS_pt_enable(self, Board_ID, PtbId, Dimension, AxisArr) -> int:
        """``APS_pt_enable(Board_ID, PtbId, Dimension, I32 *AxisArr)`` (L3856): table 0..1 on ``Dimension``
        (2..6) axes, the first the reference axis; its speeds start as that axis's PRA_VM/ACC/DEC/SF (AF6), the
        mode absolute and buffered. The card has one interpolation group: a second table, or a table on axes
        that are moving, is refused (ERR_FunctionNotAvailable, AF5)."""
        if self._card is None:
            return ERR_DeviceNotInitial
        d = _num(Dimension)
        if _num(Board_ID) != 0 or _num(PtbId) not in (0, 1) or d is None or d != int(d) or not 2 <= d <= MAX_PT_DIM:
            return ERR_ParametersInvalid
        try:
            axes = [self._axis(a) for a in list(AxisArr)[: int(d)]]
        except TypeError:
            return ERR_ParametersInvalid
        if len(axes) != d or None in axes or len(set(axes)) != len(axes):
            return ERR_ParametersInvalid
        if self._pt or any(self._card.moving(a) for a in axes):
            return ERR_FunctionNotAvailable
        self._pt[int(PtbId)] = _Table(axes, self._prm().motion(axes[0]))
        return ERR_NoError

    def APS_pt_disable(self, Board_ID, PtbId) -> int:
        """``APS_pt_disable(Board_ID, PtbId)`` (L3860): ends the table (refused while it moves: stop it first);
        its axes return to single-axis motion."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        pid, t = r
        info = self._pt_group(t)
        if info is not None and info["busy"] and not info["waiting"]:
            return ERR_FunctionNotAvailable
        if info is not None:
            if info["busy"]:
                self._card.group_stop(3, True)   # points not started are dropped
            self._card.set_mode(t.axes[0], "t_curve")
        del self._pt[pid]
        return ERR_NoError

    def APS_get_pt_status(self, Board_ID, PtbId):
        """``APS_get_pt_status(Board_ID, PtbId, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3867, L3899-3901)."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r, PTSTS()
        return ERR_NoError, self._pt_status(r[1])

    def _pt_status(self, t: _Table) -> PTSTS:
        info, started = self._pt_sync(t)
        used = 0 if info is None else int(info["pending"]) + int(info["running"])
        working = info is not None and info["busy"] and not info["waiting"]
        bits = (PTB_WORKING if working else 0) | (PTB_FULL if used >= PT_BUFFER_POINTS else 0) | \
            (PTB_EMPTY if used == 0 else 0)
        return PTSTS(bits, PT_BUFFER_POINTS - used, used, t.base + started)

    def APS_pt_start(self, Board_ID, PtbId, Reserved=0) -> int:
        """``APS_pt_start(Board_ID, PtbId)`` (L3874; the example passes a third argument 0, L3910: only 0 is
        accepted): starts executing the points in sequence (L3870-3872); points pushed later run as they come."""
        if Reserved not in (0, None):
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        t = r[1]
        t.started = True
        info = self._pt_group(t)
        if info is not None and info["waiting"]:
            self._card.aps_interp_trigger(1 << t.axes[0])
        return ERR_NoError

    def APS_pt_stop(self, Board_ID, PtbId) -> int:
        """``APS_pt_stop(Board_ID, PtbId)`` (L3875): the table decelerates to rest along its path at the reference
        axis's PRA_SD_DEC; the points not started are dropped."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        t = r[1]
        t.started = False
        info = self._pt_group(t)
        if info is not None and info["busy"]:
            self._pt_sync(t)
            self._card.group_stop(3, bool(info["waiting"]))
        return ERR_NoError

    # -- movement parameters (L3808-3820), kept for the next movement commands --------------------------------
    def _pt_set(self, Board_ID, PtbId, **kv) -> int:
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        for k, v in kv.items():
            setattr(r[1], k, v)
        return ERR_NoError

    def _pt_speed(self, Board_ID, PtbId, value, lo, hi, *fields) -> int:
        v = _num(value)
        if v is None or not lo <= v <= hi:
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        return self._pt_set(Board_ID, PtbId, **{f: v for f in fields})

    def APS_pt_set_absolute(self, Board_ID, PtbId) -> int:
        """``APS_pt_set_absolute(Board_ID, PtbId)``: the next points are absolute positions (pulse)."""
        return self._pt_set(Board_ID, PtbId, relative=False)

    def APS_pt_set_relative(self, Board_ID, PtbId) -> int:
        """``APS_pt_set_relative(Board_ID, PtbId)``: the next points are relative to the previous end point."""
        return self._pt_set(Board_ID, PtbId, relative=True)

    def APS_pt_set_vm(self, Board_ID, PtbId, Vm) -> int:
        """``APS_pt_set_vm(Board_ID, PtbId, F64 Vm)``: maximum (vector) speed of the next points, pulse/s, > 0."""
        if _num(Vm) == 0:
            return ERR_ParametersInvalid
        return self._pt_speed(Board_ID, PtbId, Vm, 0.0, 1e9, "vm")

    def APS_pt_set_ve(self, Board_ID, PtbId, Ve) -> int:
        """``APS_pt_set_ve(Board_ID, PtbId, F64 Ve)``: the speed the next points end with, pulse/s (the point
        after starts at it, AF7)."""
        return self._pt_speed(Board_ID, PtbId, Ve, 0.0, 1e9, "ve")

    def APS_pt_set_acc(self, Board_ID, PtbId, Acc) -> int:
        """``APS_pt_set_acc(Board_ID, PtbId, F64 Acc)``: acceleration of the next points, pulse/s^2 (> 0)."""
        return self._pt_speed(Board_ID, PtbId, Acc, 1e-9, 1e12, "acc")

    def APS_pt_set_dec(self, Board_ID, PtbId, Dec) -> int:
        """``APS_pt_set_dec(Board_ID, PtbId, F64 Dec)``: deceleration of the next points, pulse/s^2 (> 0)."""
        return self._pt_speed(Board_ID, PtbId, Dec, 1e-9, 1e12, "dec")

    def APS_pt_set_acc_dec(self, Board_ID, PtbId, AccDec) -> int:
        """``APS_pt_set_acc_dec(Board_ID, PtbId, F64 AccDec)``: acceleration and deceleration at once."""
        return self._pt_speed(Board_ID, PtbId, AccDec, 1e-9, 1e12, "acc", "dec")

    def APS_pt_set_s(self, Board_ID, PtbId, Sf) -> int:
        """``APS_pt_set_s(Board_ID, PtbId, F64 Sf)``: S-factor 0..1 of the next points (L2211-2236)."""
        return self._pt_speed(Board_ID, PtbId, Sf, 0.0, 1.0, "sf")

    def APS_pt_set_trans_buffered(self, Board_ID, PtbId) -> int:
        """``APS_pt_set_trans_buffered(Board_ID, PtbId)``: each next point starts when the one before has ended,
        with its own speeds (transition mode 4, L3117-3122)."""
        return self._pt_set(Board_ID, PtbId, mode=BlendMode.BUFFERED, blend=0.0)

    def APS_pt_set_trans_inp(self, Board_ID, PtbId) -> int:
        """``APS_pt_set_trans_inp(Board_ID, PtbId)``: buffered with an in-position wait between points. The card's
        interpolation has no in-position transition (its modes are L3085-3143's seven): ERR_FunctionNotAvailable,
        the mode unchanged (AF8)."""
        r = self._pt_get(Board_ID, PtbId)
        return r if isinstance(r, int) else ERR_FunctionNotAvailable

    def APS_pt_set_trans_blend_dec(self, Board_ID, PtbId, Bp) -> int:
        """``APS_pt_set_trans_blend_dec(Board_ID, PtbId, F64 Bp)``: the next point starts when the one before
        starts decelerating (mode 5, L3124-3129). Mode 5 has no parameter (the blend is set by the deceleration,
        L3126): Bp must be a finite number >= 0 and does not change the motion (AF9)."""
        b = _num(Bp)
        if b is None or b < 0:
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        return self._pt_set(Board_ID, PtbId, mode=BlendMode.BLEND_DECEL, blend=0.0)

    def APS_pt_set_trans_blend_dist(self, Board_ID, PtbId, Bp) -> int:
        """``APS_pt_set_trans_blend_dist(Board_ID, PtbId, F64 Bp)``: the next point starts when the remaining path
        of the one before is < Bp pulse (> 0; mode 6, L3131-3136)."""
        b = _num(Bp)
        if b is None or not 0 < b <= 1e12:
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        return self._pt_set(Board_ID, PtbId, mode=BlendMode.BLEND_DISTANCE, blend=b)

    def APS_pt_set_trans_blend_pctn(self, Board_ID, PtbId, Bp) -> int:
        """``APS_pt_set_trans_blend_pctn(Board_ID, PtbId, F64 Bp)`` (the manual's spelling, L3820; the library's
        ``_pcnt``): the next point starts when the remaining path of the one before is < Bp % of its length
        (0 < Bp < 100; mode 7, L3138-3143)."""
        b = _num(Bp)
        if b is None or not 0 < b < 100:
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        return self._pt_set(Board_ID, PtbId, mode=BlendMode.BLEND_PERCENT, blend=b)

    # -- instruction commands (L3822-3829) ----------------------------------------------------------------------
    def APS_pt_ext_set_do_ch(self, Board_ID, PtbId, Channel, OnOff) -> int:
        """``APS_pt_ext_set_do_ch(Board_ID, PtbId, Channel, OnOff)``: digital output ``Channel`` (0..7) goes on (1)
        or off (0) when the next movement command starts (L3824-3827; read with APS_read_d_output)."""
        ch, on = _num(Channel), _num(OnOff)
        if ch not in range(8) or on not in (0, 1):
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        r[1].ext.append(("do", int(ch), int(on)))
        return ERR_NoError

    def APS_pt_ext_set_table_no(self, Board_ID, PtbId, CtrlNo, TableNo) -> int:
        """``APS_pt_ext_set_table_no(Board_ID, PtbId, CtrlNo, TableNo)``: VAO controller ``CtrlNo`` (0..1)
        switches to VAO table ``TableNo`` (0..7) when the next movement command starts (L3828, L3446)."""
        c, n = _num(CtrlNo), _num(TableNo)
        if c not in (0, 1) or n not in range(8):
            return ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        r[1].ext.append(("vao", int(c), int(n)))
        return ERR_NoError

    # -- movement commands (L3831-3838) -------------------------------------------------------------------------
    def _pt_push(self, Board_ID, PtbId, kind, **geom):
        """Pushes one movement command; returns (rtn, PTSTS)."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r, PTSTS()
        _pid, t = r
        st = self._pt_status(t)
        if st.BitSts & PTB_FULL:
            return ERR_FunctionNotAvailable, st   # the buffer is full (L3880; check BitSts b1 first, L3901)
        c = self._card
        info = self._pt_group(t)
        if info is None or not info["busy"]:     # the table ran dry or has not begun: a new group holds it
            if info is not None:
                t.base += t.pushed
            t.pushed, t.applied, t.actions = 0, 0, {}
            t.last_ve = 0.0
            for a in t.axes:
                self._release_limits(a)          # an idle group hands its axes back first (V116)
        first = t.pushed == 0
        dwell = kind == "dwell"
        ve = 0.0 if dwell else t.ve
        vs = 0.0 if first else min(t.last_ve, t.vm)
        try:
            speeds = AdlinkPtp(vs=vs, vm=t.vm, ve=min(ve, t.vm), acc=t.acc, dec=t.dec, sf=t.sf,
                               sd_dec=self._prm().motion(t.axes[0]).sd_dec)
            params = [self._params(a) for a in t.axes]
            c.aps_interp(t.axes, params, kind, relative=t.relative and not dwell, mode=t.mode, blend=t.blend,
                         vm=t.vm, all=speeds, wait=first and not t.started, buffer_size=PT_BUFFER_POINTS,
                         point_table=True, **geom)
        except (CardCommandRefused, MotionCommandRefused):
            return ERR_FunctionNotAvailable, self._pt_status(t)
        except ValueError:
            return ERR_ParametersInvalid, self._pt_status(t)
        t.actions[t.pushed] = t.ext
        t.ext = []
        t.pushed += 1
        t.last_ve = 0.0 if dwell else min(ve, t.vm)
        return ERR_NoError, self._pt_status(t)

    def _pt_index(self, Board_ID, PtbId, index, n):
        """The table's axis order check of an arc/spiral: Index must be 0..n-1 in order on an n-axis table (the
        card's 2-D arcs and 3-D spirals run on the first axes of the array, AF10); an error code or None."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r
        try:
            idx = [int(x) for x in list(index)]
        except (TypeError, ValueError):
            return ERR_ParametersInvalid
        if idx[:n] != list(range(n)) or len(r[1].axes) != n:
            return ERR_FunctionNotAvailable
        return None

    def APS_pt_line(self, Board_ID, PtbId, Prof: PTLINE):
        """``APS_pt_line(Board_ID, PtbId, PTLINE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3835, L3903-3907):
        a line to ``Prof.Pos`` (``Prof.Dim`` = the table's dimension)."""
        r = self._pt_get(Board_ID, PtbId)
        if isinstance(r, int):
            return r, PTSTS()
        d = _num(getattr(Prof, "Dim", None))
        pos = _floats(getattr(Prof, "Pos", ()), len(r[1].axes))
        if d != len(r[1].axes) or pos is None:
            return ERR_ParametersInvalid, self._pt_status(r[1])
        return self._pt_push(Board_ID, PtbId, "line", target=pos)

    def APS_pt_arc2_ca(self, Board_ID, PtbId, Prof: PTA2CA):
        """``APS_pt_arc2_ca(Board_ID, PtbId, PTA2CA *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a 2-D arc
        about ``Prof.Center`` by ``Prof.Angle`` degrees."""
        bad = self._pt_index(Board_ID, PtbId, getattr(Prof, "Index", ()), 2)
        ctr, ang = _floats(getattr(Prof, "Center", ()), 2), _num(getattr(Prof, "Angle", None))
        if bad is not None or ctr is None or ang is None:
            return (bad if bad is not None else ERR_ParametersInvalid), PTSTS()
        return self._pt_push(Board_ID, PtbId, "arc2_ca", center=ctr, angle_deg=ang)

    def APS_pt_arc2_ce(self, Board_ID, PtbId, Prof: PTA2CE):
        """``APS_pt_arc2_ce(Board_ID, PtbId, PTA2CE *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3836): a 2-D arc
        about ``Prof.Center`` to ``Prof.End`` (``Prof.Dir`` laps, L2943-2958)."""
        bad = self._pt_index(Board_ID, PtbId, getattr(Prof, "Index", ()), 2)
        ctr, end = _floats(getattr(Prof, "Center", ()), 2), _floats(getattr(Prof, "End", ()), 2)
        d = _num(getattr(Prof, "Dir", None))
        if bad is not None or ctr is None or end is None or d is None or d != int(d) or abs(d) > 32767:
            return (bad if bad is not None else ERR_ParametersInvalid), PTSTS()
        return self._pt_push(Board_ID, PtbId, "arc2_ce", center=ctr, target=end, dir=int(d))

    def APS_pt_sprial_ca(self, Board_ID, PtbId, Prof: PTHCA):
        """``APS_pt_sprial_ca(Board_ID, PtbId, PTHCA *Prof, PTSTS *Status)`` (the manual's spelling, L3837) ->
        ``(rtn, PTSTS)``: a spiral of a 3-axis table (L3001-3035)."""
        bad = self._pt_index(Board_ID, PtbId, getattr(Prof, "Index", ()), 3)
        ctr, nrm = _floats(getattr(Prof, "Center", ()), 3), _floats(getattr(Prof, "Normal", ()), 3)
        vals = [_num(getattr(Prof, k, None)) for k in ("Angle", "DeltaH", "FinalR")]
        if bad is not None or ctr is None or nrm is None or None in vals:
            return (bad if bad is not None else ERR_ParametersInvalid), PTSTS()
        return self._pt_push(Board_ID, PtbId, "spiral_ca", center=ctr, normal=nrm, angle_deg=vals[0],
                             height=vals[1], final_radius=vals[2])

    def APS_pt_sprial_ce(self, Board_ID, PtbId, Prof: PTHCE):
        """``APS_pt_sprial_ce(Board_ID, PtbId, PTHCE *Prof, PTSTS *Status)`` (L3837) -> ``(rtn, PTSTS)``: a spiral
        to ``Prof.End`` (L3037-3063)."""
        bad = self._pt_index(Board_ID, PtbId, getattr(Prof, "Index", ()), 3)
        ctr, nrm = _floats(getattr(Prof, "Center", ()), 3), _floats(getattr(Prof, "Normal", ()), 3)
        end, d = _floats(getattr(Prof, "End", ()), 3), _num(getattr(Prof, "Dir", None))
        if bad is not None or None in (ctr, nrm, end, d) or d != int(d) or abs(d) > 32767:
            return (bad if bad is not None else ERR_ParametersInvalid), PTSTS()
        return self._pt_push(Board_ID, PtbId, "spiral_ce", center=ctr, normal=nrm, target=end, dir=int(d))

    def APS_pt_dwell(self, Board_ID, PtbId, Prof: PTDWL):
        """``APS_pt_dwell(Board_ID, PtbId, PTDWL *Prof, PTSTS *Status)`` -> ``(rtn, PTSTS)`` (L3838): the table
        holds its position ``Prof.DwTime`` ms (> 0, whole motion cycles) after the moves before it have ended;
        the next point starts after it."""
        ms = _num(getattr(Prof, "DwTime", None))
        if ms is None or not 0 < ms <= 1e9:
            return (ERR_ParametersInvalid if self._card is not None else ERR_DeviceNotInitial), PTSTS()
        return self._pt_push(Board_ID, PtbId, "dwell", dwell_s=ms * 1e-3)
