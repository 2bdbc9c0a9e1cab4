"""Bode issue: the card's stepped-sine sweep, broadband measurements, the analytic loop response that checks them,
margins, plots and export. Manual: ADLINK PCI-8254/8258 (seed 004), Bode tool L1978-2045 (adlink.md §5)."""

import numpy as np
import pytest

import servobench as sb
from servobench import frequency as fr

TS = 100e-6  # 10 kHz servo rate: 0.4 fs = 4 kHz


def linear_axis(law="gt", plant="rigid", drive="torque", filters=None, on_load=False, kvff=0, kaff=0):
    """A linear configuration (no friction, saturation, quantisation or noise) with a stable PID."""
    if law == "gt":
        servo = sb.GtServoLaw(kp=38, ki=30, kd=1660, kvff=kvff, kaff=kaff)
    else:  # the same per-tick gains in the ADLINK law: KP*2^-10, KI*2^(-13-5), KD*2^-5
        servo = sb.ApsServoLaw(kp=38 * 1024, ki=30 * 1024, ki_shift=-13, kd=1660 * 32, kvff=kvff, kaff=kaff)
    if plant == "rigid":
        p = sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4)
    else:
        p = sb.TwoMassPlant(jm_kgm2=5e-5, jl_kgm2=5e-5, k_nm_per_rad=300, c_nms_per_rad=0.01)
    if drive == "torque":
        d = sb.TorqueDrive(amps_per_volt=0.8, kt=0.5, current_limit_a=float("inf"), current_bw_hz=1500)
    else:
        d = sb.VelocityDrive(speed_per_volt_rad_s=31.4, kp_nms=0.02, ki_nm_per_rad=4.0, loop_rate_hz=20000,
                             current_limit_a=float("inf"), torque_limit_nm=1e9)
    return sb.Axis(law=servo, plant=p, drive=d, encoder=sb.Encoder(counts_per_rev=10000, quantize=False,
                                                                     on_load=on_load),
                   dac=sb.Dac(quantize=False), servo_period_s=TS, filters=filters)


def assert_agree(meas, ana, which, db=0.1, deg=1.0):
    q = meas.response(which) / ana.response(which)
    gain_err = np.abs(20 * np.log10(np.abs(q)))
    phase_err = np.abs(np.degrees(np.angle(q)))
    worst = np.argmax(gain_err)
    assert gain_err.max() < db, f"{which}: {gain_err.max():.4f} dB at {meas.freq_hz[worst]:.1f} Hz"
    assert phase_err.max() < deg, f"{which}: {phase_err.max():.4f} deg at {meas.freq_hz[np.argmax(phase_err)]:.1f} Hz"


CASES = [
    ("gt", "rigid", "torque", False),
    ("aps", "rigid", "torque", False),
    ("gt", "two_mass", "torque", False),
    ("aps", "two_mass", "torque", False),
    ("gt", "two_mass", "torque", True),      # encoder on the load (fully closed loop)
    ("gt", "rigid", "velocity", False),      # the drive's own PI speed loop at 20 kHz inside
]


@pytest.mark.parametrize("law,plant,drive,on_load", CASES)
def test_stepped_sine_agrees_with_analytic_to_0p1_db_and_1_deg(law, plant, drive, on_load):
    # Issue 5 point 3: plant, open and closed loop, from the start frequency up to 0.4 x the servo rate.
    axis = linear_axis(law, plant, drive, on_load=on_load)
    ana_dense = fr.analytic_response(axis, np.geomspace(5, 4500, 3000))
    assert ana_dense.margins().phase_margin_deg > 5, "the test loop must be stable"
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=0.4 / TS, amplitude_pulse=2, points=25, update_s=0.2)
    assert meas.status == "completed", meas.message
    assert meas.freq_hz[0] == 10 and meas.freq_hz[-1] == pytest.approx(4000)
    ana = fr.analytic_response(axis, meas.freq_hz)
    for which in ("plant", "open_loop", "closed_loop"):
        assert_agree(meas, ana, which)
    # Linear loop: a clean fundamental (the load-side response at 4 kHz is so small that the decaying switching
    # transient still shows: 0.996).
    assert np.all(meas.coherence > 0.99)
    assert np.all(meas.distortion < 1e-3)


