"""python-control both ways (issue 23.3-23.4, docs/lti-plant.md): your own linear plant into the loop
(:func:`lti_plant`, also ``LtiPlant.from_control``) and every servobench part out as a python-control system
(:func:`to_control`, also a ``to_control()`` method on the laws, biquads, plants and :class:`~servobench.Axis`), and
frequency-response data both ways (:func:`to_frd`, :func:`from_frd`).

Units (decisions LT4-LT7):

- laws: C(z) from the position error E (pulse) to the law output (DAC counts, 32767 counts = 10 V), discrete with
  ``dt`` = the servo period (s), the card's exact per-tick law (the same z-transfer :func:`~servobench.frequency.
  analytic_response` uses);
- biquads: F(z), counts/counts, ``dt`` = the filter's own sample time or the servo period you give;
- plants: continuous state space from the motor torque (N*m) to the angle (rad) -- motor or load side; with
  ``servo_period_s`` its zero-order-hold discretisation at that period (what a sampled loop sees, without the
  one-tick output delay);
- the loop (an :class:`~servobench.Axis`): discrete, ``dt`` = its servo period, from DAC counts to encoder pulses
  with the one-tick output delay (:func:`~servobench.frequency.linear_model`);
- FRD: frequencies in rad/s inside ``control.FRD`` (its convention), in Hz everywhere in servobench.

python-control is needed only here (the ``control`` extra: ``pip install servobench[control]``).
"""

from __future__ import annotations

import numpy as np

from . import _core

__all__ = ["from_frd", "lti_plant", "to_control", "to_frd"]

_LAWS = (_core.GtServoLaw, _core.ApsServoLaw)
_BIQUADS = (_core.FloatBiquad, _core.AdlinkBiquad)
_PLANTS = (_core.RigidPlant, _core.TwoMassPlant, _core.LtiPlant)


def _control():
    try:
        import control
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("servobench.interop needs python-control: pip install 'servobench[control]'") from exc
    return control


def _period(owner: str, servo_period_s, *, required: bool) -> float | None:
    if servo_period_s is None:
        if required:
            raise ValueError(f"{owner}: servo_period_s = None; give the sample time in s (> 0)")
        return None
    if isinstance(servo_period_s, bool) or not isinstance(servo_period_s, (int, float, np.floating, np.integer)):
        raise TypeError(f"{owner}: servo_period_s = {servo_period_s!r} must be a number of seconds (> 0) or None")
    ts = float(servo_period_s)
    if not (np.isfinite(ts) and 0 < ts <= 1.0):
        raise ValueError(f"{owner}: servo_period_s = {servo_period_s!r} must be finite, in (0, 1] s")
    return ts


