"""Draws the figures of docs/identify-emps.md into docs/img/ and prints the page's numbers.
Run from the repository: python docs/make_identify_emps_figures.py"""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import servobench as sb  # noqa: E402
from servobench.examples import emps_log  # noqa: E402

IMG = pathlib.Path(__file__).with_name("img")
PUBLISHED = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "offset": -3.1648}
PUBLISHED_ASYM = {"M": 95.1540, "Fv+": 166.7061, "Fc+": 20.1440, "Fv-": 240.4236, "Fc-": 20.6277}


def main():
    IMG.mkdir(exist_ok=True)
    log = emps_log()
    ls = sb.idim_ls(log, dynamics_hz=20.0)
    ls_auto = sb.idim_ls(log)
    asym = sb.idim_ls(log, friction="asymmetric", dynamics_hz=20.0)
    iv = sb.idim_iv(log, dynamics_hz=20.0)
    oe = sb.fit_time(log, strict=False)
    print(ls, "\n", asym, "\n", iv, "\n", oe)
    print("errors vs published, %:")
    print(" IDIM-LS (20 Hz)", {k: round(100 * v, 4) for k, v in ls.relative_errors(PUBLISHED).items()})
    print(" IDIM-LS (auto %.2f Hz)" % ls_auto.dynamics_hz,
          {k: round(100 * v, 4) for k, v in ls_auto.relative_errors(PUBLISHED).items()})
    print(" IDIM-LS asym", {k: round(100 * v, 4) for k, v in asym.relative_errors(PUBLISHED_ASYM).items()})
    print(" IDIM-IV", {k: round(100 * v, 4) for k, v in iv.relative_errors(PUBLISHED).items()})
    oe_names = {"M": "inertia_kgm2", "Fv": "viscous_nms", "Fc": "coulomb_nm", "offset": "load_nm"}
    print(" fit_time", {k: round(100 * (oe[n] / PUBLISHED[k] - 1), 3) for k, n in oe_names.items()})

    fig, ax = plt.subplots(figsize=(9, 3.5))
    ls.plot(ax=ax)
    ax.set_title(f"EMPS: IDIM-LS direct comparison (relative error {ls.relative_error_pct:.2f} %)")
    fig.tight_layout()
    fig.savefig(IMG / "identify_emps_force.png", dpi=100)

    est, val = log.split(0.6)
    models = {"IDIM-LS, symmetric (60 %)": sb.RigidModel.from_result(sb.idim_ls(est)),
              "IDIM-LS, asymmetric (60 %)": sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric")),
              "IDIM-IV, asymmetric (60 %)": sb.RigidModel.from_result(sb.idim_iv(est, friction="asymmetric")),
              "published, symmetric (100 %)": sb.RigidModel(95.1089, 203.5034, 20.3935, offset=-3.1648),
              "published, asymmetric (100 %)": sb.RigidModel(95.1540, 166.7061, 20.1440, 240.4236, 20.6277)}
    print("open-loop RMS on the last 40 %, mm:")
    for name, m in models.items():
        v = sb.validate(m, val)
        print(f"  {name:32s} {1e3 * v.rms:.3f} mm (R^2 {v.r2:.5f}); closed loop {1e6 * v.closed_loop['rms']:.3f} um")
    v = sb.validate(models["IDIM-LS, asymmetric (60 %)"], val)
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(9, 5))
    v.plot(ax=ax)
    ax[0].set_title("EMPS, last 40 %: model identified on the first 60 % (asymmetric IDIM-LS)")
    fig.tight_layout()
    fig.savefig(IMG / "identify_emps_validation.png", dpi=100)


if __name__ == "__main__":
    main()
