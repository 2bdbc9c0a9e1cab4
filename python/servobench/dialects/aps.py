"""The ADLINK APS function library (PCI-8254/8258 manual, seed 004) on the virtual :class:`~servobench.Card`.

Names, argument order and units are the manual's: axis IDs from 0 (``I32 axis_id = 0``, L2608), positions in
pulse, velocities in pulse/s, accelerations in pulse/s^2 (unit factor 1), axis parameters by their PRA_* numbers
(L1746-1762, L2744-2751, L3998-4019). Every function returns an I32 code: ``ERR_NoError`` (0) or a negative
error code of the APS library header ErrorCodeDef.h (the manual names only ERR_NoError; decision V49).
``APS_motion_status`` / ``APS_motion_io_status`` return the status word itself (L3168, L3611); a getter
``APS_get_x(axis, &x)`` returns the tuple ``(rtn, x)``.

A motion command the controller ignores while EMG, ALM or a limit toward the move is active returns
ERR_NoError and changes nothing but the stop code and ASTP, as the manual describes (L3931-4010; V47). A command
refused in this state of the axis (a move during homing, servo on with the alarm latched, position set while
moving) returns ERR_FunctionNotAvailable (-13) and leaves the state unchanged.

This module only translates: the motion, interpolation, position, status and compare-trigger functions are
generated, one per row of the C++ tables (``_core.APS_COMMANDS``, ``APS_ARC_COMMANDS``: name, arguments, doc),
over the C++ runner ``_core.aps_command`` (vendor/adlink/aps_commands.hpp), which checks the arguments and returns
the codes; the behaviour (moves, status words, safety) is the Card's and its ADLINK modules'. Simulation helpers (not
in the manual): :func:`run` (ticks), :func:`Sleep` (ms, as the manual's examples), :func:`wait_until`, :func:`card`.
"""

from __future__ import annotations

import inspect

import numpy as np

from .. import _core
from .._core import ApsServoLaw
from ..card import Card
from ._aps_constants import *  # noqa: F401,F403  (the header constants: the C++ table's, AX1)
from ._aps_more import _ApsMore
from ._aps_pt import PTA2CA, PTA2CE, PTDWL, PTHCA, PTHCE, PTLINE, PTSTS, _ApsPointTable, _f, _param, _v  # noqa: F401
from ._controller import DialectController, export_functions, register32, wrap32  # noqa: F401


class ApsController(DialectController):
    """One APS program's view of a :class:`~servobench.Card`: the APS_* functions with the card's axes 0..n-1."""

    _PARAMETER_ERROR = ERR_ParametersInvalid   # what an APS_* function returns instead of raising (issue 21.2)
    _COMMAND_ERROR = ERR_FunctionNotAvailable

    # -- plumbing ----------------------------------------------------------------------------------------------
    def _bad(self) -> int:
        return ERR_DeviceNotInitial if self._card is None else ERR_ParametersInvalid

    def _prm(self):
        """The card's PRA_* parameter table (vendor/adlink/aps_parameters.hpp)."""
        return _core.aps_parameters(self._card.kernel)

    # -- simulation helpers ------------------------------------------------------------------------------------
    def Sleep(self, ms: float):
        """The examples' ``Sleep(ms)``: runs the card ``ms`` milliseconds (rounded to whole servo ticks)."""
        return self.run_ms(ms)

    # -- system --------------------------------------------------------------------------------------------------
    def APS_initial(self, mode: int = 0, card: Card | None = None, **axis_parts):
        if self._card is not None:
            return ERR_DeviceAlreadyInitialed, 0
        if card is None and not axis_parts:
            card = self._machine_card()  # the machine a vendor program runs against (use_machine, issue 25.2)
        if card is None:
            axis_parts.setdefault("law", ApsServoLaw())
            axis_parts.setdefault("servo_period_s", 250e-6)
            card = Card(4, **axis_parts)
        if len(card) not in (4, 8):
            return ERR_ParametersInvalid, 0
        self._card = card
        self._prm().power_on()  # the PRA_* table (AV5)
        self._scope_init()  # sampling, trigger, interrupts (issue 10.3)
        _core.aps_point_tables(card.kernel).power_on()  # point tables (AF5-AF12, AW1)
        self._more_init()   # counters, watchdog, VAO, board parameters (AF13-AF21)
        return ERR_NoError, 1

    def APS_close(self) -> int:
        if self._card is None:
            return ERR_DeviceNotInitial
        self._more_close()  # the watchdog and the interrupt watch go with the card (AW4, AW5)
        self._card = None
        return ERR_NoError


