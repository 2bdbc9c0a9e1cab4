"""The strongest peer a user would pick for a simulated servo loop: the rigid chain's tick written once in Python and
compiled with numba (issue 22 point 5). The same arithmetic as bench_axis.python_reference (GT law, 16-bit DAC,
lagged torque drive, rigid plant with Coulomb friction solved implicitly with stiction, quantised encoder); the
benches check that it reproduces servobench's feedback exactly before timing it.

``chain_constants(axis)`` computes the plant's ZOH with SciPy (not timed: set-up, as servobench's own set-up is
not timed in the single-axis rows); ``rigid_chain`` runs one plant, ``rigid_chain_many`` runs many plants in
parallel (numba ``prange``), each with its own constants row.
"""

from __future__ import annotations

import math

import numpy as np


def chain_constants(axis) -> np.ndarray:
    """The rigid chain's constants for the numba kernels, one float64 vector (see _unpack for the layout)."""
    from scipy.linalg import expm

    law, drv, pl, enc = axis.law, axis.drive, axis.plant, axis.encoder
    ts = axis.servo_period_s
    wc = 2 * math.pi * drv.current_bw_hz
    j = pl.inertia_kgm2
    a = np.array([[-wc, 0, 0], [0, 0, 1], [drv.kt / j, 0, -pl.viscous_nms / j]])
    b = np.array([[wc, 0], [0, 0], [0, 1 / j]])

    def zoh(a_, b_):
        m = np.zeros((5, 5))
        m[:3, :3], m[:3, 3:] = a_ * ts, b_ * ts
        e = expm(m)
        return e[:3, :3], e[:3, 3:]

    phi, gam = zoh(a, b)
    al, bl = a.copy(), b.copy()
    al[1:, :] = 0
    bl[1:, :] = 0
    phil, gaml = zoh(al, bl)
    head = [enc.counts_per_rev / (2 * math.pi), law.kp, law.ki, law.kd, law.kvff, law.kaff, law.ilmt, law.bias,
            law.mtr_lmt, drv.amps_per_volt, drv.current_limit_a, pl.coulomb_nm, pl.load_nm,
            max(pl.static_nm, pl.coulomb_nm)]
    return np.concatenate([head, phi.ravel(), gam.ravel(), [phil[0, 0], gaml[0, 0], gaml[0, 1]]]).astype(float)


