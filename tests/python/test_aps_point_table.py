"""ADLINK point tables (APS_pt_*, manual §4.10.6, seed 004 L3794-3911; decisions AF4-AF12, AF22) on the virtual
card. `Lnnnn` = lines of the ADLINK PCI-8254/8258 manual."""

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import aps
from servobench.dialects.aps import PTA2CA, PTA2CE, PTDWL, PTHCA, PTHCE, PTLINE, ApsController

LAW = sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32)
TS = 250e-6


def bit(word, b):
    return (word >> b) & 1


def table(dim=2, vm=20000.0, acc=2e5):
    c = ApsController()
    assert c.APS_initial(0, sb.Card(4, law=LAW, servo_period_s=TS))[0] == 0
    for i in range(4):
        assert c.APS_set_servo_on(i, 1) == 0
    assert c.APS_pt_enable(0, 0, dim, list(range(dim))) == 0
    assert [c.APS_pt_set_vm(0, 0, vm), c.APS_pt_set_acc_dec(0, 0, acc)] == [0, 0]
    return c


def line(*pos):
    p = PTLINE(Dim=len(pos))
    p.Pos[:len(pos)] = pos
    return p


def run_until_done(c, axes=(0, 1), limit=200000, vel=False):
    """Runs until the table is done: profile positions (whole pulses, ticks x axes), MTS words of axis 0 per 40
    ticks, and with vel=True the profile velocities (pulse/s, ticks x axes)."""
    pos, words, vels = [], [], []
    for _ in range(limit // 40):
        r = c.card.run(40, signals=["pos", "prf_vel"])
        pos.append(np.stack([r[a].pos for a in axes], 1))
        vels.append(np.stack([r[a].prf_vel for a in axes], 1) / TS)
        words.append(c.APS_motion_status(0))
        if bit(words[-1], aps.MTS_MDN):
            out = (np.concatenate(pos), words)
            return out + (np.concatenate(vels),) if vel else out
    raise AssertionError("the table did not finish")


def test_points_wait_for_pt_start_then_run_in_sequence_buffered_l3870():
    c = table()
    pts = [(10000, 0), (10000, 10000), (0, 10000)]
    for p in pts:
        rtn, st = c.APS_pt_line(0, 0, line(*p))
        assert rtn == 0
    # pushed, not started: 3 points in use, none running, the group waits (MTS WAIT, NSTP; no PTB yet)
    assert (st.BitSts, st.PntBufUsageSpace, st.PntBufFreeSpace, st.RunningCnt) == (0, 3, 47, 0)
    c.run(400)
    assert c.card.profile_pos(0) == 0 and c.card.profile_pos(1) == 0
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_WAIT) and bit(m, aps.MTS_NSTP) and not bit(m, aps.MTS_MDN)
    assert c.APS_pt_start(0, 0) == 0
    c.run(40)
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_PTB) and not bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_ASTP)     # L3656
    assert c.APS_get_pt_status(0, 0)[1].BitSts == aps.PTB_WORKING
    pos, words = run_until_done(c)
    # buffered (mode 4, L3117-3122): each point ends at rest at its corner before the next starts
    for corner in pts:
        d = np.min(np.linalg.norm(pos - np.array(corner), axis=1))
        assert d < 1.0
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [0, 10000]
    st = c.APS_get_pt_status(0, 0)[1]
    assert (st.BitSts, st.PntBufUsageSpace, st.PntBufFreeSpace, st.RunningCnt) == (aps.PTB_EMPTY, 0, 50, 3)
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_MDN) and not bit(m, aps.MTS_PTB) and not bit(m, aps.MTS_NSTP)


