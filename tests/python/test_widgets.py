"""The tuning panel (issue 23.2) driven headless: setting slider values and clicking the buttons programmatically
changes what is plotted, the tuners move the sliders, apply/revert write the axis and back, export writes an axis
file the command line reads."""

from __future__ import annotations

import numpy as np
import pytest

import servobench as sb
from servobench import examples, widgets

pytest.importorskip("ipywidgets")


def _plotted(t):
    return {k: (np.array(line.get_xdata(), dtype=float), np.array(line.get_ydata(), dtype=float))
            for k, line in t.lines.items()}


def test_sliders_change_the_plotted_data():
    axis = sb.demo_axis()
    t = widgets.tuner(axis)
    before = _plotted(t)
    pm0 = t.data["margins"].phase_margin_deg
    assert t.data["margins"].verdict == "stable"
    assert before["fb"][1].size == round(0.1 / axis.servo_period_s)
    t.controls["kp"].value = 80  # what dragging the slider does
    after = _plotted(t)
    assert t.law.kp == 80 and axis.law.kp == 38, "the slider edits the candidate, not the axis"
    assert np.max(np.abs(after["fb"][1] - before["fb"][1])) > 1.0  # pulse
    assert np.max(np.abs(after["ol_db"][1] - before["ol_db"][1])) > 3.0  # dB: kp 38 -> 80 lifts the low band
    assert t.data["margins"].phase_margin_deg != pm0
    np.testing.assert_array_equal(after["ol_db"][1], t.data["bode"]["open_loop_db"])  # plotted = data
    # the notch slot: on, then moved
    t.set(notch=True, notch_hz=300.0, notch_q=2.0)
    assert t.filters[0] is not None and t._specs[0] == {"type": "notch", "center_hz": 300.0, "q": 2.0, "prewarp": True}
    g = t.data["bode"]
    i = np.argmin(np.abs(g["freq_hz"] - 300.0))
    assert g["open_loop_db"][i] < after["ol_db"][1][i] - 10.0, "the notch cuts the loop gain at its centre"
    t.controls["notch"].value = False
    assert t.filters[0] is None or t.filters[0] == axis.filters[0]
    # the drive's current loop
    t.set(current_bw_hz=100.0)
    assert t.drive.current_bw_hz == 100.0 and axis.drive.current_bw_hz == 1500.0


def test_verdict_follows_the_gain():
    t = widgets.tuner(sb.demo_axis())
    t.set(kp=32767, kd=0)  # far past the stability limit
    assert t.data["margins"].verdict == "UNSTABLE"
    assert "UNSTABLE" in t.verdict.value and "UNSTABLE" in t.axes["step"].get_title()


def test_buttons_model_tune_apply_revert_export(tmp_path):
    axis = sb.demo_axis()
    law0 = axis.law
    t = widgets.tuner(axis)
    ol0 = _plotted(t)["ol_db"][1]
    t.buttons["model_tune"].click()
    assert "model-based tune" in t.status, t.status
    assert t.law != law0 and t.controls["kp"].value == t.law.kp
    assert abs(t.data["margins"].phase_margin_deg - 60.0) < 5.0
    assert np.max(np.abs(_plotted(t)["ol_db"][1] - ol0)) > 0.5
    t.buttons["apply"].click()
    assert axis.law == t.law
    t.export_path.value = str(tmp_path / "tuned.toml")
    t.buttons["export"].click()
    back = sb.load_axis(tmp_path / "tuned.toml")
    assert back.law == t.law and back.plant == axis.plant and back.drive == axis.drive
    assert sb.frequency.analytic_margins(back).phase_margin_deg == pytest.approx(
        t.data["margins"].phase_margin_deg, abs=0.5)
    t.buttons["revert"].click()
    assert axis.law == law0 and t.law == law0 and t.controls["kp"].value == law0.kp
    np.testing.assert_allclose(_plotted(t)["ol_db"][1], ol0)


def test_measured_points_on_request_and_cleared_by_a_change():
    t = widgets.tuner(sb.demo_axis(), sweep_points=8)
    assert t.data["measured"] is None and len(t.lines["meas_db"].get_xdata()) == 0
    t.buttons["measure"].click()
    me = t.data["measured"]
    assert me is not None and me["freq_hz"].size == 8, t.status
    shown = len(t.lines["meas_db"].get_xdata()) + len(t.lines["meas_bad_db"].get_xdata())
    assert shown == 8
    ok = me["usable"]
    assert ok.sum() >= 4
    model = np.interp(np.log(me["freq_hz"][ok]), np.log(t.data["bode"]["freq_hz"]), t.data["bode"]["open_loop_db"])
    assert np.max(np.abs(me["open_loop_db"][ok] - model)) < 3.0  # dB: the measurement sees the modelled loop
    t.set(kd=900)
    assert t.data["measured"] is None and len(t.lines["meas_db"].get_xdata()) == 0


