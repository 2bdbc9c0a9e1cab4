"""The card's scope, event callbacks, probe capture, ADLINK position compare and interrupts, GT interrupts and the
GE watch (issue 10 point 3). Manual lines: GT seed 000 (gt.md), GE seed 001 (ge.md), ADLINK seed 004
(adlink.md)."""

import math

import numpy as np
import pytest

import servobench as sb
from servobench.card import FiredEvent, ScopeData
from servobench.dialects import _ge_watch as gw
from servobench.dialects._controller import DialectController
from servobench.dialects.aps import ApsController
from servobench.dialects import aps
from servobench.dialects.gt import GtController

LAW = sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870)
APS_LAW = sb.ApsServoLaw(kp=38912, kd=26560)
RAD = 2 * math.pi / 10000


def moving_card(target=3000, vel=5, acc=0.1):
    card = sb.Card(4, law=LAW)
    card.axis_on(0)
    card.clear_events(0, 4095)
    card.stage_acc(0, acc)
    card.stage_vel(0, vel)
    card.stage_pos(0, target)
    card.update(1)
    return card


# -- the scope ------------------------------------------------------------------------------------------------------
def test_scope_samples_equal_the_run_signals_with_names_units_and_plot(tmp_path):
    a, b = moving_card(), moving_card()
    a.sample([(0, "actual_pos"), (0, "volts"), (0, "p"), (0, "msts")], every_ticks=4, depth=100)
    ra = a.run(600, signals=["actual_pos", "volts"])
    rb = b.run(600, signals=["actual_pos", "volts"])
    np.testing.assert_array_equal(ra[0].actual_pos, rb[0].actual_pos)  # the sampler does not perturb the run
    d = a.scope_data()
    assert isinstance(d, ScopeData) and len(d) == 100
    assert d.names == ["actual_pos[0]", "volts[0]", "p[0]", "msts[0]"]
    assert d.units == ["pulse", "V", "count", "bits"]
    np.testing.assert_array_equal(d.ticks, np.arange(0, 400, 4))
    np.testing.assert_array_equal(d["actual_pos"], rb[0].actual_pos[0:400:4])
    np.testing.assert_array_equal(d[0, "volts"], rb[0].volts[0:400:4])
    np.testing.assert_allclose(d.time_s, d.ticks * 200e-6)
    assert a.scope_data() is None  # one-shot: one block
    fig = d.plot(path=str(tmp_path / "scope.png"))
    assert len(fig.axes) == 4 and (tmp_path / "scope.png").exists()


def test_scope_trigger_pretrigger_and_bad_input():
    card = moving_card(target=5000, vel=10, acc=0.2)
    d = card.capture_scope([(0, "error"), (0, "actual_pos")], depth=60, trigger="rising", trigger_channel=1,
                           level=2500, pretrigger=10, max_ticks=5000)
    assert d.trigger_index == 10
    assert d["actual_pos"][9] < 2500 <= d["actual_pos"][10]
    card2 = moving_card()
    d2 = card2.capture_scope([(0, "moving")], depth=8, trigger="event", events=["motion_complete"], pretrigger=3,
                             max_ticks=5000)
    assert list(d2["moving"][:4]) == [1, 1, 1, 0]
    with pytest.raises(ValueError, match="unknown signal"):
        card.sample([(0, "nope")])
    with pytest.raises(ValueError, match="axis"):
        card.sample([(4, "volts")])
    with pytest.raises(ValueError, match="pretrigger"):
        card.sample([(0, "volts")], depth=10, trigger="rising", pretrigger=10)
    with pytest.raises(ValueError, match="trigger"):
        card.sample([(0, "volts")], trigger="sometimes")
    with pytest.raises(ValueError, match="not a card event"):
        card.sample([(0, "volts")], trigger="event", events=["lunch"])
    with pytest.raises(RuntimeError, match="did not fill"):
        card.capture_scope([(0, "volts")], depth=10, trigger="rising", level=1e9, max_ticks=100)


