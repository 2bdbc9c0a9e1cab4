"""GUC-ECAT system configuration (seed 002 §3.1 L185-305), the iDEABOX velocity filters (seed 003 §4.5 L3773-3801),
the read-backs, the EtherCAT / configuration-file calls of the iDEABOX examples and the ``...Mx`` forms, each
checked against the manuals (``Lnnn`` lines of ../shared/seeds/00[23]_*.txt; decisions GS1-GS18). Units pulse, ms,
pulse/ms, pulse/ms^2; servo period 200 us (test_card_modes.TS)."""

import numpy as np
import pytest

import servobench as sb
from servobench.dialects import gts as G
from servobench.dialects.gts import GtsController, TJogPrmExt
from test_card_modes import LAW, TS, crd_xy, gts, tick_of_ms  # noqa: F401 (gts: the fixture)

MS = TS * 1e3  # ms per tick


def jog(g, axis=1, vel=10.0, acc=0.1):
    assert [g.GT_PrfJog(axis), g.GT_SetJogPrm(axis, acc), g.GT_SetVel(axis, vel), g.GT_Update(1 << (axis - 1))] \
        == [0] * 4
    g.run(tick_of_ms(vel / acc + 20))
    assert g.GT_GetPrfVel(axis)[1] == pytest.approx(vel)


def stop_time_ms(g, axis=1):
    n = 0
    while g.card.moving(axis - 1):
        g.run(1)
        n += 1
        assert n < 10**6
    return n * MS


# -- alarms, limits, senses, scales, inputs (GUC §3.1) ------------------------------------------------------------

def test_alarm_on_off_decide_whether_the_drive_alarm_stops_the_axis_guc_l197_215(gts):
    assert gts.GT_AlarmOff(1) == 0
    gts.card.set_alarm_input(0, True)
    gts.run(5)
    assert gts.card.servo_on(0) and gts.GT_GetDi(G.MC_ALARM) == (0, 0)       # ignored
    assert gts.GT_AlarmOn(1) == 0
    gts.run(5)
    assert not gts.card.servo_on(0) and gts.GT_GetDi(G.MC_ALARM) == (0, 0b1)  # the alarm takes the drive off
    assert [gts.GT_AlarmOn(0), gts.GT_AlarmOff(5)] == [7, 7] and GtsController().GT_AlarmOn(1) == -1


def test_lmts_on_off_and_lmt_sns_guc_l199_228_l294_305(gts):
    # LmtSns bit 2k = axis k+1 positive, 2k+1 negative, 1 = low level active (Tab 3-4): with no switch wired
    # (inputs low) an active-low limit triggers; GT_GetDi reads the triggered limits (bit k = axis k+1).
    assert gts.GT_GetDi(G.MC_LIMIT_POSITIVE) == (0, 0) and gts.GT_GetDi(G.MC_LIMIT_NEGATIVE) == (0, 0)
    assert gts.GT_LmtSns(0b0110) == 0                                          # axis 1 -, axis 2 +
    assert gts.card.limits(0).neg_active_low and gts.card.limits(1).pos_active_low
    assert gts.GT_GetDi(G.MC_LIMIT_POSITIVE) == (0, 0b10) and gts.GT_GetDi(G.MC_LIMIT_NEGATIVE) == (0, 0b01)
    assert gts.GT_LmtSns(0) == 0 and gts.GT_LmtSns(0x10000) == 7
    # LmtsOff / LmtsOn: both sides (-1, default) switch the axis's limits (GS3: one side only when the other agrees)
    assert gts.GT_LmtsOff(1) == 0 and not gts.card.limits(0).enabled
    assert gts.GT_LmtsOn(1, G.MC_LIMIT_POSITIVE) == 1 and not gts.card.limits(0).enabled  # refused, unchanged
    assert gts.GT_LmtsOff(1, G.MC_LIMIT_NEGATIVE) == 0                                    # already so
    assert gts.GT_LmtsOn(1, -1) == 0 and gts.card.limits(0).enabled
    assert [gts.GT_LmtsOn(1, 2), gts.GT_LmtsOff(9)] == [7, 7]


