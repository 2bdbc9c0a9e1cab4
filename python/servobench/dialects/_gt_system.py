"""The GT dialect's system and I/O commands (issue 25.3; GT manual seed 000, ch3 L480-780, ch9 L2514-2560, ch11):
several cards in one PC (GT_SwitchtoCardNo / GT_GetCurrentCardNo), the ISA base address, the sample time, the
encoder direction, the pulse-output form, the general I/O, the A/D inputs and the two auxiliary encoders; the
commands the simulation cannot carry out (:data:`UNSUPPORTED`); and :func:`gt_adapter`, which makes a GT_* method
from a table row. Mixed into :class:`~servobench.dialects.gt.GtController`. The registers are each card's GT module
(``_core.gt_card(card.kernel).system``, ``vendor/googol/gt_card.hpp``); the machine side of the wiring is
:mod:`servobench.card_io`. The controller keeps only the handles: which Card is card n, which one is current."""

from __future__ import annotations

import math
import weakref

from .. import _core, card_io
from ..card import Card

RTN_SUCCESS, RTN_COMMAND_ERROR, RTN_PARAMETER_ERROR, RTN_COMM_ERROR = 0, 1, 7, -1

_SMPL_TM_US = (48.0, 1966.08)   # GT_SetSmplTm range, us (L4070-4078, L5028-5036)
_MAX_CARDS = 16                 # card numbers 0..15 (L5134-5140)
_ADC_RATE_HZ = 770.0            # the eight channels are converted at 770 Hz (L3502)
_PULSE_AXIS_DRIVES = ("StepperDrive", "ServoPositionDrive")

#: GT functions the simulation cannot carry out: each returns 1 (command error, cmd status via "not_simulated";
#: a read returns (1, 0)) and the reason is the manual's (decision GF3).
UNSUPPORTED: dict[str, str] = {
    "GT_BrkOn": "named only as GT_BrkOff's 'Relevant Function' (L2945); the manual gives no prototype or behaviour",
    "GT_HomeSense": "named only as GT_Home's / GT_Index's 'Relevant Function' (L4168, L4213); no prototype",
    "GT_SetLmt": "named once in Table 4-x as the 'error differential limit' (L1177); no prototype, range or "
                 "formula, and the GT servo law (L786-820) has no such term",
    "GT_SetBgCommandSet": "the background command set is a structure of gt400data.h that the manual does not print "
                          "(L2417-2510); the commands it holds cannot be decoded",
    "GT_GetBgCommandResult": "reads the result fields of the gt400data.h structure GT_SetBgCommandSet takes, which "
                             "the manual does not print (L2417)",
}

# Interrupt mask bits (GT_SetIntrMsk, L4763-4785) in the status-register layout (bit 5 = positive limit: V84) ->
# the card events that set them: what the GT module's interrupt subscriptions watch.
_INTR_EVENTS = {0: ("motion_complete",), 1: ("drive_alarm",), 2: ("breakpoint",), 3: ("captured",),
                4: ("following_error",), 5: ("pos_limit", "soft_pos_limit"), 6: ("neg_limit", "soft_neg_limit")}


def gt_adapter(name: str, params: str, body, doc: str, returns: str | None = "int", owner: str = "GtController",
               module: str = "servobench.dialects.gt"):
    """A GT_* method made from a table row: ``name(self, <params>)`` (the manual's parameter list, defaults and
    annotations as printed) calling ``body(self, *args)``; the docstring is the row's (units, the manual's line);
    ``returns`` "int" for a command returning its code (the vendor wrapper turns an exception into 7 or 1)."""
    args = ", ".join(p.split("=")[0].split(":")[0].strip() for p in params.split(",") if p.strip())
    ns = {"_body": body}
    exec(f"def {name}(self{', ' if params else ''}{params}):\n    return _body(self{', ' if args else ''}{args})\n",
         ns)  # noqa: S102 -- a signature from the table, no user input
    fn = ns[name]
    fn.__doc__, fn.__qualname__, fn.__module__ = doc, f"{owner}.{name}", module
    if returns:
        fn.__annotations__["return"] = returns
    return fn


