"""Identification on a real machine's record: the EMPS benchmark (tests/data/emps, README there), read as it comes.

Published IDIM-LS values (EMPS_Description.txt, section 3.4 and 4.2) are the reference; the record is the
estimation record only -- a validation record of the same machine is not in the repository."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import servobench as sb
from servobench import cli

EMPS = Path(__file__).resolve().parents[1] / "data" / "emps" / "DATA_EMPS.mat"
UNITS = {"t": "s", "qm": "m", "qg": "m", "vir": "V"}
PUBLISHED = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "offset": -3.1648}
PUBLISHED_ASYM = {"M": 95.1540, "Fv+": 166.7061, "Fc+": 20.1440, "Fv-": 240.4236, "Fc-": 20.6277}


@pytest.fixture(scope="module")
def emps():
    return sb.IdentificationLog.from_mat(str(EMPS), units=UNITS, command_gain="gtau")


def test_the_record_reads_as_it_comes(emps):
    # 1 kHz with a jittery time vector (steps 0.999984..1.000024 ms): accepted and reported, not refused.
    assert emps.linear and len(emps) == 24841
    assert emps.sample_period_s == pytest.approx(1e-3, rel=1e-4)
    assert 10 < emps.time_jitter_ppm < 100
    assert emps.count_m == pytest.approx(5e-8, rel=1e-6)        # detected from the position's steps
    assert emps.reference is not None and emps.reference.shape == emps.measured.shape
    assert emps.extra["gtau"] == pytest.approx(35.15065188) and emps.extra["kp"] == pytest.approx(160.18)
    assert emps.force_n[0] == pytest.approx(35.15065188 * 2.53862809)
    assert emps.units["effort"] == "N" and emps.units["inertia"] == "kg"


def test_idim_ls_reproduces_the_published_symmetric_estimates(emps):
    for dyn in (20.0, None):  # the benchmark's stated 20 Hz, and the default: estimated from the record (19.0 Hz)
        r = sb.idim_ls(emps, dynamics_hz=dyn)
        for k, v in PUBLISHED.items():
            assert r[k] == pytest.approx(v, rel=1e-3), (dyn, k)
    r = sb.idim_ls(emps, dynamics_hz=20.0)
    assert r.decimation == 10 and r.cutoff_hz == pytest.approx(100.0)
    assert r.relative_error_pct == pytest.approx(4.0834, abs=0.005)
    assert r.condition_number == pytest.approx(25.99, abs=0.05)
    assert r.std_error_iid["M"] == pytest.approx(0.1085, rel=0.02)   # the benchmark's printed (iid) deviation
    for k, e in r.parameters.items():                                # HAC: larger for the coloured residual
        assert e.std_error > 1.5 * r.std_error_iid[k], k
    assert r.not_identified == []
    assert r.misfit and "asymmetric" in " ".join(r.warnings)        # the data reject symmetric friction
    assert "IDIM-LS" in str(r) and "HAC" in str(r)
    assert 18.0 < sb.idim.dynamics_frequency(emps) < 21.0


def test_idim_ls_reproduces_the_published_asymmetric_estimates(emps):
    r = sb.idim_ls(emps, friction="asymmetric", dynamics_hz=20.0)
    for k, v in PUBLISHED_ASYM.items():
        assert r[k] == pytest.approx(v, rel=5e-3), k
    assert r.relative_error_pct == pytest.approx(3.1117, abs=0.005)
    with pytest.raises(ValueError, match="offset = True with friction = 'asymmetric'"):
        sb.idim_ls(emps, friction="asymmetric", offset=True)


def test_idim_iv_and_the_one_call_entry_point(emps):
    iv = sb.idim_iv(emps, dynamics_hz=20.0)
    for k, v in PUBLISHED.items():
        assert iv[k] == pytest.approx(v, rel=0.01), k
    res = sb.identify_rigid(emps, n_starts=2)
    for k in ("M", "Fv", "Fc"):                       # the documented one-call path: within 2 % (here 0.02 %)
        assert res[k] == pytest.approx(PUBLISHED[k], rel=0.02), k
    assert res.model.fv_pos != res.model.fv_neg     # asymmetric friction chosen: the data reject symmetry
    oe = res.output_error
    assert oe is not None and oe.converged and oe.linear
    assert oe["mass_kg"] == pytest.approx(PUBLISHED["M"], rel=0.02)
    assert "segments of" in oe.summary and "Start: the IDIM-LS answer" in oe.summary
    assert "mass_kg" in str(oe) and " kg " in str(oe)           # printed in the axis's own units


def test_fit_time_as_a_user_calls_it(emps):
    # no guess, no segment length: starts from the IDIM answer, segments from the data, three starts
    fit = sb.fit_time(emps)
    assert fit.converged and fit.agrees and len(fit.starts) == 3
    for name, k in (("mass_kg", "M"), ("viscous_ns_per_m", "Fv"), ("coulomb_n", "Fc")):
        assert fit[name] == pytest.approx(PUBLISHED[k], rel=0.02), name   # measured: -0.55 %, -1.35 %, +1.89 %
    assert 50 <= fit.segment_samples <= 1000
    # honest error bars: the segment-clustered sandwich, evaluated at the fit's own segment states (J46), is of the
    # size of the IDIM's HAC bars, no longer 7-25x smaller (Ceres' white-noise values). The published Fv, Fc and
    # offset lie within 2 of them (measured 0.31, 0.78, 0.24). M lies 2.2 of them from the published IDIM-LS value: the
    # symmetric model is rejected by the data (misfit, below); the bars give the estimator's spread under its model
    # (93.75 % coverage on correctly specified coloured records, test_identify_calibration), not a rejected model's
    # bias, and the result says the model is rejected instead of leaving them to speak alone.
    idim = sb.idim_ls(emps)
    for name, k in (("inertia_kgm2", "M"), ("viscous_nms", "Fv"), ("coulomb_nm", "Fc"), ("load_nm", "offset")):
        e = fit.parameters[name]
        assert 0.7 * idim.parameters[k].std_error < e.std_error < 5 * idim.parameters[k].std_error, (name, e)
        if k != "M":
            assert abs(e.value - PUBLISHED[k]) < 2 * e.std_error, (name, e)
    assert fit.misfit and "use idim_ls(log, friction='asymmetric')" in " ".join(fit.warnings)
    assert "sandwich clustered by segment" in fit.summary
    # the symmetric model is flagged: the segment score test rejects Fv+ = Fv- (IDIM: Fv+ - Fv- = -74 N*s/m)
    assert fit.misfit and fit.asymmetry_p_value < 1e-4
    assert any("friction is asymmetric" in w and "N*s/m" in w for w in fit.warnings)


def test_the_60_40_split_is_governed_by_the_machine_drift(emps):
    # issue 19 point 7 asks the model fitted on the first 60 % to simulate the last 40 % open loop no worse than the
    # published parameters (fitted on 100 %, the last 40 % included). Measured: it does not (4.42 vs 2.92 mm), and
    # the cause is in the machine, not the estimator: the friction balance drifts during the record.
    est, val = emps.split(0.6)
    shift = {}
    for name, part in (("first 60 %", est), ("last 40 %", val)):
        a = sb.idim_ls(part, friction="asymmetric", dynamics_hz=20.0)
        shift[name] = (a["Fc+"] - a["Fc-"]) / 2     # the constant force the asymmetric model carries, N
    assert shift["last 40 %"] - shift["first 60 %"] < -0.08        # N; measured -0.113
    # the same estimator on the last 40 % itself simulates it to 0.91 mm: the simulation and the model class hold
    own = sb.validate(sb.RigidModel.from_result(sb.idim_ls(val, friction="asymmetric", dynamics_hz=20.0)), val)
    first = sb.validate(sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric", dynamics_hz=20.0)), val)
    published = sb.validate(sb.RigidModel(**dict(zip(("mass_kg", "fv_pos", "fc_pos", "fv_neg", "fc_neg"),
                                                      PUBLISHED_ASYM.values()))), val)
    assert own.rms < 1.5e-3 < published.rms < first.rms              # m; measured 0.91, 2.92, 4.42 mm
    # and the open-loop RMS is a 0.1 N question: 0.1 N of constant force moves it by about 1.7 mm
    import dataclasses
    m = sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric", dynamics_hz=20.0))
    moved = sb.validate(dataclasses.replace(m, offset=-0.1), val)
    assert abs(moved.rms - first.rms) > 1e-3


def _with_values(result, values):
    """`result` carrying other parameter values (e.g. the published ones), for its cross_test."""
    import dataclasses

    return dataclasses.replace(result, parameters={k: dataclasses.replace(e, value=values[k])
                                                   for k, e in result.parameters.items()})


def test_the_60_40_split_measured_the_benchmarks_way(emps):
    # session 13 (J49-J52): the open-loop shortfall is neither the simulation's initial state nor its hold, the
    # published figure is what a fit on the whole record gives, and on the benchmark's own validation measures
    # (cross-test force error, eq. 11; closed-loop simulation from the reference) the 60 % fit is within 1 % of the
    # published asymmetric set and better than the published symmetric one.
    est, val = emps.split(0.6)
    k, q, ts = len(est), emps.measured, emps.sample_period_s
    ls = sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric", dynamics_hz=20.0))
    # initial speed: validate's (q2 - q0)/2Ts against the central difference at the split on the whole record
    v_split = float((q[k + 1] - q[k - 1]) / (2 * ts))
    Q, _, _ = sb.simulate_rigid(ls, ts, effort=val.torque_nm, q0=float(val.measured[0]), v0=v_split)
    moved = np.sqrt(np.mean((val.measured - Q) ** 2))
    assert abs(moved - sb.validate(ls, val).rms) < 1e-4                       # m; measured 0.02 mm of 4.42 mm
    # the published parameters' 2.92 mm is what the same estimator on the whole record gives (2.93 mm)
    full = sb.RigidModel.from_result(sb.idim_ls(emps, friction="asymmetric", dynamics_hz=20.0))
    pub_asym = sb.RigidModel(**dict(zip(("mass_kg", "fv_pos", "fc_pos", "fv_neg", "fc_neg"),
                                        PUBLISHED_ASYM.values())))
    pub_sym = sb.RigidModel(95.1089, 203.5034, 20.3935, offset=-3.1648)
    assert abs(sb.validate(full, val).rms - sb.validate(pub_asym, val).rms) < 5e-5   # m
    # the benchmark's cross-test validation on the last 40 % (relative force error, %)
    a = sb.idim_ls(est, friction="asymmetric", dynamics_hz=20.0)
    s = sb.idim_ls(est, dynamics_hz=20.0)
    ct = {"ours asym": a.cross_test(val), "published asym": _with_values(a, PUBLISHED_ASYM).cross_test(val),
          "ours sym": s.cross_test(val), "published sym": _with_values(s, PUBLISHED).cross_test(val)}
    assert ct["ours asym"] <= 1.02 * ct["published asym"]               # measured 3.280 vs 3.247 %
    assert ct["ours asym"] < ct["published sym"]                        # 3.280 vs 4.223 %
    assert ct["ours sym"] <= 1.04 * ct["published sym"]                 # 4.349 vs 4.223 %
    # closed loop from the reference with the record's controller (the benchmark's simulation), m
    cl = {n: sb.validate(m, val).closed_loop["rms"] for n, m in (("ours", ls), ("asym", pub_asym),
                                                                   ("sym", pub_sym))}
    assert cl["ours"] <= 1.02 * cl["asym"] and cl["ours"] < cl["sym"]   # 1.858 vs 1.843 and 2.129 um
    with pytest.raises(TypeError, match="IdentificationLog"):
        a.cross_test(val.measured)
    with pytest.raises(ValueError, match="rotary"):
        a.cross_test(val._replace(lead_m_per_rev=0.01).to_motor_side())


def test_a_fit_on_part_of_a_stationary_record_loses_to_the_fit_on_all_of_it(emps):
    # on simulated records of a machine with constant parameters (the published asymmetric set) and a coloured
    # unmeasured force, the fit on the first 60 % simulates the last 40 % open loop worse than the fit on 100 %
    # (which saw that part's disturbance) -- so the 60/40 criterion fails without any drift (J50)
    from scipy import signal

    ts, n = emps.sample_period_s, len(emps)
    t = np.arange(n) * ts
    true = sb.RigidModel(**dict(zip(("mass_kg", "fv_pos", "fc_pos", "fv_neg", "fc_neg"), PUBLISHED_ASYM.values())))
    ctrl = sb.CascadePD.from_log(emps)
    worse = []
    for seed in range(2):
        rng = np.random.default_rng(seed)
        dist = signal.lfilter([1], [1, -0.98], rng.normal(0, 0.4, n))       # N, AR(1)
        q, _, f = sb.simulate_rigid(true, ts, reference=emps.reference, controller=ctrl, q0=float(emps.measured[0]),
                                    disturbance=dist, position_quantum=emps.count_m)
        r = sb.IdentificationLog.from_arrays(t, f, np.round(q / emps.count_m) * emps.count_m, command_unit="N",
                                             measured_unit="m", reference=emps.reference, count_m=emps.count_m)
        est, val = r.split(0.6)
        part = sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric", dynamics_hz=20.0))
        whole = sb.RigidModel.from_result(sb.idim_ls(r, friction="asymmetric", dynamics_hz=20.0))
        worse.append(sb.validate(part, val).rms / sb.validate(whole, val).rms)
    assert all(w > 1.1 for w in worse), worse                            # measured 7.34/5.05, 3.66/2.71 mm


def test_results_print_in_the_axis_units_and_at_the_motor(emps):
    log = emps._replace(lead_m_per_rev=0.01)       # a 10 mm screw
    r = sb.idim_ls(log, dynamics_hz=20.0)
    text = str(r)
    assert " kg" in text and "N*s/m" in text and "motor side (lead 10 mm/rev)" in text and "kg*m^2" in text
    k = 0.01 / (2 * np.pi)
    assert f"M = {r['M'] * k ** 2:.6g} kg*m^2" in text and f"Fc = {r['Fc'] * k:.6g} N*m" in text
    v = sb.validate(r, log.split(0.6)[1])
    assert " m (" in str(v) and "rad at the motor" in str(v)
    iv = sb.idim_iv(log, dynamics_hz=20.0)
    assert "motor side" in str(iv)


def test_validation_open_and_closed_loop_and_the_60_40_split(emps):
    est, val = emps.split(0.6)
    assert len(est) + len(val) == len(emps)
    ours = sb.RigidModel.from_result(sb.idim_ls(est, friction="asymmetric"))
    published = sb.RigidModel(95.1089, 203.5034, 20.3935, offset=-3.1648)
    v_ours, v_pub = sb.validate(ours, val), sb.validate(published, val)
    # open loop from the measured force and the initial state (the record starts the 40 % at 0.125 m/s)
    assert v_ours.r2 > 0.99 and v_pub.r2 > 0.99
    assert v_ours.rms < 0.01 and v_pub.rms < 0.01    # m; the figures are in docs/identify-emps.md
    # closed loop from the reference with the record's own controller (kp, kv, gtau): tracking within microns
    assert v_ours.closed_loop["rms"] < 5e-6
    data = v_ours.plot()
    assert set(data) >= {"time_s", "measured", "open_loop", "closed_loop"}


def test_units_in_headers_are_converted_or_refused(tmp_path, emps):
    n = 4000
    df = pd.DataFrame({"t [ms]": emps.time_s[:n] * 1e3, "F [mN]": emps.force_n[:n] * 1e3,
                       "x [mm]": emps.measured[:n] * 1e3, "r [mm]": emps.reference[:n] * 1e3})
    log = sb.IdentificationLog.from_dataframe(df, time="t", command="F", measured="x", reference="r")
    np.testing.assert_allclose(log.measured, emps.measured[:n], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(log.force_n, emps.force_n[:n], rtol=1e-12)
    assert log.linear and log.sample_period_s == pytest.approx(1e-3, rel=1e-4)
    p = tmp_path / "log.csv"
    df.to_csv(p, index=False)
    again = sb.IdentificationLog.from_csv(str(p), time="t", command="F", measured="x", reference="r")
    np.testing.assert_allclose(again.measured, log.measured, rtol=1e-12)
    rot = pd.DataFrame({"time_s": np.arange(100) * 1e-3, "tau [mN*m]": np.ones(100), "angle [deg]": np.arange(100.)})
    r = sb.IdentificationLog.from_dataframe(rot, command="tau", measured="angle")
    assert r.torque_nm[0] == pytest.approx(1e-3) and r.measured[1] == pytest.approx(np.pi / 180) and not r.linear
    bad = df.rename(columns={"x [mm]": "x [furlong]"})
    with pytest.raises(ValueError, match="column 'x': unknown unit 'furlong'"):
        sb.IdentificationLog.from_dataframe(bad, time="t", command="F", measured="x")
    wrong = df.rename(columns={"x [mm]": "x [deg]"})
    with pytest.raises(ValueError, match="column 'x': unit 'deg' is a rotary unit, but the axis is linear"):
        sb.IdentificationLog.from_dataframe(wrong, time="t", command="F", measured="x")
    untagged = df.rename(columns={"x [mm]": "x"})
    with pytest.raises(ValueError, match="column 'x' has no unit"):
        sb.IdentificationLog.from_dataframe(untagged, time="t", command="F", measured="x")
    with pytest.raises(ValueError, match="no column 'y'"):
        sb.IdentificationLog.from_dataframe(df, time="t", command="F", measured="y")
    nan = df.copy()
    nan.loc[17, "F [mN]"] = np.nan
    with pytest.raises(ValueError, match=r"F\[17\] = nan is not a finite number"):
        sb.IdentificationLog.from_dataframe(nan, time="t", command="F", measured="x")


def test_real_time_vectors():
    n = 1000
    t = np.arange(n) * 1e-3
    jitter = t + np.random.default_rng(1).uniform(-40e-9, 40e-9, n)       # +-80 ppm steps: accepted, reported
    log = sb.IdentificationLog.from_arrays(jitter, np.zeros(n), np.zeros(n), command_unit="N", measured_unit="m")
    assert 0 < log.time_jitter_ppm <= 100
    gap = t.copy()
    gap[600:] += 5e-3
    with pytest.raises(ValueError, match="time_s has a gap at sample 600"):
        sb.IdentificationLog.from_arrays(gap, np.zeros(n), np.zeros(n), command_unit="N", measured_unit="m")
    back = t.copy()
    back[300] = back[298]
    with pytest.raises(ValueError, match="time_s is not increasing at sample 300"):
        sb.IdentificationLog.from_arrays(back, np.zeros(n), np.zeros(n), command_unit="N", measured_unit="m")
    uneven = t.copy()
    uneven[500:] += 2e-7                                                    # a 200 ppm step
    with pytest.raises(ValueError, match="not uniformly sampled at sample 500"):
        sb.IdentificationLog.from_arrays(uneven, np.zeros(n), np.zeros(n), command_unit="N", measured_unit="m")


def test_linear_axis_to_the_motor_side(emps):
    lead = 0.01  # m per motor revolution (a 10 mm screw)
    log = emps._replace(lead_m_per_rev=lead)
    motor = log.to_motor_side()
    assert not motor.linear
    k = 2 * np.pi / lead
    assert motor.measured[100] == pytest.approx(emps.measured[100] * k)
    r_lin = sb.idim_ls(emps, dynamics_hz=20.0)
    r_rot = sb.idim_ls(motor, dynamics_hz=20.0)
    assert r_rot["M"] == pytest.approx(r_lin["M"] / k ** 2, rel=1e-9)   # kg -> kg*m^2 = M (lead / 2 pi)^2
    assert r_rot.parameters["M"].unit == "kg*m^2" and r_lin.parameters["M"].unit == "kg"


def test_simulation_starts_from_any_state():
    m = sb.RigidModel(2.0, 4.0, 1.0, offset=0.0)
    q, v, _ = sb.simulate_rigid(m, 1e-3, effort=np.zeros(2000), q0=0.3, v0=-0.5, substeps=20)
    assert q[0] == 0.3 and v[0] == -0.5
    # decelerates by viscous + Coulomb friction and stops: x_stop = 0.3 - 0.5 * M / Fv + Coulomb's share
    assert v[-1] == 0.0 and 0.3 - 0.25 < q[-1] < 0.3
    with pytest.raises(ValueError, match="RigidModel.fc_neg = -1.0 must be a finite number >= 0"):
        sb.RigidModel(1.0, 1.0, 1.0, fc_neg=-1.0)
    with pytest.raises(ValueError, match="mass_kg"):
        sb.RigidModel(float("nan"))


def test_bad_records_are_refused(emps):
    short = emps._slice(slice(0, 150))
    with pytest.raises(ValueError, match="too short"):
        sb.idim_ls(short, dynamics_hz=20.0)
    one_way = emps._slice(slice(2000, 3500))
    one_way = one_way._replace(measured=np.linspace(0, 0.1, len(one_way)))
    with pytest.raises(ValueError, match="no motion reversal"):
        sb.idim_ls(one_way, dynamics_hz=20.0)
    with pytest.raises(ValueError, match="dynamics_hz"):
        sb.idim_ls(emps._replace(reference=None))
    with pytest.raises(ValueError, match="dynamics_hz = 500.0 must be in"):
        sb.idim_ls(emps, dynamics_hz=500.0)
    with pytest.raises(ValueError, match="no reference"):
        sb.idim_iv(emps._replace(reference=None), dynamics_hz=20.0)


def test_cli_reads_the_same_formats(tmp_path, capsys):
    # the CLI's --log is the Python reader: a .mat file with --unit, a tagged CSV; bad input exits 2 naming the column
    code = cli.main(["identify", "--log", str(EMPS), "--unit", "t=s", "qm=m", "qg=m", "vir=V", "--command-gain",
                     "35.15065188", "--out", str(tmp_path), "-q"])
    assert code == 0
    rep = json.loads((tmp_path / "DATA_EMPS_identified.json").read_text())
    assert rep["parameters"]["inertia_kgm2"]["value"] == pytest.approx(PUBLISHED["M"], rel=0.02)
    assert "qm [m]" in rep["source"]
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,force [N],pos [parsec]\n0,0,0\n0.001,0,0\n0.002,0,0\n")
    code = cli.main(["identify", "--log", str(bad), "--measured", "pos", "--command", "force", "--out",
                     str(tmp_path / "o"), "-q"])
    assert code == 2 and "column 'pos': unknown unit 'parsec'" in capsys.readouterr().err
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())   # nothing written half-way


def test_the_plant_simulates_asymmetric_friction_and_an_offset():
    # point 3: an identified machine can be simulated: RigidPlant has Fv+/-, Fc+/- (mean and half-difference)
    p = sb.RigidPlant(inertia_kgm2=2.0, viscous_nms=5.0, viscous_asym_nms=-1.0, coulomb_nm=1.0, coulomb_asym_nm=0.2)
    np.testing.assert_allclose(p.friction_torque([-2, -0.1, 0.1, 2]), [-12.8, -1.4, 1.6, 9.2], rtol=1e-12)
    with pytest.raises(ValueError, match=r"RigidPlant.coulomb_asym_nm = 2 is outside the allowed range -1..1"):
        sb.RigidPlant(inertia_kgm2=2.0, viscous_nms=5.0, coulomb_nm=1.0, coulomb_asym_nm=2.0)
    with pytest.raises(ValueError, match=r"TwoMassPlant.load_viscous_asym_nms = nan is not a finite number"):
        sb.TwoMassPlant(load_viscous_asym_nms=float("nan"))
    model = sb.RigidModel(2.0, 4.0, 1.2, 6.0, 0.8, offset=0.3)
    plant = model.to_plant()
    assert plant.viscous_nms == 5.0 and plant.viscous_asym_nms == -1.0 and plant.load_nm == 0.3
    axis = sb.Axis(law=sb.GtServoLaw(kp=0, kd=0), plant=plant, encoder=sb.Encoder(counts_per_rev=100000),
                   drive=sb.TorqueDrive(amps_per_volt=1.0, kt=1.0, current_limit_a=100), servo_period_s=1e-3)
    for volts in (5.0, -5.0):  # steady speed (F - offset -/+ Fc+/-) / Fv+/-, in the simulator and in validate's model
        axis.reset()
        run = axis.run(np.zeros(4000), injection_v=np.full(4000, volts), signals=["speed_rad_s"])
        _, v, _ = sb.simulate_rigid(model, 1e-3, effort=np.full(4000, volts), substeps=20)
        expected = (volts - 0.3 - 1.2) / 4.0 if volts > 0 else (volts - 0.3 + 0.8) / 6.0
        assert run.speed_rad_s[-1] == pytest.approx(expected, rel=1e-3)
        assert v[-1] == pytest.approx(expected, rel=1e-3)
    lead = 0.01
    rot = model.to_plant(lead_m_per_rev=lead)
    assert rot.inertia_kgm2 == pytest.approx(2.0 * (lead / (2 * np.pi)) ** 2)


def test_axis_reset_from_any_state():
    axis = sb.Axis(law=sb.GtServoLaw(kp=0, kd=0), plant=sb.RigidPlant(inertia_kgm2=1e-3, viscous_nms=1e-3),
                   drive=sb.TorqueDrive(amps_per_volt=1.0, kt=1.0), servo_period_s=1e-3)
    axis.reset(0.5, speed_rad_s=-1.0)
    run = axis.run(np.zeros(10), signals=["angle_rad", "speed_rad_s"])
    assert run.angle_rad[0] == 0.5 and run.speed_rad_s[0] == -1.0           # the state it was put in
    assert run.angle_rad[1] == pytest.approx(0.5 - 1e-3, rel=1e-3) and -1.0 < run.speed_rad_s[1] < -0.99
    with pytest.raises(ValueError, match="a rigid plant has one body"):
        axis.reset(0.0, load_angle_rad=1.0)
    with pytest.raises(ValueError, match="Axis.reset.speed_rad_s = nan"):
        axis.reset(0.0, speed_rad_s=float("nan"))
    two = sb.Axis(law=sb.GtServoLaw(kp=0, kd=0), plant=sb.TwoMassPlant(), drive=sb.TorqueDrive(), servo_period_s=1e-3)
    two.reset(0.1, speed_rad_s=2.0, load_angle_rad=0.12, load_speed_rad_s=1.5)
    r = two.run(np.zeros(3), signals=["angle_rad", "load_angle_rad", "speed_rad_s", "load_speed_rad_s"])
    assert (r.angle_rad[0], r.speed_rad_s[0], r.load_angle_rad[0], r.load_speed_rad_s[0]) == (0.1, 2.0, 0.12, 1.5)