def test_limit_switch_stops_unless_lmts_off():
    rad = 2 * np.pi / 10000
    for off in (False, True):
        g = GtsController()
        g.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS, switches=sb.Switches(pos_limit_rad=5000 * rad)))
        assert g.GT_AxisOn(1) == 0
        if off:
            assert g.GT_LmtsOff(1) == 0
        assert [g.GT_PrfTrap(1), g.GT_SetTrapPrm(1, 1), g.GT_SetVel(1, 20), g.GT_SetPos(1, 20000),
                g.GT_Update(1)] == [0] * 5
        g.run(tick_of_ms(1500))
        assert (g.card.profile_pos(0) == 20000) == off


def test_enc_sns_profile_and_enc_scale_accept_the_simulated_wiring_only_gs4_gs5(gts):
    # GT_EncSns (L284-290, Tab 3-3): bits 0..8; a reversed encoder is not simulated (1). Scales alpha/beta (L232-239):
    # 1:1 only.
    assert [gts.GT_EncSns(0), gts.GT_EncSns(1), gts.GT_EncSns(0x200)] == [0, 1, 7]
    assert [gts.GT_ProfileScale(1, 1, 1), gts.GT_ProfileScale(1, -5, -5), gts.GT_ProfileScale(1, 2, 1),
            gts.GT_ProfileScale(1, 1, 0), gts.GT_ProfileScale(1, 40000, 1), gts.GT_ProfileScale(0, 1, 1)] \
        == [0, 0, 1, 7, 7, 7]
    assert [gts.GT_EncScale(1, 1, 1), gts.GT_EncScale(1, 3, 2), gts.GT_EncScale(1, 1, 0), gts.GT_EncScale(5, 1, 1)] \
        == [0, 1, 7, 7]


def test_gpi_sns_inverts_what_get_di_reads_guc_l267_276(gts):
    assert gts.GT_GetDi(G.MC_GPI) == (0, 0)          # nothing wired: all inputs low
    gts.set_inputs(0b101)
    assert gts.GT_GetDi(G.MC_GPI) == (0, 0b101)
    assert gts.GT_GpiSns(0b1) == 0 and gts.GT_GetDi(G.MC_GPI) == (0, 0b100)
    assert gts.GT_GpiSns(0x10000) == 7 and gts.GT_GetDi(9) == (7, 0)
    assert gts.GT_GetDi(G.MC_HOME)[0] == 1 and gts.GT_GetDi(G.MC_ARRIVE)[0] == 1  # not wired (GS6)
    with pytest.raises(ValueError, match="bits"):
        gts.set_inputs(0x10000)


def test_set_adc_filter_is_unsupported_guc_l278(gts):
    assert "GT_SetAdcFilter" in G.UNSUPPORTED and "GT_LoadConfig" in G.UNSUPPORTED
    assert [gts.GT_SetAdcFilter(1, 10), gts.GT_SetAdcFilter(0, 10), gts.GT_SetAdcFilter(1, 51)] == [1, 7, 7]


# -- stop decelerations and stop inputs ----------------------------------------------------------------------------

def test_set_stop_dec_sets_how_gt_stop_decelerates_guc_l203_247(gts):
    assert gts.GT_GetStopDec(1) == (0, 0.0, 0.0)
    jog(gts)
    assert gts.GT_Stop(1, 0) == 0
    assert stop_time_ms(gts) == pytest.approx(10 / 0.1, abs=2 * MS)       # smooth: at the jog's acc
    assert gts.GT_SetStopDec(1, 0.05, 1) == 0 and gts.GT_GetStopDec(1) == (0, 0.05, 1.0)
    for option, dec in ((0, 0.05), (1, 1.0)):
        jog(gts)
        assert gts.GT_Stop(1, option) == 0
        assert stop_time_ms(gts) == pytest.approx(10 / dec, abs=2 * MS)  # 200 ms smooth, 10 ms abrupt
    assert gts.GT_GetJogPrm(1)[1].acc == pytest.approx(0.1)              # the move's acc is kept
    assert [gts.GT_SetStopDec(1, 0, 1), gts.GT_SetStopDec(1, 1, 32768), gts.GT_SetStopDec(9, 1, 1)] == [7, 7, 7]