def test_agreement_holds_with_a_notch_and_with_feed_forward():
    # Filters in the loop (a notch at the two-mass resonance) and feed-forward on: Y/E is then not the loop gain,
    # but measured and analytic still describe the same run.
    axis0 = linear_axis("gt", "two_mass")
    notch = sb.design.notch(axis0.plant.resonance_hz, TS, q=4.0)
    axis = linear_axis("gt", "two_mass", filters=(notch, None), kvff=20, kaff=100)
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=20, update_s=0.2,
                         feedforward=True)
    ana = fr.analytic_response(axis, meas.freq_hz, feedforward=True)
    for which in ("plant", "open_loop", "closed_loop"):
        assert_agree(meas, ana, which)
    # With feed-forward Y/E differs from the loop gain by the feed-forward path ...
    assert np.max(np.abs(ana.open_loop / ana.loop_gain - 1)) > 0.1
    with pytest.raises(ValueError, match="feed-forward on"):
        meas.margins()
    # ... and without it (the default, decisions B1) the measured Y/E is the loop gain.
    meas_noff = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=20, update_s=0.2)
    ana_noff = fr.analytic_response(axis, meas_noff.freq_hz)
    assert np.max(np.abs(meas_noff.open_loop / ana_noff.loop_gain - 1)) < 0.012
    # Filters bypassed on request: the loop gain loses the notch.
    meas_nf = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=20, update_s=0.2,
                            filters=False)
    ana_nf = fr.analytic_response(axis, meas_nf.freq_hz, filters=False)
    assert_agree(meas_nf, ana_nf, "open_loop")
    assert np.allclose(ana_nf.signals["filters"], 1.0)
    # The axis's own settings are restored after each measurement.
    assert axis.law.kvff == 20 and axis.filters[0] == notch


def test_manual_example_sweep_T13_T14():
    # ADLINK L2023: update 0.1 s at 10 kHz sampling -> 1000 samples per point; L2035: 10-100 Hz, 100 points,
    # 300 pulse on a 10000 pulse/rev motor. Run on the demo axis (quantised encoder, Coulomb friction) at 10 kHz.
    axis = sb.demo_axis()
    axis = sb.Axis(law=sb.GtServoLaw(kp=38, ki=30, kd=1660), plant=axis.plant, drive=axis.drive,
                   encoder=axis.encoder, servo_period_s=TS)
    meas = fr.sine_sweep(axis, amplitude_pulse=300)  # the manual's example (the default amplitude is automatic)
    assert meas.status == "completed"
    assert len(meas) == 100 and meas.signals["ticks"] == 100 * 1000
    assert meas.freq_hz[0] == 10 and meas.freq_hz[-1] == pytest.approx(100)
    assert np.allclose(np.diff(np.log(meas.freq_hz)), np.log(10) / 99)  # log-spaced
    # 10 Hz fills the 0.1 s exactly: one whole period of 1000 samples is analysed (the settling share is cut).
    assert meas.signals["window"][0] == 1000 and meas.signals["periods"][0] == 1
    # Everywhere else whole periods after the settling share.
    w, m = meas.signals["window"], meas.signals["periods"]
    assert np.all(np.abs(w - m * 1e4 / meas.freq_hz) <= 0.5 + 1e-9)
    assert np.all(w[1:] <= 750 + 1e-9 + 1e4 / meas.freq_hz[1:])
    # The nonlinear demo axis still gives a clean first-harmonic response at 300 pulse ...
    assert np.all(meas.coherence > 0.99)
    ana = fr.analytic_response(axis, meas.freq_hz)
    err_db = np.abs(20 * np.log10(np.abs(meas.closed_loop / ana.closed_loop)))
    # ... close to the linear model while the output stays well inside +-10 V (32767 counts) ...
    linear = np.abs(meas.signals["u"]) < 20000
    assert linear[:60].all() and err_db[linear].max() < 0.1
    # ... and off it once the controller output nears the 8 A current limit and the +-10 V clamp.
    assert np.abs(meas.signals["u"]).max() > 30000 and err_db[~linear].max() > 0.1