# ---------------------------------------------------------------------------------------------------------------
# Into servobench
# ---------------------------------------------------------------------------------------------------------------
def lti_plant(system, *, lead_m_per_rev: float = 0.0, **friction) -> "_core.LtiPlant":
    """An :class:`LtiPlant` from a continuous single-input single-output python-control system
    (``control.TransferFunction`` or ``control.StateSpace``, ``dt`` = 0) or an ``(A, B, C, D)`` tuple of arrays.

    system
        the plant from the motor torque (N*m) to the encoder angle (rad); with ``lead_m_per_rev`` > 0, a linear
        axis from force (N) to position (m) behind an ideal screw of that lead (m/rev). Strictly proper with
        relative degree >= 2 (a torque accelerates), at most 7 states; a transfer function is realised by
        ``control.ss`` (scipy's ``tf2ss``). It is discretised exactly (zero-order hold) at every integration
        sub-step of the simulation, so give it in continuous time.
    friction
        the :class:`LtiPlant` keywords ``coulomb_nm``, ``static_nm``, ``stribeck_speed_rad_s``,
        ``stribeck_exponent``, ``coulomb_asym_nm`` (dry friction at the motor, N*m, rad/s) and ``load_nm`` (N*m).

    ValueError (naming the parameter) for a discrete, MIMO, improper, relative-degree-1 or too large system;
    unstable plants are accepted (see ``LtiPlant.stability``)."""
    if isinstance(system, tuple):
        if len(system) != 4:
            raise ValueError(f"system: a tuple must be (A, B, C, D), got {len(system)} items")
        a, b, c, d = (np.atleast_2d(np.asarray(m, dtype=float)) for m in system)
    else:
        control = _control()
        if not isinstance(system, control.LTI):
            raise TypeError(f"system must be a control.TransferFunction, a control.StateSpace or an (A, B, C, D) "
                            f"tuple, got {type(system).__name__}")
        if system.ninputs != 1 or system.noutputs != 1:
            raise ValueError(f"system has {system.ninputs} inputs and {system.noutputs} outputs; an LtiPlant has one "
                             "of each (motor torque in, encoder angle out)")
        if system.dt not in (0, None):
            raise ValueError(f"system.dt = {system.dt!r}: give the continuous plant (dt = 0); servobench discretises "
                             "it exactly at its integration step")
        if isinstance(system, control.TransferFunction):
            num, den = np.atleast_1d(np.squeeze(system.num[0][0])), np.atleast_1d(np.squeeze(system.den[0][0]))
            num = np.trim_zeros(num, "f") if np.any(num) else np.zeros(1)
            rel = len(np.trim_zeros(den, "f")) - len(num)
            if rel < 2:
                raise ValueError(f"system: relative degree {rel} (numerator degree {len(num) - 1}, denominator "
                                 f"degree {len(np.trim_zeros(den, 'f')) - 1}); the torque-to-angle plant needs >= 2 "
                                 "(a torque accelerates; decision LT1)")
        ss = control.ss(system)
        a, b, c, d = (np.atleast_2d(np.asarray(m, dtype=float)) for m in (ss.A, ss.B, ss.C, ss.D))
    if d.size != 1:
        raise ValueError(f"system: D has shape {d.shape}; a single-input single-output plant has a 1 x 1 D")
    return _core.LtiPlant(a=a, b=b, c=c, d=float(d.ravel()[0]), lead_m_per_rev=lead_m_per_rev, **friction)


def from_frd(frd, *, servo_period_s: float, which: str = "open_loop"):
    """A :class:`~servobench.frequency.FrequencyResponse` from a python-control ``FRD`` (frequencies in rad/s),
    e.g. a loop measured elsewhere, for servobench's margins, plots and frequency-domain identification.

    which
        what the FRD holds: ``"open_loop"`` (the loop gain, pulse/pulse; the closed loop is computed as L/(1 + L))
        or ``"plant"`` (DAC counts -> encoder pulses, as servobench's sweeps measure it). The other responses are
        NaN.
    servo_period_s
        the loop's servo period, s (the data must lie below its Nyquist frequency)."""
    control = _control()
    from .frequency import FrequencyResponse

    if not isinstance(frd, control.FrequencyResponseData):
        raise TypeError(f"frd must be a control.FRD, got {type(frd).__name__}")
    if frd.ninputs != 1 or frd.noutputs != 1:
        raise ValueError(f"frd has {frd.ninputs} inputs and {frd.noutputs} outputs; expected one of each")
    if which not in ("open_loop", "plant"):
        raise ValueError(f"which = {which!r} must be 'open_loop' or 'plant'")
    ts = _period("from_frd", servo_period_s, required=True)
    w = np.asarray(frd.omega, dtype=float)
    h = np.asarray(frd.fresp, dtype=complex).reshape(-1)
    f = w / (2 * np.pi)
    if f.size < 2 or np.any(~np.isfinite(f)) or np.any(f <= 0) or np.any(np.diff(f) <= 0):
        raise ValueError("frd.omega must hold at least 2 increasing frequencies > 0, rad/s")
    if f[-1] >= 0.5 / ts:
        raise ValueError(f"frd.omega reaches {w[-1]:.6g} rad/s = {f[-1]:.6g} Hz, not below the Nyquist frequency "
                         f"{0.5 / ts:.6g} Hz of servo_period_s = {ts}")
    nan = np.full(f.shape, np.nan + 0j)
    if which == "open_loop":
        return FrequencyResponse(freq_hz=f, plant=nan, open_loop=h, closed_loop=h / (1 + h), method="FRD",
                                 servo_period_s=ts)
    return FrequencyResponse(freq_hz=f, plant=h, open_loop=nan, closed_loop=nan.copy(), method="FRD",
                             servo_period_s=ts)