def test_blend_modes_cut_the_corner_and_save_time_l3124_l3143():
    durations, miss = {}, {}
    for name, setter in (("buffered", lambda c: c.APS_pt_set_trans_buffered(0, 0)),
                         ("dec", lambda c: c.APS_pt_set_trans_blend_dec(0, 0, 0.0)),
                         ("dist", lambda c: c.APS_pt_set_trans_blend_dist(0, 0, 2000.0)),
                         ("pctn", lambda c: c.APS_pt_set_trans_blend_pctn(0, 0, 20.0))):
        c = table()
        assert setter(c) == 0
        for p in ((10000, 0), (10000, 10000)):
            assert c.APS_pt_line(0, 0, line(*p))[0] == 0
        assert c.APS_pt_start(0, 0) == 0
        t0 = c.card.tick
        pos, words = run_until_done(c)
        durations[name] = c.card.tick - t0
        miss[name] = np.min(np.linalg.norm(pos - np.array([10000, 0]), axis=1))
        assert [c.APS_get_command(i)[1] for i in (0, 1)] == [10000, 10000]   # the end point exact
        blended = any(bit(w, aps.MTS_BLD) for w in words)
        assert blended == (name != "buffered")                                  # MTS BLD while two points run
    assert miss["buffered"] < 1.0 and all(miss[k] > 100 for k in ("dec", "dist", "pctn"))
    assert all(durations[k] < durations["buffered"] for k in ("dec", "dist", "pctn"))
    # mode 6 starts the next point 2000 pulse before the corner, mode 7 at 20 % of 10000 = 2000 pulse (L3142):
    # the same start, the same path
    assert durations["dist"] == pytest.approx(durations["pctn"], abs=2 * 4)


def test_dwell_holds_the_position_l3838():
    c = table()
    assert c.APS_pt_line(0, 0, line(5000, 0))[0] == 0
    assert c.APS_pt_dwell(0, 0, PTDWL(DwTime=200.0))[0] == 0       # ms
    assert c.APS_pt_line(0, 0, line(5000, 5000))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    pos, _ = run_until_done(c)
    still = np.all(np.diff(pos, axis=0) == 0, axis=1) & (pos[1:, 0] == 5000) & (pos[1:, 1] == 0)
    # the longest run of ticks at rest on the corner: 200 ms = 800 ticks (one motion cycle = one tick here)
    runs = np.diff(np.flatnonzero(np.diff(np.r_[0, still.astype(int), 0])))[::2]
    # plus the ticks the whole-pulse command needs to leave the corner at 2e5 pulse/s^2 on either side: half a
    # pulse takes sqrt(1 / 2e5) s = 9 ticks
    q = 2 * int(np.ceil(np.sqrt(1 / 2e5) / TS))
    assert 0.2 / TS <= runs.max() <= 0.2 / TS + q
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [5000, 5000]
    assert c.APS_pt_dwell(0, 0, PTDWL(DwTime=0.0))[0] == aps.ERR_ParametersInvalid


def test_buffer_holds_50_points_l3796():
    c = table()
    for k in range(50):
        rtn, st = c.APS_pt_line(0, 0, line(100 * (k + 1), 0))
        assert rtn == 0
    assert st.BitSts & aps.PTB_FULL and st.PntBufFreeSpace == 0 and st.PntBufUsageSpace == 50
    rtn, st = c.APS_pt_line(0, 0, line(99999, 0))
    assert rtn == aps.ERR_FunctionNotAvailable and st.PntBufUsageSpace == 50
    assert c.APS_pt_start(0, 0) == 0
    c.run(4000)
    st = c.APS_get_pt_status(0, 0)[1]
    # buffered: one point runs, the finished ones are free again
    assert not st.BitSts & aps.PTB_FULL and 1 < st.RunningCnt < 50
    assert st.PntBufFreeSpace == st.RunningCnt - 1 and st.PntBufFreeSpace + st.PntBufUsageSpace == 50
    # refill while it runs: the new points run after the others (L3880 "reloading ... repetitively")
    assert c.APS_pt_line(0, 0, line(0, 0))[0] == 0
    run_until_done(c)
    assert c.APS_get_command(0)[1] == 0 and c.APS_get_pt_status(0, 0)[1].RunningCnt == 51