def test_quality_figures_flag_a_nonlinear_loop():
    # Coulomb friction and a quantised encoder with a 2-pulse sine: the response is no longer a clean sine.
    axis = sb.demo_axis(coulomb_nm=0.02)
    meas = fr.sine_sweep(axis, start_hz=20, end_hz=200, amplitude_pulse=2, points=5, update_s=0.2)
    clean = fr.sine_sweep(linear_axis(), start_hz=20, end_hz=200, amplitude_pulse=2, points=5, update_s=0.2)
    assert meas.distortion.max() > 0.02 and clean.distortion.max() < 1e-3
    assert meas.coherence.min() < 0.99 and clean.coherence.min() > 0.9999


def test_deviation_limit_turns_the_servo_off_and_ends_the_sweep():
    # L2031: the servo is disabled immediately if |E| exceeds the deviation limit.
    axis = linear_axis()
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=200, amplitude_pulse=300, points=20, update_s=0.1,
                         deviation_limit_pulse=100)
    assert meas.status == "deviation_exceeded"
    assert "deviation limit" in meas.message and "servo turned off" in meas.message
    assert abs(meas.signals["stop_error_pulse"]) > 100
    assert 0 < len(meas) < 20
    assert not axis.servo_on
    axis.set_servo_on(True)
    assert axis.servo_on


def test_drive_alarm_ends_the_sweep():
    # L2031: ALM also turns the motor off.
    axis = linear_axis()
    axis = sb.Axis(law=axis.law, plant=axis.plant, encoder=axis.encoder, dac=axis.dac, servo_period_s=TS,
                   drive=axis.drive.replace(alarm_at_s=0.35))
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=100, points=10, update_s=0.1, amplitude_pulse=5)
    assert meas.status == "drive_alarm" and len(meas) == 3
    # The alarm trips inside the tick starting at 0.35 s and is seen at the next tick's start.
    assert meas.signals["stop_time_s"] == pytest.approx(0.35 + 2 * TS, abs=1e-9)
    assert not axis.servo_on


def test_progress_reports_and_user_stop():
    calls = []
    axis = linear_axis()
    fr.sine_sweep(axis, start_hz=10, end_hz=100, points=6, update_s=0.1, amplitude_pulse=5,
                  progress=lambda done, total: calls.append((done, total)))
    assert calls == [(i, 6) for i in range(1, 7)]
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=100, points=6, update_s=0.1, amplitude_pulse=5,
                         progress=lambda done, total: done < 2)
    assert meas.status == "stopped" and len(meas) == 2 and axis.servo_on


def test_progress_bar_on_stderr(capsys):
    fr.sine_sweep(linear_axis(), start_hz=10, end_hz=100, points=3, update_s=0.1, amplitude_pulse=5, progress=True)
    err = capsys.readouterr().err
    assert "Bode sweep" in err and "3/3" in err


def test_sweep_is_deterministic():
    a = fr.sine_sweep(sb.demo_axis(), start_hz=10, end_hz=100, points=5, update_s=0.1)
    b = fr.sine_sweep(sb.demo_axis(), start_hz=10, end_hz=100, points=5, update_s=0.1)
    assert np.array_equal(a.closed_loop, b.closed_loop)


@pytest.mark.parametrize("kwargs,name", [
    (dict(start_hz=0), "start_hz"),
    (dict(start_hz=-5), "start_hz"),
    (dict(end_hz=5000), "end_hz"),               # Nyquist is 5 kHz at 100 us
    (dict(end_hz=float("nan")), "end_hz"),
    (dict(amplitude_pulse=0), "amplitude_pulse"),
    (dict(points=1), "points"),
    (dict(points=2.5), "points"),
    (dict(update_s=0), "update_s"),
    (dict(update_s=0.05), "update_s"),           # less than one period of 10 Hz
    (dict(deviation_limit_pulse=-1), "deviation_limit_pulse"),
    (dict(settle_fraction=0.95), "settle_fraction"),
])
def test_bad_sweep_parameters_are_refused_by_name(kwargs, name):
    with pytest.raises(ValueError, match=name):
        fr.sine_sweep(linear_axis(), **kwargs)


