"""Writes notebooks/08_paths.ipynb (no outputs stored). Run: python notebooks/make_08_paths.py"""

import pathlib

import nbformat as nbf

cells = [
    nbf.v4.new_markdown_cell(
        "# 08 Coordinated paths: lines, arcs, buffers and look-ahead\n\n"
        "A coordinate system (here the GUC/iDEABOX kind: X, Y on profiles 1, 2), segments pushed into the FIFO,\n"
        "buffered IO and delays between them, and the look-ahead that lets a path of many small segments run at\n"
        "speed. Units: pulse, ms, pulse/ms, pulse/ms^2; one motion cycle = 1 ms. See docs/paths.md."),
    nbf.v4.new_code_cell(
        "import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n\n"
        "cs = sb.CoordSystem.crd_prm(dimension=2, profile=[1, 2], syn_vel_max=500, syn_acc_max=1,\n"
        "                            set_origin=True, origin_pos=[100, 100])   # GUC manual L747-765\n"
        "print(cs.axes, cs.to_axes([200000, 0]))"),
    nbf.v4.new_markdown_cell(
        "## The manual's hexagon with buffered IO and delays (GUC L802-843)\n"
        "Seven 3000 ms lines, outputs switched between segments, 400 ms and 100 ms dwells: it ends at 21500 ms."),
    nbf.v4.new_code_cell(
        "hexagon = [(200000, 0), (100000, 173205), (-100000, 173205), (-200000, 0), (-100000, -173205),\n"
        "           (100000, -173205), (200000, 0)]\n"
        "g = sb.PathGenerator(cs)\n"
        "for i, p in enumerate(hexagon, start=1):\n"
        "    g.line(p, vel=100, acc=0.1)\n"
        "    if i == 2: g.buf_io(0, 0xFFFF, 0x55)\n"
        "    if i == 3: g.buf_io(0, 0xFFFF, 0xAA)\n"
        "    if i == 4: g.buf_delay(400)\n"
        "    if i == 5: g.buf_io(0, 0xFFFF, 0x55); g.buf_delay(100)\n"
        "g.start()\nrun = sb.run_path(g)\nprint(run)\n"
        "fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))\n"
        "run.plot_xy(ax[0], title='hexagon, coloured by path speed')\n"
        "ax[1].plot(run.t_ms, run.speed, label='path speed [pulse/ms]')\n"
        "ax[1].step(run.t_ms, run.gpo / 2, label='GPO word / 2')\n"
        "ax[1].set_xlabel('t [ms]'); ax[1].legend(); plt.show()\n"
        "print('motor axes at the end:', run.axis_pos[-1], '(origin 100, 100)')"),
    nbf.v4.new_markdown_cell(
        "## A curve made of small segments, with and without look-ahead\n"
        "A rose curve as 1500 short lines at feed 50 pulse/ms, acceleration 0.5. Without look-ahead every segment\n"
        "starts and ends at rest (velEnd 0); with look-ahead (T = 5 ms, accMax = 0.5, n = 200) the path slows only\n"
        "where the curvature asks for it."),
    nbf.v4.new_code_cell(
        "th = np.linspace(0, 2 * np.pi, 1501)\n"
        "pts = np.column_stack([20000 * np.cos(3 * th) * np.cos(th), 20000 * np.cos(3 * th) * np.sin(th)])\n"
        "pts = np.round(pts)\n\n"
        "def rose(lookahead):\n"
        "    g = sb.PathGenerator(sb.CoordSystem.identity(2), start=list(pts[0]))\n"
        "    if lookahead:\n"
        "        g.init_lookahead(sb.LookAheadParams(t_ms=5, acc_max=0.5, n=200))\n"
        "    for p in pts[1:]:\n"
        "        if np.any(p != g.tail):\n"
        "            g.line(list(p), vel=50, acc=0.5)\n"
        "    g.flush(); g.start()\n"
        "    return sb.run_path(g)\n\n"
        "off, on = rose(False), rose(True)\n"
        "print('without look-ahead:', off)\nprint('with look-ahead:   ', on)\n"
        "fig, ax = plt.subplots(1, 2, figsize=(12, 5))\n"
        "off.plot_xy(ax[0], title=f'without look-ahead: {off.t_ms[-1] / 1000:.1f} s', vmax=50)\n"
        "on.plot_xy(ax[1], title=f'with look-ahead: {on.t_ms[-1] / 1000:.1f} s', vmax=50)\nplt.show()"),
    nbf.v4.new_code_cell(
        "plt.figure(figsize=(10, 3.5))\n"
        "plt.plot(on.t_ms, on.speed, label='with look-ahead')\n"
        "plt.plot(off.t_ms[:len(on.t_ms)], off.speed[:len(on.t_ms)], alpha=0.6, label='without (same time span)')\n"
        "plt.xlabel('t [ms]'); plt.ylabel('path speed [pulse/ms]'); plt.legend(); plt.show()\n"
        "print('largest |dv/dt| with look-ahead:', np.max(np.abs(np.diff(on.speed))), 'pulse/ms^2 (accMax 0.5)')"),
    nbf.v4.new_markdown_cell(
        "## Corner time T: faster corners, larger corner error\n"
        "Two lines meeting at 90 degrees. The corner speed is accMax T / |u_in - u_out| (our rule, decision C11);\n"
        "a machine that smooths its command over 8 ms cuts the corner the more, the faster it is taken."),
    nbf.v4.new_code_cell(
        "for t_ms in (1, 2, 5, 10):\n"
        "    g = sb.PathGenerator(sb.CoordSystem.identity(2))\n"
        "    g.init_lookahead(sb.LookAheadParams(t_ms=t_ms, acc_max=1, n=200))\n"
        "    g.line([20000, 0], vel=100, acc=1); g.line([20000, 20000], vel=100, acc=1); g.flush(); g.start()\n"
        "    r = sb.run_path(g)\n"
        "    k = np.argmax(r.segments == 1)\n"
        "    w = np.ones(8) / 8\n"
        "    fx, fy = np.convolve(r.pos[:, 0], w, 'valid'), np.convolve(r.pos[:, 1], w, 'valid')\n"
        "    err = np.min(np.hypot(fx - 20000, fy))\n"
        "    print(f'T = {t_ms:2d} ms: corner speed {r.speed[k]:6.2f} pulse/ms, corner error {err:7.2f} pulse, '\n"
        "          f'{r.t_ms[-1]:.0f} ms')\n"
        "    plt.plot(fx, fy, label=f'T = {t_ms} ms')\n"
        "plt.xlim(19000, 20300); plt.ylim(-300, 1000); plt.gca().set_aspect('equal'); plt.legend()\n"
        "plt.title('smoothed path near the corner'); plt.show()"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                               "language": "python"}})
path = pathlib.Path(__file__).with_name("08_paths.ipynb")
nbf.write(nb, path)
print("wrote", path)