def test_relative_points_speeds_and_parameters_l3808_l3820():
    c = table(vm=10000.0, acc=1e5)
    assert c.APS_pt_set_relative(0, 0) == 0
    assert [c.APS_pt_set_acc(0, 0, 2e5), c.APS_pt_set_dec(0, 0, 2e5), c.APS_pt_set_s(0, 0, 0.0)] == [0, 0, 0]
    assert c.APS_pt_set_ve(0, 0, 0.0) == 0
    assert c.APS_pt_line(0, 0, line(3000, 4000))[0] == 0          # by (3000, 4000): 5000 pulse at 10000 pulse/s
    assert c.APS_pt_set_absolute(0, 0) == 0
    assert c.APS_pt_line(0, 0, line(0, 0))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    pos, _, vel = run_until_done(c, vel=True)
    v = np.linalg.norm(vel, axis=1)
    assert v.max() == pytest.approx(10000, rel=1e-6)               # APS_pt_set_vm (vector speed)
    assert np.max(np.abs(pos - [3000, 4000]).sum(1) == 0)         # the relative point reached
    # T-curve at 2e5 pulse/s^2: 5000 pulse at 10000 pulse/s take 0.5 + 0.05 s per point
    assert len(pos) * TS == pytest.approx(2 * 0.55, abs=0.02)
    # bad values: the vendor code, nothing changed
    assert c.APS_pt_set_vm(0, 0, 0) == aps.ERR_ParametersInvalid
    assert c.APS_pt_set_s(0, 0, 1.5) == aps.ERR_ParametersInvalid
    assert c.APS_pt_set_ve(0, 0, -1) == aps.ERR_ParametersInvalid
    assert c.APS_pt_set_acc(0, 1, 1e5) == aps.ERR_FunctionNotAvailable    # table 1 is not enabled
    assert c.APS_pt_set_trans_blend_pctn(0, 0, 100.0) == aps.ERR_ParametersInvalid
    assert c.APS_pt_set_trans_blend_dist(0, 0, 0.0) == aps.ERR_ParametersInvalid
    assert c.APS_pt_set_trans_blend_dec(0, 0, -1.0) == aps.ERR_ParametersInvalid


def test_end_speed_carries_into_the_next_point_af7():
    c = table(vm=10000.0, acc=1e5)
    assert c.APS_pt_set_ve(0, 0, 5000.0) == 0
    assert c.APS_pt_line(0, 0, line(5000, 0))[0] == 0
    assert c.APS_pt_set_ve(0, 0, 0.0) == 0
    assert c.APS_pt_line(0, 0, line(10000, 0))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    pos, _, vel = run_until_done(c, vel=True)
    v = vel[:, 0]
    k = int(np.argmin(np.abs(pos[:, 0] - 5000)))
    assert v[k] == pytest.approx(5000, rel=0.02)                  # passes the junction at VE, no stop
    assert np.all(np.abs(np.diff(v)) <= 1e5 * TS * 1.0001)       # the speed never jumps (ACC = DEC = 1e5)


def test_trans_inp_is_the_card_cannot_do_af8():
    c = table()
    assert c.APS_pt_set_trans_inp(0, 0) == aps.ERR_FunctionNotAvailable
    assert "APS_pt_set_trans_inp" in aps.UNSUPPORTED
    assert ApsController().APS_pt_set_trans_inp(0, 0) == aps.ERR_DeviceNotInitial


def test_arcs_and_spirals_l3836_l3837():
    c = table()
    assert c.APS_pt_arc2_ca(0, 0, PTA2CA(Index=[0, 1], Center=[5000, 0], Angle=180.0))[0] == 0
    assert c.APS_pt_arc2_ce(0, 0, PTA2CE(Index=[0, 1], Center=[15000, 0], End=[15000, 5000], Dir=0))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    pos, _ = run_until_done(c)
    r1 = np.linalg.norm(pos[pos[:, 0] <= 10000] - [5000, 0], axis=1)
    assert np.all(np.abs(r1[r1 > 0] - 5000) < 2)                        # on the first circle
    assert [c.APS_get_command(i)[1] for i in (0, 1)] == [15000, 5000]
    assert c.APS_pt_arc2_ca(0, 0, PTA2CA(Index=[1, 0], Center=[0, 0], Angle=90.0))[0] == aps.ERR_FunctionNotAvailable
    assert c.APS_pt_sprial_ca(0, 0, PTHCA(Center=[0, 0, 0], Angle=90))[0] == aps.ERR_FunctionNotAvailable  # 2-D
    # a 3-axis table: a spiral about z by a full turn rising 3000 pulse, then one to an end point
    c = table(dim=3)
    assert c.APS_pt_sprial_ca(0, 0, PTHCA(Center=[2000, 0, 0], Normal=[0, 0, 1], Angle=360.0, DeltaH=3000.0,
                                          FinalR=2000.0))[0] == 0
    assert c.APS_pt_sprial_ce(0, 0, PTHCE(Center=[2000, 0, 3000], Normal=[0, 0, 1], End=[4000, 0, 5000],
                                          Dir=0))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    pos, _ = run_until_done(c, axes=(0, 1, 2))
    assert [c.APS_get_command(i)[1] for i in (0, 1, 2)] == [4000, 0, 5000]
    assert pos[:, 2].max() == 5000 and np.abs(pos[:, 1]).max() > 1900  # went round, rose


