"""The `servobench` command line and its axis files (issue 11.2): each sub-command on a small case, the files it
writes, and clear errors (exit 2, no traceback) on bad input."""

import csv
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import servobench as sb
from servobench import cli
from servobench.axisfile import (AxisFileError, axis_to_dict, load_axis, read_axis, save_axis, schema,
                                 schema_markdown)

ROOT = Path(__file__).resolve().parents[2]
AXES = ROOT / "examples" / "axes"
EXAMPLES = sorted(p.name for p in AXES.iterdir() if p.suffix in (".toml", ".json"))


def run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return code, out, err


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


# ----------------------------------------------------------------------------------------------------------------
# Axis files
# ----------------------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", EXAMPLES)
def test_example_axis_files_load_and_round_trip(name, tmp_path):
    axis = load_axis(AXES / name)
    axis.run(np.zeros(10))
    for ext in ("toml", "json"):
        p = save_axis(axis, tmp_path / f"copy.{ext}", filter_specs=read_axis(AXES / name).get("filters"))
        assert repr(load_axis(p)) == repr(axis)


def test_examples_cover_the_schema():
    assert {"gt_rigid.toml", "aps_two_mass.toml", "velocity_drive.json"} <= set(EXAMPLES)
    # gt_rigid.toml is the demo's reference axis, key for key
    assert repr(load_axis(AXES / "gt_rigid.toml")) == repr(sb.demo_axis())
    two = load_axis(AXES / "aps_two_mass.toml")
    assert isinstance(two.law, sb.ApsServoLaw) and isinstance(two.plant, sb.TwoMassPlant)
    # the notch designed in the file = the design function's integers at the axis's period
    assert two.filters[0] == sb.design.notch(300.0, 250e-6, q=1.0, prewarp=True).to_adlink()
    assert isinstance(load_axis(AXES / "velocity_drive.json").drive, sb.VelocityDrive)


def test_defaults_are_the_constructors(tmp_path):
    p = tmp_path / "empty.toml"
    p.write_text('[law]\ntype = "aps"\n')
    axis = load_axis(p)
    assert axis.law == sb.ApsServoLaw() and axis.drive == sb.TorqueDrive() and axis.plant == sb.RigidPlant()
    assert axis.servo_period_s == sb.ApsServoLaw.DEFAULT_PERIOD_S  # the card's default period (250 us)
    d = axis_to_dict(axis)
    assert d["law"]["type"] == "aps" and d["law"]["kp_shift"] == -5 and "filters" not in d


def test_every_constructor_field_is_in_the_schema():
    keys = {r["key"] for r in schema()}
    for table, classes in (("law", [sb.GtServoLaw, sb.ApsServoLaw]),
                           ("drive", [sb.TorqueDrive, sb.VelocityDrive, sb.ServoPositionDrive, sb.StepperDrive]),
                           ("plant", [sb.RigidPlant, sb.TwoMassPlant]), ("encoder", [sb.Encoder]), ("dac", [sb.Dac]),
                           ("switches", [sb.Switches])):
        for cls in classes:
            assert {f"{table}.{f}" for f in cls.FIELDS} <= keys, cls


def test_docs_show_the_generated_schema_table():
    text = (ROOT / "docs" / "cli.md").read_text()
    m = re.search(r"<!-- schema-table:begin.*?-->\n(.*?)<!-- schema-table:end -->", text, re.S)
    assert m, "docs/cli.md lost its schema-table markers"
    assert m.group(1).strip() == schema_markdown().strip(), \
        "docs/cli.md's schema table is stale: python -m servobench.axisfile --schema-markdown"
    assert text.count("\n# ") + text.startswith("# ") == 1  # one top heading (the site's toctree title)


