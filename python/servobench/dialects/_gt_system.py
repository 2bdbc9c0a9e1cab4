"""The GT dialect's system and I/O commands (issue 25.3; GT manual seed 000, ch3 L480-780, ch9 L2514-2560, ch11):
several cards in one PC (GT_SwitchtoCardNo / GT_GetCurrentCardNo), the ISA base address, the sample time, the
encoder direction, the pulse-output form, the general I/O, the A/D inputs and the two auxiliary encoders; and
the commands the simulation cannot carry out (:data:`UNSUPPORTED`). Mixed into
:class:`~servobench.dialects.gt.GtController`; the machine side of the wiring is :mod:`servobench.card_io`."""

from __future__ import annotations

import math

from .. import card_io
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


def _int_in(value, lo, hi) -> bool:
    try:
        v = float(value)
    except (TypeError, ValueError):
        return False
    return math.isfinite(v) and v == int(v) and lo <= v <= hi


# The dialect state that belongs to one card (swapped by GT_SwitchtoCardNo); the rest is the program's.
_PER_CARD = ("_card", "_axis", "_lmt_sns", "_index", "_crd_state", "_intr_state", "_sys")


def _fresh_sys() -> dict:
    return {"enc_sns": 0, "step_pulse": [False] * 4, "adc_chn": 8, "enc_zero": [0, 0],
            "capt": None}