# -- callbacks ------------------------------------------------------------------------------------------------------
def test_callbacks_stop_at_the_event_tick_may_command_the_card_and_are_deterministic():
    def program():
        card = moving_card(target=1000)
        seen = []

        def back(c, f):
            seen.append((c.tick, f.tick, f.axis, f.word, f.names))
            c.clear_events(0, 1)  # a latched event fires again only after it was cleared
            if len(seen) == 1:  # go back to 0: a command from inside the callback
                c.stage_pos(0, 0)
                c.update(1)

        card.on_event(back, axis=0, events=["motion_complete"])
        run = card.run(1200)
        return card, seen, run

    card, seen, run = program()
    assert len(seen) == 2
    assert seen[0][0] == seen[0][1] + 1 and seen[0][2:] == (0, "events", ["motion_complete"])
    events = run[0].events.astype(np.int64)
    assert events[seen[0][1]] & 1 and not events[seen[0][1] - 1] & 1  # latched in exactly that tick
    assert len(run) == 1200 and abs(card.actual_pos(0)) < 2
    _, seen2, run2 = program()
    assert seen2 == seen
    np.testing.assert_array_equal(run2[0].volts, run[0].volts)


def test_a_callback_that_does_nothing_leaves_the_run_bit_identical():
    a, b = moving_card(), moving_card()
    calls = []
    a.on_event(lambda c, f: calls.append(f), events=["motion_complete"], msts=1 << 1, timer_ticks=100)
    ra = a.run(1500)
    rb = b.run(1500)
    for name in ("actual_pos", "volts", "events"):
        np.testing.assert_array_equal(ra[0][name], rb[0][name])
    assert sum(f.word == "timer" for f in calls) == 15
    assert [f.names for f in calls if f.word == "msts"] == [["VM"]]   # cruise reached, once
    sid = a.on_event(lambda c, f: None, events=["breakpoint"])
    a.remove_event(sid)
    with pytest.raises(ValueError, match="timer"):
        a.on_event(lambda c, f: None, timer_ticks=7)
    with pytest.raises(ValueError, match="not a card event"):
        a.on_event(lambda c, f: None, events=["tea"])
    with pytest.raises(ValueError, match="axis"):
        a.on_event(lambda c, f: None, axis=9, events=["breakpoint"])
    with pytest.raises(TypeError):
        a.on_event(None)


# -- probe (GT_CaptProb, GT L3008-3049) -----------------------------------------------------------------------------
def test_gt_capt_prob_latches_all_armed_axes_and_sets_bit_3():
    g = GtController()
    card = sb.Card(4, law=LAW)
    g.GT_Open(card)
    for k in (1, 2):
        g.GT_Axis(k)
        g.GT_AxisOn()
        g.GT_ClrSts()
        g.GT_PrflT()
        g.GT_SetAcc(0.1)
        g.GT_SetVel(2 * k)
        g.GT_SetPos(20000)
        g.GT_Update()
    g.GT_Axis(3)
    assert g.GT_CaptHome() == 0                       # axis 3 busy with a home capture: left alone
    assert g.GT_CaptProb() == 0
    assert [card.capture_armed(k) for k in range(4)] == ["probe", "probe", "home", "probe"]
    assert g.GT_GetSts()[1] & 0xC000 == 0x4000       # the probe has no armed bit (V85); home keeps bit 14
    card.set_probe_time(0.2)                          # EXI0 at 200 ms = tick 1000
    rec = card.run(1500, signals=["actual_pos"])
    for k in (0, 1):
        g.GT_Axis(k + 1)
        rtn, st = g.GT_GetSts()
        assert st & 0x8                                # bit 3 on every armed axis (L3012-3016)
        cap = g.GT_GetCapt()[1]
        a = rec[k].actual_pos
        assert min(a[998], a[999]) - 1 <= cap <= max(a[998], a[999]) + 1
    g.GT_Axis(4)
    assert g.GT_GetSts()[1] & 0x8                      # axis 4 at rest captured its standing position
    assert g.GT_GetCapt() == (0, 0)
    g.GT_Axis(1)
    assert g.GT_CaptProb() == 1                        # axes 1, 2, 4 hold an uncleared capture, 3 is armed ...
    assert card.capture_armed(0) == "none"
    g.GT_ClrSts()
    assert g.GT_CaptProb() == 0 and card.capture_armed(0) == "probe"   # ... until cleared (one arm, one capture)
    g.GT_Axis(3)
    card.set_probe_position(1, 30000)                 # never reached: nothing more
    card.run(100)
    assert card.capture_armed(0) == "probe"


# -- ADLINK interrupts (L4262-4327) ---------------------------------------------------------------------------------
@pytest.fixture
def a():
    c = ApsController()
    rtn, _ = c.APS_initial(0, sb.Card(4, law=APS_LAW, servo_period_s=250e-6))
    assert rtn == 0
    c.APS_set_servo_on(0, 1)
    c.APS_set_axis_param_f(0, aps.PRA_ACC, 4e5)
    c.APS_set_axis_param_f(0, aps.PRA_DEC, 4e5)
    return c