# -- sampling, position compare trigger, host interrupts (issue 10 point 3; decisions V71-V85) -------------------
# The sources' signals, units and bits are the C++ module's table (vendor/adlink/aps_scope.cpp, Tables 4-5/4-6).
#: One sample of APS_wait_trigger_sampling (STR_SAMP_DATA_4CH {I32 tick; I32 data[4]}; data F64 here, V78).
STR_SAMP_DATA_4CH = np.dtype([("tick", np.int64), ("data", np.float64, (4,))])


class _ApsScope:
    """The sampling, trigger and interrupt functions of :class:`ApsController` (mixed in)."""

    def _scope_init(self):
        self._scope().power_on()  # sampling, trigger and timer registers: the C++ module's (AV2)
        self._ints().power_on()   # interrupt table and its own watch of the card (AV4, AW4)

    def _scope(self):
        """The card's ADLINK scope module (vendor/adlink/aps_scope.hpp): the sampling/trigger/timer registers."""
        return _core.aps_scope(self._card.kernel)

    def _board(self, Board_ID) -> bool:
        return self._card is not None and _f(Board_ID) == 0

    # -- data sampling (L3544-3665): the registers and the run are vendor/adlink/aps_scope.hpp's ------------------
    def APS_set_sampling_param(self, Board_ID, ParaNum, ParaDat) -> int:
        return self._scope().set_sampling_param(ParaNum, ParaDat) if self._board(Board_ID) else self._bad()

    def APS_get_sampling_param(self, Board_ID, ParaNum):
        return self._scope().sampling_param(ParaNum) if self._board(Board_ID) else (self._bad(), 0)

    def APS_wait_trigger_sampling(self, Board_ID, Length, PreTrgLen, TimeOutMs):
        rtn, data = self.APS_wait_trigger_sampling_async(Board_ID, Length, PreTrgLen, TimeOutMs)
        if rtn != ERR_NoError:
            return rtn, None
        s, c = self._scope(), self._card
        c.run_until(lambda _c: s.sampling_block_ready(), max_ticks=s.sampling_ticks_left(),
                    chunk=max(1, int(round(1e-3 / c.servo_period_s))))
        rtn = s.finish_sampling()
        return rtn, (data if rtn == ERR_NoError else None)

    def APS_wait_trigger_sampling_async(self, Board_ID, Length, PreTrgLen, TimeOutMs):
        if not self._board(Board_ID):
            return self._bad(), None
        rtn = self._scope().start_sampling(Length, PreTrgLen, TimeOutMs)
        return rtn, (self._scope().sampling_buffer() if rtn == ERR_NoError else None)

    def APS_get_sampling_count(self, Board_ID):
        return (ERR_NoError, self._scope().sampling_count()) if self._board(Board_ID) else (self._bad(), 0)

    def APS_stop_wait_sampling(self, Board_ID) -> int:
        if not self._board(Board_ID):
            return self._bad()
        self._scope().stop_sampling()
        return ERR_NoError

    # -- position compare trigger (L3348-3435): the parameters are aps_scope.hpp's, the rest runner rows (AY1) ------
    def APS_set_trigger_param(self, Board_ID, Param_No, Param_Val) -> int:
        return self._scope().set_trigger_param(Param_No, Param_Val) if self._board(Board_ID) else self._bad()

    def APS_get_trigger_param(self, Board_ID, Param_No):
        return self._scope().trigger_param(Param_No) if self._board(Board_ID) else (self._bad(), 0)

    # -- host interrupts (L4090-4330): the table is vendor/adlink/aps_interrupts.hpp's (AV4) ------------------------
    def _ints(self):
        """The card's ADLINK interrupt module (main switch, factors, signaled flags, the wait)."""
        return _core.aps_interrupts(self._card.kernel)

    def APS_int_enable(self, Board_ID, Enable) -> int:
        return self._ints().set_main(Enable) if self._board(Board_ID) else self._bad()

    def APS_set_int_factor(self, Board_ID, Item_No, Factor_No, Enable) -> int:
        if not self._board(Board_ID):
            return self._bad()
        return self._ints().set_factor(Item_No, Factor_No, Enable)  # the module watches the card itself (AW4)

    def APS_get_int_factor(self, Board_ID, Item_No, Factor_No):
        return self._ints().factor_enabled(Item_No, Factor_No) if self._board(Board_ID) else (self._bad(), 0)

    def APS_int_no_to_handle(self, Int_No):
        return int(Int_No)

    def APS_wait_single_int(self, Int_No, Time_Out) -> int:
        return self.APS_wait_multiple_int(1, [Int_No], 1, Time_Out)

    def APS_wait_multiple_int(self, Int_Count, Int_No_Array, Wait_All, Time_Out) -> int:
        if self._card is None:
            return ERR_DeviceNotInitial
        m = self._ints()
        rtn, ticks = m.begin_wait(Int_Count, list(Int_No_Array), Wait_All, Time_Out)
        if rtn != ERR_NoError:
            return rtn
        self._card.run_until_fired(m.wait_done, ticks)
        return ERR_NoError if m.wait_done() else ERR_TimeOut

    def APS_reset_int(self, Int_No) -> int:
        return ERR_DeviceNotInitial if self._card is None else self._ints().set_signaled(Int_No, False)

    def APS_set_int(self, Int_No) -> int:
        return ERR_DeviceNotInitial if self._card is None else self._ints().set_signaled(Int_No, True)