# ---------------------------------------------------------------------------------------------------------------
# Out of servobench
# ---------------------------------------------------------------------------------------------------------------
def to_frd(response, which: str = "open_loop", *, usable_only: bool = False):
    """A :class:`~servobench.frequency.FrequencyResponse` (measured or analytic) as a python-control ``FRD``, the
    frequencies in rad/s (2 pi f). usable_only: leave out the points the sweep's judge flagged."""
    control = _control()
    h = np.asarray(response.response(which))
    f = np.asarray(response.freq_hz, dtype=float)
    if usable_only:
        ok = np.asarray(response.usable, dtype=bool)
        h, f = h[ok], f[ok]
    return control.frd(h, 2 * np.pi * f)


def _law_tf(law, ts, part):
    control = _control()
    if isinstance(law, _core.GtServoLaw):
        kp, ki, kd = law.kp, (0.0 if law.ilmt == 0 else law.ki / 256.0), law.kd
        kvff, kaff = law.kvff, law.kaff
    else:
        g = law.effective_gains()
        kp, kd, kvff, kaff = g["kp"], g["kd"], g["kvff"], g["kaff"]
        ki = 0.0 if law.integral_limit == 0 else g["ki"]
    if part == "feedback":
        # C(z) = kp + ki z/(z-1) + kd (z-1)/z (GT L801-803, ADLINK L1723-1731); no pole at 1 without an integral.
        if ki != 0:
            return control.tf([kp + ki + kd, -(kp + 2 * kd), kd], [1, -1, 0], ts)
        return control.tf([kp + kd, -kd], [1, 0], ts)
    if part == "feedforward":  # Cff(z) = kvff (1 - z^-1) + kaff (1 - z^-1)^2
        return control.tf([kvff + kaff, -(kvff + 2 * kaff), kaff], [1, 0, 0], ts)
    raise ValueError(f"part = {part!r} must be 'feedback' or 'feedforward'")


def _plant_ss(plant, output, ts):
    control = _control()
    a, b, c_motor, c_load = _core.plant_linear(plant)
    if output not in ("motor", "load"):
        raise ValueError(f"output = {output!r} must be 'motor' or 'load'")
    if output == "load" and not isinstance(plant, _core.TwoMassPlant):
        raise ValueError(f"output = 'load': a {type(plant).__name__} has one output (motor and load are one body "
                         "or the LtiPlant's encoder angle)")
    sys = control.ss(a, b, c_load if output == "load" else c_motor, 0)
    return sys if ts is None else control.sample_system(sys, ts, method="zoh")


