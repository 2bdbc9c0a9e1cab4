"""The simulated axis and the record of a run."""

from __future__ import annotations

__all__ = ["Axis", "AxisRun", "SIGNALS", "SIGNAL_UNITS", "controller_signature"]

from dataclasses import dataclass, field
from typing import Iterable, Mapping

import numpy as np

from . import _checks, _core
from ._serialise import JsonResult, dataframe
from .trajectory import Trajectory

#: Names of the signals an axis records every tick, in order.
SIGNALS: tuple[str, ...] = tuple(name for name, _unit, _doc in _core.TRACE_SIGNALS)
#: The signals :meth:`Axis.run` records when ``signals`` is not given (decision P17): time, command, feedback,
#: following error, the law's output and the DAC voltage. Every other signal of :data:`SIGNALS` is still there on
#: request: read it (``run.current_a``) and the run is replayed once, exactly, from a copy of the axis taken before
#: it, recording all signals; ``signals="all"`` records them all at once.
DEFAULT_SIGNALS: tuple[str, ...] = ("time_s", "cmd_pos", "fb_pos", "error", "u", "volts")
#: Unit of each signal.
SIGNAL_UNITS: dict[str, str] = {name: unit for name, unit, _doc in _core.TRACE_SIGNALS}
_SIGNAL_DOCS: dict[str, str] = {name: doc for name, _unit, doc in _core.TRACE_SIGNALS}


@dataclass(frozen=True)
class AxisRun(JsonResult):
    """What an axis recorded during :meth:`Axis.run`: one NumPy array per signal, one sample per tick.

    Signals (attribute names) and units:

    ``time_s`` s; ``cmd_pos`` pulse; ``cmd_vel`` pulse/tick; ``cmd_acc`` pulse/tick^2; ``fb_pos`` pulse;
    ``error`` pulse (cmd_pos - fb_pos); law terms ``p``, ``i``, ``d``, ``vff``, ``aff``, ``bias`` and the law
    output ``u`` in DAC counts; biquad outputs ``biquad0``, ``biquad1`` in counts; ``volts`` V (computed at
    the tick, applied from the next); ``current_a`` A; ``torque_nm`` N*m; ``angle_rad`` rad; ``speed_rad_s`` rad/s
    (motor); ``load_angle_rad`` rad; ``load_speed_rad_s`` rad/s; flags (0/1): ``alarm`` (drive alarm), ``index``
    (encoder index passed since the previous tick), ``home_sw``, ``pos_limit_sw``, ``neg_limit_sw``.
    Mechanical signals are sampled at the instant the encoder is read.

    ``signals`` holds what was recorded (by default :data:`DEFAULT_SIGNALS`); a run recorded with the default set
    gives every other signal too when it is read (``run.current_a``, ``run["p"]``): the run is then replayed once
    from a copy of the axis taken before it, with all signals recorded, and checked to reproduce the feedback
    exactly (decision P17).
    """

    signals: Mapping[str, np.ndarray]
    servo_period_s: float
    law: object = field(default=None, repr=False)
    #: Why the run ended early: ``None`` (it ran every tick), ``"error_limit"`` (``|error|`` exceeded
    #: ``error_limit_pulse``) or ``"drive_alarm"``; the servo was then turned off at the last recorded tick.
    stopped: str | None = None
    #: The following error (pulse) at the tick that tripped the error limit.
    stop_error_pulse: float = 0.0
    _replay: object = field(default=None, repr=False, compare=False)
    _more: dict = field(default_factory=dict, repr=False, compare=False)

    def _signal(self, name: str) -> np.ndarray | None:
        try:
            signals = object.__getattribute__(self, "signals")
            more = object.__getattribute__(self, "_more")
            replay = object.__getattribute__(self, "_replay")
        except AttributeError:  # not initialised yet (copy, unpickling)
            return None
        if name in signals:
            return signals[name]
        if name in more:
            return more[name]
        if name in SIGNAL_UNITS and replay is not None:
            more.update({k: v for k, v in replay(signals["fb_pos"]).items() if k not in signals})
            object.__setattr__(self, "_replay", None)
            return more.get(name)
        return None

    def __getattr__(self, name: str) -> np.ndarray:
        sig = self._signal(name)
        if sig is not None:
            return sig
        if name in SIGNAL_UNITS:
            raise AttributeError(f"signal '{name}' was not recorded in this run (see Axis.run(signals=...))")
        raise AttributeError(name)

    def __getitem__(self, name: str) -> np.ndarray:
        sig = self._signal(name)
        if sig is None:
            raise KeyError(name)
        return sig

    def __len__(self) -> int:
        return len(next(iter(self.signals.values()))) if self.signals else 0

    def __repr__(self) -> str:
        n = len(self)
        return (f"AxisRun({n} ticks = {n * self.servo_period_s:.6g} s at Ts = {self.servo_period_s * 1e6:.6g} us, "
                f"signals: {', '.join(self.signals)})")

    @property
    def units(self) -> dict[str, str]:
        """Unit of each signal this run gives: the recorded ones, and for a default run every other signal too
        (read on request, see the class docstring)."""
        more = [k for k in SIGNALS if k not in self.signals and (self._replay is not None or k in self._more)]
        return {k: SIGNAL_UNITS[k] for k in [*self.signals, *more]}

    def to_dict(self) -> dict[str, np.ndarray]:
        """The recorded signals as a plain dict of arrays."""
        return dict(self.signals)

    def to_dataframe(self):
        """The recorded signals as a pandas DataFrame, one row per tick (index ``tick``), one column per signal;
        ``df.attrs["units"]`` gives each column's unit. :meth:`to_json` writes the run as standard JSON."""
        df = dataframe(dict(self.signals), self.units)
        df.index.name = "tick"
        return df

    def metrics(self, **kwargs):
        """Move metrics of this run; see :func:`servobench.move_metrics`."""
        from .metrics import move_metrics

        return move_metrics(self, **kwargs)

    def plot(self, **kwargs):
        """Draws the response (position, following error, volts); see :func:`servobench.plot.response`."""
        from .plot import response

        return response(self, **kwargs)