def test_pulse_output_axis_has_no_loop_to_measure():
    axis = sb.Axis(drive=sb.StepperDrive())
    with pytest.raises(ValueError, match="pulse-output"):
        fr.sine_sweep(axis)
    with pytest.raises(ValueError, match="pulse-output"):
        fr.analytic_response(axis, [10.0])


def test_analytic_response_refuses_bad_frequencies():
    axis = linear_axis()
    for f in ([0.0], [-1.0], [5000.0], [float("inf")]):
        with pytest.raises(ValueError, match="freq_hz"):
            fr.analytic_response(axis, f)


@pytest.mark.parametrize("excitation", ["multisine", "chirp"])
@pytest.mark.parametrize("plant", ["rigid", "two_mass"])
def test_broadband_agrees_with_analytic(excitation, plant):
    # Issue 5 point 2: a 1000-line curve from one run, H1 with R as the reference.
    axis = linear_axis("gt", plant)
    meas = fr.broadband_response(axis, excitation=excitation, start_hz=10, amplitude_pulse=2, lines=1000)
    assert len(meas) >= 900
    assert meas.freq_hz[0] >= 10 and meas.freq_hz[-1] <= 4000
    ana = fr.analytic_response(axis, meas.freq_hz)
    for which in ("plant", "open_loop", "closed_loop"):
        assert_agree(meas, ana, which, db=0.01, deg=0.1)
    assert meas.coherence.min() > 0.999


def test_broadband_coherence_drops_with_encoder_noise():
    axis = linear_axis()
    noisy = sb.Axis(law=axis.law, plant=axis.plant, drive=axis.drive, dac=axis.dac, servo_period_s=TS,
                    encoder=sb.Encoder(counts_per_rev=10000, quantize=False, noise_counts=0.5, seed=3))
    meas = fr.broadband_response(noisy, excitation="multisine", start_hz=10, amplitude_pulse=2, lines=200,
                                 periods=6)
    assert meas.coherence.min() < 0.9  # at high frequency Y is small against the noise
    assert np.median(meas.coherence[meas.freq_hz < 100]) > 0.99


def test_excitations():
    x = fr.chirp(start_hz=10, end_hz=1000, duration_s=1.0, servo_period_s=TS, amplitude=3)
    assert len(x) == 10000 and np.max(np.abs(x)) <= 3 and x[0] == 0
    m, bins = fr.multisine(start_hz=10, end_hz=1000, period_ticks=10000, servo_period_s=TS, amplitude=2, periods=2)
    assert len(m) == 20000 and np.isclose(np.max(np.abs(m)), 2) and np.allclose(m[:10000], m[10000:])
    spec = np.abs(np.fft.rfft(m[:10000]))
    assert set(np.nonzero(spec > 1e-9 * spec.max())[0]) == set(bins)
    assert bins[0] == 10 and bins[-1] == 1000
    m2, bins2 = fr.multisine(start_hz=10, end_hz=1000, period_ticks=10000, servo_period_s=TS, lines=50)
    assert len(bins2) <= 50 and len(np.unique(bins2)) == len(bins2)
    for bad in (dict(start_hz=0), dict(end_hz=6000), dict(start_hz=100, end_hz=50)):
        kw = dict(start_hz=10, end_hz=1000, duration_s=1.0, servo_period_s=TS)
        kw.update(bad)
        with pytest.raises(ValueError):
            fr.chirp(**kw)