BAD_FILES = [
    ("syntax.toml", '[law]\nkp = 38\nkd = = 3\n', r"line 3, column \d+: invalid TOML"),
    ("syntax.json", '{\n "law": {"kp": 38,\n }\n}\n', r"line 3, column \d+: invalid JSON"),
    ("unknown.toml", "[law]\nkpp = 38\n", r"law\.kpp: unknown key; did you mean 'kp'\?"),
    ("unknown_table.toml", "[plnt]\ntype = 'rigid'\n", r"plnt: unknown key or table; did you mean 'plant'\?"),
    ("range.toml", "[law]\nkp = 40000\n", r"law\.kp: GtServoLaw\.kp = 40000 is outside the allowed range 0\.\.32767"),
    ("range.json", '{"law": {"type": "aps", "kp_shift": 40}}',
     r"law\.kp_shift: ApsServoLaw\.kp_shift = 40 is outside the allowed range -31\.\.31"),
    ("period.toml", "servo_period_s = 1.0\n", r"servo_period_s: Axis\.servo_period_s = 1 is outside the allowed range"),
    ("type.toml", '[law]\nkp = "high"\n', r'law\.kp: must be a number, got a string "high"'),
    ("bool.toml", "[encoder]\nquantize = 1\n", r"encoder\.quantize: must be true or false"),
    ("variant.toml", '[drive]\nmode = "velocty"\n', r"drive\.mode: 'velocty' is not one of .*did you mean 'velocity'\?"),
    ("wrong_form.toml", "[law]\nkp_shift = -4\n", r'law\.kp_shift: is not a key of law\.type = "gt".*type = "aps"'),
    ("filter.toml", '[[filters]]\ntype = "lowpass"\ncutoff_hz = 5000\n',
     r"filters\[0\]\.cutoff_hz: lowpass\.cutoff_hz = 5000 is outside the allowed range 0 < f < 2500 Hz"),
    ("filter_missing.toml", '[[filters]]\ntype = "notch"\nq = 2\n', r"filters\[0\]\.center_hz: missing"),
    ("cross.toml", "[plant]\ncoulomb_nm = 0.1\nstatic_nm = 0.05\n", r"plant\.static_nm: RigidPlant\.static_nm = 0\.05"),
    ("whole.toml", "[encoder]\ncounts_per_rev = 1.5\n", r"encoder\.counts_per_rev: .*not a whole number"),
    ("axis.yaml", "law: {}\n", r"unknown file type '\.yaml'"),
]


@pytest.mark.parametrize("name, text, message", BAD_FILES, ids=[b[0] for b in BAD_FILES])
def test_bad_axis_file_exits_2_with_file_key_and_message(name, text, message, tmp_path, capsys):
    p = tmp_path / name
    p.write_text(text)
    code, out, err = run(capsys, "simulate", p, "--out", tmp_path / "out")
    assert code == 2
    assert err.startswith(f"servobench: error: {p}: "), err
    assert re.search(message, err), err
    with pytest.raises(AxisFileError):
        load_axis(p)
    assert not (tmp_path / "out").exists()  # nothing written


def test_missing_axis_file(tmp_path, capsys):
    code, _, err = run(capsys, "bode", tmp_path / "nope.toml")
    assert code == 2 and err.strip() == f"servobench: error: {tmp_path / 'nope.toml'}: no such file"


# ----------------------------------------------------------------------------------------------------------------
# The parser
# ----------------------------------------------------------------------------------------------------------------
def test_help_in_a_subprocess():
    r = subprocess.run([sys.executable, "-m", "servobench", "--help"], capture_output=True, text=True)
    assert r.returncode == 0
    for name in ("simulate", "bode", "tune", "identify", "demo"):
        assert name in r.stdout


@pytest.mark.parametrize("command, unit", [("simulate", "pulse/tick^2"), ("bode", "Hz"), ("tune", "deg"),
                                           ("identify", "N*m"), ("demo", "servo law")])
def test_each_command_has_help_with_units(command, unit, capsys):
    code, out, _ = run(capsys, command, "--help")
    assert code == 0 and unit in out


def test_usage_errors_exit_2(tmp_path, capsys):
    assert run(capsys, "frobnicate")[0] == 2
    assert run(capsys, "simulate")[0] == 2  # AXIS missing (argparse)
    code, _, err = run(capsys, "simulate", AXES / "gt_rigid.toml", "--vel", "0", "--out", tmp_path)
    assert code == 2 and "vel_pulse_per_tick" in err
    code, _, err = run(capsys, "bode", AXES / "gt_rigid.toml", "--end-hz", "3000", "--out", tmp_path)
    assert code == 2 and "Nyquist (2500 Hz" in err