class Axis:
    """One simulated servo axis: servo law -> biquad 0 -> biquad 1 -> DAC -> drive -> plant -> encoder.

    Parameters (keyword only; each part is a validated parameter object):

    law
        :class:`GtServoLaw` (default, the GT manual's defaults) or :class:`ApsServoLaw`.
    drive
        :class:`TorqueDrive` (V -> A -> N*m) or :class:`VelocityDrive` (V -> rad/s command, own PI loop);
        for a pulse-output card :class:`StepperDrive` or :class:`ServoPositionDrive`, fed with the command
        position as a step train of whole pulses (the servo law and the DAC are then bypassed).
    plant
        :class:`RigidPlant` or :class:`TwoMassPlant` (kg*m^2, N*m/rad, N*m*s/rad, N*m).
    encoder
        :class:`Encoder` (counts per revolution, noise, index, motor or load mounting).
    dac
        :class:`Dac` (16-bit +-10 V by default).
    switches
        :class:`Switches` (home and limit switch positions along the load, rad).
    servo_period_s
        servo period Ts in s; ``None`` takes the card's default (GT 200 us, ADLINK 250 us). The range is the
        card's: GT 48..1966.08 us, ADLINK 50..2000 us.
    substeps
        integration sub-steps per tick (1..1000); the linear dynamics are exact for any value, more sub-steps
        resolve friction events more finely. A velocity-mode drive multiplies them by its speed-loop updates per
        tick.
    filters
        the two biquads after the law, ``(f0, f1)``; each ``None`` (the card's pass-through, B0 = DIV = 1), a
        :class:`FloatBiquad` or an :class:`AdlinkBiquad` (see :mod:`servobench.design`). Each must be stable, and a
        filter bound to a sample time must be bound to this axis's servo period. Their outputs are recorded as
        ``biquad0`` and ``biquad1`` (counts).

    The controller output computed at tick k reaches the drive at tick k+1 (one-tick computation delay).
    Every :meth:`run` starts from the axis's initial state -- power-on, or the state the last :meth:`reset` set --
    so running a notebook cell twice gives the same answer; ``run(..., continue_=True)`` continues from where the
    last run or :meth:`step` left the axis instead (decision P18). :meth:`step` always continues.

    Thread safety: an Axis may be shared between threads. One run at a time: a second :meth:`run` (or a
    :class:`~servobench.Card` run using this axis) waits until the first has finished; every other call waits
    at most for the running chunk (about 20 ms of work), so the axis's state can be read while it runs.
    """

    def __init__(self, *, law=None, drive=None, plant=None, encoder=None, dac=None, switches=None,
                 servo_period_s=None, substeps: int = 1, filters=None):
        self._axis = _core.Axis(
            law=_core.GtServoLaw() if law is None else law,
            drive=_core.TorqueDrive() if drive is None else drive,
            plant=_core.RigidPlant() if plant is None else plant,
            encoder=_core.Encoder() if encoder is None else encoder,
            dac=_core.Dac() if dac is None else dac,
            switches=_core.Switches() if switches is None else switches,
            servo_period_s=servo_period_s,
            substeps=substeps,
            filters=filters,
        )
        self._start = (0.0, 0.0, 0.0, 0.0, True)  # the initial state run() starts from (see reset)
        if type(self).step is Axis.step:  # ax.step is the binding itself: one dispatch per call (decision FV10)
            self.step = self._axis.step

    # -- parts ------------------------------------------------------------------------------------
    law = property(lambda self: self._axis.law, doc="The active servo-law parameters.")
    drive = property(lambda self: self._axis.drive, doc="The drive parameters.")
    plant = property(lambda self: self._axis.plant, doc="The plant parameters.")
    encoder = property(lambda self: self._axis.encoder, doc="The encoder parameters.")
    dac = property(lambda self: self._axis.dac, doc="The DAC parameters.")
    switches = property(lambda self: self._axis.switches, doc="The switch positions.")
    servo_period_s = property(lambda self: self._axis.servo_period_s, doc="Servo period Ts, s.")
    substeps = property(lambda self: self._axis.substeps, doc="Plant integration sub-steps per tick.")
    filters = property(lambda self: self._axis.filters, doc="The two biquads (f0, f1) after the law.")
    tick = property(lambda self: self._axis.tick, doc="Ticks run since power-on/reset.")
    feedback_pulse = property(lambda self: self._axis.feedback_pulse, doc="Encoder reading now, pulse.")
    angle_rad = property(lambda self: self._axis.angle_rad, doc="Motor angle now, rad.")
    speed_rad_s = property(lambda self: self._axis.speed_rad_s, doc="Motor speed now, rad/s.")
    load_angle_rad = property(lambda self: self._axis.load_angle_rad, doc="Load angle now, rad.")
    load_speed_rad_s = property(lambda self: self._axis.load_speed_rad_s, doc="Load speed now, rad/s.")
    alarm = property(lambda self: self._axis.alarm, doc="True once the drive alarm has tripped.")
    mechanical_energy_j = property(lambda self: self._axis.mechanical_energy_j,
                                   doc="Kinetic energy of the bodies plus the shaft's spring energy now, J.")
    substeps_per_tick = property(lambda self: self._axis.substeps_per_tick,
                                 doc="Integration sub-steps actually taken per tick.")

    @property
    def default_error_limit_pulse(self) -> float:
        """The least following-error limit :meth:`run` applies by default, pulse: 2 revolutions of the encoder
        (2 x ``encoder.counts_per_rev``); a run whose command goes further from where the axis stands gets twice
        that distance instead. No tuned axis lags by that much; a loop that does has lost control (decision RB4)."""
        return 2.0 * float(self.encoder.counts_per_rev)

    def __repr__(self) -> str:
        return (f"Axis(law={self.law!r}, drive={self.drive!r}, plant={self.plant!r}, encoder={self.encoder!r}, "
                f"dac={self.dac!r}, switches={self.switches!r}, servo_period_s={self.servo_period_s!r}, "
                f"substeps={self.substeps}, filters={self.filters!r})")

    # -- control ----------------------------------------------------------------------------------
    def reset(self, angle_rad: float = 0.0, *, speed_rad_s: float = 0.0, load_angle_rad: float | None = None,
              load_speed_rad_s: float | None = None) -> None:
        """Power-on state (law memories cleared, output 0 V, tick 0) with the mechanics where you put them: motor
        angle `angle_rad` (rad, -1e6..1e6) and speed `speed_rad_s` (rad/s, -1e6..1e6); on a two-mass plant the
        load's angle and speed (default: the motor's). A body at rest starts held by its static friction. A rigid
        plant has one body: a load state different from the motor's is a ValueError."""
        a = _checks.real("Axis.reset", "angle_rad", angle_rad, -1e6, 1e6, unit="rad")
        w = _checks.real("Axis.reset", "speed_rad_s", speed_rad_s, -1e6, 1e6, unit="rad/s")
        la = a if load_angle_rad is None else _checks.real("Axis.reset", "load_angle_rad", load_angle_rad,
                                                           -1e6, 1e6, unit="rad")
        lw = w if load_speed_rad_s is None else _checks.real("Axis.reset", "load_speed_rad_s", load_speed_rad_s,
                                                             -1e6, 1e6, unit="rad/s")
        if not isinstance(self.plant, _core.TwoMassPlant) and (la != a or lw != w):
            raise ValueError(f"Axis.reset: load_angle_rad = {la}, load_speed_rad_s = {lw} differ from the motor's, but "
                             "a rigid plant has one body (leave them out)")
        plain = w == 0.0 and load_speed_rad_s is None and load_angle_rad is None
        self._start = (a, w, la, lw, plain)
        self._restart()

    def _restart(self) -> None:
        """Returns the axis to its initial state (the last reset's, or power-on), keeping its configuration: law,
        filters and the servo on/off setting."""
        a, w, la, lw, plain = self._start
        on = self._axis.servo_on
        if plain:
            self._axis.reset(a)  # the power-on reset, unchanged
        else:
            self._axis.reset_state(a, w, la, lw)
        if not on:
            self._axis.set_servo_on(False)

    def set_law(self, law) -> None:
        """Replaces the servo-law parameters from the next tick on (the card's Update)."""
        self._axis.set_law(law)

    def set_filters(self, filters) -> None:
        """Replaces both biquads' coefficients from the next tick on, ``(f0, f1)`` as in the constructor; their
        histories are kept (the card's parameter update)."""
        self._axis.set_filters(filters)

    servo_on = property(lambda self: self._axis.servo_on,
                        doc="True while the servo loop is closed (the card's servo ON / GT_AxisOn).")
    last_command_pulse = property(lambda self: self._axis.last_command_pulse,
                                  doc="Command position of the last tick run, pulse (the feedback before any run).")

    def set_servo_on(self, on: bool) -> None:
        """Servo on (True) or off (False). Off: the law is not evaluated and the output is 0 V (plus any injection);
        on again: the law and the filters restart from power-on memories (the card's GT_AxisOn / servo ON)."""
        self._axis.set_servo_on(_checks.flag("Axis.set_servo_on", "on", on))

    def step(self, command_pulse: float, n: int = 1, *, volts: float | None = None) -> float:
        """Advances `n` servo ticks holding the command position `command_pulse` (pulse) and returns the feedback
        read by the encoder at the last of them (pulse); nothing is recorded. The step API for programs in the loop
        (co-simulation, reinforcement learning): ``fb = axis.step(cmd)`` once per tick costs under a microsecond
        above the tick itself (``bench/results/batch.md``). From 1024 ticks on, a step is a run: it releases the GIL,
        waits for another thread's run of this axis and answers Ctrl-C between chunks of about 20 ms.

        volts
            if given, this voltage (V) replaces the servo law's output (and the biquads) for these ticks: a
            controller written in Python reads the feedback, computes the voltage and steps; it reaches the drive one
            tick later like the law's output.

        The ticks are exactly those :meth:`run` makes over the same commands (the state carries on between calls;
        a :meth:`run` after steps starts from the initial state again unless ``continue_=True``).
        """
        return self._axis.step(command_pulse, n, volts=volts)  # the checks are the binding's (axis_step)

    def run(self, command, *, velocities=None, accelerations=None, signals: Iterable[str] | None = None,
            injection_v=None, error_limit_pulse: float | str | None = "auto", stop_on_alarm: bool = False,
            controller=None, controller_state=None, continue_: bool = False) -> AxisRun:
        """Runs one servo tick per command sample and returns what was recorded.

        The run starts from the axis's initial state (power-on, or the last :meth:`reset`'s state), with the
        axis's present law, filters and servo on/off setting: the same call gives the same run every time.
        ``continue_=True`` continues from where the last run or :meth:`step` left the axis (its mechanics, law
        memories, filters, tick count).

        command
            command positions in pulse, one per tick (array-like), or a :class:`Trajectory` (whose velocities
            and accelerations are then used too).
        velocities, accelerations
            optional profile velocity (pulse/tick) and acceleration (pulse/tick^2) per tick, fed to the GT law's
            Kvff/Kaff terms; by default backward differences of the positions. The ADLINK law always uses the
            differences, as its manual defines CmdVel and CmdAcc.
        signals
            names of the signals to record (see :data:`SIGNALS`), or ``"all"``; fewer is faster. Default: the small
            set :data:`DEFAULT_SIGNALS` (time, command, feedback, error, law output, volts), every other signal
            still readable from the result (the run is replayed once, exactly, when one is first read); with a
            ``controller`` the default is all signals (a replay would call the controller again).
        injection_v
            optional voltage added to the controller's output before the DAC, V, one per tick (an injection at the
            plant input, for open-loop and disturbance-injection experiments; with the servo off it is the whole
            output). Like the law's output it reaches the drive one tick later.
        error_limit_pulse
            position-error protection (ADLINK ERR_POS_LEVEL, the Bode tool's deviation limit), pulse. Default
            ``"auto"``: the larger of :attr:`default_error_limit_pulse` (2 revolutions of the encoder) and twice
            the command's largest distance from the axis's position, so an unstable design stops instead of
            running away; ``None`` or 0 = off. When ``|cmd_pos - fb_pos|`` exceeds it (or is not
            a finite number) while the servo is on, the servo is turned off at that tick and the run ends there:
            :attr:`AxisRun.stopped` is ``"error_limit"`` and the arrays end at that tick.
        stop_on_alarm
            end the run, servo off, at the first tick with the drive alarm set (``stopped = "drive_alarm"``).
        controller
            a user-written controller in place of the servo law and the biquads, called every tick after the encoder
            read; it returns the voltage request (V) for the DAC (reaching the drive one tick later). Either a Python
            callable ``controller(tick, cmd_pulse, fb_pulse) -> volts`` (tick: index in this run; called with the
            GIL, so at Python speed), or a compiled C function ``double f(int64 tick, double cmd_pulse,
            double fb_pulse, double *state)`` run inside the C++ loop at full speed: a ``numba.cfunc`` (its
            ``.address`` is used), a ``ctypes`` function pointer or a raw address (int). See
            :func:`servobench.controller_signature`.
        controller_state
            for a compiled controller: a float64 NumPy array passed as ``state`` (read and updated in place; its
            memories, gains ...). ``None`` passes a null pointer.

        Releases the GIL while it runs. One run at a time per axis: a second thread's run (or any other call on
        this axis, or a card run using it) waits for it. Ctrl-C raises KeyboardInterrupt within about 20 ms; the
        axis then stands at the last whole tick it ran (its state is consistent; the recording is discarded).
        A run may record at most 2 GB (ticks x signals x 8 bytes), checked before allocating.
        """
        if isinstance(command, Trajectory):
            positions = command.pos
            velocities = command.vel if velocities is None else velocities
            accelerations = command.acc if accelerations is None else accelerations
        else:
            positions = command
        positions = np.asarray(positions, dtype=float)
        if positions.ndim == 0:
            raise ValueError("command must be a 1-D array of positions (pulse), one per tick")
        py_controller, address = _controller_hook(controller)
        if controller_state is not None and (not isinstance(controller_state, np.ndarray)
                                             or controller_state.dtype != np.float64
                                             or not controller_state.flags.c_contiguous
                                             or not controller_state.flags.writeable):
            raise TypeError("controller_state must be a writeable, C-contiguous float64 NumPy array")
        if controller_state is not None and address == 0:
            raise ValueError("controller_state is for a compiled controller (a numba cfunc or a C function pointer)")
        lo_hi = undo = None
        if not _checks.flag("Axis.run", "continue_", continue_):
            # A call that fails its checks leaves the axis as it was: check the inputs first, then restart.
            _checks.error_limit("Axis.run", "error_limit_pulse", error_limit_pulse, self, 0.0)
            _checks.flag("Axis.run", "stop_on_alarm", stop_on_alarm)
            n = positions.shape[0] if positions.ndim == 1 else -1
            # Shapes here; the binding checks every sample finite block by block as the run goes and, on a bad one,
            # puts the axis back as `undo` (decisions SP5, SQ1). The positions' extremes give the error limit's span.
            lo_hi = _precheck("positions", positions, n, extremes=True)
            for name, x in (("velocities", velocities), ("accelerations", accelerations), ("injection_v", injection_v)):
                if x is not None:
                    _precheck(name, x, n)
            undo = self._axis.copy()
            self._restart()
        fb = self.feedback_pulse  # the command's largest distance from here, without a temporary array
        if positions.size:
            lo, hi = lo_hi if lo_hi is not None else (float(positions.min()), float(positions.max()))
            span = max(abs(hi - fb), abs(lo - fb))
        else:
            span = 0.0
        limit = _checks.error_limit("Axis.run", "error_limit_pulse", error_limit_pulse, self,
                                    span if np.isfinite(span) else 0.0)
        stop_alarm = _checks.flag("Axis.run", "stop_on_alarm", stop_on_alarm)
        replay = None
        if isinstance(signals, str):
            if signals != "all":
                raise ValueError(f"signals = {signals!r}: give a list of signal names or 'all'")
            wanted = None
        elif signals is not None:
            wanted = list(signals)
        elif controller is not None:
            wanted = None  # a replay would call the user's controller again
        else:
            wanted = list(DEFAULT_SIGNALS)
            replay = _Replay(self._axis.copy(), velocities, accelerations, injection_v, limit, stop_alarm)
        rec, stop, stop_error = self._axis.run(positions, velocities, accelerations, wanted, injection_v,
                                               limit, stop_alarm, py_controller, address, controller_state, undo)
        if replay is not None:
            replay.command = rec["cmd_pos"]
        return AxisRun(signals=rec, servo_period_s=self.servo_period_s, law=self.law, stopped=stop or None,
                       stop_error_pulse=float(stop_error), _replay=replay)