def test_margins_of_a_known_loop_and_python_control():
    # L(s) = 2/(s(s+1)(s+2)) sampled densely: GM = 20 log10(3) dB at sqrt(2) rad/s.
    f = np.geomspace(0.01, 10, 4000)
    s = 2j * np.pi * f
    loop = 2 / (s * (s + 1) * (s + 2))
    m = fr.margins(f, loop)
    assert m.gain_margin_db == pytest.approx(20 * np.log10(3), abs=1e-3)
    assert m.gm_freq_hz == pytest.approx(np.sqrt(2) / (2 * np.pi), rel=1e-4)
    control = pytest.importorskip("control")
    gm, pm, _sm, wpc, wgc, _wms = control.stability_margins(control.tf([2], [1, 3, 2, 0]))
    assert m.gain_margin_db == pytest.approx(20 * np.log10(gm), abs=1e-3)
    assert m.phase_margin_deg == pytest.approx(pm, abs=0.01)
    assert m.pm_freq_hz == pytest.approx(wgc / (2 * np.pi), rel=1e-4)
    assert "phase margin" in str(m) and "Ms" in str(m)


def test_margins_measured_vs_analytic_and_figures_of_merit():
    # Point 4 on the simulated loop: the figures read from the stepped sine equal the analytic ones.
    axis = linear_axis("gt", "two_mass")
    f = np.geomspace(10, 4000, 200)
    ana = fr.analytic_response(axis, f)
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=200, update_s=0.1)
    ma, mm = ana.margins(), meas.margins()
    assert mm.phase_margin_deg == pytest.approx(ma.phase_margin_deg, abs=0.3)
    assert mm.pm_freq_hz == pytest.approx(ma.pm_freq_hz, rel=0.005)
    assert mm.gain_margin_db == pytest.approx(ma.gain_margin_db, abs=0.1)
    assert mm.bandwidth_hz == pytest.approx(ma.bandwidth_hz, rel=0.005)
    assert mm.ms == pytest.approx(ma.ms, rel=0.01)
    # A PID on an integrating plant is conditionally stable: its lower gain margin is at low frequency.
    assert ma.lower_gain_margin_db < 0 and ma.lower_gm_freq_hz < ma.pm_freq_hz
    # Resonance and anti-resonance of the plant: those of the two-mass mechanics, read as the peak and the dip of
    # |Y/U|. A damped mode on the falling -40 dB/decade background peaks slightly off its natural frequency (+0.9 %
    # here), and sampling moves the anti-resonance zeros (-0.5 % at 10 kHz; the ZOH maps only poles exactly).
    dense = fr.analytic_response(axis, np.geomspace(50, 4000, 4000))
    peaks = dense.resonances()
    kinds = [p.kind for p in peaks]
    assert kinds == ["antiresonance", "resonance"]
    assert peaks[0].freq_hz == pytest.approx(axis.plant.antiresonance_hz, rel=0.02)
    assert peaks[1].freq_hz == pytest.approx(axis.plant.resonance_hz, rel=0.02)
    assert peaks[0].prominence_db > 10 and peaks[1].prominence_db > 10
    assert fr.analytic_response(linear_axis(), np.geomspace(10, 4000, 1000)).resonances() == []


def test_frd_export():
    control = pytest.importorskip("control")
    axis = linear_axis()
    ana = fr.analytic_response(axis, np.geomspace(10, 1000, 50))
    frd = ana.to_frd("loop_gain")
    assert isinstance(frd, control.FrequencyResponseData)
    assert np.allclose(np.squeeze(frd.frdata), ana.loop_gain)
    assert np.allclose(frd.omega, 2 * np.pi * ana.freq_hz)


def test_bode_and_nyquist_plots(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    axis = linear_axis("gt", "two_mass")
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=4000, amplitude_pulse=2, points=30, update_s=0.1)
    ana = fr.analytic_response(axis, np.geomspace(10, 4000, 500))
    fig = sb.plot.bode([meas, ana], which="open_loop", path=tmp_path / "bode.png")
    ax_mag, ax_ph = fig.axes
    assert (tmp_path / "bode.png").stat().st_size > 10000
    labels = [line.get_label() for line in ax_mag.get_lines()]
    assert "measured (stepped sine): open loop Y/E" in labels and "model (analytic): open loop Y/E" in labels
    assert any("PM" in t.get_text() for t in ax_mag.texts)  # margins annotated
    measured = [line for line in ax_mag.get_lines() if line.get_label().startswith("measured (stepped")][0]
    assert measured.get_linestyle() == "None" and measured.get_marker() == "o"
    fig = meas.plot()
    assert len(fig.axes[0].get_lines()) >= 3
    fig = sb.plot.nyquist([ana, meas], path=tmp_path / "nyq.svg")
    assert (tmp_path / "nyq.svg").exists()
    assert any("1/Ms" in line.get_label() for line in fig.axes[0].get_lines())
    # The old array form still works.
    sb.plot.bode(ana.freq_hz, {"L": ana.loop_gain})
    matplotlib.pyplot.close("all")


