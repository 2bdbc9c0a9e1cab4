"""Capture of the home switch, the index mark and the probe: the actual position latched at the edge,
interpolated inside the servo tick (GT seed 000 L2013-2150, L2958-3049, L3640-3674; gt.md §5; GE seed 001
L2332-2340, ge.md §5.1)."""

import numpy as np
import pytest

import servobench as sb
from test_homing import ORG, make_axis


def test_home_capture_is_exact_at_any_speed():
    # GT L2015-2017: the capture register records the actual position at the trigger edge, +-1 pulse,
    # independent of speed. At 200 pulse/tick a tick-sampled latch would be off by up to 200 pulses.
    for vel in (0.5, 7, 200):
        loop = sb.MotionLoop(make_axis(start_pulse=0.0))
        loop.capt_home()
        assert loop.capture_armed == "home"  # status bit 14 (L2017)
        loop.command(sb.GtTCurve(pos=40000, vel=vel, acc=0.05))
        run = loop.run_until_done(10**6)
        assert loop.captured and loop.capture_source == "home" and loop.capture_armed == "none"  # bit 3 set, 14 cleared
        assert abs(loop.capture_value - ORG[0]) <= 1
        k = int(np.argmax(run.captured))
        if vel >= 7:  # the tick samples straddle the edge by several pulses
            assert run.fb_pos[k] < ORG[0] < run.fb_pos[k] + vel + 1


def test_index_capture_and_rearm_rules():
    # GT L2017, L2962, L2988: each arm gives one capture; to capture again clear bit 3 (ClrSts) and re-arm.
    # Arming while armed or while bit 3 is set is refused (command status bits 7/8, L465-471; TV46
    # "CaptHome twice").
    loop = sb.MotionLoop(make_axis(start_pulse=0.0))
    loop.capt_index()
    with pytest.raises(sb.MotionCommandRefused, match="already armed"):
        loop.capt_home()
    loop.command(sb.GtJog(vel=25, acc=0.05))
    loop.run(1000)
    assert loop.captured and loop.capture_value == 2500  # the first index mark (2500 + k * 10000)
    with pytest.raises(sb.MotionCommandRefused, match="still set"):
        loop.capt_index()
    first = loop.capture_value
    loop.run(1000)
    assert loop.capture_value == first  # holds until the next capture (L3644)
    loop.clear_status()
    loop.capt_index()
    at_arm = loop.actual_pos
    loop.run(1000)
    assert loop.capture_value == 2500 + 10000 * np.ceil((at_arm - 2500) / 10000)  # the next mark after re-arming


def test_probe_capture_interpolates_between_ticks():
    # GT L3008-3049 (GT_CaptProb: the probe latches the actual position), GE L3828-3862 (in hardware,
    # independent of speed). At constant speed the probe half-way between two ticks captures the mid position.
    axis = make_axis(start_pulse=0.0)
    loop = sb.MotionLoop(axis)
    loop.command(sb.GtJog(vel=40, acc=0.5))
    loop.run(3000)
    ts = axis.servo_period_s
    t_probe = (axis.tick + 100.5) * ts
    loop.capt_probe(t_probe)
    run = loop.run(200)
    k = int(np.argmax(run.captured))
    assert run.time_s[k] == pytest.approx(t_probe - 0.5 * ts)  # captured during tick k
    # fb_pos[k] is the encoder at the tick's start, fb_pos[k + 1] at its end: the capture is half-way
    assert abs(loop.capture_value - 0.5 * (run.fb_pos[k] + run.fb_pos[k + 1])) <= 1
    assert run.fb_pos[k + 1] - run.fb_pos[k] == pytest.approx(40, abs=1)


def test_probe_time_must_be_valid():
    loop = sb.MotionLoop(make_axis())
    with pytest.raises(ValueError, match="at_s"):
        loop.capt_probe(-1.0)