def test_set_stop_io_stops_the_axis_when_its_input_is_active_guc_l205_266(gts):
    assert gts.GT_SetStopDec(1, 0.05, 1) == 0
    assert gts.GT_SetStopIo(1, 1, G.MC_GPI, 3) == 0        # GPI 3 -> smooth stop of axis 1
    jog(gts)
    gts.set_inputs(0b100)
    gts.run(1)
    assert stop_time_ms(gts) == pytest.approx(10 / 0.05, abs=3 * MS)
    assert [gts.GT_SetStopIo(1, 2, G.MC_GPI, 3), gts.GT_SetStopIo(1, 1, G.MC_GPI, 17), gts.GT_SetStopIo(1, 1, 0, 9),
            gts.GT_SetStopIo(1, 1, 6, 1)] == [7] * 4
    assert gts.GT_SetStopIo(1, 0, G.MC_HOME, 1) == 1       # not wired (GS6)


def test_get_crd_stop_dec_reads_back_guc_l710_ideabox_l5551(gts):
    crd_xy(gts)
    assert gts.GT_GetCrdStopDec(1) == (0, 0.0, 0.0)
    assert gts.GT_SetCrdStopDec(1, 0.05, 2) == 0
    assert gts.GT_GetCrdStopDec(1) == (0, 0.05, 2.0) and gts.GT_GetCrdStopDec(2) == (0, 0.0, 0.0)
    assert gts.GT_GetCrdStopDec(3)[0] == 7 and GtsController().GT_GetCrdStopDec(1)[0] == -1


# -- read-backs ------------------------------------------------------------------------------------------------------

def test_get_trap_prm_and_get_jog_prm_read_what_was_set(gts):
    assert gts.GT_PrfTrap(1) == 0 and gts.GT_SetTrapPrm(1, 0.5) == 0
    rtn, trap = gts.GT_GetTrapPrm(1)
    assert rtn == 0 and (trap.acc, trap.dec, trap.velStart, trap.smoothTime) == (pytest.approx(0.5),
                                                                                 pytest.approx(0.5), 0, 0)
    # GUC L2898-2908 (the combined-motion example): GT_GetTrapPrm, change acc and dec, GT_SetTrapPrm with the struct
    trap.acc, trap.dec = 0.25, 0.25
    assert gts.GT_SetTrapPrm(1, trap) == 0 and gts.GT_GetTrapPrm(1)[1].acc == pytest.approx(0.25)
    trap.velStart = 1
    assert gts.GT_SetTrapPrm(1, trap) == 7                                  # velStart not simulated (V61)
    # iDEABOX Ex 4-1 L726-730: GT_GetJogPrm, change acc, GT_SetJogPrm with the struct
    assert gts.GT_PrfJog(2) == 0
    rtn, prm = gts.GT_GetJogPrm(2)
    assert rtn == 0 and isinstance(prm, TJogPrmExt)
    prm.acc, prm.smooth = 1, 0.5
    assert gts.GT_SetJogPrm(2, prm) == 0
    assert gts.GT_GetJogPrm(2) == (0, TJogPrmExt(acc=pytest.approx(1), dec=pytest.approx(1), smooth=0.5))
    assert gts.GT_SetJogPrm(2, TJogPrmExt(acc=1, smooth=2)) == 7 and gts.GT_GetJogPrm(9)[0] == 7
    assert gts.GT_GetTrapPrm(0)[0] == 7


# -- iDEABOX velocity filters (§4.5) --------------------------------------------------------------------------------