def test_adlink_interrupt_example_l4262(a):
    board_id, item, factor = 0, 0, 1 << 12          # axis 0, bit 12 IMDN (the example passes the mask, L4271)
    int_no = a.APS_set_int_factor(board_id, item, factor, 1)
    assert int_no == 12                             # item x 32 + bit (V82)
    assert a.APS_get_int_factor(0, 0, aps.IMDN) == (0, 1)
    assert a.APS_wait_single_int(int_no, 100) == aps.ERR_InterruptNotEnable  # main switch off
    a.APS_int_enable(board_id, 1)
    a.APS_relative_move(0, 10000, 40000)            # 0.1 s ramps + 0.15 s cruise
    t0 = a.card.tick
    assert a.APS_wait_single_int(int_no, -1) == aps.ERR_NoError
    assert a.card.tick - t0 == pytest.approx(0.35 / 250e-6, abs=3)   # the wait ends at the motion's end
    assert a.APS_motion_status(0) >> aps.MTS_MDN & 1
    assert a.APS_wait_single_int(int_no, 100) == 0  # still signaled: returns at once (L4270)
    assert a.APS_reset_int(int_no) == 0
    t1 = a.card.tick
    assert a.APS_wait_single_int(int_no, 100) == aps.ERR_TimeOut     # nothing moves: 100 ms of simulated time
    assert a.card.tick - t1 == 400
    assert a.APS_set_int_factor(board_id, item, factor, 0) == int_no
    assert a.APS_int_enable(board_id, 0) == 0
    assert a.APS_wait_single_int(int_no, 10) == aps.ERR_InterruptNotEnable
    assert a.card._subs == ()                      # step 5 released every watch


def test_adlink_interrupt_win32_example_l4292_and_factors(a):
    int_no = a.APS_set_int_factor(0, 0, 1 << 12, 1)
    handle = a.APS_int_no_to_handle(int_no)
    a.APS_int_enable(0, 1)
    iacc = a.APS_set_int_factor(0, 0, aps.IACC, 1)
    idec = a.APS_set_int_factor(0, 0, aps.IDEC, 1)
    a.APS_relative_move(0, 10000, 40000)
    assert a.APS_wait_single_int(iacc, 10) == 0 and a.card.tick <= 2   # acceleration starts at once
    assert a.APS_wait_multiple_int(2, [idec, handle], 0, -1) == 0      # any: the deceleration comes first
    assert a.APS_motion_status(0) >> aps.MTS_DEC & 1
    assert a.APS_wait_multiple_int(2, [idec, handle], 1, -1) == 0      # all
    assert not a.card.moving(0)
    a.APS_reset_int(handle)
    assert a.APS_set_int(handle) == 0 and a.APS_wait_single_int(handle, 0) == 0  # set by software
    # system item: the EMG input (bit 0) and the linear compare's end (ILCF0)
    emg = a.APS_set_int_factor(0, 8, aps.ISYS_EMG, 1)
    assert emg == 256
    assert a.APS_set_int_factor(0, 9, 0, 1) == aps.ERR_FunctionNotAvailable   # no DI on the card
    assert a.APS_set_int_factor(0, 0, aps.IPRED, 1) == aps.ERR_FunctionNotAvailable
    assert a.APS_set_int_factor(0, 4, aps.IMDN, 1) == aps.ERR_ParametersInvalid  # PCI-8254: axes 0-3
    assert a.APS_set_int_factor(0, 0, 7, 1) == aps.ERR_ParametersInvalid         # reserved bit
    a.card.on_event(lambda c, f: setattr(c, "emergency_stop", True), timer_ticks=40)
    assert a.APS_wait_single_int(emg, 100) == 0
    assert a.card.emergency_stop
    card = a.card
    assert a.APS_close() == 0 and len(card._subs) == 1           # the interrupt watches left with APS_close


