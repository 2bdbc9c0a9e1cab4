"""Time that flows like a card's (issue 25 point 1): the step, program and realtime modes of servobench.card_clock.

Program mode: every vendor call advances the card by its bus time, a delay by its argument, so the manuals' polling
loops end with the manuals' results, the same way every time. Realtime mode: a background thread ticks the card at
k x real time while program threads call in; each call sees the card between two chunks of ticks."""

from __future__ import annotations

import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import servobench as sb
from servobench.card_clock import VENDOR_CALL_COST_US, CardClock, ClockOptions
from servobench.dialects.aps import MTS_MDN, ApsController
from servobench.dialects.ge import GeController
from servobench.dialects.gt import GtController
from servobench.dialects.gts import GtsController

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)
APS_LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)      # tests/python/test_card_aps.py's tuned axis


def gt_card(**axis_parts):
    g = GtController()
    assert g.GT_Open(sb.Card(4, law=LAW, **axis_parts)) == 0
    return g


def gt_start_move(g, pos=20000, vel=2.0, acc=0.02):
    """GT Example 4-2 style (L935-951): T-curve on axis 1 (pulse, pulse/ST, pulse/ST^2), returns the update's code."""
    assert g.GT_Axis(1) == 0 and g.GT_ClrSts() == 0 and g.GT_AxisOn() == 0
    assert g.GT_PrflT() == 0 and g.GT_SetAcc(acc) == 0 and g.GT_SetVel(vel) == 0 and g.GT_SetPos(pos) == 0
    return g.GT_Update()


# -- options --------------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("kwargs, exc, word", [
    ({"mode": "fast"}, ValueError, "mode"),
    ({"call_cost_us": -1.0}, ValueError, "call_cost_us"),
    ({"call_cost_us": float("nan")}, ValueError, "call_cost_us"),
    ({"call_cost_us": "10"}, TypeError, "call_cost_us"),
    ({"call_costs_us": {"GT_GetSts": 2e6}}, ValueError, "call_costs_us"),
    ({"call_costs_us": {"GetSts": 1.0}}, ValueError, "call_costs_us"),
    ({"call_costs_us": [("GT_GetSts", 1.0)]}, TypeError, "call_costs_us"),
    ({"speed": 0.0}, ValueError, "speed"),
    ({"speed": float("inf")}, ValueError, "speed"),
    ({"period_ms": 0.01}, ValueError, "period_ms"),
    ({"speed": True}, TypeError, "speed"),
])
def test_options_are_validated_naming_the_field(kwargs, exc, word):
    with pytest.raises(exc, match=word):
        ClockOptions(**kwargs)


def test_cost_lookup_per_name_then_all_calls_then_vendor_default():
    o = ClockOptions(mode="program", call_costs_us={"GT_GetSts": 3.5})
    assert o.cost_us("gt", "GT_GetSts") == 3.5 and o.cost_us("gt", "GT_Update") == VENDOR_CALL_COST_US["gt"]
    assert o.cost_us("aps", "APS_get_position") == VENDOR_CALL_COST_US["aps"]
    assert ClockOptions(call_cost_us=7).cost_us("ge", "GT_GetSts") == 7.0
    assert set(VENDOR_CALL_COST_US) == {"gt", "ge", "gts", "aps"}


def test_set_clock_takes_options_or_keywords_not_both():
    card = sb.Card(4, law=LAW)
    assert card.clock is None
    clock = card.set_clock(ClockOptions(mode="program"))
    assert card.clock is clock and clock.mode == "program"
    with pytest.raises(TypeError, match="not both"):
        card.set_clock(ClockOptions(), speed=2.0)
    with pytest.raises(ValueError, match="mode"):
        card.set_clock("soon")
    clock.close()
    assert card.clock is None


# -- step mode: today's behaviour -------------------------------------------------------------------------------------
def test_step_mode_keeps_explicit_time():
    g = gt_card()
    assert gt_start_move(g) == 0
    for _ in range(100):
        g.GT_GetSts()
    assert g.card.tick == 0                                 # calls take no time
    run = g.delay(1.0)                                      # 1 ms = 5 ticks at 200 us, recorded
    assert g.card.tick == 5 and len(run) == 5
    g.card.set_clock("step")
    g.GT_GetSts()
    assert g.card.tick == 5 and len(g.delay(1.0)) == 5