# ----------------------------------------------------------------------------------------------------------------
# simulate
# ----------------------------------------------------------------------------------------------------------------
def test_simulate_writes_trace_metrics_and_plot(tmp_path, capsys):
    code, out, _ = run(capsys, "simulate", AXES / "gt_rigid.toml", "--distance-pulse", 2000, "--dwell-after", 300,
                       "--out", tmp_path, "--format", "svg")
    assert code == 0
    for f in ("gt_rigid_trace.csv", "gt_rigid_metrics.json", "gt_rigid_response.svg"):
        assert f"wrote {tmp_path / f}" in out
    header, data = read_csv(tmp_path / "gt_rigid_trace.csv")
    assert header[:5] == ["time_s [s]", "cmd_pos [pulse]", "cmd_vel [pulse/tick]", "cmd_acc [pulse/tick^2]",
                          "fb_pos [pulse]"]
    assert "volts [V]" in header and "torque_nm [N*m]" in header and len(header) == len(sb.SIGNALS)
    rep = json.loads((tmp_path / "gt_rigid_metrics.json").read_text())
    assert set(rep["metrics"]) >= {"rise_time_s", "overshoot_pulse", "settling_time_s", "peak_following_error_pulse"}
    # the same move through the library gives the same figures and the same trace
    axis = sb.demo_axis()
    run_ = axis.run(sb.trapezoid_move(distance_pulse=2000, vel_pulse_per_tick=20, acc_pulse_per_tick2=0.1,
                                      dwell_before=50, dwell_after=300))
    assert rep["ticks"] == len(run_) == len(data)
    np.testing.assert_allclose(data[:, header.index("fb_pos [pulse]")], run_.fb_pos)
    m = sb.move_metrics(run_)
    assert rep["metrics"]["peak_following_error_pulse"] == pytest.approx(m.peak_following_error_pulse)
    assert rep["metrics"]["final_error_pulse"] == m.final_error_pulse and abs(m.final_error_pulse) <= 1
    assert (tmp_path / "gt_rigid_response.svg").read_text().lstrip().startswith("<?xml")


def test_simulate_s_curve_with_fixed_ticks(tmp_path, capsys):
    code, _, _ = run(capsys, "simulate", AXES / "aps_two_mass.toml", "--move", "s-curve", "--distance-pulse", 1000,
                     "--vel", 10, "--acc", 0.05, "--jerk", 0.002, "--ticks", 700, "--out", tmp_path, "-q")
    assert code == 0
    _, data = read_csv(tmp_path / "aps_two_mass_trace.csv")
    assert len(data) == 700 and data[-1, 1] == 1000  # held at the target
    assert json.loads((tmp_path / "aps_two_mass_metrics.json").read_text())["move"]["jerk_pulse_per_tick3"] == 0.002


# ----------------------------------------------------------------------------------------------------------------
# bode
# ----------------------------------------------------------------------------------------------------------------
def test_bode_sweep_matches_the_analytic_model(tmp_path, capsys):
    code, out, _ = run(capsys, "bode", AXES / "gt_rigid.toml", "--start-hz", 20, "--end-hz", 500, "--points", 12,
                       "--amplitude-pulse", 20, "--update-s", 0.05, "--out", tmp_path, "-q")
    assert code == 0
    header, data = read_csv(tmp_path / "gt_rigid_bode.csv")
    assert header[0] == "freq_hz [Hz]" and "open_loop_gain_db [dB re 1 pulse/pulse]" in header
    assert "plant_gain_db [dB re 1 pulse/count]" in header and "coherence [1]" in header
    assert len(data) == 12 and data[0, 0] == pytest.approx(20) and data[-1, 0] == pytest.approx(500)
    rep = json.loads((tmp_path / "gt_rigid_bode.json").read_text())
    assert rep["status"] == "completed" and rep["method"] == "stepped sine"
    # the reference axis: phase margin about 47 deg at 59 Hz (test_demo); measured within 3 deg of the model
    assert abs(rep["margins"]["phase_margin_deg"] - rep["analytic_margins"]["phase_margin_deg"]) < 3
    assert 40 < rep["margins"]["phase_margin_deg"] < 55
    assert (tmp_path / "gt_rigid_bode.png").stat().st_size > 10000


def test_bode_analytic_plant(tmp_path, capsys):
    code, _, _ = run(capsys, "bode", AXES / "aps_two_mass.toml", "--kind", "plant", "--analytic", "--end-hz", 1000,
                     "--points", 50, "--out", tmp_path, "-q")
    assert code == 0
    header, data = read_csv(tmp_path / "aps_two_mass_bode.csv")
    ref = sb.analytic_response(load_axis(AXES / "aps_two_mass.toml"), data[:, 0])
    np.testing.assert_allclose(data[:, header.index("plant_gain_db [dB re 1 pulse/count]")], ref.gain_db("plant"),
                               atol=1e-6)


def test_bode_needs_a_voltage_output_axis(tmp_path, capsys):
    p = tmp_path / "stepper.toml"
    p.write_text('[drive]\nmode = "stepper"\nmicrosteps = 8\n')
    code, _, err = run(capsys, "bode", p, "--out", tmp_path)
    assert code == 2 and f"{p}: drive.mode: bode needs" in err