def _renew_subscriptions(card_ref) -> None:
    """Renews the GT module's interrupt subscriptions on its card (Card.on_event) from its registers."""
    card = card_ref()
    if card is None:
        return
    g = _core.gt_card(card.kernel)
    for sid in g.subscriptions:
        card.remove_event(sid)
    if g.timer_interrupt_mode:
        subs = [card.on_event(lambda _c, _f: g.timer_interrupt(), timer_ticks=g.interrupt_timer)] \
            if g.interrupt_timer > 0 else []
    else:
        subs = [card.on_event(lambda _c, _f: g.request_interrupt(), axis=k,
                              events=[e for b, ev in _INTR_EVENTS.items() if bits >> b & 1 for e in ev])
                for k, bits in enumerate(g.watched_bits()) if bits]
    g.subscriptions = subs


class _GtSystem:
    """Cards, addresses, sample time, encoders, pulse form, I/O, A/D and auxiliary encoders of GtController."""

    def _gt(self):
        """The current card's GT module (its registers: current axis, LmtSns, the list, the interrupts...)."""
        return _core.gt_card(self._card.kernel)

    # -- several cards (L491, L545, L5130-5150, L3713-3725) -------------------------------------------------------
    def GT_Open(self, card: Card | int | None = None, irq: int = 0, **axis_parts) -> int:
        """Opens the card(s) (PCI form, L4381-4391): ``card``, else the machine :meth:`use_machine` set (one Card
        or the PC's several GT cards, card 0 current, L5134-5140), else a new 4-axis :class:`~servobench.Card`
        built from ``axis_parts``. The GT has 4 axes (L752-756). The ISA Windows form ``GT_Open(PortBase, irq)``
        (Example 3-2, L519-523, L549-553) opens the machine's card whose base-address jumper is ``PortBase``
        (``card_io.of(card).base_address``): 0, or -1 when no card answers there; irq 0 (none) or 10..15."""
        if card is not None and not isinstance(card, Card):
            if not _int_in(card, 0, 0xFFFF) or not (_int_in(irq, 10, 15) or irq == 0):
                return RTN_PARAMETER_ERROR
            return RTN_SUCCESS if self.GT_SetAddr(int(card)) == RTN_SUCCESS else RTN_COMM_ERROR
        cards = [card] if card is not None else (self._machine_cards() if not axis_parts else [])
        self._open_cards(cards or [Card(4, **axis_parts)])
        return RTN_SUCCESS

    def GT_Close(self) -> int:
        """Closes the card(s) (L3051-3061)."""
        if self._card is None:
            return RTN_COMM_ERROR
        self._cards, self._card = [], None
        return RTN_SUCCESS

    def _open_cards(self, cards) -> None:
        for c in cards:
            if not isinstance(c, Card):
                raise TypeError(f"GT_Open: the machine must be servobench.Card objects, not {type(c).__name__}")
            if len(c) != 4:
                raise ValueError(f"a GT card has 4 axes (GT L752-756); this Card has {len(c)}")
        if not 1 <= len(cards) <= _MAX_CARDS:
            raise ValueError(f"GT_Open: 1..{_MAX_CARDS} cards in one PC (card numbers 0..15, L5134), got {len(cards)}")
        for c in cards:  # each card's module renews its interrupt subscriptions (weakly: the card owns the module)
            _core.gt_card(c.kernel).set_resubscribe(lambda ref=weakref.ref(c): _renew_subscriptions(ref))
        self._cards, self._card, self._card_no = list(cards), cards[0], 0

    def _machine_cards(self) -> list:
        """The cards of the machine :meth:`use_machine` set (a Card, a list of Cards -- the PC's GT cards in
        PCI order, card 0 first -- or a callable returning either), or []."""
        m = self._machine
        if m is None:
            return []
        if callable(m) and not isinstance(m, Card):
            m = m()
        return [m] if isinstance(m, Card) else list(m)

    def use_machine(self, machine) -> None:
        """As :meth:`DialectController.use_machine`, and a GT machine may be several cards in one PC: a list of
        :class:`~servobench.Card` (card 0 first) or a callable returning a Card or such a list."""
        if isinstance(machine, (list, tuple)):
            if not all(isinstance(c, Card) for c in machine):
                raise TypeError("use_machine: a list of servobench.Card objects (the PC's GT cards)")
            self._machine = list(machine)
            return
        super().use_machine(machine)  # type: ignore[misc]

    def _io(self) -> card_io.CardIO:
        return card_io.of(self._card)

    def _t_s(self) -> float:
        return self._card.tick * self._card.servo_period_s

    def GT_SwitchtoCardNo(self, card_no) -> int:
        """Makes card ``card_no`` (0..15, numbered in the order the PC found them) current; every later GT call acts
        on it. 0 success, -1 failure: no card with that number (L5130-5150). In program mode the card switched to
        is first brought to the time of the one left (all cards of a PC run at once)."""
        cards = getattr(self, "_cards", [])
        if not cards or not _int_in(card_no, 0, _MAX_CARDS - 1) or int(card_no) >= len(cards):
            return RTN_COMM_ERROR
        self._switch(int(card_no))
        return RTN_SUCCESS

    def _switch(self, n: int) -> None:
        old, self._card, self._card_no = self._card, self._cards[n], n
        clock = getattr(self._card, "_clock", None)
        if old is not None and clock is not None and clock.mode == "program":
            lag_ms = (old.tick * old.servo_period_s - self._t_s()) * 1e3
            if lag_ms > 0:
                clock.advance_ms(lag_ms)

    def GT_GetCurrentCardNo(self) -> int:
        """The current card number 0..15, returned (not a status code) (L3713-3725); -1 with no card open."""
        return self._card_no if getattr(self, "_cards", None) and self._card is not None else RTN_COMM_ERROR

    # -- ISA base address (DOS, L506, L547-556, L3524-3549, L4597-4611) -------------------------------------------
    def GT_SetAddr(self, Address) -> int:
        """Sets the ISA base address (DOS; default 0x300): 0 when a card of the machine answers there (its
        base-address jumper, ``card_io.of(card).base_address``), which becomes current (opened if none was: the DOS
        form of GT_Open, Example 3-1); -1 when none does, and no card is reachable then (L552-556)."""
        if not _int_in(Address, 0, 0xFFFF):
            return RTN_PARAMETER_ERROR
        self._isa_addr = int(Address)
        cards = list(getattr(self, "_cards", [])) or self._machine_cards() or [Card(4)]
        hit = [n for n, c in enumerate(cards) if card_io.of(c).base_address == int(Address)]
        if not hit:
            self._cards, self._card = [], None
            return RTN_COMM_ERROR
        if not getattr(self, "_cards", None):
            self._open_cards(cards)
        self._switch(hit[0])
        return RTN_SUCCESS

    def GT_GetAddr(self):
        """(0, base address): the one GT_SetAddr set, even a wrong one, else the default 0x300; always 0, there is
        no exchange with the card (L3524-3549)."""
        return RTN_SUCCESS, getattr(self, "_isa_addr", 0x300)

    # -- sample time (L508, L558-566, L5026-5036) -----------------------------------------------------------------
    def GT_SetSmplTm(self, Timer) -> int:
        """Sets the servo period, us, 48..1966.08 (7 outside). The simulated card's period is the machine's (the
        Card is built with it, ``servo_period_s``): the call succeeds when it asks for that period and returns 1
        (not simulated) for another one -- build the machine at the period the program sets (decision GF4)."""
        if self._card is None:
            return RTN_COMM_ERROR
        rtn = self._gt().check(Timer, *_SMPL_TM_US, "real")
        if rtn or math.isclose(float(Timer) * 1e-6, self._card.servo_period_s, rel_tol=1e-9):
            return rtn
        return self._gt().refuse("not_simulated")

    # -- pulse output form (L664-672, L5104-5128) -----------------------------------------------------------------
    def _step(self, pulse: bool) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        g = self._gt()
        if type(self._card.axes[g.axis].drive).__name__ not in _PULSE_AXIS_DRIVES:
            return g.refuse("invalid_in_mode")  # not in pulse output mode (L5108)
        g.system.step_pulse = [pulse if k == g.axis else p for k, p in enumerate(g.system.step_pulse)]
        return RTN_SUCCESS

    def GT_StepDir(self) -> int:
        """Pulse + direction output (the default) for the current axis in pulse output mode (L5104-5114); 1 on an
        analog axis. The simulated pulse drive counts the pulses whatever their form (V94); the form is kept
        (:meth:`pulse_form`)."""
        return self._step(False)

    def GT_StepPulse(self) -> int:
        """Positive / negative pulse (CW/CCW) output for the current axis in pulse output mode (L5116-5124)."""
        return self._step(True)

    def pulse_form(self, axis: int) -> str:
        """Simulation helper: ``"pulse_dir"`` or ``"cw_ccw"``, the pulse form GT_StepDir/GT_StepPulse set on axis
        ``axis`` (1..4) of the current card."""
        if not _int_in(axis, 1, 4):
            raise ValueError(f"pulse_form.axis = {axis!r} must be 1..4")
        return "cw_ccw" if self._gt().system.step_pulse[int(axis) - 1] else "pulse_dir"

    # -- general I/O (ch9 L2514-2560, L3375-3440) -----------------------------------------------------------------
    def GT_ExInpt(self):
        """(rtn, EXI0..EXI15 levels, bit n = EXIn) (L3375-3401): the machine's ``card_io.of(card).inputs``."""
        return (RTN_COMM_ERROR, 0) if self._card is None else (RTN_SUCCESS, self._io().input_word(self._t_s()))

    def GT_ExOpt(self, Data) -> int:
        """Writes EXO0..EXO15, bit n = EXOn (L3409-3440); the machine reads ``card_io.of(card).outputs``."""
        if self._card is None:
            return RTN_COMM_ERROR
        rtn = self._gt().check(Data, 0, 0xFFFF)
        if not rtn:
            self._io().outputs = int(Data)
        return rtn

    def GT_SetTime(self, value) -> int:
        """Width of the output pulse on CN7 pin 23, 0..65535 for 0..16 ms (L5042-5050): recorded as
        ``card_io.of(card).pulse_width_s`` = value x 16 ms / 65535 (decision GF6)."""
        if self._card is None:
            return RTN_COMM_ERROR
        rtn = self._gt().check(value, 0, 65535)
        if not rtn:
            self._io().pulse_width_s = int(value) * 16e-3 / 65535
        return rtn

    # -- A/D (L3498-3520, L4585-4595) -----------------------------------------------------------------------------
    def GT_SetAdcChn(self, value) -> int:
        """Number of A/D channels converted, 1..8 (default 8, decision GF7) (L4585-4595)."""
        if self._card is None:
            return RTN_COMM_ERROR
        rtn = self._gt().check(value, 1, 8)
        if not rtn:
            self._gt().system.adc_chn = int(value)
        return rtn

    def GT_GetAdc(self, Channel):
        """(rtn, A/D result of channel 1..8): 0..2047 for 0..+10 V, 2048..4095 for -0..-10 V (code = 2048 abs(V) / 10,
        at most 2047 in each half), the voltage sampled at the last 770 Hz conversion (L3498-3520). 7 for a channel
        beyond GT_SetAdcChn's number."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        rtn = self._gt().check(Channel, 1, self._gt().system.adc_chn)
        if rtn:
            return rtn, 0
        v = self._io().volts(int(Channel) - 1, math.floor(self._t_s() * _ADC_RATE_HZ) / _ADC_RATE_HZ)
        code = min(2047, int(abs(v) / 10.0 * 2048))
        return RTN_SUCCESS, code if v >= 0 else 2048 + code

    # -- encoders (L595-635, L3267-3300) and auxiliary encoders (L3124-3136, L3241-3330, L3727-3759, L4733-4747) ------
    def _aux(self) -> _core.GtAuxInputs:
        """What the machine gives the card's auxiliary-encoder inputs at this read (``card_io``'s wiring): the
        module (``vendor/googol/gt_aux_encoder.hpp``) asks for each count it needs, ``CardIO.aux_counts(n, t_s)``."""
        io = self._io()
        enc = io.aux_encoders[0]
        return _core.GtAuxInputs(io.aux_counts, io.encoder_reversed, enc.counts_per_index if enc else 0,
                                 enc.index_offset if enc else 0.0)


def _int_in(value, lo, hi) -> bool:
    """Whether `value` is a whole number in lo..hi (the handle arguments: card number, address, IRQ)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