# -- program mode ------------------------------------------------------------------------------------------------------
def gt_polling_program(seed=0):
    """The GT manual's T-curve (Example 4-2, L935-951) and its status loop (``while (status & 0x400)``, L3038) in
    program mode, on a card whose encoder has seeded noise; returns what the program saw."""
    g = gt_card(encoder=sb.Encoder(counts_per_rev=10000, noise_counts=0.7, seed=seed))
    clock = g.card.set_clock("program")
    assert gt_start_move(g) == 0
    seen = []
    while True:
        rtn, status = g.GT_GetSts()
        seen.append((g.card.tick, status, g.GT_GetAtlPos()[1]))
        if not status & 0x400:
            break
    return g, clock, seen


def test_program_mode_polling_loop_ends_at_the_manuals_position():
    g, clock, seen = gt_polling_program()
    # T-curve 20000 pulse at 2 pulse/ST and 0.02 pulse/ST^2: 100 ST up, 9900 ST at speed, 100 down = 10100 ST
    # (the profile of GT L1156 starts at the tick after the update; TV8 for 80000 at 1 / 0.01 gives 80100 ST)
    assert g.card.profile_pos(0) == 20000
    assert abs(g.GT_GetAtlPos()[1] - 20000) <= 5
    st = clock.stats()
    # every call cost 20 us = 1/10 of a 200 us tick: the ticks run are exactly the calls' time, whole ticks
    assert st.ticks == g.card.tick == (st.calls * 20_000_000) // 200_000_000
    assert clock.pending_us == pytest.approx((st.calls * 20) % 200)
    assert 10100 <= g.card.tick <= 10103                 # ends within the poll that sees the bit clear
    ticks = [t for t, _s, _p in seen]
    assert ticks == sorted(ticks) and ticks[-1] - ticks[0] >= 10000


def test_program_mode_tv8_tmotion_loop_as_written():
    # GT Example 4-2 TMotion (L935-951) with the manual's figures: SetAcc(0.01), SetVel(1), SetPos(80000), Update, then
    # "while (status & 0x400) GT_GetSts(&status)" (L3037-3040): TV8 (gt.md §9) gives 80100 ST and position 80000.
    g = gt_card()
    clock = g.card.set_clock("program")
    assert gt_start_move(g, pos=80000, vel=1, acc=0.01) == 0
    while g.GT_GetSts()[1] & 0x400:
        pass
    assert g.card.profile_pos(0) == 80000 and g.GT_GetPos() == (0, 80000)
    assert 80100 <= g.card.tick <= 80102 and clock.stats().ticks == g.card.tick


def test_program_mode_same_program_same_seed_same_result_bit_for_bit():
    _g1, _c1, seen1 = gt_polling_program(seed=3)
    _g2, _c2, seen2 = gt_polling_program(seed=3)
    assert seen1 == seen2
    _g3, _c3, seen3 = gt_polling_program(seed=4)
    assert seen3 != seen1                                # the noise is in what was seen: the comparison can fail


def test_program_mode_accumulates_fractions_of_a_tick_exactly():
    card = sb.Card(4, law=sb.ApsServoLaw(), servo_period_s=250e-6)
    a = ApsController()
    assert a.APS_initial(0, card)[0] == 0
    clock = card.set_clock("program")                    # ADLINK default 10 us per call: 25 calls = 1 tick
    for _ in range(24):
        a.APS_get_position(0)
    assert card.tick == 0 and clock.pending_us == pytest.approx(240.0)
    a.APS_get_position(0)
    assert card.tick == 1 and clock.pending_us == 0.0
    card.set_clock("program", call_costs_us={"APS_get_position": 0.1})  # 2500 calls of 0.1 us = 1 tick
    t0 = card.tick
    for _ in range(2499):
        a.APS_get_position(0)
    assert card.tick == t0
    a.APS_get_position(0)
    assert card.tick == t0 + 1
    for _ in range(5):                                   # Sleep(0.1 ms) x 5 = 0.5 ms = 2 ticks, 0.25 carried
        assert a.Sleep(0.1) is None
    assert card.tick == t0 + 3 and card.clock.pending_us == pytest.approx(0.0)