def _build():
    import numba

    @numba.njit(cache=False, inline="always")
    def _tick_loop(c, pos, vel, acc, out, st=None):
        # st (optional): the loop's state carried between calls (the step peer), [i, th, w, stuck, s, e_prev,
        # pending]; read before the loop and written after it, so the loop itself is the same code either way.
        cpr, kp, ki, kd, kvff, kaff, ilmt, bias, mlim = c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]
        apv, ilim, coul, load, fs = c[9], c[10], c[11], c[12], c[13]
        p00, p01, p02, p10, p11, p12, p20, p21, p22 = c[14], c[15], c[16], c[17], c[18], c[19], c[20], c[21], c[22]
        g00, g01, g10, g11, g20, g21 = c[23], c[24], c[25], c[26], c[27], c[28]
        pl00, gl00, gl01 = c[29], c[30], c[31]
        g, gth = g21, g11
        i = th = w = 0.0
        stuck = True
        s = e_prev = 0.0
        pending = 0.0
        if st is not None:
            i, th, w, stuck, s, e_prev, pending = st[0], st[1], st[2], st[3] != 0.0, st[4], st[5], st[6]
        for k in range(pos.shape[0]):
            icmd = max(-ilim, min(ilim, apv * pending))
            y = math.floor(th * cpr + 0.5)
            err = pos[k] - y
            s = max(-ilmt, min(ilmt, s + err))
            u = kp * err + ki * s / 256 + kd * (err - e_prev) + kvff * vel[k] + kaff * acc[k] + bias
            u = max(-mlim, min(mlim, u))
            e_prev = err
            v = max(-10.0, min(10.0, u * (10 / 32767)))
            out[k] = y
            pending = np.round(v * 3276.7) / 3276.7
            ext = -load
            xi = p00 * i + p01 * th + p02 * w + g00 * icmd + g01 * ext
            xt = p10 * i + p11 * th + p12 * w + g10 * icmd + g11 * ext
            xw = p20 * i + p21 * th + p22 * w + g20 * icmd + g21 * ext
            if fs == 0.0:
                i, th, w = xi, xt, xw
                continue
            d = xt - th
            st_ = False
            f_slip = -coul if w > 0 else coul
            if w != 0.0 and (xw + g * f_slip) * (1.0 if w > 0 else -1.0) > 0.0:
                f = f_slip
            else:
                f_stick = -xw / g
                if -fs <= f_stick <= fs:
                    f = f_stick
                    st_ = True
                else:
                    f = -fs if xw > 0 else fs
            if not (st_ and w == 0.0) and f * (d + gth * f) > 0.0:
                st_ = False
                f = 0.0 if d == 0.0 else (-1.0 if d > 0 else 1.0) * min(abs(f), abs(d) / gth)
            if st_ and stuck and w == 0.0:
                i = pl00 * i + gl00 * icmd + gl01 * ext
                continue
            i, th, w = xi + g01 * f, xt + g11 * f, xw + g21 * f
            if st_:
                w = 0.0
            stuck = st_
        if st is not None:
            st[0], st[1], st[2], st[3], st[4], st[5], st[6] = i, th, w, 1.0 if stuck else 0.0, s, e_prev, pending

    @numba.njit(cache=False)
    def rigid_chain(c, pos, vel, acc, out):
        _tick_loop(c, pos, vel, acc, out)

    @numba.njit(cache=False)
    def rigid_step(c, st, buf, cmd):
        # One tick per call, the state carried in st (see _tick_loop) plus [prev_cmd, prev_vel] in st[7:9]; buf is a
        # (4, 1) scratch array for the loop's pos, vel, acc and out: what a numba user writes for a program in the
        # loop (the step API's peer). Returns the encoder reading, pulse.
        if st[9] == 0.0:  # first tick: the velocity and acceleration start from 0, as servobench's
            st[7], st[8], st[9] = cmd, 0.0, 1.0
        v = cmd - st[7]
        buf[0, 0], buf[1, 0], buf[2, 0] = cmd, v, v - st[8]
        st[7], st[8] = cmd, v
        _tick_loop(c, buf[0], buf[1], buf[2], buf[3], st)
        return buf[3, 0]

    @numba.njit(cache=False, parallel=True)
    def rigid_chain_many(consts, pos, vel, acc, out):
        for p in numba.prange(consts.shape[0]):
            _tick_loop(consts[p], pos, vel, acc, out[p])

    @numba.njit(cache=False)
    def sweep(c, freqs, n_tick, amp, ts, settle_fraction):
        # The stepped-sine sweep of servobench.frequency.sine_sweep on the same chain: one sine per frequency (phase
        # continuous across points, state carried over), then least-squares fits of cos, -sin and a constant to the
        # command and the feedback over the last whole periods after the settling share; returns y/r per point.
        n_pt = freqs.shape[0]
        pos = np.empty(n_pt * n_tick)
        zero = np.zeros(n_pt * n_tick)
        phase = 0.0
        for p in range(n_pt):
            w = 2 * math.pi * freqs[p] * ts
            # servobench's sweep raises the first point's amplitude from 0 on a raised cosine over a quarter of
            # the settling share (decision M6); later points keep the amplitude, so they need no ramp.
            per = 1.0 / (freqs[p] * ts)
            m = max(1, int(math.floor((n_tick - math.floor(settle_fraction * n_tick)) / per + 1e-9)))
            ramp = (n_tick - min(n_tick, max(3, int(round(m * per))))) // 4 if p == 0 else 0
            for k in range(n_tick):
                a = amp * (0.5 - 0.5 * math.cos(math.pi * k / ramp)) if k < ramp else amp
                pos[p * n_tick + k] = a * math.sin(phase + w * k)
            phase = np.fmod(phase + w * n_tick, 2 * math.pi)
        y = np.empty(n_pt * n_tick)
        _tick_loop(c, pos, zero, zero, y)
        out = np.empty(n_pt, dtype=np.complex128)
        for p in range(n_pt):
            w = 2 * math.pi * freqs[p] * ts
            per = 1.0 / (freqs[p] * ts)
            m = max(1, int(math.floor((n_tick - math.floor(settle_fraction * n_tick)) / per + 1e-9)))
            ln = min(n_tick, max(3, int(round(m * per))))
            g = np.zeros((3, 3))
            rr = np.zeros(3)
            ry = np.zeros(3)
            b = np.empty(3)
            for k in range(ln):
                b[0], b[1], b[2] = math.cos(w * k), -math.sin(w * k), 1.0
                x_r = pos[(p + 1) * n_tick - ln + k]
                x_y = y[(p + 1) * n_tick - ln + k]
                for i in range(3):
                    rr[i] += b[i] * x_r
                    ry[i] += b[i] * x_y
                    for j in range(3):
                        g[i, j] += b[i] * b[j]
            cr = np.linalg.solve(g, rr)
            cy = np.linalg.solve(g, ry)
            out[p] = complex(cy[0], cy[1]) / complex(cr[0], cr[1])
        return out

    return rigid_chain, rigid_chain_many, sweep, rigid_step


_KERNELS = None


def kernels():
    """(rigid_chain, rigid_chain_many), compiled on first use (compile time is not timed by the benches)."""
    return _built()[:2]


def sweep_kernel():
    """sweep(consts, freqs_hz, n_tick, amplitude_pulse, ts_s, settle_fraction) -> closed loop y/r per frequency
    (complex), the stepped-sine sweep on the rigid chain; compiled on first use."""
    return _built()[2]


def step_kernel():
    """(rigid_step, new_state): ``rigid_step(consts, state, scratch, cmd_pulse) -> fb_pulse`` advances the rigid
    chain one tick per call (the step API's peer); ``new_state()`` returns a fresh (state, scratch) pair."""
    return _built()[3], lambda: (np.zeros(10), np.zeros((4, 1)))


def _built():
    global _KERNELS
    if _KERNELS is None:
        _KERNELS = _build()
    return _KERNELS