def _aux_row(name: str, params: str, call, doc: str, read: bool = True):
    """A row over the GT module's encoder commands: ``call(module, *args, inputs)``; -1 (or (-1, 0)) without a card."""
    def body(self, *args):
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        return call(self._gt(), *args, self._aux())

    return gt_adapter(name, params, body, doc, returns=None if read else "int")


_ENCODER_ROWS = [
    _aux_row("GT_EncSns", "Sense", lambda g, s, i: g.set_encoder_sense(s, i),
             "Encoder count direction, bits 0-3 axes 1-4, bits 4-5 auxiliary encoders 1-2: 1 reverses the count "
             "(Table 11-2, L595-635, L3267-3300). The machine's wiring is ``card_io.of(card).encoder_reversed``: an "
             "axis whose setting does not correct its wiring would run with positive feedback, which the simulated "
             "axis cannot (it returns 1, nothing changed); the auxiliary encoders' counts are reversed as asked, "
             "their reads staying where they are (decision GF5). 7 outside 0..0x3F.", read=False),
    _aux_row("GT_EncPos", "Enc_Num", lambda g, n, i: g.aux_position(n, i),
             "(rtn, position of auxiliary encoder 1 or 2, pulse) (L3241-3262); 7 for another number."),
    _aux_row("GT_EncVel", "Enc_Num", lambda g, n, i: g.aux_velocity(n, i),
             "(rtn, velocity of auxiliary encoder 1 or 2, pulse/ST): its count change over the last sample time "
             "(L3302-3323); 7 for another number."),
    _aux_row("GT_ClrEncPos", "EncNum", lambda g, n, i: g.clear_aux_position(n, i),
             "Sets the position of auxiliary encoder 1 or 2 to 0 (L3124-3136); 0 success, -1 failure (a number "
             "other than 1, 2).", read=False),
    _aux_row("GT_SetEncCapt", "", lambda g, i: g.arm_aux_capture(i),
             "Arms the INDEX capture of auxiliary encoder 1 and clears its captured flag (L4733-4747).", read=False),
    _aux_row("GT_GetEncSts", "", lambda g, i: g.aux_capture_status(i),
             "(rtn, auxiliary encoder capture status): bit 3 = the INDEX mark was captured since GT_SetEncCapt "
             "(L3741-3753)."),
    _aux_row("GT_GetEncCapt", "", lambda g, i: g.aux_capture_value(i),
             "(rtn, position of auxiliary encoder 1 at the captured INDEX mark, pulse); the previous value while "
             "nothing is captured (L3727-3739)."),
]
for _fn in _ENCODER_ROWS:
    setattr(_GtSystem, _fn.__name__, _fn)


def _unsupported(name: str, read: bool):
    def body(self, *args):
        rtn = RTN_COMM_ERROR if self._card is None else self._gt().refuse("not_simulated")
        return (rtn, 0) if read else rtn

    return gt_adapter(name, "*args", body, f"Not simulated (UNSUPPORTED): returns {'(1, 0)' if read else '1'}. "
                      f"{UNSUPPORTED[name]}.", returns=None if read else "int")


for _name in UNSUPPORTED:
    setattr(_GtSystem, _name, _unsupported(_name, _name.startswith("GT_Get")))