def test_program_mode_delay_advances_by_its_argument_not_rounded_per_call():
    g = gt_card()
    g.card.set_clock("program", call_cost_us=0)
    for _ in range(10):
        g.delay(0.1)                                     # 0.1 ms = half a tick, each
    assert g.card.tick == 5
    with pytest.raises(ValueError, match="ms"):
        g.delay(-1)
    with pytest.raises(ValueError, match="ms"):
        g.delay(float("nan"))
    assert g.card.tick == 5


def test_a_call_inside_a_call_costs_once():
    card = sb.Card(4, law=LAW)
    clock = card.set_clock("program", call_cost_us=100)
    with clock.vendor_call("gt", "GT_Outer"):
        with clock.vendor_call("gt", "GT_Inner"):
            pass
    assert clock.stats().calls == 1 and clock.pending_us == 100.0 and card.tick == 0
    with clock.vendor_call("gt", "GT_Next"):
        pass
    assert card.tick == 1


def test_program_mode_refused_and_failing_calls_still_cost_and_return_codes():
    g = gt_card()
    clock = g.card.set_clock("program", call_cost_us=200)
    assert g.GT_SetPos(2**40) == 7                       # out of range: the vendor's code, the bus time spent
    assert g.card.tick == 1 and clock.stats().calls == 1


def test_program_mode_ge_polling_loop_ends():
    # GE Example 5-1 (L1012-1019, AxisRunT), polled with GT_GetSts as the manual's examples do (L2238-2300)
    c = GeController("PX", 4)
    assert c.GT_Open(sb.Card(4, drive=sb.VelocityDrive(), law=sb.GtServoLaw(fractional_gains=True))) == 0
    c.card.set_clock("program")
    assert [c.GT_SetKp(1, 1.0), c.GT_Update(1), c.GT_AxisOn(1), c.GT_ClrSts(1)] == [0] * 4
    assert [c.GT_PrflT(1), c.GT_SetPos(1, 5000), c.GT_SetVel(1, 50), c.GT_SetAcc(1, 0.5), c.GT_Update(1)] == [0] * 5
    while c.GT_GetSts(1)[1] & 0x400:
        pass
    assert c.GT_GetPrfPos(1)[1] == 5000
    # 5000 pulse at 50 pulse/ms, 0.5 pulse/ms^2: 100 ms ramps + 100 ms at speed = 200 ms = 1000 ticks at 200 us
    assert 995 <= c.card.tick <= 1010


def test_program_mode_aps_sleep_polling_loop_ends():
    card = sb.Card(4, law=APS_LAW, servo_period_s=250e-6)
    a = ApsController()
    assert a.APS_initial(0, card)[0] == 0
    card.set_clock("program")
    assert a.APS_set_servo_on(0, 1) == 0
    assert a.APS_relative_move(0, 5000, 50000) == 0      # pulse, pulse/s
    while not a.APS_motion_status(0) >> MTS_MDN & 1:
        a.Sleep(1)                                       # the examples' loop: poll, Sleep(1 ms)
    assert a.APS_get_command(0)[1] == 5000


def test_program_mode_guc_polling_loop_ends_and_nested_calls_cost_once():
    # GUC-ECAT / iDEABOX: GT_GetSts bit 10 = the profile moves (GUC L2643-2645), 1 ms servo period
    g = GtsController()
    assert g.GT_Open(sb.Card(8, law=LAW, servo_period_s=1e-3)) == 0
    clock = g.card.set_clock("program")                  # 20 us per call: 50 calls = 1 tick
    assert g.GT_AxisOn(1) == 0 and g.GT_PrfTrap(1) == 0
    calls = clock.stats().calls
    assert g.GT_SetJogPrm(1, 0.1) == 0                   # calls GT_SetTrapPrm inside: one call, one cost
    assert clock.stats().calls == calls + 1 and clock.pending_us == pytest.approx(20.0 * (calls + 1) % 1000)
    assert [g.GT_SetVel(1, 10), g.GT_SetPos(1, 2000), g.GT_Update(1)] == [0, 0, 0]
    t0 = g.card.tick
    while g.GT_GetSts(1)[1] & 0x400:
        pass
    assert g.GT_GetPrfPos(1)[1] == 2000
    # 2000 pulse at 10 pulse/ms, 0.1 pulse/ms^2: 100 ms up, 100 ms at speed, 100 ms down = 300 ticks of 1 ms
    assert 299 <= g.card.tick - t0 <= 303