def test_velocity_filters_average_the_reported_velocities_over_2_to_the_n_ticks_ideabox_l3793_3801(gts):
    assert gts.GT_GetAxisPrfVelFilter(1) == (0, 0) and gts.GT_GetAxisEncVelFilter(1) == (0, 0)
    assert gts.GT_SetAxisPrfVelFilter(1, 3) == 0 and gts.GT_SetAxisEncVelFilter(1, 5) == 0
    assert gts.GT_GetAxisPrfVelFilter(1) == (0, 3) and gts.GT_GetAxisEncVelFilter(1) == (0, 5)
    assert [gts.GT_PrfJog(1), gts.GT_SetJogPrm(1, 0.05), gts.GT_SetVel(1, 10), gts.GT_Update(1)] == [0] * 4
    run = gts.run(tick_of_ms(50))                  # accelerating: 0.05 pulse/ms^2
    v, x = run[0].prf_vel, run[0].actual_pos
    assert gts.GT_GetPrfVel(1)[1] == pytest.approx(v[-8:].mean() / MS)              # window 2^3
    assert gts.GT_GetEncVel(1)[1] == pytest.approx((x[-1] - x[-33]) / (32 * MS))    # window 2^5
    # the mean lags: at constant acceleration it is the velocity (2^n - 1)/2 ticks ago
    raw = gts.card.profile_vel(0) / MS
    assert gts.GT_GetPrfVel(1)[1] == pytest.approx(raw - 0.05 * 3.5 * MS, rel=1e-6)
    assert gts.GT_SetAxisPrfVelFilter(1, 0) == 0 and gts.GT_GetPrfVel(1)[1] == pytest.approx(raw)
    assert [gts.GT_SetAxisPrfVelFilter(1, 8), gts.GT_SetAxisEncVelFilter(0, 1), gts.GT_GetAxisPrfVelFilter(9)[0]] \
        == [7, 7, 7]


# -- iDEABOX EtherCAT and configuration file ----------------------------------------------------------------------

def test_is_ecat_ready_and_load_config_ideabox_l611_625(gts):
    assert gts.GT_IsEcatReady() == (0, 1)
    assert gts.GT_LoadConfig("./GTS800.cfg") == 1 and gts.GT_LoadConfig("") == 7
    g = GtsController()
    assert g.GT_IsEcatReady() == (-1, 0) and g.GT_LoadConfig("./GTS800.cfg") == -1


# -- PVT Continuous-Ex -----------------------------------------------------------------------------------------------

def test_pvt_table_continuous_ex_separate_s_shares_ideabox_l6745_6803(gts):
    pos, vel, vmax, acc, dec = [0, 20000, 0], [0, 0, 0], [50, 50, 50], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5]
    # equal shares: the Continuous table; different shares: another table with the same ends
    assert gts.GT_PvtTableContinuous(1, 3, pos, vel, [40] * 3, vmax, acc, dec, 0) == 0
    assert gts.GT_PvtTableContinuousEx(2, 3, pos, vel, [40] * 3, [40] * 3, vmax, acc, dec, 0) == 0
    assert gts.GT_PvtTableContinuousEx(3, 3, pos, vel, [0] * 3, [100] * 3, vmax, acc, dec, 0) == 0
    tables = [gts.card.pvt_table(k) for k in (1, 2, 3)]
    t = np.linspace(0, tables[0].duration_ms, 400)
    np.testing.assert_allclose(tables[1].evaluate(t)["pos"], tables[0].evaluate(t)["pos"])
    assert tables[1].duration_ms == tables[0].duration_ms
    # all S in the deceleration phases, none in the acceleration: another shape, the same points
    assert np.abs(tables[2].evaluate(t)["pos"] - tables[0].evaluate(t)["pos"]).max() > 1
    np.testing.assert_allclose(tables[2].pos, pos)
    assert gts.GT_PvtTableContinuousEx(1, 4, pos, vel, [0] * 3, [0] * 3, vmax, acc, dec) == 7  # fewer than count
    assert gts.GT_PvtTableContinuousEx(33, 3, pos, vel, [0] * 3, [0] * 3, vmax, acc, dec) == 7