def _precheck(name: str, x, n: int, extremes: bool = False) -> tuple[float, float] | None:
    """The binding's shape checks of a run's input array (1-D, n samples), made before the axis restarts; with
    `extremes`, also finite, and returns the array's (min, max) (None if empty)."""
    try:
        a = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a 1-D array of numbers") from None
    if a.ndim != 1:
        raise ValueError(f"{name} must be 1-D, got {a.ndim} dimensions")
    if n >= 0 and a.shape[0] != n:
        raise ValueError(f"{name} has {a.shape[0]} samples; expected {n} (one per tick, like the positions)")
    if not (extremes and a.size):
        return None
    lo, hi = float(a.min()), float(a.max())
    if not (np.isfinite(lo) and np.isfinite(hi)):  # min/max carry NaN: no temporary array
        k = int(np.flatnonzero(~np.isfinite(a))[0])
        raise ValueError(f"{name}[{k}] = {a[k]} is not a finite number")
    return lo, hi


class _Replay:
    """The rest of a default run's signals, on request: the same run again from a copy of the axis taken before
    it, every signal recorded (decision P17). The optional arrays are copied, so changing them later changes
    nothing; the positions are the run's own recorded cmd_pos."""

    def __init__(self, axis_copy, velocities, accelerations, injection_v, limit, stop_on_alarm):
        own = lambda x: None if x is None else np.array(x, dtype=float, copy=True)  # noqa: E731
        self.axis = axis_copy
        self.vel, self.acc, self.inj = own(velocities), own(accelerations), own(injection_v)
        self.limit, self.stop_on_alarm = limit, stop_on_alarm
        self.command = None

    def __call__(self, fb_pos: np.ndarray) -> dict:
        n = len(self.command)
        cut = lambda x: None if x is None else x[:n]  # noqa: E731
        rec, _stop, _err = self.axis.run(self.command, cut(self.vel), cut(self.acc), None, cut(self.inj),
                                         self.limit, self.stop_on_alarm, None, 0, None)
        if not np.array_equal(rec["fb_pos"], fb_pos):
            raise RuntimeError("AxisRun: the replay of this run did not reproduce its feedback; record the signals "
                               "you need with Axis.run(signals=...)")
        return rec