def to_control(obj, *, servo_period_s: float | None = None, part: str = "feedback", output: str = "motor",
               which: str = "loop_gain", feedforward: bool = False, filters: bool = True, form: str = "ss"):
    """A servobench part as a python-control system (units in the module docstring).

    obj
        a servo law (GtServoLaw, ApsServoLaw; ``part`` = "feedback" C(z) or "feedforward" Cff(z), counts/pulse), a
        biquad (FloatBiquad, AdlinkBiquad; its integers' exact coefficients), a plant (RigidPlant, TwoMassPlant,
        LtiPlant; torque N*m -> angle rad at ``output`` "motor" or "load"), or an :class:`~servobench.Axis`
        (``which``: "loop_gain" F C P, "plant" P (DAC counts -> pulse, one-tick delay), "controller",
        "feedforward", "filters", "closed_loop" Y/R; ``feedforward`` / ``filters``: what is in the loop; ``form``
        "ss" (default: the state space of :func:`~servobench.frequency.linear_model`, the best conditioned) or
        "tf" (a transfer function multiplied from the exact parts). For margins give python-control the response
        on a dense grid, ``control.margin(control.frd(loop, omega))``: its ``margin`` on the system itself works on
        polynomials, where the loop's multiple pole at z = 1 (integrating plant, integral action) splits by
        ~1e-6 to 1e-5 and its default grid can miss the crossover (decision LT10).
    servo_period_s
        the sample time, s. Laws: None takes the card's default (GT 200 us, ADLINK 250 us). Biquads: None takes
        the filter's own ``sample_time_s`` (an error if that is 0). Plants: None gives the continuous system, a
        period its zero-order-hold discretisation. An axis uses its own period (giving another is an error)."""
    control = _control()
    if isinstance(obj, _LAWS):
        ts = _period("to_control", servo_period_s, required=False)
        if ts is None:
            ts = type(obj).DEFAULT_PERIOD_S
        return _law_tf(obj, ts, part)
    if isinstance(obj, _BIQUADS):
        q = obj.to_float() if isinstance(obj, _core.AdlinkBiquad) else obj
        ts = _period("to_control", servo_period_s, required=False)
        own = float(q.sample_time_s)
        if ts is None:
            if own == 0:
                raise ValueError("to_control: this biquad has sample_time_s = 0 (not bound to a period); give "
                                 "servo_period_s (s)")
            ts = own
        elif own != 0 and abs(own - ts) > 1e-9 * ts:
            raise ValueError(f"to_control: servo_period_s = {ts} differs from the biquad's sample_time_s = {own}")
        return control.tf([q.b0, q.b1, q.b2], [1.0, q.a1, q.a2], ts)
    if isinstance(obj, _PLANTS):
        return _plant_ss(obj, output, _period("to_control", servo_period_s, required=False))
    if hasattr(obj, "servo_period_s") and hasattr(obj, "law") and hasattr(obj, "plant"):
        from .frequency import linear_model

        if servo_period_s is not None and abs(float(servo_period_s) - obj.servo_period_s) > 1e-12:
            raise ValueError(f"to_control: servo_period_s = {servo_period_s} differs from the axis's "
                             f"{obj.servo_period_s} s (an axis exports at its own period)")
        systems = linear_model(obj, feedforward=feedforward, filters=filters)
        if which not in systems:
            raise ValueError(f"which = {which!r} must be one of {', '.join(systems)}")
        if form == "ss":
            return systems[which]
        if form != "tf":
            raise ValueError(f"form = {form!r} must be 'tf' or 'ss'")
        return _loop_tf(obj, which, feedforward, filters)
    raise TypeError(f"to_control: cannot export a {type(obj).__name__}; give a servo law, a biquad, a plant or an Axis")


def _loop_tf(axis, which, feedforward, filters):
    """The loop's parts as transfer functions multiplied exactly: C(z), Cff(z), F(z) from their coefficients, P(z)
    from the lifted power train by scipy's ss2tf (its leading numerator coefficient is 0 exactly: the tick model
    is strictly proper) times the one-tick delay 1/z."""
    control = _control()
    from scipy import signal

    ts = axis.servo_period_s
    law = axis.law
    c = _law_tf(law, ts, "feedback")
    cff = _law_tf(law, ts, "feedforward") if feedforward else control.tf([0.0], [1.0], ts)
    f = control.tf([1.0], [1.0], ts)
    if filters:
        for q in axis.filters:
            if q is not None:
                f = f * to_control(q, servo_period_s=ts)
    a, b, c_motor, c_load = (np.asarray(x, dtype=float) for x in _core.tick_model(getattr(axis, "_axis", axis)))
    out = (c_load if axis.encoder.on_load else c_motor).reshape(1, -1)
    vpc = (-1.0 if isinstance(law, _core.ApsServoLaw) and law.v_inverse else 1.0) * 10.0 / 32767.0
    scale = axis.encoder.counts_per_rev / (2 * np.pi) * vpc
    num, den = signal.ss2tf(a, np.asarray(b, dtype=float).reshape(-1, 1), out, np.zeros((1, 1)))
    num = np.trim_zeros(np.asarray(num, dtype=float).ravel(), "f")
    p = control.tf(scale * num, np.polymul(den, [1.0, 0.0]), ts)  # the one-tick output delay
    loop = f * c * p
    parts = {"controller": c, "feedforward": cff, "filters": f, "plant": p, "loop_gain": loop}
    if which in parts:
        return parts[which]
    # closed_loop: Y/R = F (C + Cff) P / (1 + L)
    return control.feedback(loop, 1) if not feedforward else (f * (c + cff) * p) * control.feedback(1, loop)


def _attach():
    """``to_control()`` on the parts and ``LtiPlant.from_control`` (thin aliases of the functions above)."""

    def method(self, **kw):
        return to_control(self, **kw)

    method.__doc__ = to_control.__doc__
    for cls in (*_LAWS, *_BIQUADS, *_PLANTS):
        cls.to_control = method
    _core.LtiPlant.from_control = staticmethod(lti_plant)
    from .axis import Axis

    Axis.to_control = method


_attach()
