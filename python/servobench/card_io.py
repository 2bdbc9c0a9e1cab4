"""The machine's wiring of a card's general inputs and outputs (issue 25.3): what the servo loop does not carry but a
vendor program reads and writes -- the 16 general inputs and outputs, the analog inputs, the two auxiliary encoders,
the encoder-direction wiring, the ISA base-address jumper and the pulse-width output. The card kernel (C++) has
no register for them; they live here, one :class:`CardIO` per :class:`~servobench.Card`, and the dialects read
and write them (GT: ``GT_ExInpt``/``GT_ExOpt``, ``GT_GetAdc``, ``GT_EncPos``/``GT_EncVel``/``GT_SetEncCapt``,
``GT_EncSns``, ``GT_SetAddr``, ``GT_SetTime``; GT manual seed 000 ch9 L2514-2560, ch11).

A source the machine gives (an input word, a voltage, an encoder position) is a constant or a function of the
card's time ``t_s`` (s, = ticks x servo period), so the same program reads the same values every run::

    import servobench as sb
    from servobench import card_io
    card = sb.Card(4)
    io = card_io.of(card)
    io.inputs = lambda t_s: 0x8000 if t_s >= 0.5 else 0       # EXI15 goes high at 0.5 s
    io.adc_volts[1] = 2.5                                     # analog input 2: 2.5 V
    io.aux_encoders[0] = card_io.AuxEncoder(lambda t_s: 1000.0 * t_s, counts_per_index=4000)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Union

from . import _checks, _core

__all__ = ["AuxEncoder", "CardIO", "of"]

Source = Union[float, int, Callable[[float], float]]


@dataclass(frozen=True)
class AuxEncoder:
    """An auxiliary encoder input (GT: two, No. 1 and No. 2, L3241-3330).

    position
        the counts the encoder sees (pulse), a constant or a function of the card time ``t_s`` (s); the card
        reads whole counts (floor).
    counts_per_index
        counts between two index (C) marks, 0 = no index mark; the marks are where ``floor(position)`` crosses a
        multiple of it, measured from ``index_offset`` (pulse).
    index_offset
        the position of one index mark, pulse.
    """

    position: Source = 0.0
    counts_per_index: int = 0
    index_offset: float = 0.0

    def __post_init__(self):
        if not callable(self.position):
            _checks.real("AuxEncoder", "position", self.position, -2.0**31, 2.0**31, unit="pulse")
        if isinstance(self.counts_per_index, bool) or not isinstance(self.counts_per_index, int) \
                or not 0 <= self.counts_per_index <= 2**31:
            raise ValueError(f"AuxEncoder.counts_per_index = {self.counts_per_index!r} must be an integer in "
                             "0..2^31 (0 = no index mark)")
        _checks.real("AuxEncoder", "index_offset", self.index_offset, -2.0**31, 2.0**31, unit="pulse")

    def counts(self, t_s: float) -> int:
        """Whole counts at card time ``t_s`` (s)."""
        p = float(self.position(t_s)) if callable(self.position) else float(self.position)
        if not abs(p) < 2.0**62:
            raise ValueError(f"AuxEncoder.position({t_s}) = {p} is not a finite number of pulses within +-2^62")
        return math.floor(p)

    def index_between(self, a: int, b: int) -> int | None:
        """The index-mark count (pulse) reached moving from count ``a`` to count ``b`` (the first one, in the
        direction of travel), or None; the arithmetic is the card's (``vendor/googol/gt_aux_encoder.hpp``)."""
        return _core.aux_index_mark_between(a, b, self.counts_per_index, self.index_offset)


class CardIO:
    """The general I/O wiring of one card (see the module docstring). Attributes:

    inputs
        the levels of the general inputs EXI0..EXI15 (bit n = EXIn, 1 = high): an int 0..65535 or a function of
        ``t_s`` returning one.
    outputs
        EXO0..EXO15 as the card last wrote them (bit n = EXOn); the machine reads it.
    adc_volts
        8 analog inputs, V (-10..10 V): constants or functions of ``t_s``.
    aux_encoders
        2 :class:`AuxEncoder` (or None: nothing connected, reads 0).
    encoder_reversed
        the wiring of the encoders, bit k = axis k+1 (bits 0-3) / auxiliary encoder 1, 2 (bits 4, 5): 1 = the
        encoder counts against the motor's positive direction (GT L595-635: corrected with GT_EncSns).
    base_address
        the ISA base-address jumper, 0..0xFFFF (GT default 0x300, L552).
    pulse_width_s
        the width of the pulse output (GT_SetTime, CN7 pin 23), s, as the card last set it.
    spindle_volts
        the spindle's analog output (GE GT_SetSpindleVel / GT_CloseSpindle), V, as the card last set it.
    """

    def __init__(self):
        self.inputs: Source = 0
        self.outputs = 0
        self.adc_volts: list[Source] = [0.0] * 8
        self.aux_encoders: list[AuxEncoder | None] = [None, None]
        self.encoder_reversed = 0
        self.base_address = 0x300
        self.pulse_width_s = 0.0
        self.spindle_volts = 0.0

    def input_word(self, t_s: float) -> int:
        """EXI0..EXI15 at card time ``t_s`` (s)."""
        v = self.inputs(t_s) if callable(self.inputs) else self.inputs
        if isinstance(v, bool) or not isinstance(v, (int,)) or not 0 <= v <= 0xFFFF:
            raise ValueError(f"CardIO.inputs gave {v!r} at t = {t_s} s; it must be an int 0..65535 (EXI0..EXI15)")
        return int(v)

    def aux_counts(self, n: int, t_s: float) -> int:
        """Whole counts (pulse) of auxiliary encoder ``n`` (0 = No. 1, 1 = No. 2) at card time ``t_s`` (s); 0 when
        nothing is connected."""
        enc = self.aux_encoders[n]
        return 0 if enc is None else enc.counts(t_s)

    def volts(self, channel: int, t_s: float) -> float:
        """Analog input ``channel`` (0..7) at card time ``t_s`` (s), V."""
        src = self.adc_volts[channel]
        v = float(src(t_s)) if callable(src) else float(src)
        return _checks.real("CardIO", f"adc_volts[{channel}]", v, -10.0, 10.0, unit="V")

    def __repr__(self) -> str:
        return (f"CardIO(outputs=0x{self.outputs:04x}, encoder_reversed=0x{self.encoder_reversed:02x}, "
                f"base_address=0x{self.base_address:x})")


def of(card) -> CardIO:
    """The :class:`CardIO` of ``card`` (a :class:`~servobench.Card`), made on first use."""
    io = card.__dict__.get("_io")
    if io is None:
        io = CardIO()
        object.__setattr__(card, "_io", io)
    return io