def test_instruction_commands_take_effect_with_their_move_l3822():
    c = table()
    for ch, value in ((aps.VAO_TABLE_INPUT_TYPE, 1),):
        assert c.APS_set_vao_param(0, ch, value) == 0
    assert c.APS_pt_line(0, 0, line(5000, 0))[0] == 0
    assert c.APS_pt_ext_set_do_ch(0, 0, 2, 1) == 0               # DO2 on with the 2nd point
    assert c.APS_pt_ext_set_table_no(0, 0, 1, 3) == 0            # VAO controller 1 -> table 3 with it
    assert c.APS_pt_line(0, 0, line(5000, 5000))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    c.run(400)
    assert c.APS_read_d_output(0, 0) == (0, 0) and c.vao_output(1)["table"] == 0
    c.wait_until(lambda: c.APS_get_pt_status(0, 0)[1].RunningCnt == 2, max_ticks=40000)
    assert c.APS_read_d_output(0, 0) == (0, 0b100) and c.vao_output(1)["table"] == 3
    assert c.APS_pt_ext_set_do_ch(0, 0, 8, 1) == aps.ERR_ParametersInvalid
    assert c.APS_pt_ext_set_table_no(0, 0, 2, 0) == aps.ERR_ParametersInvalid


def test_stop_disable_and_refusals_l3856_l3875():
    c = table()
    assert c.APS_pt_line(0, 0, line(20000, 0))[0] == 0
    assert c.APS_pt_line(0, 0, line(20000, 20000))[0] == 0
    assert c.APS_pt_start(0, 0) == 0
    c.Sleep(300)
    assert c.APS_pt_disable(0, 0) == aps.ERR_FunctionNotAvailable     # moving
    assert c.APS_pt_stop(0, 0) == 0
    r = c.card.run(2000, signals=["pos", "prf_vel"])
    v = r[0].prf_vel / TS
    assert v[0] > 10000 and v[-1] == 0 and np.all(np.diff(v) <= 1e-9)   # decelerates to rest on the path
    assert c.card.profile_pos(1) == 0 and c.card.profile_pos(0) < 20000
    st = c.APS_get_pt_status(0, 0)[1]
    assert st.BitSts == aps.PTB_EMPTY and st.RunningCnt == 1             # the 2nd point was dropped
    assert c.APS_pt_disable(0, 0) == 0
    assert c.APS_get_pt_status(0, 0)[0] == aps.ERR_FunctionNotAvailable  # no longer enabled
    assert c.APS_relative_move(0, 1000, 10000) == 0                     # single-axis motion again
    # refusals
    assert c.APS_pt_enable(0, 2, 2, [0, 1]) == aps.ERR_ParametersInvalid      # tables 0..1
    assert c.APS_pt_enable(0, 0, 1, [0]) == aps.ERR_ParametersInvalid         # 2..6 axes
    assert c.APS_pt_enable(0, 0, 2, [0, 0]) == aps.ERR_ParametersInvalid
    assert c.APS_pt_enable(0, 0, 2, [2, 3]) == 0
    assert c.APS_pt_enable(0, 1, 2, [0, 1]) == aps.ERR_FunctionNotAvailable   # one group on the card (AF5)
    assert c.APS_pt_line(0, 0, line(1, 2, 3))[0] == aps.ERR_ParametersInvalid  # Dim != the table's
    assert c.APS_pt_start(0, 0, 1) == aps.ERR_ParametersInvalid
    assert ApsController().APS_pt_enable(0, 0, 2, [0, 1]) == aps.ERR_DeviceNotInitial
