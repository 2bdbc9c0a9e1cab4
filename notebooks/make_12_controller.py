"""Writes notebooks/12_controller.ipynb (no outputs stored). Run: python notebooks/make_12_controller.py"""

import pathlib

import nbformat as nbf

md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell

cells = [
    md("# 12 A controller of your own in the loop\n\n"
       "The card's servo law is one choice; a research controller, a learned policy or a co-simulated program is\n"
       "another. servobench puts a user-written controller where the law sits -- after the encoder read, before the\n"
       "DAC, its output reaching the drive one tick later like the card's -- in three ways:\n\n"
       "1. **the step API**: `axis.step(cmd, volts=u)` once per tick from Python (about a microsecond per call);\n"
       "2. **a Python callable** for a whole run: `axis.run(cmd, controller=f)`, `f(tick, cmd_pulse, fb_pulse) -> V`;\n"
       "3. **a compiled function** (a `numba.cfunc`) that runs inside the C++ loop at full speed.\n\n"
       "The three give the same ticks, number for number; we compare them with the card's own GT law on a step."),
    code("import time\nimport numpy as np\nimport matplotlib.pyplot as plt\nimport numba\nimport servobench as sb\n\n"
         "step = np.concatenate([np.zeros(20), np.full(980, 1000.0)])   # 1000 pulse, 200 us ticks\n"
         "card = sb.demo_axis().run(step)                               # the GT law, tuned\n"
         "print(sb.move_metrics(card))"),
    md("## A PD law with a velocity-error filter, written in Python\n"
       "Gains in volts: `kp` V/pulse, `kd` V per pulse/tick; the derivative goes through a first-order low-pass\n"
       "(`alpha` per tick) as a real controller would filter it."),
    code("KP, KD, ALPHA = 0.012, 0.35, 0.5\n\n"
         "def make_pd():\n"
         "    mem = {'e': 0.0, 'd': 0.0}\n"
         "    def pd(tick, cmd, fb):\n"
         "        e = cmd - fb\n"
         "        mem['d'] += ALPHA * ((e - mem['e']) - mem['d'])\n"
         "        mem['e'] = e\n"
         "        return KP * e + KD * mem['d']\n"
         "    return pd\n\n"
         "t0 = time.perf_counter()\n"
         "py_run = sb.demo_axis().run(step, controller=make_pd())\n"
         "t_py = time.perf_counter() - t0\n"
         "print(sb.move_metrics(py_run))"),
    md("## The same law through the step API\n"
       "Read the encoder, compute, step: the program owns the loop."),
    code("ax = sb.demo_axis()\npd = make_pd()\nfb = []\nt0 = time.perf_counter()\n"
         "for k, c in enumerate(step):\n"
         "    fb.append(ax.step(c, volts=pd(k, c, ax.feedback_pulse)))\n"
         "t_step = time.perf_counter() - t0\n"
         "assert np.array_equal(fb, py_run.fb_pos)      # the same ticks\n"
         "print(f'step API: {t_step / len(step) * 1e6:.2f} us per tick from Python')"),
    md("## Compiled with numba: inside the C++ loop\n"
       "The signature is `sb.controller_signature()`; the gains and memories live in a float64 state array that\n"
       "the run reads and updates in place."),
    code("print(sb.controller_signature())\n\n"
         "@numba.cfunc('float64(int64, float64, float64, CPointer(float64))')\n"
         "def pd_c(tick, cmd, fb, s):\n"
         "    e = cmd - fb\n"
         "    s[4] += s[2] * ((e - s[3]) - s[4])\n"
         "    s[3] = e\n"
         "    return s[0] * e + s[1] * s[4]\n\n"
         "state = np.array([KP, KD, ALPHA, 0.0, 0.0])        # kp, kd, alpha, previous error, filtered derivative\n"
         "t0 = time.perf_counter()\n"
         "c_run = sb.demo_axis().run(step, controller=pd_c, controller_state=state)\n"
         "t_c = time.perf_counter() - t0\n"
         "assert np.array_equal(c_run.fb_pos, py_run.fb_pos)\n"
         "print(f'Python callable {t_py / len(step) * 1e6:.2f} us/tick, compiled {t_c / len(step) * 1e6:.3f} us/tick')"),
    md("## The three against the card's law"),
    code("fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))\n"
         "t_ms = card.time_s * 1e3\n"
         "ax1.plot(t_ms, card.cmd_pos, 'k:', label='command')\n"
         "ax1.plot(t_ms, card.fb_pos, label='GT law (tuned)')\n"
         "ax1.plot(t_ms, c_run.fb_pos, '--', label='your PD (numba, = Python, = step API)')\n"
         "ax1.set_ylabel('position [pulse]'); ax1.legend()\n"
         "ax2.plot(t_ms, card.volts, label='GT law')\n"
         "ax2.plot(t_ms, c_run.volts, '--', label='your PD')\n"
         "ax2.set_xlabel('time [ms]'); ax2.set_ylabel('DAC output [V]'); ax2.legend()\n"
         "ax1.set_xlim(0, 60)\nplt.tight_layout()\n"
         "print('GT law:', sb.move_metrics(card))\nprint('your PD:', sb.move_metrics(c_run))"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                                 "language": "python"}})
out = pathlib.Path(__file__).with_name("12_controller.ipynb")
nbf.write(nb, out)
print("wrote", out)
