"""ADLINK dialect functions that no other test called (docs/coverage.md "Untested"), each checked against what the
ADLINK PCI-8254/8258 manual says (seed 004 = ../shared/seeds/004_*.txt, `Lnnnn` its lines; digest spec/adlink.md)."""

import numpy as np
import pytest

from servobench.dialects import aps
from servobench.dialects.aps import ApsController
from test_card_aps_interp import FE_BOUND, TS, bit, controller
from test_card_scope import a  # noqa: F401 (a: a 4-axis card, axis 0 on, ACC = DEC = 4e5)


# -- stops ------------------------------------------------------------------------------------------------------

def test_emg_stop_stops_at_once_with_a_normal_stop_code_l2576():
    # APS_emg_stop (L2576: "stops immediately") vs APS_stop_move (L2574: decelerates at PRA_STP_DEC): the profile
    # velocity is 0 from the next tick, MDN and CSTP set, ASTP clear, stop code STOP_NORMAL (V45). On an axis of an
    # interpolation group it stops the whole group at once (L3150 group stops, C35-C44).
    c = controller(vm=20000, acc=1e5)
    assert c.APS_set_axis_param_f(1, aps.PRA_STP_DEC, 1e5) == 0
    for axis in (0, 1):
        assert c.APS_vel(axis, 0, 8000.0, 0) == 0
    c.Sleep(200)
    assert c.card.profile_vel(0) / TS == pytest.approx(8000)
    assert c.APS_emg_stop(0) == 0 and c.APS_stop_move(1) == 0
    r = c.run(600)
    v0, v1 = np.diff(r[0].pos), np.diff(r[1].pos)
    assert np.all(v0 == 0)                                                 # at once
    assert np.count_nonzero(v1) > 100 and np.all(np.diff(v1[v1 > 0]) <= 1)  # stop_move decelerates
    m = c.APS_motion_status(0)
    assert bit(m, aps.MTS_MDN) and bit(m, aps.MTS_CSTP) and not bit(m, aps.MTS_ASTP)
    assert c.APS_get_stop_code(0) == (0, aps.STOP_NORMAL)
    assert c.APS_emg_stop(0) == 0                                          # at rest: nothing to do
    # a group: the line stops on every axis in the same tick
    assert c.APS_line(2, [2, 3], 0, [30000, 40000], 0.0) == 0
    c.Sleep(300)
    assert c.APS_emg_stop(3) == 0
    r = c.run(50)
    assert np.all(np.diff(r[2].pos) == 0) and np.all(np.diff(r[3].pos) == 0)
    p2, p3 = r[2].pos[-1], r[3].pos[-1]
    assert 0 < p2 < 30000 and abs(4 * p2 - 3 * p3) <= 7                    # on the line, short of its end
    assert c.APS_get_stop_code(2) == (0, aps.STOP_NORMAL) and bit(c.APS_motion_status(2), aps.MTS_MDN)
    assert c.APS_emg_stop(9) == aps.ERR_ParametersInvalid
    assert ApsController().APS_emg_stop(0) == aps.ERR_DeviceNotInitial


# -- the _v / _all forms of the arcs and spirals, APS_arc3_ce ---------------------------------------------------