def controller_signature() -> str:
    """The C signature of a compiled controller for :meth:`Axis.run` (``controller=``): returns the voltage request
    (V) from the tick index in the run, the command and the feedback (pulse) and a pointer to the caller's float64
    state array. With numba: ``numba.cfunc("float64(int64, float64, float64, CPointer(float64))")``."""
    return "double controller(int64_t tick, double cmd_pulse, double fb_pulse, double *state)"


def _controller_hook(controller):
    """(python callable or None, C function address or 0) for Axis.run's `controller`."""
    import ctypes

    if controller is None:
        return None, 0
    if isinstance(controller, (int, np.integer)) and not isinstance(controller, bool):
        if controller <= 0:
            raise ValueError(f"controller address = {controller} must be a positive C function address")
        return None, int(controller)
    cfunc_ctypes = getattr(controller, "ctypes", None)  # numba.cfunc: check its signature, use its address
    if hasattr(controller, "address") and isinstance(cfunc_ctypes, ctypes._CFuncPtr):
        _check_c_signature(cfunc_ctypes)
        return None, int(controller.address)
    if isinstance(controller, ctypes._CFuncPtr):
        _check_c_signature(controller)
        return None, int(ctypes.cast(controller, ctypes.c_void_p).value)
    if callable(controller):
        return controller, 0
    raise TypeError(f"controller must be a callable, a numba cfunc, a ctypes function pointer or an address, "
                    f"got {type(controller).__name__}")


def _check_c_signature(fn) -> None:
    import ctypes

    args = getattr(fn, "argtypes", None)
    res = getattr(fn, "restype", None)
    if args is None:
        return  # a bare ctypes pointer without declared types: the caller vouches for it
    if res is not ctypes.c_double or len(args) != 4 or args[1] is not ctypes.c_double or args[2] is not ctypes.c_double:
        raise TypeError("compiled controller has the wrong signature; expected " + controller_signature())
