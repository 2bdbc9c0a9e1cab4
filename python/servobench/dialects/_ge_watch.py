"""The GE series data watch (GE manual seed 001, §10.1, L2464-2884; digest ge.md §6.6) on the card's sampler.

Functions taking the GE controller (any :class:`~servobench.dialects._controller.DialectController` with a card
open; axis words numbered from axis 1 as the manual's ``config[AXIS_NUM]``), for the GE dialect to wrap:

* ``GT_SetWatch(ctl, config, size)``: ``config[k]`` the signals of axis k+1 (Table 10-2: bit 0 profile position,
  1 actual position, 2 profile velocity, 3 actual velocity, 6 control voltage; bits 4, 5, 7 reserved), ``size``
  samples per block; returns 7 when the block is too large for the watch memory (L2793; V75) or a bit is reserved.
* ``GT_StartWatch(ctl, n)``: starts, one sample every n+1 control periods (``StartWatch(0)``: every period,
  L2558-2559; V74); blocks of ``size`` samples follow each other without a gap.
* ``GT_GetWatch(ctl, buffer)`` -> ``(rtn, available)``: ``available = 1`` when a full block was copied into the
  arrays attached to ``buffer`` (a :class:`TWatchBuffer`), the oldest block first (L2836-2870); a watched
  signal without an attached array returns 7 (the card would fault, L2828).
* ``GT_StopWatch(ctl)``.

Units are the GE's: position pulse (``long``), velocity pulse/ms (``double``), control voltage DAC counts
(``short``, +10 V = 32767, L5331-5337). Return codes: 0, 1 (command error: GetWatch/StartWatch before SetWatch),
7 (parameter error), -1 (no card open).
"""

from __future__ import annotations

import numpy as np

RTN_SUCCESS, RTN_COMMAND_ERROR, RTN_PARAMETER_ERROR, RTN_COMM_ERROR = 0, 1, 7, -1

from .. import _core

WATCH_PRF_POS, WATCH_ATL_POS, WATCH_PRF_VEL, WATCH_ATL_VEL, WATCH_VOLTAGE = 0x1, 0x2, 0x4, 0x8, 0x40
#: The watch memory in values (samples x watched signals, all axes): V75 (GeRegisters::kWatchMemoryValues).
WATCH_MEMORY_VALUES = 32768
# config bit -> (TAxis field, sampler signal, dtype): the table from the manual's word to the card's sampler
_BITS = {0: ("PrfPos", "pos", np.int64), 1: ("AtlPos", "actual_pos", np.int64), 2: ("PrfVel", "prf_vel", np.float64),
         3: ("AtlVel", "fbk_vel", np.float64), 6: ("Voltage", "volts", np.int16)}


class TAxis:
    """One axis of a :class:`TWatchBuffer` (``TAxis {long *PrfPos; long *AtlPos; double *PrfVel; double *AtlVel;
    short *Voltage;}``): attach a NumPy array of at least ``size`` elements to each watched signal."""

    def __init__(self):
        self.PrfPos = None
        self.AtlPos = None
        self.PrfVel = None
        self.AtlVel = None
        self.Voltage = None


class TWatchBuffer:
    """``TWatchBuffer {TAxis Axis[AXIS_NUM];}``: ``buffer.Axis[k]`` for axis k+1."""

    def __init__(self, axis_num: int = 8):
        # The GE cards have at most 8 axes (AXIS_NUM, L2784); checked before allocating (issue 21.3).
        if isinstance(axis_num, bool) or not isinstance(axis_num, (int, float)) and not hasattr(axis_num, "__index__"):
            raise TypeError(f"TWatchBuffer.axis_num must be a whole number 1..8, got {type(axis_num).__name__}")
        if not (isinstance(axis_num, int) or float(axis_num).is_integer()) or not 1 <= axis_num <= 8:
            raise ValueError(f"TWatchBuffer.axis_num = {axis_num!r} is outside the allowed range 1..8 (AXIS_NUM)")
        self.Axis = [TAxis() for _ in range(int(axis_num))]


def _selection(card):
    """The watched channels [(axis, TAxis field, sampler signal, dtype)] and the block size: the card's GE registers
    module keeps the selection (vendor/googol/ge_registers.hpp, GT_SetWatch)."""
    regs = _core.ge_registers(card.kernel)
    return [(k, *_BITS[bit]) for k, bit in regs.watch_channels()], regs.watch_size()


def GT_SetWatch(ctl, config, size) -> int:
    """Selects the watched signals (one word per axis, Table 10-2) and the block size (samples); 7 if a reserved
    bit is set, the size is not a whole number >= 1 or the block exceeds the watch memory (L2784-2793)."""
    card = ctl.card
    if card is None:
        return RTN_COMM_ERROR
    try:
        words = [float(int(w)) for w in config]
        n = float(size)
    except (TypeError, ValueError):
        return RTN_PARAMETER_ERROR
    return _core.ge_registers(card.kernel).set_watch(words, n)


def GT_StartWatch(ctl, n=0) -> int:
    """Starts watching: one sample every ``n + 1`` control periods, n = 0..65535 (L2878-2880; V74)."""
    card = ctl.card
    if card is None:
        return RTN_COMM_ERROR
    channels, size = _selection(card)
    if not channels:
        return RTN_COMMAND_ERROR
    try:
        v = float(n)
    except (TypeError, ValueError):
        return RTN_PARAMETER_ERROR
    if v != int(v) or not 0 <= v <= 65535:
        return RTN_PARAMETER_ERROR
    card.sample([(k, sig) for k, _f, sig, _dt in channels], every_ticks=int(v) + 1, depth=size, continuous=True)
    return RTN_SUCCESS


def GT_GetWatch(ctl, buffer):
    """(rtn, available): copies the oldest full block into ``buffer``'s attached arrays and returns available 1;
    0 when no block is full yet (L2836-2870)."""
    card = ctl.card
    if card is None:
        return RTN_COMM_ERROR, 0
    channels, size = _selection(card)
    if not channels:
        return RTN_COMMAND_ERROR, 0
    for k, field, _sig, _dt in channels:
        arr = getattr(buffer.Axis[k], field, None) if k < len(buffer.Axis) else None
        if arr is None or len(arr) < size:
            return RTN_PARAMETER_ERROR, 0
    data = card.scope_data()
    if data is None:
        return RTN_SUCCESS, 0
    ms = card.servo_period_s * 1e3
    for c, (k, field, sig, dt) in enumerate(channels):
        v = data.values[:, c]
        if sig in ("prf_vel", "fbk_vel"):
            v = v / ms  # pulse/tick -> pulse/ms
        elif sig == "volts":
            v = np.clip(np.rint(v * 32767 / 10), -32768, 32767)
        else:
            v = np.rint(v)
        getattr(buffer.Axis[k], field)[:size] = v.astype(dt)
    return RTN_SUCCESS, 1


def GT_StopWatch(ctl) -> int:
    """Stops watching (L2882); blocks not read are dropped."""
    card = ctl.card
    if card is None:
        return RTN_COMM_ERROR
    card.kernel.sampler_stop()
    while card.scope_data() is not None:
        pass
    return RTN_SUCCESS


GE_WATCH_FUNCTIONS = ("GT_SetWatch", "GT_StartWatch", "GT_GetWatch", "GT_StopWatch")