# -- ADLINK position compare (L3348-3435) ---------------------------------------------------------------------------
def test_adlink_linear_and_table_compare_with_the_manuals_numbers(a):
    # T23 (L3393): P1, repeat 4, interval L -> P1, P1+L, P1+2L, P1+3L, compared in L's direction.
    assert a.APS_set_trigger_param(0, aps.TGR_LCMP0_SRC, 0) == 0            # encoder of axis 0
    assert a.APS_set_trigger_param(0, aps.TGR_TRG0_SRC, aps.TRG_SRC_LCMP0) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TRG0_PWD, 10) == 0            # 1 us
    assert a.APS_set_trigger_param(0, aps.TGR_TRG_EN, 0x1) == 0
    assert a.APS_set_trigger_linear(0, 0, 1000, 4, 2000) == 0
    assert a.APS_get_trigger_linear_cmp(0, 0) == (0, 1000)
    a.card.sample([(0, "trg_pulses"), (0, "actual_pos")], depth=4000)
    a.APS_relative_move(0, 10000, 40000)
    a.Sleep(1000)
    assert a.APS_get_trigger_count(0, 0) == (0, 4)
    log = a.card.compare_log()
    np.testing.assert_array_equal(log["point"], [1000, 3000, 5000, 7000])
    d = a.card.scope_data()
    pulses = d["trg_pulses"]
    assert pulses.sum() == 4
    for k in np.flatnonzero(pulses):
        p = d["actual_pos"]
        assert any(p[k - 1] < pt <= p[k] for pt in log["point"])
    # negative interval on the way back; table compare on the command position, TRG1, both directions
    a.APS_reset_trigger_count(0, 0)
    assert a.APS_set_trigger_linear(0, 0, 9000, 3, -3000) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TCMP0_SRC, aps.TGR_SRC_COMMAND + 0) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TCMP0_DIR, 0) == 0          # negative
    assert a.APS_set_trigger_param(0, aps.TGR_TRG1_SRC, aps.TRG_SRC_TCMP0 | aps.TRG_SRC_MANUAL) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TRG1_TGL, 1) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TRG_EN, 0x3) == 0
    assert a.APS_set_trigger_table(0, 0, [8500, 4000, 100, 99999], 3) == 0
    a.APS_relative_move(0, -10000, 40000)
    a.Sleep(1000)
    assert a.APS_get_trigger_count(0, 0) == (0, 3)
    assert a.APS_get_trigger_count(0, 1) == (0, 3)
    assert a.card.compare_level(1)                   # toggled three times from low
    assert a.APS_set_trigger_manual(0, 1) == 0 and a.APS_get_trigger_count(0, 1) == (0, 4)
    assert a.APS_set_trigger_manual(0, 0) == 0 and a.APS_get_trigger_count(0, 0) == (0, 3)  # no manual source
    # PCI-8254: TRG0-1 only; bad values; the timer counts servo ticks (AF15; tests/python/test_aps_functions_more.py)
    assert a.APS_get_trigger_count(0, 2)[0] == aps.ERR_ParametersInvalid
    assert a.APS_set_trigger_param(0, aps.TGR_TRG2_SRC, 1) == aps.ERR_ParametersInvalid
    assert a.APS_set_trigger_param(0, aps.TGR_TCMP0_DIR, 3) == aps.ERR_ParametersInvalid
    assert a.APS_set_trigger_param(0, aps.TIMR_EN, 1) == 0 and a.APS_get_trigger_param(0, aps.TIMR_EN) == (0, 1)
    assert a.APS_set_trigger_param(0, aps.TIMR_EN, 2) == aps.ERR_ParametersInvalid
    assert a.APS_set_trigger_linear(0, 0, 0, 3, 0) == aps.ERR_ParametersInvalid
    assert a.APS_set_trigger_linear(0, 2, 0, 3, 5) == aps.ERR_ParametersInvalid


def test_adlink_iez_interrupt_on_the_index_mark():
    rad = 2 * math.pi / 10000
    c = ApsController()
    c.APS_initial(0, sb.Card(4, law=APS_LAW, servo_period_s=250e-6,
                             encoder=sb.Encoder(counts_per_rev=10000, index_angle_rad=2500 * rad)))
    c.APS_set_servo_on(0, 1)
    iez = c.APS_set_int_factor(0, 0, aps.IEZ, 1)
    c.APS_int_enable(0, 1)
    c.APS_relative_move(0, 30000, 40000)
    rec = []
    for _ in range(3):                                # the marks at 2500, 12500, 22500 pulse
        assert c.APS_wait_single_int(iez, 1000) == 0
        rec.append(c.card.actual_pos(0))
        c.APS_reset_int(iez)
    assert [round(p / 10000 - 0.25) for p in rec] == [0, 1, 2]
    assert all(0 <= p - m < 20 for p, m in zip(rec, (2500, 12500, 22500)))   # within the tick that passed it
    assert c.APS_wait_single_int(iez, 1000) == aps.ERR_TimeOut


