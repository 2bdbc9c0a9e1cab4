"""Issue 20 points 1-3 and 6 on measurements: every measured point judged (saturation, coherence, distortion,
quantisation, deviation trips), the automatic amplitude, the README's bode command against the model, the CLI's
verdict and exit code, and plots that say what they show."""

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import servobench as sb
from servobench import cli
from servobench import frequency as fr
from servobench.agreement import model_agreement
from servobench.examples import demo_axis

matplotlib.use("Agg")
AXES = Path(__file__).resolve().parents[2] / "examples" / "axes"


def readme_axis():
    return sb.load_axis(AXES / "gt_rigid.toml")


def test_saturating_sweep_says_so_and_leaves_the_points_out():
    # The issue's --amplitude-pulse 1e6: every point drives the DAC to full scale; the result must say so.
    meas = fr.sine_sweep(readme_axis(), start_hz=10, end_hz=1000, amplitude_pulse=1e6, points=20)
    assert meas.status == "completed"
    assert all("DAC saturated" in f for f in meas.flags)
    assert np.all(meas.signals["dac_saturated_ticks"] > 0)
    assert not meas.usable.any()
    with pytest.raises(ValueError, match="no margin"):
        meas.margins()
    assert "20 flagged" in meas.message


def test_noisy_sweep_flags_low_coherence():
    axis = readme_axis()
    axis = sb.Axis(law=axis.law, drive=axis.drive, plant=axis.plant, servo_period_s=axis.servo_period_s,
                   encoder=sb.Encoder(counts_per_rev=10000, noise_counts=30.0, seed=3))
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=1000, points=20)
    low = meas.coherence < 0.99
    assert low.any()
    assert all("coherence" in f for f, bad in zip(meas.flags, low) if bad)
    assert not meas.usable[low].any()


def test_deviation_tripping_sweep_says_so():
    meas = fr.sine_sweep(readme_axis(), start_hz=10, end_hz=1000, points=20, deviation_limit_pulse=50)
    assert meas.status == "deviation_exceeded"
    assert "deviation limit exceeded" in meas.message and "servo turned off" in meas.message


def test_broadband_saturation_and_coherence_are_judged():
    meas = fr.broadband_response(readme_axis(), start_hz=10, end_hz=1000, amplitude_pulse=1e6, lines=50)
    assert meas.signals["dac_saturated_ticks"][0] > 0
    assert all("dac saturated" in f for f in meas.flags)
    with pytest.raises(ValueError, match="no margin"):
        meas.margins()


def test_judgement_does_not_depend_on_where_the_axis_stands():
    # The sweep runs around the axis's present position. An axis standing at 10,000 pulse (after a move) once read
    # 5-7 % "distortion" at 30 of 40 points: the window's mean leaked into the harmonic bins. The judgement of a
    # point must not depend on the offset it is measured about.
    here, there = demo_axis(), demo_axis()
    there.run(np.full(2000, 10000.0))
    assert abs(there.feedback_pulse - 10000.0) < 2
    a = fr.sine_sweep(here, start_hz=10, end_hz=1000, points=40, update_s=0.1)
    b = fr.sine_sweep(there, start_hz=10, end_hz=1000, points=40, update_s=0.1)
    # The 1-count encoder's quantisation pattern depends on the position itself (a physical difference): below
    # 400 Hz it moves the distortion by <= 1.2e-3 (measured), against the 5-7e-2 the leak added and the 5e-2
    # threshold; above, where the response is a few counts, only the verdicts are compared.
    low = a.freq_hz < 400
    np.testing.assert_allclose(b.distortion[low], a.distortion[low], atol=2e-3)
    assert sum(bool(f) for f in b.flags) == sum(bool(f) for f in a.flags)
    assert a.margins().stable and b.margins().stable


def test_automatic_amplitude_stays_linear_and_agrees_with_the_model():
    # The README's command: the automatic amplitude keeps the output stage out of saturation and above the
    # quantisation floor; where the model applies the measurement agrees within 1 dB / 5 deg, and it says where not.
    axis = readme_axis()
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=1000)
    amp = meas.signals["amplitude_pulse"]
    assert amp.shape == (100,) and np.all(amp > 0) and amp[0] > amp[-1]
    assert np.all(meas.signals["dac_saturated_ticks"] == 0) and np.all(meas.signals["current_saturated_ticks"] == 0)
    agr = model_agreement(axis, meas)
    assert agr["agrees"] and agr["max_gain_error_db"] < 1.0 and agr["max_phase_error_deg"] < 5.0
    assert agr["model_applies"].sum() >= 70
    for lo, hi in agr["not_applicable_hz"]:
        assert lo > 300  # only the top of the band, where |Y| falls to the encoder's resolution
    assert "encoder quantisation" in agr["summary"]
    m = meas.margins()
    ana = fr.analytic_margins(axis)
    assert m.stable and m.stability["method"] == "Nyquist"
    assert m.phase_margin_deg == pytest.approx(ana.phase_margin_deg, abs=1.0)
    assert "left out" in m.note


def test_friction_at_low_amplitude_is_named_where_the_model_does_not_apply():
    axis = demo_axis(coulomb_nm=0.05)
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=200, amplitude_pulse=20, points=12)
    agr = model_agreement(axis, meas)
    assert not agr["model_applies"][0] and "friction" in agr["why_not"][0]
    assert "friction" in agr["summary"]


def unstable_axis():
    axis = readme_axis()
    axis.set_law(axis.law.replace(kp=38 * 30, kd=830 * 4))
    return axis