# ----------------------------------------------------------------------------------------------------------------
# tune
# ----------------------------------------------------------------------------------------------------------------
def test_tune_model_writes_a_loadable_tuned_axis(tmp_path, capsys):
    code, out, _ = run(capsys, "tune", AXES / "gt_rigid.toml", "--points", 25, "--out", tmp_path, "-q")
    assert code == 0
    tuned = load_axis(tmp_path / "gt_rigid_tuned.toml")
    expect = sb.model_based_tune(sb.demo_axis())
    assert tuned.law == expect.law and tuned.law != sb.demo_axis().law  # the new gains, feed-forward off
    assert tuned.plant == sb.demo_axis().plant  # the rest is the input's
    rep = json.loads((tmp_path / "gt_rigid_tune.json").read_text())
    assert rep["after"]["law"]["kp"] == expect.law.kp
    assert rep["after"]["analytic_margins"]["phase_margin_deg"] == pytest.approx(60, abs=2)
    assert rep["after"]["measured_margins"]["phase_margin_deg"] == pytest.approx(60, abs=5)  # the sweep agrees
    assert rep["after"]["measured_margins"]["pm_freq_hz"] > rep["before"]["analytic_margins"]["pm_freq_hz"]
    for f in ("gt_rigid_tune_step.png", "gt_rigid_tune_bode.png"):
        assert (tmp_path / f).stat().st_size > 10000


def test_tune_model_keeps_the_notch_in_design_form(tmp_path, capsys):
    code, _, _ = run(capsys, "tune", AXES / "aps_two_mass.toml", "--no-sweep", "--out", tmp_path, "-q")
    assert code == 0
    p = tmp_path / "aps_two_mass_tuned.toml"
    f0 = read_axis(p)["filters"][0]
    assert f0["type"] == "notch" and f0["adlink"] is True
    tuned = load_axis(p)
    expect = sb.model_based_tune(load_axis(AXES / "aps_two_mass.toml"))
    assert tuned.law == expect.law and tuned.filters[0] == expect.filters[0]


def test_tune_relay_on_a_velocity_drive(tmp_path, capsys):
    code, out, _ = run(capsys, "tune", AXES / "velocity_drive.json", "--method", "relay", "--data-length", 20,
                       "--points", 15, "--out", tmp_path)
    assert code == 0 and "relay tuning: completed" in out
    tuned = load_axis(tmp_path / "velocity_drive_tuned.json")  # the input's format
    res = sb.relay_autotune(load_axis(AXES / "velocity_drive.json"), data_length=20)
    assert tuned.law == res.gt_law(tuned.law) and tuned.law.kp > 0
    rep = json.loads((tmp_path / "velocity_drive_tune.json").read_text())
    assert rep["result"]["status"] == "completed" and rep["result"]["kp_spread"] < 0.1
    assert 45 < rep["after"]["measured_margins"]["phase_margin_deg"] < 75


def test_relay_needs_a_velocity_drive(tmp_path, capsys):
    code, _, err = run(capsys, "tune", AXES / "gt_rigid.toml", "--method", "relay", "--out", tmp_path)
    assert code == 2
    assert err.startswith(f"servobench: error: {AXES / 'gt_rigid.toml'}: drive.mode: relay tuning needs a "
                          "velocity-mode drive")
    assert "--method model" in err and not (tmp_path / "gt_rigid_tuned.toml").exists()


# ----------------------------------------------------------------------------------------------------------------
# identify
# ----------------------------------------------------------------------------------------------------------------
RIGID = {"inertia_kgm2": 1e-4, "viscous_nms": 1e-4, "coulomb_nm": 0.005}  # gt_rigid.toml's plant


def test_identify_twin_then_its_log(tmp_path, capsys):
    guesses = ["inertia_kgm2=1.5e-4", "viscous_nms=0.5e-4", "coulomb_nm=0.0075"]  # every guess 50 % off
    code, out, _ = run(capsys, "identify", AXES / "gt_rigid.toml", "--guess", *guesses, "--out", tmp_path, "-q")
    assert code == 0
    rep = json.loads((tmp_path / "gt_rigid_identified.json").read_text())
    for k, true in RIGID.items():  # stated tolerance: 1 % (the library reaches ~0.02 % on this noiseless twin)
        e = rep["parameters"][k]
        assert abs(e["value"] / true - 1) < 0.01 and 0 < e["std_error"] < 0.01 * true, (k, e)
        assert abs(rep["twin_error_pct"][k]) < 1
    ident = load_axis(tmp_path / "gt_rigid_identified.toml")
    assert ident.plant.inertia_kgm2 == pytest.approx(rep["parameters"]["inertia_kgm2"]["value"], rel=1e-12)
    assert ident.law == sb.demo_axis().law
    assert (tmp_path / "gt_rigid_identify_fit.png").stat().st_size > 10000
    # the log it wrote, read back through --log: the same plant
    log = tmp_path / "gt_rigid_identify_log.csv"
    assert read_csv(log)[0] == ["time_s [s]", "torque_nm [N*m]", "position_pulse [pulse]", "volts [V]"]
    code, _, _ = run(capsys, "identify", "--log", log, "--guess", *guesses, "--current-bw-hz", 1500,
                     "--out", tmp_path, "-q")
    assert code == 0
    rep2 = json.loads((tmp_path / "gt_rigid_identify_log_identified.json").read_text())
    for k, true in RIGID.items():
        assert abs(rep2["parameters"][k]["value"] / true - 1) < 0.01
    assert load_axis(tmp_path / "gt_rigid_identify_log_identified.toml").servo_period_s == pytest.approx(200e-6)