def test_adlink_compare_end_interrupt_ilcf0(a):
    a.APS_set_trigger_param(0, aps.TGR_TRG0_SRC, aps.TRG_SRC_LCMP0)
    a.APS_set_trigger_param(0, aps.TGR_TRG_EN, 1)
    a.APS_set_trigger_linear(0, 0, 100, 5, 100)
    no = a.APS_set_int_factor(0, 8, aps.ILCF0, 1)
    a.APS_int_enable(0, 1)
    a.APS_relative_move(0, 10000, 40000)
    assert a.APS_wait_single_int(no, 1000) == 0
    assert a.APS_get_trigger_count(0, 0) == (0, 5)
    assert a.card.moving(0)                          # the interrupt came as the 5th point passed


# -- ADLINK sampling (L3544-3665) -----------------------------------------------------------------------------------
def test_adlink_sampling_sources_units_and_trigger(a):
    assert a.APS_get_sampling_param(0, aps.SAMP_PA_RATE) == (0, 4)          # 1 ms at 250 us (L3548)
    for ch, src in enumerate((aps.SAMP_COM_POS, aps.SAMP_CMD_VEL, aps.SAMP_CONTROL_VOL, aps.PID_KP_CALC_COUNT)):
        assert a.APS_set_sampling_param(0, aps.SAMP_PA_SRC_CH0 + ch, src) == 0
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_EDGE, 0) == 0            # rising
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_TRIGCH, 0) == 0
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_LEVEL, 5000) == 0
    a.APS_relative_move(0, 10000, 40000)
    rtn, data = a.APS_wait_trigger_sampling(0, 200, 50, 1000)
    assert rtn == 0 and data.dtype == aps.STR_SAMP_DATA_4CH and len(data) == 200
    com, vel, mv, kp = (data["data"][:, k] for k in range(4))
    assert com[49] < 5000 <= com[50]
    assert np.all(np.diff(data["tick"]) == 4)
    assert vel.max() == 40000                                              # pulse/s, cruise
    law = a.card.axes[0].law.effective_gains()
    assert np.all(com == np.rint(com)) and np.all(mv == np.rint(mv))       # I32 sources
    assert np.abs(mv).max() <= 10000                                       # mV
    assert np.any(kp != 0)
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_SRC_CH0, 0x400 | aps.SAMP_COM_POS) == aps.ERR_ParametersInvalid
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_SRC_CH0, aps.SAMP_GTY_DEVIATION) == aps.ERR_FunctionNotAvailable
    assert a.APS_set_sampling_param(0, aps.SAMP_PA_RATE, 0) == aps.ERR_ParametersInvalid
    assert a.APS_wait_trigger_sampling(0, 10, 10, 10)[0] == aps.ERR_ParametersInvalid
    rtn, none = a.APS_wait_trigger_sampling(0, 10, 2, 50)                  # no crossing of 5000 at rest
    assert rtn == aps.ERR_TimeOut and none is None
    # asynchronous: start, let the card run, the count grows, the array fills
    a.APS_set_sampling_param(0, aps.SAMP_PA_EDGE, 2)
    rtn, arr = a.APS_wait_trigger_sampling_async(0, 100, 0, 1000)
    assert rtn == 0 and a.APS_get_sampling_count(0) == (0, 0)
    a.card.run(41)                                                         # samples at ticks 0, 4, ..., 40
    assert a.APS_get_sampling_count(0) == (0, 11) and arr["tick"][10] - arr["tick"][0] == 40
    a.card.run(400)
    assert a.APS_get_sampling_count(0) == (0, 100) and np.all(np.diff(arr["tick"]) == 4)
    rtn, arr = a.APS_wait_trigger_sampling_async(0, 100, 0, 1000)
    a.card.run(10)
    assert a.APS_stop_wait_sampling(0) == 0 and a.APS_get_sampling_count(0) == (0, 0)
    assert law is not None


# -- GT interrupts (gt.md §7, §8.9; L2219-2330, L4534-4801) ---------------------------------------------------------
def gt_move(g, axis, pos, vel=5, acc=0.1):
    g.GT_Axis(axis)
    g.GT_PrflT()
    g.GT_SetAcc(acc)
    g.GT_SetVel(vel)
    g.GT_SetPos(pos)
    return g.GT_Update()


@pytest.fixture
def g():
    c = GtController()
    c.GT_Open(sb.Card(4, law=LAW))
    for k in range(1, 5):
        c.GT_Axis(k)
        c.GT_AxisOn()
        c.GT_ClrSts()
    return c