class _GtSystem:
    """Cards, addresses, sample time, encoders, pulse form, I/O, A/D and auxiliary encoders of GtController."""

    # -- several cards (L491, L545, L5130-5150, L3713-3725) -------------------------------------------------------
    def _open_cards(self, cards) -> None:
        for c in cards:
            if not isinstance(c, Card):
                raise TypeError(f"GT_Open: the machine must be servobench.Card objects, not {type(c).__name__}")
            if len(c) != 4:
                raise ValueError(f"a GT card has 4 axes (GT L752-756); this Card has {len(c)}")
        if not 1 <= len(cards) <= _MAX_CARDS:
            raise ValueError(f"GT_Open: 1..{_MAX_CARDS} cards in one PC (card numbers 0..15, L5134), got {len(cards)}")
        self._slots = [{"_card": c, "_axis": 0, "_lmt_sns": 0, "_index": [0] * 4, "_sys": _fresh_sys()}
                       for c in cards]
        self._card_no = 0
        self._load_slot(0)

    def _load_slot(self, n: int) -> None:
        for k in _PER_CARD:
            self.__dict__.pop(k, None)
        self.__dict__.update(self._slots[n])
        self._card_no = n

    def _save_slot(self) -> None:
        if getattr(self, "_slots", None):
            self._slots[self._card_no] = {k: self.__dict__[k] for k in _PER_CARD if k in self.__dict__}

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

    def _sys_state(self) -> dict:
        st = self.__dict__.get("_sys")
        if st is None:
            st = self.__dict__["_sys"] = _fresh_sys()
        return st

    def _io(self) -> card_io.CardIO:
        return card_io.of(self._card)

    def _t_s(self) -> float:
        return self._card.tick * self._card.servo_period_s

    def GT_SwitchtoCardNo(self, card_no) -> int:
        """Makes card ``card_no`` (0..15, numbered in the order the PC found them) current; every later GT call acts
        on it. 0 success, -1 failure: no card with that number (L5130-5150). In program mode the card switched to
        is first brought to the time of the one left (all cards of a PC run at once)."""
        if not getattr(self, "_slots", None) or not _int_in(card_no, 0, _MAX_CARDS - 1) \
                or int(card_no) >= len(self._slots):
            return RTN_COMM_ERROR
        self._switch(int(card_no))
        return RTN_SUCCESS

    def _switch(self, n: int) -> None:
        old = self._card
        self._save_slot()
        self._load_slot(n)
        clock = getattr(self._card, "_clock", None)
        if old is not None and clock is not None and clock.mode == "program":
            lag_ms = (old.tick * old.servo_period_s - self._t_s()) * 1e3
            if lag_ms > 0:
                clock.advance_ms(lag_ms)

    def GT_GetCurrentCardNo(self) -> int:
        """The current card number 0..15, returned (not a status code) (L3713-3725); -1 with no card open."""
        return self._card_no if getattr(self, "_slots", None) and self._card is not None else RTN_COMM_ERROR

    # -- ISA base address (DOS, L506, L547-556, L3524-3549, L4597-4611) -------------------------------------------
    def GT_SetAddr(self, Address) -> int:
        """Sets the ISA base address (DOS; default 0x300): 0 when a card of the machine answers there (its
        base-address jumper, ``card_io.of(card).base_address``), which becomes current (opened if none was: the DOS
        form of GT_Open, Example 3-1); -1 when none does, and no card is reachable then (L552-556)."""
        if not _int_in(Address, 0, 0xFFFF):
            return RTN_PARAMETER_ERROR
        self._isa_addr = int(Address)
        cards = [s["_card"] for s in self._slots] if getattr(self, "_slots", None) else self._machine_cards()
        if not cards:
            cards = [Card(4)]
        hit = [n for n, c in enumerate(cards) if card_io.of(c).base_address == int(Address)]
        if not hit:
            self._slots, self._card = [], None
            return RTN_COMM_ERROR
        if not getattr(self, "_slots", None):
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
        try:
            t = float(Timer)
        except (TypeError, ValueError):
            return self._param_error("illegal_control_param")
        if not (math.isfinite(t) and _SMPL_TM_US[0] <= t <= _SMPL_TM_US[1]):
            return self._param_error("illegal_control_param")
        if not math.isclose(t * 1e-6, self._card.servo_period_s, rel_tol=1e-9):
            self._card.record_fault(self._axis, "not_simulated")
            return RTN_COMMAND_ERROR
        return RTN_SUCCESS

    # -- encoder direction (L595-635, L3267-3300) ----------------------------------------------------------------
    def GT_EncSns(self, Sense) -> int:
        """Encoder count direction, bits 0-3 axes 1-4, bits 4-5 auxiliary encoders 1-2: 1 reverses the count
        (Table 11-2). The machine's wiring is ``card_io.of(card).encoder_reversed``: an axis whose setting does not
        correct its wiring would run with positive feedback, which the simulated axis cannot (it returns 1,
        nothing changed); the auxiliary encoders' counts are reversed as asked (decision GF5)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(Sense, 0, 0xFFFF) or int(Sense) & ~0x3F:
            return self._param_error("illegal_control_param")
        if (int(Sense) ^ self._io().encoder_reversed) & 0xF:
            self._card.record_fault(self._axis, "not_simulated")
            return RTN_COMMAND_ERROR
        st = self._sys_state()
        for n in (0, 1):  # the position read stays where it is when the direction flips
            before = self._aux_value(n)
            st["enc_sns"] = (st["enc_sns"] & ~(1 << (4 + n))) | (int(Sense) & (1 << (4 + n)))
            st["enc_zero"][n] += self._aux_value(n) - before
        st["enc_sns"] = int(Sense)
        return RTN_SUCCESS

    # -- pulse output form (L664-672, L5104-5128) -----------------------------------------------------------------
    def _step(self, pulse: bool) -> int:
        if self._card is None:
            return RTN_COMM_ERROR
        if type(self._card.axes[self._axis].drive).__name__ not in _PULSE_AXIS_DRIVES:
            self._card.record_fault(self._axis, "invalid_in_mode")  # not in pulse output mode (L5108)
            return RTN_COMMAND_ERROR
        self._sys_state()["step_pulse"][self._axis] = pulse
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
        return "cw_ccw" if self._sys_state()["step_pulse"][int(axis) - 1] else "pulse_dir"

    # -- general I/O (ch9 L2514-2560, L3375-3440) -----------------------------------------------------------------
    def GT_ExInpt(self):
        """(rtn, EXI0..EXI15 levels, bit n = EXIn) (L3375-3401): the machine's ``card_io.of(card).inputs``."""
        return self._get(lambda: self._io().input_word(self._t_s()))

    def GT_ExOpt(self, Data) -> int:
        """Writes EXO0..EXO15, bit n = EXOn (L3409-3440); the machine reads ``card_io.of(card).outputs``."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(Data, 0, 0xFFFF):
            return self._param_error("illegal_control_param")
        self._io().outputs = int(Data)
        return RTN_SUCCESS

    def GT_SetTime(self, value) -> int:
        """Width of the output pulse on CN7 pin 23, 0..65535 for 0..16 ms (L5042-5050): recorded as
        ``card_io.of(card).pulse_width_s`` = value x 16 ms / 65535 (decision GF6)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(value, 0, 65535):
            return self._param_error("illegal_control_param")
        self._io().pulse_width_s = int(value) * 16e-3 / 65535
        return RTN_SUCCESS

    # -- A/D (L3498-3520, L4585-4595) -----------------------------------------------------------------------------
    def GT_SetAdcChn(self, value) -> int:
        """Number of A/D channels converted, 1..8 (default 8, decision GF7) (L4585-4595)."""
        if self._card is None:
            return RTN_COMM_ERROR
        if not _int_in(value, 1, 8):
            return self._param_error("illegal_control_param")
        self._sys_state()["adc_chn"] = int(value)
        return RTN_SUCCESS

    def GT_GetAdc(self, Channel):
        """(rtn, A/D result of channel 1..8): 0..2047 for 0..+10 V, 2048..4095 for -0..-10 V (code = 2048 abs(V) / 10,
        at most 2047 in each half), the voltage sampled at the last 770 Hz conversion (L3498-3520). 7 for a channel
        beyond GT_SetAdcChn's number."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        if not _int_in(Channel, 1, self._sys_state()["adc_chn"]):
            return self._param_error("illegal_control_param"), 0
        t = math.floor(self._t_s() * _ADC_RATE_HZ) / _ADC_RATE_HZ
        v = self._io().volts(int(Channel) - 1, t)
        code = min(2047, int(abs(v) / 10.0 * 2048))
        return RTN_SUCCESS, code if v >= 0 else 2048 + code

    # -- auxiliary encoders (L3124-3136, L3241-3330, L3727-3759, L4733-4747) --------------------------------------
    def _aux_raw(self, n: int, t_s: float) -> int:
        enc = self._io().aux_encoders[n]
        return 0 if enc is None else enc.counts(t_s)

    def _aux_sign(self, n: int) -> int:
        flip = (self._io().encoder_reversed ^ self._sys_state()["enc_sns"]) >> (4 + n) & 1
        return -1 if flip else 1

    def _aux_value(self, n: int, t_s: float | None = None) -> int:
        t = self._t_s() if t_s is None else t_s
        return self._aux_sign(n) * self._aux_raw(n, t) - self._sys_state()["enc_zero"][n]

    def _enc_num(self, num):
        return int(num) - 1 if _int_in(num, 1, 2) else None

    def GT_EncPos(self, Enc_Num):
        """(rtn, position of auxiliary encoder 1 or 2, pulse) (L3241-3262)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        n = self._enc_num(Enc_Num)
        if n is None:
            return self._param_error("illegal_control_param"), 0
        return RTN_SUCCESS, self._aux_value(n)

    def GT_EncVel(self, Enc_Num):
        """(rtn, velocity of auxiliary encoder 1 or 2, pulse/ST): its count change over the last sample time
        (L3302-3323)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        n = self._enc_num(Enc_Num)
        if n is None:
            return self._param_error("illegal_control_param"), 0
        t, ts = self._t_s(), self._card.servo_period_s
        return RTN_SUCCESS, float(self._aux_value(n, t) - self._aux_value(n, max(0.0, t - ts)))

    def GT_ClrEncPos(self, EncNum) -> int:
        """Sets the position of auxiliary encoder 1 or 2 to 0 (L3124-3136); 0 success, -1 failure (a number other
        than 1, 2)."""
        if self._card is None:
            return RTN_COMM_ERROR
        n = self._enc_num(EncNum)
        if n is None:
            return RTN_COMM_ERROR
        self._sys_state()["enc_zero"][n] += self._aux_value(n)
        return RTN_SUCCESS

    def GT_SetEncCapt(self) -> int:
        """Arms the INDEX capture of auxiliary encoder 1 and clears its captured flag (L4733-4747)."""
        if self._card is None:
            return RTN_COMM_ERROR
        st = self._sys_state()
        prev = st["capt"]["value"] if st["capt"] else 0
        st["capt"] = {"armed": True, "tick": self._card.tick, "raw": self._aux_raw(0, self._t_s()), "value": prev,
                      "captured": False}
        return RTN_SUCCESS

    def _capt_scan(self) -> dict | None:
        """Looks at auxiliary encoder 1 tick by tick since the last look for its first index mark."""
        cap = self._sys_state()["capt"]
        if cap is None or not cap["armed"]:
            return cap
        enc = self._io().aux_encoders[0]
        ts = self._card.servo_period_s
        for k in range(cap["tick"] + 1, self._card.tick + 1):
            raw = self._aux_raw(0, k * ts)
            mark = enc.index_between(cap["raw"], raw) if enc is not None else None
            cap["raw"], cap["tick"] = raw, k
            if mark is not None:
                cap.update(armed=False, captured=True,
                           value=self._aux_sign(0) * mark - self._sys_state()["enc_zero"][0])
                break
        cap["tick"] = max(cap["tick"], self._card.tick)
        return cap

    def GT_GetEncSts(self):
        """(rtn, auxiliary encoder capture status): bit 3 = the INDEX mark was captured since GT_SetEncCapt
        (L3741-3753)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        cap = self._capt_scan()
        return RTN_SUCCESS, 0x8 if cap is not None and cap["captured"] else 0

    def GT_GetEncCapt(self):
        """(rtn, position of auxiliary encoder 1 at the captured INDEX mark, pulse); the previous value while
        nothing is captured (L3727-3739)."""
        if self._card is None:
            return RTN_COMM_ERROR, 0
        cap = self._capt_scan()
        return RTN_SUCCESS, cap["value"] if cap is not None else 0

    # -- not simulated (UNSUPPORTED) -------------------------------------------------------------------------------
    def _unsupported(self, read: bool = False):
        if self._card is None:
            return (RTN_COMM_ERROR, 0) if read else RTN_COMM_ERROR
        self._card.record_fault(self._axis, "not_simulated")
        return (RTN_COMMAND_ERROR, 0) if read else RTN_COMMAND_ERROR

    def GT_BrkOn(self, *args) -> int:
        """Not simulated (UNSUPPORTED): returns 1."""
        return self._unsupported()

    def GT_HomeSense(self, *args) -> int:
        """Not simulated (UNSUPPORTED): returns 1."""
        return self._unsupported()

    def GT_SetLmt(self, *args) -> int:
        """Not simulated (UNSUPPORTED): returns 1."""
        return self._unsupported()

    def GT_SetBgCommandSet(self, *args) -> int:
        """Not simulated (UNSUPPORTED): returns 1."""
        return self._unsupported()

    def GT_GetBgCommandResult(self, *args):
        """Not simulated (UNSUPPORTED): returns (1, 0)."""
        return self._unsupported(read=True)