def test_identify_two_mass_twin(tmp_path, capsys):
    # aps_two_mass.toml: jm 1e-4, jl 2e-4, k 300, c 0.01, motor viscous 2e-4, Coulomb 0.03; guesses 50 % off
    true = {"jm_kgm2": 1e-4, "jl_kgm2": 2e-4, "k_nm_per_rad": 300.0, "c_nms_per_rad": 0.01,
            "motor_viscous_nms": 2e-4, "motor_coulomb_nm": 0.03}
    guesses = [f"{k}={v * f}" for (k, v), f in zip(true.items(), [1.5, 0.5, 1.5, 1.5, 0.5, 0.5])]
    code, _, _ = run(capsys, "identify", AXES / "aps_two_mass.toml", "--model", "two-mass", "--amplitude-v", 0.3,
                     "--guess", *guesses, "--out", tmp_path, "-q")
    assert code == 0
    rep = json.loads((tmp_path / "aps_two_mass_identified.json").read_text())
    assert rep["model"] == "two_mass"
    for k, v in true.items():  # stated tolerance: 2 % (as tests/python/test_identify.py)
        assert abs(rep["parameters"][k]["value"] / v - 1) < 0.02, (k, rep["parameters"][k])
    assert isinstance(load_axis(tmp_path / "aps_two_mass_identified.toml").plant, sb.TwoMassPlant)


def test_identify_input_errors(tmp_path, capsys):
    assert run(capsys, "identify")[0] == 2
    code, _, err = run(capsys, "identify", AXES / "gt_rigid.toml", "--guess", "inertia=1e-4", "--out", tmp_path)
    assert code == 2 and "did you mean 'inertia_kgm2'?" in err
    code, _, err = run(capsys, "identify", AXES / "velocity_drive.json", "--out", tmp_path)
    assert code == 2 and "drive.mode: identification needs a torque-mode drive" in err
    log = tmp_path / "log.csv"
    log.write_text("time_s,torque_nm,position_pulse\n0,0,0\n0.0002,0.1,x\n")
    code, _, err = run(capsys, "identify", "--log", log, "--guess", "inertia_kgm2=1e-4", "--out", tmp_path)
    assert code == 2 and f"{log}: line 3, column position_pulse: 'x' is not a number" in err
    log.write_text("time_s,torque_nm,angle\n0,0,0\n")
    code, _, err = run(capsys, "identify", "--log", log, "--guess", "inertia_kgm2=1e-4", "--out", tmp_path)
    assert code == 2 and "no measured column" in err
    code, _, err = run(capsys, "identify", "--log", tmp_path / "none.csv", "--guess", "inertia_kgm2=1", "--out", tmp_path)
    assert code == 2 and "no such file" in err


def test_linearity_note_names_the_friction_that_the_analytic_loop_leaves_out():
    # A measured margin far from the analytic one is explained, not silently printed: on the two-mass example the
    # motor's Coulomb friction (0.03 N*m) raises the phase margin measured at 20 pulse from 60 to about 69 deg.
    axis = load_axis(AXES / "aps_two_mass.toml")
    note = cli._linearity_note(axis, {"phase_margin_deg": 69.0}, {"phase_margin_deg": 60.0}, 20.0)
    assert "+9.0 deg" in note and "motor_coulomb_nm 0.03 N*m" in note and "--amplitude-pulse" in note
    assert cli._linearity_note(axis, {"phase_margin_deg": 61.0}, {"phase_margin_deg": 60.0}, 20.0) == ""
    assert cli._linearity_note(axis, None, {"phase_margin_deg": 60.0}, 20.0) == ""
    linear = sb.Axis(plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4))
    assert "the plant is linear" in cli._linearity_note(linear, {"phase_margin_deg": 50.0},
                                                        {"phase_margin_deg": 60.0}, 20.0)
