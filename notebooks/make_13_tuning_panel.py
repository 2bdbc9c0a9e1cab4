"""Writes notebooks/13_tuning_panel.ipynb (no outputs stored). Run: python notebooks/make_13_tuning_panel.py"""

import pathlib

import nbformat as nbf

md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell

cells = [
    md("# 13 The tuning panel\n\n"
       "`sb.widgets.tuner(axis)` is servobench's answer to MATLAB's PID Tuner: sliders on the servo law's gains, a\n"
       "notch and a low-pass biquad and the drive, and on every change the step response (simulated on the full\n"
       "nonlinear axis), the open-loop Bode plot and the margins with the stability verdict. Buttons run the\n"
       "model-based or the relay tuner, measure the loop with a stepped-sine sweep, apply the law to the axis or\n"
       "revert it, and export the tuned axis as an axis file that `servobench simulate/bode/tune` read.\n\n"
       "In a live notebook, move the sliders. Everything the panel does is also a method, so this notebook drives it\n"
       "from code, which is how the static page below was made (and how the tests check it)."),
    code("from IPython.display import Image\nimport servobench as sb\n\n"
         "axis = sb.examples.resonant_axis()     # ADLINK law, velocity drive, a 400 Hz two-mass resonance\n"
         "panel = sb.widgets.tuner(axis)\n"
         "panel                                  # the live panel (sliders, buttons, plots)"),
    md("## The untuned axis\n"
       "The law starts at the card's power-on zeros; the verdict and margins update with every slider."),
    code("print(panel.data['margins'])\nImage(panel.png())   # the panel's plots now"),
    md("## The model-based tuner\n"
       "The button `model tune` designs from the axis's analytic plant (60° phase margin, a notch at the resonance\n"
       "when it helps) and moves the sliders to the result."),
    code("panel.buttons['model_tune'].click()      # what a click does\n"
         "print(panel.status)\nprint(panel.law)\nprint(panel.data['margins'])\nImage(panel.png())   # the panel's plots now"),
    md("## By hand: a little less gain, the measured points\n"
       "`panel.set(...)` moves sliders by name; `measure Bode` runs the stepped-sine sweep on the simulated axis and\n"
       "draws its points over the model (hollow where a point failed its checks)."),
    code("panel.set(kp=int(panel.law.kp * 0.85))   # the ADLINK gains are 0..65535 counts\n"
         "panel.buttons['measure'].click()\n"
         "print(panel.status)\nprint(panel.data['margins'])\nImage(panel.png())   # the panel's plots now"),
    md("## Apply, export, revert\n"
       "`apply to axis` writes the law and the filters to the axis; `export file` writes the tuned axis file;\n"
       "`revert` restores the axis as it was when the panel opened."),
    code("panel.apply()\nprint('axis law now:', axis.law)\n"
         "path = panel.export('tuned_resonant_axis.toml')\n"
         "print(open(path).read()[:400])\n"
         "print(sb.load_axis(path).law == panel.law)\n"
         "df = panel.axis.run([0.0] * 10 + [100.0] * 990, signals=('time_s', 'cmd_pos', 'fb_pos')).to_dataframe()\n"
         "df.tail()"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                                 "language": "python"}})
out = pathlib.Path(__file__).with_name("13_tuning_panel.ipynb")
nbf.write(nb, out)
print("wrote", out)