# -- the Mx forms (CardNo first, iDEABOX L3825) --------------------------------------------------------------------

def _pvt_setup(g):
    return g.GT_PrfPvt(1) + g.GT_PvtTable(1, 2, [0, 100], [0, 1000], [0, 0])


MX_CASES = [  # (Mx form, setup, the Mx call with CardNo n, the plain call): the calls by name
    ("GT_UpdateMx", lambda g: g.GT_PrfTrap(1) + g.GT_SetTrapPrm(1, 1) + g.GT_SetVel(1, 10) + g.GT_SetPos(1, 1000),
     lambda g, n: g.GT_UpdateMx(n, 0b1), lambda g: g.GT_Update(0b1)),
    ("GT_StopMx", lambda g: g.GT_PrfJog(1) + g.GT_SetJogPrm(1, 1) + g.GT_SetVel(1, 10) + g.GT_Update(1)
     + (g.run(100) and 0), lambda g, n: g.GT_StopMx(n, 0b1, 0), lambda g: g.GT_Stop(0b1, 0)),
    ("GT_PvtStartMx", _pvt_setup, lambda g, n: g.GT_PvtStartMx(n, 0b1), lambda g: g.GT_PvtStart(0b1)),
    ("GT_PvtTableMx", lambda g: 0, lambda g, n: g.GT_PvtTableMx(n, 1, 2, [0, 100], [0, 1000], [0, 0]),
     lambda g: g.GT_PvtTable(1, 2, [0, 100], [0, 1000], [0, 0])),
    ("GT_PvtTableExMx", lambda g: 0, lambda g, n: g.GT_PvtTableExMx(n, 1, 2, [0, 100], [0, 1000], [0, 0], [0, 0]),
     lambda g: g.GT_PvtTableEx(1, 2, [0, 100], [0, 1000], [0, 0], [0, 0])),
    ("GT_PvtTableCompleteMx", lambda g: 0, lambda g, n: g.GT_PvtTableCompleteMx(n, 1, 3, [0, 50, 100], [0, 400, 1000]),
     lambda g: g.GT_PvtTableComplete(1, 3, [0, 50, 100], [0, 400, 1000])),
    ("GT_PvtTablePercentMx", lambda g: 0,
     lambda g, n: g.GT_PvtTablePercentMx(n, 1, 3, [0, 50, 100], [0, 400, 1000], [0, 50, 0]),
     lambda g: g.GT_PvtTablePercent(1, 3, [0, 50, 100], [0, 400, 1000], [0, 50, 0])),
    ("GT_PvtTableContinuousMx", lambda g: 0,
     lambda g, n: g.GT_PvtTableContinuousMx(n, 1, 2, [0, 1000], [0, 0], [50, 50], [10, 10], [1, 1], [1, 1]),
     lambda g: g.GT_PvtTableContinuous(1, 2, [0, 1000], [0, 0], [50, 50], [10, 10], [1, 1], [1, 1])),
    ("GT_PvtTableContinuousExMx", lambda g: 0,
     lambda g, n: g.GT_PvtTableContinuousExMx(n, 1, 2, [0, 1000], [0, 0], [50, 50], [20, 20], [10, 10], [1, 1],
                                              [1, 1]),
     lambda g: g.GT_PvtTableContinuousEx(1, 2, [0, 1000], [0, 0], [50, 50], [20, 20], [10, 10], [1, 1], [1, 1])),
    ("GT_FollowStartExMx", lambda g: g.GT_PrfFollowEx(2, 0) + g.GT_FollowDataPercentEx(2, 1000, 500),
     lambda g, n: g.GT_FollowStartExMx(n, 0b10, 0), lambda g: g.GT_FollowStartEx(0b10, 0)),
    ("GT_FollowSwitchExMx", lambda g: g.GT_PrfFollowEx(2, 0) + g.GT_FollowDataPercentEx(2, 1000, 500)
     + g.GT_FollowDataPercentEx(2, 1000, 500, fifo=1) + g.GT_FollowStartEx(0b10, 0),
     lambda g, n: g.GT_FollowSwitchExMx(n, 0b10), lambda g: g.GT_FollowSwitchEx(0b10)),
]