def test_gt_event_interrupt_sample_8_1_priority_and_reset(g):
    served = []

    def isr():                                     # Sample 8-1 (L2262-2277): AxisI, GetIntr, RstIntr(0)
        assert g.GT_AxisI() == 0
        rtn, event = g.GT_GetIntr()
        served.append((g.card.tick, g._axis + 1, event & 0x7F))
        g.GT_RstIntr(0)

    assert g.GT_HookIsr(isr) is None
    for k in (3, 2):
        g.GT_Axis(k)
        assert g.GT_SetIntrMsk(0x1) == 0           # motion complete
    assert g.GT_GetIntrMsk() == (0, 1)
    gt_move(g, 3, 1000)
    gt_move(g, 2, 1000)                            # the same move: both complete in the same tick
    g.run(400)
    assert len(served) == 2
    (t1, ax1, ev1), (t2, ax2, ev2) = served
    assert t1 == t2 and (ax1, ax2) == (2, 3)       # the lowest axis first (L2229), the other right after
    assert ev1 & 1 and ev2 & 1
    g.GT_Axis(2)
    assert not g.GT_GetSts()[1] & 1                # RstIntr(0) cleared the status bits
    # no interrupt pending: AxisI / RstIntr are command errors, command status bit 4 (Table 2-2)
    assert g.GT_AxisI() == 1 and g.GT_GetCmdSts() == (0, 0x10)
    assert g.GT_RstIntr(0) == 1
    # masked axis 1 does not interrupt
    gt_move(g, 1, 500)
    g.run(400)
    assert len(served) == 2


def test_gt_limit_interrupt_refires_while_pressed_then_moves_away_l2850():
    card = sb.Card(4, law=LAW, switches=sb.Switches(pos_limit_rad=3000 * RAD))
    g = GtController()
    g.GT_Open(card)
    g.GT_Axis(1)
    g.GT_AxisOn()
    g.GT_ClrSts()
    calls = []

    def handler():                                 # the GT_AxisI sample (L2862-2880)
        g.GT_AxisI()
        rtn, intr_sts = g.GT_GetIntr()
        calls.append((card.tick, intr_sts))
        if intr_sts & 0x20 and len(calls) == 5:    # after a few re-fires: move back and clear bits 5, 6
            g.GT_PrflT()
            g.GT_SetVel(5)
            g.GT_SetAcc(0.1)
            rtn, actl_pos = g.GT_GetAtlPos()
            g.GT_SetPos(actl_pos - 2000)
            g.GT_Update()
        g.GT_RstIntr(0x9F)

    g.GT_HookIsr(handler)
    g.GT_SetIntrMsk(0x20)
    g.GT_PrflV()
    g.GT_SetAcc(0.1)
    g.GT_SetVel(5)
    g.GT_Update()
    g.run(3000)
    assert len(calls) >= 5
    ticks = [t for t, _s in calls]
    assert all(s & 0x20 for _t, s in calls)
    assert ticks[1:5] == [ticks[0] + k for k in range(1, 5)]   # re-fires every tick while the limit is pressed
    assert card.actual_pos(0) < 3000 and not card.pos_limit_input(0)


def test_gt_disabled_axis_interrupts_only_on_motion_error_and_alarm(g):
    served = []
    g.GT_HookIsr(lambda: (g.GT_AxisI(), served.append(g.GT_GetIntr()[1]), g.GT_RstIntr(0)))
    g.GT_Axis(2)
    g.GT_SetIntrMsk(0x13)                          # motion complete, drive alarm, motion error
    g.GT_AxisOff()
    g.GT_AbptStp()                                 # motion complete on a disabled axis: no interrupt (L2257)
    g.run(10)
    assert served == [] and g.GT_GetSts()[1] & 1
    g.card.set_alarm_input(1, True)                # the drive alarm does interrupt
    g.run(10)
    assert len(served) == 1 and served[0] & 0x2


def test_gt_timer_interrupt_sample_8_2(g):
    count = []
    g.GT_HookIsr(lambda: (count.append(g.card.tick), g.GT_ClearInt(0)))
    assert g.GT_SetIntrTm(10) == 0 and g.GT_GetIntrTm() == (0, 10)     # 10 x 200 us = 2 ms (L4793-4795)
    assert g.GT_TmrIntr() == 0
    g.delay(100)                                   # 100 ms
    assert len(count) == 50 and np.all(np.diff(count) == 10)
    assert g.GT_GetIntr() == (0, 0)                # a timer event reads 0
    assert g.GT_EvntIntr() == 0
    g.delay(100)
    assert len(count) == 50
    assert g.GT_SetIntrTm(40000) == 7


# -- GE watch (GE L2484-2600, Example 10-1; digest T10) --------------------------------------------------------------
class _GeProgram(DialectController):
    """The GE controller as far as the watch needs it (the GE dialect proper is servobench.dialects.ge)."""

    def __init__(self, card):
        super().__init__()
        self._card = card


