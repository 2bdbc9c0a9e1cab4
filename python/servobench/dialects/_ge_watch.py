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

from .. import _core

RTN_SUCCESS, RTN_COMMAND_ERROR, RTN_PARAMETER_ERROR, RTN_COMM_ERROR = 0, 1, 7, -1
WATCH_PRF_POS, WATCH_ATL_POS, WATCH_PRF_VEL, WATCH_ATL_VEL, WATCH_VOLTAGE = 0x1, 0x2, 0x4, 0x8, 0x40
#: The watch memory in values (samples x watched signals, all axes): V75 (GeWatch::kWatchMemoryValues).
WATCH_MEMORY_VALUES = int(_core.GeWatch.WATCH_MEMORY_VALUES)
# config bit -> the TAxis field the block's channel is copied into (the watch itself: vendor/googol/ge_watch.hpp)
_FIELDS = {0: "PrfPos", 1: "AtlPos", 2: "PrfVel", 3: "AtlVel", 6: "Voltage"}


def _num(value) -> float:
    """An argument as the double C++ takes: a bool or a non-number is NaN (the watch answers 7)."""
    try:
        return float("nan") if isinstance(value, bool) else float(value)
    except (TypeError, ValueError):
        return float("nan")


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


def GT_SetWatch(ctl, config, size) -> int:
    """Selects the watched signals (one word per axis, Table 10-2) and the block size (samples); 7 if a reserved
    bit is set, the size is not a whole number >= 1 or the block exceeds the watch memory (L2784-2793)."""
    if ctl.card is None:
        return RTN_COMM_ERROR
    try:
        words, n = [float(int(w)) for w in config], float(size)
    except (TypeError, ValueError):
        return RTN_PARAMETER_ERROR
    return _core.ge_watch(ctl.card.kernel).set_watch(words, n)


def GT_StartWatch(ctl, n=0) -> int:
    """Starts watching: one sample every ``n + 1`` control periods, n = 0..65535 (L2878-2880; V74)."""
    return RTN_COMM_ERROR if ctl.card is None else _core.ge_watch(ctl.card.kernel).start(_num(n))


def GT_GetWatch(ctl, buffer):
    """(rtn, available): copies the oldest full block into ``buffer``'s attached arrays and returns available 1;
    0 when no block is full yet (L2836-2870); 7 when a watched signal has no array of ``size`` elements."""
    if ctl.card is None:
        return RTN_COMM_ERROR, 0
    watch = _core.ge_watch(ctl.card.kernel)
    axes = buffer.Axis
    arrays = [getattr(axes[k], _FIELDS[bit], None) if k < len(axes) else None for k, bit in watch.channels()]
    if any(arr is None or len(arr) < watch.size() for arr in arrays):
        return RTN_PARAMETER_ERROR, 0
    rtn, block = watch.next_block()
    for arr, values in zip(arrays, block or ()):
        arr[:len(values)] = values
    return rtn, int(block is not None)


def GT_StopWatch(ctl) -> int:
    """Stops watching (L2882); blocks not read are dropped."""
    return RTN_COMM_ERROR if ctl.card is None else _core.ge_watch(ctl.card.kernel).stop() or RTN_SUCCESS


GE_WATCH_FUNCTIONS = ("GT_SetWatch", "GT_StartWatch", "GT_GetWatch", "GT_StopWatch")
