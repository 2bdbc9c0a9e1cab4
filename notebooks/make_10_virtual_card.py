"""Writes notebooks/10_virtual_card.ipynb (no outputs stored). Run: python notebooks/make_10_virtual_card.py"""

import pathlib

import nbformat as nbf

md, code = nbf.v4.new_markdown_cell, nbf.v4.new_code_cell

cells = [
    md("# 10 The virtual card: a GT program on four axes, an APS tuning session\n\n"
       "A `servobench.Card` is a motion-control card in simulation: 4 or 8 axes on one servo clock, each a profile\n"
       "generator, the servo law, the DAC, a drive and a mechanism, with the card's double-buffered registers,\n"
       "status words and safety. The vendor *dialects* let a program written for a real card run on it with the\n"
       "manual's own function names, argument order, units and return codes.\n\n"
       "1. A **GT-series program** (Googol GT, current-axis style, units per servo tick) sets up four axes, starts\n"
       "   four different motions with one `GT_MltiUpdt`, and we plot what the card recorded.\n"
       "2. **Safety**: a following-error auto-stop and what the status words say about it.\n"
       "3. An **ADLINK APS tuning session**: a timid hand tuning on a PCI-8254, relay auto-tuning on the axis's\n"
       "   model twin, the gains written back with `APS_set_axis_param` and checked with a move on the card."),
    code("import numpy as np\nimport matplotlib.pyplot as plt\nimport servobench as sb\n"
         "from servobench.dialects import gt, aps\n"
         "from servobench.dialects.gt import GtController\nfrom servobench.dialects.aps import ApsController\n\n"
         "def bits(word, names):\n"
         "    return [n for k, n in names.items() if word >> k & 1]\n\n"
         "GT_STATUS = {0: 'motion complete', 1: 'drive alarm', 2: 'breakpoint', 3: 'captured', 4: 'following error',\n"
         "             5: '+limit', 6: '-limit', 7: 'command error', 9: 'servo on', 10: 'moving'}"),
    md("## 1. A GT program on four axes\n"
       "Four copies of the demo axis (a 400 W servo motor in torque mode, 10000 counts/rev, 200 us servo period).\n"
       "The program is written as it would be in C for the card: `GT_Axis(n)` selects the axis the next commands\n"
       "act on; `GT_SetKp`... and `GT_SetPos/Vel/Acc` are *staged* and take effect together at the next servo tick\n"
       "after `GT_Update` (one axis) or `GT_MltiUpdt(mask)` (several). Each call returns the manual's code:\n"
       "0 done, 1 command error (the reason is in `GT_GetCmdSts`), 7 parameter out of range."),
    code("base = sb.demo_axis()\n"
         "card = sb.Card(4, law=sb.GtServoLaw(), drive=base.drive, plant=base.plant, encoder=base.encoder,\n"
         "               servo_period_s=200e-6)\n"
         "g = GtController()\nassert g.GT_Open(card) == 0\n\n"
         "for axis in (1, 2, 3, 4):                      # the manual's PID set-up (Example 3-6), tuned gains\n"
         "    g.GT_Axis(axis)\n"
         "    for rtn in (g.GT_ClrSts(), g.GT_CtrlMode(0), g.GT_CloseLp(), g.GT_SetKp(38), g.GT_SetKi(60),\n"
         "                g.GT_SetKd(830), g.GT_SetKaff(12870), g.GT_SetPosErr(2000), g.GT_Update(), g.GT_AxisOn()):\n"
         "        assert rtn == 0\n\n"
         "g.GT_Axis(1); g.GT_PrflT(); g.GT_SetAcc(0.05); g.GT_SetVel(8); g.GT_SetPos(40000)      # trapezoid\n"
         "g.GT_Axis(2); g.GT_PrflS(); g.GT_SetMAcc(0.02); g.GT_SetJerk(0.0002); g.GT_SetVel(8); g.GT_SetPos(40000)\n"
         "g.GT_Axis(3); g.GT_PrflV(); g.GT_SetAcc(0.02); g.GT_SetVel(-5)                         # jog\n"
         "g.GT_Axis(4); g.GT_PrflT(); g.GT_SetAcc(0.05); g.GT_SetVel(4); g.GT_SetPos(30000)\n"
         "g.GT_SetBrkCn(10000); g.GT_PosBrk(); g.GT_AuUpdtOn()    # at 10000 pulse the breakpoint commits...\n"
         "print('MltiUpdt:', g.GT_MltiUpdt(0b1111))           # ...all four start in the same tick\n"
         "g.GT_SetVel(12)                                        # staged now, committed by the breakpoint\n"
         "rec = card.run(7500, signals=['time_s', 'pos', 'prf_vel', 'error', 'volts', 'events'])\n"
         "g.GT_Axis(3); g.GT_SmthStp(); g.GT_Update()             # stop the jog smoothly\n"
         "tail = card.run(1500, signals=['time_s', 'pos', 'prf_vel', 'error', 'volts', 'events'])\n"
         "print(rec)"),
    code("names = ['1: trapezoid', '2: S-curve', '3: jog + SmthStp', '4: breakpoint auto-update']\n"
         "fig, ax = plt.subplots(3, 1, sharex=True, figsize=(9, 7))\n"
         "for i in range(4):\n"
         "    t = np.concatenate([rec[i].time_s, tail[i].time_s])\n"
         "    v = np.concatenate([rec[i].prf_vel, tail[i].prf_vel])\n"
         "    e = np.concatenate([rec[i].error, tail[i].error])\n"
         "    u = np.concatenate([rec[i].volts, tail[i].volts])\n"
         "    ax[0].plot(t, v, label=names[i]); ax[1].plot(t, e, lw=0.7); ax[2].plot(t, u, lw=0.7)\n"
         "ax[0].set_ylabel('profile velocity\\n[pulse/tick]'); ax[0].legend(fontsize=8)\n"
         "ax[1].set_ylabel('following error\\n[pulse]'); ax[2].set_ylabel('DAC output [V]'); ax[2].set_xlabel('s')\n"
         "plt.show()\n"
         "for axis in (1, 2, 3, 4):\n"
         "    g.GT_Axis(axis); rtn, s = g.GT_GetSts(); rtn, p = g.GT_GetAtlPos()\n"
         "    print(f'axis {axis}: actual {p:7d} pulse, status 0x{s:04x}', bits(s, GT_STATUS))"),
    md("The trapezoid and the S-curve end at 40000 pulse; the S-curve's jerk-limited ramps take longer. Axis 4\n"
       "crossed its breakpoint at 10000 pulse and the auto-update committed the velocity staged after the start\n"
       "(4 -> 12 pulse/tick) without any host command: the double buffer at work. The jog ran at -5 pulse/tick\n"
       "until `GT_SmthStp` + `GT_Update`. The status words say *motion complete* and *breakpoint* (sticky event\n"
       "bits 0-7, cleared with `GT_ClrSts`) and *servo on*."),
    md("## 2. Safety: following error with auto-stop\n"
       "`GT_SetPosErr` sets the following-error limit (pulse) checked every servo tick; with `GT_AuStpOn` the card\n"
       "stops the profile and disables the drive when it is exceeded. Here we ask axis 1 for an acceleration its\n"
       "motor cannot give (20 pulse/tick^2 needs about 8 times the drive's 8 A current limit) with a limit of\n"
       "200 pulse. The event stays latched in status bit 4 until `GT_ClrSts`; the drive comes back with `GT_AxisOn`."),
    code("g.GT_Axis(1); g.GT_ClrSts(); g.GT_SetPosErr(200); g.GT_AuStpOn()\n"
         "g.GT_SetAcc(20.0); g.GT_SetVel(60); g.GT_SetPos(0); print('Update:', g.GT_Update())\n"
         "fe = card.run(1500, signals=['time_s', 'pos', 'actual_pos', 'error', 'servo_on'])\n"
         "rtn, s = g.GT_GetSts()\nprint(f'status 0x{s:04x}', bits(s, GT_STATUS))\n"
         "trip = int(np.argmax(fe[0].servo_on == 0))\n"
         "print(f'tripped {(fe[0].time_s[trip] - fe[0].time_s[0]) * 1e3:.1f} ms after the start at |E| = '\n"
         "      f'{abs(fe[0].error[trip]):.0f} pulse')\n"
         "fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 4))\n"
         "ax[0].plot(fe[0].time_s, fe[0].pos, label='command'); ax[0].plot(fe[0].time_s, fe[0].actual_pos, label='actual')\n"
         "ax[0].legend(); ax[0].set_ylabel('pulse')\n"
         "ax[1].plot(fe[0].time_s, fe[0].error); ax[1].axhline(-200, color='r', lw=0.5); ax[1].axhline(200, color='r', lw=0.5)\n"
         "ax[1].set_ylabel('error [pulse]'); ax[1].set_xlabel('s'); plt.show()\n"
         "g.GT_AuStpOff(); g.GT_SetPosErr(2000); g.GT_Update(); g.GT_ClrSts()\n"
         "print('GT_AxisOn:', g.GT_AxisOn(), '- status', bits(g.GT_GetSts()[1], GT_STATUS))"),
    md("## 3. An APS tuning session (ADLINK PCI-8254)\n"
       "A typical ADLINK installation: the card sends an analog *velocity* command to a drive in speed mode\n"
       "(31.4 rad/s per volt), 250 us servo period, the ADLINK law with its gain shifts (effective KP =\n"
       "PRA_KP_GAIN x 2^(KP_SHIFT + PID_SHIFT)). Parameters are written by their PRA numbers, speeds are in pulse/s,\n"
       "and every call returns an APS error code (0 = ERR_NoError). We start from a timid hand tuning and look at a\n"
       "10000-pulse move."),
    code("TS = 250e-6\n"
         "parts = dict(plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4, coulomb_nm=0.005),\n"
         "             drive=sb.VelocityDrive(speed_per_volt_rad_s=31.4), encoder=sb.Encoder(counts_per_rev=10000),\n"
         "             servo_period_s=TS)\n"
         "a = ApsController()\n"
         "rtn, board = a.APS_initial(0, sb.Card(4, law=sb.ApsServoLaw(), **parts))\n"
         "for para, value in ((aps.PRA_KP_GAIN, 8000), (aps.PRA_KD_GAIN, 2000), (aps.PRA_ACC, 2e6), (aps.PRA_DEC, 2e6)):\n"
         "    assert a.APS_set_axis_param(0, para, value) == aps.ERR_NoError\n"
         "assert a.APS_set_servo_on(0, 1) == 0\n\n"
         "def move_test(a, distance=10000, speed=200000):\n"
         "    assert a.APS_relative_move(0, distance, speed) == 0\n"
         "    r = a.card.run(2400, signals=['time_s', 'cmd_pos', 'fb_pos', 'error', 'volts'])[0]\n"
         "    return r, sb.move_metrics(r, settle_band_pulse=5)\n\n"
         "hand, m_hand = move_test(a)\nprint('hand tuning:', m_hand)"),
    md("Relay auto-tuning (the ADLINK tool's experiment, manual defaults with the hysteresis raised to 150 pulse:\n"
       "a relay on the position error makes the loop oscillate at its ultimate frequency; the gains follow for a\n"
       "60 deg phase margin) runs offline on the axis's model twin. The result comes back as ADLINK integers with\n"
       "shifts; we write them with `APS_set_axis_param` (staged, active from the next servo tick) and repeat the\n"
       "move in the other direction."),
    code("twin = sb.Axis(law=sb.ApsServoLaw(kp=8000, kd=2000), **parts)\n"
         "res = sb.relay_autotune(twin, hysteresis_pulse=150, sampling_time_s=TS, data_length=40)\n"
         "print(res.status, f'- ultimate point {res.ultimate_freq_hz:.1f} Hz, {res.ultimate_gain_v_per_pulse * 1e3:.3f} mV/pulse')\n"
         "law = res.aps_law()\nprint(law)\n"
         "for para, field in ((aps.PRA_KP_GAIN, 'kp'), (aps.PRA_KI_GAIN, 'ki'), (aps.PRA_KD_GAIN, 'kd'),\n"
         "                    (aps.PRA_KP_SHIFT, 'kp_shift'), (aps.PRA_KI_SHIFT, 'ki_shift'), (aps.PRA_KD_SHIFT, 'kd_shift'),\n"
         "                    (aps.PRA_PID_SHIFT, 'pid_shift')):\n"
         "    assert a.APS_set_axis_param(0, para, int(getattr(law, field))) == 0, para\n"
         "tuned, m_tuned = move_test(a, distance=-10000)\nprint('relay tuning:', m_tuned)"),
    md("The relay tuning is stiffer (it rejects load disturbances better) but a PID on the position error alone\n"
       "must *lag* to command speed through a velocity drive. Velocity feed-forward removes that lag: KVFF times\n"
       "the command velocity (pulse/tick) should give the volts the drive needs for that speed,\n"
       "2 pi/10000 rad/pulse / 250 us / 31.4 rad/s/V x 3276.7 counts/V = 262 counts per pulse/tick, i.e. KVFF = 262 x 2^5\n"
       "with KVFF_SHIFT 0 and PID_SHIFT -5."),
    code("kvff = round(2 * np.pi / 10000 / TS / 31.4 * 32767 / 10 * 2 ** 5)\n"
         "assert a.APS_set_axis_param(0, aps.PRA_KVFF_GAIN, kvff) == 0\n"
         "ff, m_ff = move_test(a)\nprint(f'relay tuning + KVFF {kvff}:', m_ff)"),
    code("fig, ax = plt.subplots(2, 1, sharex=True, figsize=(9, 5))\n"
         "for r, label in ((hand, 'hand tuning'), (tuned, 'relay tuning'), (ff, 'relay tuning + KVFF')):\n"
         "    t = r.time_s - r.time_s[0]\n"
         "    ax[0].plot(t, np.abs(r.error), label=label); ax[1].plot(t, r.volts, lw=0.7)\n"
         "ax[0].set_yscale('symlog', linthresh=1); ax[0].set_ylabel('|following error| [pulse]'); ax[0].legend()\n"
         "ax[1].set_ylabel('DAC output [V]'); ax[1].set_xlabel('s after the move command'); plt.show()\n"
         "for code in (aps.PRA_KP_GAIN, aps.PRA_KI_GAIN, aps.PRA_KD_GAIN, aps.PRA_KVFF_GAIN):\n"
         "    print(hex(code), a.APS_get_axis_param(0, code))\n"
         "print('MSTS', bits(a.APS_motion_status(0), {5: 'MDN', 16: 'ASTP'}),\n"
         "      'MIO', bits(a.APS_motion_io_status(0), {6: 'INP', 7: 'SVON'}))"),
]

nb = nbf.v4.new_notebook(cells=cells, metadata={"kernelspec": {"name": "python3", "display_name": "Python 3"}})
out = pathlib.Path(__file__).with_name("10_virtual_card.ipynb")
nbf.write(nb, out)
print("wrote", out)