# -- realtime mode ------------------------------------------------------------------------------------------------------
def test_realtime_start_stop_joins_the_thread_and_detaches():
    card = sb.Card(4, law=LAW)
    with card.set_clock("realtime", speed=1.0) as clock:
        assert clock.running and card.clock is clock
        time.sleep(0.1)
    assert not clock.running and card.clock is None
    t = card.tick
    assert t > 0
    time.sleep(0.05)
    assert card.tick == t                                # stopped means stopped
    clock.close()                                        # idempotent


def test_realtime_ctrl_c_in_the_block_stops_the_thread():
    card = sb.Card(4, law=LAW)
    with pytest.raises(KeyboardInterrupt):
        with card.set_clock("realtime") as clock:
            raise KeyboardInterrupt
    assert not clock.running and card.clock is None


def test_realtime_thread_is_joined_at_interpreter_exit():
    code = ("import servobench as sb, time\n"
            "card = sb.Card(4, law=sb.GtServoLaw(kp=38, kd=830))\n"
            "clock = card.set_clock('realtime', speed=1.0)\n"
            "time.sleep(0.1)\n"
            "print(clock.running, card.tick > 0)\n")          # exits without closing the clock
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["True", "True"]


def test_realtime_speed_factor_roughly_honoured():
    card = sb.Card(4, law=LAW)                           # Ts = 200 us
    with card.set_clock("realtime", speed=2.0) as clock:
        time.sleep(0.6)
    st = clock.stats()
    print(st)                                            # the measured figures, in the test log
    assert st.ticks > 0 and st.wall_s >= 0.6
    if st.kept_up:                                       # a timed bound only when the machine kept up
        assert 0.5 * 2.0 <= st.speed_measured <= 2.0 * 2.0
    assert st.speed_measured <= 2.0 * 1.05               # never ahead of the schedule


def _thread_cpu_s(thread) -> float:
    """CPU time of one thread of this process, s (Linux /proc schedstat: first field, ns)."""
    with open(f"/proc/self/task/{thread.native_id}/schedstat") as f:
        return int(f.read().split()[0]) * 1e-9


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="per-thread CPU time from /proc")
def test_realtime_idle_card_does_not_burn_a_core():
    card = sb.Card(4, law=LAW)
    with card.set_clock("realtime", speed=0.01, period_ms=5) as clock:   # a tick every 20 ms: mostly asleep
        wall0 = time.perf_counter()
        time.sleep(0.05)
        cpu0 = _thread_cpu_s(clock._thread)
        time.sleep(0.5)
        cpu, wall = _thread_cpu_s(clock._thread) - cpu0, time.perf_counter() - wall0
    print(f"ticking thread: {cpu * 1e3:.2f} ms CPU in {wall * 1e3:.0f} ms wall")
    assert cpu < 0.1 * wall, (cpu, wall)                 # a busy-waiting thread would use ~all of it


def test_realtime_delay_waits_for_the_card_and_run_is_refused():
    g = gt_card()
    with g.card.set_clock("realtime", speed=1.0):
        t0 = g.card.tick
        assert g.delay(10) is None                       # 10 ms = 50 ticks at 200 us
        assert g.card.tick - t0 >= 50
        with pytest.raises(RuntimeError, match="real time"):
            g.run(10)


def test_realtime_wait_until_a_move_ends():
    g = gt_card()
    # The move (2000 pulses at 2 pulse/tick: ~1100 ticks) lasts ~110 ms of wall time at k = 2, so a scheduling delay
    # of a few ms between GT_Update and the wait (a GIL switch interval is 5 ms) cannot eat the 1000 ticks the wait
    # must see; at k = 20 (11 ms) one such delay failed a CI run (waited 429; decision VK14).
    with g.card.set_clock("realtime", speed=2.0):
        assert gt_start_move(g, pos=2000, vel=2, acc=0.02) == 0
        waited = g.wait_until(lambda: not g.GT_GetSts()[1] & 0x400, max_ticks=10**6)
        assert g.card.profile_pos(0) == 2000 and waited >= 1000


def aps_card():
    a = ApsController()
    assert a.APS_initial(0, sb.Card(4, law=APS_LAW, servo_period_s=250e-6))[0] == 0
    assert a.APS_set_servo_on(0, 1) == 0
    return a