def test_ge_watch_example_10_1():
    # GE-800-PV (8 axes); the GE gives no servo period (ge.md §1.3): 200 us here. Plant with enough damping for Kp
    # alone (the example sets only Kp = 10).
    card = sb.Card(8, law=sb.GtServoLaw(), servo_period_s=200e-6,
                   plant=sb.RigidPlant(inertia_kgm2=2e-5, viscous_nms=2e-3))
    ctl = _GeProgram(card)
    BUFFER_SIZE = 400
    config = [0, 3, 0, 0, 0, 0, 0, 0]              # axis 2: profile and actual position
    assert gw.GT_SetWatch(ctl, config, BUFFER_SIZE) == 0
    buffer = gw.TWatchBuffer(8)
    PrfPos = np.zeros(BUFFER_SIZE, dtype=np.int64)
    AtlPos = np.zeros(BUFFER_SIZE, dtype=np.int64)
    buffer.Axis[1].PrfPos = PrfPos
    buffer.Axis[1].AtlPos = AtlPos
    card.stage_law(1, sb.GtServoLaw(kp=10))        # GT_SetKp(2, 10); GT_Update(2)
    card.update(1 << 1)
    card.axis_on(1)                                # GT_AxisOn(2)
    ms = 0.2                                       # servo period in ms: pulse/ms -> pulse/tick
    card.stage_pos(1, 100000)                      # GT_SetPos(2, 100000)
    card.stage_vel(1, 10 * ms)                     # GT_SetVel(2, 10) pulse/ms
    card.stage_acc(1, 1 * ms * ms)                 # GT_SetAcc(2, 1) pulse/ms^2
    assert gw.GT_StartWatch(ctl, 0) == 0           # every control period
    card.update(1 << 1)                            # GT_Update(2)
    out = []
    while True:                                    # do { GetWatch; if (available) save; GetSts } while (moving)
        rtn, available = gw.GT_GetWatch(ctl, buffer)
        assert rtn == 0
        if available:
            out.append(np.column_stack([PrfPos, AtlPos]).copy())
        card.run(100)                              # the host's loop takes 20 ms of card time
        if not card.moving(1):
            break
    while True:                                    # one more block after the stop
        rtn, available = gw.GT_GetWatch(ctl, buffer)
        if available:
            out.append(np.column_stack([PrfPos, AtlPos]).copy())
            break
        card.run(100)
    assert gw.GT_StopWatch(ctl) == 0
    data = np.vstack(out)
    # T10: t_acc = 10 ms, d_acc = 50 pulse, the move takes 10010 ms = 50050 ticks (+ the commit tick)
    move_ticks = 50050
    prf = data[:, 0]
    assert np.all(np.diff(prf) >= 0) and prf[-1] == 100000
    k_end = int(np.argmax(prf == 100000))
    assert abs(k_end - (move_ticks + 1)) <= 10      # the discrete profile ends within 2 ms of the continuous 10010 ms
    # blocks: those filled while moving, then "one more" (the loop after the stop). The digest's T10 estimate
    # ceil(move / 400) + 1 counts one too many when the move ends inside a block, as here (50050 = 125.1 x 400):
    # the block holding the end fills after the stop and is that "one more".
    assert len(out) == k_end // BUFFER_SIZE + 1 == math.ceil(move_ticks / BUFFER_SIZE)
    assert 40 <= prf[50] <= 60                      # after 10 ms of 1 pulse/ms^2: ~50 pulse (the ramp)
    np.testing.assert_array_equal(prf[10000:10005] - prf[9999:10004], [2] * 5)  # cruise 10 pulse/ms = 2/tick
    assert abs(data[-1, 1] - 100000) <= 5           # the actual position follows
    # contiguous blocks: sample k is tick k of the same move recorded tick by tick
    twin = sb.Card(8, law=sb.GtServoLaw(), servo_period_s=200e-6,
                   plant=sb.RigidPlant(inertia_kgm2=2e-5, viscous_nms=2e-3))
    twin.stage_law(1, sb.GtServoLaw(kp=10))
    twin.update(1 << 1)
    twin.axis_on(1)
    twin.stage_pos(1, 100000)
    twin.stage_vel(1, 10 * ms)
    twin.stage_acc(1, 1 * ms * ms)
    twin.update(1 << 1)
    rec = twin.run(len(data), signals=["pos", "actual_pos"])
    np.testing.assert_array_equal(data[:, 0], rec[1].pos)
    np.testing.assert_array_equal(data[:, 1], np.rint(rec[1].actual_pos))
    # the watch functions' codes
    assert gw.GT_SetWatch(ctl, [0, 0x10], 10) == 7                 # reserved bit
    assert gw.GT_SetWatch(ctl, [0x4F] * 8, 1000) == 7              # 40 signals x 1000 > the watch memory (V75)
    assert gw.GT_SetWatch(ctl, [0x40], 5) == 0
    assert gw.GT_StartWatch(ctl, 1) == 0
    assert gw.GT_GetWatch(ctl, gw.TWatchBuffer(8)) == (7, 0)       # no array attached for the watched voltage
    volts = np.zeros(5, dtype=np.int16)
    b = gw.TWatchBuffer(8)
    b.Axis[0].Voltage = volts
    card.run(20)
    assert gw.GT_GetWatch(ctl, b) == (0, 1) and np.all(volts == 0)  # axis 1 off: 0 V
    assert gw.GT_GetWatch(_GeProgram(None), b) == (-1, 0)