def _number(x) -> list:
    """A number argument as the runner takes it: one value (NaN when it is none), no values when not given."""
    return [] if x is None else [_f(x)]


def _runner_function(name: str, args: str, doc: str, kinds: str, reply: str):
    """One ApsController method of a row of the C++ tables: the manual's signature (``args``), one call of the C++
    runner ``_core.aps_command`` (vendor/adlink/aps_commands.hpp) with each argument a number or an array
    (``kinds``); it returns what the runner returns (the code, a status word, or ``(code, values...)``)."""
    sig = inspect.Signature([_param(t) for t in ("self", *(a.strip() for a in args.split(",") if a.strip()))],
                            **({"return_annotation": "int"} if reply in ("", "w") else {}))
    convert = [_v if k == "a" else _number for k in kinds]

    def method(*a, **kw):
        bound = sig.bind(*a, **kw)
        bound.apply_defaults()
        self, *values = bound.arguments.values()
        card = None if self._card is None else self._card.kernel
        return _core.aps_command(card, name, [c(x) for c, x in zip(convert, values)])

    method.__name__, method.__qualname__, method.__doc__ = name, f"ApsController.{name}", doc
    method.__signature__ = sig  # type: ignore[attr-defined]
    method.__annotations__ = {"return": "int"} if reply in ("", "w") else {}
    return method


_SHAPES = {name: (kinds, reply) for name, kinds, reply in _core.APS_COMMAND_SHAPES}
for _name, _args, _doc in (*_core.APS_COMMANDS, *_core.APS_ARC_COMMANDS):  # the generator: the runner's rows
    if _name in _SHAPES:
        setattr(ApsController, _name, _runner_function(_name, _args, _doc, *_SHAPES[_name]))

for _mixin in (_ApsScope, _ApsPointTable, _ApsMore):  # the blocks' functions are ApsController methods
    for _name, _fn in list(vars(_mixin).items()):
        if callable(_fn) and not _name.startswith("__"):
            setattr(ApsController, _name, _fn)
for _name, _args, _doc in _core.APS_COMMANDS:  # what each function does: the C++ table's row (AX2)
    getattr(ApsController, _name).__doc__ = _doc

#: Functions the simulation cannot carry out: they return the vendor's error code (issue 25.3).
UNSUPPORTED = {
    "APS_pt_set_trans_inp": "the card's interpolation has no in-position transition (its seven modes, L3085-3143): "
                            "ERR_FunctionNotAvailable, the table keeps its mode (AF8)",
}


_default = ApsController()
APS_FUNCTIONS: tuple[str, ...] = export_functions(globals(), _default, "APS_")


def Sleep(ms: float):
    """The examples' ``Sleep(ms)``: runs the open card ``ms`` milliseconds (rounded to whole servo ticks)."""
    return _default.Sleep(ms)


def use_machine(machine) -> None:
    """The simulated machine a vendor program's ``APS_initial`` opens (a Card or a factory; None forgets it):
    :meth:`~servobench.dialects._controller.DialectController.use_machine` of the default controller."""
    _default.use_machine(machine)


def vao_output(ctrl: int) -> dict:
    """Simulation helper: what PWM ``ctrl`` (0..1) of the open card outputs now (:meth:`ApsController.vao_output`)."""
    return _default.vao_output(ctrl)


# The vendor's names (return codes, PRA_* parameter numbers, the other header constants, the APS_* functions) and
# the simulation helpers; numpy and the package internals stay out of ``from ... import *`` and completion.
__all__ = ["ApsController", "APS_FUNCTIONS", "Sleep", "card", "controller", "run", "wait_until", "use_machine",
           "vao_output", "UNSUPPORTED", "PTSTS", "PTLINE", "PTA2CA", "PTA2CE", "PTHCA", "PTHCE", "PTDWL",
           *sorted(n for n in dict(globals()) if n.split("_")[0] in (
               "ERR", "PRA", "MF", "STOP", "STR", "TGR", "TIMR", "TRG", "MTS", "MIO", "PRB", "PRS", "VAO", "WDT",
               "ITP", "SAMP", "PT", "PTB")),
           *APS_FUNCTIONS]