def test_realtime_hold_groups_calls_without_ticks_between():
    a = aps_card()
    with a.card.set_clock("realtime", speed=5.0) as clock:
        assert a.APS_relative_move(0, 50000, 20000) == 0     # pulse, pulse/s: 2.5 s of card time
        changed = 0
        for _ in range(50):
            with clock.hold():                           # no torn reads: both reads at one tick
                t = a.card.tick
                p1 = a.APS_get_command(0)[1]
                time.sleep(0.002)
                p2 = a.APS_get_command(0)[1]
                assert a.card.tick == t and p1 == p2
            time.sleep(0.002)
            changed += a.card.tick != t
        assert changed > 0                               # the card did tick between the groups


def test_realtime_several_program_threads_under_contention():
    a = aps_card()
    errors, reads = [], [[] for _ in range(4)]
    stop = threading.Event()

    def reader(k):
        try:
            while not stop.is_set():
                rtn, pos = a.APS_get_command(0)
                msts = a.APS_motion_status(0)
                assert rtn == 0 and msts >= 0, (rtn, msts)
                reads[k].append(pos)
                if k % 2:
                    time.sleep(0.0005)
        except BaseException as exc:  # noqa: BLE001 -- reported by the main thread
            errors.append(exc)

    t_start = time.perf_counter()
    with a.card.set_clock("realtime", speed=5.0) as clock:
        assert a.APS_relative_move(0, 10000, 20000) == 0     # 0.5 s at speed plus the ramps, of card time
        threads = [threading.Thread(target=reader, args=(k,)) for k in range(4)]
        for t in threads:
            t.start()
        done = a.wait_until(lambda: a.APS_motion_status(0) >> MTS_MDN & 1, max_ticks=10**6)
        stop.set()
        for t in threads:
            t.join(timeout=30)
        assert not any(t.is_alive() for t in threads), "a program thread hung"
    assert time.perf_counter() - t_start < 120           # bounded: no deadlock (about 0.12 s at 5x when kept up)
    assert not errors, errors
    assert a.APS_get_command(0)[1] == 10000 and done > 0
    for r in reads:
        assert len(r) > 0 and np.all(np.diff(r) >= 0)   # a monotone move reads monotone from every thread
    print(clock.stats(), [len(r) for r in reads])


def test_realtime_ge_keeps_its_reentry_code_under_contention():
    # GE L266: -3 "command re-entered: do not call the controller from several threads at once". The clock
    # serialises a call against the ticking, not against the vendor's own rule: concurrent GE calls may get -3.
    c = GeController("PX", 4)
    assert c.GT_Open(sb.Card(4, drive=sb.VelocityDrive(), law=sb.GtServoLaw(fractional_gains=True))) == 0
    assert [c.GT_SetKp(1, 1.0), c.GT_Update(1), c.GT_AxisOn(1), c.GT_ClrSts(1)] == [0] * 4
    codes, errors = [], []

    def reader():
        try:
            for _ in range(300):
                rtn, _pos = c.GT_GetPrfPos(1)
                codes.append(rtn)
        except BaseException as exc:  # noqa: BLE001
            errors.append(exc)

    with c.card.set_clock("realtime", speed=5.0):
        assert [c.GT_PrflT(1), c.GT_SetPos(1, 5000), c.GT_SetVel(1, 10), c.GT_SetAcc(1, 0.1), c.GT_Update(1)] == [0] * 5
        threads = [threading.Thread(target=reader) for _ in range(3)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=60)
        assert not any(t.is_alive() for t in threads)
    assert not errors and len(codes) == 900
    assert set(codes) <= {0, -3} and codes.count(0) > 0


def test_realtime_error_in_the_thread_reaches_the_program():
    card = sb.Card(4, law=LAW)

    def bad(_card, _ev):
        raise ZeroDivisionError("callback")

    card.on_event(bad, timer_ticks=10)
    clock = card.set_clock("realtime", speed=1.0)
    deadline = time.perf_counter() + 10
    while clock.running and time.perf_counter() < deadline:
        time.sleep(0.01)
    assert not clock.running
    with pytest.raises(RuntimeError, match="ZeroDivisionError"):
        clock.close()


def test_clock_rejects_bad_arguments():
    card = sb.Card(4, law=LAW)
    with pytest.raises(TypeError, match="options"):
        CardClock(card, {"mode": "program"})
    clock = card.set_clock("program")
    with pytest.raises(ValueError, match="max_ticks"):
        clock.wait_until(lambda: True, max_ticks=-1)