def test_unstable_loop_margins_are_marked_and_cli_exits_1(tmp_path, capsys):
    m = fr.analytic_margins(unstable_axis())
    assert m.verdict == "UNSTABLE" and str(m).startswith("UNSTABLE")
    path = tmp_path / "unstable.toml"
    text = (AXES / "gt_rigid.toml").read_text().replace("kp = 38", "kp = 1140").replace("kd = 830", "kd = 3320")
    path.write_text(text)
    code = cli.main(["bode", str(path), "--analytic", "--end-hz", "1000", "--out", str(tmp_path), "--format", "png"])
    out = capsys.readouterr()
    assert code == 1
    assert out.out.startswith("UNSTABLE")
    assert "UNSTABLE" in out.err
    import json

    rep = json.loads((tmp_path / "unstable_bode.json").read_text())
    assert rep["unstable"] and rep["analytic_margins"]["stable"] is False


def test_cli_saturating_sweep_reads_no_margin_and_exits_1(tmp_path, capsys):
    code = cli.main(["bode", str(AXES / "gt_rigid.toml"), "--end-hz", "1000", "--points", "10",
                     "--amplitude-pulse", "1e6", "--out", str(tmp_path)])
    out = capsys.readouterr()
    assert code == 1
    assert "no measured margin" in out.out and "DAC" in out.out and "phase margin inf" not in out.out
    assert "no measured margin" in out.err


def test_readme_bode_command_reports_amplitudes_flags_and_agreement(tmp_path, capsys):
    code = cli.main(["bode", str(AXES / "gt_rigid.toml"), "--end-hz", "1000", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0
    assert "excitation amplitude chosen per point" in out
    assert "measured vs model within" in out and "(within 1 dB / 5 deg)" in out
    import json

    rep = json.loads((tmp_path / "gt_rigid_bode.json").read_text())
    assert rep["amplitude_pulse"] == "auto" and len(rep["amplitude_pulse_used"]) == 100
    assert rep["model_agreement"]["agrees"] and rep["margins"]["stable"]
    assert all("freq_hz" in p and p["reason"] for p in rep["points_flagged"])


def test_plots_name_their_sources_and_return_what_they_drew(tmp_path):
    import matplotlib.pyplot as plt

    axis = readme_axis()
    meas = fr.sine_sweep(axis, start_hz=10, end_hz=1000, points=30)
    ana = fr.analytic_response(axis, np.geomspace(10, 1000, 300))
    fig, axs = plt.subplots(2, 1)
    p = sb.plot.bode([meas, ana], which="open_loop", ax=axs)
    assert p.figure is fig and p.drawn_axes == tuple(axs)
    labels = [ln.get_label() for ln in axs[0].get_lines()]
    assert "measured (stepped sine): open loop Y/E" in labels and "model (analytic): open loop Y/E" in labels
    assert any("flagged" in lab for lab in labels)  # hollow: left out of margins
    texts = [t.get_text() for t in axs[0].texts]
    assert any(t.startswith("measured (stepped sine): stable") for t in texts)
    assert any(t.startswith("model (analytic): stable") for t in texts)
    assert any("lower GM" in t for t in texts)
    assert set(p.data["margins"]) == {"measured (stepped sine)", "model (analytic)"}
    d = p.data["measured (stepped sine): open loop Y/E"]
    assert len(d["freq_hz"]) == 30 and d["usable"].dtype == bool and (~d["usable"]).any()
    # before/after labels
    after = fr.sine_sweep(axis, start_hz=10, end_hz=1000, points=10)
    q = sb.plot.bode([meas, after], which="open_loop", labels=["before", "after"], margins=False)
    labels = [ln.get_label() for ln in q.axes[0].get_lines()]
    assert "before: open loop Y/E" in labels and "after: open loop Y/E" in labels
    q = sb.plot.bode([meas, after], which="open_loop", margins=False)
    labels = [ln.get_label() for ln in q.axes[0].get_lines()]
    assert "measured (stepped sine) #1: open loop Y/E" in labels
    # an unstable loop says so on the plot
    u = fr.analytic_response(unstable_axis(), np.geomspace(10, 2000, 300))
    r = sb.plot.bode(u, which="open_loop")
    assert any("UNSTABLE" in t.get_text() for a in r.axes for t in a.texts)
    # Nyquist: frequency arrows and the verdict
    fig2, ax2 = plt.subplots()
    n = sb.plot.nyquist([ana, meas], which="open_loop", ax=ax2)
    assert n.figure is fig2 and "stable" in ax2.get_title()
    assert sum(1 for c in ax2.texts if c.get_text().endswith("Hz")) >= 6
    assert len(ax2.patches) + len([c for c in ax2.get_children() if type(c).__name__ == "Annotation"]) >= 6
    # every plot function accepts ax= and returns its data
    run = axis.run(np.full(200, 100.0), signals=("cmd_pos", "fb_pos", "error", "volts", "time_s"))
    fig3, ax3 = plt.subplots(3, 1)
    assert sb.plot.response(run, ax=ax3).figure is fig3
    fig4, ax4 = plt.subplots()
    fc = sb.plot.friction_curve(axis.plant, ax=ax4)
    assert fc.figure is fig4 and len(fc.data["torque_nm"]) == 801
    fig5, ax5 = plt.subplots(2, 1)
    assert sb.plot.plant_bode(axis.plant, period_s=axis.servo_period_s, ax=ax5).figure is fig5
    fig6, ax6 = plt.subplots(2, 1)
    assert sb.plot.filter_response(sb.design.notch(100, 1e-4, q=3), ax=ax6).figure is fig6
    plt.close("all")