def test_relay_button_on_a_velocity_axis_and_refusal_on_torque():
    tv = widgets.tuner(examples.velocity_axis())
    tv.buttons["relay_tune"].click()
    assert tv.status.startswith("relay tune"), tv.status
    assert tv.law.kp > 0 and tv.data["margins"].verdict == "stable"
    tt = widgets.tuner(sb.demo_axis())
    law = tt.law
    tt.buttons["relay_tune"].click()
    assert "velocity-mode drive" in tt.status and tt.law == law


def test_model_tune_keeps_its_notch_and_exports_it_in_design_form(tmp_path):
    t = widgets.tuner(examples.resonant_axis())
    t.model_tune()
    assert t.controls["notch"].value and t._specs[0]["type"] == "notch"
    kept = t.filters[0]
    t.set(kp=int(t.law.kp * 0.9))
    assert t.filters[0] == kept, "a gain change keeps the tuner's notch"
    p = t.export(tmp_path / "tuned.json")
    back = sb.load_axis(p)
    assert back.filters[0] == kept and back.law == t.law
    assert '"notch"' in open(p).read()


def test_bad_input_names_the_parameter():
    t = widgets.tuner(sb.demo_axis())
    with pytest.raises(ValueError, match="kp"):
        t.set(kp=-1)
    with pytest.raises(ValueError, match="kp"):
        t.set(kp=40000)
    with pytest.raises(ValueError, match="unknown"):
        t.set(gain=3)
    with pytest.raises(ValueError, match="notch_hz"):
        t.set(notch_hz=float("nan"))
    with pytest.raises(TypeError, match="axis"):
        widgets.tuner("axis")
    with pytest.raises(ValueError, match="step_pulse"):
        widgets.tuner(sb.demo_axis(), step_pulse=0)
    stepper = sb.Axis(drive=sb.StepperDrive())
    with pytest.raises(ValueError, match="voltage-output"):
        widgets.tuner(stepper)


#: SHA-256 of the earlier docs picture, taken while the slider column collapsed to 1 px (it showed no sliders).
_OLD_SCREENSHOT_SHA256 = "648a95e2deded9a0c9ae55b5853f4dea2e4fd05f47e1a19ac96c3fe2fca57d8a"


def test_slider_column_cannot_collapse():
    """In a flex row a widget box may shrink to nothing (its overflow is auto): the slider column keeps its width,
    the plots take the rest (decision W20)."""
    panel = widgets.tuner(examples.resonant_axis())
    left, right = panel.widget.children[1].children
    assert left.layout.flex == "0 0 auto" and int(left.layout.min_width.rstrip("px")) >= 400
    assert right.layout.flex == "1 1 auto"
    sliders = [c for c in panel.controls.values() if "Slider" in type(c).__name__]
    assert all(int(s.layout.width.rstrip("px")) <= int(left.layout.min_width.rstrip("px")) for s in sliders)


def test_docs_screenshot_is_the_real_panel():
    """docs/img/widgets_tuner.png is made by docs/make_widgets_screenshot.py (Voila + headless Chromium); its record
    says every slider was visible on the page, and the picture shows the slider tracks in the left column."""
    import hashlib
    import json
    from pathlib import Path

    import matplotlib.image as mpimg

    img_dir = Path(__file__).resolve().parents[2] / "docs" / "img"
    png = (img_dir / "widgets_tuner.png").read_bytes()
    record = json.loads((img_dir / "widgets_tuner.json").read_text())
    digest = hashlib.sha256(png).hexdigest()
    assert digest != _OLD_SCREENSHOT_SHA256, "the old picture without sliders"
    assert digest == record["png_sha256"], "the picture is the one the script measured"
    panel = widgets.tuner(examples.resonant_axis())  # the notebook's axis
    n_sliders = sum("Slider" in type(c).__name__ for c in panel.controls.values())
    assert record["sliders"] == record["visible_sliders"] == n_sliders == 12
    assert all(w >= 300 and h >= 20 for w, h in record["slider_px"])
    rgb = (mpimg.imread(img_dir / "widgets_tuner.png")[..., :3] * 255).round()
    height, width = rgb.shape[:2]
    assert width >= 1100 and height >= 600
    # a slider track: a row where most of the column x = 170..320 px is the track's grey (189, 189, 189)
    track = (np.abs(rgb[:, 170:320] - 189.0) <= 4).all(axis=2).mean(axis=1) >= 0.6
    runs = np.count_nonzero(np.diff(track.astype(int)) == 1)
    assert runs >= n_sliders - 2, f"{runs} slider tracks seen in the picture's left column"
