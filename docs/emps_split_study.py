"""Prints the numbers of the "Validation on a 60/40 split" section of docs/identify-emps.md (issue 19 point 7):
the EMPS record's 50/50, 60/40 and 70/30 splits, and simulated closed-loop records of the same trajectory with a
known drift and without one. The time-varying-friction model fitted by maximum likelihood needs statsmodels (not a
servobench dependency: the model is rejected, see the page); without it that part is skipped.
Run from the repository: python docs/emps_split_study.py [n_seeds]"""

import importlib.util
import sys
import warnings

import numpy as np
from scipy import signal

import servobench as sb
from servobench.examples import emps_log
from servobench.idim import _prepare, filtered_derivatives

PUB_ASYM = sb.RigidModel(95.1540, 166.7061, 20.1440, 240.4236, 20.6277)
PUB_SYM = sb.RigidModel(95.1089, 203.5034, 20.3935, offset=-3.1648)
SPLITS = (0.5, 0.6, 0.7)


def open_loop_mm(model, val, v0=None):
    """Open-loop RMS (mm) of `model` on `val` from the measured force, with the initial speed v0 (m/s; None:
    validate's own estimate)."""
    if v0 is None:
        return 1e3 * sb.validate(model, val).rms
    q, _, _ = sb.simulate_rigid(model, val.sample_period_s, effort=val.torque_nm, q0=float(val.measured[0]), v0=v0)
    return 1e3 * float(np.sqrt(np.mean((val.measured - q) ** 2)))