def test_axis_injection_servo_off_and_error_guard():
    axis = linear_axis()
    # Servo off: the law is silent; an injected voltage alone drives the plant, one tick late.
    axis.set_servo_on(False)
    inj = np.zeros(50)
    inj[0] = 1.0
    run = axis.run(np.zeros(50), injection_v=inj)
    assert run.volts[0] == 1.0 and np.all(run.volts[1:] == 0) and np.all(run.u == 0)
    assert run.current_a[0] == 0 and run.current_a[2] > 0
    assert run.fb_pos[-1] > 0
    axis.set_servo_on(True)
    # The error guard: a 1000-pulse step with a 100-pulse limit stops at the first tick.
    run = axis.run(np.full(100, 1000.0), error_limit_pulse=100)
    assert run.stopped == "error_limit" and len(run) == 1 and run.stop_error_pulse > 100
    assert not axis.servo_on
    with pytest.raises(ValueError, match="error_limit_pulse"):
        axis.run(np.zeros(3), error_limit_pulse=-1)
    with pytest.raises(ValueError, match="injection_v"):
        axis.run(np.zeros(3), injection_v=np.zeros(4))
    assert axis.last_command_pulse == 1000.0


@pytest.mark.filterwarnings("ignore:stability_margins. Falling back:UserWarning")
@pytest.mark.filterwarnings("ignore:Badly conditioned filter coefficients")
@pytest.mark.parametrize("feedforward", [False, True])
def test_linear_model_for_python_control_matches_the_analytic_response(feedforward):
    control = pytest.importorskip("control")
    notch = sb.design.notch(550, TS, q=4.0)
    axis = linear_axis("aps", "two_mass", filters=(notch, None), kvff=20, kaff=100)
    model = fr.linear_model(axis, feedforward=feedforward)
    f = np.geomspace(10, 4000, 50)
    ana = fr.analytic_response(axis, f, feedforward=feedforward)
    z = np.exp(2j * np.pi * f * TS)
    for name in ("plant", "loop_gain", "closed_loop"):
        assert model[name].dt == TS
        assert np.allclose(model[name](z), ana.response(name), rtol=1e-8, atol=0)
    # python-control's own margins on the exported loop agree with ours.
    gm, pm, _sm, _wpc, wgc, _wms = control.stability_margins(model["loop_gain"])
    m = fr.analytic_response(axis, np.geomspace(10, 4900, 20000)).margins()
    assert m.phase_margin_deg == pytest.approx(pm, abs=0.05)
    assert m.pm_freq_hz == pytest.approx(wgc / (2 * np.pi), rel=1e-3)


def test_measured_margins_leave_out_points_the_encoder_did_not_see():
    # A coarse encoder near Nyquist sees no motion: Y/E = 0 there carries no phase. margins() of the measurement
    # leaves those points out instead of refusing the whole curve; with fewer than 2 seen points it says why.
    import dataclasses

    axis = linear_axis("gt", "rigid")
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=2000, amplitude_pulse=2, points=12, update_s=0.1)
    assert meas.status == "completed", meas.message
    full = meas.margins()
    ol = np.array(meas.open_loop)
    ol[-1] = 0.0
    blind = dataclasses.replace(meas, open_loop=ol)
    m = blind.margins()
    assert m.phase_margin_deg == pytest.approx(full.phase_margin_deg, abs=1e-9)
    assert m.pm_freq_hz == pytest.approx(full.pm_freq_hz, rel=1e-12)
    with pytest.raises(ValueError, match="only 1 of 12 measured points"):
        dataclasses.replace(meas, open_loop=np.where(np.arange(12) == 3, ol, 0.0)).margins()