def test_gt_reset_masks_every_interrupt(g):
    served = []
    g.GT_HookIsr(lambda: (g.GT_AxisI(), served.append(1), g.GT_RstIntr(0)))
    g.GT_SetIntrMsk(0x1)
    assert g.GT_Reset() == 0
    assert g.GT_GetIntrMsk() == (0, 0)
    g.GT_Axis(1)
    g.GT_AxisOn()
    gt_move(g, 1, 300)
    g.run(300)
    assert served == []


def test_gt_capture_status_conditions_bit_by_bit():
    # GT L2013-2017, L2958-3006, L3640-3674, Table 2-2 bits 7/8 (L465-471): arming sets 14 (home) / 15 (index),
    # the capture sets 3 and clears 14/15, one arm one capture, re-arming while armed or captured is refused with
    # the bit of the command called, GetCapt holds the value until the next capture.
    rad = 2 * math.pi / 8000
    card = sb.Card(4, law=sb.GtServoLaw(kp=30, ki=0, kd=600, kaff=8000),
                   encoder=sb.Encoder(counts_per_rev=8000, index_angle_rad=6000 * rad),
                   switches=sb.Switches(home_min_rad=50000 * rad, home_max_rad=60000 * rad))
    g = GtController()
    g.GT_Open(card)
    g.GT_Axis(1)
    g.GT_AxisOn()
    g.GT_ClrSts()
    assert sts_of(g) & 0xC008 == 0
    assert g.GT_CaptHome() == 0 and sts_of(g) & 0xC008 == 0x4000          # armed: bit 14
    assert g.GT_CaptHome() == 1 and g.GT_GetCmdSts() == (0, 0x100)        # again while armed: bit 8
    assert g.GT_CaptIndex() == 1 and g.GT_GetCmdSts() == (0, 0x80)        # CaptIndex while armed: bit 7
    assert sts_of(g) & 0x80                                                # command error on the axis status
    gt_move(g, 1, 70000, vel=4, acc=1)
    g.wait_until(lambda: sts_of(g) & 0x8, max_ticks=100000, chunk=5)
    st = sts_of(g)
    assert st & 0x8 and not st & 0xC000                                    # captured: bit 3 on, 14 off
    rtn, home = g.GT_GetCapt()
    assert abs(home - 50000) <= 1
    assert g.GT_CaptIndex() == 1 and g.GT_GetCmdSts() == (0, 0x80)        # bit 3 still set: refused
    g.GT_ClrSts()
    assert not sts_of(g) & 0x8 and g.GT_GetCapt() == (0, home)            # the value holds (L3644)
    assert g.GT_CaptIndex() == 0 and sts_of(g) & 0xC008 == 0x8000         # armed: bit 15
    g.wait_until(lambda: sts_of(g) & 0x8, max_ticks=100000, chunk=5)
    assert sts_of(g) & 0xC008 == 0x8 and g.GT_GetCapt()[1] != home        # one capture, the next index mark
    assert (g.GT_GetCapt()[1] - 6000) % 8000 in (0, 1, 7999)
    g.GT_ClrSts()
    assert g.GT_CaptIndex() == 0
    g.GT_ClrSts()                                                          # ClrSts keeps the arm (bit 15)
    assert sts_of(g) & 0x8000
    card.arm_capture(0, "none")
    assert not sts_of(g) & 0xC000


def sts_of(g):
    rtn, s = g.GT_GetSts()
    assert rtn == 0
    return s