def run_path(c, axes, limit_ticks=40000):
    """Runs until every axis reports MDN: (profile positions, vector speed pulse/s from the profile velocities,
    following errors); rows = ticks."""
    pos, vel, err = [], [], []
    for _ in range(limit_ticks // 200):
        r = c.card.run(200, signals=["pos", "prf_vel", "error"])
        pos.append(np.stack([r[a].pos for a in axes], 1))
        vel.append(np.linalg.norm(np.stack([r[a].prf_vel for a in axes], 1), axis=1) / TS)
        err.append(np.stack([r[a].error for a in axes], 1))
        if all(bit(c.APS_motion_status(a), aps.MTS_MDN) for a in axes):
            return np.concatenate(pos), np.concatenate(vel), np.concatenate(err)
    raise AssertionError("the move did not end")


R = 4000.0
ARCS = {
    # name: (call(c, tail...), axes, end, check(pos) -> bool)
    "arc2_ca": (lambda c, *t: getattr(c, "APS_arc2_ca" + t[0])([0, 1], 0, [-R, 0], 90, 0.0, *t[1:]), (0, 1),
                (-R, R), lambda p: np.abs(np.hypot(p[:, 0] + R, p[:, 1]) - R).max() <= 1.5),
    "arc2_ce": (lambda c, *t: getattr(c, "APS_arc2_ce" + t[0])([0, 1], 0, [-R, 0], [-R, R], 1, 0.0, *t[1:]),
                (0, 1), (-R, R), lambda p: np.abs(np.hypot(p[:, 0] + R, p[:, 1]) - R).max() <= 1.5),
    "arc3_ce": (lambda c, *t: getattr(c, "APS_arc3_ce" + t[0])([0, 1, 2], 0, [0, 0, -R], [R, 0, -R], 0, 0.0, *t[1:]),
                (0, 1, 2), (R, 0, -R), lambda p: (np.abs(np.linalg.norm(p - [0, 0, -R], axis=1) - R).max() <= 1.5
                                                  and np.all(p[:, 1] == 0))),
    "sprial_ca": (lambda c, *t: getattr(c, "APS_sprial_ca" + t[0])([0, 1, 2], 0, [-R, 0, 0], [0, 0, 1], 360, 2000,
                                                                   R / 2, 0.0, *t[1:]),
                  (0, 1, 2), (-R / 2, 0, 2000), lambda p: np.all(np.diff(p[:, 2]) >= 0)),
    "sprial_ce": (lambda c, *t: getattr(c, "APS_sprial_ce" + t[0])([0, 1, 2], 0, [-R, 0, 0], [0, 0, 1],
                                                                   [-R, R / 2, 2000], 0, 0.0, *t[1:]),
                  (0, 1, 2), (-R, R / 2, 2000),                         # radius R -> R/2 over a CCW quarter, rising
                  lambda p: (np.all(np.diff(p[:, 2]) >= 0)
                             and np.all(np.diff(np.hypot(p[:, 0] + R, p[:, 1])) <= 1.5))),
}


def _vm_speeds(form):
    if form == "":
        return (), 10000.0, 1e5, 0.0
    if form == "_v":
        return (15000.0,), 15000.0, 1e5, 0.0
    return (0.0, 12000.0, 0.0, 5e4, 5e4, 0.5), 12000.0, 5e4, 0.5          # Vs, Vm, Ve, Acc, Dec, SFac


@pytest.mark.parametrize("form", ["", "_v", "_all"])
@pytest.mark.parametrize("name", list(ARCS))
def test_arc_and_spiral_forms_reach_their_end_at_their_speed_l2886_3063(name, form):
    # L2886-2926 (arc2/arc3 by centre + angle; arc3 by the right-hand rule about the normal), L2943-2958 (by centre
    # + end with Dir), L3001-3063 (spirals, the manual's "sprial" spelling). The _v form takes the vector speed Vm
    # (pulse/s); the _all form every speed of the vector profile: Vs, Vm, Ve, Acc, Dec and the S-factor SFac; the
    # plain form the first axis's PRA_VM / PRA_ACC (T19, L2829-2855). With the S-curve the ramp lasts
    # (1 + SFac) (Vm - Vs) / Acc (TV38).
    call, axes, end, check = ARCS[name]                                   # arc3_ce with form "": APS_arc3_ce
    tail, vm, acc, sfac = _vm_speeds(form)
    c = controller(vm=10000.0, acc=1e5)
    assert call(c, form, *tail) == aps.ERR_NoError
    pos, v, err = run_path(c, list(axes))
    pos = np.vstack([np.zeros(len(axes)), pos])
    assert [c.APS_get_command(i)[1] for i in axes] == [round(x) for x in end]
    assert check(pos)
    assert v.max() == pytest.approx(vm, rel=1e-3)
    ramp = (np.flatnonzero(v >= vm * (1 - 1e-6))[0] + 1) * TS
    assert ramp == pytest.approx((1 + sfac) * vm / acc, abs=2 * TS)
    assert np.abs(err).max() < FE_BOUND


def test_arc3_ca_forms_turn_about_the_normal_l2899_2911():
    # APS_arc3_ca (L2899, Gram-Schmidt L2911): a 3-D arc about the centre, right-hand rule about NormalArray. From
    # (0, 0, 0) about the centre (0, 0, -R) with the normal +y by 90 deg: the radius vector +z turns into +x
    # (right-hand rule about +y), so the arc ends at (R, 0, -R) in the XZ plane.
    for form, tail, vm in (("", (), 10000.0), ("_v", (15000.0,), 15000.0),
                           ("_all", (0.0, 12000.0, 0.0, 5e4, 5e4, 0.5), 12000.0)):
        c = controller(vm=10000.0, acc=1e5)
        assert getattr(c, "APS_arc3_ca" + form)([0, 1, 2], 0, [0, 0, -R], [0, 1, 0], 90, 0.0, *tail) == 0
        pos, v, err = run_path(c, [0, 1, 2])
        assert [c.APS_get_command(i)[1] for i in (0, 1, 2)] == [round(R), 0, round(-R)]
        assert np.abs(np.linalg.norm(pos - [0, 0, -R], axis=1) - R).max() <= 1.5 and np.all(pos[:, 1] == 0)
        assert v.max() == pytest.approx(vm, rel=1e-3) and np.abs(err).max() < FE_BOUND


def test_arc_forms_bad_input_l2930_2933():
    # L2930-2933: an arc by centre + end of exactly 180 or 360 deg is ambiguous: ERR_ParametersInvalid; the _all
    # speeds must be usable (Vm > 0, Acc > 0, SFac 0..1), the arrays as long as the dimension.
    c = controller()
    bad = aps.ERR_ParametersInvalid
    assert c.APS_arc3_ce([0, 1, 2], 0, [R, 0, 0], [2 * R, 0, 0], 0, 0.0) == bad          # 180 deg
    assert c.APS_arc3_ce_v([0, 1, 2], 0, [R, 0, 0], [0, 0, 0], 0, 0.0, 1000.0) == bad    # 360 deg
    assert c.APS_arc2_ca_v([0, 1], 0, [R, 0], 90, 0.0, -5.0) == bad                      # Vm <= 0
    assert c.APS_arc2_ce_all([0, 1], 0, [R, 0], [R, R], 0, 0.0, 0, 1000, 0, 0, 1e4, 0.5) == bad   # Acc 0
    assert c.APS_sprial_ca_all([0, 1, 2], 0, [R, 0, 0], [0, 0, 1], 90, 10, R, 0.0, 0, 1000, 0, 1e4, 1e4, 2) == bad
    assert c.APS_arc3_ca_v([0, 1], 0, [R, 0, 0], [0, 0, 1], 90, 0.0, 1000.0) == bad      # two axes for a 3-D arc
    assert c.APS_sprial_ce_v([0, 1, 2], 0, [R, 0, 0], [0, 0], [R, R, 5], 0, 0.0, 1000.0) == bad   # normal of 2
    assert all(not bit(c.APS_motion_status(i), aps.MTS_HMV) for i in range(3))
    assert [c.APS_get_command(i)[1] for i in range(3)] == [0, 0, 0]                    # nothing moved


# -- trigger read-backs -----------------------------------------------------------------------------------------

def test_get_trigger_param_reads_back_what_was_set_l3348_3435(a):
    # APS_get_trigger_param (L3348-3435; adlink.md §6.10): the value APS_set_trigger_param stored; an unknown
    # parameter number is ERR_ParametersInvalid; a refused set leaves the old value.
    settings = {aps.TGR_LCMP0_SRC: 0, aps.TGR_TCMP0_SRC: aps.TGR_SRC_COMMAND + 1, aps.TGR_TCMP0_DIR: 2,
                aps.TGR_TRG0_SRC: aps.TRG_SRC_LCMP0 | aps.TRG_SRC_TCMP0, aps.TGR_TRG0_PWD: 500,
                aps.TGR_TRG0_LOGIC: 1, aps.TGR_TRG0_TGL: 1, aps.TGR_TRG_EN: 0x1}
    for p, v in settings.items():
        assert a.APS_set_trigger_param(0, p, v) == 0
    for p, v in settings.items():
        assert a.APS_get_trigger_param(0, p) == (0, v)
    assert a.APS_set_trigger_param(0, aps.TGR_TRG0_PWD, 0) == aps.ERR_ParametersInvalid    # 1..10^7
    assert a.APS_get_trigger_param(0, aps.TGR_TRG0_PWD) == (0, 500)
    assert a.APS_get_trigger_param(0, 9999) == (aps.ERR_ParametersInvalid, 0)
    assert a.APS_get_trigger_param(1, aps.TGR_TRG_EN)[0] == aps.ERR_ParametersInvalid     # board 0 only
    assert ApsController().APS_get_trigger_param(0, aps.TGR_TRG_EN)[0] == aps.ERR_DeviceNotInitial


def test_get_trigger_table_cmp_is_the_next_table_point_l3397_3430(a):
    # APS_get_trigger_table_cmp: the next point TCMPx compares (L3397-3430: the table's points in order, in the
    # TGR_TCMPx_DIR direction); the manual prints no text for it: 0 once every point is compared (V128).
    assert a.APS_set_trigger_param(0, aps.TGR_TCMP0_SRC, 0) == 0                 # encoder of axis 0
    assert a.APS_set_trigger_param(0, aps.TGR_TCMP0_DIR, 1) == 0                 # positive
    assert a.APS_set_trigger_param(0, aps.TGR_TRG0_SRC, aps.TRG_SRC_TCMP0) == 0
    assert a.APS_set_trigger_param(0, aps.TGR_TRG_EN, 0x1) == 0
    table = [1000, 2500, 6000]
    assert a.APS_set_trigger_table(0, 0, table, 3) == 0
    assert a.APS_get_trigger_table_cmp(0, 0) == (0, 1000)
    assert a.APS_relative_move(0, 2000, 40000) == 0
    a.Sleep(500)
    assert a.APS_get_trigger_count(0, 0) == (0, 1) and a.APS_get_trigger_table_cmp(0, 0) == (0, 2500)
    assert a.APS_relative_move(0, 8000, 40000) == 0
    a.Sleep(1000)
    assert a.APS_get_trigger_count(0, 0) == (0, 3) and a.APS_get_trigger_table_cmp(0, 0) == (0, 0)
    assert a.APS_get_trigger_table_cmp(0, 2) == (aps.ERR_ParametersInvalid, 0)   # TCMP0/1
