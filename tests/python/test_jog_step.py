"""ADLINK jog (continuous and step mode) and on-the-fly PTP changes (ADLINK seed 004 L2639-2710,
L2757-2767; adlink.md §6.5, §6.6, §10 T36)."""

import numpy as np
import pytest

import servobench as sb
from servobench.homing import JOG_PHASES
from test_homing import make_axis


def _jog(params, on_ticks, start=0.0):
    axis = make_axis(start_pulse=start)
    loop = sb.MotionLoop(axis)
    loop.jog(params)
    loop.jog_on = True
    first = loop.run(on_ticks)
    loop.jog_on = False
    rest = loop.run_until_done(10**6)
    return loop, first, rest


@pytest.mark.parametrize("on_ticks", [1, 300, 2000, 3333])
@pytest.mark.parametrize("sf", [0.0, 0.6])
def test_t36_jog_step_total_is_a_whole_multiple_of_the_offset(on_ticks, sf):
    # adlink.md §10 T36, seed L2657: a rising edge moves JG_OFFSET and stops; after JG_DELAY, if JOG-ON is still
    # on, the axis moves on until it goes off; the total displacement is increased to an integer multiple of the
    # offset (final displacement = ceil(n) * offset).
    p = sb.AdlinkJog(mode=1, dir=1, offset=1000, delay_us=20000, vm=1e5, acc=1e6, dec=1e6, sf=sf)
    loop, first, rest = _jog(p, on_ticks)
    total = loop.pos - loop.jog_origin
    assert total % 1000 == 0 and total >= 1000
    if first.phase[-1] != JOG_PHASES.index("continuous"):  # released during the step or the delay: one offset
        assert total == 1000
    else:
        # the plain deceleration from the release speed would stop short of it by less than one offset
        v_tick = 1e5 * 200e-6
        dec_tick = 1e6 * (200e-6) ** 2
        released_at = first.pos[-1] - loop.jog_origin
        natural = released_at + (1 + sf) * v_tick ** 2 / (2 * dec_tick)
        assert natural - 25 <= total < natural + 1000 + 25
    assert loop.jog_phase == "idle" and not loop.moving


def test_jog_step_negative_direction_and_continuous_mode():
    # ADLINK L2678 (JG_DIR 0 = negative), L2645 (continuous: rising edge -> velocity move, falling edge ->
    # decelerating stop).
    loop, _first, _rest = _jog(sb.AdlinkJog(mode=1, dir=0, offset=700, delay_us=0), 1500)
    total = loop.pos - loop.jog_origin
    assert total < 0 and total % 700 == 0
    loop, first, rest = _jog(sb.AdlinkJog(mode=0, dir=1, vm=5e4, acc=5e5, dec=2.5e5), 1000)
    v = np.diff(np.concatenate([first.pos, rest.pos]))
    assert v.max() == pytest.approx(10, abs=1)  # 5e4 pulse/s = 10 pulse/tick
    decel = rest.pos[-1] - first.pos[-1]
    assert decel == pytest.approx(10 ** 2 / (2 * 2.5e5 * 4e-8), rel=0.05)  # v^2 / (2 DEC)


def test_adlink_on_the_fly_ptp_changes():
    # ADLINK L2757-2767: during a PTP move, (1) a new target with the same speeds, (2) a new maximum speed with the
    # same target, (3) a whole new PTP command -- including a target behind the axis (stop, then move back).
    base = dict(vm=1e5, acc=1e6, dec=1e6)
    gen = sb.ProfileGenerator(period_s=200e-6)
    gen.command(sb.AdlinkPtp(pos=100000, **base))
    gen.run(1000)
    gen.command(sb.AdlinkPtp(pos=60000, **base))  # (1)
    out = gen.run_until_done()
    assert out["pos"][-1] == 60000 and np.max(np.abs(out["vel"])) <= 20 + 1e-9
    gen.command(sb.AdlinkPtp(pos=0, **base))
    gen.run(500)
    gen.command(sb.AdlinkPtp(pos=0, vm=2e4, acc=1e6, dec=1e6))  # (2) slower, same target
    out = gen.run_until_done()
    assert out["pos"][-1] == 0 and abs(out["vel"][-200]) == pytest.approx(4, abs=1e-9)
    gen.command(sb.AdlinkPtp(pos=50000, sf=0.5, **base))
    gen.run(400)
    gen.command(sb.AdlinkPtp(pos=1000, sf=0.5, **base))  # (3) behind the stopping point: stop, come back
    out = gen.run_until_done()
    assert out["pos"][-1] == 1000 and out["pos"].max() > 1000
    acc = np.diff(out["vel"])
    assert np.max(np.abs(acc)) <= 1e6 * 4e-8 * (1 + 1e-6)  # never beyond ACC/DEC, even at the change


def test_adlink_velocity_move_can_switch_to_ptp():
    # ADLINK L2564-2566: a velocity move can switch to a PTP move to a given position.
    gen = sb.ProfileGenerator(period_s=250e-6)
    p = sb.AdlinkPtp(pos=0, vm=4e4, acc=4e5, dec=4e5, sf=0.3)
    gen.adlink_velocity(4e4, p)
    gen.run(2000)
    gen.command(p.replace(pos=30000))
    out = gen.run_until_done()
    assert out["pos"][-1] == 30000 and gen.mode == "adlink_ptp"