def tvp_friction(est):
    """IDIM regression with Fc+ and Fc- as random walks (one variance) and white noise, both variances by maximum
    likelihood (statsmodels' Kalman filter, diffuse start); the model with the filtered state at the end of `est`."""
    from statsmodels.tsa.statespace.mlemodel import MLEModel

    class TVP(MLEModel):
        def __init__(self, y, X):
            super().__init__(y, k_states=5, k_posdef=2, initialization="diffuse")
            self["design"] = X.T[None, :, :]
            self["transition"] = np.eye(5)
            sel = np.zeros((5, 2))
            sel[2, 0] = sel[4, 1] = 1
            self["selection"] = sel

        @property
        def param_names(self):
            return ["sigma2.e", "sigma2.fc"]

        @property
        def start_params(self):
            return np.array([np.var(self.endog) * 0.01, 1e-4])

        def transform_params(self, p):
            return p ** 2

        def untransform_params(self, p):
            return p ** 0.5

        def update(self, params, **kw):
            params = super().update(params, **kw)
            self["obs_cov", 0, 0] = params[0]
            self["state_cov"] = np.eye(2) * params[1]

    X, y, *_ = _prepare(est, 20.0, None, None, 49, "asymmetric", False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = TVP(y, X).fit(disp=False, maxiter=300)
    b = res.filtered_state[:, -1]
    return sb.RigidModel(b[0], max(b[1], 0), max(b[2], 0), max(b[3], 0), max(b[4], 0)), float(res.params[1])


def simulated_record(log, seed, drift_n):
    """The EMPS trajectory in closed loop (its controller and reference) on the published asymmetric model, with a
    coloured unmeasured force (AR(1), pole 0.98, 0.4 N innovations) and a linear drift of drift_n N over the
    record, the position quantised to the encoder count."""
    ts, n = log.sample_period_s, len(log)
    t = np.arange(n) * ts
    rng = np.random.default_rng(seed)
    dist = signal.lfilter([1], [1, -0.98], rng.normal(0, 0.4, n)) - drift_n * t / t[-1]
    ctrl = sb.CascadePD(log.extra["kp"], log.extra["kv"], log.extra["gtau"])
    q, _, f = sb.simulate_rigid(PUB_ASYM, ts, reference=log.reference, controller=ctrl, q0=float(log.measured[0]),
                                disturbance=dist, position_quantum=log.count_m)
    q = np.round(q / log.count_m) * log.count_m
    return sb.IdentificationLog.from_arrays(t, f, q, command_unit="N", measured_unit="m", reference=log.reference,
                                            count_m=log.count_m)


def asym(log):
    return sb.RigidModel.from_result(sb.idim_ls(log, friction="asymmetric", dynamics_hz=20.0))


def main(n_seeds=5):
    have_sm = importlib.util.find_spec("statsmodels") is not None
    log = emps_log()
    ts = log.sample_period_s
    _, dq, _ = filtered_derivatives(log.measured, ts, 100.0)
    full = asym(log)
    print("EMPS, open-loop RMS over the validation part, mm")
    for frac in SPLITS:
        est, val = log.split(frac)
        k = len(est)
        q = val.measured
        v0s = {"validate": None, "central at the split": (log.measured[k + 1] - log.measured[k - 1]) / (2 * ts),
               "IDIM filter, whole record": float(dq[k]),
               "IDIM filter, validation part": float(filtered_derivatives(q, ts, 100.0)[1][0])}
        ls, iv = asym(est), sb.RigidModel.from_result(sb.idim_iv(est, friction="asymmetric", dynamics_hz=20.0))
        for name, m in (("published asymmetric", PUB_ASYM), ("published symmetric", PUB_SYM),
                        ("IDIM-LS asym, 100 %", full), ("IDIM-LS asym, estimation part", ls),
                        ("IDIM-IV asym, estimation part", iv)):
            print(f"  {frac:.0%} {name:31s}", " ".join(f"{open_loop_mm(m, val, v):6.2f}" for v in v0s.values()),
                  f"| closed loop {1e6 * sb.validate(m, val).closed_loop['rms']:.3f} um")
        Xa, ya, *_ = _prepare(val, 20.0, None, None, 49, "asymmetric", False)
        Xs, ys, *_ = _prepare(val, 20.0, None, None, 49, "symmetric", True)
        th = lambda m: np.array([m.mass_kg, m.fv_pos, m.fc_pos, m.fv_neg, m.fc_neg])  # noqa: E731
        rel = lambda X, y, t: 100 * np.linalg.norm(y - X @ t) / np.linalg.norm(y)  # noqa: E731
        sym = sb.idim_ls(est, dynamics_hz=20.0)
        print(f"  {frac:.0%} force relative error on the validation part (eq. 11), %: asym estimation part "
              f"{rel(Xa, ya, th(ls)):.3f}, published asym {rel(Xa, ya, th(PUB_ASYM)):.3f}; sym estimation part "
              f"{rel(Xs, ys, np.array(list(sym.values().values()))):.3f}, published sym "
              f"{rel(Xs, ys, np.array([95.1089, 203.5034, 20.3935, -3.1648])):.3f}")
        if have_sm:
            m, q2 = tvp_friction(est)
            print(f"  {frac:.0%} ML random-walk Fc+/Fc- (variance {q2:.3g} N^2 per decimated sample): "
                  f"{open_loop_mm(m, val):.2f} mm")
    print(f"simulated records (published asymmetric machine, {n_seeds} seeds), open-loop RMS, mm: "
          "true parameters / fitted on 100 % / fitted on the estimation part")
    for drift in (0.0, 0.3):
        wins = total = 0
        for seed in range(n_seeds):
            r = simulated_record(log, seed, drift)
            full_r = asym(r)
            row = []
            for frac in SPLITS:
                est, val = r.split(frac)
                a, b, c = open_loop_mm(PUB_ASYM, val), open_loop_mm(full_r, val), open_loop_mm(asym(est), val)
                wins += c <= b
                total += 1
                extra = ""
                if have_sm and seed == 0:
                    extra = f" ML-RW {open_loop_mm(tvp_friction(est)[0], val):.1f}"
                row.append(f"{frac:.0%}: {a:.2f}/{b:.2f}/{c:.2f}{extra}")
            print(f"  drift {drift} N, seed {seed}: " + " | ".join(row))
            sys.stdout.flush()
        print(f"  drift {drift} N: the estimation-part fit is no worse than the 100 % fit in {wins} of {total} cases")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