def _opened():
    g = GtsController()
    assert g.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS)) == 0
    for a in range(1, 5):
        g.GT_AxisOn(a)
    return g


@pytest.mark.parametrize("mx,setup,call_mx,call_plain", MX_CASES, ids=[c[0] for c in MX_CASES])
def test_mx_forms_do_what_the_plain_forms_do_on_card_1(mx, setup, call_mx, call_plain):
    a, b = _opened(), _opened()
    assert setup(a) == 0 and setup(b) == 0
    ra, rb = call_mx(a, 1), call_plain(b)
    assert ra == rb
    a.run(200), b.run(200)
    assert a.card.snapshot() == b.card.snapshot()
    # CardNo: axes 1-16 are card 1 (L3825); one simulated card of 4 axes -> CardNo 1 only
    assert call_mx(a, 2) == 7 and call_mx(a, 0) == 7
    assert call_mx(GtsController(), 1) == -1
    assert mx in G.GTS_FUNCTIONS and callable(getattr(G, mx))


# -- G0 lines (GUC L322-327, iDEABOX L1594-1606) --------------------------------------------------------------------

def _crd_run(g, crd=1):
    x, v = [], []
    while g.GT_CrdStatus(crd)[1] or not x:
        g.run(1)
        x.append(g.GT_GetCrdPos(crd)[1][0])
        v.append(g.GT_GetCrdVel(crd)[1])
    return np.asarray(x), np.asarray(v)


def test_g0_lines_start_and_end_at_rest_even_under_look_ahead(gts):
    # GT_LnXYG0 / GT_LnXYZG0 (GUC L322-327, iDEABOX L1594-1606): a rapid line from rest to rest whatever the
    # look-ahead plans; collinear ordinary lines keep their speed through the joint.
    assert gts.GT_SetCrdPrm(1, G.TCrdPrm(dimension=3, profile=[1, 2, 3], synVelMax=500, synAccMax=1)) == 0
    assert gts.GT_InitLookAhead(1, 0, 5, 1, 50) == 0
    assert [gts.GT_LnXYZ(1, 10000, 0, 0, 20, 1), gts.GT_LnXYZ(1, 20000, 0, 0, 20, 1),
            gts.GT_LnXYZG0(1, 30000, 0, 0, 20, 1), gts.GT_LnXYZ(1, 40000, 0, 0, 20, 1),
            gts.GT_CrdData(1, None), gts.GT_CrdStart(1, 0)] == [0] * 6
    x, v = _crd_run(gts)
    assert v[np.argmin(np.abs(x - 10000))] == pytest.approx(20, rel=0.01)   # ordinary joint: full speed
    for end in (20000, 30000):                                               # the G0's start and end: at rest
        assert v[np.abs(x - end) < 0.5].min() == pytest.approx(0, abs=1e-9)
    assert x[-1] == 40000
    # the 2-D form on a 2-D crd
    g = GtsController()
    assert g.GT_Open(sb.Card(4, law=LAW, servo_period_s=TS)) == 0 and g.GT_AxisOn(1) == 0 and g.GT_AxisOn(2) == 0
    crd_xy(g)
    assert g.GT_InitLookAhead(1, 0, 5, 1, 50) == 0
    assert [g.GT_LnXY(1, 10000, 0, 20, 1), g.GT_LnXYG0(1, 20000, 0, 20, 1), g.GT_LnXY(1, 30000, 0, 20, 1),
            g.GT_CrdData(1, None), g.GT_CrdStart(1, 0)] == [0] * 5
    x, v = _crd_run(g)
    assert v[np.abs(x - 20000) < 0.5].min() == pytest.approx(0, abs=1e-9) and x[-1] == 30000
